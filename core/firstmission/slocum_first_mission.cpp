#include "firstmission/slocum_first_mission.h"

#include <cmath>
#include <cstdio>
#include <optional>

#include "common/input_error.h"
#include "common/units.h"
#include "firstmission/first_mission_messages.h"
#include "hydrostatics/static_trim.h"
#include "weighing/disk_weights.h"
#include "weighing/roll_correction.h"
#include "weighing/roll_test.h"
#include "weighing/slocum_layout.h"

namespace auv {
namespace {

namespace msg = firstmission::msg;

double toG(double kg) { return kg * 1000.0; }
double toMm(double m) { return units::mToMm(m); }
double r6(double v) { return std::round(v * 1e6) / 1e6; }

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
std::string gText(double kg) { return fmt("%.0f g", toG(kg)); }
std::string signedG(double kg) { return fmt("%+.0f g", toG(kg)); }

// G of the glider after replacing ballast `from` by `to` (mass M_before -> M_after).
Eigen::Vector2d movedCg(const SlocumLayout& L, double mb, double M_before, const Eigen::Vector2d& cg,
                        const SlocumBallast& from, const SlocumBallast& to, double M_after) {
  return (M_before * cg + movableMomentYZ(L, to, mb) - movableMomentYZ(L, from, mb)) / M_after;
}

nlohmann::json ballastJson(const SlocumLayout& L, const SlocumBallast& b) {
  nlohmann::json j;
  for (int i = 0; i < kSlocumItemCount; ++i) j[slocumItemName(static_cast<SlocumItem>(i))] = r6(toG(b.item_kg[static_cast<std::size_t>(i)]));
  for (std::size_t k = 0; k < 3; ++k) {
    j["disk_" + L.disks[k].name + "_top"] = r6(toG(b.disks[k].top_kg));
    j["disk_" + L.disks[k].name + "_bottom"] = r6(toG(b.disks[k].bottom_kg));
  }
  j["battery_angle_rad"] = r6(b.battery_angle_rad);
  return j;
}

nlohmann::json swappedJson(const SlocumLayout& L, const DiskArrangement& a) {
  nlohmann::json s = nlohmann::json::array();
  for (std::size_t k = 0; k < 3; ++k) {
    if (a.swap[k]) s.push_back(L.disks[k].name);
  }
  return s;
}

std::string side(double v, const char* pos, const char* neg) { return v >= 0.0 ? pos : neg; }

// One sentence for a pair of bottles changed by the tank step.
Message bottlePairNote(const MessageFormat& pair, SlocumItem a, SlocumItem c, const SlocumBallast& from,
                       const SlocumBallast& to, double scale_after_kg) {
  const double da = to.at(a) - from.at(a), dc = to.at(c) - from.at(c);
  return Message(pair, {signedG(da), slocumItemName(a), signedG(dc), slocumItemName(c), signedG(da + dc),
                        gText(scale_after_kg)});
}

FirstMissionReport compute(const VehicleProfile& v, const TankWeighing& w);

}  // namespace

FirstMissionReport slocumFirstMission(const VehicleProfile& v, const TankWeighing& w) {
  try {
    return compute(v, w);
  } catch (const InputError& e) {
    // The weighing checks name file fields but not the file; add it so the
    // operator sees "session.json: ballast_g.wing_rail_port: ...". Profile
    // errors ("slocum...") already carry the profile file.
    if (!e.where().file.empty() || w.file.empty()) throw;
    throw InputError(e.field(), e.problem(), e.fix(), {w.file, 0, 0});
  }
}

namespace {

FirstMissionReport compute(const VehicleProfile& v, const TankWeighing& w) {
  if (!w.vehicle.empty() && w.vehicle != v.id) {
    throw InputError("vehicle", "the weighing is for '" + w.vehicle + "' but the profile is '" + v.id + "'",
                     "choose --vehicle " + w.vehicle + " or correct \"vehicle\" in the file", {w.file, 0, 0});
  }
  const SlocumLayout L = slocumLayout(v);
  const double mb = w.battery_mass_kg.value_or(L.battery.mass_kg);
  validateBallast(L, w.ballast, "ballast_g", "roll_battery.angle_rad");

  // The scales hang directly above the bottles (report §4.1).
  const double x_fore = L.item(kForePort).position_m.x() - v.cb_m.x();
  const double x_aft = L.item(kAftUpper).position_m.x() - v.cb_m.x();
  const ScaleStations stations{x_fore, x_aft};

  // The report's step for the glider as weighed (kept for the record).
  const TankBuoyancy tank_weighed = tankBuoyancy(w.readings, v.hull, stations);
  const BottleStep step_weighed = planBottleStep(tank_weighed, w.readings, w.ballast, L);

  // "Now": as weighed, or as the technician set the bottles after the tank step.
  SlocumBallast now = w.ballast;
  TankReadings readings = w.readings;
  if (w.bottles_after_tank_step_kg) {
    for (int i = 0; i <= kAftLower; ++i) {
      const auto item = static_cast<SlocumItem>(i);
      const double set = (*w.bottles_after_tank_step_kg)[static_cast<std::size_t>(i)];
      readings = withAddedMass(readings, stations, set - now.at(item), i <= kForeStarboard ? x_fore : x_aft);
      now.at(item) = set;
    }
    validateBallast(L, now, "after_tank_step_g", "roll_battery.angle_rad");
  }
  const TankBuoyancy tank = tankBuoyancy(readings, v.hull, stations);
  const BottleStep step = planBottleStep(tank, readings, now, L);
  const double M_now = readings.dry_mass_kg;
  const double M = step.mass_after_kg;

  // Cross-section G relative to the hull axis: measured by the roll test, or
  // the profile's nominal BG straight below B.
  Eigen::Vector2d cg_now(0.0, v.bg_m);
  std::optional<RollTestResult> test;
  if (w.roll_test) {
    test = analyseRollTest(w.roll_test->resolve(L.hull_radius_m), M_now);
    cg_now = test->cg_yz_m;
  }
  const Eigen::Vector2d cg_step = movedCg(L, mb, M_now, cg_now, now, step.after, M);

  SlocumBallast final_b = step.after;
  Eigen::Vector2d cg_final = cg_step;
  std::optional<RollCorrection> roll;
  std::optional<HArmCorrection> harm;
  if (test) {
    roll = correctRoll(L, step.after, mb, M, cg_step);
    const RollOption& ro = roll->best();
    harm = correctHArm(L, ro.after, M, ro.cg_yz_m[1]);
    final_b = harm->best().after;
    cg_final = movedCg(L, mb, M, ro.cg_yz_m, ro.after, final_b, M);
  }
  // Lateral and vertical moves keep every mass at its x, so only the tank
  // step changes the longitudinal CG: moments of the predicted readings.
  const double x_now = tank.cg_x_from_cb_m;
  const double x_final = (step.bow_scale_after_kg * x_fore + step.aft_scale_after_kg * x_aft) / M;
  const Eigen::Vector3d off_now(x_now, cg_now[0], cg_now[1]);
  const Eigen::Vector3d off_final(x_final, cg_final[0], cg_final[1]);
  const StaticTrim trim_now = staticTrimFromOffset(off_now);
  const StaticTrim trim_final = staticTrimFromOffset(off_final);

  FirstMissionReport r;
  r.vehicle_id = v.id;
  r.method = "tank";
  r.weight_kg = M_now;
  r.buoyancy_kg = tank.target_neutral_mass_kg;
  r.net_buoyancy_kg = r.buoyancy_kg - r.weight_kg;
  r.cb_m = v.cb_m;
  r.cg_m = v.cb_m + off_now;
  r.temperature_degC = readings.target.temperature_degC;
  r.salinity_psu = w.target_salinity_psu;
  r.pressure_dbar = readings.target_pressure_dbar;
  r.density_kgm3 = readings.target.density_kgm3;
  r.pitch_before_deg = units::radToDeg(trim_now.pitch_rad);
  r.roll_before_deg = units::radToDeg(trim_now.roll_rad);

  for (const AdjustmentPoint& p : v.points) {
    PointRecommendation pr;
    pr.name = p.name;
    pr.label = p.label;
    for (int i = 0; i < kSlocumItemCount; ++i) {
      const auto item = static_cast<SlocumItem>(i);
      if (p.name != slocumItemName(item)) continue;
      pr.add_kg = final_b.at(item) - now.at(item);
      const long n = std::lround(pr.add_kg / L.mass_resolution_kg);
      if (n != 0) pr.pieces.push_back({L.mass_resolution_kg, static_cast<int>(n)});
    }
    r.points.push_back(pr);
  }
  r.predicted.net_buoyancy_kg = step.net_buoyancy_after_kg;
  r.predicted.cg_offset_m = off_final.head<2>();
  r.predicted.pitch_deg = units::radToDeg(trim_final.pitch_rad);
  r.predicted.roll_deg = units::radToDeg(trim_final.roll_rad);

  // --- notes: one sentence per finding or change ---
  r.notes.push_back(Message(
      msg::kTankDisplaces,
      {fmt("%.1f kg/m3", readings.tank.density_kgm3), fmt("%.1f degC", readings.tank.temperature_degC),
       fmt("%.4f kg", tank.tank_neutral_mass_kg), fmt("%.6f m3", tank.volume_tank_m3),
       fmt("%.1f degC", readings.target.temperature_degC), fmt("%.6f m3", tank.volume_target_m3),
       fmt("%.4f kg", tank.target_neutral_mass_kg), fmt("%.1f kg/m3", readings.target.density_kgm3)}));
  r.notes.push_back(Message(r.net_buoyancy_kg >= 0 ? msg::kWeighsLight : msg::kWeighsHeavy,
                            {fmt("%.3f kg", M_now), fmt("%.1f g", toG(std::abs(r.net_buoyancy_kg))),
                             signedG(step.total_change_kg)}));
  if (step.after.at(kForePort) != now.at(kForePort) || step.after.at(kForeStarboard) != now.at(kForeStarboard)) {
    r.notes.push_back(bottlePairNote(msg::kBowBottles, kForePort, kForeStarboard, now, step.after, step.bow_scale_after_kg));
  }
  if (step.after.at(kAftUpper) != now.at(kAftUpper) || step.after.at(kAftLower) != now.at(kAftLower)) {
    r.notes.push_back(bottlePairNote(msg::kAftBottles, kAftUpper, kAftLower, now, step.after, step.aft_scale_after_kg));
  }
  r.warnings.assign(step.warnings.begin(), step.warnings.end());

  if (!test) {
    r.notes.push_back(Message(msg::kNoRollTest));
  } else {
    r.warnings.insert(r.warnings.end(), test->warnings.begin(), test->warnings.end());
    r.notes.push_back(Message(msg::kRollTest, {fmt("%.2f mm", toMm(test->h_m)), std::to_string(test->h_each_m.size()),
                                               fmt("%.2f mm", toMm(std::abs(cg_now[0]))),
                                               side(cg_now[0], "starboard", "port"), fmt("%.2f mm", toMm(cg_now[1]))}));
    const RollOption& ro = roll->best();
    if (std::abs(ro.rail_shift_kg) > 0.0) {
      r.notes.push_back(Message(msg::kMoveRail, {gText(std::abs(ro.rail_shift_kg)),
                                                 side(ro.rail_shift_kg, "port to the starboard", "starboard to the port")}));
    }
    if (std::abs(ro.bottle_shift_kg) > 0.0) {
      r.notes.push_back(Message(ro.method == RollMethod::RailsAndBottles ? msg::kMoveBowBottleRails : msg::kMoveBowBottle,
                                {gText(std::abs(ro.bottle_shift_kg)),
                                 side(ro.bottle_shift_kg, "port to the starboard", "starboard to the port")}));
    }
    r.notes.push_back(Message(msg::kRollBattery, {fmt("%+.4f rad", ro.battery_angle_rad),
                                                  fmt("%+.2f deg", units::radToDeg(ro.battery_angle_rad)),
                                                  side(ro.battery_angle_rad, "starboard", "port"),
                                                  fmt("%+.4f rad", now.battery_angle_rad)}));
    if (roll->chosen < 0) {
      r.warnings.push_back(
          Message(msg::kRollRemains, {fmt("%.2f deg", units::radToDeg(std::atan2(ro.cg_yz_m[0], ro.cg_yz_m[1])))}));
    }
    const DiskArrangement& da = harm->best();
    for (std::size_t k = 0; k < 3; ++k) {
      if (!da.swap[k]) continue;
      const DiskSeats& s = ro.after.disks[k];
      const double dz = (s.top_kg - s.bottom_kg) * (L.disks[k].bottom_z_m - L.disks[k].top_z_m) / M;
      r.notes.push_back(Message(msg::kSwapDisks, {L.disks[k].name, gText(s.top_kg), gText(s.bottom_kg),
                                                  dz >= 0 ? "lowers" : "raises", fmt("%.2f mm", toMm(std::abs(dz)))}));
    }
    if (std::abs(da.aft_shift_kg) > 0.0) {
      r.notes.push_back(Message(msg::kMoveAftBottle, {gText(std::abs(da.aft_shift_kg)),
                                                      side(da.aft_shift_kg, "lower to the upper", "upper to the lower"),
                                                      fmt("%.2f mm", toMm(da.h_after_swap_m)), fmt("%.2f mm", toMm(da.h_m)),
                                                      fmt("%.2f mm", toMm(harm->target_m))}));
    }
    if (!da.reaches_target) {
      r.warnings.push_back(Message(msg::kHArmUnreachable, {fmt("%.2f mm", toMm(harm->target_m)),
                                                           fmt("%.2f mm", toMm(da.h_m)), std::to_string(da.number)}));
    }
  }

  if (r.predicted.net_buoyancy_kg < v.spec.net_buoyancy_min_kg - 1e-9) {
    r.warnings.push_back(Message(msg::kEndsHeavy, {fmt("%+.1f g", toG(r.predicted.net_buoyancy_kg))}));
  } else if (r.predicted.net_buoyancy_kg > v.spec.net_buoyancy_max_kg + 1e-9) {
    r.warnings.push_back(Message(msg::kAboveBand, {fmt("%+.1f g", toG(r.predicted.net_buoyancy_kg))}));
  }
  if (std::abs(r.predicted.pitch_deg) > v.spec.pitch_tolerance_deg) {
    r.warnings.push_back(
        Message(msg::kPitchOutside, {fmt("%+.2f deg", r.predicted.pitch_deg), fmt("%.2f deg", v.spec.pitch_tolerance_deg)}));
  }
  if (std::abs(r.predicted.roll_deg) > v.spec.roll_tolerance_deg) {
    r.warnings.push_back(
        Message(msg::kRollOutside, {fmt("%+.2f deg", r.predicted.roll_deg), fmt("%.2f deg", v.spec.roll_tolerance_deg)}));
  }

  // --- Slocum specifics ---
  nlohmann::json& d = r.details;
  d["glider"] = w.glider;
  d["state"] = w.bottles_after_tank_step_kg ? "after_tank_step" : "as_weighed";
  d["tank"] = {{"scale_total_g", r6(toG(tank_weighed.scale_total_kg))},
               {"tank_neutral_mass_kg", r6(tank_weighed.tank_neutral_mass_kg)},
               {"volume_tank_m3", r6(tank_weighed.volume_tank_m3 * 1e3) / 1e3},
               {"volume_target_m3", r6(tank_weighed.volume_target_m3 * 1e3) / 1e3},
               {"target_neutral_mass_kg", r6(tank_weighed.target_neutral_mass_kg)},
               {"mass_change_g", r6(toG(tank_weighed.mass_change_kg))},
               {"bow_change_g", r6(toG(tank_weighed.bow_change_kg))},
               {"aft_change_g", r6(toG(tank_weighed.aft_change_kg))},
               {"level_scale_g", {{"bow", r6(toG(tank_weighed.level_bow_scale_kg))}, {"aft", r6(toG(tank_weighed.level_aft_scale_kg))}}},
               {"recommended_bottles_g", ballastJson(L, step_weighed.after)},
               {"thermal_expansion_per_degC", v.hull.thermal_expansion_per_degC},
               {"tank_density_kgm3", w.readings.tank.density_kgm3},
               {"tank_temperature_degC", w.readings.tank.temperature_degC}};
  d["expected_tank_readings_g"] = {{"bow", r6(toG(step.bow_scale_after_kg))}, {"aft", r6(toG(step.aft_scale_after_kg))}};
  d["mass_after_kg"] = r6(M);
  d["ballast_now_g"] = ballastJson(L, now);
  d["ballast_final_g"] = ballastJson(L, final_b);
  d["battery"] = {{"mass_kg", mb}, {"radius_m", L.battery.radius_m}, {"max_angle_rad", L.battery.max_angle_rad},
                  {"angle_now_rad", now.battery_angle_rad}, {"angle_rad", r6(final_b.battery_angle_rad)},
                  {"angle_deg", r6(units::radToDeg(final_b.battery_angle_rad))}};
  d["cg_z_source"] = test ? "roll test (report 4.2)" : "profile bg_mm (no roll test)";
  if (test) {
    nlohmann::json each = nlohmann::json::array();
    for (double h : test->h_each_m) each.push_back(r6(toMm(h)));
    d["roll_test"] = {{"initial_roll_rad", test->initial_roll_rad}, {"glider_mass_kg", r6(M_now)},
                      {"h_each_mm", each}, {"h_mm", r6(toMm(test->h_m))}, {"spread_mm", r6(toMm(test->spread_m))},
                      {"cg_y_mm", r6(toMm(cg_now[0]))}, {"cg_z_mm", r6(toMm(cg_now[1]))}};
    nlohmann::json opts = nlohmann::json::array();
    for (const RollOption& o : roll->options) {
      opts.push_back({{"method", rollMethodName(o.method)}, {"feasible", o.feasible},
                      {"battery_angle_rad", r6(o.battery_angle_rad)}, {"rail_shift_g", r6(toG(o.rail_shift_kg))},
                      {"bottle_shift_g", r6(toG(o.bottle_shift_kg))}, {"h_mm", r6(toMm(o.cg_yz_m[1]))}});
    }
    const RollOption& ro = roll->best();
    d["roll_correction"] = {{"method", roll->chosen >= 0 ? rollMethodName(ro.method) : "none_reaches_zero_roll"},
                            {"battery_angle_rad", r6(ro.battery_angle_rad)},
                            {"battery_angle_deg", r6(units::radToDeg(ro.battery_angle_rad))},
                            {"rail_shift_g", r6(toG(ro.rail_shift_kg))}, {"bottle_shift_g", r6(toG(ro.bottle_shift_kg))},
                            {"h_after_mm", r6(toMm(ro.cg_yz_m[1]))}, {"options", opts}};
    nlohmann::json arr = nlohmann::json::array();
    for (const DiskArrangement& a : harm->arrangements) {
      arr.push_back({{"number", a.number}, {"swapped", swappedJson(L, a)}, {"h_after_swap_mm", r6(toMm(a.h_after_swap_m))},
                     {"aft_shift_up_g", r6(toG(a.aft_shift_kg))}, {"h_mm", r6(toMm(a.h_m))},
                     {"reaches_target", a.reaches_target}});
    }
    const DiskArrangement& da = harm->best();
    d["h_arm"] = {{"target_mm", r6(toMm(harm->target_m))}, {"before_mm", r6(toMm(harm->h_before_m))},
                  {"after_mm", r6(toMm(da.h_m))}, {"reached", da.reaches_target}, {"arrangement", da.number},
                  {"swapped_disks", swappedJson(L, da)}, {"aft_shift_up_g", r6(toG(da.aft_shift_kg))},
                  {"arrangements", arr}};
  }
  return r;
}

}  // namespace
}  // namespace auv
