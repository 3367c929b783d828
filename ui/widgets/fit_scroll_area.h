#pragma once
// A scroll area for a whole page: the page's content fills the view and
// shrinks like an unscrolled page down to its minimum size; only below that
// (a 1366 x 768 screen) does it scroll. (QScrollArea's own resizing follows
// the content's preferred height when it wraps words, so it would scroll
// where the page fits.)
#include <QScrollArea>
#include <QScrollBar>
#include <algorithm>

namespace auv::ui {

class FitScrollArea : public QScrollArea {
 public:
  FitScrollArea() {
    setFrameShape(QFrame::NoFrame);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  }
  QSize minimumSizeHint() const override { return {100, 100}; }

 protected:
  void resizeEvent(QResizeEvent* e) override {
    QScrollArea::resizeEvent(e);
    fit();
  }
  void showEvent(QShowEvent* e) override {
    QScrollArea::showEvent(e);
    fit();
  }

 private:
  void fit() {
    QWidget* w = widget();
    if (!w) return;
    const int bar = verticalScrollBar()->sizeHint().width();
    const int min_h = w->minimumSizeHint().height();
    const bool scrolls = min_h > maximumViewportSize().height();
    const int width = maximumViewportSize().width() - (scrolls ? bar : 0);
    w->resize(width, std::max(min_h, maximumViewportSize().height()));
  }
};

}  // namespace auv::ui
