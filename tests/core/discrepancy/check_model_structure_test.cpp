// The model check's equation error against the vehicle the simulator flies:
// a vehicle written two ways is one vehicle to the check, and a term changes
// the model as the replay and --accept change it.
// - A hydrodynamics table may hold the Munk moment inside M_w' (munk_moment
//   "inside_Mw") or leave it to the simulator's Coriolis terms ("added"). The
//   check calibrates one net u w pitch derivative either way.
// - quadratic_pitch_damping s makes M_|q|q (1 + s) times the calibrated one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "discrepancy/physics_terms.h"
#include "discrepancy/profile_update.h"
#include "delphin_test_log.h"
#include "discrepancy/vehicle_check.h"
#include "sim/model_loader.h"
#include "vehicle/profile_loader.h"
#include "vehicle/profile_writer.h"

namespace auv::discrepancy {
namespace {

struct TwoWritings {
  VehicleProfile added = loadVehicleProfile(std::string(AUV_RESOURCE_DIR) + "/vehicles/delphin2.json");
  VehicleProfile inside;
  double net_mw = 0.0;    // the vehicle's net u w derivative, M_w' + Munk
  double mw_added = 0.0;  // M_w' of the table that leaves the Munk moment to the simulator
  MissionLog log;
  TwoWritings() {
    const sim::SimVehicle v = sim::loadSimVehicle(added, AUV_RESOURCE_DIR);
    const sim::Hydrodynamics& h = v.model.hydro;
    const double L = v.model.body.reference_length_m;
    mw_added = h.Mw_prime;
    net_mw = h.Mw_prime + (h.Xudot_kg - h.Zwdot_kg) / (0.5 * 1025.0 * L * L * L);
    nlohmann::json j = profileToJson(added);
    j["hydrodynamics"]["Mw_prime"] = net_mw;
    j["hydrodynamics"]["munk_moment"] = "inside_Mw";
    inside = parseVehicleProfile(j.dump(), "inside.json");
    log = test_logs::delphinTestLog(v);
  }
};

// The pitch-moment channel of the equation error at every row.
std::vector<double> pitchMomentError(const CheckModel& c, const Params& p) {
  std::vector<std::uint32_t> rows(c.samples().size());
  std::iota(rows.begin(), rows.end(), 0u);
  const std::vector<Channel> ch = c.equationChannels();
  const auto pitch = static_cast<std::size_t>(std::find(ch.begin(), ch.end(), Channel::kPitchMoment) - ch.begin());
  std::vector<double> all(rows.size() * ch.size()), out(rows.size());
  c.equationError(p, rows, all.data());
  for (std::size_t r = 0; r < rows.size(); ++r) out[r] = all[r * ch.size() + pitch];
  return out;
}

// RMS of (a - b) over RMS of (c - d), over the rows where all four are
// finite; NaN when the reference is zero.
double rmsRatio(const std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& c,
                const std::vector<double>& d) {
  double num = 0.0, den = 0.0;
  for (std::size_t r = 0; r < a.size(); ++r) {
    if (!std::isfinite(a[r]) || !std::isfinite(b[r]) || !std::isfinite(c[r]) || !std::isfinite(d[r])) continue;
    num += (a[r] - b[r]) * (a[r] - b[r]);
    den += (c[r] - d[r]) * (c[r] - d[r]);
  }
  return den > 0.0 ? std::sqrt(num / den) : std::numeric_limits<double>::quiet_NaN();
}

double profileNetMw(const CheckModel& c) {
  for (const CalibrationConstant& k : c.calibrationConstants())
    if (k.id == "net_pitch_moment_derivative") return k.profile_value;
  return std::numeric_limits<double>::quiet_NaN();
}

TEST(MunkStructure, TheCheckFliesAnMwHoldingTheMunkMomentAsTheSameVehicle) {
  const TwoWritings w;
  ASSERT_EQ(sim::loadSimVehicle(w.inside, AUV_RESOURCE_DIR).model.hydro.munk_factor, 0.0);
  const auto a = makeCheckModel(w.log, w.added, AUV_RESOURCE_DIR);
  const auto b = makeCheckModel(w.log, w.inside, AUV_RESOURCE_DIR);
  EXPECT_NEAR(profileNetMw(*a), w.net_mw, 1e-12);
  EXPECT_NEAR(profileNetMw(*b), w.net_mw, 1e-12);  // was M_w' + Munk twice over
  // The pitch-moment equation error at one parameter vector: the two differ
  // only by the Munk term's density (the table is at 1025 kg/m3, the
  // simulator adds (X_udot - Z_wdot) u w whatever the water), far less than
  // the Munk moment itself (the error before: M_w' less it twice over).
  const Params p{a->nuisanceStart(), {}};
  const std::vector<std::string> names = a->nuisanceNames();
  const auto k = static_cast<Eigen::Index>(std::find(names.begin(), names.end(), "net_pitch_moment_derivative") - names.begin());
  Params lessMunk = p;
  lessMunk.nuisance[k] -= w.net_mw - w.mw_added;
  const std::vector<double> ea = pitchMomentError(*a, p), eb = pitchMomentError(*b, p), em = pitchMomentError(*a, lessMunk);
  EXPECT_LT(rmsRatio(eb, ea, em, ea), 0.01);  // NaN (fails) if the Munk moment had no effect
}

TEST(MunkStructure, AcceptWritesTheNetDerivativeIntoAnMwThatHoldsTheMunkMoment) {
  const TwoWritings w;
  ModelCheckResult r;
  CalibrationValue c;
  c.id = "net_pitch_moment_derivative";
  c.value = 0.8 * w.net_mw;
  c.profile_value = w.net_mw;
  c.sigma = 0.01 * std::abs(w.net_mw);
  c.identified = true;
  r.calibration.push_back(c);
  const nlohmann::json out = profileWithAcceptedTerms(profileToJson(w.inside), w.inside, r, "survey.csv");
  const sim::SimVehicle s = sim::loadSimVehicle(parseVehicleProfile(out.dump(), "accepted.json"), AUV_RESOURCE_DIR);
  EXPECT_EQ(s.model.hydro.munk_factor, 0.0);
  EXPECT_NEAR(s.model.hydro.Mw_prime, 0.8 * w.net_mw, 1e-12);  // not less the Munk moment the table holds already
}

// With the crossflow group held at the analysis's 1.3 (Z_|w|w, M_|w|w and
// M_|q|q), a quadratic pitch damping of 0.5 is the vehicle whose M_|q|q is
// 1.3 x 1.5 the table's, as the replay (adjustedModel) and --accept have it.
// Before, the equation error added 0.5 of the table's M_|q|q: 1.8 x.
TEST(QuadraticPitchDamping, TheTermScalesTheCalibratedMqq) {
  const TwoWritings w;
  CheckSetup held;
  held.auv.calibration_priors = {{"crossflow_pitch_moment", 1.3, 0.05}};
  nlohmann::json j = profileToJson(w.added);
  j["hydrodynamics"]["Mqq_kgm2_per_rad2"] = 1.5 * j["hydrodynamics"]["Mqq_kgm2_per_rad2"].get<double>();
  const VehicleProfile damped = parseVehicleProfile(j.dump(), "damped.json");
  const auto a = makeCheckModel(w.log, w.added, AUV_RESOURCE_DIR, held);
  const auto b = makeCheckModel(w.log, damped, AUV_RESOURCE_DIR, held);
  const Params p{a->nuisanceStart(), {}};
  Params withTerm = p;
  withTerm.terms[*findTerm("quadratic_pitch_damping")] = 0.5;
  const std::vector<double> e0 = pitchMomentError(*a, p), ea = pitchMomentError(*a, withTerm), eb = pitchMomentError(*b, p);
  EXPECT_LT(rmsRatio(ea, eb, eb, e0), 1e-6);  // NaN (fails) if the damping had no effect
}

}  // namespace
}  // namespace auv::discrepancy
