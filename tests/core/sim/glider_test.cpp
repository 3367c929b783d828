// Slocum G2 in the simulator: the steady glide is the lift/drag/buoyancy
// force balance, the pitch is core hydrostatics' static trim of battery and
// pump, and the saw-tooth flies its yos between the set depths.
#include "sim/glider_simulator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/input_error.h"
#include "common/units.h"
#include "hydrostatics/static_trim.h"
#include "sim/mission_plan.h"
#include "sim/sim_log.h"
#include "sim_fixtures.h"

namespace auv::sim {
namespace {

struct Slocum {
  VehicleProfile profile = loadVehicleProfile(testing::resourceDir() + "/vehicles/slocum_g2.json");
  GliderModel model = loadGliderModel(profile);
};

TEST(Glider, ParametersFromTheProfileSection) {
  const Slocum s;
  EXPECT_DOUBLE_EQ(s.model.mass_kg, 52.2);
  EXPECT_DOUBLE_EQ(s.model.hull.volume_m3, 0.05103);
  EXPECT_DOUBLE_EQ(s.model.pump_max_m3, 250e-6);  // Baird 2007 sec. 2: +-250 cc
  EXPECT_DOUBLE_EQ(s.model.hull.compressibility_per_dbar, 5e-6);
  EXPECT_DOUBLE_EQ(s.model.hull.thermal_expansion_per_degC, 7e-5);  // the profile's, unchanged
  EXPECT_NEAR(s.model.r_g_m.z(), 0.006, 1e-15);                    // h-arm 6 mm
  VehicleProfile hugin = loadVehicleProfile(testing::resourceDir() + "/vehicles/hugin1000.json");
  try {
    (void)loadGliderModel(hugin);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "glider_flight");
  }
}

TEST(Glider, SteadyGlideBalancesLiftDragAndBuoyancy) {
  const Slocum s;
  const GliderModel& g = s.model;
  const double rho = 1025.0;
  for (double nb_g : {-250.0, -60.0, 40.0, 200.0}) {
    for (double pitch_deg : {-35.0, -26.0, -15.0, 15.0, 26.0, 35.0}) {
      const double F = nb_g * 1e-3 * units::g0;
      const SteadyGlideSolution sol = steadyGlide(g, rho, F, units::degToRad(pitch_deg));
      if (F * pitch_deg < 0) {
        EXPECT_FALSE(sol.gliding);
        continue;
      }
      ASSERT_TRUE(sol.gliding);
      // Independent check: lift is perpendicular to the path, drag along it;
      // together they cancel the net buoyancy (vertical), nothing horizontal.
      const double a = std::abs(sol.alpha_rad), gamma = std::abs(units::degToRad(pitch_deg)) + a;
      const double q = 0.5 * rho * sol.speed_mps * sol.speed_mps;
      const double L = q * g.wing_area_m2 * g.lift_slope_per_rad * a;
      const double D = q * g.wing_area_m2 * (g.Cd0 + g.induced_drag_per_rad2 * a * a);
      EXPECT_NEAR(L * std::cos(gamma) + D * std::sin(gamma), std::abs(F), 1e-9 * std::abs(F));
      EXPECT_NEAR(L * std::sin(gamma), D * std::cos(gamma), 1e-9 * std::abs(F));
      EXPECT_NEAR(sol.w_up_mps, sol.speed_mps * std::sin(units::degToRad(pitch_deg) + sol.alpha_rad), 1e-15);
      EXPECT_GT(sol.w_up_mps * F, 0.0);  // light climbs, heavy dives
    }
  }
  // A Slocum at 26 deg with 250 g of buoyancy: about 0.2 m/s vertical.
  const SteadyGlideSolution sol = steadyGlide(g, rho, 0.25 * units::g0, units::degToRad(26.0));
  EXPECT_NEAR(sol.w_up_mps, 0.2, 0.05);
}

TEST(Glider, BatteryInversionIsCoreStaticTrim) {
  const Slocum s;
  const GliderModel& g = s.model;
  const FlownMass m = flownMass(g.mass_kg, g.r_g_m, g.cb_profile_m, {}, {}, {}, 0.0);
  const double V = g.hull.volume_m3, rho = 1024.0;
  for (double pump : {-250e-6, 0.0, 250e-6}) {
    for (double pitch_deg : {-26.0, -10.0, 0.0, 12.0, 26.0}) {
      const double x = batteryForPitch(g, m, V, rho, pump, units::degToRad(pitch_deg));
      if (std::abs(x) >= g.battery_travel_m) continue;  // out of travel: clamped
      // Oracle: core staticTrim with the battery mass moved and the CB moved
      // by the pumped volume in the nose.
      const double W = m.mass_kg * units::g0, B = rho * units::g0 * (V + pump);
      const Eigen::Vector3d rg = m.r_g_m + Eigen::Vector3d(g.battery_mass_kg * x / m.mass_kg, 0, 0);
      const Eigen::Vector3d rb(pump * g.pump_x_m / (V + pump), 0, 0);
      EXPECT_NEAR(units::radToDeg(staticTrim(W, B, rg, rb).pitch_rad), pitch_deg, 1e-9) << pump << " " << pitch_deg;
    }
  }
  // With the pump at zero, level trim needs the battery at its zero.
  EXPECT_NEAR(batteryForPitch(g, m, V, rho, 0.0, 0.0), 0.0, 1e-15);
}

TEST(Glider, SawToothFliesItsYosAndLogsGliderChannels) {
  const Slocum s;
  const MissionPlan plan = loadMissionPlan(testing::resourceDir() + "/examples/slocum_g2_yo.plan.json");
  ASSERT_TRUE(plan.isGliderPlan());
  const SimTrace tr = simulateGlider(s.model, plan.water, resolveGliderScenario(plan, s.profile), plan.options);
  ASSERT_EQ(tr.size(), 5401u);
  // Inflections: deepest a little past 150 m (the pump takes 50 s to turn it),
  // shallowest a little above 10 m; between, the set pitch.
  const double deepest = *std::max_element(tr.depth_m.begin(), tr.depth_m.end());
  EXPECT_GT(deepest, 150.0);
  EXPECT_LT(deepest, 160.0);
  std::vector<double> dive_starts;
  double pitch_sum = 0.0;
  int pitch_n = 0;
  for (std::size_t i = 1; i < tr.size(); ++i) {
    if (tr.depth_cmd_m[i] == 150.0 && tr.depth_cmd_m[i - 1] == 10.0) dive_starts.push_back(tr.time_s[i]);
    if (tr.depth_m[i] > 40 && tr.depth_m[i] < 120 && tr.pump_volume_m3[i] < -249e-6) {
      pitch_sum += tr.pitch_rad[i];
      ++pitch_n;
    }
    EXPECT_LE(std::abs(tr.battery_position_m[i]), s.model.battery_travel_m + 1e-12);
    EXPECT_LE(std::abs(tr.pump_volume_m3[i]), s.model.pump_max_m3 + 1e-12);
  }
  EXPECT_NEAR(units::radToDeg(pitch_sum / pitch_n), -26.0, 0.05);
  // Yo period: the time to glide 10 -> 150 -> 10 m at the steady vertical
  // speed of each depth's water (F_B = g (rho (V_hull(T, p) + pump) - m)),
  // integrated by hand, plus two inflections, each at most the pump's full
  // 500 cc at 10 cc/s, the speed lag twice (stopping, starting: 2 x 10 s),
  // the pitch lag (10 s) and one 4 s control interval.
  ASSERT_GE(dive_starts.size(), 3u);
  const double period = (dive_starts.back() - dive_starts.front()) / static_cast<double>(dive_starts.size() - 1);
  double steady = 0.0;
  for (double z = 10.05; z < 150.0; z += 0.1) {
    const WaterSample ws = plan.water.at(z);
    const double V = s.model.hull.volumeAt(ws.temperature_degC, ws.pressure_dbar);
    for (double sign : {-1.0, 1.0}) {
      const double F = units::g0 * (ws.density_kgm3 * (V + sign * 250e-6) - tr.truth.mass_kg);
      steady += 0.1 / std::abs(steadyGlide(s.model, ws.density_kgm3, F, units::degToRad(sign * 26.0)).w_up_mps);
    }
  }
  std::printf("yo period %.0f s, steady-glide legs alone %.0f s\n", period, steady);
  EXPECT_GT(period, steady);
  EXPECT_LT(period, steady + 2.0 * (50.0 + 20.0 + 10.0 + 4.0));

  const MissionLog log = toMissionLog(tr, {"slocum_g2", "plan", plan.file, 49, 0, {}, {}});
  for (const char* c : {"depth", "pitch", "pump_volume", "battery_position", "roll_mass", "temperature", "pressure"}) {
    EXPECT_TRUE(log.has(c)) << c;
  }
  EXPECT_FALSE(log.has("speed"));  // a glider measures no speed through water
  EXPECT_FALSE(log.has("prop_rpm"));
  EXPECT_DOUBLE_EQ(log.channel("pump_volume").values[1000], tr.pump_volume_m3[1000] * 1e6);
  ASSERT_NE(log.metadataValue("truth_net_buoyancy_pump0_mean_kg"), nullptr);
  // Trimmed neutral at 5 m; denser water below outweighs the compressing
  // hull: tens of grams light at depth.
  const double nb = std::stod(*log.metadataValue("truth_net_buoyancy_pump0_mean_kg"));
  EXPECT_GT(nb, 0.03);
  EXPECT_LT(nb, 0.15);
}

TEST(Glider, PlanErrorsNameTheField) {
  const std::string mixed = R"({"format": "auvballast-mission-plan", "version": 1, "vehicle": "slocum_g2",
    "water": {"density_kgm3": 1025}, "legs": [{"type": "yo", "dive_to_m": 100, "climb_to_m": 10, "duration_s": 600},
    {"type": "depth", "depth_m": 1, "prop_demand": 1, "duration_s": 10}]})";
  try {
    (void)parseMissionPlan(JsonReader::parseText(mixed, "m.json"), "m.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "legs[1].type");
  }
  const std::string upside_down = R"({"format": "auvballast-mission-plan", "version": 1, "vehicle": "slocum_g2",
    "water": {"density_kgm3": 1025}, "legs": [{"type": "yo", "dive_to_m": 10, "climb_to_m": 100, "duration_s": 600}]})";
  try {
    (void)parseMissionPlan(JsonReader::parseText(upside_down, "u.json"), "u.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "legs[0].dive_to_m");
  }
}

}  // namespace
}  // namespace auv::sim
