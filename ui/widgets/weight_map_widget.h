#pragma once
#include <QWidget>

#include "widgets/weight_map_model.h"

namespace auv::ui {

// Top-down view of the vehicle (bow to the right, starboard down, as seen
// from above) with each adjustment point where it sits: grey = installed,
// green squares = pieces to add, red = pieces to remove, sized by mass.
class WeightMapWidget : public QWidget {
  Q_OBJECT
 public:
  explicit WeightMapWidget(QWidget* parent = nullptr);
  void setModel(WeightMapModel model);
  const WeightMapModel& model() const { return model_; }
  QSize sizeHint() const override { return {760, 300}; }

 protected:
  void paintEvent(QPaintEvent*) override;

 private:
  WeightMapModel model_;
};

}  // namespace auv::ui
