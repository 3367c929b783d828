// analyzeMission: the log with the profile's accepted attitude sensor biases
// taken out, analysed (mission_analysis.cpp), their sigmas carried into the
// ballast state's.
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "analysis/analysis_messages.h"
#include "analysis/attitude_sensor_bias.h"
#include "analysis/mission_analysis.h"

namespace auv::analysis {
namespace {

std::string text(const char* f, double v) {
  char b[32];
  std::snprintf(b, sizeof b, f, v);
  return b;
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
    const AnalysisReport a = detail::analyzeRecordedLog(*withAttitudeBiasRemoved(log, hi), v, o);
    const AnalysisReport b = detail::analyzeRecordedLog(*withAttitudeBiasRemoved(log, lo), v, o);
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
  const std::optional<MissionLog> corrected = withAttitudeBiasRemoved(log, bias);
  if (!corrected) return detail::analyzeRecordedLog(log, v, o);
  AnalysisReport rep = detail::analyzeRecordedLog(*corrected, v, o);
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
