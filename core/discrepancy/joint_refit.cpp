#include "discrepancy/joint_refit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "common/units.h"
#include "discrepancy/held_shifts.h"

namespace auv::discrepancy::detail {

namespace {

// "propeller torque 0.000 +- 0.020 N m at 100 rpm; the profile assumed 0.052"
std::string calibrationWords(const CalibrationValue& c) {
  char b[256];
  if (c.id == "propeller_torque") {
    const double k = 1e4;  // N m/rpm^2 -> N m at 100 rpm (bollard pull)
    std::snprintf(b, sizeof b, "%s %.3f +- %.3f N m at 100 rpm; the profile assumed %.3f", c.label.c_str(), k * c.value,
                  k * c.sigma, k * c.profile_value);
  } else {
    std::snprintf(b, sizeof b, "%s %.3g +- %.2g %s; the profile assumed %.3g", c.label.c_str(), c.value, c.sigma,
                  c.unit.c_str(), c.profile_value);
  }
  return b;
}

// The ballast state's spread from the held constants (an analysis's
// calibration, or BG at the profile's): the fit refitted with each held
// constant one of its sigmas up. The fit's own sigma assumes the held values
// exact; on 50 drawn HUGIN truths it covered the net buoyancy within 2 sigma
// on 13, with the spread on 49 (docs/decisions/model-check-calibration.md).
struct HeldSpread {
  double net_var = 0.0, x_var = 0.0, y_var = 0.0;
  std::vector<double> term_var;  // per accepted term, in its fit unit
};

HeldSpread heldSpread(const FitSetup& s, const std::vector<std::uint32_t>& fitRows, const std::vector<std::size_t>& accepted,
                      const Fit& fin) {
  const CheckModel& m = s.m;
  HeldSpread out;
  out.term_var.assign(accepted.size(), 0.0);
  const HeldShifts h = heldShifts(s, fitRows, accepted, fin.params);
  const double net0 = m.netBuoyancyKg(h.unshifted);
  const double x0 = units::mToMm(m.cgX(h.unshifted)), y0 = units::mToMm(m.cgY(h.unshifted));
  for (const Params& p : h.shifted) {
    for (std::size_t a = 0; a < accepted.size(); ++a)
      out.term_var[a] += std::pow(p.terms[accepted[a]] - h.unshifted.terms[accepted[a]], 2);
    out.net_var += std::pow(m.netBuoyancyKg(p) - net0, 2);
    if (m.hasCg()) {
      out.x_var += std::pow(units::mToMm(m.cgX(p)) - x0, 2);
      out.y_var += std::pow(units::mToMm(m.cgY(p)) - y0, 2);
    }
  }
  return out;
}

}  // namespace

void reportCalibration(const CheckModel& m, const Fit& fin, ModelCheckResult& R) {
  R.calibration.clear();
  for (const CalibrationConstant& k : m.calibrationConstants()) {
    CalibrationValue c;
    c.id = k.id;
    c.unit = k.unit;
    c.label = k.label;
    c.value = fin.params.nuisance[k.index] * k.display_scale;
    // A held constant's fit sigma is the holding prior's, not a measurement.
    c.sigma = k.held_sigma > 0.0 ? k.held_sigma : fin.sigma[k.index] * k.display_scale;
    c.profile_value = k.profile_value;
    c.prior_sigma = k.prior_sigma;
    c.from_analysis = k.from_analysis;
    c.identified = c.sigma < 0.5 * c.prior_sigma;
    // Far from the profile: more than 3 of its own sigmas and more than half
    // the prior's (a small but certain difference is not worth a word).
    const double d = std::abs(c.value - c.profile_value);
    if (d > 3.0 * c.sigma && d > 0.5 * c.prior_sigma) c.finding = calibrationWords(c);
    R.calibration.push_back(c);
  }
  // Library terms the analysis calibrated (hull law, mass drift), as held; one 2 of
  // its sigmas from the profile's is reported as missing physics instead of
  // a finding here (held_term_findings.h).
  for (const HeldTermValue& h : m.heldTerms()) {
    CalibrationValue c;
    c.id = h.id;
    c.unit = h.unit;
    c.label = h.label;
    c.value = h.value;
    c.sigma = h.sigma;
    c.profile_value = h.profile_value;
    c.prior_sigma = h.prior_sigma;
    c.from_analysis = true;
    c.identified = c.sigma < 0.5 * c.prior_sigma;
    R.calibration.push_back(c);
  }
}

Fit jointRefit(const FitSetup& s, const std::vector<std::uint32_t>& fitRows, const std::vector<std::size_t>& accepted,
               const Params& base, std::vector<MissingPhysics>& found, ModelCheckResult& R) {
  const CheckModel& m = s.m;
  const auto& lib = termLibrary();
  Params st = base;
  for (std::size_t a : accepted) st.terms[a] = R.accepted[a];
  const Fit fin = fit(s, fitRows, accepted, st);
  R.final_params = fin.params;
  R.accepted = TermValues{};
  for (std::size_t a : accepted) R.accepted[a] = fin.params.terms[a];
  const HeldSpread held = heldSpread(s, fitRows, accepted, fin);
  for (auto& mp : found) {
    const std::size_t term = *findTerm(mp.id);
    const auto pos = std::find(accepted.begin(), accepted.end(), term) - accepted.begin();
    mp.profile_value = m.profileTermValue(term);
    mp.value = mp.profile_value + fin.params.terms[term] * lib[term].display_scale;
    mp.sigma = fin.sigma[s.nN + pos] * lib[term].display_scale;
    mp.sigma = std::max(mp.sigma, mp.split_half_sigma);  // model_check.h: the structure's share
    mp.calibration_sigma = std::sqrt(held.term_var[static_cast<std::size_t>(pos)]) * std::abs(lib[term].display_scale);
    mp.sigma = std::hypot(mp.sigma, mp.calibration_sigma);
  }
  for (int j = 0; j < s.nN; ++j) {
    R.nuisance.push_back(fin.params.nuisance[j]);
    R.nuisance_sigma.push_back(fin.sigma[j]);
  }
  reportCalibration(m, fin, R);
  R.net_buoyancy_kg = m.netBuoyancyKg(fin.params);
  {
    // Sigma of the reported net buoyancy by finite differences over the nuisance.
    double var = 0.0;
    for (int j = 0; j < s.nN; ++j) {
      Params q = fin.params;
      q.nuisance[j] += fin.sigma[j];
      const double d = m.netBuoyancyKg(q) - R.net_buoyancy_kg;
      var += d * d;
    }
    R.net_buoyancy_sigma_kg = std::sqrt(var);
  }
  R.net_buoyancy_sigma_kg = std::sqrt(R.net_buoyancy_sigma_kg * R.net_buoyancy_sigma_kg + held.net_var);
  if (m.hasCg()) {
    R.has_cg = true;
    R.cg_x_mm = units::mToMm(m.cgX(fin.params));
    R.cg_y_mm = units::mToMm(m.cgY(fin.params));
    double vx = 0.0, vy = 0.0;
    for (int j = 0; j < s.nN; ++j) {
      Params q = fin.params;
      q.nuisance[j] += fin.sigma[j];
      vx += std::pow(units::mToMm(m.cgX(q)) - R.cg_x_mm, 2);
      vy += std::pow(units::mToMm(m.cgY(q)) - R.cg_y_mm, 2);
    }
    R.cg_x_sigma_mm = std::sqrt(vx + held.x_var);
    R.cg_y_sigma_mm = std::sqrt(vy + held.y_var);
  }
  return fin;
}

}  // namespace auv::discrepancy::detail
