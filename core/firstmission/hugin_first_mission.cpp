#include "firstmission/hugin_first_mission.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>

#include "ballast/ballast_solver.h"
#include "common/input_error.h"
#include "common/units.h"
#include "firstmission/first_mission_messages.h"
#include "hydrostatics/balance.h"
#include "vehicle/installed_check.h"

namespace auv {
namespace {

std::string kgText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f kg", v);
  return buf;
}

std::vector<double> usableSizes(const VehicleProfile& v, bool optional) {
  std::vector<double> s = v.kit.pieces_kg;
  if (optional) s.insert(s.end(), v.kit.optional_pieces_kg.begin(), v.kit.optional_pieces_kg.end());
  std::sort(s.begin(), s.end());
  s.erase(std::unique(s.begin(), s.end()), s.end());
  return s;
}

}  // namespace

std::vector<int> decomposeInstalled(double mass_kg, const std::vector<double>& sizes,
                                    const std::string& point_name) {
  const std::string field = "installed." + point_name;
  if (!std::isfinite(mass_kg) || mass_kg < 0.0) {
    throw InputError(field, "installed mass must be a number >= 0", "give the kg of adjustment weight at the point");
  }
  // Fewest pieces summing to the mass, exact in grams (dynamic programming):
  // the operator typed a total, we need the pieces to know what can come out.
  const long target = std::lround(mass_kg * 1000.0);
  std::vector<long> grams;
  for (double s : sizes) grams.push_back(std::lround(s * 1000.0));
  std::vector<int> best(static_cast<std::size_t>(target) + 1, INT_MAX);
  std::vector<int> via(best.size(), -1);
  best[0] = 0;
  for (long m = 1; m <= target; ++m) {
    for (std::size_t k = 0; k < grams.size(); ++k) {
      const long prev = m - grams[k];
      if (prev < 0 || best[static_cast<std::size_t>(prev)] == INT_MAX) continue;
      const int n = best[static_cast<std::size_t>(prev)] + 1;
      if (n < best[static_cast<std::size_t>(m)]) {
        best[static_cast<std::size_t>(m)] = n;
        via[static_cast<std::size_t>(m)] = static_cast<int>(k);
      }
    }
  }
  if (best[static_cast<std::size_t>(target)] == INT_MAX) {
    std::string kit;
    for (double s : sizes) kit += (kit.empty() ? "" : ", ") + kgText(s);
    throw InputError(field, kgText(mass_kg) + " is not a sum of kit pieces (" + kit + ")",
                     "enter the installed mass as a sum of the kit's piece sizes");
  }
  std::vector<int> counts(sizes.size(), 0);
  for (long m = target; m > 0; m -= grams[static_cast<std::size_t>(via[static_cast<std::size_t>(m)])]) {
    ++counts[static_cast<std::size_t>(via[static_cast<std::size_t>(m)])];
  }
  return counts;
}

FirstMissionReport craneFirstMission(const VehicleProfile& vehicle, CraneFirstMissionInput in) {
  if (vehicle.points.empty()) {
    throw InputError("vehicle", "profile '" + vehicle.id + "' has no adjustment points",
                     "add adjustment_points to the vehicle profile");
  }
  if (!in.installed_kg.empty()) checkInstalledKg(vehicle, in.installed_kg, "installed");
  in.weighing.cg_z_m = vehicle.cb_m.z() + vehicle.bg_m;
  const CraneResult crane = weighCrane(in.weighing);
  const WaterState water = resolveWater(in.water);
  const Balance before = computeBalance(crane.mass, vehicle.hull, vehicle.cb_m, water);

  BallastProblem problem;
  problem.vehicle = crane.mass;
  problem.displaced_mass_kg = before.buoyancy_kg;
  problem.cb_m = vehicle.cb_m;
  problem.points = vehicle.points;
  problem.piece_sizes_kg = usableSizes(vehicle, in.use_optional_pieces);
  problem.spec = vehicle.spec;
  problem.policy = in.policy;
  for (std::size_t i = 0; i < in.installed_kg.size(); ++i) {
    problem.installed.push_back(decomposeInstalled(in.installed_kg[i], problem.piece_sizes_kg, vehicle.points[i].name));
  }
  const BallastSolution sol = solveBallast(problem);

  FirstMissionReport r;
  r.vehicle_id = vehicle.id;
  r.method = "crane";
  r.weight_kg = before.mass_kg;
  r.buoyancy_kg = before.buoyancy_kg;
  r.net_buoyancy_kg = before.net_buoyancy_kg;
  r.cg_m = before.cg_m;
  r.cg_sigma_m = crane.cg_sigma_m;
  r.cb_m = before.cb_m;
  r.temperature_degC = in.water.temperature_degC;
  r.salinity_psu = in.water.salinity_psu;
  r.depth_m = in.water.depth_m;
  r.pressure_dbar = water.pressure_dbar;
  r.density_kgm3 = water.density_kgm3;
  r.pitch_before_deg = units::radToDeg(before.trim.pitch_rad);
  r.roll_before_deg = units::radToDeg(before.trim.roll_rad);
  for (std::size_t p = 0; p < vehicle.points.size(); ++p) {
    PointRecommendation pr;
    pr.name = vehicle.points[p].name;
    pr.label = vehicle.points[p].label;
    pr.add_kg = sol.add_kg[p];
    for (std::size_t k = 0; k < problem.piece_sizes_kg.size(); ++k) {
      if (sol.delta[p][k] != 0) pr.pieces.push_back({problem.piece_sizes_kg[k], sol.delta[p][k]});
    }
    r.points.push_back(pr);
  }
  r.predicted.net_buoyancy_kg = sol.net_buoyancy_kg;
  r.predicted.cg_offset_m = (sol.cg_m - vehicle.cb_m).head<2>();
  r.predicted.pitch_deg = sol.pitch_deg;
  r.predicted.roll_deg = sol.roll_deg;
  r.warnings.assign(crane.warnings.begin(), crane.warnings.end());
  r.warnings.insert(r.warnings.end(), sol.warnings.begin(), sol.warnings.end());
  r.notes = sol.notes;
  if (!before.trim.stable) {
    r.warnings.push_back(Message(firstmission::msg::kCapsizeProfileBg));
  }
  r.details = {{"rope_x_m", {in.weighing.rope_x_fore_m, in.weighing.rope_x_aft_m}},
               {"rope_y_m", in.weighing.rope_y_m},
               {"sum_of_parts_kg", crane.sum_of_parts_kg},
               {"bg_mm", units::mToMm(vehicle.bg_m)},
               {"cg_z_source", "profile: z_CB + bg_mm (hanging cannot observe CG height)"},
               {"in_band", {{"net_buoyancy", sol.buoyancy_in_band}, {"pitch", sol.pitch_in_band},
                            {"roll", sol.roll_in_band}}}};
  return r;
}

}  // namespace auv
