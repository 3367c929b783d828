#include "sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/input_error.h"
#include "common/units.h"
#include "sim/actuator_forces.h"
#include "sim/actuator_state.h"
#include "sim/dynamics.h"
#include "sim/power_model.h"

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

struct FlownMass {
  double mass_kg = 0.0;
  Eigen::Vector3d r_g_m = Eigen::Vector3d::Zero();
  double extra_Ixx = 0.0, extra_Iyy = 0.0;
};

FlownMass flownMass(const VehicleModel& model, const Scenario& sc) {
  FlownMass f;
  Eigen::Vector3d moment = model.body.mass_kg * model.body.r_g_m;
  f.mass_kg = model.body.mass_kg;
  for (const MassItem& item : sc.extra_masses) {
    const Eigen::Vector3d r = item.position_m - model.body.cb_profile_m;
    f.mass_kg += item.mass_kg;
    moment += item.mass_kg * r;
    f.extra_Ixx += item.mass_kg * (r.y() * r.y() + r.z() * r.z());
    f.extra_Iyy += item.mass_kg * (r.x() * r.x() + r.z() * r.z());
  }
  if (!(f.mass_kg > 0.0)) {
    throw InputError("extra_masses", "the vehicle mass would not be positive", "check the ballast changes");
  }
  f.r_g_m = moment / f.mass_kg;
  return f;
}

