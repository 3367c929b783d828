#include "missionlog/mission_files.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>

#include "common/input_error.h"
#include "missionlog/detail/mission_groups.h"
#include "missionlog/detail/report_problem.h"
#include "missionlog/iso8601.h"
#include "missionlog/log_table.h"

namespace auv {
namespace {

bool sameUnitSpelling(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}


namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string listNames(const std::vector<fs::path>& files, std::size_t max = 12) {
  std::string s;
  for (std::size_t i = 0; i < files.size() && i < max; ++i) s += (s.empty() ? "" : ", ") + files[i].filename().string();
  if (files.size() > max) s += ", ... (" + std::to_string(files.size()) + " in all)";
  return s;
}

void addFolder(const fs::path& dir, const LogReaderRegistry& registry, MissionFiles& out) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.is_regular_file(ec)) files.push_back(e.path());
  if (ec)
    throw InputError("log", "cannot list the folder: " + ec.message(), "check the folder's permissions",
                     {dir.string(), 0, 0});
  std::sort(files.begin(), files.end());
  std::size_t found = 0;
  for (const auto& f : files) {
    bool log = false;
    if (!detail::isKnownNonLogFile(f)) {
      try {
        log = registry.find(f) != nullptr;
      } catch (const InputError&) {
        log = false;  // unreadable: listed as skipped
      }
    }
    (log ? out.logs : out.skipped).push_back(f);
    found += log;
  }
  if (!found)
    throw InputError("log",
                     "the folder holds no file that a reader recognises" +
                         (files.empty() ? std::string(" (it is empty)") : " (skipped: " + listNames(files) + ")"),
                     "give the folder with the vehicle's log files, or the files themselves", {dir.string(), 0, 0});
}

// Where a part's rows lie on the mission's time base.
struct Span {
  std::string key;
  double first = 0, last = 0;
  std::string firstFile, lastFile;
};

// The spans of the parts, merged by `key` (file name -> key), in time order.
template <class Key>
std::vector<Span> spansBy(const std::vector<MissionPart>& parts, const std::vector<double>& offset, Key key) {
  std::map<std::string, Span> byKey;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const MissionLog& l = parts[k].log;
    if (l.time.empty()) continue;
    const std::string kk = key(fs::path(parts[k].file).filename().string());
    const double a = l.time.front() + offset[k], b = l.time.back() + offset[k];
    auto [it, fresh] = byKey.try_emplace(kk, Span{kk, a, b, parts[k].file, parts[k].file});
    if (!fresh) {
      if (a < it->second.first) it->second.first = a, it->second.firstFile = parts[k].file;
      if (b > it->second.last) it->second.last = b, it->second.lastFile = parts[k].file;
    }
  }
  std::vector<Span> spans;
  for (auto& [k, s] : byKey) spans.push_back(std::move(s));
  std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.first < b.first; });
  return spans;
}

std::string fileOf(const std::string& path) { return fs::path(path).filename().string(); }

// Files of one stream (detail::missionStreamKey) that overlap in time: a file
// given twice or a clock that jumped. Files of different streams (a
// SeaExplorer payload file that runs on a few seconds into the next yo's
// navigation file) overlap by design.
void noteOverlaps(const std::vector<MissionPart>& parts, const std::vector<double>& offset, const std::string& label,
                  const ReadOptions& o, ReadReport& r) {
  std::map<std::string, std::vector<std::size_t>> streams;
  for (std::size_t k = 0; k < parts.size(); ++k)
    if (!parts[k].log.time.empty()) streams[detail::missionStreamKey(fileOf(parts[k].file))].push_back(k);
  std::size_t overlaps = 0, files = 0;
  double seconds = 0;
  std::string first;
  for (auto& [stream, ks] : streams) {
    files += ks.size();
    std::sort(ks.begin(), ks.end(), [&](std::size_t a, std::size_t b) {
      return parts[a].log.time.front() + offset[a] < parts[b].log.time.front() + offset[b];
    });
    double reach = -INFINITY;
    std::size_t reachK = 0;
    for (std::size_t k : ks) {
      const double a = parts[k].log.time.front() + offset[k], b = parts[k].log.time.back() + offset[k];
      if (a < reach) {
        if (!overlaps++) first = fileOf(parts[k].file) + " starts before " + fileOf(parts[reachK].file) + " ends";
        seconds += std::min(reach, b) - a;
      }
      if (b > reach) reach = b, reachK = k;
    }
  }
  if (overlaps)
    detail::reportProblem(r, o, ReadProblemKind::kTimeNotIncreasing, {label, 0, 0}, "time",
                          std::to_string(overlaps) + " of " + std::to_string(files) +
                              " files overlap in time with an earlier file of the same kind (" +
                              numberText(std::round(seconds)) + " s in all; first: " + first +
                              "); rows of both were kept in time order",
                          "check that no file is given twice and that the files are of one vehicle and mission");
}

