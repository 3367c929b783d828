#pragma once
// Reader plugins, one class per file format with one entry point (the
// PlotJuggler pattern). The registry picks the reader by content, not by file
// extension: vendors call everything ".csv", ".txt" or ".log".
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "missionlog/mission_log.h"
#include "missionlog/read_options.h"
#include "missionlog/read_report.h"

namespace auv {

class LogReader {
 public:
  virtual ~LogReader() = default;
  virtual std::string formatName() const = 0;
  // Cheap content sniffing on the first bytes of the file (up to 64 KiB).
  virtual bool canRead(const std::filesystem::path& path, std::string_view firstBytes) const = 0;
  // Throws InputError when nothing sensible can be read and ReadCancelled
  // when the progress callback cancels; everything else goes into `report`.
  virtual MissionLog read(const std::filesystem::path& path, const ReadOptions& options,
                          ReadReport& report) const = 0;
};

class LogReaderRegistry {
 public:
  // Every reader this build knows, most specific first.
  static LogReaderRegistry withBuiltinReaders();

  void add(std::unique_ptr<LogReader> reader);
  // First reader whose canRead() accepts the file, or nullptr. Throws
  // InputError if the file cannot be opened.
  const LogReader* find(const std::filesystem::path& path) const;
  // find() + read(); throws InputError naming the known formats if none fits.
  MissionLog read(const std::filesystem::path& path, const ReadOptions& options,
                  ReadReport& report) const;
  std::vector<std::string> formatNames() const;

 private:
  std::vector<std::unique_ptr<LogReader>> readers_;
};

// Up to `maxBytes` from the start of the file; throws InputError if unreadable.
std::string readFirstBytes(const std::filesystem::path& path, std::size_t maxBytes = 65536);

}  // namespace auv
