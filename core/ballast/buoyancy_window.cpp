#include "ballast/buoyancy_window.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "ballast/mass_quanta.h"

namespace auv::ballast {
namespace {

// Below a milligram two classes are the same: numerical noise only.
constexpr double kSameKg = 1e-6;

bool noWorse(const BuoyancyClass& a, const BuoyancyClass& b) {
  if (a.negative_kg > b.negative_kg + kSameKg) return false;
  if (a.negative_kg < b.negative_kg - kSameKg) return true;
  return a.band_violation_kg <= b.band_violation_kg + kSameKg;
}

}  // namespace

std::vector<std::int64_t> reachableTotals(const std::vector<PointOptions>& points) {
  // Kits are usually on a coarse grid (0.1 kg and up): then a flag per grid
  // step is far cheaper than sorting every pairwise sum.
  std::int64_t step = 0, lo = 0, hi = 0;
  for (const PointOptions& p : points) {
    for (std::int64_t m : p.mass_q) step = std::gcd(step, m - p.mass_q.front());
    step = std::gcd(step, p.mass_q.front());
    lo += p.mass_q.front();
    hi += p.mass_q.back();
  }
  if (step > 0 && (hi - lo) / step < 4'000'000) {
    const std::size_t cells = static_cast<std::size_t>((hi - lo) / step) + 1;
    std::vector<char> reach(cells, 0), next(cells, 0);
    reach[0] = 1;  // offset by the sum of the points' lowest masses
    std::int64_t span = 0;
    for (const PointOptions& p : points) {
      std::fill(next.begin(), next.end(), 0);
      const std::size_t used = static_cast<std::size_t>(span / step) + 1;
      for (std::int64_t m : p.mass_q) {
        const std::size_t shift = static_cast<std::size_t>((m - p.mass_q.front()) / step);
        for (std::size_t i = 0; i < used; ++i) next[i + shift] |= reach[i];
      }
      span += p.mass_q.back() - p.mass_q.front();
      reach.swap(next);
    }
    std::vector<std::int64_t> sums;
    for (std::size_t i = 0; i < cells; ++i)
      if (reach[i]) sums.push_back(lo + static_cast<std::int64_t>(i) * step);
    return sums;
  }
  std::vector<std::int64_t> sums{0};
  for (const PointOptions& p : points) {
    std::vector<std::int64_t> next;
    next.reserve(sums.size() * p.count());
    for (std::int64_t s : sums)
      for (std::int64_t m : p.mass_q) next.push_back(s + m);
    std::sort(next.begin(), next.end());
    next.erase(std::unique(next.begin(), next.end()), next.end());
    sums = std::move(next);
  }
  return sums;
}

BuoyancyClass classify(double net_kg, double net_lo_kg, double net_hi_kg) {
  BuoyancyClass c;
  c.negative_kg = std::max(0.0, -net_kg);
  c.band_violation_kg = net_kg < net_lo_kg ? net_lo_kg - net_kg : (net_kg > net_hi_kg ? net_kg - net_hi_kg : 0.0);
  return c;
}

TotalWindow windowNoWorseThan(const std::vector<std::int64_t>& totals, double net_now_kg, double net_lo_kg,
                              double net_hi_kg, const BuoyancyClass& limit) {
  TotalWindow w;
  w.lo_q = std::numeric_limits<std::int64_t>::max();
  w.hi_q = std::numeric_limits<std::int64_t>::min();
  w.best = limit;
  // The class is convex in the total, so the qualifying totals form an interval.
  for (std::int64_t t : totals) {
    if (noWorse(classify(net_now_kg - toKg(t), net_lo_kg, net_hi_kg), limit)) {
      w.lo_q = std::min(w.lo_q, t);
      w.hi_q = std::max(w.hi_q, t);
    }
  }
  return w;
}

TotalWindow continuousWindow(double net_now_kg, double net_lo_kg, double net_hi_kg, const BuoyancyClass& limit) {
  TotalWindow w;
  w.best = limit;
  double lo_kg = -1e9, hi_kg = 1e9;  // added total, kg
  if (limit.negative_kg > kSameKg) {
    hi_kg = net_now_kg + limit.negative_kg;  // no heavier than now
  } else {
    lo_kg = net_now_kg - net_hi_kg - limit.band_violation_kg;
    hi_kg = std::min(net_now_kg, net_now_kg - net_lo_kg + limit.band_violation_kg);
  }
  w.lo_q = static_cast<std::int64_t>(std::floor(lo_kg / kQuantumKg)) - 1;
  w.hi_q = static_cast<std::int64_t>(std::ceil(hi_kg / kQuantumKg)) + 1;
  return w;
}

TotalWindow bestWindow(const std::vector<std::int64_t>& totals, double net_now_kg, double net_lo_kg,
                       double net_hi_kg) {
  BuoyancyClass best{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (std::int64_t t : totals) {
    const BuoyancyClass c = classify(net_now_kg - toKg(t), net_lo_kg, net_hi_kg);
    if (c.negative_kg < best.negative_kg - kSameKg ||
        (c.negative_kg <= best.negative_kg + kSameKg && c.band_violation_kg < best.band_violation_kg)) {
      best = c;
    }
  }
  return windowNoWorseThan(totals, net_now_kg, net_lo_kg, net_hi_kg, best);
}

}  // namespace auv::ballast
