#include "discrepancy/savitzky_golay.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace auv::discrepancy {

Smoothed savitzkyGolay(const std::vector<double>& y, double dt, int half, int order, int min_half) {
  const std::size_t n = y.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Smoothed s{std::vector<double>(n, nan), std::vector<double>(n, nan), std::vector<double>(n, nan)};
  min_half = std::max(1, min_half);
  // Coefficients per half width m: rows 0, 1, 2 of the pseudo-inverse of the
  // Vandermonde matrix in k = -m..m give the value and k-derivatives at 0.
  struct Coef {
    std::vector<double> c0, c1, c2;
  };
  std::vector<Coef> coef(static_cast<std::size_t>(std::max(half, 0)) + 1);
  for (int m = min_half; m <= half; ++m) {
    const int deg = std::clamp(std::min(order, 2 * m), 2, 6);
    Eigen::MatrixXd V(2 * m + 1, deg + 1);
    for (int k = -m; k <= m; ++k)
      for (int p = 0; p <= deg; ++p) V(k + m, p) = std::pow(static_cast<double>(k), p);
    const Eigen::MatrixXd pinv = (V.transpose() * V).ldlt().solve(V.transpose());
    Coef c;
    for (int k = 0; k <= 2 * m; ++k) {
      c.c0.push_back(pinv(0, k));
      c.c1.push_back(pinv(1, k) / dt);
      c.c2.push_back(2.0 * pinv(2, k) / (dt * dt));
    }
    coef[static_cast<std::size_t>(m)] = std::move(c);
  }
  // Largest symmetric window without NaN from the runs of valid samples.
  std::vector<int> left(n), right(n);
  int run = 0;
  for (std::size_t i = 0; i < n; ++i) {
    run = std::isfinite(y[i]) ? run + 1 : 0;
    left[i] = run - 1;
  }
  run = 0;
  for (std::size_t i = n; i-- > 0;) {
    run = std::isfinite(y[i]) ? run + 1 : 0;
    right[i] = run - 1;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(y[i])) continue;
    const int m = std::min({half, left[i], right[i]});
    if (m < min_half) continue;
    const Coef& c = coef[static_cast<std::size_t>(m)];
    double a = 0, b = 0, d = 0;
    for (int k = -m; k <= m; ++k) {
      const double v = y[static_cast<std::size_t>(static_cast<long>(i) + k)];
      const auto j = static_cast<std::size_t>(k + m);
      a += c.c0[j] * v;
      b += c.c1[j] * v;
      d += c.c2[j] * v;
    }
    s.value[i] = a;
    s.d1[i] = b;
    s.d2[i] = d;
  }
  return s;
}

}  // namespace auv::discrepancy
