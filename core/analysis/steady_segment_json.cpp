#include "analysis/steady_segment_json.h"

#include <cmath>

#include "common/input_error.h"

namespace auv::analysis {
namespace {

// A mean with its standard error, or null when the channel had no samples.
nlohmann::json meanJson(const MeanEstimate& m) {
  if (!m.valid() || !std::isfinite(m.mean)) return nullptr;
  return {{"mean", m.mean}, {"se", std::isfinite(m.se) ? nlohmann::json(m.se) : nlohmann::json(nullptr)},
          {"n", m.n}};
}

MeanEstimate meanFrom(const nlohmann::json& j, const std::string& where) {
  MeanEstimate m;
  if (j.is_null()) return m;
  if (!j.is_object() || !j.contains("mean") || !j["mean"].is_number() || !j.contains("n") || !j["n"].is_number_unsigned())
    throw InputError(where, "needs {mean, se, n} or null", "write it with 'auvballast analyze' or 'model-check'");
  m.mean = j["mean"].get<double>();
  if (j.contains("se") && j["se"].is_number()) m.se = j["se"].get<double>();
  m.n = j["n"].get<std::size_t>();
  return m;
}

double numberOr(const nlohmann::json& j, const char* key, double fallback) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : fallback;
}

}  // namespace

nlohmann::json steadySegmentsJson(const std::vector<SteadySegmentMeans>& segments) {
  nlohmann::json a = nlohmann::json::array();
  for (const SteadySegmentMeans& s : segments) {
    a.push_back({{"start_s", s.start_s}, {"end_s", s.end_s}, {"speed_mps", meanJson(s.speed_mps)},
                 {"pitch_deg", meanJson(s.pitch_deg)}, {"roll_deg", meanJson(s.roll_deg)},
                 {"elevator_deg", meanJson(s.elevator_deg)}, {"depth_rate_mps", meanJson(s.depth_rate_mps)},
                 {"prop_rpm", meanJson(s.prop_rpm)},
                 {"density_kgm3", std::isfinite(s.density_kgm3) ? nlohmann::json(s.density_kgm3) : nlohmann::json(nullptr)},
                 {"buoyancy_n", std::isfinite(s.buoyancy_n) ? nlohmann::json(s.buoyancy_n) : nlohmann::json(nullptr)}});
    if (std::isfinite(s.pressure_dbar)) a.back()["pressure_dbar"] = s.pressure_dbar;
    if (std::isfinite(s.temperature_degC)) a.back()["temperature_degC"] = s.temperature_degC;
    if (const auto& r = s.regressors)
      a.back()["cycle_regressors"] = {{"cc", r->cc},     {"sin_theta", r->sin_theta}, {"au_w", r->au_w},
                                      {"u_w", r->u_w},   {"aw_w", r->aw_w},           {"au_u", r->au_u},
                                      {"au_u_e", r->au_u_e}};
  }
  return a;
}

std::vector<SteadySegmentMeans> steadySegmentsFromJson(const nlohmann::json& j, const std::string& where) {
  if (!j.is_array()) throw InputError(where, "is not a list of steady segments", "write it with 'auvballast analyze'");
  std::vector<SteadySegmentMeans> out;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string at = where + "[" + std::to_string(i) + "]";
    const nlohmann::json& e = j[i];
    if (!e.is_object()) throw InputError(at, "is not an object", "write it with 'auvballast analyze'");
    SteadySegmentMeans s;
    s.start_s = numberOr(e, "start_s", 0.0);
    s.end_s = numberOr(e, "end_s", 0.0);
    for (auto [key, field] : {std::pair{"speed_mps", &s.speed_mps}, {"pitch_deg", &s.pitch_deg}, {"roll_deg", &s.roll_deg},
                              {"elevator_deg", &s.elevator_deg}, {"depth_rate_mps", &s.depth_rate_mps},
                              {"prop_rpm", &s.prop_rpm}})
      *field = meanFrom(e.contains(key) ? e[key] : nlohmann::json(nullptr), at + "." + key);
    s.density_kgm3 = numberOr(e, "density_kgm3", s.density_kgm3);
    s.buoyancy_n = numberOr(e, "buoyancy_n", s.buoyancy_n);
    // Rows written before the hull-law levers have neither (no lever).
    s.pressure_dbar = numberOr(e, "pressure_dbar", s.pressure_dbar);
    s.temperature_degC = numberOr(e, "temperature_degC", s.temperature_degC);
    if (e.contains("cycle_regressors") && e["cycle_regressors"].is_object()) {
      const nlohmann::json& r = e["cycle_regressors"];
      BalanceRegressors g;
      for (auto [key, field] : {std::pair{"cc", &g.cc}, {"sin_theta", &g.sin_theta}, {"au_w", &g.au_w}, {"u_w", &g.u_w},
                                {"aw_w", &g.aw_w}, {"au_u", &g.au_u}, {"au_u_e", &g.au_u_e}}) {
        if (!r.contains(key) || !r[key].is_number())
          throw InputError(at + ".cycle_regressors." + key, "is missing or not a number", "write it with 'auvballast analyze'");
        *field = r[key].get<double>();
      }
      s.regressors = g;
    }
    out.push_back(s);
  }
  return out;
}

}  // namespace auv::analysis
