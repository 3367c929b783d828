// Pre-mission planning against independent oracles: EOS-80 densities and the
// hull volume law computed here, conservation of mass and first moment, the
// small-angle attitude sensitivity 1/BG, and the thesis's kit limits.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "common/input_error.h"
#include "common/units.h"
#include "plan_fixture.h"
#include "planning/installed_prediction.h"

using namespace auv;
using namespace auv::planning_test;

namespace {

double addedKg(const PreMissionPlan& p) {
  double s = 0;
  for (const auto& pt : p.points) s += pt.add_kg;
  return s;
}

template <class Strings>
bool anyContains(const Strings& v, const std::string& what) {
  for (const auto& s : v) {
    if (s.find(what) != std::string::npos) return true;
  }
  return false;
}

PreMissionInput baseInput() {
  PreMissionInput in;
  in.installed_kg = {10.8, 10.8, 22.8, 22.8};  // thesis App. G.2
  in.estimate = estimateAt(5.3, 12.0, 1.5, 8.0, 35.0, 100.0);
  in.next = nextMissionWater(water(6.0, 35.0, 50.0), 0.0, "operator");
  return in;
}

}  // namespace

TEST(PreMissionPlan, MassFromTheLogWaterAndBuoyancyInTheNextWater) {
  // A hull that expands and compresses, so the volume law matters.
  VehicleProfile v = hugin();
  PreMissionInput in = baseInput();
  HullModel hull = v.hull;
  hull.thermal_expansion_per_degC = 6.9e-5;  // aluminium, volumetric
  hull.compressibility_per_dbar = 3.0e-6;
  in.hull = hull;
  in.estimate = estimateAt(5.3, 12.0, 1.5, 14.0, 34.0, 80.0);
  in.next = nextMissionWater(water(4.0, 35.2, 150.0), 0.0, "operator");
  const PreMissionPlan p = planPreMission(v, in);

  // Oracle: V(T, p) = V0 (1 + a (T - T0)) (1 - k p), rho from EOS-80 with pressure.
  auto volume = [&](double t, double pr) {
    return hull.volume_m3 * (1 + 6.9e-5 * (t - hull.reference_temperature_degC)) * (1 - 3.0e-6 * pr);
  };
  const double p_log = seawater::pressureFromDepth(80.0), p_next = seawater::pressureFromDepth(150.0);
  const double mass = seawater::density(34.0, 14.0, p_log) * volume(14.0, p_log) - 5.3;
  const double b_next = seawater::density(35.2, 4.0, p_next) * volume(4.0, p_next);
  EXPECT_NEAR(p.vehicle.mass.mass_kg, mass, 1e-9);
  EXPECT_NEAR(p.net_before_kg, b_next - mass, 1e-9);
  EXPECT_NEAR(p.predicted.net_buoyancy_kg, b_next - mass - addedKg(p), 1e-9);
  // Colder, saltier, deeper water: several kg more buoyant than in the log.
  EXPECT_GT(p.net_before_kg - 5.3, 2.0);
}

TEST(PreMissionPlan, MoveConservesMassAndFirstMoment) {
  const VehicleProfile v = hugin();
  const PreMissionPlan p = planPreMission(v, baseInput());
  // CG after = (m cg + sum m_i r_i) / (m + sum m_i), from the points alone.
  Eigen::Vector3d moment = p.vehicle.mass.mass_kg * p.vehicle.mass.cg_m;
  double mass = p.vehicle.mass.mass_kg;
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    double from_pieces = 0;
    for (const auto& pc : p.points[i].pieces) from_pieces += pc.size_kg * pc.count;
    EXPECT_NEAR(from_pieces, p.points[i].add_kg, 1e-9);
    moment += p.points[i].add_kg * v.points[i].position_m;
    mass += p.points[i].add_kg;
    // Never takes out more than is installed, never beyond capacity.
    EXPECT_GE(baseInput().installed_kg[i] + p.points[i].add_kg, -1e-9);
    EXPECT_LE(baseInput().installed_kg[i] + p.points[i].add_kg, v.points[i].capacity_kg + 1e-9);
  }
  const Eigen::Vector3d cg = moment / mass;
  EXPECT_NEAR(p.predicted.cg_offset_m.x(), cg.x() - v.cb_m.x(), 1e-12);
  EXPECT_NEAR(p.predicted.cg_offset_m.y(), cg.y() - v.cb_m.y(), 1e-12);
}