// Gaps between groups (a Slocum segment, a SeaExplorer yo, a Seaglider
// dive) noted once for the mission when longer than a missing file would leave.
void noteGaps(const std::vector<Span>& spans, const std::string& label, const ReadOptions& o, ReadReport& r) {
  if (spans.size() < 2) return;
  std::vector<double> gaps, durations;
  for (const Span& s : spans) durations.push_back(s.last - s.first);
  double reach = spans[0].last;
  for (std::size_t k = 1; k < spans.size(); ++k) {
    if (spans[k].first > reach) gaps.push_back(spans[k].first - reach);
    reach = std::max(reach, spans[k].last);
  }
  if (gaps.empty()) return;
  std::nth_element(durations.begin(), durations.begin() + static_cast<std::ptrdiff_t>(durations.size() / 2),
                   durations.end());
  double limit = std::max(600.0, 0.5 * durations[durations.size() / 2]);
  if (gaps.size() >= 3) {
    std::vector<double> g = gaps;
    std::nth_element(g.begin(), g.begin() + static_cast<std::ptrdiff_t>(g.size() / 2), g.end());
    limit = std::max(limit, 3.0 * g[g.size() / 2]);
  }
  std::size_t n = 0, reachK = 0;
  double largest = 0;
  std::string where;
  reach = spans[0].last;
  for (std::size_t k = 1; k < spans.size(); ++k) {
    const double d = spans[k].first - reach;
    if (d > limit) {
      ++n;
      if (d > largest) {
        largest = d;
        where = fileOf(spans[reachK].lastFile) + " and " + fileOf(spans[k].firstFile);
      }
    }
    if (spans[k].last > reach) reach = spans[k].last, reachK = k;
  }
  if (n)
    detail::reportProblem(r, o, ReadProblemKind::kTimeGap, {label, 0, 0}, "time",
                          std::to_string(n) + " gap" + (n > 1 ? "s" : "") + " between files longer than " +
                              numberText(std::round(limit)) + " s (largest " + numberText(std::round(largest)) +
                              " s, between " + where + "); nothing changed",
                          "check whether a dive, yo or segment file is missing from the mission");
}

void addUp(ReadReport& total, const ReadReport& part, const ReadOptions& o) {
  total.lines += part.lines;
  total.data_lines += part.data_lines;
  total.rows_skipped += part.rows_skipped;
  total.rows_merged += part.rows_merged;
  total.cells_blanked += part.cells_blanked;
  for (std::size_t k = 0; k < total.counts.size(); ++k) {
    const auto kind = static_cast<ReadProblemKind>(k);
    long long kept = 0;
    for (const auto& p : total.problems) kept += p.kind == kind;
    for (const auto& p : part.problems)
      if (p.kind == kind && kept < static_cast<long long>(o.max_problems_per_kind)) {
        total.problems.push_back(p);
        ++kept;
      }
    total.counts[k] += part.counts[k];
  }
}

}  // namespace

MissionFiles expandMissionPaths(const std::vector<fs::path>& inputs, const LogReaderRegistry& registry) {
  MissionFiles out;
  if (inputs.empty()) throw InputError("log", "no log given", "give --log FILE or --log FOLDER (repeatable)");
  for (const auto& p : inputs) {
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      addFolder(p, registry, out);
    } else if (fs::exists(p, ec)) {
      out.logs.push_back(p);
    } else {
      throw InputError("log", "no such file or folder", "check the path", {p.string(), 0, 0});
    }
  }
  return out;
}

