// Writer of the interchange CSV. Numbers are written in the shortest form that
// reads back to the same double (std::to_chars), so write -> read is exact and
// a simulated log compares bit for bit with what was simulated.
#include <charconv>
#include <cmath>
#include <fstream>
#include <ostream>

#include "common/input_error.h"
#include "missionlog/interchange_csv.h"

namespace auv {
namespace {

void checkWritable(const MissionLog& log) {
  auto bad = [](std::string field, std::string problem, std::string fix) {
    throw InputError(std::move(field), std::move(problem), std::move(fix));
  };
  for (const auto& m : log.metadata) {
    if (m.key.find_first_of(":\r\n") != std::string::npos)
      bad("metadata", "key '" + m.key + "' contains a colon or a line break",
          "metadata keys are single words such as `vehicle`");
    if (m.value.find_first_of("\r\n") != std::string::npos)
      bad("metadata", "value of '" + m.key + "' contains a line break", "keep metadata values on one line");
    if (m.key.empty() && m.value.find(':') != std::string::npos)
      bad("metadata", "free-text comment '" + m.value + "' contains a colon and would read back as a key",
          "give it a key");
  }
  for (std::size_t i = 1; i < log.time.size(); ++i)
    if (!(log.time[i] > log.time[i - 1]))
      bad("time", "not strictly increasing at row " + std::to_string(i), "sort the rows and merge repeated times");
  for (double t : log.time)
    if (!std::isfinite(t)) bad("time", "contains a non-finite value", "every row needs a finite time");
  for (const auto& c : log.channels) {
    if (c.name.empty() || c.name == "time" ||
        c.name.find_first_of(",[]\"\r\n#") != std::string::npos || c.name.front() == ' ' ||
        c.name.back() == ' ')
      bad(c.name, "channel name cannot be written in a CSV header",
          "use letters, digits and '_' (no comma, bracket, quote or '#')");
    if (c.unit.find_first_of(",[]\"\r\n") != std::string::npos)
      bad(c.name, "unit '" + c.unit + "' cannot be written in a CSV header", "use a plain unit such as m/s");
    if (c.values.size() != log.time.size())
      bad(c.name, "has " + std::to_string(c.values.size()) + " values for " + std::to_string(log.time.size()) + " rows",
          "every channel needs one value (or NaN) per row");
    for (double v : c.values)
      if (std::isinf(v)) bad(c.name, "contains an infinite value", "use NaN for 'not sampled'");
  }
}

void append(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

}  // namespace

void writeInterchangeCsv(const MissionLog& log, std::ostream& out) {
  checkWritable(log);
  std::string buf;
  buf.reserve(1 << 20);
  for (const auto& m : log.metadata) {
    if (m.key.empty()) buf += "# " + m.value + "\n";
    else buf += "# " + m.key + ": " + m.value + "\n";
  }
  buf += "time [s]";
  for (const auto& c : log.channels) {
    buf += ',';
    buf += c.name;
    if (!c.unit.empty()) buf += " [" + c.unit + "]";
  }
  buf += '\n';
  for (std::size_t i = 0; i < log.time.size(); ++i) {
    append(buf, log.time[i]);
    for (const auto& c : log.channels) {
      buf += ',';
      if (!std::isnan(c.values[i])) append(buf, c.values[i]);
    }
    buf += '\n';
    if (buf.size() > (1 << 20) - 4096) {
      out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
      buf.clear();
    }
  }
  out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
}

void writeInterchangeCsv(const MissionLog& log, const std::filesystem::path& path) {
  checkWritable(log);  // before touching the file
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out)
    throw InputError("output", "cannot create the file", "check the directory and its permissions",
                     {path.string(), 0, 0});
  writeInterchangeCsv(log, out);
  out.flush();
  if (!out)
    throw InputError("output", "writing failed (disk full?)", "free space and write again",
                     {path.string(), 0, 0});
}

}  // namespace auv
