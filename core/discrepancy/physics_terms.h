#pragma once
// The library of named physics terms the model check may find missing from
// a vehicle model. Each term is one table entry (physics_terms.cpp): its
// parameter with unit and plausible bounds, the channels it acts on, and how
// it enters
//   (a) the equation error: what it does to one sample (`Effects`), and
//   (b) the simulator: what it changes in the model or the replay
//       (`SimAdjustment`), so that an accepted term changes the simulation,
//   (c) the vehicle profile: where an accepted value is written.
// Adding a term = one entry in the table plus, if it acts in a new way, one
// field in Effects/SimAdjustment that the two models consume.
// The vehicle's ballast state (net buoyancy, CG x/y) is not a term: every
// model estimates it, always, and it is never reported as missing physics.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace auv::discrepancy {

// Residual and simulation channels.
enum class Channel {
  kVerticalVelocity,  // m/s, up positive (gliders: the steady-glide balance)
  kVerticalForce,     // N, body z (AUV heave equation)
  kPitchMoment,       // N m (AUV pitch equation)
  kRollMoment,        // N m (AUV roll equation)
  kDepth,             // m
  kPitch,             // rad
  kRoll,              // rad
  kSpeed,             // m/s
  kSurgeForce,        // N, body x (AUV surge equation)
};
const char* channelName(Channel c);
const char* channelUnit(Channel c);  // unit of the reported RMS (deg for angles)
double channelDisplayScale(Channel c);  // SI -> reported unit

enum VehicleFamilyBits : unsigned { kAuvFamily = 1u, kGliderFamily = 2u };

// What a term may read at one sample.
struct TermInputs {
  double hours_from_reference = 0.0;  // t - t_ref
  double pressure_dbar = 0.0;
  double temperature_degC = 0.0;
  double reference_temperature_degC = 20.0;  // T0 of the hull model
  double prop_torque_basis = 0.0;  // rpm^2 (rho/rho_ref) K_T(J)/K_T0: torque per unit coefficient
  double pitch_damping_basis = 0.0;  // M_|q|q |q| q of the nominal model [N m]
};

// What all active terms do to one sample (accumulated).
struct Effects {
  double volume_factor = 1.0;      // multiplies the hull volume
  double extra_mass_kg = 0.0;      // adds to the weight (at the CG)
  double pitch_bias_rad = 0.0;     // measured - true
  double roll_bias_rad = 0.0;      // measured - true
  double depth_offset_m = 0.0;     // depth reading - true depth
  double vertical_current_mps = 0.0;  // water velocity, up positive
  double roll_moment_nm = 0.0;     // extra roll moment, starboard down positive
  double pitch_moment_nm = 0.0;    // extra pitch moment, nose up positive
};

// How accepted terms change the simulator: model parameters (applied to a
// copy of sim::VehicleModel or the glider constants) and replay hooks.
struct SimAdjustment {
  double compressibility_per_dbar = 0.0;
  double thermal_expansion_per_degC = 0.0;
  double prop_torque_nm_per_rpm2 = 0.0;
  double pitch_damping_scale = 0.0;  // M_|q|q -> (1 + s) M_|q|q
  double mass_drift_kg_per_h = 0.0;
  double pitch_bias_rad = 0.0;
  double roll_bias_rad = 0.0;
  double depth_offset_m = 0.0;
  double vertical_current_mps = 0.0;
};

struct PhysicsTerm {
  std::string_view id;
  std::string_view parameter;  // what the value is, for people
  std::string_view unit;
  double lower = 0.0, upper = 0.0;  // plausible bounds of the value
  double typical = 1.0;             // scale of a small but real effect (fit scaling)
  unsigned families = 0;            // VehicleFamilyBits
  std::string_view channels;        // what it acts on, for people
  std::string_view excitation;      // what a log must contain to see it
  // The value as the report shows it (deg for angle biases).
  double display_scale = 1.0;
  void (*effect)(double value, const TermInputs& in, Effects& e) = nullptr;
  void (*simulate)(double value, SimAdjustment& a) = nullptr;
  // Acts on the transients (a damping): when the whole-log held-out replay
  // refuses it, the test is repeated on short horizons restarted from the
  // log, where its effect shows; the others change what accumulates over
  // the whole log and are judged there only.
  bool transient = false;
};

inline constexpr std::size_t kTermCount = 9;
using TermValues = std::array<double, kTermCount>;  // SI values, indexed like termLibrary()

// The table, in a fixed order. Values are SI inside (rad for the biases);
// `display_scale` converts to the unit shown.
const std::array<PhysicsTerm, kTermCount>& termLibrary();
std::optional<std::size_t> findTerm(std::string_view id);

// Accumulates the effects of all non-zero terms.
void applyEffects(const TermValues& values, const TermInputs& in, Effects& e);
SimAdjustment simAdjustment(const TermValues& values);

// Terms accepted earlier and written into the profile under
// "model_check": {"terms": {id: value in the display unit}} (see
// profile_update.h); zero for the others. Throws InputError on an unknown id
// or a value outside the term's bounds.
TermValues acceptedTermsFromProfile(const nlohmann::json& sections, const std::string& file);

}  // namespace auv::discrepancy
