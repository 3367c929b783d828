#include "sim/replay.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "common/input_error.h"
#include "common/units.h"
#include "missionlog/resample.h"
#include "sim/heading_control.h"
#include "sim/replay_start.h"
#include "sim/step_engine.h"

namespace auv::sim {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool hasSamples(const MissionLog& log, const char* name) {
  const LogChannel* c = log.find(name);
  return c != nullptr && c->validCount() > 0;
}

// A driving channel brought onto the model grid one chunk of steps at a time,
// so memory follows the chunk, not the time span. A hole (or the stretch
// before the first sample) holds the nearest earlier (or the first) valid value.
class GridChannel {
 public:
  GridChannel() = default;
  GridChannel(const MissionLog& log, const char* name, Interpolation method) : method_(method) {
    if (hasSamples(log, name)) series_ = log.series(name);
  }
  bool empty() const { return series_.empty(); }
  void restart() { last_ = kNaN; }
  void fill(const std::vector<double>& grid) {
    if (empty()) return;
    values_ = resample(series_, grid, {method_});
    if (std::isnan(last_)) {
      const auto valid = std::find_if(values_.begin(), values_.end(), [](double x) { return !std::isnan(x); });
      if (valid != values_.end()) last_ = *valid;
    }
    for (double& x : values_) {
      if (std::isnan(x)) {
        x = last_;
      } else {
        last_ = x;
      }
    }
  }
  double operator[](std::size_t i) const { return values_[i]; }

