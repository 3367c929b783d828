#include "analysis/glider_flight.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "analysis/statistics.h"
#include "common/units.h"

namespace auv::analysis {

namespace {


double volumeFactor(const GliderFlightConstants& c, double p_dbar, double T_degC) {
  return (1.0 - c.compressibility_per_dbar * p_dbar) *
         (1.0 + c.thermal_expansion_per_degC * (T_degC - c.reference_temperature_degC));
}

// h(alpha) = a alpha tan(alpha + phi) - Cd0 - Cd1 alpha^2 for phi = |pitch|
// is -Cd0 at alpha = 0 and grows without bound towards alpha = pi/2 - phi, so
// a root always exists; the smallest one is the physical (unstalled) glide,
// the one gliderflight's fixed-point iteration converges to.
double solveAlphaAbs(double a, double Cd1, double Cd0, double phi) {
  if (!(phi > 0.0)) return 0.0;
  const double top = 0.5 * std::numbers::pi - phi;
  auto h = [&](double x) { return a * x * std::tan(x + phi) - Cd0 - Cd1 * x * x; };
  double lo = 0.0, hi = 0.0;
  const double step = std::min(0.002, 0.25 * top);
  for (double x = step; x < top; x += step) {
    if (h(x) > 0.0) {
      hi = x;
      lo = x - step;
      break;
    }
  }
  if (hi == 0.0) return top;
  for (int i = 0; i < 60 && hi - lo > 1e-13; ++i) {
    const double mid = 0.5 * (lo + hi);
    (h(mid) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// Newton's method from a nearby root (continuation along the table), with
// the bracketing solver as fallback.
double newtonAlphaAbs(double a, double Cd1, double Cd0, double phi, double start) {
  const double top = 0.5 * std::numbers::pi - phi;
  double x = start;
  for (int i = 0; i < 30; ++i) {
    const double tn = std::tan(x + phi);
    const double h = a * x * tn - Cd0 - Cd1 * x * x;
    const double dh = a * tn + a * x * (1.0 + tn * tn) - 2.0 * Cd1 * x;
    if (!(dh > 0.0)) break;
    const double nx = x - h / dh;
    if (!(nx > 0.0 && nx < top)) break;
    if (std::abs(nx - x) < 1e-14) return nx;
    x = nx;
  }
  return solveAlphaAbs(a, Cd1, Cd0, phi);
}

// alpha(|theta|) tabulated for one Cd0 over the pitch range in use (the fit
// evaluates thousands of samples per Cd0).
class AlphaTable {
 public:
  static constexpr double kStep = units::degToRad(0.05);
  AlphaTable(const GliderFlightConstants& c, double Cd0, double phi_min, double phi_max) : c_(&c), Cd0_(Cd0) {
    lo_ = std::max(units::degToRad(0.5), phi_min - kStep);
    const double hi = std::min(units::degToRad(85.0), phi_max + kStep);
    const auto n = static_cast<std::size_t>(std::max(0.0, (hi - lo_) / kStep)) + 2;
    a_.resize(n);
    a_[0] = solveAlphaAbs(c.lift_slope_per_rad, c.induced_drag_per_rad2, Cd0, lo_);
    for (std::size_t i = 1; i < n; ++i)
      a_[i] = newtonAlphaAbs(c.lift_slope_per_rad, c.induced_drag_per_rad2, Cd0, lo_ + static_cast<double>(i) * kStep,
                             a_[i - 1]);
  }
  double Cd0() const { return Cd0_; }
  double alphaAbs(double phi) const {
    const double x = (phi - lo_) / kStep;
    if (!(x >= 0.0) || x >= static_cast<double>(a_.size() - 1))
      return solveAlphaAbs(c_->lift_slope_per_rad, c_->induced_drag_per_rad2, Cd0_, phi);
    const auto i = static_cast<std::size_t>(x);
    const double f = x - static_cast<double>(i);
    return a_[i] + f * (a_[i + 1] - a_[i]);
  }

 private:
  const GliderFlightConstants* c_;
  double Cd0_;
  double lo_ = 0.0;
  std::vector<double> a_;
};

double glideW(const GliderFlightConstants& c, double V0, double Cd0, double alpha_abs_fn_result, double theta,
              const GlideSample& s) {
  if (c.form == GlideForm::kSeaglider) {
    const double V = V0 * volumeFactor(c, s.pressure_dbar, s.temperature_degC) + s.pump_m3;
    return seagliderVerticalSpeed(c, units::g0 * (s.density_kgm3 * V - c.mass_kg), theta, Cd0);
  }
  const double alpha = std::copysign(alpha_abs_fn_result, theta);
  const double path = theta + alpha;
  const double V = V0 * volumeFactor(c, s.pressure_dbar, s.temperature_degC) + s.pump_m3;
  const double FB = units::g0 * (s.density_kgm3 * V - c.mass_kg);
  const double denom = Cd0 + c.induced_drag_per_rad2 * alpha * alpha;
  const double U2 = 2.0 * FB * std::sin(path) / (s.density_kgm3 * c.wing_area_m2 * denom);
  if (!(U2 > 0.0)) return 0.0;
  return std::sqrt(U2) * std::sin(path);
}

double correctedPitch(const GliderFlightConstants& c, double pitch) { return c.pitch_scale * pitch + c.pitch_offset_rad; }

struct Problem {
  const GliderFlightConstants& c;
  const ReferenceState& ref;
  std::vector<const GlideSample*> s;  // samples in use
  double phi_min = 0.0, phi_max = 0.0;  // |corrected pitch| range of the samples
  mutable std::vector<AlphaTable> cache;  // the few Cd0 values in use at once

  void setRange() {
    phi_min = std::numeric_limits<double>::infinity();
    phi_max = 0.0;
    for (const GlideSample* x : s) {
      const double phi = std::abs(correctedPitch(c, x->pitch_rad));
      phi_min = std::min(phi_min, phi);
      phi_max = std::max(phi_max, phi);
    }
  }
  const AlphaTable& table(double Cd0) const {
    for (const AlphaTable& t : cache)
      if (t.Cd0() == Cd0) return t;
    if (cache.size() >= 4) cache.erase(cache.begin());
    cache.emplace_back(c, Cd0, phi_min, phi_max);
    return cache.back();
  }

  // Residuals model - observed; returns the sum of squares.
  double residuals(double nb, double Cd0, std::vector<double>& r) const {
    const AlphaTable& table = this->table(Cd0);
    const double V0 = hullVolumeForNetBuoyancy(c, ref, nb);
    r.resize(s.size());
    double ss = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const double th = correctedPitch(c, s[i]->pitch_rad);
      const double w = glideW(c, V0, Cd0, table.alphaAbs(std::abs(th)), th, *s[i]);
      r[i] = w - s[i]->w_obs_mps;
      ss += r[i] * r[i];
    }
    return ss;
  }
};

struct LmResult {
  double nb, Cd0, cost;
  bool converged;
  Eigen::Matrix2d JtJ;
};

LmResult levenbergMarquardt(const Problem& p, double nb, double Cd0, int max_iter) {
  std::vector<double> r, r1, r2;
  double cost = p.residuals(nb, Cd0, r);
  double lambda = 1e-3;
  bool converged = false;
  Eigen::Matrix2d JtJ = Eigen::Matrix2d::Identity();
  const double dnb = 1e-4, dcd = 1e-5;
  for (int it = 0; it < max_iter; ++it) {
    p.residuals(nb + dnb, Cd0, r1);
    p.residuals(nb, Cd0 + dcd, r2);
    Eigen::Vector2d g = Eigen::Vector2d::Zero();
    JtJ.setZero();
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Eigen::Vector2d J((r1[i] - r[i]) / dnb, (r2[i] - r[i]) / dcd);
      JtJ += J * J.transpose();
      g += J * r[i];
    }
    bool improved = false;
    for (int tries = 0; tries < 12; ++tries) {
      Eigen::Matrix2d A = JtJ;
      A.diagonal() *= 1.0 + lambda;
      const Eigen::Vector2d step = -A.ldlt().solve(g);
      const double nb_new = nb + step[0];
      const double cd_new = std::max(1e-4, Cd0 + step[1]);
      std::vector<double> rn;
      const double c_new = p.residuals(nb_new, cd_new, rn);
      if (c_new < cost) {
        const double rel = (cost - c_new) / std::max(cost, 1e-300);
        nb = nb_new;
        Cd0 = cd_new;
        cost = c_new;
        r.swap(rn);
        lambda = std::max(lambda / 3.0, 1e-9);
        improved = true;
        if (rel < 1e-10 || (std::abs(step[0]) < 1e-7 && std::abs(step[1]) < 1e-8)) converged = true;
        break;
      }
      lambda *= 4.0;
    }
    if (!improved) {
      converged = true;  // no descent direction left: at the minimum to working precision
      break;
    }
    if (converged) break;
  }
  return {nb, Cd0, cost, converged, JtJ};
}

}  // namespace

double seagliderVerticalSpeed(const GliderFlightConstants& c, double FB, double theta, double hd_b) {
  // basestation's hydro_model iteration (Eriksen et al. 2001, eqs. 7-8) on
  // magnitudes: glide angle g = |pitch| + alpha, both in degrees.
  if (!(FB * theta > 0.0) || !(hd_b > 0.0)) return 0.0;
  const double B = std::abs(FB), phi = units::radToDeg(std::abs(theta));
  const double l2 = c.hull_length_m * c.hull_length_m, a = c.hd_a_per_deg, cc = c.hd_c_per_deg2, s = c.hd_s;
  double g = 45.0;
  double q = std::pow(B / (l2 * hd_b), 1.0 / (1.0 + s));
  bool flying = false;
  for (int j = 0; j < 40; ++j) {
    const double qPrev = q;
    const double scaled = std::pow(qPrev, -s);
    const double tg = std::tan(units::degToRad(g));
    const double D = a * a * tg * tg * scaled / (4.0 * hd_b * cc);
    if (!(D > 1.0)) return 0.0;
    const double r = std::sqrt(1.0 - 1.0 / D);
    q = B * std::sin(units::degToRad(g)) * scaled / (2.0 * l2 * hd_b) * (1.0 + r);
    const double alpha = a * tg / (2.0 * cc) * (1.0 - r);
    g = phi + alpha;
    if (!(g < 89.9)) return 0.0;
    flying = true;
    if (j >= 2 && std::abs(q - qPrev) <= 1e-9 * q) break;
  }
  if (!flying || !(q > 0.0)) return 0.0;
  return std::copysign(std::sqrt(2.0 * q / c.rho0_kgm3) * std::sin(units::degToRad(g)), theta);
}

double steadyAngleOfAttackNear(const GliderFlightConstants& c, double phi_abs_rad, double Cd0, double start) {
  return newtonAlphaAbs(c.lift_slope_per_rad, c.induced_drag_per_rad2, Cd0, phi_abs_rad, start);
}

double steadyAngleOfAttack(const GliderFlightConstants& c, double pitch_rad, double Cd0) {
  const double th = correctedPitch(c, pitch_rad);
  return std::copysign(solveAlphaAbs(c.lift_slope_per_rad, c.induced_drag_per_rad2, Cd0, std::abs(th)), th);
}

double hullVolumeForNetBuoyancy(const GliderFlightConstants& c, const ReferenceState& ref, double nb_kg) {
  return (c.mass_kg + nb_kg) / (ref.density_kgm3 * volumeFactor(c, ref.pressure_dbar, ref.temperature_degC));
}

double steadyGlideVerticalSpeed(const GliderFlightConstants& c, const ReferenceState& ref, double nb_kg, double Cd0,
                                const GlideSample& s) {
  const double th = correctedPitch(c, s.pitch_rad);
  const double a = solveAlphaAbs(c.lift_slope_per_rad, c.induced_drag_per_rad2, Cd0, std::abs(th));
  return glideW(c, hullVolumeForNetBuoyancy(c, ref, nb_kg), Cd0, a, th, s);
}

GliderFitResult fitSteadyGlide(std::span<const GlideSample> samples, const GliderFlightConstants& c,
                               const ReferenceState& ref, const GliderFitOptions& o) {
  GliderFitResult res;
  Problem p{c, ref, {}, 0.0, 0.0, {}};
  const std::size_t stride = std::max<std::size_t>(1, (samples.size() + o.max_samples - 1) / std::max<std::size_t>(1, o.max_samples));
  for (std::size_t i = 0; i < samples.size(); i += stride) p.s.push_back(&samples[i]);
  p.setRange();
  res.samples = p.s.size();
  if (p.s.size() < 10) {
    res.message = "fewer than 10 steady-glide samples";
    return res;
  }
  std::vector<double> r;
  res.rms_start_mps = std::sqrt(p.residuals(0.0, o.Cd0_start, r) / static_cast<double>(p.s.size()));

  // Coarse scan over nb so that LM starts on the right side of a sign
  // change (with the wrong sign the model cannot dive or climb and is flat).
  double best_nb = 0.0, best = std::numeric_limits<double>::infinity();
  for (double nb = -2.0; nb <= 2.0 + 1e-9; nb += 0.025) {
    const double cst = p.residuals(nb, o.Cd0_start, r);
    if (cst < best) {
      best = cst;
      best_nb = nb;
    }
  }
  const LmResult lm = levenbergMarquardt(p, best_nb, o.Cd0_start, o.max_iterations);
  res.converged = lm.converged;
  if (!lm.converged) res.message = "Levenberg-Marquardt did not converge in " + std::to_string(o.max_iterations) + " iterations";
  res.net_buoyancy_kg = lm.nb;
  res.Cd0 = lm.Cd0;
  res.hull_volume_m3 = hullVolumeForNetBuoyancy(c, ref, lm.nb);
  const double cost = p.residuals(lm.nb, lm.Cd0, r);
  const double n = static_cast<double>(p.s.size());
  res.rms_mps = std::sqrt(cost / n);

  // AR(1) inflation of the least-squares covariance, lag pairs within blocks.
  MeanAccumulator acc;
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (i > 0 && p.s[i]->block != p.s[i - 1]->block) acc.endBlock();
    acc.add(r[i]);
  }
  const MeanEstimate re = acc.result();
  res.residual_lag1 = re.lag1;
  const double s2 = cost / std::max(1.0, n - 2.0);
  const Eigen::Matrix2d cov = lm.JtJ.inverse() * s2 * (n / std::max(1.0, re.n_eff));
  res.sigma_ar1_kg = std::sqrt(std::max(0.0, cov(0, 0)));
  res.Cd0_sigma = std::sqrt(std::max(0.0, cov(1, 1)));

