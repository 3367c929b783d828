#include "missionlog/slocum_ascii_reader.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>

#include "common/input_error.h"
#include "missionlog/channel_aliases.h"
#include "missionlog/detail/ascii_text.h"
#include "missionlog/detail/line_cells.h"
#include "missionlog/detail/report_problem.h"
#include "missionlog/detail/slocum_channels.h"
#include "missionlog/log_table.h"
#include "missionlog/text_cells.h"
#include "missionlog/text_lines.h"
#include "missionlog/unit_spelling.h"

namespace auv {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kMaxSensors = 20000;

using detail::splitBlanks;
using detail::trim;
using Token = detail::Cell;

// `key: value` with a key of letters, digits and '_'.
bool tagLine(std::string_view line, std::string& key, std::string& value) {
  const auto colon = line.find(':');
  if (colon == std::string_view::npos || colon == 0) return false;
  const std::string_view k = line.substr(0, colon);
  for (char c : k)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_')) return false;
  key = std::string(k);
  value = std::string(trim(line.substr(colon + 1)));
  return true;
}

enum class Stream { kEngineering, kScience };

class SlocumParser {
 public:
  SlocumParser(std::string file, const ReadOptions& o, ReadReport& r) : file_(std::move(file)), opt_(o), rep_(r) {}
  bool line(std::string_view text, LineFlag flag);
  MissionLog finish();

 private:
  enum class State { kTags, kLabels, kData };
  void problem(ReadProblemKind kind, long column, std::string channel, std::string what, std::string fix) {
    detail::reportProblem(rep_, opt_, kind, {file_, line_, column}, std::move(channel), std::move(what), std::move(fix));
  }
  void skip(ReadProblemKind kind, long column, std::string channel, std::string what, std::string fix) {
    ++rep_.rows_skipped;
    problem(kind, column, std::move(channel), std::move(what), std::move(fix));
  }
  void labelLine(std::string_view text, LineFlag flag);
  void plan();
  void dataLine(std::string_view text, LineFlag flag);
  long tagValue(const char* key, long fallback) const;

