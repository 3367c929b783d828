#include "plot/min_max_pyramid.h"

#include <cmath>
#include <stdexcept>

namespace auv::ui {
namespace {

using Summary = MinMaxPyramid::Summary;

// A summary under construction, with the extremes' values at hand.
struct Acc {
  Summary s;
  double vmin = 0.0, vmax = 0.0;
  // Appends a range just right of the one held: strict comparisons keep the
  // earliest extreme on ties.
  void add(double lo, std::size_t imin, double hi, std::size_t imax, std::size_t first, std::size_t last,
           std::size_t count, double sum) {
    if (count == 0) return;
    if (s.count == 0) {
      s = Summary{imin, imax, first, last, count, sum};
      vmin = lo;
      vmax = hi;
      return;
    }
    if (lo < vmin) {
      vmin = lo;
      s.imin = imin;
    }
    if (hi > vmax) {
      vmax = hi;
      s.imax = imax;
    }
    s.last = last;
    s.count += count;
    s.sum += sum;
  }
  void sample(std::span<const double> v, std::size_t i) {
    if (std::isfinite(v[i])) add(v[i], i, v[i], i, i, i, 1, v[i]);
  }
};

}  // namespace

MinMaxPyramid::MinMaxPyramid(std::span<const double> v) : n_(v.size()) {
  if (n_ >= kEmpty) throw std::length_error("MinMaxPyramid: more than 4e9 samples");
  // Level 0 from the samples, each further level from the one below.
  std::size_t block = kFan;
  while (block <= n_) {
    std::vector<Node> level(n_ / block);
    for (std::size_t j = 0; j < level.size(); ++j) {
      Acc a;
      if (levels_.empty()) {
        for (std::size_t i = j * kFan; i < (j + 1) * kFan; ++i) a.sample(v, i);
      } else {
        for (std::size_t c = j * kFan; c < (j + 1) * kFan; ++c) {
          const Node& k = levels_.back()[c];
          a.add(k.vmin, k.imin, k.vmax, k.imax, k.first, k.last, k.count, k.sum);
        }
      }
      if (a.s.count > 0) {
        level[j] = Node{a.vmin, a.vmax, a.s.sum, static_cast<std::uint32_t>(a.s.imin),
                        static_cast<std::uint32_t>(a.s.imax), static_cast<std::uint32_t>(a.s.first),
                        static_cast<std::uint32_t>(a.s.last), static_cast<std::uint32_t>(a.s.count)};
      }
    }
    levels_.push_back(std::move(level));
    block *= kFan;
  }
}

MinMaxPyramid::Summary MinMaxPyramid::query(std::span<const double> v, std::size_t lo, std::size_t hi) const {
  Acc a;
  hi = std::min(hi, std::min(n_, v.size()));
  std::size_t i = lo;
  while (i < hi) {
    // The largest whole block that starts at i and ends by hi.
    int level = -1;
    std::size_t block = kFan;
    for (std::size_t k = 0; k < levels_.size(); ++k, block *= kFan) {
      if (i % block != 0 || i + block > hi) break;
      level = static_cast<int>(k);
    }
    if (level < 0) {
      a.sample(v, i);
      ++i;
      continue;
    }
    std::size_t size = kFan;
    for (int k = 0; k < level; ++k) size *= kFan;
    const Node& node = levels_[static_cast<std::size_t>(level)][i / size];
    a.add(node.vmin, node.imin, node.vmax, node.imax, node.first, node.last, node.count, node.sum);
    i += size;
  }
  return a.s;
}

}  // namespace auv::ui
