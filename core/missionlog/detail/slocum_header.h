#pragma once
// The ASCII header of a Slocum binary file (.dbd and kin): `key: value`
// lines, as many as `num_ascii_tags` says, starting with `dbd_label:`.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "missionlog/mission_log.h"

namespace auv::detail {

// The only encoding of the binary cycles this reader knows (and the only one
// the gliders have written since 2003).
inline constexpr long kSlocumEncoding = 5;

struct SlocumHeader {
  std::vector<MetadataEntry> tags;  // in file order
  long sensors_per_cycle = 0;
  long total_num_sensors = 0;
  long state_bytes_per_cycle = 0;
  bool sensor_list_factored = false;
  std::string sensor_list_crc;  // as written (case kept)
  std::size_t end = 0;          // byte offset just past the header
  std::size_t lines = 0;        // header lines read

  const std::string* tag(std::string_view key) const;
};

// True when `head` starts with the binary header's first line (the dbd2asc
// text output starts with `dbd_label:` too, but names DBD_ASC there).
bool isSlocumBinaryHeader(std::string_view head);

// Throws InputError naming the file, the header line and the fix when the
// header is missing, cut short, of another encoding or inconsistent.
SlocumHeader parseSlocumHeader(std::string_view data, const std::string& file);

}  // namespace auv::detail