std::string missionLabel(const std::vector<fs::path>& inputs) {
  if (inputs.empty()) return "log";
  std::string first = inputs.front().filename().string();
  if (first.empty()) first = inputs.front().parent_path().filename().string();
  if (first.empty()) first = inputs.front().string();
  return inputs.size() == 1 ? first : first + " and " + std::to_string(inputs.size() - 1) + " more";
}

MissionLog mergeMission(std::vector<MissionPart> parts, const ReadOptions& options, ReadReport& report) {
  if (parts.empty()) throw InputError("log", "no log to merge", "give at least one log file");
  const std::size_t np = parts.size();
  // A common start: every part's times are shifted by its start's distance
  // from the earliest. Starts are whole milliseconds, so the difference and
  // the shifted times are exact and equal instants stay equal.
  std::vector<std::optional<double>> start(np);
  for (std::size_t k = 0; k < np; ++k) start[k] = parts[k].log.startEpochSeconds();
  for (std::size_t k = 1; k < np; ++k)
    if (start[k].has_value() != start[0].has_value())
      throw InputError("time",
                       "'" + fileOf(parts[k].file) + "' has " + (start[k] ? "absolute (dated)" : "relative") +
                           " time but '" + fileOf(parts[0].file) + "' has " + (start[0] ? "absolute" : "relative") +
                           " time; they cannot be put on one time base",
                       "give files of one mission, each with a date and time (or none with one)",
                       {parts[k].file, 0, 0});
  double common = 0;
  if (start[0]) {
    common = *start[0];
    for (const auto& s : start) common = std::min(common, *s);
  }
  std::vector<double> offset(np, 0.0);
  for (std::size_t k = 0; k < np; ++k)
    if (start[k]) offset[k] = *start[k] - common;

  std::vector<std::size_t> order(np);
  for (std::size_t k = 0; k < np; ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const auto first = [&](std::size_t k) {
      return parts[k].log.time.empty() ? INFINITY : parts[k].log.time.front() + offset[k];
    };
    return first(a) < first(b);
  });

  std::vector<double> time;
  std::size_t total = 0;
  for (const auto& p : parts) total += p.log.time.size();
  time.reserve(total);
  for (std::size_t k = 0; k < np; ++k)
    for (double t : parts[k].log.time) time.push_back(t + offset[k]);
  std::sort(time.begin(), time.end());
  time.erase(std::unique(time.begin(), time.end()), time.end());
  const std::size_t n = time.size();

  report = ReadReport{};
  std::vector<fs::path> names;
  for (const auto& p : parts) names.emplace_back(p.file);
  report.file = missionLabel(names);
  std::vector<std::string> formats;
  for (const auto& p : parts) {
    addUp(report, p.report, options);
    if (std::find(formats.begin(), formats.end(), p.report.format) == formats.end()) formats.push_back(p.report.format);
  }
  for (const auto& f : formats) report.format += (report.format.empty() ? "" : " + ") + f;
  report.rows_merged += static_cast<long long>(total - n);
  noteOverlaps(parts, offset, report.file, options, report);
  noteGaps(spansBy(parts, offset, [](const std::string& f) { return detail::missionGroupKey(f); }), report.file,
           options, report);

  MissionLog out;
  out.time = std::move(time);
  std::unordered_map<std::string, std::size_t> byName;
  struct Conflict {
    long long count = 0;
    std::string first, second;
    double at = 0;
  };
  std::map<std::string, Conflict> conflicts;
  for (std::size_t k : order) {
    MissionPart& part = parts[k];
    for (const auto& m : part.log.metadata)
      if (m.key != "start" && !out.metadataValue(m.key)) out.metadata.push_back(m);
    std::vector<std::size_t> at(part.log.time.size());
    for (std::size_t i = 0; i < at.size(); ++i)
      at[i] = static_cast<std::size_t>(
          std::lower_bound(out.time.begin(), out.time.end(), part.log.time[i] + offset[k]) - out.time.begin());
    for (auto& c : part.log.channels) {
      auto hit = byName.find(c.name);
      // Units that differ only in letter case are one unit here: a Slocum's
      // flight and science computers spell the same sensor's unit "Mbytes"
      // and "mbytes", "NTU" and "ntu". No logger writes both mbar and Mbar.
      if (hit != byName.end() && !sameUnitSpelling(out.channels[hit->second].unit, c.unit)) {
        std::string renamed = c.name + "_" + fs::path(part.file).stem().string();
        for (int s = 2; byName.count(renamed); ++s) renamed = c.name + "_" + std::to_string(s);
        detail::reportProblem(report, options, ReadProblemKind::kDuplicateColumn, {part.file, 0, 0}, c.name,
                              "'" + c.name + "' is in [" + c.unit + "] here but in [" +
                                  out.channels[hit->second].unit + "] in an earlier file; this one is named '" +
                                  renamed + "'",
                              "check that the files are of one vehicle");
        c.name = renamed;
        hit = byName.end();
      }
      if (hit == byName.end()) {
        LogChannel d;
        d.name = c.name;
        d.unit = c.unit;
        d.source_unit = c.source_unit;
        d.values.assign(n, kNaN);
        hit = byName.emplace(c.name, out.channels.size()).first;
        out.channels.push_back(std::move(d));
      }
      LogChannel& d = out.channels[hit->second];
      for (std::size_t i = 0; i < c.values.size() && i < at.size(); ++i) {
        const double v = c.values[i];
        if (std::isnan(v)) continue;
        double& dst = d.values[at[i]];
        if (std::isnan(dst)) {
          dst = v;
        } else if (dst != v) {
          Conflict& x = conflicts[d.name];
          if (!x.count++) x.second = part.file, x.at = out.time[at[i]];
        }
      }
    }
  }
  for (const auto& [name, x] : conflicts)
    detail::reportProblem(report, options, ReadProblemKind::kConflictingDuplicate, {x.second, 0, 0}, name,
                          std::to_string(x.count) + " values differ from an earlier file's at the same time (first at " +
                              numberText(x.at) + " s); the earlier file's were kept",
                          "check that no two files hold the same sensor with different clocks");
  if (start[0]) out.setMetadata("start", formatIso8601(common, 3));
  std::string files;
  for (std::size_t k : order) files += (files.empty() ? "" : ", ") + fileOf(parts[k].file);
  out.setMetadata("mission_files", std::to_string(np) + " files: " + files);
  report.rows_kept = static_cast<long long>(n);
  return out;
}

