#include "widgets/busy_indicator.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>

#include "wizard/background_task.h"

namespace auv::ui {

BusyIndicator::BusyIndicator(QWidget* parent) : QWidget(parent) {
  setObjectName("busy_indicator");
  bar_ = new QProgressBar;
  bar_->setObjectName("busy_bar");
  bar_->setRange(0, 0);  // indeterminate: the analysis reports no progress
  bar_->setTextVisible(false);
  bar_->setMaximumHeight(16);
  bar_->setFixedWidth(160);
  words_ = new QLabel;
  words_->setObjectName("busy_words");
  words_->setWordWrap(true);
  auto* lay = new QHBoxLayout(this);
  lay->setContentsMargins(0, 0, 0, 0);
  lay->addWidget(bar_);
  lay->addWidget(words_, 1);
  setVisible(false);
}

void BusyIndicator::follow(BackgroundTask* task) {
  tasks_.push_back(task);
  connect(task, &BackgroundTask::started, this, [this] { refresh(); });
  connect(task, &BackgroundTask::finished, this, [this] { refresh(); });
  connect(task, &QObject::destroyed, this, [this, task] { std::erase(tasks_, task); });
}

bool BusyIndicator::busy() const {
  for (const BackgroundTask* t : tasks_)
    if (t->running()) return true;
  return false;
}

QString BusyIndicator::text() const { return words_->text(); }

void BusyIndicator::refresh() {
  QString what;
  for (const BackgroundTask* t : tasks_)
    if (t->running()) {
      what = t->what();
      break;
    }
  const bool on = busy();
  words_->setText(what);
  if (on != shown_) {
    shown_ = on;
    setVisible(on);
    emit busyChanged(on);
  }
}

}  // namespace auv::ui
