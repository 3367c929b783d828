#pragma once
// The sensor list of a Slocum binary file: one line per sensor of the
// glider's master list, `s: T|F <index> <index in this file or -1> <bytes>
// <name> <unit>`. It is in the file after the header, or, when the header
// says `sensor_list_factored: 1`, in a cache file named by its CRC.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace auv::detail {

struct SlocumSensor {
  std::string name;
  std::string unit;
  int bytes = 0;  // 1, 2, 4 or 8
};

struct SlocumSensorList {
  std::vector<SlocumSensor> sensors;  // those in the file, in file order
  std::size_t end = 0;                // byte offset just past the last line read
};

// Reads `lines` sensor lines from `data` starting at `at`, checking that the
// ones marked T number exactly `inFile`, each index once. Throws InputError
// naming `source` (the data file or the cache file) and the line.
SlocumSensorList parseSlocumSensorList(std::string_view data, std::size_t at, long lines, long inFile,
                                       const std::string& source, long firstLine);

// Like parseSlocumSensorList for a whole cache file (its number of lines is
// whatever it holds).
SlocumSensorList parseSlocumCache(std::string_view data, long inFile, const std::string& source);

}  // namespace auv::detail
