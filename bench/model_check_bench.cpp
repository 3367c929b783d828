// Speed of the model check (issue 5): a 3 h log at 1 Hz in under 2 s and a
// 24 h log at 10 Hz in under 20 s, for a glider (steady-glide model) and an
// AUV (rigid-body equation error plus replays through the simulator). The
// logs are the concealed-effect generators' (a hull compressibility hidden in
// the glider's, extra propeller torque in the AUV's). Timed: building the
// check model from the log and running the whole check (base fit, selection
// with bootstrap, held-out simulations, final fit, localisation). Prints
// wall-clock and process CPU time (the machine is shared).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>

#include "discrepancy/model_check.h"
#include "discrepancy/synthetic_auv.h"
#include "discrepancy/synthetic_glider.h"
#include "discrepancy/vehicle_check.h"
#include "sim/mission_plan.h"
#include "vehicle/profile_loader.h"

namespace {

using namespace auv;
using namespace auv::discrepancy;

void timeCheck(const char* label, const MissionLog& log, const VehicleProfile& v, double limit_s) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  const auto model = makeCheckModel(log, v, AUV_RESOURCE_DIR);
  const ModelCheckResult r = runModelCheck(*model);
  const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::string found;
  for (const auto& m : r.missing_physics) found += " " + m.id;
  std::printf("%-34s %8zu rows %6.2f h  wall %6.2f s  cpu %6.2f s  (limit %4.0f s: %s)  samples %zu  found:%s\n", label,
              log.rowCount(), log.duration() / 3600.0, wall, cpu, limit_s, wall < limit_s ? "ok" : "SLOW", r.samples,
              found.empty() ? " nothing" : found.c_str());
}

MissionLog gliderLog(const VehicleProfile& v, double hours, double interval_s) {
  SyntheticGliderTruth t;
  t.constants.mass_kg = v.mass_kg;
  t.constants.thermal_expansion_per_degC = v.hull.thermal_expansion_per_degC;
  t.constants.reference_temperature_degC = v.hull.reference_temperature_degC;
  t.constants.compressibility_per_dbar = 5e-6;
  SyntheticGliderMission m;
  m.max_depth_m = 200.0;
  const double yo_s = 2.0 * m.max_depth_m / 0.17 + m.surface_s;
  m.yos = static_cast<int>(std::ceil(hours * 3600.0 / yo_s));
  m.sample_interval_s = interval_s;
  m.step_s = std::min(0.5, interval_s);
  m.seed = 7;
  MissionLog log = synthesizeGliderLog(t, m);
  // Trim to the asked length.
  std::size_t n = 0;
  while (n < log.time.size() && log.time[n] <= hours * 3600.0) ++n;
  log.time.resize(n);
  for (auto& c : log.channels) c.values.resize(n);
  return log;
}

MissionLog auvLog(const sim::SimVehicle& sv, double hours, double interval_s) {
  SyntheticAuvTruth t;
  t.ballast_error.net_buoyancy_kg = 0.3;
  t.ballast_error.cg_shift_m = Eigen::Vector3d(0.002, 0.0005, 0.0);
  t.extra_prop_KQ0 = 0.004;
  SyntheticAuvMission m;
  m.legs_count = static_cast<int>(std::ceil(hours * 3600.0 / m.leg_s));
  m.trace_interval_s = interval_s;
  m.seed = 7;
  return synthesizeAuvLog(sv, "delphin2", t, m);
}

}  // namespace

int main() {
  const std::string res = AUV_RESOURCE_DIR;
  const VehicleProfile slocum = loadVehicleProfile(res + "/vehicles/slocum_g2.json");
  const VehicleProfile delphin = loadVehicleProfile(res + "/vehicles/delphin2.json");
  const sim::SimVehicle sv = sim::loadSimVehicle(delphin, res);
  std::puts("model check speed (issue 5 targets: 3 h at 1 Hz < 2 s, 24 h at 10 Hz < 20 s)");
  timeCheck("glider, 3 h at 1 Hz", gliderLog(slocum, 3.0, 1.0), slocum, 2.0);
  timeCheck("AUV (Delphin2), 3 h at 1 Hz", auvLog(sv, 3.0, 1.0), delphin, 2.0);
  timeCheck("glider, 24 h at 10 Hz", gliderLog(slocum, 24.0, 0.1), slocum, 20.0);
  timeCheck("AUV (Delphin2), 24 h at 10 Hz", auvLog(sv, 24.0, 0.1), delphin, 20.0);
  return 0;
}
