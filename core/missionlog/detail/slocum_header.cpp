#include "missionlog/detail/slocum_header.h"

#include <cstdlib>

#include "common/input_error.h"
#include "missionlog/detail/ascii_text.h"
#include "missionlog/log_table.h"

namespace auv::detail {
namespace {

constexpr long kMaxTags = 64;
constexpr long kMaxSensors = 65535;
constexpr std::string_view kFix = "the file is not a complete Slocum binary file; copy it from the glider again";

bool splitTag(std::string_view line, std::string_view& key, std::string_view& value) {
  const auto colon = line.find(':');
  if (colon == std::string_view::npos || colon == 0) return false;
  key = line.substr(0, colon);
  for (char c : key)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || isDigit(c) || c == '_')) return false;
  value = trim(line.substr(colon + 1));
  return true;
}

long integerTag(const SlocumHeader& h, std::string_view key, long lo, long hi, const std::string& file) {
  const std::string* v = h.tag(key);
  long line = 0;
  for (std::size_t i = 0; i < h.tags.size(); ++i)
    if (h.tags[i].key == key) line = static_cast<long>(i) + 1;
  if (!v)
    throw InputError(std::string(key), "the header has no `" + std::string(key) + ":` line", std::string(kFix),
                     {file, static_cast<long>(h.lines), 0});
  char* end = nullptr;
  const long n = std::strtol(v->c_str(), &end, 10);
  if (v->empty() || *end != '\0' || n < lo || n > hi)
    throw InputError(std::string(key),
                     "'" + printableText(*v) + "' is not a whole number from " + std::to_string(lo) + " to " +
                         std::to_string(hi),
                     std::string(kFix), {file, line, 0});
  return n;
}

}  // namespace

const std::string* SlocumHeader::tag(std::string_view key) const {
  for (const auto& t : tags)
    if (t.key == key) return &t.value;
  return nullptr;
}

bool isSlocumBinaryHeader(std::string_view head) {
  if (head.substr(0, 10) != "dbd_label:") return false;
  const auto nl = head.find('\n');
  const std::string_view label = trim(head.substr(10, nl == std::string_view::npos ? 64 : nl - 10));
  return label.find("DBD_ASC") == std::string_view::npos && label.find("dinkum_binary_data_ascii") == std::string_view::npos;
}

SlocumHeader parseSlocumHeader(std::string_view data, const std::string& file) {
  SlocumHeader h;
  if (data.empty())
    throw InputError("dbd_label", "the file is empty (0 bytes)",
                     "the glider wrote nothing into it or the copy failed; copy the file from the glider again",
                     {file, 0, 0});
  if (!isSlocumBinaryHeader(data))
    throw InputError("dbd_label", "the file does not start with `dbd_label: DBD(dinkum_binary_data)file`",
                     "give a Slocum binary file (.dbd .ebd .sbd .tbd .mbd .nbd or compressed .dcd ...)", {file, 1, 1});
  long wanted = kMaxTags;
  std::size_t at = 0;
  while (static_cast<long>(h.lines) < wanted) {
    const auto nl = data.find('\n', at);
    if (nl == std::string_view::npos || nl - at > 4096)
      throw InputError("header", "the file ends inside header line " + std::to_string(h.lines + 1), std::string(kFix),
                       {file, static_cast<long>(h.lines) + 1, 0});
    std::string_view line = data.substr(at, nl - at);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++h.lines;
    std::string_view key, value;
    if (!splitTag(line, key, value))
      throw InputError("header",
                       "line " + std::to_string(h.lines) + " is not a `key: value` tag ('" + printableText(line) + "')",
                       std::string(kFix), {file, static_cast<long>(h.lines), 1});
    h.tags.push_back({std::string(key), std::string(value)});
    at = nl + 1;
    if (key == "num_ascii_tags") wanted = integerTag(h, "num_ascii_tags", 3, kMaxTags, file);
    if (key == "encoding_ver") {
      const long enc = integerTag(h, "encoding_ver", 0, 1000000, file);
      if (enc != kSlocumEncoding)
        throw InputError("encoding_ver",
                         "encoding_ver " + std::to_string(enc) + " is not the Slocum binary encoding this reader knows (" +
                             std::to_string(kSlocumEncoding) + ")",
                         "the file is damaged or from an unknown firmware; decode it with the vendor's dbd2asc and "
                         "read its text output",
                         {file, static_cast<long>(h.lines), static_cast<long>(line.find(':')) + 2});
    }
  }
  h.end = at;
  if (!h.tag("encoding_ver"))
    throw InputError("encoding_ver", "the header has no `encoding_ver:` line", std::string(kFix),
                     {file, static_cast<long>(h.lines), 0});
  h.sensors_per_cycle = integerTag(h, "sensors_per_cycle", 1, kMaxSensors, file);
  h.total_num_sensors = h.tag("total_num_sensors") ? integerTag(h, "total_num_sensors", 1, kMaxSensors, file)
                                                   : h.sensors_per_cycle;
  h.state_bytes_per_cycle = integerTag(h, "state_bytes_per_cycle", 1, kMaxSensors, file);
  if (h.state_bytes_per_cycle != (h.sensors_per_cycle + 3) / 4)
    throw InputError("state_bytes_per_cycle",
                     std::to_string(h.state_bytes_per_cycle) + " state bytes do not hold 2 bits for each of " +
                         std::to_string(h.sensors_per_cycle) + " sensors",
                     std::string(kFix), {file, 0, 0});
  h.sensor_list_factored = h.tag("sensor_list_factored") && integerTag(h, "sensor_list_factored", 0, 1, file) == 1;
  if (const std::string* crc = h.tag("sensor_list_crc")) h.sensor_list_crc = *crc;
  return h;
}

}  // namespace auv::detail
