#include "wizard/worker_pool.h"

#include <QThread>
#include <algorithm>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace auv::ui {

QThreadPool* workerPool() {
  static QThreadPool* pool = [] {
    auto* p = new QThreadPool;
    p->setMaxThreadCount(std::max(1, QThread::idealThreadCount() - 1));
    return p;
  }();
  return pool;
}

void clearAvxUpperState() {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  static const bool avx = __builtin_cpu_supports("avx");
  if (avx) __asm__ volatile("vzeroupper");
#endif
}

void lowerWorkerPriority() {
  clearAvxUpperState();  // every time: the job's own code may follow Qt code on this thread
#ifdef __linux__
  // Per thread on Linux: setpriority on the thread id, not the process.
  thread_local bool done = false;
  if (done) return;
  done = true;
  const auto tid = static_cast<id_t>(syscall(SYS_gettid));
  if (getpriority(PRIO_PROCESS, tid) < 10) setpriority(PRIO_PROCESS, tid, 10);
#else
  QThread::currentThread()->setPriority(QThread::LowPriority);
#endif
}

}  // namespace auv::ui
