// The CG y that levels the vehicle at cruise (analysis/auv_roll_estimation.h)
// on segments whose roll is the exact equilibrium of a vehicle with a known
// CG y, BG and propeller torque, flown level or steeply pitched. The oracle
// is the level-flight heeling equivalent y + Q / W: zeroing it levels the
// vehicle in level cruise whatever pitch the log was flown at.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analysis/auv_roll_estimation.h"
#include "common/units.h"

namespace auv::analysis {
namespace {

constexpr double kW_n = 15000.0, kBg_m = 0.02, kTorque_nm_per_100rpm2 = 20.0;

double torqueNm(double rpm) { return kTorque_nm_per_100rpm2 * std::pow(rpm / 100.0, 2); }

MeanEstimate exact(double v, double se) {
  MeanEstimate m;
  m.mean = v;
  m.se = se;
  m.n = 600;
  return m;
}

// Roll balance with pitch theta: W cos(theta) (BG sin(phi) - y cos(phi)) = Q.
SteadySegmentMeans segment(double t0_s, double rpm, double pitch_deg, double y_m) {
  const double th = units::degToRad(pitch_deg);
  const double r = std::hypot(kBg_m, y_m), a = std::atan2(y_m, kBg_m);
  const double phi = a + std::asin(torqueNm(rpm) / (kW_n * std::cos(th) * r));
  SteadySegmentMeans g;
  g.start_s = t0_s;
  g.end_s = t0_s + 900.0;
  g.prop_rpm = exact(rpm, 0.1);
  g.pitch_deg = exact(pitch_deg, 0.01);
  g.roll_deg = exact(units::radToDeg(phi), 0.01);
  return g;
}

AuvTrimContext context() {
  AuvTrimContext c;
  c.weight_n = kW_n;
  c.bg_measured_m = kBg_m;
  c.bg_profile_m = kBg_m;
  c.log_has_rpm = true;
  return c;
}

AuvTrimEstimate estimate(const std::vector<SteadySegmentMeans>& s) {
  AuvTrimEstimate e;
  estimateRoll(s, context(), e);
  return e;
}

TEST(RollEstimation, CruiseCgYIsTheLevelFlightEquivalentAtAnyPitch) {
  constexpr double y_m = 0.001;
  for (double pitch_deg : {0.0, -15.0, -55.0}) {
    SCOPED_TRACE(pitch_deg);
    std::vector<SteadySegmentMeans> s;
    for (int i = 0; i < 4; ++i) s.push_back(segment(1000.0 * i, i % 2 ? 150.0 : 120.0, pitch_deg, y_m));
    const AuvTrimEstimate e = estimate(s);
    ASSERT_TRUE(e.y_cruise_identified);
    EXPECT_EQ(e.cruise_rpm, 150.0);
    EXPECT_NEAR(e.y_m, y_m, 1e-6);
    // Read as level flight, the 55-deg log's torque came out 1/cos(55 deg) =
    // 1.74 times too large: 6.2 mm here instead of 4.0.
    EXPECT_NEAR(e.y_cruise_m, y_m + torqueNm(150.0) / kW_n, 2e-6);
  }
}

TEST(RollEstimation, OnePropellerSpeedTakesTheRollAsTorqueAtAnyPitch) {
  for (double pitch_deg : {0.0, -40.0}) {
    SCOPED_TRACE(pitch_deg);
    const std::vector<SteadySegmentMeans> s{segment(0.0, 150.0, pitch_deg, 0.0), segment(1000.0, 150.0, pitch_deg, 0.0)};
    const AuvTrimEstimate e = estimate(s);
    ASSERT_TRUE(e.y_cruise_identified);
    EXPECT_EQ(e.y_basis, "cruise_equivalent");
    EXPECT_NEAR(e.y_cruise_m, torqueNm(150.0) / kW_n, 2e-6);
  }
}

}  // namespace
}  // namespace auv::analysis