MissionLog readMission(const std::vector<fs::path>& inputs, const ReadOptions& options, ReadReport& report,
                       const LogReaderRegistry& registry) {
  std::error_code ec;
  if (inputs.size() == 1 && !fs::is_directory(inputs.front(), ec)) return registry.read(inputs.front(), options, report);
  const MissionFiles files = expandMissionPaths(inputs, registry);
  if (files.logs.size() == 1 && files.skipped.empty()) return registry.read(files.logs.front(), options, report);
  std::vector<MissionPart> parts;
  parts.reserve(files.logs.size());
  const double nFiles = static_cast<double>(files.logs.size());
  for (std::size_t k = 0; k < files.logs.size(); ++k) {
    ReadOptions o = options;
    if (options.progress)
      o.progress = [&options, k, nFiles](double f) { return options.progress((static_cast<double>(k) + f) / nFiles); };
    MissionPart p;
    p.file = files.logs[k].string();
    p.log = registry.read(files.logs[k], o, p.report);
    parts.push_back(std::move(p));
  }
  MissionLog log = mergeMission(std::move(parts), options, report);
  if (!files.skipped.empty()) log.setMetadata("mission_files_skipped", listNames(files.skipped, 50));
  report.file = missionLabel(inputs);
  return log;
}

MissionLog readMission(const std::vector<fs::path>& inputs, const ReadOptions& options, ReadReport& report) {
  return readMission(inputs, options, report, LogReaderRegistry::withBuiltinReaders());
}

}  // namespace auv
