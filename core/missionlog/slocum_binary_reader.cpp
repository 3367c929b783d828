#include "missionlog/slocum_binary_reader.h"

#include <cmath>
#include <fstream>
#include <limits>

#include "common/input_error.h"
#include "missionlog/detail/ascii_text.h"
#include "missionlog/detail/memory_guard.h"
#include "missionlog/detail/report_problem.h"
#include "missionlog/detail/slocum_channels.h"
#include "missionlog/detail/slocum_file.h"
#include "missionlog/text_lines.h"

namespace auv {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kExtensions[] = {".dbd", ".ebd", ".sbd", ".tbd", ".mbd", ".nbd",
                                       ".dcd", ".ecd", ".scd", ".tcd", ".mcd", ".ncd"};

// A missing end tag 'X' is not reported: gliders since about 2017 do not
// write it, and their files are complete.
void reportDamage(const detail::SlocumFile& f, const std::string& name, const ReadOptions& o, ReadReport& r) {
  const auto& c = f.cycles;
  const std::string where = f.compressed ? " of the decompressed data" : "";
  if (!c.damage.empty())
    detail::reportProblem(r, o, ReadProblemKind::kTruncatedLine, {name, 0, 0}, "",
                          "byte " + std::to_string(c.damage_at) + where + " (after " + std::to_string(c.cycles) +
                              " data cycles): " + c.damage,
                          "the file is truncated or damaged; copy it from the glider again");
}

// inf and nan are decoded as stored but are no samples in the log; gliders
// write them routinely (m_time_til_wpt is inf while no waypoint is ahead), so
// each sensor gets one line in the report with the count, not one per value.
void reportNonFinite(const TableColumn& col, std::size_t inf, std::size_t nan, const std::string& name,
                     const ReadOptions& o, ReadReport& r) {
  const std::size_t count = inf + nan;
  if (count == 0) return;
  std::string what;
  if (inf) what = std::to_string(inf) + " value(s) stored as inf or -inf";
  if (inf && nan) what += " and ";
  if (nan) what += std::to_string(nan) + " value(s) stored as nan";
  detail::reportProblem(r, o, ReadProblemKind::kValueOutOfRange, {name, 0, 0}, col.name,
                        what + "; treated as not sampled", "nothing to do: the glider wrote them so");
  r.counts[static_cast<std::size_t>(ReadProblemKind::kValueOutOfRange)] += static_cast<long long>(count) - 1;
  r.cells_blanked += static_cast<long long>(count);
}

// Every file's first cycle repeats every sensor's last value. On files that
// continue a mission it has the same time as the second cycle, which holds the
// current values: the two are one row, the second cycle's values winning
// (docs/decisions/slocum-binary-repeated-values.md).
bool foldFirstCycle(const detail::SlocumCycles& cy) {
  return cy.cycles >= 2 && cy.time[0] == cy.time[1] && !std::isnan(cy.time[0]);
}

LogTable buildTable(const detail::SlocumFile& f, const std::string& name, const ReadOptions& o, ReadReport& r) {
  const auto& cy = f.cycles;
  const std::size_t skip = foldFirstCycle(cy) ? 1 : 0;
  const std::size_t rows = cy.cycles - skip;
  LogTable t;
  t.file = name;
  t.epoch = true;
  t.tag = f.science ? "sci" : "eng";
  t.record_dimension = "cycle";
  t.time.assign(cy.time.begin() + static_cast<std::ptrdiff_t>(skip), cy.time.end());
  t.row_where.resize(rows);
  for (std::size_t i = 0; i < rows; ++i) t.row_where[i] = static_cast<long long>(i + skip);
  r.rows_merged += static_cast<long long>(skip);
  for (std::size_t k = 0; k < f.sensors.size(); ++k) {
    const auto& s = f.sensors[k];
    if (detail::isSlocumEngineeringTime(s.name) || detail::isSlocumScienceTime(s.name)) continue;
    bool nmea = false;
    TableColumn col = detail::slocumColumn(s.name, s.unit, {name, 0, 0}, nmea);
    const auto& sv = cy.sensors[k];
    if (!sv.cycle.empty()) {
      col.values.assign(rows, kNaN);
      std::size_t inf = 0, nan = 0;
      for (std::size_t j = 0; j < sv.cycle.size(); ++j) {
        std::size_t row = sv.cycle[j];
        if (skip) {
          if (row == 0 && sv.cycle.size() > 1 && sv.cycle[1] == 1) continue;  // the second cycle's value wins
          row = row == 0 ? 0 : row - 1;
        }
        double v = sv.value[j];
        if (std::isnan(v)) ++nan;
        else if (std::isinf(v)) {
          ++inf;
          v = kNaN;
        } else if (nmea) v = detail::slocumNmeaToDegrees(v);
        col.values[row] = v;
      }
      reportNonFinite(col, inf, nan, name, o, r);
    }
    t.columns.push_back(std::move(col));
  }
  return t;
}

MissionLog toLog(const detail::SlocumFile& f, const std::string& name, const ReadOptions& o, ReadReport& r) {
  if (f.time_sensor < 0)
    throw InputError("time",
                     "none of the " + std::to_string(f.sensors.size()) +
                         " sensors in the file is m_present_time or sci_m_present_time",
                     "the glider's sensor list for this file type must include m_present_time (flight) or "
                     "sci_m_present_time (science); add it to the .sbd/.tbd list on the glider",
                     {name, 0, 0});
  reportDamage(f, name, o, r);
  r.data_lines = static_cast<long long>(f.cycles.cycles);
  r.lines = static_cast<long long>(f.header.lines);
  if (f.cycles.cycles == 0)
    throw InputError("cycles", "the file holds no complete data cycle",
                     "the glider closed the file right after opening it; read the next file of the mission",
                     {name, 0, 0});
  std::vector<LogTable> streams;
  streams.push_back(buildTable(f, name, o, r));
  auto tags = f.header.tags;
  tags.push_back({"sensor_list", f.sensor_list_source});
  return detail::finishSlocumLog(std::move(streams), std::move(tags), o, r);
}

std::string readWholeFile(const std::filesystem::path& path) {
  BlockFile file(path);  // throws the project's message for missing files and folders
  std::string bytes(static_cast<std::size_t>(file.size()), '\0');
  std::size_t got = 0;
  while (got < bytes.size()) {
    const std::size_t n = file.read(bytes.data() + got, bytes.size() - got);
    if (n == 0) break;
    got += n;
  }
  bytes.resize(got);
  return bytes;
}

}  // namespace

