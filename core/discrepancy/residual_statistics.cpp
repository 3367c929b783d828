#include "discrepancy/residual_statistics.h"

#include <algorithm>
#include <cmath>

#include "common/units.h"

namespace auv::discrepancy::detail {

namespace {

double mad(std::vector<double> v) {
  if (v.empty()) return kNaN;
  auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  const double med = *mid;
  for (double& x : v) x = std::abs(x - med);
  std::nth_element(v.begin(), mid, v.end());
  return 1.4826 * *mid;
}

}  // namespace

double channelFloor(Channel c) {
  switch (c) {
    case Channel::kVerticalVelocity: return 1e-3;
    case Channel::kDepth: return 0.01;
    case Channel::kPitch:
    case Channel::kRoll: return units::degToRad(0.01);
    case Channel::kSpeed: return 1e-3;
    default: return 1e-6;
  }
}

std::vector<double> robustSigmas(const FitSetup& s, const std::vector<double>& r) {
  std::vector<double> sig(s.C);
  for (std::size_t c = 0; c < s.C; ++c) {
    std::vector<double> v;
    for (std::size_t i = c; i < r.size(); i += s.C)
      if (std::isfinite(r[i])) v.push_back(r[i]);
    const double m = mad(v);
    sig[c] = std::max(std::isfinite(m) ? m : 1.0, channelFloor(s.eq[c]));
  }
  return sig;
}

std::vector<double> effectiveShares(const FitSetup& s, const SampleTable& S, const std::vector<double>& r) {
  std::vector<double> out(s.C, 1.0);
  for (std::size_t c = 0; c < s.C; ++c) {
    double num = 0.0, den = 0.0, mean = 0.0, n = 0.0;
    for (std::size_t i = 0; i < S.size(); ++i)
      if (std::isfinite(r[i * s.C + c])) {
        mean += r[i * s.C + c];
        n += 1.0;
      }
    if (n < 3) continue;
    mean /= n;
    for (std::size_t i = 0; i + 1 < S.size(); ++i) {
      const double a = r[i * s.C + c], b = r[(i + 1) * s.C + c];
      if (S.block[i] != S.block[i + 1] || !std::isfinite(a) || !std::isfinite(b)) continue;
      num += (a - mean) * (b - mean);
    }
    for (std::size_t i = 0; i < S.size(); ++i) {
      const double a = r[i * s.C + c];
      if (std::isfinite(a)) den += (a - mean) * (a - mean);
    }
    const double rho = den > 0 ? std::clamp(num / den, 0.0, 0.999) : 0.0;
    out[c] = (1.0 - rho) / (1.0 + rho);
  }
  return out;
}

double rmsOf(double sse, double n) { return n > 0 ? std::sqrt(sse / n) : kNaN; }

std::vector<double> channelColumn(const std::vector<double>& v, std::size_t C, std::size_t c) {
  std::vector<double> out(v.size() / C);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = v[i * C + c];
  return out;
}

void rmsPerChannel(const std::vector<double>& v, std::size_t C, std::vector<double>& sse, std::vector<double>& n) {
  sse.assign(C, 0.0);
  n.assign(C, 0.0);
  for (std::size_t i = 0; i < v.size(); ++i)
    if (std::isfinite(v[i])) {
      sse[i % C] += v[i] * v[i];
      n[i % C] += 1.0;
    }
}

}  // namespace auv::discrepancy::detail
