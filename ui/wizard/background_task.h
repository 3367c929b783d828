#pragma once
// One piece of work of a page (an analysis, the plot preparation) run in the
// worker pool so the window keeps repainting and answering while it runs
// (issue 14: a 1100 h log froze the window ~3 s). The work returns a closure
// that applies its result; the task calls it on the UI thread when the
// worker is done, exactly once. settle() waits a short grace for tasks just
// started and applies those done, so a small log shows its page at once,
// without a busy indicator flashing up (nothing is painted in between).
#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <functional>
#include <initializer_list>

namespace auv::ui {

class BackgroundTask : public QObject {
  Q_OBJECT
 public:
  using Apply = std::function<void()>;  // runs on the UI thread
  using Work = std::function<Apply()>;  // runs in a worker; must not touch widgets

  explicit BackgroundTask(QObject* parent = nullptr);
  ~BackgroundTask() override;

  // Starts `work`; `what` says in words what runs (the busy indicator shows
  // it). A task still running is finished first (its result applied).
  void start(const QString& what, Work work);
  // Waits up to the grace for all `tasks` and applies those that are done.
  static void settle(std::initializer_list<BackgroundTask*> tasks);
  bool running() const { return pending_; }
  QString what() const { return what_; }
  // Waits for the worker and applies its result now (Next pressed early,
  // tests, shutdown).
  void finishNow();
  // Every task runs its work on the UI thread, as before issue 14: only for
  // bench/ui_freeze_bench's "before" figure.
  static void setRunInlineForBench(bool on);
  // How long settle() waits for short work before showing the indicator
  // (80 ms; the GUI tests raise it so small logs land whole on every page,
  // and measure the product's value where it matters).
  static int graceMs();
  static void setGraceMs(int ms);

 signals:
  void started();
  void finished();

 private:
  void apply();
  QFutureWatcher<Apply> watcher_;
  QString what_;
  bool pending_ = false;  // started and not yet applied
};

}  // namespace auv::ui
