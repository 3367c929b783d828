#include "analysis/segments.h"

#include "analysis/analysis_messages.h"
#include "analysis/averaged_legs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string_view>
#include <utility>

#include "common/input_error.h"
#include "seawater/depth_pressure.h"

namespace auv::analysis {

const char* toString(SegmentKind kind) {
  switch (kind) {
    case SegmentKind::kSurface: return "surface";
    case SegmentKind::kDive: return "dive";
    case SegmentKind::kClimb: return "climb";
    case SegmentKind::kLevel: return "level";
    case SegmentKind::kSteady: return "steady";
    case SegmentKind::kGlide: return "glide";
  }
  return "?";
}

TimeSeries depthSeries(const MissionLog& log, double latitude_deg) {
  if (log.has("depth")) {
    TimeSeries d = log.series("depth");
    if (d.size() >= 2) return d;
  }
  if (log.has("pressure")) {
    TimeSeries p = log.series("pressure");
    for (double& v : p.v) v = seawater::depthFromPressure(std::clamp(v, 0.0, 11000.0), latitude_deg);
    if (p.size() >= 2) return p;
  }
  throw InputError("depth", "the log has no usable depth or pressure channel (at least two samples needed)",
                   "import a log with a 'depth [m]' or 'pressure [dbar]' column");
}

namespace {

struct Run {
  SegmentKind kind;
  double start, end;
  bool gap_before;  // a data gap separates this run from the previous one
  int prev, next;
  bool alive = true;
};

// Absorb runs shorter than `min_s` into their longer neighbour, shortest
// first, never across a data gap. O(k log k) in the number of runs.
void mergeShortRuns(std::vector<Run>& runs, double min_s) {
  const int k = static_cast<int>(runs.size());
  for (int i = 0; i < k; ++i) {
    runs[i].prev = i - 1;
    runs[i].next = i + 1 < k ? i + 1 : -1;
  }
  auto dur = [&](int i) { return runs[i].end - runs[i].start; };
  std::set<std::pair<double, int>> queue;
  for (int i = 0; i < k; ++i)
    if (dur(i) < min_s) queue.insert({dur(i), i});
  auto linkedPrev = [&](int i) { return runs[i].gap_before ? -1 : runs[i].prev; };
  auto linkedNext = [&](int i) {
    const int n = runs[i].next;
    return (n >= 0 && !runs[n].gap_before) ? n : -1;
  };
  auto unlink = [&](int i) {
    runs[i].alive = false;
    if (runs[i].prev >= 0) runs[runs[i].prev].next = runs[i].next;
    if (runs[i].next >= 0) runs[runs[i].next].prev = runs[i].prev;
  };
  auto requeue = [&](int i, double old) {
    queue.erase({old, i});
    if (dur(i) < min_s) queue.insert({dur(i), i});
  };
  // Joins j (the later run) into i; both must be alive and adjacent.
  auto join = [&](int i, int j) {
    const double oi = dur(i), oj = dur(j);
    queue.erase({oj, j});
    runs[i].end = runs[j].end;
    unlink(j);
    requeue(i, oi);
  };
  while (!queue.empty()) {
    const int s = queue.begin()->second;
    queue.erase(queue.begin());
    const int p = linkedPrev(s), n = linkedNext(s);
    if (p < 0 && n < 0) continue;  // an island between gaps: keep as is
    const int into = (n < 0 || (p >= 0 && dur(p) >= dur(n))) ? p : n;
    const double od = dur(into);
    if (into == p) {
      runs[p].end = runs[s].end;
    } else {
      runs[n].start = runs[s].start;
      runs[n].gap_before = runs[s].gap_before;
    }
    unlink(s);
    requeue(into, od);
    // The grown run may now touch a run of its own kind.
    const int a = linkedPrev(into);
    if (a >= 0 && runs[a].kind == runs[into].kind) {
      join(a, into);
      const int b = linkedNext(a);
      if (b >= 0 && runs[b].kind == runs[a].kind) join(a, b);
    } else {
      const int b = linkedNext(into);
      if (b >= 0 && runs[b].kind == runs[into].kind) join(into, b);
    }
  }
}

// Windows in which `channel` changes: a command that steps by more than
// `step` (hold semantics), or a measured channel whose local rate exceeds
// `rate_limit`. Each window is extended by `settle_s` after the change.
void addUnsteadyWindows(const MissionLog& log, const char* channel, bool command, double step_or_rate,
                        const SegmentOptions& o, std::vector<TimeWindow>& out) {
  if (!log.has(channel)) return;
  const TimeSeries s = log.series(channel);
  if (s.size() < 2) return;
  if (command) {
    for (std::size_t i = 1; i < s.size(); ++i)
      if (std::abs(s.v[i] - s.v[i - 1]) > step_or_rate) out.push_back({s.t[i], s.t[i] + o.settle_s});
    return;
  }
  const std::vector<double> r = localRate(s, o.rate_window_s, o.max_gap_s);
  std::size_t i = 0;
  while (i < s.size()) {
    if (!(std::abs(r[i]) > step_or_rate)) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < s.size() && std::abs(r[j + 1]) > step_or_rate) ++j;
    // The boxcar spreads a step over one window: the change itself happened
    // inside [t_i, t_j]; extend by the half window on each side.
    out.push_back({s.t[i] - 0.5 * o.rate_window_s, s.t[j] + 0.5 * o.rate_window_s + o.settle_s});
    i = j + 1;
  }
}

Message fmtWindowNote(const char* what, std::size_t count, double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f", seconds);
  return Message(msg::kWindowExcluded, {what, std::to_string(count), buf});
}

}  // namespace

