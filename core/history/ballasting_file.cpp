#include "history/ballasting_file.h"

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "common/input_error.h"
#include "history/configuration_id.h"
#include "history/number_text.h"

namespace auv {
namespace {

constexpr std::array<const char*, 11> kColumns = {
    "Config",      "Date",        "Type",           "Area",           "Salinity",     "Temperature",
    "TotalWeight", "AddedWeight", "DepthDeviation", "PitchDeviation", "RollDeviation"};
constexpr const char* kUnknown = "Unknown";

struct Token {
  std::string text;
  long line = 0, column = 0;
};

// Fields are separated by tabs and line breaks; the thesis wraps one record
// over several lines and ends lines with a tab, so empty fields are dropped.
std::vector<Token> tokenize(const std::string& text) {
  std::vector<Token> out;
  long line = 1, col = 1;
  Token cur;
  auto flush = [&] {
    const auto b = cur.text.find_first_not_of(' ');
    if (b != std::string::npos) {
      cur.text = cur.text.substr(b, cur.text.find_last_not_of(' ') - b + 1);
      out.push_back(cur);
    }
    cur = Token{};
  };
  for (char c : text) {
    if (c == '\t' || c == '\n' || c == '\r') {
      flush();
    } else {
      if (cur.text.empty()) {
        cur.line = line;
        cur.column = col;
      }
      cur.text += c;
    }
    if (c == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  flush();
  return out;
}

bool equalsNoCase(const std::string& a, const char* b) {
  std::size_t i = 0;
  for (; i < a.size() && b[i]; ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  return i == a.size() && b[i] == 0;
}

class RecordReader {
 public:
  RecordReader(const std::vector<Token>& t, std::size_t first, const std::string& file)
      : t_(t), first_(first), file_(file) {}

  [[noreturn]] void fail(std::size_t k, const std::string& problem, const std::string& fix) const {
    const Token& tok = t_[first_ + k];
    throw InputError(kColumns[k], problem, fix, {file_, tok.line, tok.column});
  }
  const std::string& text(std::size_t k) const { return t_[first_ + k].text; }

  std::optional<double> number(std::size_t k, double lo, double hi) const {
    if (text(k) == kUnknown) return std::nullopt;
    const auto v = parseNumber(text(k));
    if (!v) fail(k, "'" + text(k) + "' is not a number", "write a number or Unknown");
    if (*v < lo || *v > hi)
      fail(k, "value " + text(k) + " is outside " + formatShortest(lo) + ".." + formatShortest(hi),
           "check the value");
    return v;
  }

  TimePoint date(std::size_t k) const {
    // d.m.yyyy-h:mm with one or two digits for day, month, hour and minute.
    int d = 0, m = 0, y = 0, h = 0, mi = 0, used = 0;
    const std::string& s = text(k);
    if (std::sscanf(s.c_str(), "%2d.%2d.%4d-%2d:%2d%n", &d, &m, &y, &h, &mi, &used) != 5 ||
        used != int(s.size()) || y < 1000)
      fail(k, "'" + s + "' is not a date", "write dd.mm.yyyy-hh:mm, e.g. 4.4.2014-15:28");
    try {
      return makeUtc(y, unsigned(m), unsigned(d), h, mi, 0);
    } catch (const InputError& e) {
      fail(k, e.problem(), "write dd.mm.yyyy-hh:mm, e.g. 4.4.2014-15:28");
    }
  }

  std::vector<double> masses(std::size_t k) const {
    std::vector<double> out;
    std::string part;
    std::istringstream in(text(k));
    while (std::getline(in, part, ':')) {
      const auto v = parseNumber(part);
      if (!v || *v < 0.0 || *v > 1000.0)
        fail(k, "'" + text(k) + "' is not a list of added masses",
             "write kg per point separated by ':', e.g. 0:0:19.2:19.2");
      out.push_back(*v);
    }
    if (out.empty() || text(k).back() == ':')
      fail(k, "'" + text(k) + "' is not a list of added masses",
           "write kg per point separated by ':', e.g. 0:0:19.2:19.2");
    return out;
  }

  BallastingRow row() const {
    BallastingRow r;
    r.line = t_[first_].line;
    r.config_id = text(0);
    if (!isValidConfigurationId(r.config_id))
      fail(0, "'" + r.config_id + "' is not an xx-xx-xx code", "e.g. 1-2-3 or sys-0-0");
    r.at = date(1);
    r.vehicle_type = text(2);
    r.area = text(3) == kUnknown ? "" : text(3);
    r.salinity_psu = number(4, 0.0, 45.0);
    r.temperature_degC = number(5, -3.0, 45.0);
    r.total_weight_kg = number(6, 0.0, 1e5);
    r.added_kg = masses(7);
    r.depth_deviation_m = number(8, -1e4, 1e4);
    r.pitch_deviation_deg = number(9, -90.0, 90.0);
    r.roll_deviation_deg = number(10, -180.0, 180.0);
    return r;
  }

 private:
  const std::vector<Token>& t_;
  std::size_t first_;
  const std::string& file_;
};

std::string field(const std::optional<double>& v) { return v ? formatShortest(*v) : kUnknown; }

// Tabs and line breaks are the separators; inside a name they become spaces.
std::string name(const std::string& s) {
  std::string out = s;
  for (char& c : out)
    if (c == '\t' || c == '\n' || c == '\r') c = ' ';
  return out.find_first_not_of(' ') == std::string::npos ? std::string(kUnknown) : out;
}

std::string dateText(TimePoint t) {
  using namespace std::chrono;
  const auto day = floor<days>(t);
  const year_month_day ymd{day};
  const hh_mm_ss hms{t - day};
  char buf[48];
  std::snprintf(buf, sizeof buf, "%u.%u.%d-%02d:%02d", unsigned(ymd.day()), unsigned(ymd.month()),
                int(ymd.year()), int(hms.hours().count()), int(hms.minutes().count()));
  return buf;
}
}  // namespace

BallastingFile parseBallastingFile(const std::string& text, const std::string& file_name) {
  const std::vector<Token> tokens = tokenize(text);
  const std::string header_fix =
      "the file must start with the 11 column names Config, Date, Type, Area, Salinity, "
      "Temperature, TotalWeight, AddedWeight, DepthDeviation, PitchDeviation, RollDeviation, "
      "separated by tabs";
  for (std::size_t k = 0; k < kColumns.size(); ++k) {
    if (k >= tokens.size())
      throw InputError("header", "file ends before column '" + std::string(kColumns[k]) + "'",
                       header_fix, {file_name, 0, 0});
    if (!equalsNoCase(tokens[k].text, kColumns[k]))
      throw InputError("header",
                       "expected column '" + std::string(kColumns[k]) + "', found '" +
                           tokens[k].text + "'",
                       header_fix, {file_name, tokens[k].line, tokens[k].column});
  }
  const std::size_t body = tokens.size() - kColumns.size();
  if (body % kColumns.size() != 0) {
    const Token& start = tokens[tokens.size() - body % kColumns.size()];
    throw InputError("record",
                     "the last record has " + std::to_string(body % kColumns.size()) +
                         " of 11 fields",
                     "complete the record (write Unknown for a value not known; fields are "
                     "separated by tabs)",
                     {file_name, start.line, start.column});
  }
  BallastingFile out;
  for (std::size_t first = kColumns.size(); first < tokens.size(); first += kColumns.size()) {
    try {
      out.rows.push_back(RecordReader(tokens, first, file_name).row());
    } catch (const InputError& e) {
      out.warnings.push_back(std::string(e.what()) + " (record skipped)");
    }
  }
  return out;
}

BallastingFile readBallastingFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError("ballasting file", "cannot open '" + path + "'",
                     "check the path; the thesis keeps it as <config-id>/ballasting");
  std::ostringstream text;
  text << in.rdbuf();
  return parseBallastingFile(text.str(), path);
}

std::string formatBallastingFile(const std::vector<BallastingRow>& rows) {
  std::string s =
      "Config\tDate\tType\tArea\nSalinity\tTemperature\tTotalWeight\tAddedWeight\n"
      "DepthDeviation\tPitchDeviation\tRollDeviation\t\n";
  for (const BallastingRow& r : rows) {
    std::string added;
    for (double m : r.added_kg) {
      if (!added.empty()) added += ':';
      added += formatShortest(m);
    }
    s += r.config_id + "\t" + dateText(r.at) + "\t" + name(r.vehicle_type) + "\t" + name(r.area) +
         "\n";
    s += field(r.salinity_psu) + "\t" + field(r.temperature_degC) + "\t" + field(r.total_weight_kg) +
         "\t" + added + "\n";
    s += field(r.depth_deviation_m) + "\t" + field(r.pitch_deviation_deg) + "\t" +
         field(r.roll_deviation_deg) + "\t\n";
  }
  return s;
}

std::vector<std::string> ballastingPointNames(std::size_t count) {
  if (count == 4) return {"fore_starboard", "fore_port", "aft_starboard", "aft_port"};
  std::vector<std::string> names;
  for (std::size_t i = 1; i <= count; ++i) names.push_back("point" + std::to_string(i));
  return names;
}

}  // namespace auv
