#include "discrepancy/model_check_report.h"

#include "discrepancy/plan_estimate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace auv::discrepancy {

namespace {

// Six significant digits: coefficients of 1e-6 keep their digits, and the
// file does not carry the noise of the last bits.
nlohmann::json num(double v) {
  if (!std::isfinite(v)) return nullptr;
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return std::strtod(b, nullptr);
}

nlohmann::json localisationJson(const Localisation& l) {
  nlohmann::json f = nlohmann::json::array();
  for (const FactorFinding& x : l.ranked) {
    nlohmann::json bins = nlohmann::json::array();
    for (const BinSummary& b : x.bins) bins.push_back({{"label", b.label}, {"mean", num(b.mean)}, {"rms", num(b.rms)}, {"count", b.count}});
    nlohmann::json j = {{"factor", x.factor}, {"share", num(x.share)}, {"text", x.text}, {"bins", bins}};
    if (x.linear) j["slope"] = {{"value", num(x.slope)}, {"per", x.step}};
    f.push_back(j);
  }
  return {{"channel", channelName(l.channel)}, {"unit", channelUnit(l.channel)}, {"source", l.source},
          {"rms", num(l.rms)},            {"mean", num(l.mean)},               {"samples", l.count},
          {"summary", l.summary},        {"ranked", f}};
}

}  // namespace

