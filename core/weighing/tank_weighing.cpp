#include "weighing/tank_weighing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/input_error.h"
#include "weighing/weighing_messages.h"

namespace auv {
namespace {

void requireIn(double v, double lo, double hi, const char* field, const char* what) {
  if (!std::isfinite(v) || v < lo || v > hi) {
    char fix[160];
    std::snprintf(fix, sizeof fix, "give %s between %g and %g", what, lo, hi);
    throw InputError(field, "value is missing or out of range", fix);
  }
}

std::string grams(double kg) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f g", kg * 1000.0);
  return buf;
}

// Whole pieces: the operator weighs lead shot to the kit resolution. Readings
// are typed in whole grams, so exact halves are common; the nudge makes a
// half that floating point stored as 135.4999999 round like 135.5 (away
// from zero) every time.
double roundTo(double kg, double res) {
  const double n = kg / res;
  return std::round(n + std::copysign(1e-9, n)) * res;
}

// Shares `change` between two bottles (index a, b) half each, in whole
// pieces, spilling into the partner at a full or empty bottle. The caller has
// already limited `change` to what the pair can take.
void sharePair(SlocumBallast& b, const SlocumLayout& L, SlocumItem a, SlocumItem c, double change, double res) {
  const long n = std::lround(change / res);
  long na = n >= 0 ? n / 2 : -((-n + 1) / 2);  // floor(n / 2)
  double ma = b.at(a) + static_cast<double>(na) * res;
  double mc = b.at(c) + static_cast<double>(n - na) * res;
  auto spill = [](double& m, double& partner, double cap) {
    if (m > cap) { partner += m - cap; m = cap; }
    if (m < 0.0) { partner += m; m = 0.0; }
  };
  spill(ma, mc, L.item(a).capacity_kg);
  spill(mc, ma, L.item(c).capacity_kg);
  b.at(a) = ma;
  b.at(c) = mc;
}

}  // namespace

TankBuoyancy tankBuoyancy(const TankReadings& r, const HullModel& hull, const ScaleStations& s) {
  requireIn(r.dry_mass_kg, 1.0, 1000.0, "dry_mass_kg", "the dry mass in kg");
  // Spring scales only pull: a glider that floats in the tank cannot be weighed this way.
  requireIn(r.bow_scale_kg, 0.0, 100.0, "tank.bow_scale_g", "the bow spring-scale reading");
  requireIn(r.aft_scale_kg, 0.0, 100.0, "tank.aft_scale_g", "the aft spring-scale reading");
  requireIn(r.tank.density_kgm3, 990.0, 1050.0, "tank.density_kgm3", "the tank water density in kg/m3");
  requireIn(r.tank.temperature_degC, -2.0, 40.0, "tank.temperature_degC", "the tank temperature in degC");
  requireIn(r.target.density_kgm3, 990.0, 1060.0, "target.density_kgm3", "the deployment water density in kg/m3");
  requireIn(r.target.temperature_degC, -2.5, 40.0, "target.temperature_degC", "the deployment temperature in degC");
  requireIn(r.target_pressure_dbar, 0.0, 2000.0, "target.pressure_dbar", "the pressure in dbar");
  if (!(s.aft_x_m < 0.0 && s.bow_x_m > 0.0)) {
    throw InputError("slocum.ballast_bottles", "CB must lie between the bow and aft scale stations",
                     "check the bottles' x_mm and cb_mm.x_mm in the vehicle profile");
  }

  TankBuoyancy t;
  t.scale_total_kg = r.bow_scale_kg + r.aft_scale_kg;
  t.tank_neutral_mass_kg = r.dry_mass_kg - t.scale_total_kg;
  if (!(t.tank_neutral_mass_kg > 0.0)) {
    throw InputError("tank.bow_scale_g", "the scale readings add up to more than the dry mass",
                     "check the units: scale readings in grams, dry mass in kg");
  }
  t.volume_tank_m3 = t.tank_neutral_mass_kg / r.tank.density_kgm3;
  t.volume_target_m3 = t.volume_tank_m3 *
                       (1.0 + hull.thermal_expansion_per_degC * (r.target.temperature_degC - r.tank.temperature_degC)) *
                       (1.0 - hull.compressibility_per_dbar * r.target_pressure_dbar);
  t.target_neutral_mass_kg = t.volume_target_m3 * r.target.density_kgm3;
  t.mass_change_kg = t.target_neutral_mass_kg - r.dry_mass_kg;

  // Level means x_G = x_B; the net apparent weight then acts at CB and the
  // scales share it by the lever rule (half/half for symmetric stations).
  const double apparent = t.scale_total_kg + t.mass_change_kg;
  t.bow_share = -s.aft_x_m / (s.bow_x_m - s.aft_x_m);
  t.level_bow_scale_kg = apparent * t.bow_share;
  t.level_aft_scale_kg = apparent - t.level_bow_scale_kg;
  t.bow_change_kg = t.level_bow_scale_kg - r.bow_scale_kg;
  t.aft_change_kg = t.level_aft_scale_kg - r.aft_scale_kg;
  t.cg_x_from_cb_m = (r.bow_scale_kg * s.bow_x_m + r.aft_scale_kg * s.aft_x_m) / r.dry_mass_kg;
  return t;
}

