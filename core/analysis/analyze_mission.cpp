// analyzeMission: the log with the profile's accepted attitude sensor biases
// taken out, analysed (mission_analysis.cpp), their sigmas carried into the
// ballast state's.
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "analysis/analysis_messages.h"
#include "analysis/attitude_sensor_bias.h"
#include "analysis/calibration_segments.h"
#include "analysis/mission_analysis.h"

namespace auv::analysis {
namespace {

std::string text(const char* f, double v) {
  char b[32];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// The log with `b` taken out, analysed with the history's segments read
// the same way: each was stored with the biases its own analysis took out,
// and the sensor is the same (a history mission analysed before a 1 deg
// bias was accepted would otherwise join with legs 1 deg off, about 6 kg on
// a HUGIN's net buoyancy).
AnalysisReport analyzeWithBiasRemoved(const MissionLog& log, const VehicleProfile& v, const AnalysisOptions& o,
                                      const AttitudeSensorBias& b) {
  AnalysisOptions on_sensor = o;
  for (HistoryMission& h : on_sensor.history) {
    for (SteadySegmentMeans& s : h.segments)
      s = withAttitudeRaised(s, h.pitch_bias_removed_deg - b.pitch_deg, h.roll_bias_removed_deg - b.roll_deg);
    h.pitch_bias_removed_deg = b.pitch_deg;
    h.roll_bias_removed_deg = b.roll_deg;
  }
  const std::optional<MissionLog> corrected = withAttitudeBiasRemoved(log, b);
  AnalysisReport rep = detail::analyzeRecordedLog(corrected ? *corrected : log, v, on_sensor);
  rep.pitch_bias_removed_deg = b.pitch_deg;
  rep.roll_bias_removed_deg = b.roll_deg;
  if (b.any() && rep.details.contains("auv_estimate"))
    rep.details["auv_estimate"]["attitude_bias_removed_deg"] = {{"pitch", b.pitch_deg}, {"roll", b.roll_deg}};
  return rep;
}

// The ballast state's sigmas widened by an accepted bias's own sigma: the
// log analysed again with the bias one sigma either side, half the spread
// added in quadrature (net buoyancy, CG x, CG y). The balance is nonlinear
// in the angle of attack, so the spread, not a derivative at one point.
void carryBiasSigma(const MissionLog& log, const VehicleProfile& v, const AnalysisOptions& o,
                    const AttitudeSensorBias& bias, AnalysisReport& rep) {
  auto widen = [&](double AttitudeSensorBias::*angle, double sigma) {
    if (!(sigma > 0.0)) return;
    AttitudeSensorBias hi = bias, lo = bias;
    hi.*angle += sigma;
    lo.*angle -= sigma;
    const AnalysisReport a = analyzeWithBiasRemoved(log, v, o, hi);
    const AnalysisReport b = analyzeWithBiasRemoved(log, v, o, lo);
    for (auto member : {&AnalysisReport::net_buoyancy_kg, &AnalysisReport::cg_x_mm, &AnalysisReport::cg_y_mm}) {
      EstimatedValue& e = rep.*member;
      if (e.known && (a.*member).known && (b.*member).known)
        e.sigma = std::hypot(e.sigma, 0.5 * ((a.*member).value - (b.*member).value));
    }
  };
  widen(&AttitudeSensorBias::pitch_deg, bias.pitch_sigma_deg);
  widen(&AttitudeSensorBias::roll_deg, bias.roll_sigma_deg);
}

}  // namespace

AnalysisReport analyzeMission(const MissionLog& log, const VehicleProfile& v, const AnalysisOptions& o) {
  const AttitudeSensorBias bias = acceptedAttitudeBias(v);
  AnalysisReport rep = analyzeWithBiasRemoved(log, v, o, bias);
  rep.options = o;
  if (!bias.any()) return rep;
  carryBiasSigma(log, v, o, bias, rep);
  // What the legs still show is on top of the accepted bias: report the sensor's whole bias.
  for (CalibrationParameter& q : rep.calibration)
    if (q.id == "pitch_sensor_bias") {
      q.value += bias.pitch_deg;
      q.prior_value = q.profile_value = bias.pitch_deg;
    }
  rep.notes.insert(rep.notes.begin(),
                   Message(msg::kAttitudeBiasRemoved, {text("%+.2f", bias.pitch_deg), text("%.2f", bias.pitch_sigma_deg),
                                                      text("%+.2f", bias.roll_deg), text("%.2f", bias.roll_sigma_deg)}));
  return rep;
}

}  // namespace auv::analysis
