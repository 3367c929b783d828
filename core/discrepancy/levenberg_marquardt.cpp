#include "discrepancy/levenberg_marquardt.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace auv::discrepancy {

namespace {

Eigen::VectorXd clampTo(const LmProblem& p, Eigen::VectorXd x) {
  for (Eigen::Index j = 0; j < x.size(); ++j) x[j] = std::clamp(x[j], p.lower[j], p.upper[j]);
  return x;
}

// Forward differences, stepping inwards at an upper bound.
Eigen::MatrixXd forwardJacobian(const LmProblem& p, const Eigen::VectorXd& x, const Eigen::VectorXd& r0) {
  Eigen::MatrixXd J(r0.size(), x.size());
  Eigen::VectorXd r1;
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    double h = 1e-3 * p.scale[j];
    if (x[j] + h > p.upper[j]) h = -h;
    Eigen::VectorXd xp = x;
    xp[j] += h;
    p.residuals(xp, r1);
    J.col(j) = (r1 - r0) / h;
  }
  return J;
}

}  // namespace

Eigen::MatrixXd numericJacobian(const LmProblem& p, const Eigen::VectorXd& x) {
  Eigen::VectorXd r1, r2;
  p.residuals(x, r1);
  Eigen::MatrixXd J(r1.size(), x.size());
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    const double h = 1e-3 * p.scale[j];
    Eigen::VectorXd a = x, b = x;
    a[j] += h;
    b[j] -= h;
    p.residuals(a, r1);
    p.residuals(b, r2);
    J.col(j) = (r1 - r2) / (2.0 * h);
  }
  return J;
}

LmResult levenbergMarquardt(const LmProblem& p, const Eigen::VectorXd& x0, const LmOptions& o) {
  LmResult res;
  Eigen::VectorXd x = clampTo(p, x0);
  Eigen::VectorXd r;
  p.residuals(x, r);
  double cost = r.squaredNorm();
  double lambda = 1e-3;
  const Eigen::VectorXd S = p.scale;  // column scaling: work in x / scale
  Eigen::MatrixXd J = forwardJacobian(p, x, r);
  for (int it = 0; it < o.max_iterations; ++it) {
    res.iterations = it + 1;
    // A parameter whose bounds meet is held: it takes no step. Left in the
    // normal equations, the others' step assumes it moves, the clamp undoes
    // that, and the damped retries stall after a token step (the model check's
    // refits with a held constant shifted came back unmoved).
    Eigen::MatrixXd Js = J * S.asDiagonal();
    for (Eigen::Index j = 0; j < Js.cols(); ++j)
      if (!(p.upper[j] > p.lower[j])) Js.col(j).setZero();
    const Eigen::MatrixXd A0 = Js.transpose() * Js;
    const Eigen::VectorXd g = Js.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 12; ++tries) {
      Eigen::MatrixXd A = A0;
      for (Eigen::Index j = 0; j < A.rows(); ++j) A(j, j) += lambda * std::max(A0(j, j), 1e-12);
      const Eigen::VectorXd step = S.asDiagonal() * Eigen::VectorXd(-A.ldlt().solve(g));
      const Eigen::VectorXd xn = clampTo(p, x + step);
      Eigen::VectorXd rn;
      p.residuals(xn, rn);
      const double cn = rn.squaredNorm();
      if (std::isfinite(cn) && cn < cost) {
        const double rel = (cost - cn) / std::max(cost, 1e-300);
        x = xn;
        r.swap(rn);
        cost = cn;
        lambda = std::max(lambda / 3.0, 1e-9);
        improved = true;
        if (rel < o.relative_tolerance) res.converged = true;
        break;
      }
      lambda *= 4.0;
    }
    if (!improved) {
      res.converged = true;  // no descent left at working precision
      break;
    }
    if (res.converged) break;
    J = forwardJacobian(p, x, r);
  }
  J = forwardJacobian(p, x, r);
  res.x = x;
  res.cost = cost;
  res.r = r;
  res.JtJ = J.transpose() * J;
  return res;
}

}  // namespace auv::discrepancy
