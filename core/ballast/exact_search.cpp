#include "ballast/exact_search.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ballast/mass_quanta.h"

namespace auv::ballast {
namespace {

constexpr double kEffortWeight = 1048576.0;  // effort first, removals second, in one number

double distance(double v, double lo, double hi) { return v < lo ? lo - v : (v > hi ? v - hi : 0.0); }

}  // namespace

ExactSearch::ExactSearch(const TrimModel& model, const TrimTargets& targets, const std::vector<PointOptions>& points)
    : model_(model), targets_(targets) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const PointOptions& o = points[i];
    Pt p;
    p.r = o.position_m;
    p.opt = &o;
    p.lo_q = o.mass_q.front();
    p.hi_q = o.mass_q.back();
    p.lo_kg = toKg(p.lo_q);
    p.hi_kg = toKg(p.hi_q);
    p.min_effort = *std::min_element(o.effort.begin(), o.effort.end());
    p.min_removals = *std::min_element(o.removals.begin(), o.removals.end());
    p.original = i;
    pts_.push_back(p);
  }
  // Fore to aft: the points still free deep in the tree then sit close
  // together in x, so the pitch bound (the first priority after buoyancy)
  // tightens early.
  std::stable_sort(pts_.begin(), pts_.end(), [](const Pt& a, const Pt& b) { return a.r.x() > b.r.x(); });

  const std::size_t n = pts_.size();
  rest_lo_q_.assign(n + 1, 0);
  rest_hi_q_.assign(n + 1, 0);
  rest_effort_.assign(n + 1, 0);
  rest_removals_.assign(n + 1, 0);
  rest_lo_kg_.assign(n + 1, 0.0);
  rest_val0_.assign(n + 1, {0.0, 0.0, 0.0});
  for (std::size_t k = n; k-- > 0;) {
    rest_lo_q_[k] = rest_lo_q_[k + 1] + pts_[k].lo_q;
    rest_hi_q_[k] = rest_hi_q_[k + 1] + pts_[k].hi_q;
    rest_effort_[k] = rest_effort_[k + 1] + pts_[k].min_effort;
    rest_removals_[k] = rest_removals_[k + 1] + pts_[k].min_removals;
    rest_lo_kg_[k] = rest_lo_kg_[k + 1] + pts_[k].lo_kg;
    for (int a = 0; a < 3; ++a) rest_val0_[k][static_cast<std::size_t>(a)] = rest_val0_[k + 1][static_cast<std::size_t>(a)] + pts_[k].lo_kg * pts_[k].r[a];
  }
  order_.resize(n + 1);
  for (std::size_t k = 0; k <= n; ++k) {
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<std::size_t>& ord = order_[k][static_cast<std::size_t>(axis)];
      for (std::size_t j = k; j < n; ++j) ord.push_back(j);
      std::stable_sort(ord.begin(), ord.end(),
                       [&](std::size_t a, std::size_t b) { return pts_[a].r[axis] < pts_[b].r[axis]; });
    }
  }
  buffers_.resize(n);
}

std::pair<double, double> ExactSearch::lpRange(std::size_t level, int axis, double a_kg, double b_kg) const {
  // min and max of sum m_j c_j over lo_j <= m_j <= hi_j, a <= sum m_j <= b
  // (fractional knapsack: take the cheapest coefficients first).
  const std::vector<std::size_t>& ord = order_[level][static_cast<std::size_t>(axis)];
  const double sum0 = rest_lo_kg_[level], val0 = rest_val0_[level][static_cast<std::size_t>(axis)];
  double s = sum0, lo = val0;
  for (std::size_t j : ord) {
    const double c = pts_[j].r[axis], cap = pts_[j].hi_kg - pts_[j].lo_kg;
    const double add = std::clamp(c < 0 ? b_kg - s : a_kg - s, 0.0, cap);
    s += add;
    lo += add * c;
  }
  s = sum0;
  double hi = val0;
  for (auto it = ord.rbegin(); it != ord.rend(); ++it) {
    const double c = pts_[*it].r[axis], cap = pts_[*it].hi_kg - pts_[*it].lo_kg;
    const double add = std::clamp(c > 0 ? b_kg - s : a_kg - s, 0.0, cap);
    s += add;
    hi += add * c;
  }
  return {lo, hi};
}

