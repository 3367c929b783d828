#pragma once
// The words and an indeterminate bar shown while a page's background work
// runs ("Analysing the log: steady segments, deviations, calibration…").
// It follows any number of tasks: visible while one of them runs, saying
// what the first running one does, hidden when all are done. Cancel is
// offered only where the core can stop (the log import has its own bar).
#include <QWidget>
#include <vector>

class QLabel;
class QProgressBar;

namespace auv::ui {

class BackgroundTask;

class BusyIndicator : public QWidget {
  Q_OBJECT
 public:
  explicit BusyIndicator(QWidget* parent = nullptr);
  void follow(BackgroundTask* task);
  // Some followed task is running (what the wizard waits for).
  bool busy() const;
  QString text() const;

 signals:
  void busyChanged(bool busy);

 private:
  void refresh();
  bool shown_ = false;
  std::vector<BackgroundTask*> tasks_;
  QProgressBar* bar_;
  QLabel* words_;
};

}  // namespace auv::ui