nlohmann::json toJson(const ModelCheckResult& r) {
  nlohmann::json j;
  nlohmann::json mp = nlohmann::json::array();
  for (const MissingPhysics& m : r.missing_physics) {
    nlohmann::json x = {{"id", m.id},
                        {"value", num(m.value)},
                        {"profile_value", num(m.profile_value)},
                        {"unit", m.unit},
                        {"sigma", num(m.sigma)},
                        {"split_half_sigma", num(m.split_half_sigma)},
                        {"calibration_sigma", num(m.calibration_sigma)},
                        {"rms_before", num(m.rms_before)},
                        {"rms_after", num(m.rms_after)},
                        {"channel", channelName(m.channel)},
                        {"channel_unit", channelUnit(m.channel)},
                        {"where", m.where},
                        {"inclusion_probability", num(m.inclusion_probability)},
                        {"t_value", num(m.t_value)},
                        {"delta_bic", num(m.delta_bic)},
                        {"heldout_gain", num(m.heldout_gain)}};
    if (!m.confused_with.empty()) x["confused_with"] = m.confused_with;
    if (!m.rivals.empty()) {
      x["rivals"] = nlohmann::json::array();
      for (const TermRival& rv : m.rivals) x["rivals"].push_back({{"id", rv.id}, {"inclusion_probability", num(rv.inclusion_probability)}});
    }
    if (!m.evidence.empty()) x["evidence"] = m.evidence;
    mp.push_back(x);
  }
  j["missing_physics"] = mp;
  nlohmann::json cal = nlohmann::json::array();
  nlohmann::json findings = nlohmann::json::array();
  for (const CalibrationValue& c : r.calibration) {
    nlohmann::json x = {{"id", c.id},
                        {"value", num(c.value)},
                        {"unit", c.unit},
                        {"sigma", num(c.sigma)},
                        {"profile_value", num(c.profile_value)},
                        {"prior_sigma", num(c.prior_sigma)},
                        {"identified", c.identified},
                        {"from_analysis", c.from_analysis}};
    if (!c.finding.empty()) {
      x["finding"] = c.finding;
      findings.push_back(c.finding);
    }
    cal.push_back(x);
  }
  j["calibration"] = cal;
  j["calibration_findings"] = findings;
  j["net_buoyancy_kg"] = num(r.net_buoyancy_kg);
  j["net_buoyancy_sigma_kg"] = num(r.net_buoyancy_sigma_kg);
  if (r.has_cg) {
    j["cg_offset_mm"] = {{"x", num(r.cg_x_mm)}, {"y", num(r.cg_y_mm)}};
    j["cg_offset_sigma_mm"] = {{"x", num(r.cg_x_sigma_mm)}, {"y", num(r.cg_y_sigma_mm)}};
  }
  nlohmann::json mc;
  mc["model"] = r.model;
  mc["samples"] = r.samples;
  mc["units"] = r.units;
  mc["effective_sample_share"] = num(r.neff_ratio);
  mc["net_buoyancy_without_terms_kg"] = num(r.net_buoyancy_base_kg);
  if (r.reference_water)
    mc["reference_water"] = {{"density_kgm3", num(r.reference_water->density_kgm3)},
                             {"temperature_degC", num(r.reference_water->temperature_degC)},
                             {"pressure_dbar", num(r.reference_water->pressure_dbar)}};
  nlohmann::json ballast = nlohmann::json::object();
  for (std::size_t k = 0; k < r.nuisance_names.size() && k < r.nuisance.size(); ++k) {
    const bool calibration = std::any_of(r.calibration.begin(), r.calibration.end(),
                                         [&](const CalibrationValue& c) { return c.id == r.nuisance_names[k]; });
    if (!calibration) ballast[r.nuisance_names[k]] = {{"value", num(r.nuisance[k])}, {"sigma", num(r.nuisance_sigma[k])}};
  }
  mc["ballast_state"] = ballast;
  nlohmann::json cands = nlohmann::json::array();
  for (const CandidateReport& c : r.candidates) {
    cands.push_back({{"id", c.id},
                     {"status", c.status},
                     {"value_alone", num(c.value)},
                     {"sigma_alone", num(c.sigma)},
                     {"t_value", num(c.t_value)},
                     {"inclusion_probability", num(c.inclusion_probability)},
                     {"ballast_state_r2", num(c.nuisance_r2)}});
    if (std::isfinite(c.twin_value)) {
      cands.back()["noise_twin_value_alone"] = num(c.twin_value);
      cands.back()["noise_twin_sigma_alone"] = num(c.twin_sigma);
    }
  }
  mc["candidates"] = cands;
  nlohmann::json ident = nlohmann::json::array();
  for (const IdentifiabilityIssue& i : r.identifiability)
    ident.push_back({{"a", i.a}, {"b", i.b}, {"correlation", num(i.correlation)}, {"message", i.message}});
  mc["identifiability"] = ident;
  mc["stlsq_selected"] = r.stlsq_selected;
  nlohmann::json rms = nlohmann::json::array();
  for (const ChannelRms& c : r.rms)
    rms.push_back({{"channel", channelName(c.channel)},
                   {"unit", channelUnit(c.channel)},
                   {"source", c.source},
                   {"fitted_before", num(c.fitted_before)},
                   {"fitted_after", num(c.fitted_after)},
                   {"heldout_before", num(c.heldout_before)},
                   {"heldout_after", num(c.heldout_after)},
                   {"samples", c.samples}});
  mc["rms"] = rms;
  nlohmann::json loc = nlohmann::json::array();
  for (const Localisation& l : r.localisation) loc.push_back(localisationJson(l));
  mc["localisation"] = loc;
  mc["notes"] = r.notes;
  if (const auto& b = r.analysis_without_pitch_bias) {
    nlohmann::json x = {{"pitch_sensor_bias_deg", num(b->pitch_bias_deg)},
                        {"pitch_sensor_bias_sigma_deg", num(b->pitch_bias_sigma_deg)},
                        {"net_buoyancy_kg", num(b->net_buoyancy_kg)},
                        {"net_buoyancy_sigma_kg", num(b->net_buoyancy_sigma_kg)}};
    if (b->has_cg_x) x["cg_offset_mm"] = {{"x", num(b->cg_x_mm)}}, x["cg_offset_sigma_mm"] = {{"x", num(b->cg_x_sigma_mm)}};
    mc["analysis_without_pitch_bias"] = x;
  }
  mc["warnings"] = r.warnings;
  j["model_check"] = mc;
  return j;
}

