#include <cmath>
#include <cstdio>
#include <sstream>

#include "common/units.h"
#include "planning/pre_mission_plan.h"

namespace auv {
namespace {

double r6(double v) { return std::round(v * 1e6) / 1e6; }

nlohmann::json waterJson(const PlannedWater& w, const WaterState& s) {
  return {{"temperature_degC", r6(w.temperature_degC)}, {"salinity_psu", r6(w.salinity_psu)},
          {"depth_m", r6(w.depth_m)}, {"pressure_dbar", r6(s.pressure_dbar)}, {"density_kgm3", r6(s.density_kgm3)}};
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v == 0.0 ? 0.0 : v);
  return buf;
}

}  // namespace

nlohmann::json toJson(const PreMissionPlan& p) {
  nlohmann::json points = nlohmann::json::array();
  for (const auto& pt : p.points) {
    nlohmann::json pieces = nlohmann::json::array();
    for (const auto& pc : pt.pieces) pieces.push_back({{"size_kg", r6(pc.size_kg)}, {"count", pc.count}});
    nlohmann::json j = {{"name", pt.name}, {"label", pt.label}, {"add_kg", r6(pt.add_kg)}, {"pieces", pieces}};
    points.push_back(j);
  }
  // Explanations belong to the points that change, in profile order.
  std::size_t e = 0;
  for (std::size_t i = 0; i < p.points.size() && e < p.explanations.size(); ++i) {
    if (!p.points[i].pieces.empty()) points[i]["explanation"] = p.explanations[e++];
  }
  const nlohmann::json predicted = {
      {"net_buoyancy_kg", r6(p.predicted.net_buoyancy_kg)},
      {"net_buoyancy_sigma_kg", r6(p.net_sigma_kg)},
      {"cg_offset_mm", {{"x", r6(units::mToMm(p.predicted.cg_offset_m.x()))},
                        {"y", r6(units::mToMm(p.predicted.cg_offset_m.y()))}}},
      {"pitch_deg", r6(p.predicted.pitch_deg)},
      {"pitch_sigma_deg", r6(p.pitch_sigma_deg)},
      {"roll_deg", r6(p.predicted.roll_deg)},
      {"roll_sigma_deg", r6(p.roll_sigma_deg)},
      {"in_band", {{"net_buoyancy", p.buoyancy_in_band}, {"pitch", p.pitch_in_band}, {"roll", p.roll_in_band}}},
      {"flight_pitch_deg", p.flight_pitch_after_deg ? nlohmann::json(r6(*p.flight_pitch_after_deg)) : nlohmann::json(nullptr)},
      {"flight_speed_mps", p.flight_speed_mps > 0.0 ? nlohmann::json(r6(p.flight_speed_mps)) : nlohmann::json(nullptr)},
      {"flight_pitch_in_band", p.flight_pitch_in_band ? nlohmann::json(*p.flight_pitch_in_band) : nlohmann::json(nullptr)}};
  nlohmann::json j;
  j["vehicle"] = p.vehicle_id;
  j["mode"] = "pre-mission";
  j["policy"] = toString(p.policy);
  j["recommendation"] = {{"policy", toString(p.policy)}, {"points", points}, {"predicted", predicted}};
  j["predicted"] = predicted;
  j["before"] = {{"net_buoyancy_kg", r6(p.net_before_kg)}, {"pitch_deg", r6(p.pitch_before_deg)},
                 {"roll_deg", r6(p.roll_before_deg)},
                 {"flight_pitch_deg", p.flight_pitch_before_deg ? nlohmann::json(r6(*p.flight_pitch_before_deg))
                                                                : nlohmann::json(nullptr)}};
  nlohmann::json at = nlohmann::json::array();
  for (const auto& r : p.at_points) {
    at.push_back({{"role", r.role}, {"water", waterJson(r.water, r.state)}, {"displaced_kg", r6(r.displaced_kg)},
                  {"net_before_kg", r6(r.net_before_kg)}, {"net_after_kg", r6(r.net_after_kg)}});
  }
  j["safety"] = {{"margin_kg", r6(p.margin_kg)},
                 {"sigma_kg", r6(p.net_sigma_kg)},
                 {"hull_law_sigma_kg", r6(p.hull_law_sigma_kg)},
                 {"rule", "net buoyancy after the move >= k * sigma at every planned point"},
                 {"band_kg", {r6(p.band_lo_kg), r6(p.band_hi_kg)}},
                 {"safe", p.safe},
                 {"points", at}};
  const TrimEstimate& es = p.estimate;
  j["estimate"] = {
      {"net_buoyancy_kg", r6(es.net_buoyancy_kg)},
      {"net_buoyancy_sigma_kg", r6(es.net_buoyancy_sigma_kg)},
      {"cg_offset_mm", {{"x", es.cg_x_m ? nlohmann::json(r6(units::mToMm(*es.cg_x_m))) : nlohmann::json()},
                        {"y", es.cg_y_m ? nlohmann::json(r6(units::mToMm(*es.cg_y_m))) : nlohmann::json()}}},
      {"water", {{"temperature_degC", r6(es.water.temperature_degC)}, {"salinity_psu", r6(es.salinity_psu)},
                 {"pressure_dbar", r6(es.water.pressure_dbar)}, {"density_kgm3", r6(es.water.density_kgm3)}}},
      {"mass_kg", r6(p.vehicle.mass.mass_kg)},
      {"mass_sigma_kg", r6(p.vehicle.mass_sigma_kg)}};
  j["water"] = waterJson(p.at_points.front().water, p.at_points.front().state);
  if (p.calibration_manoeuvre) j["calibration_manoeuvre"] = *p.calibration_manoeuvre;
  if (p.after_move_net_sigma_kg)
    j["after_move_expected_sigma"] = {{"net_buoyancy_kg", r6(*p.after_move_net_sigma_kg)},
                                      {"cg_x_mm", p.after_move_x_sigma_m ? nlohmann::json(r6(*p.after_move_x_sigma_m * 1e3))
                                                                         : nlohmann::json(nullptr)}};
  j["warnings"] = p.warnings;
  j["notes"] = p.notes;
  if (!p.details.empty()) j["details"] = p.details;
  return j;
}