 private:
  Interpolation method_ = Interpolation::kLinear;
  TimeSeries series_;
  std::vector<double> values_;
  double last_ = kNaN;
};

// Rows further apart than this split the replay into spans; the model
// restarts from the first row after the gap. 20 typical row spacings, at
// least 30 s: longer than any autopilot transient worth following through a
// drop-out, and it bounds the steps flown (and the time taken) by the rows.
double restartGap_s(const std::vector<double>& t) {
  std::vector<double> d;
  d.reserve(t.size());
  for (std::size_t i = 1; i < t.size(); ++i) d.push_back(t[i] - t[i - 1]);
  if (d.empty()) return 30.0;
  std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
  return std::max(30.0, 20.0 * d[d.size() / 2]);
}

constexpr long kChunkSteps = 4096;  // model steps whose driving values are held at once


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

namespace {

struct Drivers {
  GridChannel rpm, elevator, th_front, th_aft, pitch_cmd, depth_cmd, heading_set, rudder;
};

struct SpanContext {
  const VehicleModel& model;
  const DepthAutopilotConfig& apcfg;
  const WaterColumn& water;
  const MissionLog& log;
  const ReplayOptions& opt;
  ReplayDrive drive;
};

// Flies rows [row0, row1) (no gap between them) from the state of row0 and
// appends one sample per row; returns the engine's totals through `totals`.
void replaySpan(const SpanContext& c, Drivers& d, std::size_t row0, std::size_t row1, SimTrace& tr, SimTrace& totals) {
  const MissionLog& log = c.log;
  const double dt = c.opt.dt_s;
  const double t0 = log.time[row0];
  const long n_steps = static_cast<long>(std::floor((log.time[row1 - 1] - t0) / dt + 1e-9));
  for (GridChannel* g : {&d.rpm, &d.elevator, &d.th_front, &d.th_aft, &d.pitch_cmd, &d.depth_cmd, &d.heading_set,
                         &d.rudder})
    g->restart();

  const InitialState init = replayStartState(log, t0, c.model, row0 > 0);

  StepEngine eng(c.model, c.water, dt, c.opt.surface_model);
  eng.start(init, c.opt.loading);
  const long control_every = std::max(1L, std::lround(c.apcfg.sample_time_s / dt));
  DepthAutopilot ap(c.apcfg, c.model);
  HeadingAutopilot hp(c.apcfg.heading, static_cast<double>(control_every) * dt);
  ActuatorDemand demand;
  double rudder_demand = 0.0;
  GaussianSource no_noise(0);
  const SensorNoise exact;
  const double W = eng.weightN();
  const bool actuators = c.drive == ReplayDrive::Actuators;

  std::size_t row = row0;  // next row to sample, at the step nearest to its time
  const auto stepOf = [&](std::size_t r) {
    return std::clamp(std::lround((log.time[r] - t0) / dt), 0L, n_steps);
  };
  std::vector<double> grid;
  for (long c0 = 0; c0 <= n_steps; c0 += kChunkSteps) {
    const long c1 = std::min(n_steps, c0 + kChunkSteps - 1);
    grid.clear();
    for (long k = c0; k <= c1; ++k) grid.push_back(t0 + static_cast<double>(k) * dt);
    for (GridChannel* g : {&d.rpm, &d.elevator, &d.th_front, &d.th_aft, &d.pitch_cmd, &d.depth_cmd, &d.heading_set,
                           &d.rudder})
      g->fill(grid);
    for (long k = c0; k <= c1; ++k) {
      const auto i = static_cast<std::size_t>(k - c0);
      if (k > 0) eng.sampleWater();
      ActuatorState& act = eng.actuators();
      act.prop_rps = std::max(0.0, d.rpm[i] / 60.0);
      if (actuators) {
        act.plane_rad = -units::degToRad(d.elevator[i]);  // log sign -> paper sign
        if (c.model.thruster_count > 0) {
          act.thruster_rpm[0] = d.th_front[i];
          act.thruster_rpm[1] = d.th_aft[i];
        }
      }
      if (!d.rudder.empty()) eng.yaw().rudder_rad = units::degToRad(d.rudder[i]);

      const Measurement meas = eng.measure(no_noise, exact);
      const bool control_now = k % control_every == 0;
      // Without a logged heading the heading hold keeps the start heading.
      const double heading_cmd = !c.apcfg.heading.enabled ? kNaN
                                 : d.heading_set.empty()  ? init.heading_rad
                                                          : units::degToRad(d.heading_set[i]);
      if (control_now && !actuators) {
        Setpoint sp{d.depth_cmd[i], 0.0, 0.0};
        if (c.drive == ReplayDrive::PitchCommands) {
          sp.pitch_rad = units::degToRad(d.pitch_cmd[i]);
          sp.pitch_is_demand = true;
        }
        demand = ap.update(meas, sp, eng.water().density_kgm3);
      }
      if (control_now && d.rudder.empty())
        rudder_demand = hp.update(heading_cmd, eng.yaw().heading_rad, eng.yaw().r_radps);
      if (row < row1 && stepOf(row) == k) {
        const SampleExtras x{d.depth_cmd.empty() ? kNaN : d.depth_cmd[i],
                             actuators ? kNaN : ap.outputs().pitch_cmd_rad, heading_cmd, ap.outputs().hover_force_n};
        eng.record(tr, grid[i], meas, x, W, no_noise, exact);
        while (row < row1 && stepOf(row) == k) ++row;  // rows closer than dt share a step
      }
      if (k == n_steps) break;
      if (actuators) {
        eng.stepHeld(W);
        if (d.rudder.empty()) advanceRudder(c.model, rudder_demand, dt, eng.yaw());
      } else {
        eng.step(W, demand, d.rudder.empty() ? rudder_demand : eng.yaw().rudder_rad);
      }
    }
  }
  eng.finish(totals);
}

}  // namespace

SimTrace replay(const VehicleModel& model, const DepthAutopilotConfig& apcfg, const WaterColumn& water,
                const MissionLog& log, const ReplayOptions& opt) {
  if (!(opt.dt_s > 0.0 && opt.dt_s <= 1.0)) {
    throw InputError("dt_s", "model step must be in (0, 1] s", "use 0.05 s (20 Hz) as in the paper");
  }
  if (log.rowCount() < 2) throw InputError("time", "the log has fewer than two rows", "replay a longer log");
  require(log, "prop_rpm", "to turn the propeller");
  require(log, "depth", "for the start depth");
  const ReplayDrive drive = resolveReplayDrive(model, log, opt.drive);

  Drivers d;
  d.rpm = GridChannel(log, "prop_rpm", Interpolation::kLinear);
  if (drive == ReplayDrive::Actuators) {
    d.elevator = GridChannel(log, "elevator", Interpolation::kLinear);
    if (model.thruster_count > 0) {
      d.th_front = GridChannel(log, "thruster_front_rpm", Interpolation::kLinear);
      d.th_aft = GridChannel(log, "thruster_aft_rpm", Interpolation::kLinear);
    }
  } else {
    d.depth_cmd = GridChannel(log, "depth_cmd", Interpolation::kHold);
    if (drive == ReplayDrive::PitchCommands) d.pitch_cmd = GridChannel(log, "pitch_cmd", Interpolation::kLinear);
  }
  d.rudder = GridChannel(log, "rudder", Interpolation::kLinear);
  if (d.rudder.empty()) {
    d.heading_set = GridChannel(log, "heading_cmd", Interpolation::kHold);
    if (d.heading_set.empty()) d.heading_set = GridChannel(log, "heading", Interpolation::kLinear);
  }

  const SpanContext ctx{model, apcfg, water, log, opt, drive};
  const double gap_s = restartGap_s(log.time);
  SimTrace tr;
  tr.reserve(log.rowCount());
  bool first_span = true;
  for (std::size_t row0 = 0; row0 < log.rowCount();) {
    std::size_t row1 = row0 + 1;
    while (row1 < log.rowCount() && log.time[row1] - log.time[row1 - 1] <= gap_s) ++row1;
    SimTrace totals;
    replaySpan(ctx, d, row0, row1, tr, totals);
    if (first_span) tr.truth = totals.truth;  // the vehicle as flown from the first row
    tr.energy_j += totals.energy_j;
    tr.hotel_energy_j += totals.hotel_energy_j;
    tr.prop_energy_j += totals.prop_energy_j;
    tr.thruster_energy_j += totals.thruster_energy_j;
    tr.fins_energy_j += totals.fins_energy_j;
    first_span = false;
    row0 = row1;
  }
  return tr;
}

}  // namespace auv::sim
