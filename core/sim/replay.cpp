#include "sim/replay.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "common/input_error.h"
#include "common/units.h"
#include "missionlog/resample.h"
#include "sim/heading_control.h"
#include "sim/step_engine.h"

namespace auv::sim {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool hasSamples(const MissionLog& log, const char* name) {
  const LogChannel* c = log.find(name);
  return c != nullptr && c->validCount() > 0;
}

// `name` on the model grid; a gap (or the stretch before the first sample)
// holds the nearest earlier (or the first) valid value. Empty if absent.
std::vector<double> onGrid(const MissionLog& log, const char* name, const std::vector<double>& grid,
                           Interpolation method) {
  if (!hasSamples(log, name)) return {};
  std::vector<double> v = resample(log.series(name), grid, {method});
  const auto valid = std::find_if(v.begin(), v.end(), [](double x) { return !std::isnan(x); });
  double last = valid == v.end() ? kNaN : *valid;
  for (double& x : v) {
    if (std::isnan(x)) {
      x = last;
    } else {
      last = x;
    }
  }
  return v;
}

double first(const std::vector<double>& v, double fallback) { return v.empty() ? fallback : v.front(); }

void require(const MissionLog& log, const char* name, const std::string& why) {
  if (!hasSamples(log, name)) {
    throw InputError(name, "the log has no " + std::string(name) + " samples, needed " + why,
                     "replay a log that records it, or choose another --drive");
  }
}

}  // namespace

std::string replayDriveName(ReplayDrive d) {
  switch (d) {
    case ReplayDrive::Auto: return "auto";
    case ReplayDrive::Actuators: return "actuators";
    case ReplayDrive::PitchCommands: return "pitch";
    case ReplayDrive::DepthCommands: return "depth";
  }
  return "auto";
}

ReplayDrive parseReplayDrive(const std::string& name) {
  for (ReplayDrive d : {ReplayDrive::Auto, ReplayDrive::Actuators, ReplayDrive::PitchCommands,
                        ReplayDrive::DepthCommands}) {
    if (name == replayDriveName(d)) return d;
  }
  throw InputError("drive", "unknown replay drive '" + name + "'", "use auto, actuators, pitch or depth");
}

ReplayDrive resolveReplayDrive(const VehicleModel& model, const MissionLog& log, ReplayDrive requested) {
  const bool thrusters = model.thruster_count > 0;
  const auto actuatorsOk = [&] {
    return hasSamples(log, "elevator") &&
           (!thrusters || (hasSamples(log, "thruster_front_rpm") && hasSamples(log, "thruster_aft_rpm")));
  };
  switch (requested) {
    case ReplayDrive::Auto:
      if (actuatorsOk()) return ReplayDrive::Actuators;
      if (hasSamples(log, "pitch_cmd")) return ReplayDrive::PitchCommands;
      if (hasSamples(log, "depth_cmd")) return ReplayDrive::DepthCommands;
      throw InputError("elevator", "the log has neither elevator, pitch_cmd nor depth_cmd samples",
                       "replay a log that records the stern plane or the autopilot's commands");
    case ReplayDrive::Actuators:
      require(log, "elevator", "to drive the stern planes");
      if (thrusters) {
        require(log, "thruster_front_rpm", "to drive the tunnel thrusters");
        require(log, "thruster_aft_rpm", "to drive the tunnel thrusters");
      }
      return requested;
    case ReplayDrive::PitchCommands:
      require(log, "pitch_cmd", "to steer the planes");
      if (thrusters) require(log, "depth_cmd", "for the tunnel thrusters' depth loop");
      return requested;
    case ReplayDrive::DepthCommands:
      require(log, "depth_cmd", "as the autopilot's set point");
      return requested;
  }
  return requested;
}

