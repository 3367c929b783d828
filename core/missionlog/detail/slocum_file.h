#pragma once
// One Slocum binary file decoded to its sensors' raw values, before any
// mapping to channels: the header, where the sensor list came from, and the
// new values of every sensor with their data cycle. The reader builds the
// log from this; the tests compare it with an independent decoder.
#include <filesystem>
#include <string>
#include <string_view>

#include "missionlog/detail/slocum_cycles.h"
#include "missionlog/detail/slocum_header.h"
#include "missionlog/detail/slocum_sensor_list.h"
#include "missionlog/read_options.h"

namespace auv::detail {

struct SlocumFile {
  SlocumHeader header;
  std::vector<SlocumSensor> sensors;  // in file order
  std::string sensor_list_source;     // "the file itself" or the cache file used
  bool compressed = false;            // LZ4 blocks (.dcd ...)
  int time_sensor = -1;               // m_present_time, else sci_m_present_time, else -1
  bool science = false;               // timed by sci_m_present_time
  SlocumCycles cycles;
  std::size_t data_bytes = 0;         // after decompression
};

// Decodes a whole file held in memory. `file` names it in messages and
// places the cache search next to it. Throws InputError when nothing can be
// read (empty, not Slocum, unknown encoding, missing cache, bad known bytes).
SlocumFile decodeSlocumFile(std::string_view bytes, const std::filesystem::path& file, const ReadOptions& options);

// True when `head` (the first bytes of a file) is a Slocum binary file,
// plain or LZ4-compressed.
bool looksLikeSlocumBinary(std::string_view head);

}  // namespace auv::detail
