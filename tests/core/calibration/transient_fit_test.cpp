// The transients of a survey log as an output-error problem (issue 11 item
// 2): on truths drawn away from the profile, the simulator flown with the
// logged stern plane and propeller from the logged window starts matches
// the log at the truth's parameters to the sensor noise, and the joint fit
// with the steady legs finds the net buoyancy and the stern-plane
// effectiveness closer than the steady legs alone, with sigmas that cover
// the truth.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <cstdio>

#include "analysis/auv_calibration.h"
#include "analysis/auv_steady_model.h"
#include "analysis/auv_transient_fit.h"
#include "analysis/mission_analysis.h"
#include "analysis/profile_constants.h"
#include "common/units.h"
#include "seawater/depth_pressure.h"
#include "identification_harness.h"
#include "sim/model_loader.h"
#include "sim/sim_log.h"
#include "sim/simulator.h"
#include "vehicle/profile_loader.h"

namespace auv::analysis {
namespace {

const std::vector<double> kInstalled = {7.2, 7.2, 25.2, 25.2};

struct Case {
  sim::DrawnTruth truth;
  sim::VehicleModel truth_model;
  MissionLog log;
  double mass_kg = 0.0;
};

Case flyTruth(const VehicleProfile& profile, std::uint64_t seed) {
  const std::string res = AUV_RESOURCE_DIR;
  const sim::SimVehicle nominal = sim::loadSimVehicle(loadVehicleProfile(res + "/vehicles/hugin1000.json"), res);
  Case c;
  c.truth = sim::drawTruth(seed);
  const sim::SurveyMission m = sim::makeSurveyMission(seed);
  c.truth_model = sim::truthModel(nominal.model, c.truth);
  const std::vector<MassItem> installed = sim::installedWeights(profile, kInstalled);
  const sim::WaterSample w0 = m.water().at(m.scenario.initial_depth_m, 0.0);
  const double displaced0 = w0.density_kgm3 * c.truth_model.body.hull.volumeAt(w0.temperature_degC, w0.pressure_dbar);
  sim::Scenario sc = m.scenario;
  sc.extra_masses = installed;
  sc.ballast_error = sim::truthBallastError(c.truth_model, installed, displaced0, c.truth);
  sim::SimOptions opt = m.options;
  opt.seed = seed * 7 + 1;
  // 10 Hz rows: at 1 Hz the pitch command's steps fall between rows and the
  // replay misses them by up to a second (chi2 30-40 at the truth).
  opt.trace_interval_s = 0.1;
  const sim::SimTrace tr = sim::simulate(c.truth_model, nominal.autopilot, m.water(), sc, opt);
  c.log = sim::toMissionLog(tr, {"hugin1000", "plan", "transient test", seed, 0, kInstalled, {sim::latitudeMetadata(m.latitude_deg)}});
  sim::applyDropouts(c.log, seed);
  c.mass_kg = tr.truth.mass_kg;
  return c;
}

TEST(TransientFit, ReplayAtTheTruthMatchesTheLogAndTheJointFitIsNoWorseThanSteadyLegs) {
  const identification::Harness h;
  const VehicleProfile& profile = h.profile();
  // 1103: three speeds, steady legs separate the net buoyancy from the
  // planes (0.07 kg); 1112: two speeds and two depths (0.46 kg). Seed 1105
  // (two speeds, 8.8 kg from steady legs) used to show the transients' gain;
  // since its vehicle broaches at the surface (the survey's surface model)
  // and its steady dives count, the steady legs give 4.3 kg and the log has
  // too few transients below 3 m. Seed 1102 is a known miss (joint 8.47 +-
  // 0.05 kg against 8.20): the bench's coverage is below 90 %, so the fit is
  // off by default.
  for (std::uint64_t seed : {1103ULL, 1112ULL}) {
    const Case c = flyTruth(profile, seed);
    SCOPED_TRACE(c.truth.describe());
    AnalysisOptions steady;
    steady.installed_kg = kInstalled;
    steady.bg_m = c.truth.bg_m;
    steady.use_transients = false;
    AnalysisOptions joint = steady;
    joint.use_transients = true;
    const AnalysisReport a = analyzeMission(c.log, profile, steady);
    const AnalysisReport b = analyzeMission(c.log, profile, joint);
    ASSERT_TRUE(a.net_buoyancy_kg.known);
    ASSERT_TRUE(b.net_buoyancy_kg.known);
    const double Vref = profile.hull.volumeAt(b.temperature_degC.mean, b.pressure_dbar.mean);
    const double net_truth = b.density_kgm3.mean * Vref - c.mass_kg;

    // The residuals at the truth's own parameters: sensor noise only.
    const sim::VehicleModel nominal = sim::loadVehicleModel(profile);
    TransientFitContext tc;
    double installed = 0.0;
    for (double k : kInstalled) installed += k;
    tc.weight_n = (profile.mass_kg + installed) * units::g0;
    tc.density_ref_kgm3 = b.density_kgm3.mean;
    tc.buoyancy_ref_n = units::g0 * b.density_kgm3.mean * Vref;
    const sim::DepthAutopilotConfig ap = sim::loadAutopilotConfig(profile);
    tc.autopilot = ap;
    const TransientFit fit(c.log, nominal, tc);
    ASSERT_GT(fit.windowCount(), 3u);
    Eigen::VectorXd p = Eigen::VectorXd::Zero(kCalibrationCount);
    const double L = nominal.body.reference_length_m;
    const sim::Hydrodynamics& hn = nominal.hydro;
    p(kNet) = units::g0 * net_truth;
    p(kXg) = c.truth.cg_x_m;
    p(kHeave) = c.truth.heave_scale;
    p(kPitchUw) = 0.5 * tc.density_ref_kgm3 * L * L * L * hn.Mw_prime * c.truth.pitch_scale +
                  (c.truth.munk_inside_Mw ? 0.0 : 1.0) * (hn.Xudot_kg - hn.Zwdot_kg);
    p(kCrossflow) = c.truth.crossflow_scale;
    p(kPlanes) = c.truth.plane_scale;
    p(kPlaneOffset) = 0.0;
    p(kBg) = c.truth.bg_m;
    p(kPitchDamping) = c.truth.pitch_scale;
    const Eigen::VectorXd r = fit.residuals(p);
    const double chi2 = r.squaredNorm() / static_cast<double>(r.size());
    // The mapping of p onto the simulator is the truth's model (up to the
    // Munk moment taken at the reference density inside M_w).
    const Eigen::VectorXd rt = fit.residualsOf(c.truth_model, p);
    EXPECT_NEAR(rt.squaredNorm(), r.squaredNorm(), 0.05 * r.squaredNorm());
    std::printf("  seed %llu: %zu windows, chi2/residual at the truth %.2f (pitch sigma %.3f deg, depth %.3f m)\n"
                "    net truth %.3f kg: steady %.3f +- %.3f, joint %.3f +- %.3f\n",
                static_cast<unsigned long long>(seed), fit.windowCount(), chi2, units::radToDeg(fit.pitchSigmaRad()),
                fit.depthSigmaM(), net_truth, a.net_buoyancy_kg.value, a.net_buoyancy_kg.sigma, b.net_buoyancy_kg.value,
                b.net_buoyancy_kg.sigma);
    // Noise plus what 10 Hz rows still miss of the commands: a few sigma rms.
    EXPECT_LT(chi2, 5.0);
    EXPECT_LE(std::abs(b.net_buoyancy_kg.value - net_truth), 2.0 * b.net_buoyancy_kg.sigma);
    EXPECT_LE(std::abs(b.cg_x_mm.value - units::mToMm(c.truth.cg_x_m)), 2.0 * b.cg_x_mm.sigma + 0.05);
    // The transients add information: never a wider sigma, half of one the
    // steady legs leave near its prior.
    EXPECT_LE(b.net_buoyancy_kg.sigma, a.net_buoyancy_kg.sigma * 1.001);
    if (a.net_buoyancy_kg.sigma > 1.0) {
      EXPECT_LT(b.net_buoyancy_kg.sigma, 0.5 * a.net_buoyancy_kg.sigma);
    }
  }
}

// A log the vehicle did not fly as commanded is not replayed: 3101 (net
// +2.65 kg, CG x -19 mm) cannot get down to its commands with the elevator
// at its dive stop, and fitted through the replay it said net +1.70 kg
// better than the truth with a sigma of 0.42 (4 sigma), and the move made
// from it left the vehicle 0.65 kg heavy. The steady legs' answer stands,
// and the report says why the transients were not used.
TEST(TransientFit, IsSkippedOnALogNotFlownAsCommanded) {
  const identification::Harness h;
  const VehicleProfile& profile = h.profile();
  const Case c = flyTruth(profile, 3101);
  SCOPED_TRACE(c.truth.describe());
  AnalysisOptions steady;
  steady.installed_kg = kInstalled;
  steady.bg_m = c.truth.bg_m;
  AnalysisOptions joint = steady;
  joint.use_transients = true;
  const AnalysisReport a = analyzeMission(c.log, profile, steady);
  const AnalysisReport b = analyzeMission(c.log, profile, joint);
  ASSERT_TRUE(b.details.contains("flight_envelope"));
  EXPECT_TRUE(b.details["flight_envelope"].contains("too_light"));
  ASSERT_TRUE(b.details.contains("transients_skipped"));
  EXPECT_EQ(b.details["transients_skipped"], "log not flown as commanded");
  EXPECT_TRUE(std::any_of(b.notes.begin(), b.notes.end(),
                          [](const Message& m) { return m.id() == "analysis.transients_not_flown_as_commanded"; }));
  EXPECT_FALSE(b.details.contains("transient_windows"));
  ASSERT_TRUE(a.net_buoyancy_kg.known && b.net_buoyancy_kg.known);
  EXPECT_EQ(b.net_buoyancy_kg.value, a.net_buoyancy_kg.value);
  EXPECT_EQ(b.net_buoyancy_kg.sigma, a.net_buoyancy_kg.sigma);
  const double Vref = profile.hull.volumeAt(b.temperature_degC.mean, b.pressure_dbar.mean);
  const double net_truth = b.density_kgm3.mean * Vref - c.mass_kg;
  EXPECT_LE(std::abs(b.net_buoyancy_kg.value - net_truth), 2.0 * b.net_buoyancy_kg.sigma);
}

// With a history calibration (a second mission, the known weight change a
// calibration experiment) the transients are not replayed either: that
// joint fit already pins the vehicle, and with the replay added its 2-sigma
// coverage over the bench's truths fell to 87 % (seeds 2100, 3100).
TEST(TransientFit, IsSkippedWhenTheHistoryCalibrates) {
  const identification::Harness h;
  const VehicleProfile& profile = h.profile();
  const Case c = flyTruth(profile, 1103);
  AnalysisOptions first;
  first.installed_kg = kInstalled;
  first.bg_m = c.truth.bg_m;
  const AnalysisReport a = analyzeMission(c.log, profile, first);
  ASSERT_FALSE(a.steady_segments.empty());
  AnalysisOptions with_history = first;
  with_history.use_transients = true;
  with_history.history.push_back({a.steady_segments, {7.2, 7.2, 20.2, 25.2}});
  const AnalysisReport b = analyzeMission(c.log, profile, with_history);
  ASSERT_TRUE(b.details.contains("transients_skipped"));
  EXPECT_EQ(b.details["transients_skipped"], "history calibration");
  EXPECT_TRUE(std::any_of(b.notes.begin(), b.notes.end(),
                          [](const Message& m) { return m.id() == "analysis.transients_with_history"; }));
  EXPECT_FALSE(b.details.contains("transient_windows"));
  AnalysisOptions alone = first;
  alone.use_transients = true;
  EXPECT_TRUE(analyzeMission(c.log, profile, alone).details.contains("transient_windows"));
}

// A simulated survey says where it flew: its water column's pressure was
// computed for 60 deg N, and without "latitude" in the header the analysis
// (45 deg) read depth and pressure 0.13 % apart, which the model check then
// named a -0.08 m depth-sensor offset on every harness log.
TEST(TransientFit, SimulatedLogsCarryTheirLatitude) {
  const identification::Harness h;
  const Case c = flyTruth(h.profile(), 1103);
  const std::optional<double> lat = latitudeFromMetadata(c.log);
  ASSERT_TRUE(lat.has_value());
  EXPECT_DOUBLE_EQ(*lat, 60.0);
  const LogChannel* z = c.log.find("depth");
  const LogChannel* p = c.log.find("pressure");
  ASSERT_TRUE(z && p);
  double with = 0.0, without = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < z->values.size(); ++i) {
    if (!std::isfinite(z->values[i]) || !std::isfinite(p->values[i]) || z->values[i] < 40.0) continue;
    with += z->values[i] - seawater::depthFromPressure(p->values[i], *lat);
    without += z->values[i] - seawater::depthFromPressure(p->values[i], 45.0);
    ++n;
  }
  ASSERT_GT(n, 1000);
  EXPECT_LT(std::abs(with / n), 0.01);
  EXPECT_GT(std::abs(without / n), 0.05);
}

}  // namespace
}  // namespace auv::analysis
