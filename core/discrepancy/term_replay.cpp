#include "discrepancy/term_replay.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/input_error.h"
#include "common/units.h"
#include "missionlog/resample.h"
#include "sim/replay_start.h"
#include "sim/step_engine.h"

namespace auv::discrepancy {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRhoRef = 1025.0;

// `name` on the grid; before the first and across gaps the nearest earlier
// (or the first) value holds, as in sim::replay.
std::vector<double> onGrid(const MissionLog& log, const char* name, const std::vector<double>& grid, Interpolation m) {
  const LogChannel* c = log.find(name);
  if (c == nullptr || c->validCount() == 0) return {};
  std::vector<double> v = resample(log.series(name), grid, {m});
  const auto valid = std::find_if(v.begin(), v.end(), [](double x) { return !std::isnan(x); });
  double last = valid == v.end() ? kNaN : *valid;
  for (double& x : v) {
    if (std::isnan(x)) x = last;
    else last = x;
  }
  return v;
}

}  // namespace

double propKQ0ForTorque(const sim::Propeller& p, double k) {
  const double D = p.diameter_m;
  return k * 3600.0 / (kRhoRef * D * D * D * D * D);
}

sim::VehicleModel adjustedModel(const sim::VehicleModel& model, const SimAdjustment& a) {
  sim::VehicleModel m = model;
  m.body.hull.compressibility_per_dbar += a.compressibility_per_dbar;
  m.body.hull.thermal_expansion_per_degC += a.thermal_expansion_per_degC;
  if (a.prop_torque_nm_per_rpm2 != 0.0 && m.prop.diameter_m > 0.0) {
    const double signedKQ = m.prop.torque_sign * m.prop.KQ0 + propKQ0ForTorque(m.prop, a.prop_torque_nm_per_rpm2);
    m.prop.torque_sign = signedKQ < 0.0 ? -1.0 : 1.0;
    m.prop.KQ0 = std::abs(signedKQ);
  }
  m.hydro.Mqq_kgm2 *= 1.0 + a.pitch_damping_scale;
  return m;
}

