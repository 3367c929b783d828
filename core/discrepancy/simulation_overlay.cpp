#include "discrepancy/simulation_overlay.h"

#include <cmath>
#include <limits>

#include "analysis/mission_analysis.h"
#include "analysis/segments.h"
#include "analysis/series_tools.h"
#include "seawater/depth_pressure.h"

namespace auv::discrepancy {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
// Vertical velocity from the depth record over the glider check's 10 s boxcar.
constexpr double kRateWindow_s = 10.0;
constexpr double kMaxGap_s = 60.0;

// The recorded channel at the sample times, in its display unit.
std::vector<double> recordedAt(const MissionLog& log, Channel c, const std::vector<double>& t) {
  std::vector<double> out(t.size(), kNaN);
  TimeSeries s;
  double scale = 1.0;
  const double lat = analysis::latitudeFromMetadata(log).value_or(seawater::kDefaultLatitude_deg);
  switch (c) {
    case Channel::kDepth: s = analysis::depthSeries(log, lat); break;
    case Channel::kPitch:
    case Channel::kRoll:
    case Channel::kSpeed: {
      const char* name = c == Channel::kPitch ? "pitch" : c == Channel::kRoll ? "roll" : "speed";
      if (!log.has(name)) return out;
      s = log.series(name);  // canonical units: deg, deg, m/s = the display units
      break;
    }
    case Channel::kVerticalVelocity: {
      s = analysis::depthSeries(log, lat);
      const std::vector<double> rate = analysis::localRate(s, kRateWindow_s, kMaxGap_s);
      for (std::size_t i = 0; i < s.size(); ++i) s.v[i] = -rate[i];  // up positive
      scale = channelDisplayScale(c);
      break;
    }
    default: return out;  // force/moment channels are not recorded
  }
  if (s.empty()) return out;
  analysis::SeriesCursor cur(s, false, kMaxGap_s);
  for (std::size_t i = 0; i < t.size(); ++i) out[i] = cur.at(t[i]) * scale;
  return out;
}

}  // namespace

SimulationOverlay simulationOverlay(const CheckModel& model, const ModelCheckResult& result, const MissionLog& log) {
  SimulationOverlay o;
  const SampleTable& s = model.samples();
  o.t_s = s.t;
  const std::vector<Channel> ch = model.simulationChannels();
  const std::size_t n = s.size(), C = ch.size();
  std::vector<double> before, after;
  model.simulationError(result.base_params, before);
  model.simulationError(result.final_params, after);
  double worst = -kInf;
  for (std::size_t c = 0; c < C; ++c) {
    ChannelOverlay co;
    co.channel = ch[c];
    co.unit = channelUnit(ch[c]);
    const double k = channelDisplayScale(ch[c]);
    co.recorded = recordedAt(log, ch[c], s.t);
    co.simulated_before.assign(n, kNaN);
    co.simulated_after.assign(n, kNaN);
    double sb = 0.0, sa = 0.0, s1 = 0.0, s2 = 0.0;
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double r = co.recorded[i], eb = before[i * C + c] * k, ea = after[i * C + c] * k;
      if (!std::isfinite(r) || !std::isfinite(eb) || !std::isfinite(ea)) continue;
      co.simulated_before[i] = r - eb;
      co.simulated_after[i] = r - ea;
      sb += eb * eb;
      sa += ea * ea;
      s1 += r;
      s2 += r * r;
      ++m;
    }
    co.scored = m;
    if (m > 0) {
      const double mean = s1 / static_cast<double>(m);
      co.rms_before = std::sqrt(sb / static_cast<double>(m));
      co.rms_after = std::sqrt(sa / static_cast<double>(m));
      co.recorded_sd = std::sqrt(std::max(0.0, s2 / static_cast<double>(m) - mean * mean));
      co.mismatch = co.recorded_sd > 0.0 ? co.rms_before / co.recorded_sd : 0.0;
      if (co.mismatch > worst) {
        worst = co.mismatch;
        o.largest = c;
      }
    }
    o.channels.push_back(std::move(co));
  }
  return o;
}

}  // namespace auv::discrepancy
