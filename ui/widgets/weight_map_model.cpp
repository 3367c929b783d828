#include "widgets/weight_map_model.h"

namespace auv::ui {

int WeightMapModel::piecesToAdd() const {
  int n = 0;
  for (const auto& p : points)
    for (const auto& c : p.change) n += c.count > 0 ? c.count : 0;
  return n;
}

int WeightMapModel::piecesToRemove() const {
  int n = 0;
  for (const auto& p : points)
    for (const auto& c : p.change) n += c.count < 0 ? -c.count : 0;
  return n;
}

WeightMapModel makeWeightMapModel(const VehicleProfile& v, const std::vector<double>& installed_kg,
                                  const FirstMissionReport& report) {
  WeightMapModel m;
  m.length_m = v.hull.length_m;
  m.diameter_m = v.hull.diameter_m;
  m.cb_x_m = v.cb_m.x();
  m.cb_y_m = v.cb_m.y();
  for (std::size_t i = 0; i < v.points.size(); ++i) {
    MapPoint p;
    p.name = v.points[i].name;
    p.label = v.points[i].label;
    p.x_m = v.points[i].position_m.x();
    p.y_m = v.points[i].position_m.y();
    p.installed_kg = i < installed_kg.size() ? installed_kg[i] : 0.0;
    for (const auto& r : report.points) {
      if (r.name == p.name) {
        p.change = r.pieces;
        p.change_kg = r.add_kg;
      }
    }
    m.points.push_back(p);
  }
  return m;
}

}  // namespace auv::ui
