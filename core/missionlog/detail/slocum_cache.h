#pragma once
// Where the sensor list of a file with `sensor_list_factored: 1` is found:
// a cache file named by the header's `sensor_list_crc` (any case, as the
// gliders have written both), `.cac` (text) or `.ccc` (LZ4 blocks), looked
// up in the reader's cache folder, then next to the data file, then in the
// per-user cache, which the reader fills from every file that carries its
// own list so that later factored files of the same glider read without one.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace auv::detail {

// $XDG_CACHE_HOME/auvballast/slocum-cache, else ~/.cache/auvballast/slocum-cache,
// else empty (no home).
std::filesystem::path slocumUserCacheDir();

// The folders searched for a cache, in order, without duplicates or empties.
std::vector<std::filesystem::path> slocumCacheSearchPath(const std::filesystem::path& optionDir,
                                                         const std::filesystem::path& dataFile, bool userCache);

// The cache file for `crc` in the first folder that has one (.cac before
// .ccc within a folder), or nullopt.
std::optional<std::filesystem::path> findSlocumCache(const std::vector<std::filesystem::path>& dirs,
                                                     std::string_view crc);

// The cache's sensor lines (LZ4 blocks undone for .ccc). Throws InputError.
std::string loadSlocumCache(const std::filesystem::path& cacheFile);

// Writes `<dir>/<crc lower case>.cac` unless a cache for `crc` is there.
// Best effort: returns false (and writes nothing) on any failure, because a
// read-only home must not stop a file from being read.
bool storeSlocumCache(const std::filesystem::path& dir, std::string_view crc, std::string_view sensorLines);

}  // namespace auv::detail
