#pragma once
// The threads background work runs on (imports, analyses, plot preparation,
// model checks). On a small machine the UI thread must still get the CPU
// the moment it has something to do: measured on 2 busy cores, two workers
// at the UI's priority starved it for ~1 s (an 1100 h log). So the pool
// leaves one core to the UI when there are several, and its threads run at
// a lower priority (nice +10 on Linux) than the UI thread.
#include <QThreadPool>

namespace auv::ui {

QThreadPool* workerPool();
// Called first by every piece of work run on workerPool() (pool threads
// are created lazily, so the pool cannot set it once).
void lowerWorkerPriority();

}  // namespace auv::ui