std::string toText(const PreMissionPlan& p) {
  std::ostringstream o;
  o << "Pre-mission plan for " << p.vehicle_id << " (policy " << toString(p.policy) << ")\n";
  o << "Recommendation:\n";
  for (const auto& e : p.explanations) o << "  " << e << "\n";
  o << "Predicted at the operating depth: net buoyancy " << fmt("%+.2f", p.predicted.net_buoyancy_kg) << " +- "
    << fmt("%.2f", p.net_sigma_kg) << " kg, pitch " << fmt("%+.2f", p.predicted.pitch_deg) << " +- "
    << fmt("%.2f", p.pitch_sigma_deg) << " deg, roll " << fmt("%+.2f", p.predicted.roll_deg) << " +- "
    << fmt("%.2f", p.roll_sigma_deg) << " deg\n";
  if (p.flight_pitch_before_deg && p.flight_pitch_after_deg) {
    o << "Pitch in level flight at " << fmt("%.2f", p.flight_speed_mps) << " m/s: " << fmt("%+.2f", *p.flight_pitch_before_deg)
      << " deg now, " << fmt("%+.2f", *p.flight_pitch_after_deg) << " deg after the move\n";
  }
  o << "Safety (margin " << fmt("%.2f", p.margin_kg) << " kg):";
  for (const auto& r : p.at_points) {
    o << " " << r.role << " " << fmt("%+.2f", r.net_after_kg) << " kg;";
  }
  o << (p.safe ? " safe\n" : " NOT SAFE\n");
  for (const auto& n : p.notes) o << "  note: " << n << "\n";
  for (const auto& w : p.warnings) o << "  WARNING: " << w << "\n";
  return o.str();
}

}  // namespace auv
