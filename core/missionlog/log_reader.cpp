#include "missionlog/log_reader.h"

#include <cerrno>
#include <cstring>
#include <fstream>

#include "common/input_error.h"
#include "missionlog/delimited_text_reader.h"
#include "missionlog/interchange_csv.h"
#include "missionlog/netcdf_reader.h"
#include "missionlog/seaexplorer_raw_reader.h"
#include "missionlog/slocum_ascii_reader.h"
#include "missionlog/slocum_binary_reader.h"

namespace auv {

LogReaderRegistry LogReaderRegistry::withBuiltinReaders() {
  LogReaderRegistry r;
  // Binary and tagged formats first (magic bytes; SeaExplorer's header line
  // before the generic text reader, which would take a plain one), then the interchange CSV,
  // then the generic text reader, which would accept an interchange file too.
  r.add(std::make_unique<GliderNetcdfReader>());
  r.add(std::make_unique<SeaExplorerRawReader>());
  // Before the dbd2asc text reader: both files start with `dbd_label:`.
  r.add(std::make_unique<SlocumBinaryReader>());
  r.add(std::make_unique<SlocumAsciiReader>());
  r.add(std::make_unique<InterchangeCsvReader>());
  r.add(std::make_unique<DelimitedTextReader>());
  return r;
}

void LogReaderRegistry::add(std::unique_ptr<LogReader> reader) {
  if (reader) readers_.push_back(std::move(reader));
}

std::string readFirstBytes(const std::filesystem::path& path, std::size_t maxBytes) {
  // Opening a FIFO blocks until a writer appears, and a device never ends:
  // refuse them before opening.
  std::error_code ec;
  const auto type = std::filesystem::status(path, ec).type();
  if (type == std::filesystem::file_type::fifo || type == std::filesystem::file_type::character ||
      type == std::filesystem::file_type::block || type == std::filesystem::file_type::socket) {
    throw InputError("log", type == std::filesystem::file_type::fifo ? "is a FIFO (named pipe), not a log file"
                                                                       : "is a device or socket, not a log file",
                     "save the recording to a regular file and give that path", {path.string(), 0, 0});
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError("log", std::string("cannot open file: ") + std::strerror(errno),
                     "check the path and the file permissions", {path.string(), 0, 0});
  std::string s(maxBytes, '\0');
  in.read(s.data(), static_cast<std::streamsize>(maxBytes));
  s.resize(static_cast<std::size_t>(in.gcount()));
  return s;
}

const LogReader* LogReaderRegistry::find(const std::filesystem::path& path) const {
  const std::string head = readFirstBytes(path);
  for (const auto& r : readers_)
    if (r->canRead(path, head)) return r.get();
  return nullptr;
}

std::vector<std::string> LogReaderRegistry::formatNames() const {
  std::vector<std::string> n;
  for (const auto& r : readers_) n.push_back(r->formatName());
  return n;
}

MissionLog LogReaderRegistry::read(const std::filesystem::path& path, const ReadOptions& options,
                                   ReadReport& report) const {
  const LogReader* r = find(path);
  if (!r) {
    std::string names;
    for (const auto& n : formatNames()) names += (names.empty() ? "" : "; ") + n;
    throw InputError("log", "no reader recognises this file's content",
                     "convert it to the mission-log CSV format (known formats: " + names + ")",
                     {path.string(), 0, 0});
  }
  return r->read(path, options, report);
}

}  // namespace auv
