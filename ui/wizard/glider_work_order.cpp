#include "wizard/glider_work_order.h"

#include <cmath>

#include "common/input_error.h"
#include "widgets/inputs.h"
#include "wizard/advice_text.h"

namespace auv::ui {
namespace {


QString q(const std::string& s) { return QString::fromStdString(s); }

double num(const nlohmann::json& j, const char* k, double fallback = NAN) {
  return j.is_object() && j.contains(k) && j[k].is_number() ? j[k].get<double>() : fallback;
}

QString g0(double g) { return signedFixed(std::round(g) == 0.0 ? 0.0 : std::round(g), 0); }

// The plan's English lines in the wizard's words: "<list>_ids" holds each
// line's message id and arguments (core/planning/glider_plan_messages.h).
QStringList planLines(const nlohmann::json& p, const std::string& list) {
  const nlohmann::json lines = p.value(list, nlohmann::json::array());
  const nlohmann::json ids = p.value(list + "_ids", nlohmann::json::array());
  QStringList out;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string english = lines[i].get<std::string>();
    if (i < ids.size() && ids[i].is_object() && !ids[i].value("id", std::string()).empty())
      out << adviceText(Message(ids[i]["id"].get<std::string>(), english,
                                ids[i].value("args", std::vector<std::string>())));
    else
      out << q(english);
  }
  return out;
}

void slocumSteps(const nlohmann::json& p, GliderInstructions& out) {
  for (const auto& pt : p.value("points", nlohmann::json::array())) {
    const double add = std::round(num(pt, "add_g", 0.0));
    if (add == 0.0) continue;
    const QString label = q(pt.value("label", pt.value("name", std::string())));
    out.steps << (add > 0 ? GliderInstructions::tr("%1: add %2 g of lead shot (holds at most %3 g).")
                          : GliderInstructions::tr("%1: take out %2 g of lead shot (holds at most %3 g)."))
                     .arg(label)
                     .arg(fixed(std::abs(add), 0))
                     .arg(fixed(num(pt, "capacity_g", 0.0), 0));
  }
  out.steps << GliderInstructions::tr("Bow bottles %1 g, aft bottles %2 g: %3 g in all, in %4 g steps.")
                   .arg(g0(num(p, "bow_change_g", 0.0)), g0(num(p, "aft_change_g", 0.0)), g0(num(p, "total_change_g", 0.0)))
                   .arg(fixed(num(p, "resolution_g", 1.0), 0));
  if (p.contains("roll_trim")) {
    const auto& r = p["roll_trim"];
    const double g = std::abs(num(r, "rail_transfer_g", 0.0));
    out.steps << (std::round(g) == 0.0
                      ? GliderInstructions::tr("Roll %1° at zero roll command: no wing-rail change.").arg(signedFixed(num(r, "roll_deg", 0.0), 2))
                      : GliderInstructions::tr("Roll %1° at zero roll command: move %2 g from the %3 (included above).")
                            .arg(signedFixed(num(r, "roll_deg", 0.0), 2))
                            .arg(fixed(g, 0))
                            .arg(r.value("direction", std::string()) == "starboard rail -> port rail"
                                     ? GliderInstructions::tr("starboard wing rail to the port wing rail")
                                     : GliderInstructions::tr("port wing rail to the starboard wing rail")));
  }
  if (p.contains("pitch_trim")) {
    const auto& t = p["pitch_trim"];
    out.steps << GliderInstructions::tr("Pitch: level flight at pump zero needs the battery at %1 mm (centre of travel %2 mm); "
                       "the bow/aft split above brings it back to the centre.")
                     .arg(fixed(num(t, "battery_for_level_mm", 0.0), 1))
                     .arg(fixed(num(t, "battery_centre_mm", 0.0), 1));
  }
}

void seagliderSteps(const nlohmann::json& p, const VehicleProfile* v, GliderInstructions& out) {
  const auto& s = p["seaglider"];
  const double lead = num(s, "lead_change_g", 0.0);
  out.steps << (lead == 0.0 ? GliderInstructions::tr("Lead: no change (the VBD takes it).")
                : lead > 0  ? GliderInstructions::tr("Lead: add %1 g (%2 cm³ of lead).").arg(fixed(lead, 0)).arg(fixed(num(s, "lead_volume_cm3", 0.0), 1))
                            : GliderInstructions::tr("Lead: take off %1 g (%2 cm³ of lead).").arg(fixed(-lead, 0)).arg(fixed(-num(s, "lead_volume_cm3", 0.0), 1)));
  out.steps << GliderInstructions::tr("Set $C_VBD from %1 to %2 (VBD %3 cm³).")
                   .arg(fixed(num(s, "C_VBD_old", 0.0), 0))
                   .arg(fixed(num(s, "C_VBD_new", 0.0), 0))
                   .arg(signedFixed(num(s, "VBD_change_cm3", 0.0), 1));
  if (s.contains("C_PITCH_new")) {
    const nlohmann::json sg = v && v->sections.contains("seaglider") ? v->sections["seaglider"] : nlohmann::json::object();
    const double lo = num(sg, "PITCH_MIN", -1e9), hi = num(sg, "PITCH_MAX", 1e9), c = num(s, "C_PITCH_new", 0.0);
    if (c >= lo && c <= hi) {
      out.steps << GliderInstructions::tr("Set $C_PITCH from %1 to %2 (pitch mass for level flight at %3 mm).")
                       .arg(fixed(num(s, "C_PITCH_old", 0.0), 0))
                       .arg(fixed(c, 0))
                       .arg(fixed(num(s, "pitch_mass_for_level_mm", 0.0), 1));
    } else {
      // A count the pitch mass cannot reach: the log's pitch trim does not
      // fit this vehicle; asking for it would be a wrong instruction.
      out.steps << GliderInstructions::tr("Keep $C_PITCH at %1: the log's pitch trim gives %2, outside PITCH_MIN .. PITCH_MAX (%3 .. %4); "
                         "check the pitch trim on a test dive.")
                       .arg(fixed(num(s, "C_PITCH_old", 0.0), 0))
                       .arg(fixed(c, 0))
                       .arg(fixed(lo, 0))
                       .arg(fixed(hi, 0));
    }
  }
  out.steps << GliderInstructions::tr("Basis: %1.").arg(q(s.value("basis", std::string())));
}

}  // namespace

