#include "ballast/point_options.h"

#include <algorithm>
#include <cstdlib>

#include "ballast/mass_quanta.h"

namespace auv::ballast {
namespace {

// One dynamic-programming layer per piece size: the cheapest way to reach
// each mass change with the sizes so far, and how we got there.
struct Node {
  std::int64_t mass_q = 0;
  int effort = 0;
  int removals = 0;
  int prev = -1;  // index in the previous layer
  int count = 0;  // signed pieces of this layer's size
};

bool cheaper(const Node& a, const Node& b) {
  if (a.effort != b.effort) return a.effort < b.effort;
  return a.removals < b.removals;
}

}  // namespace

PointOptions pointOptions(const Eigen::Vector3d& position_m, const std::vector<std::int64_t>& sizes_q,
                          const std::vector<int>& installed, std::int64_t capacity_q) {
  const std::size_t n = sizes_q.size();
  auto inst = [&](std::size_t s) { return s < installed.size() ? installed[s] : 0; };
  std::int64_t installed_q = 0;
  for (std::size_t s = 0; s < n; ++s) installed_q += inst(s) * sizes_q[s];
  const std::int64_t max_change = capacity_q - installed_q;  // may be negative (over capacity now)

  // What the sizes not yet processed can still take away; partial states
  // that can no longer end within capacity are dropped early.
  std::vector<std::int64_t> rest_remove(n + 1, 0);
  for (std::size_t s = n; s-- > 0;) rest_remove[s] = rest_remove[s + 1] + inst(s) * sizes_q[s];

  std::vector<std::vector<Node>> layers(n + 1);
  layers[0].push_back(Node{});
  for (std::size_t s = 0; s < n; ++s) {
    const int lo = -inst(s);
    const int hi = static_cast<int>(std::max<std::int64_t>(0, capacity_q / sizes_q[s])) - inst(s);
    const std::vector<Node>& prev = layers[s];
    std::vector<Node> next;
    for (std::size_t i = 0; i < prev.size(); ++i) {
      for (int k = lo; k <= hi; ++k) {
        const std::int64_t m = prev[i].mass_q + k * sizes_q[s];
        if (m - rest_remove[s + 1] > max_change) break;  // k only grows from here
        next.push_back(Node{m, prev[i].effort + std::abs(k), prev[i].removals + std::max(0, -k),
                            static_cast<int>(i), k});
      }
    }
    std::stable_sort(next.begin(), next.end(), [](const Node& a, const Node& b) { return a.mass_q < b.mass_q; });
    std::vector<Node>& kept = layers[s + 1];
    for (const Node& nd : next) {
      if (!kept.empty() && kept.back().mass_q == nd.mass_q) {
        if (cheaper(nd, kept.back())) kept.back() = nd;
      } else {
        kept.push_back(nd);
      }
    }
  }

  PointOptions out;
  out.position_m = position_m;
  out.sizes = static_cast<int>(n);
  for (const Node& nd : layers[n]) {
    if (nd.mass_q > max_change) continue;
    out.mass_q.push_back(nd.mass_q);
    out.mass_kg.push_back(toKg(nd.mass_q));
    out.effort.push_back(nd.effort);
    out.removals.push_back(nd.removals);
    const std::size_t at = out.delta.size();
    out.delta.resize(at + n, 0);
    const Node* cur = &nd;
    for (std::size_t s = n; s-- > 0;) {
      out.delta[at + s] = cur->count;
      cur = &layers[s][static_cast<std::size_t>(cur->prev)];
    }
  }
  return out;
}

}  // namespace auv::ballast
