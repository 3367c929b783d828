#include "wizard/background_task.h"

#include <QDeadlineTimer>
#include <QThread>
#include <QtConcurrent/QtConcurrent>
#include <atomic>
#include <exception>

#include "wizard/worker_pool.h"

namespace auv::ui {
namespace {
std::atomic<bool> g_inline{false};
std::atomic<int> g_grace_ms{80};
}  // namespace

void BackgroundTask::setRunInlineForBench(bool on) { g_inline = on; }
int BackgroundTask::graceMs() { return g_grace_ms; }
void BackgroundTask::setGraceMs(int ms) { g_grace_ms = ms; }

BackgroundTask::BackgroundTask(QObject* parent) : QObject(parent) {
  connect(&watcher_, &QFutureWatcher<Apply>::finished, this, [this] { apply(); });
}

BackgroundTask::~BackgroundTask() {
  // The work may reference the page's data: it must not outlive the page.
  watcher_.waitForFinished();
}

void BackgroundTask::start(const QString& what, Work work) {
  finishNow();
  what_ = what;
  if (g_inline) {
    if (const Apply result = work()) result();
    emit finished();
    return;
  }
  pending_ = true;
  watcher_.setFuture(QtConcurrent::run(workerPool(), [work = std::move(work)]() -> Apply {
    lowerWorkerPriority();
    // The pages' work catches what it expects; anything else must not be
    // lost in the pool (QtConcurrent would rethrow it on the UI thread).
    try {
      return work();
    } catch (const std::exception& e) {
      qWarning("background work failed: %s", e.what());
      return [] {};
    }
  }));
  emit started();
}

void BackgroundTask::settle(std::initializer_list<BackgroundTask*> tasks) {
  // The UI thread is blocked at most the grace.
  const auto done = [&] {
    for (const BackgroundTask* t : tasks)
      if (t->pending_ && !t->watcher_.isFinished()) return false;
    return true;
  };
  QDeadlineTimer deadline(g_grace_ms.load());
  while (!done() && !deadline.hasExpired()) QThread::usleep(500);
  for (BackgroundTask* t : tasks) t->apply();
}

void BackgroundTask::finishNow() {
  if (!pending_) return;
  watcher_.waitForFinished();
  apply();
}

void BackgroundTask::apply() {
  // The watcher's finished signal arrives after finishNow() applied it.
  if (!pending_ || !watcher_.isFinished()) return;
  pending_ = false;
  if (const Apply result = watcher_.result()) result();
  emit finished();
}

}  // namespace auv::ui
