// Min/max-per-pixel decimation, tested without widgets against brute force.
#include "plot/min_max_decimation.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <random>

namespace auv::ui {
namespace {

struct Data {
  std::vector<double> t, v;
};

Data noisySine(std::size_t n, unsigned seed = 7) {
  Data d;
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.3);
  for (std::size_t i = 0; i < n; ++i) {
    d.t.push_back(static_cast<double>(i) * 0.1);
    d.v.push_back(std::sin(static_cast<double>(i) * 1e-4) * 10.0 + noise(rng));
  }
  return d;
}

}  // namespace

TEST(Decimation, FewSamplesPassThroughUnchanged) {
  const std::vector<double> t = {0, 1, 2, 3, 4}, v = {5, 4, 3, 2, 1};
  const auto out = decimateMinMax(t, v, 0, 4, 100);
  ASSERT_EQ(out.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(out[i].x, t[i]);
    EXPECT_EQ(out[i].y, v[i]);
  }
}

TEST(Decimation, KeepsEveryColumnsExtremaInTimeOrder) {
  const Data d = noisySine(100000);
  const double x0 = 1000.0, x1 = 6000.0;
  const std::size_t buckets = 500;
  const auto out = decimateMinMax(d.t, d.v, x0, x1, buckets);
  // At most two per column plus one neighbour each side.
  EXPECT_LE(out.size(), 2 * buckets + 2);
  EXPECT_GE(out.size(), buckets);
  for (std::size_t i = 1; i < out.size(); ++i) EXPECT_LT(out[i - 1].x, out[i].x);
  // Brute force: every column's min and max are among the output points.
  const double w = (x1 - x0) / buckets;
  std::size_t checked = 0;
  for (std::size_t b = 0; b < buckets; ++b) {
    const double c0 = x0 + w * static_cast<double>(b), c1 = x0 + w * static_cast<double>(b + 1);
    const bool last = b + 1 == buckets;  // the last column runs to x1 inclusive
    auto inColumn = [&](double x) { return x >= c0 && (last ? x <= x1 : x < c1); };
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < d.t.size(); ++i) {
      if (!inColumn(d.t[i])) continue;
      lo = std::min(lo, d.v[i]);
      hi = std::max(hi, d.v[i]);
    }
    if (!std::isfinite(lo)) continue;
    bool has_lo = false, has_hi = false;
    for (const auto& p : out) {
      if (!inColumn(p.x)) continue;
      has_lo |= p.y == lo;
      has_hi |= p.y == hi;
    }
    EXPECT_TRUE(has_lo && has_hi) << "column " << b;
    ++checked;
  }
  EXPECT_EQ(checked, buckets);
  // The line runs to the edges: one sample just outside on each side.
  EXPECT_LT(out.front().x, x0);
  EXPECT_GT(out.back().x, x1);
}

TEST(Decimation, SpikeOfOneSampleSurvives) {
  Data d = noisySine(200000);
  d.v[123456] = 1000.0;  // a single bad sample a full render would show
  const auto out = decimateMinMax(d.t, d.v, d.t.front(), d.t.back(), 800);
  bool found = false;
  for (const auto& p : out) found |= p.y == 1000.0 && p.x == d.t[123456];
  EXPECT_TRUE(found);
}

TEST(Decimation, UnsampledRowsAreSkipped) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> t = {0, 1, 2, 3, 4, 5}, v = {nan, 1, nan, nan, 2, nan};
  const auto out = decimateMinMax(t, v, 0.5, 4.5, 10);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].y, 1);
  EXPECT_EQ(out[1].y, 2);
}

TEST(Decimation, EmptyOrDegenerateInputGivesNothing) {
  const std::vector<double> none;
  EXPECT_TRUE(decimateMinMax(none, none, 0, 1, 10).empty());
  const std::vector<double> t = {0, 1}, v = {1, 2};
  EXPECT_TRUE(decimateMinMax(t, v, 1, 1, 10).empty());
  EXPECT_TRUE(decimateMinMax(t, v, 0, 1, 0).empty());
}

TEST(Decimation, DayOfTenHertzInFewMilliseconds) {
  // 24 h at 10 Hz: the "stays fluid" case (notes: ~3.5 ms per 1e6).
  const Data d = noisySine(864000);
  const auto start = std::chrono::steady_clock::now();
  std::size_t n = 0;
  for (int k = 0; k < 10; ++k) n += decimateMinMax(d.t, d.v, d.t.front(), d.t.back(), 1000).size();
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / 10.0;
  EXPECT_GT(n, 0u);
  EXPECT_LT(ms, 10.0) << "decimating 864k samples took " << ms << " ms";
  std::printf("[ decimation ] 864k samples -> %zu points in %.2f ms\n", n / 10, ms);
}

}  // namespace auv::ui

#include "plot/nice_axis.h"

namespace auv::ui {

TEST(NiceAxis, TicksOnOneTwoFiveAndCoverTheData) {
  const NiceAxis a = niceAxis(0.3, 97.2);
  EXPECT_DOUBLE_EQ(a.step, 50.0);  // raw 24.2 -> 50
  EXPECT_DOUBLE_EQ(a.min, 0.0);
  EXPECT_DOUBLE_EQ(a.max, 100.0);
  EXPECT_EQ(a.ticks, 3);
  const NiceAxis b = niceAxis(-1.63, 2.41);  // raw 1.01 -> 2
  EXPECT_DOUBLE_EQ(b.step, 2.0);
  EXPECT_DOUBLE_EQ(b.min, -2.0);
  EXPECT_DOUBLE_EQ(b.max, 4.0);
  EXPECT_EQ(b.ticks, 4);
  const NiceAxis c = niceAxis(5.0, 5.0);  // flat line: still a span
  EXPECT_LT(c.min, 5.0);
  EXPECT_GT(c.max, 5.0);
  for (double lo : {-700.0, -3.3, 0.0, 0.01, 12.5}) {
    for (double span : {1e-3, 0.7, 13.0, 4000.0}) {
      const NiceAxis n = niceAxis(lo, lo + span);
      EXPECT_LE(n.min, lo);
      EXPECT_GE(n.max, lo + span - 1e-9 * span);
      EXPECT_GE(n.ticks, 2);
      EXPECT_LE(n.ticks, 11);
    }
  }
}

}  // namespace auv::ui
