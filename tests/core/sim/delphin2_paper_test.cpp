// Delphin2 against Tanakitkorn et al., sec. 8 and Tables 1-2. The paper
// publishes no controller gains, so ours (resources/vehicles/delphin2.json,
// "autopilot") were tuned once on this model; every other number is the
// paper's. Tolerances are wide where the paper itself reports only "about"
// or where its own simulation and experiment differ (sec. 8.1: "the
// experiments exhibit a reduced overshoot"). Each test states the paper's
// value, ours, and the band asserted; docs/decisions/sim-delphin2-validation.md
// has the table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/units.h"
#include "sim/ballast_cost.h"
#include "sim/power_model.h"
#include "sim/simulator.h"
#include "sim_fixtures.h"

namespace auv::sim {
namespace {

using testing::Delphin2;

const WaterColumn& tank() {
  static const WaterColumn w = WaterColumn::uniform(1000.0);  // fresh-water towing tank
  return w;
}

struct StepResponse {
  double overshoot_m = 0.0;  // beyond the new demand, in the direction of the step
  double settle_s = 0.0;     // last time outside +-0.1 m, from the step
};

StepResponse response(const SimTrace& tr, double t0, double t1, double from, double to) {
  StepResponse r;
  const double dir = to > from ? 1.0 : -1.0;
  for (std::size_t i = 0; i < tr.size(); ++i) {
    if (tr.time_s[i] < t0 || tr.time_s[i] >= t1) continue;
    r.overshoot_m = std::max(r.overshoot_m, (tr.depth_m[i] - to) * dir);
    if (std::abs(tr.depth_m[i] - to) > 0.1) r.settle_s = tr.time_s[i] - t0;
  }
  return r;
}

double mean(const std::vector<double>& v, const SimTrace& tr, double t0, double t1) {
  double s = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < tr.size(); ++i) {
    if (tr.time_s[i] >= t0 && tr.time_s[i] < t1) {
      s += v[i];
      ++n;
    }
  }
  return s / n;
}

SimTrace hover121(const Delphin2& d, bool anti_windup) {
  DepthAutopilotConfig ap = d.autopilot;
  ap.anti_windup = anti_windup;
  Scenario sc;
  sc.net_buoyancy_n = 6.0;
  sc.legs = {{60.0, 1.0, 0.0}, {60.0, 2.0, 0.0}, {60.0, 1.0, 0.0}};
  return simulate(d.model, ap, tank(), sc);
}

// Steady flight at constant depth: 60 s hover, `seconds` at the demand.
SimTrace flight(const Delphin2& d, double demand, double net_n, double seconds = 180.0) {
  Scenario sc;
  sc.net_buoyancy_n = net_n;
  sc.legs = {{60.0, 1.0, 0.0}, {seconds, 1.0, demand}};
  return simulate(d.model, d.autopilot, tank(), sc);
}

TEST(Delphin2Paper, HoverStepsWithAntiWindup) {
  // Sec. 8.1 / fig. 14b: overshoot about 0.2 m, settles in less than 15 s.
  // Ours: 0.18-0.22 m, 10-15 s.
  const Delphin2 d;
  const SimTrace tr = hover121(d, true);
  const StepResponse down = response(tr, 60, 120, 1, 2), up = response(tr, 120, 180, 2, 1);
  for (const StepResponse& r : {down, up}) {
    EXPECT_GT(r.overshoot_m, 0.1);
    EXPECT_LT(r.overshoot_m, 0.3);
    EXPECT_LT(r.settle_s, 16.0);
  }
  // No steady-state error: the integrator carries the 6 N.
  EXPECT_NEAR(tr.depth_m.back(), 1.0, 0.005);
  EXPECT_NEAR(tr.hover_force_n.back(), 6.0, 0.2);
}

TEST(Delphin2Paper, HoverStepsWithPlainIntegratorOvershootMore) {
  // Sec. 8.1 / fig. 14a: overshoot about 0.5 m, settles within 30 s.
  // Ours: 0.43-0.48 m, 21-22 s.
  const Delphin2 d;
  const SimTrace plain = hover121(d, false);
  const SimTrace aw = hover121(d, true);
  const StepResponse down = response(plain, 60, 120, 1, 2), up = response(plain, 120, 180, 2, 1);
  for (const StepResponse& r : {down, up}) {
    EXPECT_GT(r.overshoot_m, 0.35);
    EXPECT_LT(r.overshoot_m, 0.65);
    EXPECT_LT(r.settle_s, 30.0);
  }
  EXPECT_GT(down.overshoot_m, 2.0 * response(aw, 60, 120, 1, 2).overshoot_m);
}

TEST(Delphin2Paper, PlainIntegratorOvershootGrowsWithStepSize) {
  // Sec. 8.1 / fig. 16: with the plain integrator the overshoot grows with
  // the step, "as high as 1 m for 4 m depth change"; anti-windup removes it.
  // Ours: 2.3 m for the 4 m step (0.45 m for 1 m), 0.20 m with anti-windup.
  // The growth is reproduced, its size is not: it depends on the integral gain
  // and thruster saturation the paper does not publish (gains that give 1 m
  // here halve the 1 m-step overshoot of fig. 14a instead). Asserted: more than
  // twice the 1 m-step overshoot, and anti-windup below 0.35 m.
  const Delphin2 d;
  DepthAutopilotConfig plain = d.autopilot;
  plain.anti_windup = false;
  Scenario sc;
  sc.net_buoyancy_n = 6.0;
  sc.initial_depth_m = 1.0;
  sc.legs = {{90.0, 5.0, 0.0}};
  const StepResponse big = response(simulate(d.model, plain, tank(), sc), 0, 90, 1, 5);
  const StepResponse big_aw = response(simulate(d.model, d.autopilot, tank(), sc), 0, 90, 1, 5);
  const StepResponse small = response(hover121(d, false), 60, 120, 1, 2);
  EXPECT_GT(big.overshoot_m, 2.0 * small.overshoot_m);
  EXPECT_GT(big.overshoot_m, 0.9);
  EXPECT_LT(big_aw.overshoot_m, 0.35);
}

TEST(Delphin2Paper, PropellerDemandGivesThePapersSpeeds) {
  // Sec. 7: demands 10 / 16 / 22 give about 0.26 / 0.6 / 1.0 m/s (+6 N).
  // Ours: 0.255 / 0.570 / 1.025 m/s. Band +-0.05 m/s.
  const Delphin2 d;
  const double paper[] = {0.26, 0.60, 1.00};
  const double demand[] = {10.0, 16.0, 22.0};
  for (int i = 0; i < 3; ++i) {
    const SimTrace tr = flight(d, demand[i], 6.0);
    EXPECT_NEAR(mean(tr.speed_mps, tr, 180, 240), paper[i], 0.05) << "demand " << demand[i];
  }
}

TEST(Delphin2Paper, FliesPitchedDownAtMidAndHighSpeed) {
  // Sec. 8.2: "at mid-speed and high-speed the vehicle needs to pitch down by
  // -5 deg approximately to balance the net buoyancy force". Ours: -5.2 deg
  // (mid), -4.8 deg (high); band -5 +- 1.5 deg. At high speed the thrusters
  // are off and hull lift + planes carry the 6 N; depth held within 0.1 m.
  const Delphin2 d;
  for (double demand : {16.0, 22.0}) {
    const SimTrace tr = flight(d, demand, 6.0);
    EXPECT_NEAR(units::radToDeg(mean(tr.pitch_rad, tr, 180, 240)), -5.0, 1.5) << "demand " << demand;
    for (std::size_t i = 0; i < tr.size(); ++i) {
      if (tr.time_s[i] > 120) {
        EXPECT_NEAR(tr.depth_m[i], 1.0, 0.1) << "t " << tr.time_s[i];
      }
    }
  }
  const SimTrace high = flight(d, 22.0, 6.0);
  EXPECT_EQ(high.thruster_front_rpm.back(), 0.0);
  EXPECT_EQ(high.thruster_aft_rpm.back(), 0.0);
  // Speed transitions disturb depth by less than 0.2 m (sec. 8.2).
  for (std::size_t i = 0; i < high.size(); ++i) {
    if (high.time_s[i] > 30) {
      EXPECT_NEAR(high.depth_m[i], 1.0, 0.2);
    }
  }
}

TEST(Delphin2Paper, SuddenThreeNewtonBuoyancyChange) {
  // Sec. 8.4 / fig. 18: a 3 N change deviates depth by about 0.3 m and is
  // recovered within 20 s, at zero and at high speed. Ours is stiffer: about
  // 0.10 m (zero speed) and 0.09 m (high speed), recovered to within 0.05 m in
  // 8 s and 16 s. Asserted: deviation 0.05..0.35 m, recovery < 20 s.
  const Delphin2 d;
  for (double demand : {0.0, 22.0}) {
    Scenario sc;
    sc.net_buoyancy_n = 6.0;
    sc.legs = {{200.0, 1.0, demand}};
    sc.buoyancy_changes = {{80.0, -3.0}, {140.0, 3.0}};  // weight added, then removed
    const SimTrace tr = simulate(d.model, d.autopilot, tank(), sc);
    for (double tc : {80.0, 140.0}) {
      double dev = 0.0, recover = 0.0;
      for (std::size_t i = 0; i < tr.size(); ++i) {
        if (tr.time_s[i] < tc || tr.time_s[i] > tc + 60) continue;
        const double e = std::abs(tr.depth_m[i] - 1.0);
        dev = std::max(dev, e);
        if (e > 0.05) recover = tr.time_s[i] - tc;
      }
      EXPECT_GT(dev, 0.05) << "demand " << demand << " t " << tc;
      EXPECT_LT(dev, 0.35) << "demand " << demand << " t " << tc;
      EXPECT_LT(recover, 20.0) << "demand " << demand << " t " << tc;
    }
  }
}

TEST(Delphin2Paper, HoverPowerDependsOnBuoyancy) {
  // Tables 1-2 at zero speed: 52.05 W at +6 N, 36.39 W at +1 N. The thruster
  // power coefficient is calibrated on the +6 N row only; +1 N is a
  // prediction. Ours: 52.2 W and 31.7 W. Our +1 N value is lower because the
  // simulated thrusters hold still where the real ones dither around zero
  // (sec. 8.3), and the deadband hides less. Asserted: +6 N within 1 W of the
  // paper, +1 N within 6 W, and the difference at least 10 W (paper 15.7 W).
  const Delphin2 d;
  const SimTrace six = flight(d, 0.0, 6.0, 120.0);
  const SimTrace one = flight(d, 0.0, 1.0, 120.0);
  const double p6 = mean(six.power_w, six, 80, 180), p1 = mean(one.power_w, one, 80, 180);
  EXPECT_NEAR(p6, 52.05, 1.0);
  EXPECT_NEAR(p1, 36.39, 6.0);
  EXPECT_GT(p6 - p1, 10.0);
}

TEST(Delphin2Paper, PowerAgainstSpeedHasTheTrendOfTables1And2) {
  // +6 N (Table 1): 52.05, 59.06, 67.80, 59.90 W for demands 0/10/16/22 - the
  // total rises with speed and drops at high speed when the thrusters switch
  // off. +1 N (Table 2): 36.39, 39.42, 47.40, 53.07 W - rises monotonically.
  // Ours: 52.2, 56.3, 69.8, 52.6 and 31.7, 35.1, 44.0, 52.5 W. Asserted: the
  // same ordering, every row within 8 W, and the buoyancy effect shrinking with
  // speed (P6 - P1 at high speed < 1/3 of that at rest).
  const Delphin2 d;
  const double table6[] = {52.05, 59.06, 67.80, 59.90};
  const double table1[] = {36.39, 39.42, 47.40, 53.07};
  const double demand[] = {0.0, 10.0, 16.0, 22.0};
  double p6[4], p1[4];
  for (int i = 0; i < 4; ++i) {
    const SimTrace a = flight(d, demand[i], 6.0), b = flight(d, demand[i], 1.0);
    p6[i] = mean(a.power_w, a, 160, 240);
    p1[i] = mean(b.power_w, b, 160, 240);
    EXPECT_NEAR(p6[i], table6[i], 8.0) << "demand " << demand[i];
    EXPECT_NEAR(p1[i], table1[i], 8.0) << "demand " << demand[i];
  }
  EXPECT_LT(p6[0], p6[1]);
  EXPECT_LT(p6[1], p6[2]);
  EXPECT_GT(p6[2], p6[3]);
  EXPECT_LT(p1[0], p1[1]);
  EXPECT_LT(p1[1], p1[2]);
  EXPECT_LT(p1[2], p1[3]);
  EXPECT_LT(p6[3] - p1[3], (p6[0] - p1[0]) / 3.0);
}

TEST(Delphin2Paper, ExtraWattsOfABallastError) {
  // The operator's number: watts spent because the vehicle is not neutral.
  // At rest it is the thruster power of eq. 16/25 inverted (hoverHoldPowerW);
  // the closed-loop simulation must agree with that steady-state value.
  const Delphin2 d;
  const BallastErrorCost hover6 = ballastErrorCost(d.model, d.autopilot, tank(), 6.0, 0.0);
  const double analytic = hoverHoldPowerW(d.model, 6.0, 1000.0) - hoverHoldPowerW(d.model, 0.0, 1000.0);
  EXPECT_NEAR(hover6.extra_power_w, analytic, 0.03 * analytic);
  EXPECT_NEAR(hover6.extra_power_w, 21.8, 1.0);  // Table 1 thrusters at rest: 10.73 + 11.11 W
  // In flight at high speed the hull carries the error for almost nothing.
  const BallastErrorCost fly6 = ballastErrorCost(d.model, d.autopilot, tank(), 6.0, 22.0);
  EXPECT_LT(std::abs(fly6.extra_power_w), 1.0);
  EXPECT_NEAR(units::radToDeg(fly6.mean_pitch_rad), -5.0, 1.5);
  // A heavy vehicle costs as much as an equally light one at rest.
  const BallastErrorCost heavy = ballastErrorCost(d.model, d.autopilot, tank(), -6.0, 0.0);
  EXPECT_NEAR(heavy.extra_power_w, hover6.extra_power_w, 0.05 * hover6.extra_power_w);
}

}  // namespace
}  // namespace auv::sim
