// The SeaExplorer raw reader: gzip -> `;` table -> tidy -> MissionLog, with
// the rules every reader shares (log_table.h).
#include "missionlog/seaexplorer_raw_reader.h"

#include <fstream>

#include "common/input_error.h"
#include "missionlog/detail/arrival_order.h"
#include "missionlog/detail/ascii_text.h"
#include "missionlog/detail/gzip_inflate.h"
#include "missionlog/detail/memory_guard.h"
#include "missionlog/detail/report_problem.h"
#include "missionlog/detail/seaexplorer_rows.h"
#include "missionlog/log_table.h"

namespace auv {
namespace {

// Sensor clocks answer within a second; a step back of this size is a clock jump.
constexpr double kArrivalJitter_s = 10.0;

bool startsWithHeader(std::string_view text) {
  const std::size_t semi = text.find(';');
  if (semi == std::string_view::npos) return false;
  const std::string_view first = detail::trim(text.substr(0, semi));
  return detail::iequals(first, "Timestamp") || detail::iequals(first, "PLD_REALTIMECLOCK");
}

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

}  // namespace

bool SeaExplorerRawReader::canRead(const std::filesystem::path&, std::string_view head) const {
  if (detail::isGzip(head)) return startsWithHeader(detail::inflateGzipHead(head, 4096));
  return startsWithHeader(head.substr(0, 4096));
}

MissionLog SeaExplorerRawReader::read(const std::filesystem::path& path, const ReadOptions& options,
                                      ReadReport& report) const {
  const std::string name = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError("log", "cannot open file", "check the path and the file permissions", {name, 0, 0});
  return detail::guardMemory(name, [&] {
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return parseSeaExplorerRaw(bytes, name, options, report);
  });
}

MissionLog parseSeaExplorerRaw(std::string_view bytes, const std::string& sourceName, const ReadOptions& options,
                               ReadReport& report, std::size_t maxInflatedBytes) {
  report = ReadReport{};
  report.file = sourceName;
  report.format = "SeaExplorer raw";
  if (options.progress && !options.progress(0.0)) throw ReadCancelled(sourceName);
  detail::InflateResult text;
  if (detail::isGzip(bytes)) {
    text = detail::inflateGzip(bytes, sourceName, maxInflatedBytes, options.progress);
  } else {
    text.text = std::string(bytes);
  }
  if (!text.complete)
    detail::reportProblem(report, options, ReadProblemKind::kTruncatedLine, {sourceName, 0, 0}, "",
                          text.damage + " at compressed byte " + std::to_string(text.stopped_at) +
                              "; the rows before it were read, the rest of the file is lost",
                          "copy the file again from the glider or its data server");
  const detail::SeaExplorerName name = detail::parseSeaExplorerName(fileName(sourceName));
  LogTable t = detail::parseSeaExplorerTable(text.text, text.complete, sourceName, name, options, report);
  if (name.stream.size()) t.tag = name.stream + (name.yo >= 0 ? std::to_string(name.yo) : std::string());
  if (!name.glider.empty()) {
    t.metadata.push_back({"vehicle", "SeaExplorer " + name.glider});
    t.metadata.push_back({"seaexplorer_mission", name.mission});
  }
  detail::sortArrivalJitter(t, kArrivalJitter_s);
  detail::mergeSameTimeRows(t, detail::SameTimeRows::kMergeUnlessConflict, report);
  tidyTable(t, options, report);
  MissionLog log = finishTable(std::move(t), report, true);
  if (options.progress && !options.progress(1.0)) throw ReadCancelled(sourceName);
  return log;
}

}  // namespace auv
