#include "discrepancy/physics_terms.h"

#include <cmath>

#include "common/input_error.h"
#include "common/units.h"
#include "vehicle/json_reader.h"

namespace auv::discrepancy {

const char* channelName(Channel c) {
  switch (c) {
    case Channel::kVerticalVelocity: return "vertical_velocity";
    case Channel::kVerticalForce: return "vertical_force";
    case Channel::kPitchMoment: return "pitch_moment";
    case Channel::kRollMoment: return "roll_moment";
    case Channel::kDepth: return "depth";
    case Channel::kPitch: return "pitch";
    case Channel::kRoll: return "roll";
    case Channel::kSpeed: return "speed";
    case Channel::kSurgeForce: return "surge_force";
  }
  return "?";
}

const char* channelUnit(Channel c) {
  switch (c) {
    case Channel::kVerticalVelocity: return "cm/s";
    case Channel::kVerticalForce: return "N";
    case Channel::kPitchMoment:
    case Channel::kRollMoment: return "N m";
    case Channel::kDepth: return "m";
    case Channel::kPitch:
    case Channel::kRoll: return "deg";
    case Channel::kSpeed: return "m/s";
    case Channel::kSurgeForce: return "N";
  }
  return "";
}

double channelDisplayScale(Channel c) {
  switch (c) {
    case Channel::kVerticalVelocity: return 100.0;
    case Channel::kPitch:
    case Channel::kRoll: return units::radToDeg(1.0);
    default: return 1.0;
  }
}

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// One entry per term. The effect functions are the linear (first-order)
// physics of each term; the simulate functions say which knob of the
// simulator carries it.
const std::array<PhysicsTerm, kTermCount> kLibrary = {{
    {"hull_compressibility", "hull volume lost per dbar of pressure (V = V0 (1 - k p))", "1/dbar", -1e-5, 3e-5, 3e-6,
     kAuvFamily | kGliderFamily, "buoyancy -> vertical force / vertical velocity, grows with pressure",
     "a range of pressures (dives of different depth)", 1.0,
     [](double v, const TermInputs& in, Effects& e) { e.volume_factor *= 1.0 - v * in.pressure_dbar; },
     [](double v, SimAdjustment& a) { a.compressibility_per_dbar += v; }},
    {"thermal_expansion", "hull volume gained per degC (V = V0 (1 + a (T - T0)))", "1/degC", -2e-4, 3e-4, 3e-5,
     kAuvFamily | kGliderFamily, "buoyancy -> vertical force / vertical velocity, follows water temperature",
     "temperature changes that do not follow depth (fronts, internal waves, another season)", 1.0,
     [](double v, const TermInputs& in, Effects& e) {
       e.volume_factor *= 1.0 + v * (in.temperature_degC - in.reference_temperature_degC);
     },
     [](double v, SimAdjustment& a) { a.thermal_expansion_per_degC += v; }},
    {"propeller_torque", "propeller reaction roll moment per rpm^2 at bollard pull (rho 1025)", "N*m/rpm^2", -1e-3, 1e-3,
     1e-6, kAuvFamily, "roll moment -> roll, grows with rpm^2", "legs at different propeller speeds", 1.0,
     [](double v, const TermInputs& in, Effects& e) { e.roll_moment_nm += v * in.prop_torque_basis; },
     [](double v, SimAdjustment& a) { a.prop_torque_nm_per_rpm2 += v; }},
    {"mass_drift", "mass gained per hour (water uptake, ice, fouling, lost weight)", "kg/h", -2.0, 2.0, 0.005,
     kAuvFamily | kGliderFamily, "weight -> vertical force / vertical velocity, grows with time",
     "a long record, or the same manoeuvre repeated at its start and end", 1.0,
     [](double v, const TermInputs& in, Effects& e) { e.extra_mass_kg += v * in.hours_from_reference; },
     [](double v, SimAdjustment& a) { a.mass_drift_kg_per_h += v; }},
    {"pitch_sensor_bias", "attitude sensor pitch reading minus true pitch", "deg", -5.0 * kDeg, 5.0 * kDeg, 0.5 * kDeg,
     kAuvFamily | kGliderFamily, "pitch -> angle of attack, glide path, pitch moment",
     "dives and climbs (gliders) or legs at different speeds (AUVs)", 1.0 / kDeg,
     [](double v, const TermInputs&, Effects& e) { e.pitch_bias_rad += v; },
     [](double v, SimAdjustment& a) { a.pitch_bias_rad += v; }},
    {"roll_sensor_bias", "attitude sensor roll reading minus true roll", "deg", -5.0 * kDeg, 5.0 * kDeg, 0.5 * kDeg,
     kAuvFamily, "roll -> roll moment balance", "an independent CG y (a roll test), since a constant roll is also a CG y",
     1.0 / kDeg, [](double v, const TermInputs&, Effects& e) { e.roll_bias_rad += v; },
     [](double v, SimAdjustment& a) { a.roll_bias_rad += v; }},
    {"depth_sensor_offset", "depth sensor reading minus true depth", "m", -10.0, 10.0, 0.2, kAuvFamily | kGliderFamily,
     "depth against the CTD pressure", "an independent pressure (CTD) channel", 1.0,
     [](double v, const TermInputs&, Effects& e) { e.depth_offset_m += v; },
     [](double v, SimAdjustment& a) { a.depth_offset_m += v; }},
    {"quadratic_pitch_damping", "extra quadratic pitch damping M_|q|q, as a fraction of the calibrated coefficient",
     "scale of the calibrated coefficient", -0.9, 5.0, 0.3, kAuvFamily, "pitch moment -> pitch in manoeuvres",
     "fast pitch changes (depth steps, hover manoeuvres)", 1.0,
     [](double v, const TermInputs& in, Effects& e) { e.pitch_moment_nm += v * in.pitch_damping_basis; },
     [](double v, SimAdjustment& a) { a.pitch_damping_scale += v; }, true},
    {"vertical_current", "vertical water velocity (upwelling positive)", "m/s", -0.05, 0.05, 0.003,
     kAuvFamily | kGliderFamily, "depth rate over ground -> vertical velocity",
     "dives and climbs with different buoyancy-engine volumes", 1.0,
     [](double v, const TermInputs&, Effects& e) { e.vertical_current_mps += v; },
     [](double v, SimAdjustment& a) { a.vertical_current_mps += v; }},
}};

}  // namespace

