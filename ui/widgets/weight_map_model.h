#pragma once
// What the top-down weight map draws, built from a profile and a report so
// the widget itself holds no ballast logic: per point, the pieces already
// installed and the signed change by piece size.
#include <string>
#include <vector>

#include "firstmission/first_mission_report.h"
#include "vehicle/vehicle_profile.h"

namespace auv::ui {

// One square on the map: a single kit piece, or (for many small pieces such
// as 162 × 1 g of lead shot) one square for all of them, labelled with the count.
struct MapBlock {
  double mass_kg = 0.0;
  int pieces = 1;
  bool add = true;
};

struct MapPoint {
  std::string name;
  std::string label;
  double x_m = 0.0;
  double y_m = 0.0;
  double installed_kg = 0.0;
  std::vector<PieceCount> change;  // signed counts per size
  double change_kg = 0.0;

  // Pieces drawn one by one up to this many per size, else as one block.
  static constexpr int kMaxSeparatePieces = 6;
  std::vector<MapBlock> blocks() const;
};

struct WeightMapModel {
  double length_m = 0.0;
  double diameter_m = 0.0;
  double cb_x_m = 0.0;
  double cb_y_m = 0.0;
  bool grams = false;             // glider ballast is set to the gram
  double px_per_sqrt_kg = 7.0;    // square side = this * sqrt(mass): area ∝ mass
  std::vector<MapPoint> points;

  int piecesToAdd() const;
  int piecesToRemove() const;
};

// `installed_kg` in profile point order. The square scale is 7 px/sqrt(kg)
// (a 4.8 kg HUGIN piece ~15 px) unless the largest square would be under
// 10 px, as for a glider's grams of lead; then the largest is drawn 24 px.
WeightMapModel makeWeightMapModel(const VehicleProfile& vehicle, const std::vector<double>& installed_kg,
                                  const FirstMissionReport& report);
// The same from any per-point change (a pre-mission plan's points).
WeightMapModel makeWeightMapModel(const VehicleProfile& vehicle, const std::vector<double>& installed_kg,
                                  const std::vector<PointRecommendation>& changes);

}  // namespace auv::ui
