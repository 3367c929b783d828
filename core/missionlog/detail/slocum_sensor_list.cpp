#include "missionlog/detail/slocum_sensor_list.h"

#include <charconv>

#include "common/input_error.h"
#include "missionlog/detail/ascii_text.h"
#include "missionlog/log_table.h"

namespace auv::detail {
namespace {

constexpr const char* kFix = "the sensor list is damaged; copy the file (or its cache) from the glider again";

std::string_view nextWord(std::string_view& s) {
  std::size_t i = 0;
  while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
  std::size_t j = i;
  while (j < s.size() && s[j] != ' ' && s[j] != '\t') ++j;
  const std::string_view w = s.substr(i, j - i);
  s.remove_prefix(j);
  return w;
}

bool toLong(std::string_view w, long& v) {
  const auto r = std::from_chars(w.data(), w.data() + w.size(), v);
  return !w.empty() && r.ec == std::errc() && r.ptr == w.data() + w.size();
}

struct Builder {
  long inFile;
  const std::string& source;
  std::vector<SlocumSensor> slots;
  std::vector<char> filled;
  long marked = 0;

  Builder(long n, const std::string& src) : inFile(n), source(src), slots(static_cast<std::size_t>(n)), filled(static_cast<std::size_t>(n), 0) {}

  [[noreturn]] void bad(long line, const std::string& what) const {
    throw InputError("sensor_list", what, kFix, {source, line, 0});
  }

  void line(std::string_view text, long lineNo) {
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    std::string_view rest = text;
    const std::string_view tag = nextWord(rest), flag = nextWord(rest), total = nextWord(rest),
                           index = nextWord(rest), bytes = nextWord(rest), name = nextWord(rest),
                           unit = nextWord(rest);
    long t = 0, i = 0, b = 0;
    if (tag != "s:" || (flag != "T" && flag != "F") || !toLong(total, t) || !toLong(index, i) || !toLong(bytes, b) ||
        name.empty() || !trim(rest).empty())
      bad(lineNo, "'" + printableText(text, 60) + "' is not a sensor line (s: T|F index index bytes name unit)");
    if (flag == "F") return;
    if (i < 0 || i >= inFile)
      bad(lineNo, "sensor " + printableText(name) + " has index " + std::to_string(i) + " but the file holds " +
                      std::to_string(inFile) + " sensors");
    if (b != 1 && b != 2 && b != 4 && b != 8)
      bad(lineNo, "sensor " + printableText(name) + " has " + std::to_string(b) + " bytes (1, 2, 4 or 8 expected)");
    auto& f = filled[static_cast<std::size_t>(i)];
    if (f) bad(lineNo, "two sensors have index " + std::to_string(i));
    f = 1;
    ++marked;
    slots[static_cast<std::size_t>(i)] = {std::string(name), std::string(unit), static_cast<int>(b)};
  }

  SlocumSensorList finish(std::size_t end, long lineNo) {
    if (marked != inFile)
      bad(lineNo, "the sensor list marks " + std::to_string(marked) + " sensors as in the file, the header says " +
                      std::to_string(inFile));
    return {std::move(slots), end};
  }
};

}  // namespace

SlocumSensorList parseSlocumSensorList(std::string_view data, std::size_t at, long lines, long inFile,
                                       const std::string& source, long firstLine) {
  Builder b(inFile, source);
  for (long k = 0; k < lines; ++k) {
    const auto nl = data.find('\n', at);
    if (nl == std::string_view::npos)
      b.bad(firstLine + k, "the file ends inside the sensor list (line " + std::to_string(k + 1) + " of " +
                               std::to_string(lines) + ")");
    b.line(data.substr(at, nl - at), firstLine + k);
    at = nl + 1;
  }
  return b.finish(at, firstLine + lines);
}

SlocumSensorList parseSlocumCache(std::string_view data, long inFile, const std::string& source) {
  Builder b(inFile, source);
  std::size_t at = 0;
  long lineNo = 0;
  while (at < data.size()) {
    auto nl = data.find('\n', at);
    if (nl == std::string_view::npos) nl = data.size();
    ++lineNo;
    const std::string_view text = data.substr(at, nl - at);
    if (!trim(text).empty()) b.line(text, lineNo);
    at = nl + 1;
  }
  return b.finish(data.size(), lineNo);
}

}  // namespace auv::detail