namespace {

TermReplayTrace replayOneSpan(const sim::VehicleModel& base, const sim::DepthAutopilotConfig& apcfg,
                              const sim::WaterColumn& water, const MissionLog& log, const SimAdjustment& a,
                              std::span<const double> times, const TermReplayOptions& opt, bool restart,
                              std::uint64_t span_index) {
  const sim::VehicleModel model = adjustedModel(base, a);
  const sim::ReplayDrive drive = sim::resolveReplayDrive(model, log, opt.drive);
  const double dt = opt.dt_s;
  const double t0 = log.time.front();
  const std::vector<double> grid = uniformGrid(t0, log.time.back(), dt);
  const long n_steps = static_cast<long>(grid.size()) - 1;
  const std::vector<double> rpm = onGrid(log, "prop_rpm", grid, Interpolation::kLinear);
  if (rpm.empty()) throw InputError("prop_rpm", "the log has no prop_rpm samples", "an AUV replay needs the propeller speed");
  std::vector<double> elevator, th_front, th_aft, pitch_cmd, depth_cmd;
  if (drive == sim::ReplayDrive::Actuators) {
    elevator = onGrid(log, "elevator", grid, Interpolation::kLinear);
    if (model.thruster_count > 0) {
      th_front = onGrid(log, "thruster_front_rpm", grid, Interpolation::kLinear);
      th_aft = onGrid(log, "thruster_aft_rpm", grid, Interpolation::kLinear);
    }
  } else {
    depth_cmd = onGrid(log, "depth_cmd", grid, Interpolation::kHold);
    if (drive == sim::ReplayDrive::PitchCommands) pitch_cmd = onGrid(log, "pitch_cmd", grid, Interpolation::kLinear);
  }
  // Output step of each requested time.
  std::vector<long> stepOf(times.size());
  for (std::size_t i = 0; i < times.size(); ++i) stepOf[i] = std::clamp(std::lround((times[i] - t0) / dt), 0L, n_steps);

  sim::InitialState init = sim::replayStartState(log, t0, model, restart);
  init.depth_m -= a.depth_offset_m;
  init.pitch_rad -= a.pitch_bias_rad;
  init.roll_rad -= a.roll_bias_rad;
  // The log's depth rate is over ground; the vehicle moves through the water.
  if (init.depth_rate_mps) *init.depth_rate_mps += a.vertical_current_mps;

  sim::StepEngine eng(model, water, dt, opt.surface_model);
  eng.start(init, opt.loading);
  const long control_every = std::max(1L, std::lround(apcfg.sample_time_s / dt));
  sim::DepthAutopilot ap(apcfg, model);
  const double W0 = eng.weightN();
  const double dW_per_s = units::g0 * a.mass_drift_kg_per_h / 3600.0;
  if (opt.preload_hover_integrator) ap.preloadHoverIntegrator(eng.buoyancyN() - (W0 + dW_per_s * (t0 - opt.mass_reference_time_s)));
  sim::ActuatorDemand demand;
  sim::GaussianSource noise(opt.noise_seed * 0x9E3779B97F4A7C15ULL + span_index);

  TermReplayTrace tr;
  for (auto* v : {&tr.depth_m, &tr.pitch_rad, &tr.roll_rad, &tr.speed_mps, &tr.vertical_velocity_mps, &tr.elevator_deg,
                  &tr.pressure_dbar, &tr.thruster_front_rpm, &tr.thruster_aft_rpm, &tr.pitch_cmd_deg})
    v->assign(times.size(), kNaN);
  tr.since_start_s.resize(times.size());
  for (std::size_t i = 0; i < times.size(); ++i) tr.since_start_s[i] = times[i] - t0;
  std::size_t next = 0;
  for (long k = 0; k <= n_steps; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (k > 0) eng.sampleWater();
    const double W = W0 + dW_per_s * (grid[i] - opt.mass_reference_time_s);
    sim::ActuatorState& act = eng.actuators();
    act.prop_rps = std::max(0.0, rpm[i] / 60.0);
    if (drive == sim::ReplayDrive::Actuators) {
      act.plane_rad = -units::degToRad(elevator[i]);
      if (model.thruster_count > 0) {
        act.thruster_rpm[0] = th_front[i];
        act.thruster_rpm[1] = th_aft[i];
      }
    }
    // What the sensors say: the autopilot steers on them, the log records them.
    sim::Measurement meas = eng.measure(noise, opt.noise);
    meas.depth_m += a.depth_offset_m;
    meas.pitch_rad += a.pitch_bias_rad;
    meas.depth_rate_mps -= a.vertical_current_mps;
    if (k % control_every == 0 && drive != sim::ReplayDrive::Actuators) {
      sim::Setpoint sp{depth_cmd[i], 0.0, 0.0};
      if (drive == sim::ReplayDrive::PitchCommands) {
        sp.pitch_rad = units::degToRad(pitch_cmd[i]);
        sp.pitch_is_demand = true;
      }
      demand = ap.update(meas, sp, eng.water().density_kgm3);
    }
    while (next < times.size() && stepOf[next] == k) {
      tr.depth_m[next] = meas.depth_m;
      tr.pitch_rad[next] = meas.pitch_rad;
      tr.roll_rad[next] = eng.state()[sim::kPhi] + a.roll_bias_rad + noise.next(opt.noise.roll_rad);
      tr.speed_mps[next] = meas.speed_mps;
      tr.vertical_velocity_mps[next] = -meas.depth_rate_mps;
      tr.elevator_deg[next] = -units::radToDeg(eng.actuators().plane_rad);  // paper sign -> log sign
      tr.pressure_dbar[next] = eng.water().pressure_dbar + noise.next(opt.noise.pressure_dbar);
      tr.thruster_front_rpm[next] = eng.actuators().thruster_rpm[0];
      tr.thruster_aft_rpm[next] = eng.actuators().thruster_rpm[1];
      if (drive == sim::ReplayDrive::DepthCommands) tr.pitch_cmd_deg[next] = units::radToDeg(ap.outputs().pitch_cmd_rad);
      ++next;
    }
    if (k == n_steps) break;
    if (drive == sim::ReplayDrive::Actuators) {
      eng.stepHeld(W);
    } else {
      eng.step(W, demand, 0.0);
    }
    eng.state()[sim::kZ] -= a.vertical_current_mps * dt;
  }
  return tr;
}

// Rows [r0, r1) of `log`, every channel.
MissionLog sliceRows(const MissionLog& log, std::size_t r0, std::size_t r1) {
  MissionLog out;
  out.metadata = log.metadata;
  out.time.assign(log.time.begin() + static_cast<long>(r0), log.time.begin() + static_cast<long>(r1));
  for (const LogChannel& c : log.channels) {
    LogChannel k;
    k.name = c.name;
    k.unit = c.unit;
    k.source_unit = c.source_unit;
    k.values.assign(c.values.begin() + static_cast<long>(r0), c.values.begin() + static_cast<long>(r1));
    out.channels.push_back(std::move(k));
  }
  return out;
}

// Rows of a surface interval (options.surface_depth_m): shallower than the
// limit for at least `min_s`.
std::vector<bool> surfaceRows(const MissionLog& log, double limit_m, double min_s) {
  std::vector<bool> out(log.rowCount(), false);
  const LogChannel* depth = log.find("depth");
  if (depth == nullptr || !std::isfinite(limit_m)) return out;
  const std::vector<double>& z = depth->values;
  for (std::size_t r0 = 0; r0 < z.size();) {
    if (!(z[r0] < limit_m)) {
      ++r0;
      continue;
    }
    std::size_t r1 = r0;
    while (r1 < z.size() && z[r1] < limit_m) ++r1;
    if (log.time[r1 - 1] - log.time[r0] >= min_s) std::fill(out.begin() + static_cast<long>(r0), out.begin() + static_cast<long>(r1), true);
    r0 = r1;
  }
  return out;
}

}  // namespace