const std::array<PhysicsTerm, kTermCount>& termLibrary() { return kLibrary; }

std::optional<std::size_t> findTerm(std::string_view id) {
  for (std::size_t i = 0; i < kTermCount; ++i)
    if (kLibrary[i].id == id) return i;
  return std::nullopt;
}

void applyEffects(const TermValues& values, const TermInputs& in, Effects& e) {
  for (std::size_t i = 0; i < kTermCount; ++i)
    if (values[i] != 0.0) kLibrary[i].effect(values[i], in, e);
}

SimAdjustment simAdjustment(const TermValues& values) {
  SimAdjustment a;
  for (std::size_t i = 0; i < kTermCount; ++i)
    if (values[i] != 0.0) kLibrary[i].simulate(values[i], a);
  return a;
}

TermValues acceptedTermsFromProfile(const nlohmann::json& sections, const std::string& file) {
  TermValues v{};
  if (!sections.contains("model_check")) return v;
  const JsonReader mc(sections["model_check"], file, "model_check");
  if (!mc.has("terms")) return v;
  const JsonReader terms = mc.child("terms");
  for (auto it = terms.node().begin(); it != terms.node().end(); ++it) {
    const auto k = findTerm(it.key());
    if (!k) {
      std::string ids;
      for (const auto& t : kLibrary) ids += (ids.empty() ? "" : ", ") + std::string(t.id);
      terms.fail(it.key(), "is not a model-check term", "use one of: " + ids);
    }
    const PhysicsTerm& t = kLibrary[*k];
    const double lo = std::min(t.lower, t.upper) * t.display_scale, hi = std::max(t.lower, t.upper) * t.display_scale;
    v[*k] = terms.numberIn(it.key(), lo, hi) / t.display_scale;
  }
  return v;
}

}  // namespace auv::discrepancy