ExactSearch::Bound ExactSearch::boundFromBox(const double lo[3], const double hi[3]) const {
  double p_min = -std::numbers::pi, p_max = std::numbers::pi;
  double r_min = -std::numbers::pi, r_max = std::numbers::pi;
  if (lo[2] > 0) {  // upright is stable everywhere in the box: both angles are monotone
    p_min = std::atan2(-hi[0], hi[0] > 0 ? lo[2] : hi[2]);
    p_max = std::atan2(-lo[0], lo[0] < 0 ? lo[2] : hi[2]);
    r_min = std::atan2(lo[1], lo[1] < 0 ? lo[2] : hi[2]);
    r_max = std::atan2(hi[1], hi[1] > 0 ? lo[2] : hi[2]);
  }
  const TrimTargets& t = targets_;
  Bound out;
  out.pitch = std::max({0.0, t.pitch_lo - p_max, p_min - t.pitch_hi});
  out.roll = std::max({0.0, t.roll_lo - r_max, r_min - t.roll_hi});
  const double dp = distance(t.pitch_centre, p_min, p_max) / t.pitch_scale;
  const double dr = distance(t.roll_centre, r_min, r_max) / t.roll_scale;
  out.residual = dp * dp + dr * dr;
  const double mp = (0.5 * (p_min + p_max) - t.pitch_centre) / t.pitch_scale;
  const double mr = (0.5 * (r_min + r_max) - t.roll_centre) / t.roll_scale;
  out.heuristic = mp * mp + mr * mr;
  return out;
}

ExactSearch::Bound ExactSearch::bound(std::size_t level, std::int64_t fixed_q, const Eigen::Vector3d& d) const {
  double lo[3], hi[3];
  if (level + 1 == pts_.size()) {
    // One point left: its mass is an interval, d moves along its position.
    const Pt& p = pts_[level];
    const double m0 = std::max(p.lo_kg, toKg(phase_.total_lo_q - fixed_q));
    const double m1 = std::min(p.hi_kg, toKg(phase_.total_hi_q - fixed_q));
    for (int axis = 0; axis < 3; ++axis) {
      const double a = d[axis] + m0 * p.r[axis], b = d[axis] + m1 * p.r[axis];
      lo[axis] = std::min(a, b);
      hi[axis] = std::max(a, b);
    }
  } else {
    const double a = toKg(phase_.total_lo_q - fixed_q), b = toKg(phase_.total_hi_q - fixed_q);
    for (int axis = 0; axis < 3; ++axis) {
      const auto [l, h] = lpRange(level, axis, a, b);
      lo[axis] = d[axis] + l;
      hi[axis] = d[axis] + h;
    }
  }
  return boundFromBox(lo, hi);
}

ExactSearch::Value ExactSearch::goalValue(const TrimScores& s, int effort, int removals) const {
  switch (phase_.goal) {
    case Goal::Pitch: return {s.pitch_violation, 0.0};
    case Goal::Roll: return {s.roll_violation, 0.0};
    case Goal::ResidualThenEffort: break;
  }
  return {residualStep(s.residual), effort * kEffortWeight + removals};
}

ExactSearch::Value ExactSearch::goalBound(const Bound& b, int effort, int removals, std::size_t level) const {
  switch (phase_.goal) {
    case Goal::Pitch: return {b.pitch, 0.0};
    case Goal::Roll: return {b.roll, 0.0};
    case Goal::ResidualThenEffort: break;
  }
  return {residualStep(b.residual), (effort + rest_effort_[level]) * kEffortWeight + removals + rest_removals_[level]};
}

bool ExactSearch::better(const Value& a, const Value& b) const {
  return a.primary < b.primary || (a.primary == b.primary && a.secondary < b.secondary);
}

bool ExactSearch::mayImprove(const Value& bound) const {
  // A node whose bound cannot be strictly better than the incumbent holds
  // nothing better (ties keep the incumbent, the first found).
  return !have_best_ || better(bound, best_value_);
}

bool ExactSearch::admissible(const Bound& b) const {
  return b.pitch <= phase_.pitch_max && b.roll <= phase_.roll_max && b.residual <= phase_.residual_max;
}

void ExactSearch::leaves(std::int64_t fixed_q, const Eigen::Vector3d& d, int effort, int removals) {
  const std::size_t level = pts_.size() - 1;
  const Pt& p = pts_[level];
  const PointOptions& o = *p.opt;
  const auto first = std::lower_bound(o.mass_q.begin(), o.mass_q.end(), phase_.total_lo_q - fixed_q);
  const auto last = std::upper_bound(o.mass_q.begin(), o.mass_q.end(), phase_.total_hi_q - fixed_q);
  for (auto it = first; it != last; ++it) {
    const std::size_t i = static_cast<std::size_t>(it - o.mass_q.begin());
    ++stats_.leaves;
    const Eigen::Vector3d dd = d + o.mass_kg[i] * p.r;
    // Only what the objective reads (pitch_x, roll); the full outcome of the
    // winner is recomputed by evaluate().
    TrimOutcome out;
    out.pitch_x_rad = std::atan2(-dd.x(), dd.z());
    out.roll_rad = std::atan2(dd.y(), dd.z());
    const TrimScores s = scoreOutcome(out, targets_);
    if (s.pitch_violation > phase_.pitch_max || s.roll_violation > phase_.roll_max ||
        s.residual > phase_.residual_max) {
      continue;
    }
    const Value v = goalValue(s, effort + o.effort[i], removals + o.removals[i]);
    if (!have_best_ || better(v, best_value_)) {
      have_best_ = true;
      best_value_ = v;
      path_[level] = static_cast<int>(i);
      best_path_ = path_;
    }
  }
}