GliderInstructions gliderInstructions(const nlohmann::json& p, const VehicleProfile* v) {
  GliderInstructions out;
  if (!p.is_object()) return out;
  const double add = num(p, "mass_to_add_g", 0.0), sigma = num(p, "mass_to_add_sigma_g");
  const nlohmann::json t = p.value("target", nlohmann::json::object());
  const QString grams = std::isfinite(sigma) ? GliderInstructions::tr("%1 ± %2 g").arg(g0(add), fixed(sigma, 0)) : GliderInstructions::tr("%1 g").arg(g0(add));
  out.headline = GliderInstructions::tr("Mass to add %1 for neutral with the pump at zero in %2 kg/m³ water at %3 dbar, %4 °C.")
                     .arg(grams)
                     .arg(fixed(num(t, "density_kgm3", 0.0), 2))
                     .arg(fixed(num(t, "pressure_dbar", 0.0), 0))
                     .arg(fixed(num(t, "temperature_degC", 0.0), 2));
  out.target = GliderInstructions::tr("Target water: %1.").arg(q(t.is_object() ? t.value("basis", std::string()) : std::string()));
  const std::string type = p.value("vehicle_type", std::string());
  if (type == "slocum") {
    slocumSteps(p, out);
  } else if (type == "seaglider") {
    seagliderSteps(p, v, out);
  } else {
    out.steps << GliderInstructions::tr("Change the glider's mass by %1 g at its ballast places so that it stays level.").arg(g0(add));
    if (p.contains("linear_battery_for_level_mm"))
      out.steps << GliderInstructions::tr("Linear battery for level flight at pump zero: %1 mm.").arg(fixed(num(p, "linear_battery_for_level_mm", 0.0), 1));
  }
  out.cannot_tell = planLines(p, "cannot_tell");
  out.warnings = planLines(p, "warnings");
  return out;
}

