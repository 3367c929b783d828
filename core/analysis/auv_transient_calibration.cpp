#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "analysis/steady_solution.h"

namespace auv::analysis::detail {
namespace {

// Jacobian of the transient residuals by forward differences, steps a
// hundredth of each parameter's current sigma.
Eigen::MatrixXd transientJacobian(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& f, const Eigen::VectorXd& p, const Eigen::VectorXd& r0,
                                  const Eigen::MatrixXd& cov) {
  Eigen::MatrixXd J(r0.size(), p.size());
  for (Eigen::Index k = 0; k < p.size(); ++k) {
    const double h = 0.01 * std::sqrt(std::max(0.0, cov(k, k)));
    // The replay flies each window's buoyancy from the profile's hull law
    // and mass: the buoyancy-law groups do not enter it (saves replays).
    if (!(h > 1e-12) || k >= kCompressibility) {
      J.col(k).setZero();
      continue;
    }
    Eigen::VectorXd q = p;
    q(k) += h;
    J.col(k) = (f(q) - r0) / h;
  }
  return J;
}

}  // namespace

// Joint output-error fit (Levenberg-Marquardt) of the transients with the
// steady rows and the priors as pseudo-observations, from the steady answer.
// The transient information is divided by its chi2 per residual times the
// AR(1) factor (1 + rho) / (1 - rho) of its residuals, so model error and
// correlated samples widen the posterior instead of narrowing it.
void fitTransients(const Solved& s, const TransientResiduals& tr, double steady_inflation,
                   const Eigen::MatrixXd& prior_info, SteadyCalibration& out) {
  const auto& f = tr.residuals;
  const Eigen::Index nd = s.n_data;
  Eigen::MatrixXd A = s.At;  // steady rows scaled by their inflation, then the priors
  Eigen::VectorXd b = s.bt;
  A.topRows(nd) /= std::sqrt(steady_inflation);
  b.head(nd) /= std::sqrt(steady_inflation);
  Eigen::VectorXd p = s.p;
  Eigen::VectorXd rt = f(p);
  if (rt.size() == 0) return;
  auto cost = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& r) { return (A * q - b).squaredNorm() + r.squaredNorm(); };
  double c = cost(p, rt), lambda = 1e-2;
  Eigen::MatrixXd scale_cov = out.cov;
  Eigen::MatrixXd Jt = transientJacobian(f, p, rt, scale_cov);
  for (int it = 0, pass = 0; it < 16; ++it) {
    const Eigen::MatrixXd H = A.transpose() * A + Jt.transpose() * Jt;
    const Eigen::VectorXd g = A.transpose() * (A * p - b) + Jt.transpose() * rt;
    bool accepted = false;
    double c_new = c;
    for (int tries = 0; tries < 6 && !accepted; ++tries) {
      Eigen::MatrixXd Hl = H;
      Hl.diagonal() += lambda * H.diagonal();
      const Eigen::VectorXd dp = -Hl.ldlt().solve(g);
      const Eigen::VectorXd pn = p + dp;
      const Eigen::VectorXd rn = f(pn);
      c_new = cost(pn, rn);
      if (std::isfinite(c_new) && c_new < c) {
        p = pn;
        rt = rn;
        accepted = true;
        lambda = std::max(1e-6, lambda / 10);
      } else {
        lambda *= 10;
      }
    }
    if (!accepted) break;
    const double gain = (c - c_new) / c;
    c = c_new;
    scale_cov = (H).inverse();
    Jt = transientJacobian(f, p, rt, scale_cov);
    if (gain < 1e-5 || it == 7) {
      // Variance components: each channel's sigma from its own misfit at
      // this optimum (a channel the model follows worse weighs less), then
      // the fit again from here.
      if (pass++ > 0 || !tr.reweight) break;
      tr.reweight(p);
      rt = f(p);
      c = cost(p, rt);
      lambda = 1e-2;
      Jt = transientJacobian(f, p, rt, scale_cov);
    }
  }
  const auto n = static_cast<double>(rt.size());
  const double chi2 = rt.squaredNorm() / n;
  double num = 0.0;
  for (Eigen::Index i = 1; i < rt.size(); ++i) num += rt(i) * rt(i - 1);
  const double rho = std::clamp(num / std::max(1e-30, rt.squaredNorm()), 0.0, 0.99);
  const double inflation = std::max(1.0, chi2 * (1 + rho) / (1 - rho));
  // Consistency with the steady legs alone (whose coverage is honest): the
  // joint estimate of net buoyancy and CG x may move from theirs by what
  // the transients add, Var(d) = C_steady - C_joint; a larger move is
  // model error in the transients, and their information is divided by it.
  const Eigen::MatrixXd cov_steady = out.cov;
  double inflation_used = inflation;
  Eigen::MatrixXd cov_j = (s.data_info / steady_inflation + prior_info + Jt.transpose() * Jt / inflation).inverse();
  for (int round = 0; round < 4; ++round) {
    double worst = 0.0;
    for (int k : {static_cast<int>(kNet), static_cast<int>(kXg)}) {
      const double d = p(k) - s.p(k);
      const double var = std::max(cov_steady(k, k) - cov_j(k, k), 1e-6 * cov_steady(k, k));
      worst = std::max(worst, d * d / var);
    }
    if (worst <= 1.0) break;
    inflation_used *= worst;
    cov_j = (s.data_info / steady_inflation + prior_info + Jt.transpose() * Jt / inflation_used).inverse();
  }
  out.p = p;
  out.cov = cov_j;
  // Linearised jackknife over the windows: without window i the optimum
  // moves by (H - J_i'J_i)^-1 J_i' r_i. Their spread is model error the
  // residual statistics cannot see (every window fitted well, but each to
  // its own parameters); it is added to the posterior covariance.
  const Eigen::MatrixXd H = A.transpose() * A + Jt.transpose() * Jt;
  const auto ng = static_cast<Eigen::Index>(tr.group_ends.size());
  if (ng >= 3) {
    std::vector<Eigen::VectorXd> d;
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(p.size());
    Eigen::Index begin = 0;
    for (Eigen::Index end : tr.group_ends) {
      const Eigen::MatrixXd Ji = Jt.middleRows(begin, end - begin);
      const Eigen::VectorXd gi = Ji.transpose() * rt.segment(begin, end - begin);
      d.push_back((H - Ji.transpose() * Ji).ldlt().solve(gi));
      mean += d.back() / static_cast<double>(ng);
      begin = end;
    }
    Eigen::MatrixXd jk = Eigen::MatrixXd::Zero(p.size(), p.size());
    for (const Eigen::VectorXd& di : d) jk += (di - mean) * (di - mean).transpose();
    jk *= static_cast<double>(ng - 1) / static_cast<double>(ng);
    // n - 1 degrees of freedom: widen to the Student t quantile of 2 sigma.
    static constexpr double kT975[] = {12.71, 4.30, 3.18, 2.78, 2.57, 2.45, 2.36, 2.31, 2.26, 2.23, 2.20, 2.18, 2.16, 2.14};
    const double t = ng - 1 <= 14 ? kT975[ng - 2] : 1.96 + 2.5 / static_cast<double>(ng - 1);
    jk *= (t / 1.96) * (t / 1.96);
    out.cov += jk;
    out.transient_jackknife_net_sigma_n = std::sqrt(std::max(0.0, jk(kNet, kNet)));
  }
  out.transient_net_sigma_n = std::sqrt(std::max(0.0, out.cov(kNet, kNet)));
  // Windows that disagree more than they inform (the jackknife's spread
  // larger than their information) would widen what the steady segments
  // already know: the steady answer stands.
  if (out.cov(kNet, kNet) > cov_steady(kNet, kNet) || out.cov(kXg, kXg) > cov_steady(kXg, kXg)) {
    out.p = s.p;
    out.cov = cov_steady;
    out.transients_kept = false;
  } else {
    out.transients_kept = true;
  }
  out.transient_residuals = static_cast<std::size_t>(rt.size());
  out.transient_chi2_per_residual = chi2;
  out.transient_inflation = inflation_used;
}

}  // namespace auv::analysis::detail