TEST(PreMissionPlan, NeverNegativeAtAnyPlannedPointIncludingTheMargin) {
  const VehicleProfile v = hugin();
  PreMissionInput in = baseInput();
  // Deep mission: seawater is ~4.6 kg/m3 denser at 1000 m, so a vehicle that
  // is in band down there is heavy at the surface.
  in.next = nextMissionWater(water(4.0, 35.0, 1000.0), 0.0, "operator");
  const PreMissionPlan p = planPreMission(v, in);
  ASSERT_EQ(p.at_points.size(), 2u);
  EXPECT_EQ(p.at_points[1].role, "surface");
  EXPECT_TRUE(p.safe);
  EXPECT_NEAR(p.margin_kg, 1.645 * p.net_sigma_kg, 1e-12);
  EXPECT_GE(p.net_sigma_kg, in.estimate.net_buoyancy_sigma_kg);
  for (const auto& r : p.at_points) EXPECT_GE(r.net_after_kg, p.margin_kg - 1e-6) << r.role;
  // Surface vs 1000 m at the same T, S: rho V differs by the compression of seawater.
  const double spread = p.at_points[0].displaced_kg - p.at_points[1].displaced_kg;
  const double rho_deep = seawater::density(35, 4, seawater::pressureFromDepth(1000)), rho_top = seawater::density(35, 4, 0);
  EXPECT_NEAR(spread, (rho_deep - rho_top) * v.hull.volume_m3, 1e-9);
  EXPECT_GT(spread, 6.5);
  // So the band at depth cannot be met, and the plan says why.
  EXPECT_FALSE(p.buoyancy_in_band);
  EXPECT_GE(p.predicted.net_buoyancy_kg, spread + p.margin_kg - 1e-6);
  EXPECT_TRUE(anyContains(p.warnings, "safety margin")) << ::testing::PrintToString(p.warnings);
}

TEST(PreMissionPlan, CompressibleHullMakesTheDeepestPointTheCriticalOne) {
  VehicleProfile v = hugin();
  PreMissionInput in = baseInput();
  HullModel hull = v.hull;
  hull.compressibility_per_dbar = 2.0e-5;  // softer than seawater (~4.4e-6 /dbar)
  in.hull = hull;
  in.next = nextMissionWater(water(6.0, 35.0, 100.0), 400.0, "operator");
  const PreMissionPlan p = planPreMission(v, in);
  ASSERT_EQ(p.at_points.size(), 3u);
  const auto deepest = std::find_if(p.at_points.begin(), p.at_points.end(), [](const auto& r) { return r.role == "deepest"; });
  ASSERT_NE(deepest, p.at_points.end());
  for (const auto& r : p.at_points) EXPECT_GE(r.net_after_kg, deepest->net_after_kg - 1e-12) << r.role;
  EXPECT_GE(deepest->net_after_kg, p.margin_kg - 1e-6);
  EXPECT_TRUE(p.safe);
}

