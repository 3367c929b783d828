#include "widgets/weight_map_model.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace auv::ui {

std::vector<MapBlock> MapPoint::blocks() const {
  std::vector<MapBlock> out;
  for (const auto& c : change) {
    if (c.count == 0) continue;
    const int n = std::abs(c.count);
    if (n <= kMaxSeparatePieces) {
      for (int k = 0; k < n; ++k) out.push_back({c.size_kg, 1, c.count > 0});
    } else {
      out.push_back({c.size_kg * n, n, c.count > 0});
    }
  }
  return out;
}

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
  return makeWeightMapModel(v, installed_kg, report.points);
}

WeightMapModel makeWeightMapModel(const VehicleProfile& v, const std::vector<double>& installed_kg,
                                  const std::vector<PointRecommendation>& changes) {
  WeightMapModel m;
  m.length_m = v.hull.length_m;
  m.diameter_m = v.hull.diameter_m;
  m.cb_x_m = v.cb_m.x();
  m.cb_y_m = v.cb_m.y();
  m.grams = v.kind == "glider";
  double largest = 0.0;
  for (std::size_t i = 0; i < v.points.size(); ++i) {
    MapPoint p;
    p.name = v.points[i].name;
    p.label = v.points[i].label;
    p.x_m = v.points[i].position_m.x();
    p.y_m = v.points[i].position_m.y();
    p.installed_kg = i < installed_kg.size() ? installed_kg[i] : 0.0;
    for (const auto& r : changes) {
      if (r.name == p.name) {
        p.change = r.pieces;
        p.change_kg = r.add_kg;
      }
    }
    for (const auto& b : p.blocks()) largest = std::max(largest, b.mass_kg);
    m.points.push_back(p);
  }
  if (largest > 0 && m.px_per_sqrt_kg * std::sqrt(largest) < 10.0) m.px_per_sqrt_kg = 24.0 / std::sqrt(largest);
  return m;
}

}  // namespace auv::ui
