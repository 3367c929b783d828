#include "discrepancy/synthetic_auv.h"

#include <cmath>

#include "common/units.h"
#include "sim/sim_log.h"

namespace auv::discrepancy {

void applyTruthEffects(sim::VehicleModel& model, const SyntheticAuvTruth& truth) {
  model.body.hull.compressibility_per_dbar += truth.extra_compressibility_per_dbar;
  model.body.hull.thermal_expansion_per_degC += truth.extra_thermal_expansion_per_degC;
  const double kq = model.prop.torque_sign * model.prop.KQ0 + truth.extra_prop_KQ0;
  model.prop.torque_sign = kq < 0 ? -1.0 : 1.0;
  model.prop.KQ0 = std::abs(kq);
  model.hydro.Mqq_kgm2 *= 1.0 + truth.pitch_damping_scale;
}

void applyTruthEffects(sim::Scenario& sc, const SyntheticAuvTruth& truth, double duration_s) {
  // A biased sensor: the autopilot holds the biased reading at the command,
  // i.e. the true state at command - bias.
  for (sim::DepthLeg& L : sc.legs) {
    L.depth_m -= truth.depth_offset_m;
    L.pitch_rad -= units::degToRad(truth.pitch_bias_deg);
  }
  if (truth.mass_drift_kg_per_h != 0.0) {
    const double step = 10.0;
    for (double t = step; t < duration_s; t += step)
      sc.buoyancy_changes.push_back({t, -units::g0 * truth.mass_drift_kg_per_h * step / 3600.0});
  }
}

void recordSensorBiases(MissionLog& log, const SyntheticAuvTruth& truth) {
  auto shift = [&](const char* name, double d) {
    if (LogChannel* c = log.find(name))
      for (double& x : c->values) x += d;
  };
  shift("depth", truth.depth_offset_m);
  shift("depth_cmd", truth.depth_offset_m);
  shift("pitch", truth.pitch_bias_deg);
  shift("pitch_cmd", truth.pitch_bias_deg);
  shift("roll", truth.roll_bias_deg);
}

MissionLog synthesizeAuvLog(const sim::SimVehicle& vehicle, const std::string& id, const SyntheticAuvTruth& truth,
                            const SyntheticAuvMission& m) {
  sim::VehicleModel model = vehicle.model;
  applyTruthEffects(model, truth);

  sim::Scenario sc;
  if (!m.legs.empty()) {
    sc.legs = m.legs;
  } else {
    for (int i = 0; i < m.legs_count; ++i) {
      sim::DepthLeg L;
      L.duration_s = m.leg_s;
      L.depth_m = m.depths_m[static_cast<std::size_t>(i) % m.depths_m.size()];
      L.prop_demand = m.prop_demands[static_cast<std::size_t>(i) % m.prop_demands.size()];
      sc.legs.push_back(L);
    }
  }
  sc.ballast_error = truth.ballast_error;
  sc.initial_depth_m = sc.legs.front().depth_m - truth.depth_offset_m;
  sc.initial_speed_mps = 0.8;
  applyTruthEffects(sc, truth, sim::scenarioDuration(sc));
  sim::SimOptions o;
  o.trace_interval_s = m.trace_interval_s;
  o.seed = m.seed;
  o.surface_model = m.surface_model;
  o.noise = m.noise;
  if (m.default_noise) {
    o.noise.depth_m = 0.01;
    o.noise.pitch_rad = units::degToRad(0.05);
    o.noise.roll_rad = units::degToRad(0.05);
    o.noise.speed_mps = 0.01;
    o.noise.temperature_degC = 0.002;
    o.noise.salinity_psu = 0.003;
    o.noise.pressure_dbar = 0.01;
  }
  double maxDepth = 0.0;
  for (const auto& L : sc.legs) maxDepth = std::max(maxDepth, L.depth_m);
  const sim::WaterColumn water = sim::WaterColumn::fromCast(m.cast, maxDepth + 50.0);
  const sim::SimTrace tr = sim::simulate(model, vehicle.autopilot, water, sc, o);

  sim::SimLogInfo info;
  info.vehicle = id;
  info.seed = m.seed;
  info.input = "model-check synthetic mission";
  info.thruster_count = model.thruster_count;
  auto f = [](double x) { return sim::formatNumber(x); };
  info.extra = {{"truth_extra_compressibility_per_dbar", f(truth.extra_compressibility_per_dbar)},
                {"truth_extra_thermal_expansion_per_degC", f(truth.extra_thermal_expansion_per_degC)},
                {"truth_extra_prop_KQ0", f(truth.extra_prop_KQ0)},
                {"truth_pitch_damping_scale", f(truth.pitch_damping_scale)},
                {"truth_mass_drift_kg_per_h", f(truth.mass_drift_kg_per_h)},
                {"truth_pitch_sensor_bias_deg", f(truth.pitch_bias_deg)},
                {"truth_roll_sensor_bias_deg", f(truth.roll_bias_deg)},
                {"truth_depth_sensor_offset_m", f(truth.depth_offset_m)}};
  MissionLog log = sim::toMissionLog(tr, info);
  recordSensorBiases(log, truth);
  return log;
}

}  // namespace auv::discrepancy