TEST(PreMissionPlan, ExactPlanLandsInTheBandWithTheOptionalPiece) {
  const VehicleProfile v = hugin();
  PreMissionInput in = baseInput();
  in.use_optional_pieces = true;
  const PreMissionPlan p = planPreMission(v, in);
  EXPECT_TRUE(p.buoyancy_in_band);
  EXPECT_GE(p.predicted.net_buoyancy_kg, p.band_lo_kg - 1e-9);
  EXPECT_LE(p.predicted.net_buoyancy_kg, v.spec.net_buoyancy_max_kg + 1e-9);
  EXPECT_TRUE(p.pitch_in_band);
  EXPECT_TRUE(p.roll_in_band);
  EXPECT_LT(std::abs(p.predicted.pitch_deg), 0.5);
  // From 12 mm forward, 1.5 mm starboard to within the bands: the CG moved aft and to port.
  EXPECT_LT(std::abs(p.predicted.cg_offset_m.x()), 0.2e-3);
  EXPECT_LT(std::abs(p.predicted.cg_offset_m.y()), 0.05e-3);
}

TEST(PreMissionPlan, AttitudeSigmaIsTheOffsetSigmaOverBg) {
  // Near level, d(pitch)/d(x) = -1/BG and d(roll)/d(y) = 1/BG (static_trim.h).
  const VehicleProfile v = hugin();
  PreMissionInput in = baseInput();
  in.use_optional_pieces = true;
  in.estimate.cg_x_sigma_m = 0.04e-3;
  in.estimate.cg_y_sigma_m = 0.01e-3;
  in.estimate.net_buoyancy_sigma_kg = 0.0;
  const PreMissionPlan p = planPreMission(v, in);
  ASSERT_LT(std::abs(p.predicted.pitch_deg), 0.5);
  EXPECT_NEAR(p.pitch_sigma_deg, units::radToDeg(0.04e-3 / v.bg_m), 0.02 * p.pitch_sigma_deg);
  EXPECT_NEAR(p.roll_sigma_deg, units::radToDeg(0.01e-3 / v.bg_m), 0.02 * p.roll_sigma_deg);
}

TEST(PreMissionPlan, SaysWhenTheKitCannotReachRollAndNamesThePiece) {
  // Issue #6 item 4: with BG 20 mm one 1.2 kg piece moved across the 0.65 m
  // between the points rolls the vehicle by atan(0.78 / (1564 * 0.02)) = 1.4 deg.
  const VehicleProfile v = hugin();
  PreMissionInput in = baseInput();
  in.estimate = estimateAt(0.6, 0.0, 0.4, 6.0, 35.0, 50.0, 0.05, 0.01, 0.001);
  const PreMissionPlan p = planPreMission(v, in);
  EXPECT_FALSE(p.roll_in_band);
  EXPECT_TRUE(anyContains(p.warnings, "roll band")) << ::testing::PrintToString(p.warnings);
  EXPECT_TRUE(anyContains(p.warnings, "piece would reach it")) << ::testing::PrintToString(p.warnings);
  EXPECT_TRUE(anyContains(p.notes, "optional pieces (0.5 kg)"));
  // The best it can do is at most half a step: |roll| <= 0.72 deg.
  EXPECT_LE(std::abs(p.predicted.roll_deg), 0.5 * units::radToDeg(std::atan(1.2 * 0.65 / (p.vehicle.mass.mass_kg * v.bg_m))) + 0.01);
  in.use_optional_pieces = true;
  const PreMissionPlan q = planPreMission(v, in);
  EXPECT_LT(std::abs(q.predicted.roll_deg), std::abs(p.predicted.roll_deg));
}

TEST(PreMissionPlan, HalfWayMovesAboutHalfAndStaysSafe) {
  const VehicleProfile v = hugin();
  PreMissionInput in = baseInput();
  in.use_optional_pieces = true;
  const PreMissionPlan exact = planPreMission(v, in);
  in.policy = PlanPolicy::HalfWay;
  const PreMissionPlan half = planPreMission(v, in);
  // Net buoyancy: the band moves up by half the excess over it.
  const double excess = half.net_before_kg - half.band_hi_kg;
  EXPECT_GT(half.predicted.net_buoyancy_kg, exact.predicted.net_buoyancy_kg + 0.4 * excess);
  EXPECT_LT(half.predicted.net_buoyancy_kg, exact.predicted.net_buoyancy_kg + 0.6 * excess + 0.3);
  // Pitch about half-way (on tan pitch, the CG-CB offset).
  const double t_before = std::tan(units::degToRad(half.pitch_before_deg));
  const double t_half = std::tan(units::degToRad(half.predicted.pitch_deg));
  EXPECT_NEAR(t_half / t_before, 0.5, 0.1);
  EXPECT_TRUE(half.safe);
}

