#include "analysis/statistics.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace auv::analysis {

double studentT975(double nu) {
  // Table for nu = 1..30 (Abramowitz & Stegun 26.10), interpolated in 1/nu,
  // which is nearly linear; above 30 the Cornish-Fisher series in 1/nu
  // (A&S 26.7.5) is accurate to 1e-4.
  static constexpr std::array<double, 30> kTable = {
      12.7062, 4.3027, 3.1824, 2.7764, 2.5706, 2.4469, 2.3646, 2.3060, 2.2622, 2.2281,
      2.2010,  2.1788, 2.1604, 2.1448, 2.1314, 2.1199, 2.1098, 2.1009, 2.0930, 2.0860,
      2.0796,  2.0739, 2.0687, 2.0639, 2.0595, 2.0555, 2.0518, 2.0484, 2.0452, 2.0423};
  if (!(nu >= 1.0)) nu = 1.0;
  if (nu <= 30.0) {
    const double lo = std::floor(nu);
    const auto i = static_cast<std::size_t>(lo) - 1;
    if (lo == nu || i + 1 >= kTable.size()) return kTable[i];
    const double w = (1.0 / lo - 1.0 / nu) / (1.0 / lo - 1.0 / (lo + 1.0));
    return kTable[i] + w * (kTable[i + 1] - kTable[i]);
  }
  const double z = 1.959963984540054;
  const double z2 = z * z, z3 = z2 * z, z5 = z3 * z2, z7 = z5 * z2;
  return z + (z3 + z) / (4.0 * nu) + (5.0 * z5 + 16.0 * z3 + 3.0 * z) / (96.0 * nu * nu) +
         (3.0 * z7 + 19.0 * z5 + 17.0 * z3 - 15.0 * z) / (384.0 * nu * nu * nu);
}

void MeanAccumulator::add(double x) {
  if (n_ == 0) shift_ = x;
  const double d = x - shift_;
  ++n_;
  s1_ += d;
  s2_ += d * d;
  if (open_.n > 0) {
    open_.pair_prod += prev_ * d;
    open_.pair_first += prev_;
    open_.pair_second += d;
    open_.diff2 += (d - prev_) * (d - prev_);
    ++open_.pairs;
  }
  prev_ = d;
  open_.s1 += d;
  open_.s2 += d * d;
  ++open_.n;
}

void MeanAccumulator::endBlock() {
  if (open_.n > 0) closed_.push_back(open_);
  open_ = {};
}

MeanEstimate MeanAccumulator::result(SeriesModel model) const {
  MeanEstimate e;
  e.n = n_;
  if (n_ == 0) return e;
  const double n = static_cast<double>(n_);
  const double m = s1_ / n;  // shifted mean
  e.mean = shift_ + m;
  e.blocks = closed_.size() + (open_.n > 0 ? 1 : 0);
  if (n_ == 1) {
    e.sd = 0.0;
    e.n_eff = 1.0;
    e.se = e.ci95 = std::numeric_limits<double>::infinity();
    return e;
  }
  const double ss = std::max(0.0, s2_ - s1_ * m);
  e.sd = std::sqrt(ss / (n - 1.0));
  // Pooled within-block lag-1 autocorrelation.
  double ss_within = 0.0, cov_within = 0.0, diff2 = 0.0;
  std::size_t n_within = 0, pairs = 0;
  auto visitLag = [&](const Block& b) {
    const double mb = b.s1 / static_cast<double>(b.n);
    ss_within += std::max(0.0, b.s2 - b.s1 * mb);
    n_within += b.n;
    cov_within += b.pair_prod - mb * (b.pair_first + b.pair_second) + mb * mb * static_cast<double>(b.pairs);
    pairs += b.pairs;
    diff2 += b.diff2;
  };
  for (const Block& b : closed_) visitLag(b);
  if (open_.n > 0) visitLag(open_);
  double r = 0.0;
  if (pairs > 0 && ss_within > 0.0)
    r = std::clamp((cov_within / static_cast<double>(pairs)) / (ss_within / static_cast<double>(n_within)), 0.0, 0.9999);
  e.lag1 = r;
  e.n_eff = std::clamp(n * (1.0 - r) / (1.0 + r), 1.0, n);
  double se = e.sd / std::sqrt(e.n_eff);
  double ci = studentT975(std::max(1.0, e.n_eff - 1.0)) * se;
  if (model == SeriesModel::kProfile) {
    const double noise_var = pairs > 0 ? 0.5 * diff2 / static_cast<double>(pairs) : e.sd * e.sd;
    e.n_eff = n;
    se = std::sqrt(noise_var / n);
    ci = studentT975(n - 1.0) * se;
  }

  // Between-block scatter: with three or more blocks, the block means must
  // agree within the interval, otherwise the interval widens to their spread.
  if (e.blocks >= 3) {
    double sw = 0.0, sw2 = 0.0, swd2 = 0.0;
    auto visit = [&](const Block& b) {
      const double w = static_cast<double>(b.n);
      const double dm = b.s1 / w - m;
      sw += w;
      sw2 += w * w;
      swd2 += w * dm * dm;
    };
    for (const Block& b : closed_) visit(b);
    if (open_.n > 0) visit(open_);
    const double k_eff = sw * sw / sw2;
    if (k_eff > 1.0 + 1e-9) {
      const double var_b = swd2 / sw * k_eff / (k_eff - 1.0);
      const double se_b = std::sqrt(var_b / k_eff);
      const double ci_b = studentT975(std::max(1.0, k_eff - 1.0)) * se_b;
      if (ci_b > ci) {
        ci = ci_b;
        se = se_b;
      }
    }
  }
  e.se = se;
  e.ci95 = ci;
  return e;
}

}  // namespace auv::analysis