Segmentation detectSegments(const MissionLog& log, const SegmentOptions& o) {
  Segmentation seg;
  const TimeSeries depth = depthSeries(log, seawater::kDefaultLatitude_deg);
  const std::vector<double> rate = localRate(depth, o.rate_window_s, o.max_gap_s);
  const std::size_t n = depth.size();

  // Per-sample state with hysteresis, collected directly into runs.
  std::vector<Run> runs;
  SegmentKind state = SegmentKind::kLevel;
  bool have_state = false;
  for (std::size_t i = 0; i < n; ++i) {
    const double z = depth.v[i], r = rate[i];
    seg.max_depth_m = std::max(seg.max_depth_m, z);
    SegmentKind next = state;
    const bool at_surface = have_state && state == SegmentKind::kSurface;
    if (z < o.surface_depth_m || (at_surface && z < o.surface_depth_m + o.surface_hysteresis_m)) {
      next = SegmentKind::kSurface;
    } else if (std::isnan(r)) {
      if (!have_state || at_surface) next = SegmentKind::kLevel;
    } else if (r > o.dive_rate_mps) {
      next = SegmentKind::kDive;
    } else if (r < -o.dive_rate_mps) {
      next = SegmentKind::kClimb;
    } else if (std::abs(r) < o.level_rate_mps) {
      next = SegmentKind::kLevel;
    } else if (!have_state || at_surface) {
      next = r > 0 ? SegmentKind::kDive : SegmentKind::kClimb;
    }
    const bool gap = i > 0 && depth.t[i] - depth.t[i - 1] > o.max_gap_s;
    if (runs.empty() || gap || next != state) {
      // A run ends where the next begins (contiguous cover) unless a gap
      // separates them, in which case it ends at its last sample.
      if (!runs.empty() && !gap) runs.back().end = depth.t[i];
      runs.push_back({next, depth.t[i], depth.t[i], gap, -1, -1});
    } else {
      runs.back().end = depth.t[i];
    }
    state = next;
    have_state = true;
  }
  mergeShortRuns(runs, o.min_phase_s);
  for (const Run& r : runs)
    if (r.alive && r.end > r.start) seg.phases.push_back({r.kind, r.start, r.end, r.kind, {}});

  if (o.glider) {
    for (const Segment& p : seg.phases) {
      if (p.kind != SegmentKind::kDive && p.kind != SegmentKind::kClimb) continue;
      Segment g{SegmentKind::kGlide, p.start_s + o.glide_trim_s, p.end_s - o.glide_trim_s, p.kind, {}};
      if (g.duration() >= o.min_phase_s) seg.operating.push_back(g);
    }
    return seg;
  }

  // Steady level flight: level phases minus the settling after their start
  // and minus every interval in which a command stepped or the speed or
  // propeller speed was changing.
  std::vector<TimeWindow> level;
  for (const Segment& p : seg.phases)
    if (p.kind == SegmentKind::kLevel && p.start_s + o.settle_s < p.end_s)
      level.push_back({p.start_s + o.settle_s, p.end_s});
  struct Source {
    const char* channel;
    bool command;
    double limit;
    const char* what;
  };
  const Source sources[] = {
      {"depth_cmd", true, o.depth_cmd_step_m, "depth command steps"},
      {"pitch_cmd", true, o.pitch_cmd_step_deg, "pitch command steps"},
      {"speed", false, o.speed_rate_limit_mps2, "speed changes"},
      {"prop_rpm", false, o.rpm_rate_limit_per_s, "propeller speed changes"},
  };
  std::vector<TimeWindow> cut, command_cut;
  for (const Source& s : sources) {
    std::vector<TimeWindow> w;
    addUnsteadyWindows(log, s.channel, s.command, s.limit, o, w);
    w = mergeWindows(std::move(w));
    // The legs the mission planned: a logged pitch command may be the depth
    // loop's own output, which swings with the oscillation being averaged.
    const std::string_view ch = s.channel;
    if (ch == "depth_cmd" || ch == "prop_rpm") command_cut.insert(command_cut.end(), w.begin(), w.end());
    // Only what falls inside level flight is worth a note.
    const std::vector<TimeWindow> inside = subtractWindows(level, subtractWindows(level, w));
    double total = 0.0;
    for (const TimeWindow& x : inside) total += x.duration();
    if (!inside.empty()) seg.notes.push_back(fmtWindowNote(s.what, inside.size(), total));
    cut.insert(cut.end(), w.begin(), w.end());
  }
  for (const TimeWindow& w : subtractWindows(level, mergeWindows(std::move(cut))))
    if (w.duration() >= o.min_steady_s) seg.operating.push_back({SegmentKind::kSteady, w.start_s, w.end_s, SegmentKind::kLevel, {}});
  command_cut = mergeWindows(std::move(command_cut));
  if (o.auv_steady_glides)
    for (Segment& g : auvSteadyGlides(log, seg.phases, o)) seg.operating.push_back(std::move(g));
  std::sort(seg.operating.begin(), seg.operating.end(),
            [](const Segment& a, const Segment& b) { return a.start_s < b.start_s; });
  seg.command_cuts = command_cut;
  if (!o.average_oscillating_legs) return seg;
  const std::vector<Segment> legs = averagedLegs(log, depth, command_cut, seg.operating, o);
  if (legs.empty()) return seg;
  // Steady windows inside an averaged leg would count its data twice.
  std::erase_if(seg.operating, [&](const Segment& s) {
    return std::any_of(legs.begin(), legs.end(),
                       [&](const Segment& l) { return s.start_s < l.end_s && s.end_s > l.start_s; });
  });
  seg.operating.insert(seg.operating.end(), legs.begin(), legs.end());
  std::sort(seg.operating.begin(), seg.operating.end(),
            [](const Segment& a, const Segment& b) { return a.start_s < b.start_s; });
  seg.notes.push_back(Message(msg::kAveragedLegs, {std::to_string(legs.size())}));
  return seg;
}

}  // namespace auv::analysis