TEST(PreMissionPlan, OneExplanationPerChangedPointAndTheSharesAddUp) {
  const VehicleProfile v = hugin();
  const PreMissionPlan p = planPreMission(v, baseInput());
  std::size_t changed = 0;
  for (const auto& pt : p.points) changed += !pt.pieces.empty();
  ASSERT_GT(changed, 0u);
  EXPECT_EQ(p.explanations.size(), changed);
  for (const auto& e : p.explanations) {
    EXPECT_NE(e.find("net buoyancy by"), std::string::npos) << e;
    EXPECT_EQ(std::count(e.begin(), e.end(), '.') >= 1, true);
  }
  const auto j = toJson(p);
  std::size_t with_text = 0;
  for (const auto& pt : j["recommendation"]["points"]) with_text += pt.contains("explanation");
  EXPECT_EQ(with_text, changed);
}

TEST(PreMissionPlan, JsonHasTheFirstMissionShapes) {
  const PreMissionPlan p = planPreMission(hugin(), baseInput());
  const auto j = toJson(p);
  ASSERT_EQ(j["recommendation"]["points"].size(), 4u);
  EXPECT_EQ(j["recommendation"]["points"][0]["name"], "fore_starboard");
  for (const char* k : {"net_buoyancy_kg", "pitch_deg", "roll_deg"}) {
    EXPECT_TRUE(j["recommendation"]["predicted"][k].is_number()) << k;
    EXPECT_EQ(j["recommendation"]["predicted"][k], j["predicted"][k]);
  }
  EXPECT_TRUE(j["predicted"]["cg_offset_mm"]["x"].is_number());
  EXPECT_TRUE(j["safety"]["safe"].get<bool>());
  EXPECT_EQ(j["policy"], "exact");
}

TEST(PreMissionPlan, ClassicPolicyIsTheTableOnTheAnalysisDeviations) {
  // Table F.2 case 3 (+0.8 deg nose up, no depth/roll error) on App. G.2's pieces.
  PreMissionInput in = baseInput();
  in.policy = PlanPolicy::Classic;
  in.estimate.depth_error_m = 0.0;
  in.estimate.pitch_error_deg = 0.8;
  in.estimate.roll_deg = 0.0;
  const PreMissionPlan p = planPreMission(hugin(), in);
  const double expected[] = {1.2, 1.2, -1.2, -1.2};  // Table G.3
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(p.points[i].add_kg, expected[i], 1e-9) << i;
  EXPECT_EQ(p.details["classic"]["weight_case"], "W = B");
  in.estimate.roll_deg.reset();
  try {
    planPreMission(hugin(), in);
    FAIL() << "no roll deviation";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "errors.roll_deg");
  }
}

TEST(PreMissionPlan, BadInputNamesTheField) {
  const VehicleProfile v = hugin();
  PreMissionInput in = baseInput();
  in.installed_kg = {1.2, 1.2};
  try {
    planPreMission(v, in);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "installed");
  }
  in = baseInput();
  in.installed_kg[2] = 1.3;  // not a sum of pieces
  try {
    planPreMission(v, in);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "installed.aft_starboard");
  }
  in = baseInput();
  in.estimate.net_buoyancy_sigma_kg = -1;
  try {
    planPreMission(v, in);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "net_buoyancy_sigma_kg");
  }
  EXPECT_THROW(planPolicyFromString("fast"), InputError);
}