  // Jackknife over groups of consecutive glide segments.
  std::vector<int> blocks;
  for (const GlideSample* s : p.s)
    if (blocks.empty() || blocks.back() != s->block) blocks.push_back(s->block);
  const std::size_t G = std::min(o.max_jackknife_groups, blocks.size());
  res.groups = G;
  if (G >= 4) {
    std::vector<int> group_of_block_index(blocks.size());
    for (std::size_t b = 0; b < blocks.size(); ++b) group_of_block_index[b] = static_cast<int>(b * G / blocks.size());
    std::vector<int> group(p.s.size());
    std::size_t bi = 0;
    for (std::size_t i = 0; i < p.s.size(); ++i) {
      if (i > 0 && p.s[i]->block != p.s[i - 1]->block) ++bi;
      group[i] = group_of_block_index[bi];
    }
    std::vector<double> est;
    for (std::size_t g = 0; g < G; ++g) {
      Problem q{c, ref, {}, p.phi_min, p.phi_max, {}};
      for (std::size_t i = 0; i < p.s.size(); ++i)
        if (group[i] != static_cast<int>(g)) q.s.push_back(p.s[i]);
      if (q.s.size() < 10) continue;
      est.push_back(levenbergMarquardt(q, lm.nb, lm.Cd0, 20).nb);
    }
    if (est.size() >= 4) {
      double m = 0.0;
      for (double e : est) m += e;
      m /= static_cast<double>(est.size());
      double ss = 0.0;
      for (double e : est) ss += (e - m) * (e - m);
      const double k = static_cast<double>(est.size());
      res.sigma_jackknife_kg = std::sqrt((k - 1.0) / k * ss);
    }
  }
  res.net_buoyancy_sigma_kg = std::max(res.sigma_ar1_kg, res.sigma_jackknife_kg);
  return res;
}

}  // namespace auv::analysis