void mergeIntoAnalysisJson(nlohmann::json& a, const ModelCheckResult& r, bool terms_accepted) {
  const nlohmann::json m = toJson(r);
  nlohmann::json mc = m["model_check"];
  mc["analysis_estimate"] = {{"net_buoyancy_kg", a.value("net_buoyancy_kg", nlohmann::json())},
                             {"net_buoyancy_sigma_kg", a.value("net_buoyancy_sigma_kg", nlohmann::json())},
                             {"cg_offset_mm", a.value("cg_offset_mm", nlohmann::json())}};
  a["missing_physics"] = m["missing_physics"];
  a["calibration"] = m["calibration"];
  a["calibration_findings"] = m["calibration_findings"];
  // An analysis calibrated jointly with an earlier mission across a known
  // weight change (issue 11 item 3) has had a calibration experiment the
  // check's single-log fit has not: its estimate stays the report's, the
  // check's is kept beside it.
  const bool joint = a.contains("details") && a["details"].contains("auv_estimate") &&
                     a["details"]["auv_estimate"].value("history_segments_used", 0) > 0 &&
                     a.value("net_buoyancy_kg", nlohmann::json()).is_number();
  const bool auv = a.value("vehicle_kind", std::string()) == "auv";
  const bool analysis_knows = a.value("net_buoyancy_kg", nlohmann::json()).is_number();
  const bool any_term = terms_accepted && !r.missing_physics.empty();
  if (!joint && auv && analysis_knows) {
    mc["check_estimate"] = {{"net_buoyancy_kg", m["net_buoyancy_kg"]}, {"net_buoyancy_sigma_kg", m["net_buoyancy_sigma_kg"]},
                            {"cg_offset_mm", m.value("cg_offset_mm", nlohmann::json())}};
    if (!any_term) {
      mc["estimate_source"] = "analysis (no model-check term accepted)";
    } else if (m["net_buoyancy_kg"].is_number() && m["net_buoyancy_sigma_kg"].is_number() &&
               m["net_buoyancy_sigma_kg"].get<double>() > 0.0) {
      // planEstimate's rule: the check's centre, the sigma widened by the
      // disagreement the accepted terms did not explain.
      const auto widen = [](nlohmann::json& value, nlohmann::json& sigma, const nlohmann::json& cv, const nlohmann::json& cs) {
        if (!cv.is_number() || !cs.is_number() || !(cs.get<double>() > 0.0)) return;
        if (value.is_number() && sigma.is_number())
          sigma = adoptedSigma(value.get<double>(), sigma.get<double>(), cv.get<double>(), cs.get<double>());
        else
          sigma = cs;
        value = cv;
      };
      // planEstimate's analysis side with an accepted pitch sensor bias: the
      // log analysed again without it.
      if (mc.contains("analysis_without_pitch_bias")) {
        const nlohmann::json& f = mc["analysis_without_pitch_bias"];
        a["net_buoyancy_kg"] = f["net_buoyancy_kg"];
        a["net_buoyancy_sigma_kg"] = f["net_buoyancy_sigma_kg"];
        if (f.contains("cg_offset_mm") && a.contains("cg_offset_mm") && a["cg_offset_mm"].is_object() &&
            a.contains("cg_offset_sigma_mm") && a["cg_offset_sigma_mm"].is_object()) {
          a["cg_offset_mm"]["x"] = f["cg_offset_mm"]["x"];
          a["cg_offset_sigma_mm"]["x"] = f["cg_offset_sigma_mm"]["x"];
        }
      }
      widen(a["net_buoyancy_kg"], a["net_buoyancy_sigma_kg"], m["net_buoyancy_kg"], m["net_buoyancy_sigma_kg"]);
      if (m.contains("cg_offset_mm") && a.contains("cg_offset_mm") && a["cg_offset_mm"].is_object() &&
          a.contains("cg_offset_sigma_mm") && a["cg_offset_sigma_mm"].is_object())
        widen(a["cg_offset_mm"]["x"], a["cg_offset_sigma_mm"]["x"], m["cg_offset_mm"].value("x", nlohmann::json()),
              m["cg_offset_sigma_mm"].value("x", nlohmann::json()));
      mc["estimate_source"] = "model check with the accepted terms (sigma widened by its difference from the analysis)";
    }
  } else if (joint) {
    mc["check_estimate"] = {{"net_buoyancy_kg", m["net_buoyancy_kg"]}, {"net_buoyancy_sigma_kg", m["net_buoyancy_sigma_kg"]},
                            {"cg_offset_mm", m.value("cg_offset_mm", nlohmann::json())}};
    mc["estimate_source"] = "analysis calibrated with the configuration's earlier mission";
    // CG y is about roll, which the move does not calibrate: the check's
    // where the analysis has none.
    if (m.contains("cg_offset_mm") && a.contains("cg_offset_mm") && a["cg_offset_mm"].is_object() &&
        a["cg_offset_mm"].value("y", nlohmann::json()).is_null() && m["cg_offset_mm"].value("y", nlohmann::json()).is_number()) {
      a["cg_offset_mm"]["y"] = m["cg_offset_mm"]["y"];
      if (!a.contains("cg_offset_sigma_mm") || !a["cg_offset_sigma_mm"].is_object()) a["cg_offset_sigma_mm"] = nlohmann::json::object();
      a["cg_offset_sigma_mm"]["y"] = m["cg_offset_sigma_mm"].value("y", nlohmann::json());
    }
  } else {
    a["net_buoyancy_kg"] = m["net_buoyancy_kg"];
    a["net_buoyancy_sigma_kg"] = m["net_buoyancy_sigma_kg"];
    if (m.contains("cg_offset_mm")) {
      a["cg_offset_mm"] = m["cg_offset_mm"];
      a["cg_offset_sigma_mm"] = m["cg_offset_sigma_mm"];
    }
    // What the check's replay now tells is no longer "not identifiable"
    // (e.g. Delphin2 with its thrusters running in every steady segment);
    // why the steady flight could not stays under analysis_why.
    if (a.contains("not_identifiable") && a["not_identifiable"].is_object()) {
      nlohmann::json& ni = a["not_identifiable"];
      nlohmann::json why = nlohmann::json::object();
      auto adopt = [&](const char* key, bool told) {
        if (!told || !ni.contains(key)) return;
        why[key] = ni[key];
        ni.erase(key);
      };
      adopt("net_buoyancy_kg", m["net_buoyancy_kg"].is_number());
      adopt("cg_offset_mm.x", m.contains("cg_offset_mm") && m["cg_offset_mm"].value("x", nlohmann::json()).is_number());
      if (!why.empty()) mc["analysis_why"] = why;
    }
  }
  a["model_check"] = mc;
}

