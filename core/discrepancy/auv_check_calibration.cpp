#include "discrepancy/auv_check_model.h"

// The check's calibration constants (issue 11 item 6): the nuisance vector
// after the ballast state, its priors and bounds, the analysis's groups held,
// and the model with the constants applied. Split from auv_check_model.cpp,
// which keeps the states, the equation error and the replay.
#include <algorithm>
#include <cmath>

#include "sim/flown_mass.h"

namespace auv::discrepancy {

namespace {
constexpr double kRhoRef = 1025.0;
}  // namespace

// Calibration constants in the nuisance vector, after the ballast state.
enum CalibrationIndex : int {
  kTorque = 3,
  kHeave,
  kCrossflow,
  kNetMw,
  kPitchDamping,
  kRollDamping,
  kPlanes,
  kDrag,
  kBg,
  kNuisanceCount
};

namespace {

struct CalibrationSpec {
  CalibrationIndex index;
  const char* id;
  const char* label;
  const char* unit;
};
// Scale groups: value = the vehicle's derivatives as a multiple of the profile's.
constexpr CalibrationSpec kCalibration[] = {
    {kTorque, "propeller_torque", "propeller torque", "N*m/rpm^2"},
    {kHeave, "heave_derivatives", "heave derivatives Z_w, Z_q, Z_ww", "x profile"},
    {kNetMw, "net_pitch_moment_derivative", "net pitch-moment derivative M_w' with the Munk moment", "nondimensional"},
    {kCrossflow, "crossflow_pitch_moment", "crossflow pitch moment M_|w|w", "x profile"},
    {kPitchDamping, "pitch_damping", "linear pitch damping M_q", "x profile"},
    {kRollDamping, "roll_damping", "roll damping K_p, K_|p|p", "x profile"},
    {kPlanes, "stern_plane_effectiveness", "stern-plane effectiveness Z_uud, M_uud", "x profile"},
    {kDrag, "surge_drag", "surge drag X_u, X_uu", "x profile"},
    {kBg, "bg", "metacentric height BG (CG below CB, as flown)", "m"},
};
constexpr double kGroupSigma = 0.3;  // default prior sigma of a hydrodynamic group (issue 11)
// A group the analysis calibrated is held at its value: a prior this share
// of the analysis's sigma. Fitted freely, the equation error's noisy
// regressors (1 Hz depth rate, attitude and speed noise) shrank the moment
// groups to their bounds on our own model as truth (BG 20 -> 4 mm, pitch
// damping 1 -> 0.1) and bent the net buoyancy 0.3-1 kg; held, the check's
// net is within 0.2 kg and names no term on those logs
// (docs/decisions/model-check-calibration.md).
constexpr double kHeldPriorShare = 0.05;
}  // namespace

double AuvCheckModel::profileTorque() const {
  const sim::Propeller& p = model_.prop;
  const std::size_t k = *findTerm("propeller_torque");
  return p.torque_sign * p.KQ0 * kRhoRef * std::pow(p.diameter_m, 5) / 3600.0 + baseline_[k];
}

// The analysis's prior (auv_trim_estimation.cpp): a quarter of the profile's BG.
double AuvCheckModel::bgSigma() const { return 0.25 * profile_bg_m_; }

double AuvCheckModel::torqueSigma() const { return std::max(std::abs(profileTorque()), termLibrary()[*findTerm("propeller_torque")].typical); }

// Munk moment (X_udot - Z_wdot) u w as a nondimensional M_w' (rho 1025).
double AuvCheckModel::munkPrime() const {
  const double L = model_.body.reference_length_m;
  return (model_.hydro.Xudot_kg - model_.hydro.Zwdot_kg) / (0.5 * kRhoRef * L * L * L);
}

// The part of it the simulator adds on top of M_w': none when the profile's
// M_w' holds it (munk_moment "inside_Mw").
double AuvCheckModel::addedMunkPrime() const { return model_.hydro.munk_factor * munkPrime(); }

// The linear u w pitch-moment coefficient the vehicle flies with. Whether a
// tabulated M_w' holds the Munk moment or not changes even its sign, and a
// log sees only the sum: one constant, prior sigma 30 % of M_w' plus half
// the Munk moment (inside or on top are both within 2 sigma).
double AuvCheckModel::profileNetMw() const { return model_.hydro.Mw_prime + addedMunkPrime(); }
double AuvCheckModel::netMwSigma() const {
  return std::max(kGroupSigma * std::abs(model_.hydro.Mw_prime) + 0.5 * std::abs(munkPrime()), 1e-4);
}

sim::VehicleModel AuvCheckModel::calibratedModel(const Params& p) const {
  sim::VehicleModel m = model_;
  if (p.nuisance.size() < kNuisanceCount) return m;
  const double z = p.nuisance[kHeave], mq = p.nuisance[kPitchDamping];
  const double k = p.nuisance[kRollDamping], d = p.nuisance[kPlanes];
  m.hydro.Zw_prime *= z;
  m.hydro.Zq_prime *= z;
  const bool analysisGroups = crossflowFromAnalysis();
  if (!analysisGroups) m.hydro.Zww_kg_per_m *= z;
  // The simulator adds the Munk moment to M_w' itself (Coriolis terms) unless M_w' holds it.
  m.hydro.Mw_prime = p.nuisance[kNetMw] - addedMunkPrime();
  m.hydro.Mww_kg *= p.nuisance[kCrossflow];
  if (analysisGroups) {
    // Held at the analysis's crossflow_scale, which is one crossflow drag
    // coefficient along the hull for all three (auv_transient_fit.cpp).
    m.hydro.Zww_kg_per_m *= p.nuisance[kCrossflow];
    m.hydro.Mqq_kgm2 *= p.nuisance[kCrossflow];
  }
  m.hydro.Mq_prime *= mq;
  m.hydro.Kp_kgm2_per_s *= k;
  m.hydro.Kpp_kgm2 *= k;
  m.planes.X_uudd_per_deg2 *= d;
  m.planes.Z_uud_per_deg *= d;
  m.planes.M_uud_per_deg *= d;
  m.hydro.Xu_kg_per_s *= p.nuisance[kDrag];
  m.hydro.Xuu_kg_per_m *= p.nuisance[kDrag];
  return m;
}

std::vector<std::string> AuvCheckModel::nuisanceNames() const {
  std::vector<std::string> n(kNuisanceCount);
  n[0] = "net_buoyancy_kg", n[1] = "cg_x_shift_m", n[2] = "cg_y_shift_m";
  for (const CalibrationSpec& c : kCalibration) n[c.index] = c.id;  // by index: the table is not in index order
  return n;
}

std::vector<CalibrationConstant> AuvCheckModel::calibrationConstants() const {
  std::vector<CalibrationConstant> out;
  for (const CalibrationSpec& c : kCalibration) {
    CalibrationConstant k;
    k.id = c.id;
    k.label = c.label;
    k.unit = c.unit;
    k.index = c.index;
    k.profile_value = c.index == kTorque ? profileTorque() : c.index == kNetMw ? profileNetMw() : c.index == kBg ? profile_bg_m_ : 1.0;
    k.prior_sigma = c.index == kTorque ? torqueSigma() : c.index == kNetMw ? netMwSigma() : c.index == kBg ? bgSigma() : kGroupSigma;
    if (const auto* a = calibrationPrior(c.id); a) {
      k.held_sigma = a->sigma;
      k.from_analysis = true;
    }
    if (crossflowFromAnalysis() && c.index == kHeave) k.label = "heave derivatives Z_w, Z_q";
    if (crossflowFromAnalysis() && c.index == kCrossflow) k.label = "crossflow drag Z_|w|w, M_|w|w, M_|q|q";
    if (c.index == kBg && !calibrationPrior(c.id)) k.held_sigma = bgSigma();  // held at the profile's
    out.push_back(k);
  }
  return out;
}

std::vector<HeldTermValue> AuvCheckModel::heldTerms() const {
  std::vector<HeldTermValue> out;
  for (const AuvCheckOptions::HeldTerm& h : opt_.held_terms) {
    const auto k = findTerm(h.id);
    if (!k) continue;
    const PhysicsTerm& t = termLibrary()[*k];
    out.push_back({h.id, std::string(t.unit), std::string(t.parameter), h.value, h.sigma, h.profile_value, h.prior_sigma, h.rival});
  }
  return out;
}

double AuvCheckModel::profileTermValue(std::size_t term) const {
  const PhysicsTerm& t = termLibrary()[term];
  double v = baseline_[term] * t.display_scale;
  if (t.id == "hull_compressibility") v += model_.body.hull.compressibility_per_dbar;
  if (t.id == "thermal_expansion") v += model_.body.hull.thermal_expansion_per_degC;
  if (t.id == "quadratic_pitch_damping") v += 1.0;  // the vehicle's M_|q|q as a multiple of the profile's
  return v;
}

TermValues AuvCheckModel::total(const Params& p) const {
  TermValues t = baseline_;
  for (std::size_t k = 0; k < kTermCount; ++k) t[k] += p.terms[k];
  // The calibrated propeller torque replaces the profile's: the model's own
  // K_Q0 is in the dynamics, the difference goes through the library term.
  if (p.nuisance.size() >= kNuisanceCount) t[*findTerm("propeller_torque")] += p.nuisance[kTorque] - profileTorque();
  return t;
}

sim::VehicleLoading AuvCheckModel::loading(const Params& p) const {
  sim::VehicleLoading l;
  l.extra_masses = installed_;
  l.error.net_buoyancy_kg = p.nuisance[0];
  // BG as flown: the vertical CG is as uncertain as the hydrodynamics (a
  // drawn truth of 12-30 mm against the profile's 20 mm left the pitch and
  // roll restoring moments 40 % off, and the hydrodynamic groups and the
  // ballast bent to make up for it).
  const double dz = p.nuisance.size() > kBg ? p.nuisance[kBg] - profile_bg_m_ : 0.0;
  l.error.cg_shift_m = Eigen::Vector3d(p.nuisance[1], p.nuisance[2], dz);
  return l;
}

const AuvCheckOptions::CalibrationPrior* AuvCheckModel::calibrationPrior(const std::string& id) const {
  for (const auto& c : opt_.calibration_priors)
    if (c.id == id && std::isfinite(c.value) && c.sigma > 0.0) return &c;
  return nullptr;
}

// quadratic_pitch_damping s makes M_|q|q (1 + s) times the calibrated one
// (the equation error, the replay and --accept alike). Its plausible range
// speaks of the vehicle against the hydrodynamics table (0.1 to 6 times the
// table's M_|q|q), so with the crossflow group held at the analysis's c,
// which scales M_|q|q already, it is (1 + lower) / c - 1 to (1 + upper) / c - 1.
std::pair<double, double> AuvCheckModel::termRange(std::size_t term) const {
  const PhysicsTerm& t = termLibrary()[term];
  const AuvCheckOptions::CalibrationPrior* c = calibrationPrior("crossflow_pitch_moment");
  if (t.id != "quadratic_pitch_damping" || c == nullptr) return {t.lower, t.upper};
  const double scale = std::max(c->value, 0.05);
  return {(1.0 + t.lower) / scale - 1.0, (1.0 + t.upper) / scale - 1.0};
}

// Free, the check keeps its own groups (Z_ww with the heave derivatives,
// M_|q|q at the profile's so that an extra quadratic damping stays a library
// term: measured on the Delphin2 drawn truths, moving both into the crossflow
// group cost 5 of 27 top-1 hits and named terms on 4 controls). Held at the
// analysis's calibration, it follows the analysis's grouping.
bool AuvCheckModel::crossflowFromAnalysis() const {
  return calibrationPrior("crossflow_pitch_moment") != nullptr;
}

// A held group's bounds close on its value: a prior of a twentieth of the
// analysis's sigma alone let the equation error drag BG 27 of those sigmas
// (19.3 -> 12.9 mm on a simulated log of the profile's own 19.6 mm, and the
// propeller torque with it to 0.66 of the truth).
Eigen::VectorXd AuvCheckModel::holdAtAnalysis(Eigen::VectorXd bound) const {
  for (const CalibrationSpec& c : kCalibration)
    if (const auto* a = calibrationPrior(c.id); a) bound[c.index] = a->value;
  return bound;
}

Eigen::VectorXd AuvCheckModel::nuisanceStart() const {
  Eigen::VectorXd x = Eigen::VectorXd::Ones(kNuisanceCount);
  x.head(3).setZero();
  x[kTorque] = profileTorque();
  x[kNetMw] = profileNetMw();
  x[kBg] = profile_bg_m_;
  for (const CalibrationSpec& c : kCalibration)
    if (const auto* a = calibrationPrior(c.id)) x[c.index] = a->value;
  return x;
}

Eigen::VectorXd AuvCheckModel::nuisanceScale() const {
  Eigen::VectorXd x = Eigen::VectorXd::Constant(kNuisanceCount, 0.1);
  x.head(3) << 0.01, 1e-4, 1e-4;
  x[kTorque] = 0.1 * torqueSigma();
  x[kNetMw] = 0.1 * netMwSigma();
  x[kBg] = 0.1 * bgSigma();
  return x;
}

Eigen::VectorXd AuvCheckModel::nuisanceLower() const {
  Eigen::VectorXd x = Eigen::VectorXd::Constant(kNuisanceCount, 0.1);
  x.head(3) << -0.05 * model_.body.mass_kg, -0.1, -0.1;
  x[kTorque] = profileTorque() - 20.0 * torqueSigma();
  x[kNetMw] = profileNetMw() - 10.0 * netMwSigma();
  x[kBg] = 0.2 * profile_bg_m_;  // statically stable: the vehicle flew
  return holdAtAnalysis(x);
}

Eigen::VectorXd AuvCheckModel::nuisanceUpper() const {
  Eigen::VectorXd x = Eigen::VectorXd::Constant(kNuisanceCount, 4.0);
  x.head(3) << 0.05 * model_.body.mass_kg, 0.1, 0.1;
  x[kTorque] = profileTorque() + 20.0 * torqueSigma();
  x[kNetMw] = profileNetMw() + 10.0 * netMwSigma();
  x[kBg] = 3.0 * profile_bg_m_;
  return holdAtAnalysis(x);
}

std::vector<NuisancePrior> AuvCheckModel::priors() const {
  std::vector<NuisancePrior> p;
  if (opt_.cg_y_sigma_m) p.push_back({2, opt_.cg_y_prior_shift_m, *opt_.cg_y_sigma_m, true});
  // Calibration constants: propeller torque 0 +- the profile's (it may be
  // anything from none to twice the assumed), the rest at the profile's.
  for (const CalibrationConstant& c : calibrationConstants()) {
    if (const auto* a = calibrationPrior(c.id))
      p.push_back({c.index, a->value, kHeldPriorShare * a->sigma, false});
    else if (c.index == kBg)
      // Without the analysis's BG the check keeps the profile's: fitted
      // freely from the equation error it collapsed to its bound (the
      // restoring moment's regressor is the noisiest), and on the Delphin2
      // drawn truths it cost the model check top-1 hits.
      p.push_back({c.index, c.profile_value, kHeldPriorShare * c.prior_sigma, false});
    else
      p.push_back({c.index, c.id == "propeller_torque" ? 0.0 : c.profile_value, c.prior_sigma, false});
  }
  return p;
}

}  // namespace auv::discrepancy
