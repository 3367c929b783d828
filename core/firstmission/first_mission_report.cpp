#include "firstmission/first_mission_report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "common/units.h"

namespace auv {
namespace {

// Round for presentation in files: 1e-6 of the unit keeps sub-gram precision.
double r6(double v) { return std::round(v * 1e6) / 1e6; }

nlohmann::json mm3(const Eigen::Vector3d& m) {
  return {{"x", r6(units::mToMm(m.x()))}, {"y", r6(units::mToMm(m.y()))}, {"z", r6(units::mToMm(m.z()))}};
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v == 0.0 ? 0.0 : v);  // no "-0.00"
  return buf;
}

// Glider ballast is lead shot in grams, AUV kit pieces are kilograms.
std::string mass(double kg) { return std::abs(kg) < 0.1 ? fmt("%.0f g", kg * 1000.0) : fmt("%.2f kg", kg); }

std::string buoyancyWord(double net_kg) {
  if (std::abs(net_kg) < 0.0005) return "neutral";
  return net_kg > 0 ? "too light" : "too heavy";
}

}  // namespace

nlohmann::json toJson(const FirstMissionReport& r) {
  nlohmann::json points = nlohmann::json::array();
  for (const auto& p : r.points) {
    nlohmann::json pieces = nlohmann::json::array();
    for (const auto& pc : p.pieces) pieces.push_back({{"size_kg", r6(pc.size_kg)}, {"count", pc.count}});
    points.push_back({{"name", p.name}, {"label", p.label}, {"add_kg", r6(p.add_kg)}, {"pieces", pieces}});
  }
  nlohmann::json j;
  j["vehicle"] = r.vehicle_id;
  j["method"] = r.method;
  j["weight_kg"] = r6(r.weight_kg);
  j["buoyancy_kg"] = r6(r.buoyancy_kg);
  j["net_buoyancy_kg"] = r6(r.net_buoyancy_kg);
  j["cg_mm"] = mm3(r.cg_m);
  j["cg_sigma_mm"] = mm3(r.cg_sigma_m);
  j["cb_mm"] = mm3(r.cb_m);
  j["water"] = {{"temperature_degC", r.temperature_degC}, {"salinity_psu", r.salinity_psu},
                {"depth_m", r.depth_m}, {"pressure_dbar", r6(r.pressure_dbar)},
                {"density_kgm3", r6(r.density_kgm3)}};
  j["before"] = {{"pitch_deg", r6(r.pitch_before_deg)}, {"roll_deg", r6(r.roll_before_deg)}};
  j["recommendation"] = {{"points", points}};
  j["predicted"] = {{"net_buoyancy_kg", r6(r.predicted.net_buoyancy_kg)},
                    {"cg_offset_mm", {{"x", r6(units::mToMm(r.predicted.cg_offset_m.x()))},
                                      {"y", r6(units::mToMm(r.predicted.cg_offset_m.y()))}}},
                    {"pitch_deg", r6(r.predicted.pitch_deg)},
                    {"roll_deg", r6(r.predicted.roll_deg)}};
  j["warnings"] = r.warnings;
  j["notes"] = r.notes;
  if (!r.details.empty()) j["details"] = r.details;
  return j;
}

std::string toText(const FirstMissionReport& r) {
  std::ostringstream o;
  o << "Vehicle " << r.vehicle_id << " (" << r.method << " weighing)\n";
  o << "  water: " << fmt("%.2f", r.temperature_degC) << " degC, " << fmt("%.2f", r.salinity_psu) << " PSU, "
    << fmt("%.1f", r.depth_m) << " m -> density " << fmt("%.3f", r.density_kgm3) << " kg/m3\n";
  o << "  weight " << fmt("%.2f", r.weight_kg) << " kg, buoyancy " << fmt("%.2f", r.buoyancy_kg)
    << " kg, net buoyancy " << fmt("%+.3f", r.net_buoyancy_kg) << " kg (" << buoyancyWord(r.net_buoyancy_kg)
    << ")\n";
  const Eigen::Vector3d d = r.cg_m - r.cb_m;
  o << "  CG - CB: x " << fmt("%+.1f", units::mToMm(d.x())) << " mm, y " << fmt("%+.1f", units::mToMm(d.y()))
    << " mm, z " << fmt("%+.1f", units::mToMm(d.z())) << " mm; static pitch "
    << fmt("%+.2f", r.pitch_before_deg) << " deg, roll " << fmt("%+.2f", r.roll_before_deg) << " deg\n";
  o << "Recommendation:\n";
  for (const auto& p : r.points) {
    o << "  " << p.label << ": " << (p.add_kg > 0 ? "+" : p.add_kg < 0 ? "-" : "") << mass(std::abs(p.add_kg));
    std::string sep = " (";
    for (const auto& pc : p.pieces) {
      if (pc.count == 0) continue;
      o << sep << (pc.count > 0 ? "add " : "remove ") << std::abs(pc.count) << " x " << mass(pc.size_kg);
      sep = ", ";
    }
    if (sep == ", ") o << ")";
    o << "\n";
  }
  o << "Predicted after the change: net buoyancy " << fmt("%+.3f", r.predicted.net_buoyancy_kg)
    << " kg, CG - CB x " << fmt("%+.1f", units::mToMm(r.predicted.cg_offset_m.x())) << " mm, y "
    << fmt("%+.1f", units::mToMm(r.predicted.cg_offset_m.y())) << " mm, pitch "
    << fmt("%+.2f", r.predicted.pitch_deg) << " deg, roll " << fmt("%+.2f", r.predicted.roll_deg) << " deg\n";
  for (const auto& n : r.notes) o << "  note: " << n << "\n";
  for (const auto& w : r.warnings) o << "  WARNING: " << w << "\n";
  return o.str();
}

}  // namespace auv
