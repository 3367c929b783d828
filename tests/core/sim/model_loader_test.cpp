#include "sim/model_loader.h"

#include <gtest/gtest.h>

#include "common/input_error.h"
#include "common/units.h"
#include "sim_fixtures.h"
#include "vehicle/json_reader.h"

namespace auv::sim {
namespace {

using testing::Delphin2;

TEST(ModelLoader, Delphin2MatchesPaperAppendixA) {
  const Delphin2 d;
  const VehicleModel& m = d.model;
  EXPECT_DOUBLE_EQ(m.body.mass_kg, 79.40);
  EXPECT_DOUBLE_EQ(m.body.hull.volume_m3, 0.08);
  EXPECT_DOUBLE_EQ(m.body.reference_length_m, 1.96);
  EXPECT_DOUBLE_EQ(m.body.Iyy_kgm2, 35.0);
  EXPECT_NEAR((m.body.r_g_m - Eigen::Vector3d(0, 0, 0.06)).norm(), 0.0, 1e-15);  // r_b = 0: r_g relative to CB
  EXPECT_DOUBLE_EQ(m.hydro.Xudot_kg, -2.4);
  EXPECT_DOUBLE_EQ(m.hydro.Zwdot_kg, -65.5);
  EXPECT_DOUBLE_EQ(m.hydro.Mqdot_kgm2, -14.17);
  EXPECT_DOUBLE_EQ(m.hydro.Zw_prime, -28.5e-3);
  EXPECT_DOUBLE_EQ(m.hydro.Zq_prime, -12.6e-3);
  EXPECT_DOUBLE_EQ(m.hydro.Mw_prime, -4.5e-3);
  EXPECT_DOUBLE_EQ(m.hydro.Mq_prime, -5.3e-3);
  EXPECT_DOUBLE_EQ(m.hydro.Xuu_kg_per_m, -6.5);
  EXPECT_DOUBLE_EQ(m.hydro.Zww_kg_per_m, -183.0);
  EXPECT_DOUBLE_EQ(m.hydro.Zqq_kgm, 0.0);
  EXPECT_DOUBLE_EQ(m.hydro.Mww_kg, -59.0);
  EXPECT_DOUBLE_EQ(m.hydro.Mqq_kgm2, -82.0);
  EXPECT_DOUBLE_EQ(m.prop.KT0, 0.0946);
  EXPECT_DOUBLE_EQ(m.prop.diameter_m, 0.305);
  EXPECT_DOUBLE_EQ(m.prop.c1, 0.6999);
  EXPECT_DOUBLE_EQ(m.prop.c2, 1.5205);
  EXPECT_DOUBLE_EQ(m.prop.wake_fraction, 0.36);
  EXPECT_DOUBLE_EQ(m.prop.thrust_deduction, 0.11);
  EXPECT_DOUBLE_EQ(m.prop.rps_a2, -0.0055);
  EXPECT_DOUBLE_EQ(m.prop.rps_a1, 0.4136);
  EXPECT_DOUBLE_EQ(m.prop.rps_a0, -1.7895);
  ASSERT_EQ(m.thruster_count, 2);
  for (const auto& t : m.thrusters) {
    EXPECT_DOUBLE_EQ(t.KT_per_rpm2, 1.2870e-4);
    EXPECT_DOUBLE_EQ(t.diameter_m, 0.07);
    EXPECT_DOUBLE_EQ(t.c_th1_s2_per_m2, 0.35);
    EXPECT_DOUBLE_EQ(t.c_th2, 1.5);
    EXPECT_DOUBLE_EQ(t.deadband_rpm, 150.0);  // sec. 2
  }
  EXPECT_DOUBLE_EQ(m.thrusters[0].x_m, 0.52);
  EXPECT_DOUBLE_EQ(m.thrusters[1].x_m, -0.54);
  EXPECT_DOUBLE_EQ(m.thruster_drag.a1, 0.5660);
  EXPECT_DOUBLE_EQ(m.thruster_drag.b1, 7.6089);
  EXPECT_DOUBLE_EQ(m.thruster_drag.a2, 0.0565);
  EXPECT_DOUBLE_EQ(m.thruster_drag.b2, 0.8968);
  EXPECT_DOUBLE_EQ(m.planes.X_uudd_per_deg2, -0.0036);
  EXPECT_DOUBLE_EQ(m.planes.Z_uud_per_deg, 0.3241);
  EXPECT_DOUBLE_EQ(m.planes.M_uud_per_deg, 0.3254);
  EXPECT_DOUBLE_EQ(m.power.hotel_w, 30.0);  // sec. 2
}

TEST(ModelLoader, AppendixANetBuoyancyIsSixNewtonsInFreshWater) {
  // App. A gives m = 79.40 kg, V = 0.08 m^3 and W - B = -6 N. In fresh water
  // (1000 kg/m^3) the first two give B - W = 5.88 N: the volume is printed to
  // two digits, so the scenarios trim to exactly +6 N (Scenario::net_buoyancy_n).
  const Delphin2 d;
  const double B = 1000.0 * units::g0 * d.model.body.hull.volume_m3;
  const double W = d.model.body.mass_kg * units::g0;
  EXPECT_NEAR(B - W, 6.0, 0.15);
}

TEST(ModelLoader, AutopilotWeightsAreThePapersFigure12) {
  const Delphin2 d;
  EXPECT_DOUBLE_EQ(d.autopilot.u_th_mid_mps, 0.85);
  EXPECT_DOUBLE_EQ(d.autopilot.u_th_width_mps, 0.03);
  EXPECT_DOUBLE_EQ(d.autopilot.u_s_mid_mps, 0.5);
  EXPECT_DOUBLE_EQ(d.autopilot.u_s_width_mps, 0.04);
  EXPECT_DOUBLE_EQ(d.autopilot.sample_time_s, 0.2);  // 5 Hz
  EXPECT_DOUBLE_EQ(d.autopilot.hover_preload_factor, 1.2);
  EXPECT_LT(d.autopilot.hover_force.kd, 0.0);  // PI-D: derivative on the state
  EXPECT_NEAR(d.autopilot.pitch_bias.kp, units::degToRad(-15.0), 1e-15);  // file is in degrees
}

TEST(ModelLoader, MissingFieldIsNamedWithFileAndPath) {
  Delphin2 d;
  d.profile.sections["hydrodynamics"].erase("Zwdot_kg");
  try {
    (void)loadVehicleModel(d.profile);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "hydrodynamics.Zwdot_kg");
    EXPECT_EQ(e.where().file, testing::delphin2Path());
  }
}

TEST(ModelLoader, OutOfRangeAndWrongSignAreRejected) {
  Delphin2 d;
  d.profile.sections["hydrodynamics"]["Xuu_kg_per_m"] = 6.5;  // damping must be <= 0
  EXPECT_THROW((void)loadVehicleModel(d.profile), InputError);
  Delphin2 e;
  e.profile.sections["autopilot"]["pitch_bias"]["K_P_deg_per_m"] = 15.0;
  try {
    (void)loadAutopilotConfig(e.profile);
    FAIL() << "expected InputError";
  } catch (const InputError& err) {
    EXPECT_EQ(err.field(), "autopilot.pitch_bias.K_P_deg_per_m");
  }
  Delphin2 f;
  f.profile.sections["actuators"]["tunnel_thrusters"]["spacing_m"] = 1.2;  // != 0.52 + 0.54
  EXPECT_THROW((void)loadVehicleModel(f.profile), InputError);
}

TEST(ModelLoader, ProfileWithoutSimSectionsSaysWhichIsMissing) {
  Delphin2 d;
  d.profile.sections.erase("actuators");
  try {
    (void)loadVehicleModel(d.profile);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "actuators");
  }
}

}  // namespace
}  // namespace auv::sim
