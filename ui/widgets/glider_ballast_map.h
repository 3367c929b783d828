#pragma once
// Where a glider's grams go, drawn twice: from above (bow to the right,
// starboard down) and from the side (bow to the right, keel down), each
// ballast place where the profile puts it, with its change in grams and
// what it holds afterwards. Built from planGliderBallast's JSON, so the
// widget holds no ballast logic. One drawing for the page and the tests.
#include <QFont>
#include <QRectF>
#include <QString>
#include <QWidget>
#include <vector>

#include <nlohmann/json.hpp>

#include "vehicle/vehicle_profile.h"

class QPainter;

namespace auv::ui {

struct GliderMapPlace {
  QString label;
  double x_m = 0.0, y_m = 0.0, z_m = 0.0;  // body axes: x forward, y starboard, z down
  double add_g = 0.0;
  double after_g = -1.0;     // < 0: not known
  double capacity_g = -1.0;  // < 0: not known
};

struct GliderMapModel {
  double length_m = 0.0;
  double diameter_m = 0.0;
  std::vector<GliderMapPlace> places;
  QString note;  // drawn under the views (e.g. Seaglider's VBD and pitch settings)
};

GliderMapModel makeGliderMapModel(const VehicleProfile& v, const nlohmann::json& plan);

// The two views in `area`; returns the label rectangles (places order, top
// view then side view) so tests can check that nothing overlaps.
std::vector<QRectF> drawGliderBallastMap(QPainter& p, const QRectF& area, const GliderMapModel& m, const QFont& font);

class GliderBallastMap : public QWidget {
  Q_OBJECT
 public:
  explicit GliderBallastMap(QWidget* parent = nullptr);
  void setModel(GliderMapModel m);
  const GliderMapModel& model() const { return model_; }
  const std::vector<QRectF>& labelRects() const { return labels_; }
  QSize sizeHint() const override { return {760, 380}; }
  QSize minimumSizeHint() const override { return {560, 360}; }

 protected:
  void paintEvent(QPaintEvent*) override;

 private:
  GliderMapModel model_;
  std::vector<QRectF> labels_;
};

}  // namespace auv::ui