SimTrace replay(const VehicleModel& model, const DepthAutopilotConfig& apcfg, const WaterColumn& water,
                const MissionLog& log, const ReplayOptions& opt) {
  if (!(opt.dt_s > 0.0 && opt.dt_s <= 1.0)) {
    throw InputError("dt_s", "model step must be in (0, 1] s", "use 0.05 s (20 Hz) as in the paper");
  }
  if (log.rowCount() < 2) throw InputError("time", "the log has fewer than two rows", "replay a longer log");
  require(log, "prop_rpm", "to turn the propeller");
  require(log, "depth", "for the start depth");
  const ReplayDrive drive = resolveReplayDrive(model, log, opt.drive);
  const double dt = opt.dt_s;

  // Driving channels on the model grid, sized before the loop.
  const double t0 = log.time.front();
  const std::vector<double> grid = uniformGrid(t0, log.time.back(), dt);
  const long n_steps = static_cast<long>(grid.size()) - 1;
  const std::vector<double> rpm = onGrid(log, "prop_rpm", grid, Interpolation::kLinear);
  std::vector<double> elevator, th_front, th_aft, pitch_cmd, depth_cmd, heading_set;
  if (drive == ReplayDrive::Actuators) {
    elevator = onGrid(log, "elevator", grid, Interpolation::kLinear);
    if (model.thruster_count > 0) {
      th_front = onGrid(log, "thruster_front_rpm", grid, Interpolation::kLinear);
      th_aft = onGrid(log, "thruster_aft_rpm", grid, Interpolation::kLinear);
    }
  } else {
    depth_cmd = onGrid(log, "depth_cmd", grid, Interpolation::kHold);
    if (drive == ReplayDrive::PitchCommands) pitch_cmd = onGrid(log, "pitch_cmd", grid, Interpolation::kLinear);
  }
  const std::vector<double> rudder = onGrid(log, "rudder", grid, Interpolation::kLinear);
  if (rudder.empty()) {
    heading_set = onGrid(log, "heading_cmd", grid, Interpolation::kHold);
    if (heading_set.empty()) heading_set = onGrid(log, "heading", grid, Interpolation::kLinear);
  }
  // One trace sample per log row, at the nearest step.
  std::vector<char> sample_at(grid.size(), 0);
  for (double t : log.time) {
    const long k = std::clamp(std::lround((t - t0) / dt), 0L, n_steps);
    sample_at[static_cast<std::size_t>(k)] = 1;
  }

  const std::vector<double> depth0 = onGrid(log, "depth", {t0}, Interpolation::kLinear);
  const auto at0 = [&](const char* name, double fallback) {
    return first(onGrid(log, name, {t0}, Interpolation::kLinear), fallback);
  };
  InitialState init;
  init.depth_m = depth0.front();
  init.pitch_rad = units::degToRad(at0("pitch", 0.0));
  init.roll_rad = units::degToRad(at0("roll", 0.0));
  init.heading_rad = units::degToRad(at0("heading", 0.0));
  init.speed_mps = at0("speed", 0.0);
  init.prop_rps = rpm.front() / 60.0;

  StepEngine eng(model, water, dt, opt.surface_model);
  eng.start(init, opt.loading);
  const long control_every = std::max(1L, std::lround(apcfg.sample_time_s / dt));
  DepthAutopilot ap(apcfg, model);
  HeadingAutopilot hp(apcfg.heading, static_cast<double>(control_every) * dt);
  ActuatorDemand demand;
  double rudder_demand = 0.0;
  GaussianSource no_noise(0);
  const SensorNoise exact;
  const double W = eng.weightN();

  SimTrace tr;
  tr.reserve(log.rowCount());
  for (long k = 0; k <= n_steps; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (k > 0) eng.sampleWater();
    ActuatorState& act = eng.actuators();
    act.prop_rps = std::max(0.0, rpm[i] / 60.0);
    if (drive == ReplayDrive::Actuators) {
      act.plane_rad = -units::degToRad(elevator[i]);  // log sign -> paper sign
      if (model.thruster_count > 0) {
        act.thruster_rpm[0] = th_front[i];
        act.thruster_rpm[1] = th_aft[i];
      }
    }
    if (!rudder.empty()) eng.yaw().rudder_rad = units::degToRad(rudder[i]);

    const Measurement meas = eng.measure(no_noise, exact);
    const bool control_now = k % control_every == 0;
    // Without a logged heading the heading hold keeps the start heading.
    const double heading_cmd = !apcfg.heading.enabled ? kNaN
                               : heading_set.empty()  ? init.heading_rad
                                                      : units::degToRad(heading_set[i]);
    if (control_now && drive != ReplayDrive::Actuators) {
      Setpoint sp{depth_cmd[i], 0.0, 0.0};
      if (drive == ReplayDrive::PitchCommands) {
        sp.pitch_rad = units::degToRad(pitch_cmd[i]);
        sp.pitch_is_demand = true;
      }
      demand = ap.update(meas, sp, eng.water().density_kgm3);
    }
    if (control_now && rudder.empty()) rudder_demand = hp.update(heading_cmd, eng.yaw().heading_rad, eng.yaw().r_radps);
    if (sample_at[i]) {
      const SampleExtras x{depth_cmd.empty() ? kNaN : depth_cmd[i],
                           drive == ReplayDrive::Actuators ? kNaN : ap.outputs().pitch_cmd_rad, heading_cmd,
                           ap.outputs().hover_force_n};
      eng.record(tr, grid[i], meas, x, W, no_noise, exact);
    }
    if (k == n_steps) break;
    if (drive == ReplayDrive::Actuators) {
      eng.stepHeld(W);
      if (rudder.empty()) advanceRudder(model, rudder_demand, dt, eng.yaw());
    } else {
      eng.step(W, demand, rudder.empty() ? rudder_demand : eng.yaw().rudder_rad);
    }
  }
  eng.finish(tr);
  return tr;
}

}  // namespace auv::sim
