#include "sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/input_error.h"
#include "common/units.h"
#include "sim/actuator_forces.h"
#include "sim/actuator_state.h"
#include "sim/dynamics.h"
#include "sim/heading_control.h"
#include "sim/power_model.h"
#include "sim/step_engine.h"

namespace auv::sim {

double scenarioDuration(const Scenario& sc) {
  double t = 0.0;
  for (const auto& leg : sc.legs) t += leg.duration_s;
  return t;
}

double submergedFraction(double z, double d) {
  const double r = 0.5 * d;
  const double h = std::clamp(z + r, 0.0, d);  // submerged height of the section
  const double alpha = 2.0 * std::acos(std::clamp((r - h) / r, -1.0, 1.0));
  return (alpha - std::sin(alpha)) / (2.0 * std::numbers::pi);
}

namespace {

void validate(const Scenario& sc, const SimOptions& opt) {
  if (!(opt.dt_s > 0.0 && opt.dt_s <= 1.0)) {
    throw InputError("dt_s", "model step must be in (0, 1] s", "use 0.05 s (20 Hz) as in the paper");
  }
  if (sc.legs.empty()) throw InputError("legs", "the scenario has no legs", "add at least one depth leg");
  for (std::size_t i = 0; i < sc.legs.size(); ++i) {
    if (!(sc.legs[i].duration_s > 0.0)) {
      throw InputError("legs[" + std::to_string(i) + "].duration_s", "must be positive", "give the leg a duration");
    }
  }
}

// The depth command at time t inside leg i (which ends at leg_end_s): the
// leg's depth, or on a ramp leg the straight line from the depth before it.
double legDepthCommand(const Scenario& sc, std::size_t i, double leg_end_s, double t) {
  const DepthLeg& L = sc.legs[i];
  if (!L.ramp) return L.depth_m;
  const double from = i == 0 ? sc.initial_depth_m : sc.legs[i - 1].depth_m;
  const double f = std::clamp(1.0 - (leg_end_s - t) / L.duration_s, 0.0, 1.0);
  return from + f * (L.depth_m - from);
}

}  // namespace

SimTrace simulate(const VehicleModel& model, const DepthAutopilotConfig& apcfg, const WaterColumn& water,
                  const Scenario& sc, const SimOptions& opt) {
  validate(sc, opt);
  const double dt = opt.dt_s;
  const long control_every = std::max(1L, std::lround(apcfg.sample_time_s / dt));
  const long trace_every = std::max(1L, std::lround(opt.trace_interval_s / dt));
  const long n_steps = std::lround(scenarioDuration(sc) / dt);

  // Everything below is sized here; the step loop only reads and appends
  // into reserved storage.
  StepEngine eng(model, water, dt, opt.surface_model);
  InitialState init;
  init.depth_m = sc.initial_depth_m;
  init.pitch_rad = sc.initial_pitch_rad;
  init.roll_rad = sc.initial_roll_rad;
  init.heading_rad = sc.initial_heading_rad;
  init.speed_mps = sc.initial_speed_mps;
  // A vehicle that starts under way starts with its propeller turning.
  if (sc.initial_speed_mps > 0.0) init.prop_rps = propellerRpsFromDemand(model.prop, sc.legs.front().prop_demand);
  eng.start(init, sc.loading());

  DepthAutopilot ap(apcfg, model);
  HeadingAutopilot hp(apcfg.heading, static_cast<double>(control_every) * dt);
  ActuatorDemand demand;
  double rudder_demand = 0.0;
  GaussianSource noise(opt.seed);

  std::vector<BuoyancyChange> changes = sc.buoyancy_changes;
  std::sort(changes.begin(), changes.end(), [](const auto& a, const auto& b) { return a.time_s < b.time_s; });
  std::vector<double> leg_end(sc.legs.size()), leg_heading(sc.legs.size());
  double acc = 0.0, heading = sc.initial_heading_rad;
  for (std::size_t i = 0; i < sc.legs.size(); ++i) {
    leg_end[i] = (acc += sc.legs[i].duration_s);
    if (!std::isnan(sc.legs[i].heading_rad)) heading = sc.legs[i].heading_rad;
    leg_heading[i] = heading;
  }

  SimTrace tr;
  tr.reserve(static_cast<std::size_t>(n_steps / trace_every + 2));

  const double weight0 = eng.weightN();
  if (opt.preload_hover_integrator) ap.preloadHoverIntegrator(eng.buoyancyN() - weight0);

  double delta_b = 0.0;
  std::size_t next_change = 0, leg = 0;
  for (long k = 0; k <= n_steps; ++k) {
    const double t = static_cast<double>(k) * dt;
    while (next_change < changes.size() && changes[next_change].time_s <= t + 1e-9) {
      delta_b += changes[next_change++].delta_n;
    }
    while (leg + 1 < sc.legs.size() && t >= leg_end[leg] - 1e-9) ++leg;
    const DepthLeg& L = sc.legs[leg];
    const double depth_cmd_m = legDepthCommand(sc, leg, leg_end[leg], t);

    if (k > 0) eng.sampleWater();
    const double W = weight0 - delta_b;
    const bool control_now = k % control_every == 0;
    const bool trace_now = k % trace_every == 0 || k == n_steps;

    Measurement meas;
    if (control_now || trace_now) meas = eng.measure(noise, opt.noise);
    if (control_now) {
      demand = ap.update(meas, {depth_cmd_m, L.pitch_rad, L.prop_demand}, eng.water().density_kgm3);
      rudder_demand = hp.update(leg_heading[leg], eng.headingMeasured(noise, opt.noise), eng.yaw().r_radps);
    }
    if (trace_now) {
      const SampleExtras x{depth_cmd_m, ap.outputs().pitch_cmd_rad,
                           apcfg.heading.enabled ? leg_heading[leg] : std::numeric_limits<double>::quiet_NaN(),
                           ap.outputs().hover_force_n};
      eng.record(tr, t, meas, x, W, noise, opt.noise);
    }
    if (k == n_steps) break;
    eng.step(W, demand, rudder_demand);
  }
  eng.finish(tr);
  return tr;
}

}  // namespace auv::sim
