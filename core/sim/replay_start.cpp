#include "sim/replay_start.h"

#include <algorithm>
#include <cmath>

#include "common/units.h"
#include "missionlog/resample.h"

namespace auv::sim {

double loggedValueAt(const MissionLog& log, const char* name, double t0, double fallback) {
  const LogChannel* c = log.find(name);
  if (c == nullptr || c->validCount() == 0) return fallback;
  const TimeSeries s = log.series(name);
  const std::vector<double> v = resample(s, std::vector<double>{t0}, {Interpolation::kLinear});
  if (!std::isnan(v.front())) return v.front();
  const auto it = std::lower_bound(s.t.begin(), s.t.end(), t0);
  if (it != s.t.end()) return s.v[static_cast<std::size_t>(it - s.t.begin())];
  return s.v.back();
}

std::optional<double> loggedDepthRate(const MissionLog& log, double t0, double window_s) {
  const LogChannel* c = log.find("depth");
  if (c == nullptr) return std::nullopt;
  double n = 0, st = 0, sz = 0, stt = 0, stz = 0;
  const auto first = std::lower_bound(log.time.begin(), log.time.end(), t0);
  for (auto r = static_cast<std::size_t>(first - log.time.begin()); r < log.rowCount() && log.time[r] <= t0 + window_s; ++r) {
    const double z = c->values[r], t = log.time[r] - t0;
    if (!std::isfinite(z)) continue;
    n += 1;
    st += t;
    sz += z;
    stt += t * t;
    stz += t * z;
  }
  const double den = n * stt - st * st;
  if (n < 3 || !(den > 0.0)) return std::nullopt;
  return (n * stz - st * sz) / den;
}

InitialState replayStartState(const MissionLog& log, double t0, const VehicleModel& model, bool in_motion) {
  InitialState s;
  s.depth_m = loggedValueAt(log, "depth", t0, 0.0);
  s.pitch_rad = units::degToRad(loggedValueAt(log, "pitch", t0, 0.0));
  s.roll_rad = units::degToRad(loggedValueAt(log, "roll", t0, 0.0));
  s.heading_rad = units::degToRad(loggedValueAt(log, "heading", t0, 0.0));
  s.speed_mps = loggedValueAt(log, "speed", t0, 0.0);
  s.prop_rps = loggedValueAt(log, "prop_rpm", t0, 0.0) / 60.0;
  if (!in_motion) return s;
  s.depth_rate_mps = loggedDepthRate(log, t0);
  s.plane_rad = -units::degToRad(loggedValueAt(log, "elevator", t0, 0.0));  // logged sign: positive = trailing edge down
  if (model.thruster_count > 0) s.thruster_rpm[0] = loggedValueAt(log, "thruster_front_rpm", t0, 0.0);
  if (model.thruster_count > 1) s.thruster_rpm[1] = loggedValueAt(log, "thruster_aft_rpm", t0, 0.0);
  return s;
}

}  // namespace auv::sim