// A used buoyancy law widens the plan's margin by its sigma; an edited
// report with a negative or missing one is refused, naming the entry.
TEST(TrimEstimateFromReport, AUsedLawNeedsANonNegativeSigma) {
  nlohmann::json r = nlohmann::json::parse(R"({
    "net_buoyancy_kg": 2.5, "net_buoyancy_sigma_kg": 0.2,
    "water": {"temperature_degC": 6.5, "salinity_psu": 34.5, "depth_m": 49.6},
    "calibration": [{"id": "propeller_torque", "value": 9.0, "sigma": -1.0, "used": true},
                    {"id": "hull_compressibility", "value": 3e-6, "sigma": 1e-6, "used": true}]
  })");
  EXPECT_DOUBLE_EQ(trimEstimateFromReport(r, "a.json").hull_compressibility_sigma_per_dbar, 1e-6);
  for (const nlohmann::json& bad_sigma : {nlohmann::json(-1e-6), nlohmann::json(nullptr)}) {
    r["calibration"][1]["sigma"] = bad_sigma;
    try {
      trimEstimateFromReport(r, "a.json");
      FAIL() << bad_sigma;
    } catch (const InputError& err) {
      const std::string m = err.what();
      EXPECT_NE(m.find("a.json"), std::string::npos) << m;
      EXPECT_NE(m.find("calibration[1]"), std::string::npos) << m;
      EXPECT_NE(m.find("sigma"), std::string::npos) << m;
    }
  }
  r["calibration"][1]["used"] = false;  // not used: the plan keeps the profile's law, its sigma unread
  EXPECT_DOUBLE_EQ(trimEstimateFromReport(r, "a.json").hull_compressibility_sigma_per_dbar, 0.0);
}

TEST(TrimEstimateFromReport, ReadsTheAnalysisContract) {
  const nlohmann::json r = nlohmann::json::parse(R"({
    "net_buoyancy_kg": 2.5, "net_buoyancy_sigma_kg": 0.2,
    "cg_offset_mm": {"x": -4.0, "y": null}, "cg_offset_sigma_mm": {"x": 0.3, "y": null},
    "errors": {"depth_m": 0.4, "pitch_deg": -0.6, "roll_deg": 0.7},
    "water": {"temperature_degC": 6.5, "salinity_psu": 34.5, "density_kgm3": null, "pressure_dbar": 50.0, "depth_m": 49.6}
  })");
  const TrimEstimate e = trimEstimateFromReport(r, "a.json");
  EXPECT_DOUBLE_EQ(e.net_buoyancy_kg, 2.5);
  ASSERT_TRUE(e.cg_x_m.has_value());
  EXPECT_DOUBLE_EQ(*e.cg_x_m, -0.004);
  EXPECT_DOUBLE_EQ(e.cg_x_sigma_m, 0.0003);
  EXPECT_FALSE(e.cg_y_m.has_value());
  EXPECT_NEAR(e.water.density_kgm3, seawater::density(34.5, 6.5, 50.0), 1e-12);  // derived when null
  EXPECT_DOUBLE_EQ(*e.roll_deg, 0.7);
  nlohmann::json bad = r;
  bad["net_buoyancy_kg"] = nullptr;
  try {
    trimEstimateFromReport(bad, "a.json");
    FAIL();
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("net_buoyancy_kg"), std::string::npos) << err.what();
  }
}

