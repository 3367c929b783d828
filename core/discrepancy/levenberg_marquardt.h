#pragma once
// A small Levenberg-Marquardt for the nonlinear refinement of the selected
// parameters: forward-difference Jacobian on scaled variables, Marquardt's
// diagonal damping, box bounds by projection. Enough for a handful of
// parameters and tens of thousands of residuals.
#include <functional>

#include <Eigen/Core>

namespace auv::discrepancy {

struct LmProblem {
  // Weighted residuals at x (fixed length; a residual that cannot be
  // computed should be 0, not NaN).
  std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& r)> residuals;
  Eigen::VectorXd scale;  // typical size of each parameter (finite-difference step = 1e-3 scale)
  Eigen::VectorXd lower, upper;
};

struct LmOptions {
  int max_iterations = 40;
  double relative_tolerance = 1e-9;
};

struct LmResult {
  Eigen::VectorXd x;
  double cost = 0.0;       // sum of squared residuals
  Eigen::MatrixXd JtJ;     // at the solution, in the unscaled parameters
  Eigen::VectorXd r;       // residuals at the solution
  int iterations = 0;
  bool converged = false;
};

LmResult levenbergMarquardt(const LmProblem& problem, const Eigen::VectorXd& x0, const LmOptions& options = {});

// Jacobian of the residuals at x (central differences, step 1e-3 scale).
Eigen::MatrixXd numericJacobian(const LmProblem& problem, const Eigen::VectorXd& x);

}  // namespace auv::discrepancy
