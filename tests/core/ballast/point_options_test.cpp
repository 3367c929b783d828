// Per-point options and reachable totals against plain enumeration.
#include "ballast/point_options.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

#include "ballast/buoyancy_window.h"
#include "ballast/mass_quanta.h"

namespace auv::ballast {
namespace {

// Every count vector (after the move) a point can hold, by nested loops.
std::map<std::int64_t, std::pair<int, int>> enumerate(const std::vector<std::int64_t>& sizes,
                                                     const std::vector<int>& installed, std::int64_t cap) {
  std::map<std::int64_t, std::pair<int, int>> best;  // change -> (effort, removals)
  std::vector<int> after(sizes.size(), 0);
  std::int64_t inst_q = 0;
  for (std::size_t s = 0; s < sizes.size(); ++s) inst_q += installed[s] * sizes[s];
  auto rec = [&](auto&& self, std::size_t s, std::int64_t mass) -> void {
    if (mass > cap) return;
    if (s == sizes.size()) {
      int effort = 0, removals = 0;
      for (std::size_t k = 0; k < sizes.size(); ++k) {
        effort += std::abs(after[k] - installed[k]);
        removals += std::max(0, installed[k] - after[k]);
      }
      const auto key = mass - inst_q;
      const auto val = std::make_pair(effort, removals);
      if (!best.count(key) || val < best[key]) best[key] = val;
      return;
    }
    for (int c = 0; mass + c * sizes[s] <= cap; ++c) {
      after[s] = c;
      self(self, s + 1, mass + c * sizes[s]);
    }
  };
  rec(rec, 0, 0);
  return best;
}

TEST(PointOptions, HuginKitEmptyPoint) {
  // 1.2 / 2.4 / 4.8 kg into 40 kg: every multiple of 1.2 kg up to 39.6 kg.
  const PointOptions o = pointOptions({1, 0, 0}, {12000, 24000, 48000}, {}, toQuanta(40.0));
  ASSERT_EQ(o.count(), 34u);
  EXPECT_EQ(o.mass_q.front(), 0);
  EXPECT_EQ(o.mass_q.back(), toQuanta(39.6));
  // 39.6 = 8 x 4.8 + 1 x 1.2 (9 pieces); 3.6 = 2.4 + 1.2 (2 pieces)
  EXPECT_EQ(o.effort.back(), 9);
  EXPECT_EQ(std::vector<int>(o.deltaOf(33), o.deltaOf(33) + 3), (std::vector<int>{1, 0, 8}));
  EXPECT_EQ(o.effort[3], 2);
}

TEST(PointOptions, OverCapacityMustRemove) {
  // 3 x 4.8 kg installed, capacity 10 kg: at least 4.4 kg must come out.
  const PointOptions o = pointOptions({0, 0, 0}, {12000, 24000, 48000}, {0, 0, 3}, toQuanta(10.0));
  EXPECT_EQ(o.mass_q.front(), -toQuanta(14.4));
  EXPECT_EQ(o.mass_q.back(), -toQuanta(4.8));
}

TEST(PointOptions, MatchesEnumerationOnRandomKits) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + static_cast<int>(rng() % 3);
    std::vector<std::int64_t> sizes;
    for (int s = 0; s < n; ++s) sizes.push_back(1000 * (1 + static_cast<std::int64_t>(rng() % 12)));
    std::sort(sizes.begin(), sizes.end());
    sizes.erase(std::unique(sizes.begin(), sizes.end()), sizes.end());
    std::vector<int> inst;
    for (std::size_t s = 0; s < sizes.size(); ++s) inst.push_back(static_cast<int>(rng() % 3));
    const std::int64_t cap = 1000 * static_cast<std::int64_t>(rng() % 30);
    const auto expected = enumerate(sizes, inst, cap);
    const PointOptions o = pointOptions({0, 0, 0}, sizes, inst, cap);
    ASSERT_EQ(o.count(), expected.size()) << "trial " << trial;
    std::size_t i = 0;
    for (const auto& [m, ev] : expected) {
      EXPECT_EQ(o.mass_q[i], m);
      EXPECT_EQ(o.effort[i], ev.first);
      EXPECT_EQ(o.removals[i], ev.second);
      std::int64_t sum = 0;
      for (std::size_t s = 0; s < sizes.size(); ++s) {
        EXPECT_GE(o.deltaOf(i)[s], -inst[s]);  // never more out than in
        sum += o.deltaOf(i)[s] * sizes[s];
      }
      EXPECT_EQ(sum, m);
      ++i;
    }
  }
}

TEST(ReachableTotals, GridAndSortPathsAgreeWithPairwiseSums) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<PointOptions> pts;
    const int n = 1 + static_cast<int>(rng() % 4);
    for (int p = 0; p < n; ++p) {
      // Odd sizes (in 0.1 g) defeat the coarse grid on some trials.
      const std::int64_t a = 500 + static_cast<std::int64_t>(rng() % 9000), b = a + 1 + static_cast<std::int64_t>(rng() % 9000);
      pts.push_back(pointOptions({0, 0, 0}, {a, b}, {static_cast<int>(rng() % 2), 0}, 25000));
    }
    std::vector<std::int64_t> naive{0};
    for (const auto& p : pts) {
      std::vector<std::int64_t> next;
      for (auto s : naive)
        for (auto m : p.mass_q) next.push_back(s + m);
      std::sort(next.begin(), next.end());
      next.erase(std::unique(next.begin(), next.end()), next.end());
      naive = next;
    }
    EXPECT_EQ(reachableTotals(pts), naive) << "trial " << trial;
  }
  // A span of more than 4 million grid steps takes the sorting path.
  const std::vector<PointOptions> wide = {pointOptions({0, 0, 0}, {4999}, {}, 5'000'000),
                                          pointOptions({0, 0, 0}, {7001}, {}, 5'000'000)};
  std::vector<std::int64_t> naive;
  for (auto a : wide[0].mass_q)
    for (auto b : wide[1].mass_q) naive.push_back(a + b);
  std::sort(naive.begin(), naive.end());
  naive.erase(std::unique(naive.begin(), naive.end()), naive.end());
  EXPECT_EQ(reachableTotals(wide), naive);
}

}  // namespace
}  // namespace auv::ballast