TEST(TrimEstimateFromReport, PlansRollOnTheCruiseEquivalentCgY) {
  // A static CG y of +0.5 mm, but the propeller torque rolls the vehicle
  // so that it flies as if y were -0.8 mm: the plan levels it at cruise.
  const nlohmann::json r = nlohmann::json::parse(R"({
    "net_buoyancy_kg": 2.5, "net_buoyancy_sigma_kg": 0.2,
    "cg_offset_mm": {"x": 0.0, "y": 0.5}, "cg_offset_sigma_mm": {"x": 0.3, "y": 0.01},
    "cruise": {"prop_rpm": 160, "roll_deg": -2.3, "roll_sigma_deg": 0.01, "cg_y_mm": -0.8, "cg_y_sigma_mm": 0.004},
    "water": {"temperature_degC": 6.5, "salinity_psu": 34.5, "pressure_dbar": 50.0, "depth_m": 49.6}
  })");
  const TrimEstimate e = trimEstimateFromReport(r, "a.json");
  ASSERT_TRUE(e.cg_y_m.has_value());
  EXPECT_DOUBLE_EQ(*e.cg_y_m, -0.0008);
  EXPECT_DOUBLE_EQ(e.cg_y_sigma_m, 0.000004);
  EXPECT_EQ(e.cg_y_basis, "cruise");
  PreMissionInput in = baseInput();
  in.estimate.cg_y_m = e.cg_y_m;
  in.estimate.cg_y_basis = e.cg_y_basis;
  in.estimate.cruise_rpm = e.cruise_rpm;
  const PreMissionPlan p = planPreMission(hugin(), in);
  EXPECT_TRUE(anyContains(p.notes, "roll is planned and predicted at cruise (160 rpm"));
  // More weight goes to starboard than to port: the CG moves to +y.
  double moment_y = 0.0;
  for (std::size_t i = 0; i < p.points.size(); ++i) moment_y += p.points[i].add_kg * hugin().points[i].position_m.y();
  EXPECT_GT(moment_y, 0.0);
}

TEST(TrimEstimateFromReport, PlansRollWithTheBgTheRollWasMeasuredWith) {
  // The analysis turned a 14 deg cruise roll into y = BG sin(roll) with the
  // roll test's BG (14 mm, the profile says 20 mm). The plan must roll the
  // vehicle back with the same BG: with the profile's, 3.4 mm of side offset
  // reads as 9.7 deg and every lateral move is predicted 30 % too small.
  nlohmann::json r = nlohmann::json::parse(R"({
    "net_buoyancy_kg": 2.5, "net_buoyancy_sigma_kg": 0.05,
    "cg_offset_mm": {"x": 0.0, "y": 0.3}, "cg_offset_sigma_mm": {"x": 0.05, "y": 0.01},
    "cruise": {"prop_rpm": 160, "roll_deg": 14.0, "roll_sigma_deg": 0.01, "cg_y_mm": 3.3870, "cg_y_sigma_mm": 0.004},
    "water": {"temperature_degC": 8.0, "salinity_psu": 35.0, "pressure_dbar": 100.0, "depth_m": 99.0},
    "details": {"auv_estimate": {"bg_mm": 14.0, "bg_source": "--bg-mm"}}
  })");
  const TrimEstimate e = trimEstimateFromReport(r, "a.json");
  ASSERT_TRUE(e.bg_m.has_value());
  EXPECT_DOUBLE_EQ(*e.bg_m, 0.014);
  PreMissionInput in = baseInput();
  in.estimate = e;
  in.policy = PlanPolicy::Exact;
  in.use_optional_pieces = true;
  const PreMissionPlan p = planPreMission(hugin(), in);
  // Within 0.1 deg: the static trim also holds (W - B) r_CB, which this
  // hand sum leaves out; the profile's BG would be 4 deg away.
  EXPECT_NEAR(p.roll_before_deg, units::radToDeg(std::atan(3.387 / 14.0)), 0.1);
  // A side move the operator makes instead, by hand: 9.6 kg to starboard
  // (the points lie on the CB's plane, so the pieces also raise the CG).
  const VehicleProfile& v = hugin();
  const std::vector<double> after = {in.installed_kg[0] + 4.8, in.installed_kg[1], in.installed_kg[2] + 4.8, in.installed_kg[3]};
  const InstalledPrediction ip = predictInstalled(v, p, in.installed_kg, after);
  const double W = p.vehicle.mass.mass_kg;
  double m = W, my = W * 0.003387, mz = W * 0.014;
  for (std::size_t i = 0; i < after.size(); ++i) {
    const double dm = after[i] - in.installed_kg[i];
    m += dm;
    my += dm * (v.points[i].position_m.y() - v.cb_m.y());
    mz += dm * (v.points[i].position_m.z() - v.cb_m.z());
  }
  EXPECT_NEAR(ip.roll_deg, units::radToDeg(std::atan2(my / m, mz / m)), 0.1);
  EXPECT_GT(ip.roll_deg, 20.0);  // with the profile's 20 mm it would read 15.5 deg
  // The profile's BG only where the analysis used it.
  r["details"]["auv_estimate"]["bg_source"] = "profile";
  EXPECT_FALSE(trimEstimateFromReport(r, "a.json").bg_m.has_value());
  r["details"]["auv_estimate"]["bg_source"] = "--bg-mm";
  r["details"]["auv_estimate"]["bg_mm"] = -3.0;
  try {
    trimEstimateFromReport(r, "a.json");
    FAIL();
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("bg_mm"), std::string::npos) << err.what();
  }
}