  std::string file_;
  const ReadOptions& opt_;
  ReadReport& rep_;
  State state_ = State::kTags;
  long long line_ = 0;
  std::vector<MetadataEntry> tags_;
  std::vector<std::vector<std::string>> labels_;
  long labelLines_ = 3;
  long long labelLineNo_ = 0;
  std::vector<std::string> sensors_, units_;
  std::optional<std::size_t> engTime_, sciTime_, engSecs_, sciSecs_;
  std::vector<int> target_;  // per sensor: column index, -1 = time
  std::vector<char> nmea_;
  std::vector<TableColumn> columns_;
  LogTable eng_, sci_;
  std::vector<Token> tokens_;
  std::vector<double> row_;
  bool relative_ = false;
};

long SlocumParser::tagValue(const char* key, long fallback) const {
  for (const auto& t : tags_)
    if (t.key == key) {
      char* end = nullptr;
      const long v = std::strtol(t.value.c_str(), &end, 10);
      return end && *end == '\0' && !t.value.empty() ? v : fallback;
    }
  return fallback;
}

bool SlocumParser::line(std::string_view text, LineFlag flag) {
  ++line_;
  if (line_ == 1 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  switch (state_) {
    case State::kTags: {
      if (flag == LineFlag::kOverlong)
        throw InputError("header", "line " + std::to_string(line_) + " of the header is longer than " +
                                       std::to_string(opt_.block_bytes) + " bytes (binary data?)",
                         "this is not a dbd2asc text file", {file_, line_, 0});
      std::string key, value;
      if (line_ == 1 && (!tagLine(text, key, value) || key != "dbd_label"))
        throw InputError("dbd_label", "the file does not start with `dbd_label:`",
                         "convert the binary .dbd/.ebd files with dbd2asc (or dba_merge) and read the output",
                         {file_, 1, 1});
      if (tagLine(text, key, value)) {
        tags_.push_back({key, value});
        return true;
      }
      labelLines_ = tagValue("num_label_lines", 3);
      if (labelLines_ < 1 || labelLines_ > 10) labelLines_ = 3;
      state_ = State::kLabels;
      labelLineNo_ = line_;
      [[fallthrough]];
    }
    case State::kLabels:
      if (flag == LineFlag::kOverlong) throw InputError("labels", "a label line is longer than the read block",
                                                        "this is not a dbd2asc text file", {file_, line_, 0});
      labelLine(text, flag);
      return true;
    case State::kData:
      dataLine(text, flag);
      return true;
  }
  return true;
}

void SlocumParser::labelLine(std::string_view text, LineFlag flag) {
  std::vector<Token> t;
  splitBlanks(text, t);
  if (labels_.size() == 2) {
    // The bytes line holds 1, 2, 4 or 8 per sensor. Anything else means it is
    // missing and this is already the first row.
    bool bytes = t.size() == labels_[0].size();
    for (const auto& k : t) bytes = bytes && (k.text == "1" || k.text == "2" || k.text == "4" || k.text == "8");
    if (!bytes) {
      tags_.push_back({"note", "the bytes label line is missing; line " + std::to_string(line_) + " is read as data"});
      plan();
      dataLine(text, flag);
      return;
    }
  }
  std::vector<std::string> cells;
  for (const auto& k : t) cells.emplace_back(k.text);
  labels_.push_back(std::move(cells));
  if (static_cast<long>(labels_.size()) == labelLines_) plan();
}

void SlocumParser::plan() {
  sensors_ = labels_[0];
  const InputLocation namesAt{file_, labelLineNo_, 1};
  if (sensors_.empty())
    throw InputError("sensors", "the sensor-name line after the header tags is empty",
                     "the file needs the three dbd2asc label lines (names, units, bytes)", namesAt);
  if (sensors_.size() > kMaxSensors)
    throw InputError("sensors", "more than " + std::to_string(kMaxSensors) + " sensors", "this is not a dbd2asc file",
                     namesAt);
  {
    double v = 0;
    bool numbers = true;  // sensor names never read as numbers or NaN
    for (const auto& name : sensors_) numbers = numbers && parseNumberCell(name, false, v) != CellValue::kBad;
    if (numbers)
      throw InputError("sensors", "the line after the header tags holds numbers, not sensor names",
                       "the three label lines (sensor names, units, bytes) are missing; export with dbd2asc again",
                       namesAt);
  }
  if (labels_.size() >= 2) units_ = labels_[1];
  if (units_.size() != sensors_.size()) {
    problem(ReadProblemKind::kUnitAssumed, 0, "",
            "the units line has " + std::to_string(units_.size()) + " entries for " + std::to_string(sensors_.size()) +
                " sensors; the units line is ignored (the Slocum units of the known sensors are used)",
            "export the file with dbd2asc again");
    units_.assign(sensors_.size(), "");
  }
  const long spc = tagValue("sensors_per_cycle", static_cast<long>(sensors_.size()));
  if (spc != static_cast<long>(sensors_.size()))
    tags_.push_back({"note", "sensors_per_cycle says " + std::to_string(spc) + ", the label line names " +
                                 std::to_string(sensors_.size()) + " sensors (the label line is used)"});

  target_.assign(sensors_.size(), -1);
  nmea_.assign(sensors_.size(), 0);
  std::map<std::string, std::size_t> used;
  for (std::size_t k = 0; k < sensors_.size(); ++k) {
    const std::string& s = sensors_[k];
    if (detail::isSlocumEngineeringTime(s)) { engTime_ = k; continue; }
    if (detail::isSlocumScienceTime(s)) { sciTime_ = k; continue; }
    if (s == "m_present_secs_into_mission") engSecs_ = k;
    if (s == "sci_m_present_secs_into_mission") sciSecs_ = k;
    bool nmea = false;
    TableColumn c = detail::slocumColumn(s, units_[k], {file_, labelLineNo_, 0}, nmea);
    nmea_[k] = nmea ? 1 : 0;
    target_[k] = static_cast<int>(columns_.size());
    columns_.push_back(std::move(c));
  }
  if (!engTime_ && !sciTime_) {
    if (!engSecs_ && !sciSecs_)
      throw InputError("time",
                       "none of the " + std::to_string(sensors_.size()) +
                           " sensors is m_present_time or sci_m_present_time",
                       "export the file including m_present_time (and sci_m_present_time for science data)",
                       namesAt);
    // Seconds into the mission are a relative clock; they stay channels too.
    relative_ = true;
  }
  for (LogTable* t : {&eng_, &sci_}) {
    t->file = file_;
    t->epoch = !relative_;
    t->columns = columns_;
  }
  eng_.tag = "eng";
  sci_.tag = "sci";
  row_.assign(sensors_.size(), kNaN);
  state_ = State::kData;
}

void SlocumParser::dataLine(std::string_view text, LineFlag flag) {
  if (flag == LineFlag::kOverlong) {
    ++rep_.data_lines;
    skip(ReadProblemKind::kOverlongLine, 0, "",
         "line is longer than " + std::to_string(opt_.block_bytes) + " bytes (binary data?); skipped",
         "remove the damaged part of the file");
    return;
  }
  if (trim(text).empty()) return;
  ++rep_.data_lines;
  splitBlanks(text, tokens_);
  const std::size_t n = sensors_.size();
  if (tokens_.size() != n) {
    const std::string counts = std::to_string(tokens_.size()) + " values for " + std::to_string(n) + " sensors";
    if (tokens_.size() < n && flag == LineFlag::kFinalNoNewline)
      skip(ReadProblemKind::kTruncatedLine, static_cast<long>(text.size()) + 1, "",
           "the last line is cut short (" + counts + "); row skipped",
           "the file was probably copied while dbd2asc was still writing it; convert it again");
    else
      skip(ReadProblemKind::kWrongCellCount,
           tokens_.size() > n ? static_cast<long>(tokens_[n].offset) + 1 : 0, "", "row has " + counts + "; row skipped",
           "a row must hold one value per sensor of the label line");
    return;
  }
  for (std::size_t k = 0; k < n; ++k) {
    double v = kNaN;
    switch (parseNumberCell(tokens_[k].text, false, v)) {
      case CellValue::kNumber: break;
      case CellValue::kEmpty: v = kNaN; break;
      case CellValue::kBad:
        skip(ReadProblemKind::kNotANumber, static_cast<long>(tokens_[k].offset) + 1, sensors_[k],
             "'" + printableText(tokens_[k].text) + "' is not a number; row skipped",
             "dbd2asc writes numbers or NaN; the file is damaged here");
        return;
    }
    if (nmea_[k] && !std::isnan(v) && std::isfinite(v)) v = detail::slocumNmeaToDegrees(v);
    row_[k] = v;
  }
  // Which clock times this row: the glider computer's, else the science bay's.
  double t = kNaN;
  Stream stream = Stream::kEngineering;
  if (!relative_) {
    if (engTime_ && !std::isnan(row_[*engTime_])) t = row_[*engTime_];
    else if (sciTime_ && !std::isnan(row_[*sciTime_])) {
      t = row_[*sciTime_];
      stream = Stream::kScience;
    } else if (!engTime_) {
      stream = Stream::kScience;
    }
  } else {
    if (engSecs_ && !std::isnan(row_[*engSecs_])) t = row_[*engSecs_];
    else if (sciSecs_ && !std::isnan(row_[*sciSecs_])) {
      t = row_[*sciSecs_];
      stream = Stream::kScience;
    }
  }
  if (flag == LineFlag::kFinalNoNewline)
    problem(ReadProblemKind::kNoFinalNewline, 0, "",
            "the last line has no line end; kept because it has all " + std::to_string(n) + " values",
            "end the file with a line break");
  LogTable& table = stream == Stream::kEngineering ? eng_ : sci_;
  const std::size_t rowIndex = table.time.size();
  table.time.push_back(t);
  table.row_where.push_back(line_);
  for (std::size_t k = 0; k < n; ++k) {
    const int c = target_[k];
    if (c < 0) continue;
    auto& vals = table.columns[static_cast<std::size_t>(c)].values;
    const double v = row_[k];
    if (vals.empty()) {
      if (std::isnan(v)) continue;
      vals.assign(rowIndex, kNaN);
    }
    vals.push_back(v);
  }
}

MissionLog SlocumParser::finish() {
  rep_.lines = line_;
  if (state_ == State::kTags)
    throw InputError("header", line_ == 0 ? "the file is empty" : "the file ends inside the header tags",
                     "the file was cut short; convert the .dbd/.ebd file with dbd2asc again", {file_, line_, 0});
  if (state_ == State::kLabels)
    throw InputError("labels",
                     "the file ends inside the label lines (" + std::to_string(labels_.size()) + " of " +
                         std::to_string(labelLines_) + ")",
                     "the file was cut short; convert the .dbd/.ebd file with dbd2asc again", {file_, line_, 0});
  if (eng_.time.empty() && sci_.time.empty()) {
    std::string why = "no data rows";
    if (rep_.data_lines > 0)
      why = "no usable data rows (" + std::to_string(rep_.data_lines) + " rows, all skipped; first: " +
            (rep_.problems.empty() ? std::string("?") : rep_.problems.front().text()) + ")";
    throw InputError("rows", why, "the file needs at least one row with m_present_time or sci_m_present_time",
                     {file_, line_, 0});
  }
  std::vector<LogTable> streams;
  streams.push_back(std::move(eng_));
  streams.push_back(std::move(sci_));
  return detail::finishSlocumLog(std::move(streams), tags_, opt_, rep_);
}

template <class Pull>
MissionLog run(const std::string& name, std::uint64_t total, Pull pull, const ReadOptions& options,
               ReadReport& report) {
  report = ReadReport{};
  report.file = name;
  report.format = "Slocum ASCII (dbd2asc)";
  try {
    SlocumParser parser(name, options, report);
    forEachLine(name, total, pull, options, [&](std::string_view l, LineFlag f) { return parser.line(l, f); });
    return parser.finish();
  } catch (const std::bad_alloc&) {
    throw InputError("log", "not enough memory to hold this log", "split the file or use a larger machine", {name, 0, 0});
  }
}

}  // namespace

bool SlocumAsciiReader::canRead(const std::filesystem::path&, std::string_view head) const {
  if (head.substr(0, 3) == "\xEF\xBB\xBF") head.remove_prefix(3);
  return head.substr(0, 10) == "dbd_label:";
}

MissionLog SlocumAsciiReader::read(const std::filesystem::path& path, const ReadOptions& options,
                                   ReadReport& report) const {
  return readSlocumAscii(path, options, report);
}

// A raw Slocum binary (.dbd/.ebd/.sbd/...) starts with the same `dbd_label:`
// tags as dbd2asc output; telling its owner to "export with m_present_time"
// would be wrong: it has to be converted (or read by a binary reader) first.
static void refuseRawSlocumBinary(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  static const char* const kBinary[] = {".dbd", ".ebd", ".sbd", ".tbd", ".mbd", ".nbd",
                                        ".dcd", ".ecd", ".scd", ".tcd", ".mcd", ".ncd"};
  for (const char* b : kBinary) {
    if (ext == b) {
      throw InputError("log", "is a raw Slocum binary file (" + ext + "), not dbd2asc text output",
                       "convert it with dbd2asc (with its cache files) and give the text output, or a glider NetCDF",
                       {path.string(), 0, 0});
    }
  }
}

MissionLog readSlocumAscii(const std::filesystem::path& path, const ReadOptions& options, ReadReport& report) {
  refuseRawSlocumBinary(path);
  BlockFile file(path);
  return run(file.name(), file.size(), FilePull{&file}, options, report);
}

MissionLog parseSlocumAscii(std::string_view text, const std::string& sourceName, const ReadOptions& options,
                            ReadReport& report) {
  return run(sourceName, text.size(), MemoryPull{text}, options, report);
}

}  // namespace auv