// A logger drop-out longer than 20 row spacings (at least 30 s) ends a span
// (and, with restart_every_s, so does that much flight) and the replay
// restarts from the first row after it, as sim::replay does:
// steps, memory and time follow the rows, not a gap of days. A surface
// interval as long ends a span the same way. Requested times inside a gap
// or at the surface stay NaN.
TermReplayTrace termReplay(const sim::VehicleModel& base, const sim::DepthAutopilotConfig& apcfg,
                           const sim::WaterColumn& water, const MissionLog& log, const SimAdjustment& a,
                           std::span<const double> times, const TermReplayOptions& opt) {
  if (log.rowCount() < 2) throw InputError("time", "the log has fewer than two rows", "replay a longer log");
  const std::vector<double>& T = log.time;
  std::vector<double> d;
  for (std::size_t i = 1; i < T.size(); ++i) d.push_back(T[i] - T[i - 1]);
  std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
  const double gap_s = std::max(30.0, 20.0 * d[d.size() / 2]);
  const std::vector<bool> surfaced = surfaceRows(log, opt.surface_depth_m, gap_s);
  std::vector<std::pair<std::size_t, std::size_t>> spans;
  for (std::size_t r0 = 0; r0 < T.size();) {
    if (surfaced[r0]) {
      ++r0;
      continue;
    }
    std::size_t r1 = r0 + 1;
    const auto horizonEnds = [&](std::size_t r) { return opt.restart_every_s > 0.0 && T[r] - T[r0] >= opt.restart_every_s; };
    while (r1 < T.size() && T[r1] - T[r1 - 1] <= gap_s && !horizonEnds(r1) && !surfaced[r1]) ++r1;
    spans.push_back({r0, r1});
    r0 = r1;
  }
  if (spans.size() == 1 && spans.front().first == 0 && spans.front().second == T.size()) return replayOneSpan(base, apcfg, water, log, a, times, opt, false, 0);

  TermReplayTrace tr;
  for (auto* v : {&tr.depth_m, &tr.pitch_rad, &tr.roll_rad, &tr.speed_mps, &tr.vertical_velocity_mps, &tr.elevator_deg,
                  &tr.pressure_dbar, &tr.thruster_front_rpm, &tr.thruster_aft_rpm, &tr.pitch_cmd_deg, &tr.since_start_s})
    v->assign(times.size(), kNaN);
  std::uint64_t span_index = 0;
  for (const auto& [r0, r1] : spans) {
    if (r1 - r0 < 2) continue;  // a lone row between gaps: nothing to fly
    std::vector<double> sub;
    std::vector<std::size_t> at;
    for (std::size_t i = 0; i < times.size(); ++i) {
      if (times[i] >= T[r0] && times[i] <= T[r1 - 1]) {
        sub.push_back(times[i]);
        at.push_back(i);
      }
    }
    if (sub.empty()) continue;
    const TermReplayTrace part = replayOneSpan(base, apcfg, water, sliceRows(log, r0, r1), a, sub, opt, r0 > 0, ++span_index);
    for (std::size_t j = 0; j < at.size(); ++j) {
      tr.depth_m[at[j]] = part.depth_m[j];
      tr.pitch_rad[at[j]] = part.pitch_rad[j];
      tr.roll_rad[at[j]] = part.roll_rad[j];
      tr.speed_mps[at[j]] = part.speed_mps[j];
      tr.vertical_velocity_mps[at[j]] = part.vertical_velocity_mps[j];
      tr.elevator_deg[at[j]] = part.elevator_deg[j];
      tr.pressure_dbar[at[j]] = part.pressure_dbar[j];
      tr.thruster_front_rpm[at[j]] = part.thruster_front_rpm[j];
      tr.thruster_aft_rpm[at[j]] = part.thruster_aft_rpm[j];
      tr.pitch_cmd_deg[at[j]] = part.pitch_cmd_deg[j];
      tr.since_start_s[at[j]] = part.since_start_s[j];
    }
  }
  return tr;
}

}  // namespace auv::discrepancy