TankReadings withAddedMass(TankReadings r, const ScaleStations& s, double mass_kg, double x_m) {
  const double to_bow = mass_kg * (x_m - s.aft_x_m) / (s.bow_x_m - s.aft_x_m);
  r.dry_mass_kg += mass_kg;
  r.bow_scale_kg += to_bow;
  r.aft_scale_kg += mass_kg - to_bow;
  return r;
}

BottleStep planBottleStep(const TankBuoyancy& t, const TankReadings& r, const SlocumBallast& now,
                          const SlocumLayout& L) {
  const double res = L.mass_resolution_kg;
  BottleStep st;
  // Round the total down: ending a gram light is harmless, a gram heavy is not.
  const double total = std::floor(t.mass_change_kg / res + 1e-9) * res;
  auto pairRange = [&](SlocumItem a, SlocumItem c) {
    return std::pair<double, double>{-(now.at(a) + now.at(c)),
                                     L.item(a).capacity_kg - now.at(a) + L.item(c).capacity_kg - now.at(c)};
  };
  const auto [bow_lo, bow_hi] = pairRange(kForePort, kForeStarboard);
  const auto [aft_lo, aft_hi] = pairRange(kAftUpper, kAftLower);

  // Level split of the rounded total, in whole pieces.
  const double bow_level = roundTo(t.bow_change_kg + (total - t.mass_change_kg) * t.bow_share, res);
  double bow = std::clamp(bow_level, bow_lo, bow_hi);
  double aft = std::clamp(total - bow, aft_lo, aft_hi);
  double left = total - bow - aft;
  if (std::abs(left) > res / 2.0) {
    // Buoyancy first, level second: the bow pair absorbs what the aft pair cannot.
    const double extra = std::clamp(left, bow_lo - bow, bow_hi - bow);
    bow += extra;
    left -= extra;
  }
  if (std::abs(bow - bow_level) > res / 2.0) {
    st.warnings.push_back(Message(weighing::msg::kBottlesNotLevel, {grams(bow_level), grams(total - bow_level)}));
  }
  if (left > res / 2.0) {
    st.warnings.push_back(Message(weighing::msg::kBottlesFull, {grams(left)}));
  } else if (left < -res / 2.0) {
    st.warnings.push_back(Message(weighing::msg::kBottlesEmpty, {grams(-left)}));
  }
  st.after = now;
  sharePair(st.after, L, kForePort, kForeStarboard, bow, res);
  sharePair(st.after, L, kAftUpper, kAftLower, aft, res);
  st.bow_change_kg = bow;
  st.aft_change_kg = aft;
  st.total_change_kg = bow + aft;
  st.mass_after_kg = r.dry_mass_kg + st.total_change_kg;
  st.net_buoyancy_after_kg = t.target_neutral_mass_kg - st.mass_after_kg;
  st.bow_scale_after_kg = r.bow_scale_kg + bow;
  st.aft_scale_after_kg = r.aft_scale_kg + aft;
  return st;
}

RollTest RollTestRecord::resolve(double default_lever_arm_m) const {
  const double arm = lever_arm_m.value_or(default_lever_arm_m);
  RollTest t;
  t.initial_roll_rad = initial_roll_rad;
  for (const Hang& h : applied) t.applied.push_back({h.mass_kg, h.starboard ? arm : -arm, 0.0, h.roll_rad});
  return t;
}

}  // namespace auv