WorkOrder makeGliderWorkOrder(const WizardState& s, TimePoint now) {
  if (!s.vehicle || !s.glider_plan.is_object())
    throw InputError("plan", "no glider answer yet", "go back to the glider pre-mission page");
  const VehicleProfile& v = *s.vehicle;
  const nlohmann::json& p = s.glider_plan;
  const GliderInstructions in = gliderInstructions(p, &v);
  WorkOrder w;
  w.title = WorkOrder::tr("Ballast work order");
  w.header << WorkOrder::tr("Vehicle: %1 (%2)").arg(q(v.name), q(v.id)) << WorkOrder::tr("Configuration: %1").arg(q(s.configuration_id))
           << WorkOrder::tr("Date: %1").arg(q(toIsoUtc(now)).replace('T', ' ').replace('Z', " UTC"));
  if (!s.log_file.empty()) w.header << GliderInstructions::tr("From the log: %1").arg(q(s.log_file).section('/', -1));
  w.water_title = WorkOrder::tr("Next mission's water");
  w.water << in.headline << in.target;
  // The printed table has six columns, the last the box to tick.
  w.columns = {GliderInstructions::tr("Place"), GliderInstructions::tr("Change"), GliderInstructions::tr("Pieces"), GliderInstructions::tr("Holds at most"), GliderInstructions::tr("Note"), WorkOrder::tr("Done")};
  double most_g = 0.0;
  for (const auto& pt : p.value("points", nlohmann::json::array())) {
    const double add = std::round(num(pt, "add_g", 0.0));
    most_g = std::max(most_g, std::abs(add));
    const double cap = num(pt, "capacity_g");
    const QString pieces = add == 0.0                    ? QString()
                           : p.value("vehicle_type", "") == "slocum" ? GliderInstructions::tr("%1 × 1 g lead shot").arg(fixed(std::abs(add), 0))
                                                                   : GliderInstructions::tr("%1 g lead").arg(fixed(std::abs(add), 0));
    w.rows.push_back({q(pt.value("label", pt.value("name", std::string()))), GliderInstructions::tr("%1 g").arg(g0(add)), pieces,
                      std::isfinite(cap) ? GliderInstructions::tr("%1 g").arg(fixed(cap, 0)) : QString(), QString(), QString()});
  }
  const double sigma = num(p, "mass_to_add_sigma_g");
  w.expected << (std::isfinite(sigma) ? GliderInstructions::tr("Neutral with the pump at zero in the water above, within ± %1 g (1 σ).").arg(fixed(sigma, 0))
                                      : GliderInstructions::tr("Neutral with the pump at zero in the water above."));
  w.notes = in.steps;
  for (const auto& c : in.cannot_tell) w.notes << GliderInstructions::tr("Cannot tell: %1").arg(c);
  w.warnings = in.warnings;
  // The top-down map of the same places: one square per place, 1 g pieces.
  w.map.length_m = v.hull.length_m;
  w.map.diameter_m = v.hull.diameter_m;
  w.map.cb_x_m = v.cb_m.x();
  w.map.cb_y_m = v.cb_m.y();
  w.map.grams = true;
  w.map.px_per_sqrt_kg = most_g > 0 ? 24.0 / std::sqrt(most_g / 1000.0) : 7.0;
  for (const auto& pt : p.value("points", nlohmann::json::array())) {
    const AdjustmentPoint* ap = v.findPoint(pt.value("name", std::string()));
    if (!ap) continue;
    MapPoint mp;
    mp.name = ap->name;
    mp.label = ap->label;
    mp.x_m = ap->position_m.x();
    mp.y_m = ap->position_m.y();
    // What the place holds now, when the history knows it.
    const auto idx = static_cast<std::size_t>(ap - v.points.data());
    mp.installed_kg = s.mission_installed_kg.size() == v.points.size() ? s.mission_installed_kg[idx] : NAN;
    const int g = static_cast<int>(std::round(num(pt, "add_g", 0.0)));
    if (g != 0) mp.change.push_back({0.001, g});
    mp.change_kg = g / 1000.0;
    w.map.points.push_back(mp);
  }
  if (w.map.points.empty()) w.map.length_m = 0.0;  // nothing to place: no map
  w.signature = WorkOrder::tr("Done by: ______________________   Signature: ______________________   Date: ____________");
  return w;
}

}  // namespace auv::ui
