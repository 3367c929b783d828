#pragma once
#include <QWidget>
#include <array>
#include <optional>

namespace auv::ui {

// What the side view draws: the hull from the profile, the two rope
// stations, the readings of the four part scales (two per rope: starboard
// and port, one behind the other in this view) and of the hook scale, and
// the CB and (when the readings give one) the CG in x.
struct CraneSideViewData {
  double length_m = 0.0;
  double diameter_m = 0.0;
  double rope_fore_x_m = 0.0;
  double rope_aft_x_m = 0.0;
  std::array<double, 4> scales_kg{};  // FS, FP, AS, AP
  double total_kg = 0.0;
  double cb_x_m = 0.0;
  std::optional<double> cg_x_m;
};

// Side view of a vehicle hanging from the crane (bow to the right): where
// each scale hangs and what it reads, so a swapped fore/aft station or a
// reading typed into the wrong box shows at a glance.
class CraneSideView : public QWidget {
  Q_OBJECT
 public:
  explicit CraneSideView(QWidget* parent = nullptr);
  void setData(const CraneSideViewData& d);
  const CraneSideViewData& data() const { return data_; }
  QSize sizeHint() const override { return {520, 210}; }
  QSize minimumSizeHint() const override { return {360, 180}; }

 protected:
  void paintEvent(QPaintEvent*) override;

 private:
  CraneSideViewData data_;
};

}  // namespace auv::ui
