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
// are created lazily, so the pool cannot set it once). Also clears the
// upper halves of the AVX registers (clearAvxUpperState).
void lowerWorkerPriority();

// vzeroupper where the CPU has AVX. A thread inherits its creator's vector
// registers; once Qt GUI has started, the UI thread's upper AVX state is
// dirty, and every SSE instruction of a thread that inherits it pays the
// AVX-SSE transition: measured, the HUGIN demo model check took 11.4 s in a
// process with a QGuiApplication against 2.0 s without, and 2.0 s again
// after this (docs/decisions/worker-avx-state.md). No-op elsewhere.
void clearAvxUpperState();

}  // namespace auv::ui
