#pragma once
// A scroll area for a whole page: the page's content fills the view and
// shrinks like an unscrolled page down to its minimum size; only below that
// (a 1366 x 768 screen) does it scroll. (QScrollArea's own resizing follows
// the content's preferred height when it wraps words, so it would scroll
// where the page fits.)
#include <QLayout>
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
    const QSize view = maximumViewportSize();
    int width = view.width();
    int min_h = minimumHeightAt(w, width);
    if (min_h > view.height()) {  // it scrolls: the bar takes its width
      width -= bar;
      min_h = minimumHeightAt(w, width);
    }
    w->resize(width, std::max(min_h, view.height()));
  }

  // The height the page needs at `width`: word-wrapped labels need more
  // lines when narrow, which the plain minimum size hint does not know (the
  // layout would then overlap its widgets).
  static int minimumHeightAt(QWidget* w, int width) {
    int h = w->minimumSizeHint().height();
    if (QLayout* l = w->layout(); l && l->hasHeightForWidth()) h = std::max(h, l->minimumHeightForWidth(width));
    return h;
  }
};

}  // namespace auv::ui
