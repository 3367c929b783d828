#pragma once
#include <QColor>
#include <QFont>
#include <QRectF>
#include <QString>
#include <QWidget>
#include <vector>

#include "widgets/weight_map_model.h"

class QPainter;

namespace auv::ui {

// What drawWeightMap needs besides the model: the text font and colours.
struct WeightMapStyle {
  QFont font;
  QColor background = Qt::white;
  QColor text = Qt::black;
};

// Where drawWeightMap put the point labels (model order) and the hull.
struct WeightMapLayout {
  std::vector<QRectF> labels;
  QRectF hull;
};

// Draws the top-down weight map into `area` of the painter's coordinates
// (nominal 96 dpi pixels: line widths and marks are sized for that; scale
// the painter for other resolutions). One drawing for the widget and the
// printed work order, so both show the same map.
WeightMapLayout drawWeightMap(QPainter& p, const QRectF& area, const WeightMapModel& model, const WeightMapStyle& style);

// Top-down view of the vehicle (bow to the right, starboard down, as seen
// from above) with each adjustment point where it sits: grey = installed,
// green squares = pieces to add, red = pieces to remove, sized by mass. Each
// point's label ("<point>: <change> (<now> → <after>)") sits in a band above
// or below the hull with a leader line, in rows that never overlap.
class WeightMapWidget : public QWidget {
  Q_OBJECT
 public:
  explicit WeightMapWidget(QWidget* parent = nullptr);
  void setModel(WeightMapModel model);
  const WeightMapModel& model() const { return model_; }
  // Where the last paint put the point labels (model order) and the hull.
  const std::vector<QRectF>& labelRects() const { return label_rects_; }
  QRectF hullRect() const { return hull_rect_; }
  QSize sizeHint() const override { return {760, 300}; }

 protected:
  void paintEvent(QPaintEvent*) override;

 private:
  WeightMapModel model_;
  std::vector<QRectF> label_rects_;
  QRectF hull_rect_;
};

}  // namespace auv::ui