bool SlocumBinaryReader::canRead(const std::filesystem::path& path, std::string_view head) const {
  if (head.empty()) {
    const std::string ext = detail::lower(path.extension().string());
    for (const char* e : kExtensions)
      if (ext == e) return true;
    return false;
  }
  return detail::looksLikeSlocumBinary(head);
}

MissionLog SlocumBinaryReader::read(const std::filesystem::path& path, const ReadOptions& options,
                                    ReadReport& report) const {
  return readSlocumBinary(path, options, report);
}

MissionLog readSlocumBinary(const std::filesystem::path& path, const ReadOptions& options, ReadReport& report) {
  return detail::guardMemory(path.string(), [&] {
    if (options.progress && !options.progress(0.0)) throw ReadCancelled(path.string());
    const std::string bytes = readWholeFile(path);
    return parseSlocumBinary(bytes, path, options, report);
  });
}

MissionLog parseSlocumBinary(std::string_view bytes, const std::filesystem::path& file, const ReadOptions& options,
                             ReadReport& report) {
  const std::string name = file.string();
  report = ReadReport{};
  report.file = name;
  report.format = "Slocum binary";
  return detail::guardMemory(name, [&] {
    const detail::SlocumFile f = detail::decodeSlocumFile(bytes, file, options);
    if (options.progress && !options.progress(0.5)) throw ReadCancelled(name);
    MissionLog log = toLog(f, name, options, report);
    if (options.progress && !options.progress(1.0)) throw ReadCancelled(name);
    return log;
  });
}

}  // namespace auv
