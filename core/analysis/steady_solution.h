#pragma once
// The steady legs' linear solution inside the calibration (auv_calibration.cpp),
// shared with the transients' joint fit (auv_transient_calibration.cpp).
#include <Eigen/Dense>

#include "analysis/auv_calibration.h"

namespace auv::analysis::detail {

struct Solved {
  bool ok = false;
  Eigen::VectorXd p;
  Eigen::MatrixXd cov, data_info;
  Eigen::MatrixXd At;  // whitened data rows, then prior rows
  Eigen::VectorXd bt;
  double chi2_data = 0.0;
  int n_data = 0;
};

// Joint output-error fit (Levenberg-Marquardt) of the transients with the
// steady rows and the priors as pseudo-observations, from the steady answer s;
// steady_inflation scales the steady rows' variance. Sets out.p, out.cov
// (the steady ones when the transients knew less) and the transient fields.
void fitTransients(const Solved& s, const TransientResiduals& tr, double steady_inflation,
                   const Eigen::MatrixXd& prior_info, SteadyCalibration& out);

}  // namespace auv::analysis::detail
