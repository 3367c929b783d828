#include "discrepancy/glider_ballast_answer.h"

#include <algorithm>
#include <cmath>

namespace auv::discrepancy {

namespace {

nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

GliderBallastAnswer gliderBallastAnswer(const GliderCheckModel& m, const ModelCheckResult& r, const analysis::GliderTarget& t) {
  GliderBallastAnswer a;
  a.target = t;
  const Params& p = r.final_params;
  a.mass_to_add_g = 1000.0 * m.massToAddKg(p, t);
  a.mass_to_add_without_terms_g = 1000.0 * m.massToAddKg(r.base_params, t);
  a.hours_to_end = m.hoursFromReferenceToEnd();
  a.mass_change_at_end_g = 1000.0 * m.massChangeAtEndKg(p);
  a.hull_volume_m3 = m.hullVolumeM3(p);
  a.mass_now_kg = m.constants().mass_kg + a.mass_change_at_end_g / 1000.0;
  a.reference_temperature_degC = m.constants().reference_temperature_degC;
  const auto& lib = termLibrary();
  const TermValues& base = m.baseline();
  // Uncertainty: first-order propagation of the joint fit's sigmas (net
  // buoyancy and each accepted term), by central differences.
  double var = 0.0;
  if (!r.nuisance_sigma.empty() && std::isfinite(r.nuisance_sigma[0])) {
    const double h = 1e-3;
    Params hi = p, lo = p;
    hi.nuisance[0] += h;
    lo.nuisance[0] -= h;
    const double d = (m.massToAddKg(hi, t) - m.massToAddKg(lo, t)) / (2 * h);
    var += std::pow(d * r.nuisance_sigma[0], 2);
  }
  for (const MissingPhysics& mp : r.missing_physics) {
    const auto k = findTerm(mp.id);
    if (!k) continue;
    a.terms_used.push_back(mp.id);
    const double sigma = mp.sigma / lib[*k].display_scale;
    if (std::isfinite(sigma) && sigma > 0) {
      const double h = lib[*k].typical * 0.1;
      Params hi = p, lo = p;
      hi.terms[*k] += h;
      lo.terms[*k] -= h;
      const double d = (m.massToAddKg(hi, t) - m.massToAddKg(lo, t)) / (2 * h);
      var += std::pow(d * sigma, 2);
    }
    if (mp.id == "mass_drift") {
      a.mass_drift_g_per_h = 1000.0 * (base[*k] + p.terms[*k]);
      a.mass_drift_sigma_g_per_h = 1000.0 * sigma;
    }
  }
  // A term found over a rival (model_check.h): the answer with the rival
  // instead, weighted by its bootstrap share, widens the sigma (model
  // averaging), so a coin-flip between compressibility and thermal
  // expansion does not read as a firm number.
  for (const RivalFit& rf : r.rival_fits) {
    const double d = m.massToAddKg(rf.params, t) - m.massToAddKg(p, t);
    var += rf.weight * d * d;
    a.rival_spread_g = std::max(a.rival_spread_g, 1000.0 * std::abs(d));
  }
  // A candidate the check did not accept but the bootstrap often picked
  // (a mass drift that helps the equation error but not the held-out
  // simulation, on a short log) may still be there: its linearised value,
  // weighted by its inclusion probability, widens the sigma too.
  const auto counted = [&](const std::string& id) {  // accepted, or already carried as a rival
    return std::find(a.terms_used.begin(), a.terms_used.end(), id) != a.terms_used.end() ||
           std::any_of(r.rival_fits.begin(), r.rival_fits.end(), [&](const RivalFit& rf) { return rf.rival == id; });
  };
  for (const CandidateReport& c : r.candidates) {
    const auto k = findTerm(c.id);
    if (!k || !(c.inclusion_probability > 0.0) || !std::isfinite(c.value) || counted(c.id)) continue;
    Params with = p;
    with.terms[*k] += c.value / lib[*k].display_scale;
    const double d = m.massToAddKg(with, t) - m.massToAddKg(p, t);
    var += c.inclusion_probability * d * d;
    a.unconfirmed_spread_g = std::max(a.unconfirmed_spread_g, 1000.0 * std::abs(d) * std::sqrt(c.inclusion_probability));
  }
  a.mass_to_add_sigma_g = 1000.0 * std::sqrt(var);
  const auto total = [&](const char* id) {
    const auto k = findTerm(id);
    return k ? base[*k] + p.terms[*k] : 0.0;
  };
  a.pitch_bias_removed_deg = total("pitch_sensor_bias") * 180.0 / 3.14159265358979323846;
  if (a.mass_drift_g_per_h == 0.0) a.mass_drift_g_per_h = 1000.0 * total("mass_drift");
  a.compressibility_per_dbar = m.constants().compressibility_per_dbar + total("hull_compressibility");
  a.thermal_expansion_per_degC = m.constants().thermal_expansion_per_degC + total("thermal_expansion");
  return a;
}

void mergeGliderAnswer(nlohmann::json& j, const GliderBallastAnswer& a) {
  nlohmann::json& mc = j["model_check"];
  if (mc.contains("analysis_estimate")) {
    mc["analysis_estimate"]["mass_to_add_g"] = j.value("mass_to_add_g", nlohmann::json());
    mc["analysis_estimate"]["mass_to_add_sigma_g"] = j.value("mass_to_add_sigma_g", nlohmann::json());
  }
  j["mass_to_add_g"] = num(a.mass_to_add_g);
  j["mass_to_add_sigma_g"] = num(a.mass_to_add_sigma_g);
  j["target_density_kgm3"] = num(a.target.density_kgm3);
  j["target"] = {{"density_kgm3", num(a.target.density_kgm3)},
                 {"pressure_dbar", num(a.target.pressure_dbar)},
                 {"temperature_degC", num(a.target.temperature_degC)},
                 {"basis", a.target.basis}};
  mc["glider_ballast"] = {
      {"mass_to_add_g", num(a.mass_to_add_g)},
      {"mass_to_add_sigma_g", num(a.mass_to_add_sigma_g)},
      {"mass_to_add_without_terms_g", num(a.mass_to_add_without_terms_g)},
      {"basis", "neutral at the target with the pump at zero: rho_t V0 (1 - kappa p_t)(1 + alpha (T_t - T_ref)) minus the "
                "mass at the end of the log; V0 and the terms from the joint fit"},
      {"terms_used", a.terms_used},
      {"hull_volume_m3", num(a.hull_volume_m3)},
      {"mass_now_kg", num(a.mass_now_kg)},
      {"reference_temperature_degC", num(a.reference_temperature_degC)},
      {"mass_drift_g_per_h", num(a.mass_drift_g_per_h)},
      {"mass_drift_sigma_g_per_h", num(a.mass_drift_sigma_g_per_h)},
      {"mass_change_at_end_g", num(a.mass_change_at_end_g)},
      {"hours_from_fit_reference_to_end", num(a.hours_to_end)},
      {"pitch_bias_removed_deg", num(a.pitch_bias_removed_deg)},
      {"rival_spread_g", num(a.rival_spread_g)},
      {"unconfirmed_spread_g", num(a.unconfirmed_spread_g)},
      {"compressibility_per_dbar", num(a.compressibility_per_dbar)},
      {"thermal_expansion_per_degC", num(a.thermal_expansion_per_degC)}};
}

}  // namespace auv::discrepancy