void ExactSearch::dfs(std::size_t level, std::int64_t fixed_q, const Eigen::Vector3d& d, int effort, int removals) {
  if (stats_.limited) return;
  if (phase_.node_limit > 0 && stats_.nodes >= phase_.node_limit) {
    stats_.limited = true;
    return;
  }
  if (level + 1 == pts_.size()) {
    leaves(fixed_q, d, effort, removals);
    return;
  }
  ++stats_.nodes;
  const Pt& p = pts_[level];
  const PointOptions& o = *p.opt;
  const auto first = std::lower_bound(o.mass_q.begin(), o.mass_q.end(),
                                      phase_.total_lo_q - fixed_q - rest_hi_q_[level + 1]);
  const auto last = std::upper_bound(o.mass_q.begin(), o.mass_q.end(),
                                     phase_.total_hi_q - fixed_q - rest_lo_q_[level + 1]);
  std::vector<Child>& kids = buffers_[level];
  kids.clear();
  for (auto it = first; it != last; ++it) {
    const std::size_t i = static_cast<std::size_t>(it - o.mass_q.begin());
    const Bound b = bound(level + 1, fixed_q + o.mass_q[i], d + o.mass_kg[i] * p.r);
    if (!admissible(b)) continue;
    const Value key = goalBound(b, effort + o.effort[i], removals + o.removals[i], level + 1);
    if (!mayImprove(key)) continue;
    kids.push_back({key, b.heuristic, i});
  }
  // Most promising first: an early good incumbent is what makes the bounds bite.
  std::sort(kids.begin(), kids.end(), [](const Child& a, const Child& b) {
    if (a.key.primary != b.key.primary) return a.key.primary < b.key.primary;
    if (a.heuristic != b.heuristic) return a.heuristic < b.heuristic;
    return a.key.secondary < b.key.secondary;
  });
  for (const Child& c : kids) {  // kids is not touched by deeper levels
    if (!mayImprove(c.key)) continue;
    path_[level] = static_cast<int>(c.index);
    dfs(level + 1, fixed_q + o.mass_q[c.index], d + o.mass_kg[c.index] * p.r, effort + o.effort[c.index],
        removals + o.removals[c.index]);
  }
}

Candidate ExactSearch::evaluate(const std::vector<int>& option) const {
  Candidate c;
  c.option = option;
  double added = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (const Pt& p : pts_) {
    const std::size_t i = static_cast<std::size_t>(option[p.original]);
    added += p.opt->mass_kg[i];
    moment += p.opt->mass_kg[i] * p.r;
    c.effort += p.opt->effort[i];
    c.removals += p.opt->removals[i];
  }
  c.outcome = model_.outcome(added, moment);
  c.scores = scoreOutcome(c.outcome, targets_);
  return c;
}

ExactSearch::Bound ExactSearch::relaxedBound(const PhaseSpec& phase) {
  phase_ = phase;
  return bound(0, 0, model_.d0);
}

std::optional<Candidate> ExactSearch::run(const PhaseSpec& phase, const Candidate* start) {
  phase_ = phase;
  have_best_ = false;
  stats_ = {};
  const std::size_t n = pts_.size();
  path_.assign(n, 0);
  if (start != nullptr && start->option.size() == n) {
    std::int64_t total = 0;
    for (const Pt& p : pts_) total += p.opt->mass_q[static_cast<std::size_t>(start->option[p.original])];
    const Candidate c = evaluate(start->option);
    if (total >= phase.total_lo_q && total <= phase.total_hi_q && c.scores.pitch_violation <= phase.pitch_max &&
        c.scores.roll_violation <= phase.roll_max && c.scores.residual <= phase.residual_max) {
      have_best_ = true;
      best_value_ = goalValue(c.scores, c.effort, c.removals);
      best_path_.assign(n, 0);
      for (std::size_t k = 0; k < n; ++k) best_path_[k] = start->option[pts_[k].original];
    }
  }
  if (n == 0) {
    const Candidate c = evaluate({});
    if (phase.total_lo_q > 0 || phase.total_hi_q < 0 || c.scores.pitch_violation > phase.pitch_max ||
        c.scores.roll_violation > phase.roll_max || c.scores.residual > phase.residual_max) {
      return std::nullopt;
    }
    return c;
  }
  dfs(0, 0, model_.d0, 0, 0);
  if (!have_best_) return std::nullopt;
  std::vector<int> option(n, 0);
  for (std::size_t k = 0; k < n; ++k) option[pts_[k].original] = best_path_[k];
  return evaluate(option);
}

}  // namespace auv::ballast
