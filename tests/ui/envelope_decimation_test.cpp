// The min/max pyramid and the envelope decimation of very long series,
// against brute force (no widgets).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <random>

#include "plot/envelope_decimation.h"
#include "plot/min_max_pyramid.h"

namespace auv::ui {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Brute force over [lo, hi): earliest min and max, count, sum.
MinMaxPyramid::Summary scan(const std::vector<double>& v, std::size_t lo, std::size_t hi) {
  MinMaxPyramid::Summary s;
  for (std::size_t i = lo; i < hi; ++i) {
    if (!std::isfinite(v[i])) continue;
    if (s.count == 0) s.first = s.imin = s.imax = i;
    if (v[i] < v[s.imin]) s.imin = i;
    if (v[i] > v[s.imax]) s.imax = i;
    s.last = i;
    ++s.count;
    s.sum += v[i];
  }
  return s;
}

// 4 million samples at 1 s (1111 h) of a slow wave with noise, and one
// sample of 1000 at `spike`.
struct Series {
  std::vector<double> t, v;
};
Series longSeries(std::size_t n, std::size_t spike) {
  Series s;
  s.t.resize(n);
  s.v.resize(n);
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 0.5);
  for (std::size_t i = 0; i < n; ++i) {
    s.t[i] = static_cast<double>(i);
    s.v[i] = 50.0 * std::sin(static_cast<double>(i) * 2e-3) + noise(rng);
  }
  s.v[spike] = 1000.0;
  return s;
}

bool contains(const std::vector<PlotPoint>& pts, double x, double y) {
  for (const auto& p : pts)
    if (p.x == x && p.y == y) return true;
  return false;
}

}  // namespace

TEST(MinMaxPyramid, AnyRangeEqualsAScan) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  std::vector<double> v(70000);
  for (auto& x : v) x = std::round(u(rng));  // many ties: the earliest must win
  for (std::size_t i = 30000; i < 31000; ++i) v[i] = kNaN;  // a drop-out
  for (std::size_t i = 0; i < v.size(); i += 7) v[i] = kNaN;
  const MinMaxPyramid p(v);
  std::uniform_int_distribution<std::size_t> pos(0, v.size());
  for (int k = 0; k < 3000; ++k) {
    std::size_t lo = pos(rng), hi = pos(rng);
    if (lo > hi) std::swap(lo, hi);
    if (k % 3 == 0) hi = std::min(v.size(), lo + k % 300);  // short ranges too
    const auto a = p.query(v, lo, hi), b = scan(v, lo, hi);
    ASSERT_EQ(a.count, b.count) << lo << ".." << hi;
    EXPECT_EQ(a.imin, b.imin) << lo << ".." << hi;
    EXPECT_EQ(a.imax, b.imax) << lo << ".." << hi;
    EXPECT_EQ(a.first, b.first);
    EXPECT_EQ(a.last, b.last);
    EXPECT_NEAR(a.sum, b.sum, 1e-9 * (1.0 + std::abs(b.sum)));
  }
  // All NaN: nothing.
  EXPECT_EQ(p.query(v, 30100, 30900).count, 0u);
  EXPECT_EQ(p.query(v, 30100, 30900).imin, MinMaxPyramid::Summary::kNone);
}

TEST(EnvelopeDecimation, SparseColumnsDrawExactlyTheMinMaxLine) {
  const Series s = longSeries(200000, 123456);
  const MinMaxPyramid p(s.v);
  for (const auto& [x0, x1, buckets] : {std::tuple{0.0, 199999.0, 800}, std::tuple{1000.5, 6000.25, 500},
                                        std::tuple{123000.0, 124000.0, 900}, std::tuple{50.0, 120.0, 100}}) {
    const std::size_t b = static_cast<std::size_t>(buckets);
    const Envelope e = decimateEnvelope(s.t, s.v, p, x0, x1, b, 1e9);  // never dense
    const auto ref = decimateMinMax(s.t, s.v, x0, x1, b);
    EXPECT_FALSE(e.dense);
    EXPECT_TRUE(e.lower.empty() && e.upper.empty());
    ASSERT_EQ(e.line.size(), ref.size()) << x0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
      EXPECT_EQ(e.line[i].x, ref[i].x);
      EXPECT_EQ(e.line[i].y, ref[i].y);
    }
  }
}

TEST(EnvelopeDecimation, FourMillionSamplesKeepEveryColumnsExtremesAndTheSpikeAtAnyZoom) {
  const std::size_t n = 4'000'000, spike = 2'718'281;
  const Series s = longSeries(n, spike);
  const MinMaxPyramid p(s.v);
  const std::size_t buckets = 1000;  // a 1000 px wide plot
  const double x0 = s.t.front(), x1 = s.t.back();
  const auto start = std::chrono::steady_clock::now();
  const Envelope e = decimateEnvelope(s.t, s.v, p, x0, x1, buckets);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ envelope ] 4e6 samples -> %zu + %zu + %zu points in %.2f ms\n", e.line.size(), e.lower.size(),
              e.upper.size(), ms);
  // 4000 samples per column: the band with the mean line, each bounded by the width.
  ASSERT_TRUE(e.dense);
  for (const auto* line : {&e.line, &e.lower, &e.upper}) {
    EXPECT_GE(line->size(), buckets);
    EXPECT_LE(line->size(), buckets + 2);
  }
  // Every column's min is on the lower edge and its max on the upper edge,
  // and the mean line runs through the column's mean (brute force).
  const double w = (x1 - x0) / static_cast<double>(buckets);
  std::size_t i = 0;
  for (std::size_t b = 0; b < buckets; ++b) {
    const double edge = b + 1 == buckets ? x1 + 1.0 : x0 + w * static_cast<double>(b + 1);
    const std::size_t begin = i;
    while (i < n && s.t[i] < edge) ++i;
    const auto c = scan(s.v, begin, i);
    ASSERT_GT(c.count, 0u);
    EXPECT_EQ(e.lower[b].x, s.t[c.imin]) << b;
    EXPECT_EQ(e.lower[b].y, s.v[c.imin]) << b;
    EXPECT_EQ(e.upper[b].x, s.t[c.imax]) << b;
    EXPECT_EQ(e.upper[b].y, s.v[c.imax]) << b;
    EXPECT_NEAR(e.line[b].y, c.sum / static_cast<double>(c.count), 1e-9) << b;
  }
  EXPECT_TRUE(contains(e.upper, s.t[spike], 1000.0));
  EXPECT_LT(ms, 20.0);  // on the UI thread at every zoom step (measured ~0.5 ms)

  // Zoomed to 10 h around the spike (36 samples per column): still a band,
  // the spike on its upper edge, the neighbouring extremes from the data.
  const Envelope mid = decimateEnvelope(s.t, s.v, p, s.t[spike] - 18000.0, s.t[spike] + 18000.0, buckets);
  EXPECT_TRUE(mid.dense);
  EXPECT_LE(mid.upper.size(), buckets + 2);
  EXPECT_TRUE(contains(mid.upper, s.t[spike], 1000.0));
  // Zoomed to 10 min: every raw sample is back, the spike between its neighbours.
  const Envelope near = decimateEnvelope(s.t, s.v, p, s.t[spike] - 300.0, s.t[spike] + 300.0, buckets);
  EXPECT_FALSE(near.dense);
  EXPECT_EQ(near.line.size(), 601u + 2u);
  for (std::size_t k = spike - 300; k <= spike + 300; ++k) EXPECT_TRUE(contains(near.line, s.t[k], s.v[k])) << k;
}

}  // namespace auv::ui
