#pragma once
// What the top-down weight map draws, built from a profile and a report so
// the widget itself holds no ballast logic: per point, the pieces already
// installed and the signed change by piece size.
#include <string>
#include <vector>

#include "firstmission/first_mission_report.h"
#include "vehicle/vehicle_profile.h"

namespace auv::ui {

struct MapPoint {
  std::string name;
  std::string label;
  double x_m = 0.0;
  double y_m = 0.0;
  double installed_kg = 0.0;
  std::vector<PieceCount> change;  // signed counts per size
  double change_kg = 0.0;
};

struct WeightMapModel {
  double length_m = 0.0;
  double diameter_m = 0.0;
  double cb_x_m = 0.0;
  double cb_y_m = 0.0;
  std::vector<MapPoint> points;

  int piecesToAdd() const;
  int piecesToRemove() const;
};

WeightMapModel makeWeightMapModel(const VehicleProfile& vehicle, const std::vector<double>& installed_kg,
                                  const FirstMissionReport& report);

}  // namespace auv::ui