std::string toText(const ModelCheckResult& r) {
  std::string s;
  char b[512];
  s += "Model check: " + r.model + "\n";
  std::snprintf(b, sizeof b, "  %zu samples in %d dives/legs (effective share %.3f)\n", r.samples, r.units, r.neff_ratio);
  s += b;
  if (r.missing_physics.empty()) {
    s += "  Missing physics: none found (the model with its ballast state explains the log within its noise).\n";
  } else {
    s += "  Missing physics, best first:\n";
    for (const MissingPhysics& m : r.missing_physics) {
      std::snprintf(b, sizeof b, "    %-24s %.4g +- %.2g %s (profile %.4g); held-out %s RMS %.3g -> %.3g %s\n", m.id.c_str(),
                    m.value, m.sigma, m.unit.c_str(), m.profile_value, channelName(m.channel), m.rms_before, m.rms_after,
                    channelUnit(m.channel));
      s += b;
      if (!m.where.empty()) s += "      where: " + m.where + "\n";
      if (!m.evidence.empty()) s += "      note: " + m.evidence + "\n";
    }
  }
  if (!r.calibration.empty()) {
    s += "  Calibration (the analysis's where it calibrated them, else fitted with the ballast state under priors; not missing physics):\n";
    for (const CalibrationValue& c : r.calibration) {
      std::snprintf(b, sizeof b, "    %-26s %.4g +- %.2g %s (profile %.4g, prior sigma %.2g)%s\n", c.id.c_str(), c.value, c.sigma,
                    c.unit.c_str(), c.profile_value, c.prior_sigma,
                    c.from_analysis ? " - the analysis's, held" : c.identified ? "" : " - stayed at its prior");
      s += b;
    }
    for (const CalibrationValue& c : r.calibration)
      if (!c.finding.empty()) s += "  Calibration finding: " + c.finding + "\n";
  }
  std::snprintf(b, sizeof b, "  Net buoyancy (jointly with the accepted terms): %+.3f +- %.3f kg (without them %+.3f kg)\n",
                r.net_buoyancy_kg, r.net_buoyancy_sigma_kg, r.net_buoyancy_base_kg);
  s += b;
  if (r.has_cg) {
    std::snprintf(b, sizeof b, "  CG offset (CG - CB): x %+.2f +- %.2f mm, y %+.2f +- %.2f mm\n", r.cg_x_mm, r.cg_x_sigma_mm,
                  r.cg_y_mm, r.cg_y_sigma_mm);
    s += b;
  }
  s += "  RMS per channel (before -> after; fitted | held-out):\n";
  for (const ChannelRms& c : r.rms) {
    std::snprintf(b, sizeof b, "    %-10s %-18s %.4g -> %.4g | %.4g -> %.4g %s\n", c.source.c_str(), channelName(c.channel),
                  c.fitted_before, c.fitted_after, c.heldout_before, c.heldout_after, channelUnit(c.channel));
    s += b;
  }
  s += "  Where the ballast-only model misses:\n";
  for (const Localisation& l : r.localisation) s += "    " + l.source + ", " + channelName(l.channel) + ": " + l.summary + "\n";
  for (const IdentifiabilityIssue& i : r.identifiability) s += "  Identifiability: " + i.message + "\n";
  for (const std::string& w : r.warnings) s += "  Warning: " + w + "\n";
  return s;
}

}  // namespace auv::discrepancy