double buoyancyN(const VehicleModel& model, const WaterSample& ws, double z, bool surface) {
  const double V = model.body.hull.volumeAt(ws.temperature_degC, ws.pressure_dbar);
  const double frac = surface ? submergedFraction(z, model.body.hull.diameter_m) : 1.0;
  return ws.density_kgm3 * units::g0 * V * frac;
}

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
  FlownMass fm = flownMass(model, sc);
  StateVector s = StateVector::Zero();
  s[kZ] = sc.initial_depth_m;
  s[kTheta] = sc.initial_pitch_rad;
  s[kPhi] = sc.initial_roll_rad;
  s[kU] = sc.initial_speed_mps;
  if (sc.net_buoyancy_n) {
    const WaterSample ws = water.at(std::max(0.0, s[kZ]));
    const double B = buoyancyN(model, ws, s[kZ], opt.surface_model);
    fm.mass_kg = (B - *sc.net_buoyancy_n) / units::g0;  // trim mass at the CG
  }
  Dynamics dyn(model);
  dyn.setMassProperties(fm.mass_kg, fm.r_g_m, fm.extra_Ixx, fm.extra_Iyy);
  DepthAutopilot ap(apcfg, model);
  const ActuatorDynamics act_dyn(model, dt);
  ActuatorState act;
  // A vehicle that starts under way starts with its propeller turning.
  if (sc.initial_speed_mps > 0.0) act.prop_rps = propellerRpsFromDemand(model.prop, sc.legs.front().prop_demand);
  ActuatorDemand demand;
  GaussianSource noise(opt.seed);

  std::vector<BuoyancyChange> changes = sc.buoyancy_changes;
  std::sort(changes.begin(), changes.end(), [](const auto& a, const auto& b) { return a.time_s < b.time_s; });
  std::vector<double> leg_end(sc.legs.size());
  double acc = 0.0;
  for (std::size_t i = 0; i < sc.legs.size(); ++i) leg_end[i] = (acc += sc.legs[i].duration_s);

  SimTrace tr;
  tr.reserve(static_cast<std::size_t>(n_steps / trace_every + 2));

  const double weight0 = fm.mass_kg * units::g0;
  if (opt.preload_hover_integrator) {
    const WaterSample ws = water.at(std::max(0.0, s[kZ]));
    ap.preloadHoverIntegrator(buoyancyN(model, ws, s[kZ], opt.surface_model) - weight0);
  }

  double delta_b = 0.0;
  std::size_t next_change = 0, leg = 0;
  for (long k = 0; k <= n_steps; ++k) {
    const double t = static_cast<double>(k) * dt;
    while (next_change < changes.size() && changes[next_change].time_s <= t + 1e-9) {
      delta_b += changes[next_change++].delta_n;
    }
    while (leg + 1 < sc.legs.size() && t >= leg_end[leg] - 1e-9) ++leg;
    const DepthLeg& L = sc.legs[leg];

    const WaterSample ws = water.at(std::max(0.0, s[kZ]));
    const double B = buoyancyN(model, ws, s[kZ], opt.surface_model);
    const double W = weight0 - delta_b;
    const bool control_now = k % control_every == 0;
    const bool trace_now = k % trace_every == 0 || k == n_steps;

    Measurement meas;
    if (control_now || trace_now) {
      const double sth = std::sin(s[kTheta]), cth = std::cos(s[kTheta]), cph = std::cos(s[kPhi]);
      meas.depth_m = s[kZ] + noise.next(opt.noise.depth_m);
      meas.depth_rate_mps = -s[kU] * sth + s[kW] * cth * cph + noise.next(opt.noise.depth_rate_mps);
      meas.pitch_rad = s[kTheta] + noise.next(opt.noise.pitch_rad);
      meas.pitch_rate_radps = s[kQ] * cph + noise.next(opt.noise.pitch_rate_radps);
      meas.speed_mps = s[kU] + noise.next(opt.noise.speed_mps);
    }
    if (control_now) demand = ap.update(meas, {L.depth_m, L.pitch_rad, L.prop_demand}, ws.density_kgm3);

    const PowerBreakdown P = electricalPower(model, act, s[kU]);
    if (trace_now) {
      tr.time_s.push_back(t);
      tr.depth_m.push_back(meas.depth_m);
      tr.depth_cmd_m.push_back(L.depth_m);
      tr.pitch_rad.push_back(meas.pitch_rad);
      tr.pitch_cmd_rad.push_back(ap.outputs().pitch_cmd_rad);
      tr.roll_rad.push_back(s[kPhi] + noise.next(opt.noise.roll_rad));
      tr.speed_mps.push_back(meas.speed_mps);
      tr.x_m.push_back(s[kX]);
      tr.prop_rpm.push_back(act.prop_rps * 60.0);
      tr.elevator_rad.push_back(-act.plane_rad);
      tr.thruster_front_rpm.push_back(act.thruster_rpm[0]);
      tr.thruster_aft_rpm.push_back(act.thruster_rpm[1]);
      tr.power_w.push_back(P.total_w);
      tr.power_prop_w.push_back(P.prop_w);
      tr.power_thruster_front_w.push_back(P.thruster_w[0]);
      tr.power_thruster_aft_w.push_back(P.thruster_w[1]);
      tr.power_fins_w.push_back(P.fins_w);
      tr.net_buoyancy_n.push_back(B - W);
      tr.hover_force_n.push_back(ap.outputs().hover_force_n);
      tr.temperature_degC.push_back(ws.temperature_degC);
      tr.salinity_psu.push_back(ws.salinity_psu);
      tr.pressure_dbar.push_back(ws.pressure_dbar);
    }
    if (k == n_steps) break;

    tr.energy_j += P.total_w * dt;
    tr.hotel_energy_j += P.hotel_w * dt;
    tr.prop_energy_j += P.prop_w * dt;
    tr.thruster_energy_j += (P.thruster_w[0] + P.thruster_w[1]) * dt;
    tr.fins_energy_j += P.fins_w * dt;

    StepInputs in;
    in.water_density_kgm3 = ws.density_kgm3;
    in.weight_n = W;
    in.buoyancy_n = B;
    in.actuators = act;
    dyn.setStepInputs(in);
    dyn.rk4Step(s, dt);
    act_dyn.advance(act, demand);
  }
  return tr;
}

}  // namespace auv::sim