TEST(PreMissionPlan, UnidentifiedCgIsAssumedAtCbWithAWarning) {
  PreMissionInput in = baseInput();
  in.estimate.cg_x_m.reset();
  const PreMissionPlan p = planPreMission(hugin(), in);
  EXPECT_TRUE(p.vehicle.cg_x_assumed);
  EXPECT_TRUE(anyContains(p.warnings, "CG x was not identified"));
}

// A log not flown as commanded (details.flight_envelope, analysis
// flight_envelope.h) is read into the estimate, and the plan built on it
// says so with the sigma it rests on; a log flown as commanded gets no note.
TEST(PreMissionPlan, APlanFromALogNotFlownAsCommandedSaysSo) {
  nlohmann::json r = nlohmann::json::parse(R"({
    "net_buoyancy_kg": 2.5, "net_buoyancy_sigma_kg": 0.2,
    "cg_offset_mm": {"x": -4.0, "y": null}, "cg_offset_sigma_mm": {"x": 0.3, "y": null},
    "water": {"temperature_degC": 6.5, "salinity_psu": 34.5, "density_kgm3": null, "pressure_dbar": 50.0, "depth_m": 49.6},
    "details": {"flight_envelope": {"leg_s": 7000.0,
      "too_light": {"legs": 2, "seconds": 1500.0, "median_depth_error_m": -2.8, "elevator_stop_deg": 25.0},
      "porpoising": {"legs": 9, "seconds": 7400.0, "pitch_sd_deg": 24.8, "period_s": 24.5}}}
  })");
  const TrimEstimate e = trimEstimateFromReport(r, "a.json");
  EXPECT_TRUE(e.log_too_light);
  EXPECT_FALSE(e.log_too_heavy);
  EXPECT_TRUE(e.log_porpoising);
  auto noteOf = [](const PreMissionPlan& p) -> std::string {
    for (const Message& n : p.notes)
      if (n.id() == "plan.log_not_as_commanded") return n;
    return {};
  };
  PreMissionInput in = baseInput();
  in.estimate = e;
  const PreMissionPlan p = planPreMission(hugin(), in);
  const std::string note = noteOf(p);
  EXPECT_NE(note.find("too light or stern-heavy to hold its depth, porpoising"), std::string::npos) << note;
  char sigma[16];
  std::snprintf(sigma, sizeof sigma, "%.2f kg", p.net_sigma_kg);
  EXPECT_NE(note.find(sigma), std::string::npos) << note;
  r["details"]["flight_envelope"] = {{"leg_s", 7000.0}};
  in.estimate = trimEstimateFromReport(r, "a.json");
  EXPECT_EQ(noteOf(planPreMission(hugin(), in)), "");
}
