#include "analysis/attitude_sensor_bias.h"

#include <cmath>

namespace auv::analysis {
namespace {

double termDeg(const nlohmann::json& sections, const char* id) {
  const auto mc = sections.find("model_check");
  if (mc == sections.end() || !mc->is_object()) return 0.0;
  const auto terms = mc->find("terms");
  if (terms == mc->end() || !terms->is_object()) return 0.0;
  const auto t = terms->find(id);
  return t != terms->end() && t->is_number() && std::isfinite(t->get<double>()) ? t->get<double>() : 0.0;
}

// The sigma the latest acceptance of term `id` recorded; 0 without one.
double acceptedSigmaDeg(const nlohmann::json& sections, const char* id) {
  const auto mc = sections.find("model_check");
  if (mc == sections.end() || !mc->is_object()) return 0.0;
  const auto acc = mc->find("accepted");
  if (acc == mc->end() || !acc->is_array()) return 0.0;
  double sigma = 0.0;
  for (const auto& a : *acc)
    if (a.is_object() && a.value("id", "") == id && a.contains("sigma") && a["sigma"].is_number() &&
        std::isfinite(a["sigma"].get<double>()))
      sigma = std::abs(a["sigma"].get<double>());
  return sigma;
}

void subtract(MissionLog& log, const char* channel, double deg) {
  if (deg == 0.0) return;
  if (LogChannel* c = log.find(channel))
    for (double& x : c->values) x -= deg;  // NaN (not sampled) stays NaN
}

}  // namespace

AttitudeSensorBias acceptedAttitudeBias(const VehicleProfile& v) {
  if (v.kind == "glider") return {};
  AttitudeSensorBias b{termDeg(v.sections, "pitch_sensor_bias"), termDeg(v.sections, "roll_sensor_bias")};
  if (b.pitch_deg != 0.0) b.pitch_sigma_deg = acceptedSigmaDeg(v.sections, "pitch_sensor_bias");
  if (b.roll_deg != 0.0) b.roll_sigma_deg = acceptedSigmaDeg(v.sections, "roll_sensor_bias");
  return b;
}

std::optional<MissionLog> withAttitudeBiasRemoved(const MissionLog& log, const AttitudeSensorBias& b) {
  if (!b.any()) return std::nullopt;
  MissionLog out = log;
  subtract(out, "pitch", b.pitch_deg);
  subtract(out, "roll", b.roll_deg);
  return out;
}

}  // namespace auv::analysis
