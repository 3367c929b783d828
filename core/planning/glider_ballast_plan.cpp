#include "planning/glider_ballast_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/input_error.h"
#include "common/units.h"
#include "planning/glider_plan_messages.h"
#include "seawater/seawater.h"
#include "vehicle/json_reader.h"
#include "weighing/slocum_layout.h"
#include "weighing/tank_weighing.h"

namespace auv {

namespace {

namespace msg = planning::msg;

constexpr double kLeadDensity_kgm3 = 11296.0;  // basestation's lead, 11.296 g/cm3

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

const nlohmann::json* find(const nlohmann::json& j, std::initializer_list<const char*> path) {
  const nlohmann::json* x = &j;
  for (const char* k : path) {
    if (!x->is_object() || !x->contains(k) || (*x)[k].is_null()) return nullptr;
    x = &(*x)[k];
  }
  return x;
}

double number(const nlohmann::json& j, std::initializer_list<const char*> path, double fallback) {
  const nlohmann::json* x = find(j, path);
  return x && x->is_number() ? x->get<double>() : fallback;
}

// The report's glider pitch trim (analysis details.glider_trim.pitch).
struct Trim {
  bool known = false;
  double T1 = 0, T2 = 0, T3 = 0;
};
Trim trimOf(const nlohmann::json& r) {
  Trim t;
  const nlohmann::json* p = find(r, {"details", "glider_trim", "pitch"});
  if (p && p->contains("T2_per_mm")) {
    t.known = true;
    t.T1 = (*p)["T1_per_cm3"].get<double>();
    t.T2 = (*p)["T2_per_mm"].get<double>();
    t.T3 = (*p)["T3"].get<double>();
  }
  return t;
}

void slocumPlan(const VehicleProfile& v, const GliderPlanInput& in, double add_kg, nlohmann::json& out) {
  const SlocumLayout L = slocumLayout(v);
  SlocumBallast now;
  const bool known = !in.installed_kg.empty();
  for (std::size_t i = 0; i < v.points.size() && known; ++i)
    for (int k = 0; k < kSlocumItemCount; ++k)
      if (v.points[i].name == slocumItemName(static_cast<SlocumItem>(k))) now.at(static_cast<SlocumItem>(k)) = in.installed_kg[i];
  if (!known) {
    // Unknown contents: half-full bottles and rails, so that both adding and
    // removing are possible; the capacity check is then only indicative.
    for (int k = 0; k < kSlocumItemCount; ++k) now.at(static_cast<SlocumItem>(k)) = 0.5 * L.item(static_cast<SlocumItem>(k)).capacity_kg;
    msg::addPlanLine(out, "warnings", Message(msg::kContentsUnknown));
  }
  const double xb = L.item(kForePort).position_m.x(), xa = L.item(kAftUpper).position_m.x();
  // Pitch moment the trim asks for: the battery sits at battery_for_level
  // for level flight at pump zero; moving that moment into the bottles brings
  // it back to the profile's centre of travel.
  const Trim t = trimOf(in.report);
  double moment_kgm = 0.0, battery_level_mm = 0.0;
  const double batt_kg = number(v.sections, {"glider_flight", "pitch_battery_mass_kg"}, 9.0);
  const double centre_mm = number(v.sections, {"glider_flight", "pitch_battery_centre_mm"}, 0.0);
  if (t.known) {
    battery_level_mm = -t.T3 / t.T2;
    moment_kgm = batt_kg * units::mmToM(battery_level_mm - centre_mm);
    out["pitch_trim"] = {{"battery_for_level_mm", battery_level_mm},
                         {"battery_centre_mm", centre_mm},
                         {"pitch_battery_mass_kg", batt_kg},
                         {"moment_to_bottles_kg_m", moment_kgm}};
  } else {
    msg::addPlanLine(out, "cannot_tell", Message(msg::kNoPitchTrim));
  }
  TankBuoyancy tb;
  tb.mass_change_kg = add_kg;
  tb.bow_share = -xa / (xb - xa);
  tb.bow_change_kg = add_kg * tb.bow_share + moment_kgm / (xb - xa);
  tb.aft_change_kg = add_kg - tb.bow_change_kg;
  tb.target_neutral_mass_kg = v.mass_kg + add_kg;
  TankReadings tr;
  tr.dry_mass_kg = v.mass_kg;
  BottleStep st = planBottleStep(tb, tr, now, L);
  // Roll: a port/starboard wing-rail transfer m bg sin(roll) = dm (y_s - y_p).
  double rail_kg = 0.0;
  if (const nlohmann::json* r = find(in.report, {"details", "glider_trim", "roll", "roll_deg"})) {
    const double roll = units::degToRad(r->get<double>());
    const double ys = L.item(kRailStarboard).position_m.y(), yp = L.item(kRailPort).position_m.y();
    const double bg = v.bg_m > 0 ? v.bg_m : L.target_h_arm_m;
    const double res = L.mass_resolution_kg;
    rail_kg = std::round(v.mass_kg * bg * std::sin(roll) / (ys - yp) / res) * res;  // from starboard to port when > 0
    const double maxMove = rail_kg > 0 ? std::min(st.after.at(kRailStarboard), L.item(kRailPort).capacity_kg - st.after.at(kRailPort))
                                       : std::min(st.after.at(kRailPort), L.item(kRailStarboard).capacity_kg - st.after.at(kRailStarboard));
    if (std::abs(rail_kg) > maxMove + 1e-12) {
      msg::addPlanLine(out, "warnings", Message(msg::kRailsShort, {fmt("%.0f", 1000 * std::abs(rail_kg))}));
      rail_kg = std::copysign(maxMove, rail_kg);
    }
    st.after.at(kRailStarboard) -= rail_kg;
    st.after.at(kRailPort) += rail_kg;
    out["roll_trim"] = {{"roll_deg", r->get<double>()}, {"bg_mm", units::mToMm(bg)}, {"rail_transfer_g", 1000 * rail_kg},
                        {"direction", rail_kg >= 0 ? "starboard rail -> port rail" : "port rail -> starboard rail"}};
  } else {
    msg::addPlanLine(out, "cannot_tell", Message(msg::kNoRoll));
  }
  nlohmann::json pts = nlohmann::json::array();
  for (int k = 0; k < kSlocumItemCount; ++k) {
    const auto item = static_cast<SlocumItem>(k);
    const AdjustmentPoint* p = v.findPoint(slocumItemName(item));
    pts.push_back({{"name", slocumItemName(item)},
                   {"label", p ? p->label : slocumItemName(item)},
                   {"add_g", std::round(1000 * (st.after.at(item) - now.at(item)))},
                   {"after_g", std::round(1000 * st.after.at(item))},
                   {"capacity_g", std::round(1000 * L.item(item).capacity_kg)}});
  }
  out["points"] = pts;
  out["bow_change_g"] = std::round(1000 * st.bow_change_kg);
  out["aft_change_g"] = std::round(1000 * st.aft_change_kg);
  out["total_change_g"] = std::round(1000 * st.total_change_kg);
  out["resolution_g"] = 1000 * L.mass_resolution_kg;
  for (const auto& w : st.warnings) msg::addPlanLine(out, "warnings", Message(w));
}

void seagliderPlan(const VehicleProfile& v, const GliderPlanInput& in, double add_kg, double rho_t, nlohmann::json& out) {
  const JsonReader s(v.sections.at("seaglider"), v.file, "seaglider");
  const double cnv = s.numberIn("VBD_CNV_cm3_per_count", -10.0, 10.0, -0.2453);
  const double cvbd = s.numberIn("C_VBD", 0.0, 5000.0);
  const double vmin = s.numberIn("VBD_MIN", 0.0, 5000.0), vmax = s.numberIn("VBD_MAX", 0.0, 5000.0);
  const double margin = s.numberIn("VBD_margin_cm3", 0.0, 1000.0, 150.0);
  const double cpitch = s.numberIn("C_PITCH", 0.0, 5000.0);
  const double pcnv = s.numberIn("PITCH_CNV_cm_per_count", -1.0, 1.0, 0.00313);
  // Neutral at the target with the VBD at C_VBD needs the volume to shrink by
  // add/rho_t (add > 0: too light). The counts grow as the volume shrinks
  // (VBD_CNV < 0). Lead first only when C_VBD would leave its allowed range.
  auto countsFor = [&](double dV_cm3) { return dV_cm3 / cnv; };
  const double lo = std::min(vmin, vmax) + std::abs(margin / cnv), hi = std::max(vmin, vmax) - std::abs(margin / cnv);
  double lead_kg = 0.0;
  double dV_cm3 = -add_kg / rho_t * 1e6;
  double newC = cvbd + countsFor(dV_cm3);
  if (newC < lo || newC > hi) {
    // Lead brings C_VBD back to the nearest allowed count: each kg of lead
    // is (1 - rho_t / rho_lead) kg of weight in water.
    const double targetC = std::clamp(newC, lo, hi);
    const double dV_wanted = (targetC - cvbd) * cnv;  // cm3 the VBD will take
    const double left_kg = add_kg + dV_wanted * 1e-6 * rho_t;  // still to add as weight in water
    lead_kg = left_kg / (1.0 - rho_t / kLeadDensity_kgm3);
    dV_cm3 = dV_wanted;
    newC = targetC;
  }
  const double lead_g = std::round(lead_kg * 1000.0);
  out["seaglider"] = {{"basis", "basestation ballast calculation: VBD " + fmt("%.4f", cnv) + " cm3 per count, lead " +
                                    fmt("%.3f", kLeadDensity_kgm3 / 1000) + " g/cm3; C_VBD kept " + fmt("%.0f", margin) +
                                    " cm3 inside VBD_MIN..VBD_MAX"},
                      {"lead_change_g", lead_g},
                      {"lead_volume_cm3", lead_g / (kLeadDensity_kgm3 / 1000)},
                      {"C_VBD_old", cvbd},
                      {"C_VBD_new", std::round(newC)},
                      {"VBD_change_cm3", dV_cm3}};
  const Trim t = trimOf(in.report);
  if (t.known) {
    // Level at the new VBD zero: tan(pitch) = T1 dV + T2 b + T3 = 0, b in the
    // interchange sign (forward positive) = -(AD - C_PITCH) PITCH_CNV 10.
    const double b = -(t.T3 + t.T1 * dV_cm3) / t.T2;
    const double newPitch = cpitch - b / (10.0 * pcnv);
    out["seaglider"]["C_PITCH_old"] = cpitch;
    out["seaglider"]["C_PITCH_new"] = std::round(newPitch);
    out["seaglider"]["pitch_mass_for_level_mm"] = b;
  } else {
    msg::addPlanLine(out, "cannot_tell", Message(msg::kNoCPitch));
  }
  out["points"] = nlohmann::json::array();
  if (lead_g != 0.0) out["points"].push_back({{"name", "lead"}, {"label", "Lead ballast"}, {"add_g", lead_g}});
}

}  // namespace

std::optional<double> massToAddAtTargetKg(const nlohmann::json& r, const analysis::GliderTarget& t) {
  const nlohmann::json* gb = find(r, {"model_check", "glider_ballast"});
  if (gb && gb->contains("hull_volume_m3")) {
    return analysis::gliderMassToAddKg(number(*gb, {"hull_volume_m3"}, 0), number(*gb, {"compressibility_per_dbar"}, 0),
                                       number(*gb, {"thermal_expansion_per_degC"}, 0),
                                       number(*gb, {"reference_temperature_degC"}, 20), t, number(*gb, {"mass_now_kg"}, 0));
  }
  const nlohmann::json* f = find(r, {"details", "glider_fit"});
  if (!f || !f->contains("hull_volume_m3")) return std::nullopt;
  return analysis::gliderMassToAddKg(number(*f, {"hull_volume_m3"}, 0), number(*f, {"constants", "compressibility_per_dbar"}, 0),
                                     number(*f, {"constants", "thermal_expansion_per_degC"}, 0),
                                     number(*f, {"constants", "reference_temperature_degC"}, 20), t, number(*f, {"mass_kg"}, 0));
}

nlohmann::json planGliderBallast(const VehicleProfile& v, const GliderPlanInput& in) {
  nlohmann::json out;
  for (const char* list : {"warnings", "warnings_ids", "cannot_tell", "cannot_tell_ids"}) out[list] = nlohmann::json::array();
  double add_kg = 0.0, sigma_kg = 0.0;
  nlohmann::json target = in.report.value("target", nlohmann::json());
  if (in.target) {
    const std::optional<double> a = massToAddAtTargetKg(in.report, *in.target);
    if (!a) throw InputError("report", "has no fitted glider hull volume to carry to another water",
                             "give an analysis or model-check report of a glider log");
    add_kg = *a;
    target = {{"density_kgm3", in.target->density_kgm3}, {"pressure_dbar", in.target->pressure_dbar},
              {"temperature_degC", in.target->temperature_degC}, {"basis", in.target->basis}};
  } else {
    const nlohmann::json* m = find(in.report, {"mass_to_add_g"});
    if (!m || !m->is_number())
      throw InputError("report", "has no glider mass_to_add_g (" + in.report.value("mass_to_add_why_not", std::string("not identified")) + ")",
                       "analyse a glider log with pitch, pump volume and depth");
    add_kg = m->get<double>() / 1000.0;
  }
  sigma_kg = number(in.report, {"mass_to_add_sigma_g"}, NAN) / 1000.0;
  out["mass_to_add_g"] = 1000 * add_kg;
  out["mass_to_add_sigma_g"] = std::isfinite(sigma_kg) ? nlohmann::json(1000 * sigma_kg) : nlohmann::json(nullptr);
  out["target"] = target;
  const double rho_t = target.is_object() ? number(target, {"density_kgm3"}, 1025.0) : 1025.0;
  if (v.sections.contains("slocum")) {
    out["vehicle_type"] = "slocum";
    slocumPlan(v, in, add_kg, out);
  } else if (v.sections.contains("seaglider")) {
    out["vehicle_type"] = "seaglider";
    seagliderPlan(v, in, add_kg, rho_t, out);
  } else {
    out["vehicle_type"] = v.sections.contains("seaexplorer") ? "seaexplorer" : "glider";
    const Trim t = trimOf(in.report);
    if (t.known) out["linear_battery_for_level_mm"] = -t.T3 / t.T2;
    out["points"] = nlohmann::json::array();
    msg::addPlanLine(out, "cannot_tell", Message(msg::kNoGeometry, {fmt("%+.0f", 1000 * add_kg)}));
    msg::addPlanLine(out, "cannot_tell", Message(msg::kNoZeroOffset));
  }
  return out;
}

analysis::GliderTarget targetFromReport(const nlohmann::json& r, const analysis::GliderTargetRequest& q, double latitude) {
  analysis::GliderTarget t;
  const nlohmann::json* base = find(r, {"target"});
  if (!base)
    throw InputError("report", "has no glider target", "give an analysis or model-check report of a glider log");
  t.density_kgm3 = number(*base, {"density_kgm3"}, NAN);
  t.pressure_dbar = number(*base, {"pressure_dbar"}, NAN);
  t.temperature_degC = number(*base, {"temperature_degC"}, NAN);
  t.salinity_psu = number(r, {"water", "salinity_psu"}, NAN);
  if (!q.any()) {
    t.basis = base->value("basis", std::string("the report's target"));
    return t;
  }
  if (q.depth_m) t.pressure_dbar = seawater::pressureFromDepth(*q.depth_m, latitude);
  if (q.pressure_dbar) t.pressure_dbar = *q.pressure_dbar;
  if (q.temperature_degC) t.temperature_degC = *q.temperature_degC;
  if (q.density_kgm3) {
    t.density_kgm3 = *q.density_kgm3;
  } else if (std::isfinite(t.salinity_psu)) {
    t.density_kgm3 = seawater::density(t.salinity_psu, t.temperature_degC, t.pressure_dbar);
  } else {
    throw InputError("target-density", "the report has no salinity to compute the target density from", "give --target-density KG_M3");
  }
  t.basis = "given on the command line; the rest from the report's target (" + base->value("basis", std::string("?")) + ")";
  if (!q.density_kgm3) t.basis += "; density from EOS-80 with the report's mean salinity " + fmt("%.3f", t.salinity_psu);
  return t;
}

std::string gliderPlanText(const nlohmann::json& p) {
  std::string o = "Glider ballast (" + p.value("vehicle_type", std::string("glider")) + "): add " +
                  fmt("%+.0f", p.value("mass_to_add_g", 0.0)) + " g";
  if (p["mass_to_add_sigma_g"].is_number()) o += " +- " + fmt("%.0f", p["mass_to_add_sigma_g"].get<double>()) + " g";
  if (p["target"].is_object())
    o += " for neutral (pump at zero) at " + fmt("%.2f", number(p["target"], {"density_kgm3"}, NAN)) + " kg/m3, " +
         fmt("%.0f", number(p["target"], {"pressure_dbar"}, NAN)) + " dbar, " +
         fmt("%.2f", number(p["target"], {"temperature_degC"}, NAN)) + " degC";
  o += "\n";
  for (const auto& x : p.value("points", nlohmann::json::array()))
    if (x.value("add_g", 0.0) != 0.0)
      o += "  " + x.value("label", x.value("name", std::string())) + ": " + fmt("%+.0f", x.value("add_g", 0.0)) + " g\n";
  if (p.contains("roll_trim"))
    o += "  roll " + fmt("%+.2f", p["roll_trim"]["roll_deg"].get<double>()) + " deg: " +
         fmt("%.0f", std::abs(p["roll_trim"]["rail_transfer_g"].get<double>())) + " g " +
         p["roll_trim"]["direction"].get<std::string>() + "\n";
  if (p.contains("seaglider")) {
    const auto& s = p["seaglider"];
    o += "  lead " + fmt("%+.0f", s["lead_change_g"].get<double>()) + " g; $C_VBD " + fmt("%.0f", s["C_VBD_old"].get<double>()) +
         " -> " + fmt("%.0f", s["C_VBD_new"].get<double>());
    if (s.contains("C_PITCH_new"))
      o += "; $C_PITCH " + fmt("%.0f", s["C_PITCH_old"].get<double>()) + " -> " + fmt("%.0f", s["C_PITCH_new"].get<double>());
    o += "\n";
  }
  if (p.contains("linear_battery_for_level_mm"))
    o += "  linear battery for level trim at pump zero: " + fmt("%.1f", p["linear_battery_for_level_mm"].get<double>()) + " mm\n";
  for (const auto& c : p["cannot_tell"]) o += "  cannot tell: " + c.get<std::string>() + "\n";
  for (const auto& w : p["warnings"]) o += "  warning: " + w.get<std::string>() + "\n";
  return o;
}

}  // namespace auv
