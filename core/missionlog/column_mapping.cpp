#include "missionlog/column_mapping.h"

#include <fstream>
#include <nlohmann/json.hpp>

#include "common/input_error.h"
#include "missionlog/unit_conversion.h"
#include "missionlog/unit_spelling.h"
#include "vehicle/json_reader.h"

namespace auv {
namespace {

constexpr int kVersion = 1;

void refuseUnknownKeys(const JsonReader& r, std::initializer_list<std::string_view> known) {
  r.refuseUnknownKeys(known, "docs/formats/column-mapping.md");
}

bool flag(const JsonReader& r, const std::string& key, bool fallback) {
  if (!r.has(key)) return fallback;
  const auto& n = r.node().at(key);
  if (!n.is_boolean()) r.fail(key, "expected true or false, got " + n.dump(), "write true or false without quotes");
  return n.get<bool>();
}

template <class E, std::size_t N>
E choice(const JsonReader& r, const std::string& key, const std::pair<const char*, E> (&options)[N], E fallback) {
  if (!r.has(key)) return fallback;
  const std::string v = r.text(key);
  std::string list;
  for (const auto& [name, e] : options) {
    if (v == name) return e;
    list += (list.empty() ? "\"" : ", \"") + std::string(name) + "\"";
  }
  r.fail(key, "unknown value \"" + v + "\"", "use one of " + list);
}

constexpr std::pair<const char*, Delimiter> kDelimiters[] = {
    {"auto", Delimiter::kAuto}, {",", Delimiter::kComma}, {";", Delimiter::kSemicolon},
    {"tab", Delimiter::kTab},   {"whitespace", Delimiter::kWhitespace}};
constexpr std::pair<const char*, DecimalMark> kDecimals[] = {
    {"auto", DecimalMark::kAuto}, {".", DecimalMark::kPoint}, {",", DecimalMark::kComma}};
constexpr std::pair<const char*, TimeFormat> kTimeFormats[] = {
    {"auto", TimeFormat::kAuto},
    {"seconds", TimeFormat::kSeconds},
    {"epoch", TimeFormat::kEpochSeconds},
    {"iso8601", TimeFormat::kIso8601},
    {"dd.mm.yyyy hh:mm:ss", TimeFormat::kDayMonthYear},
    {"hh:mm:ss", TimeFormat::kTimeOfDay}};

template <class E, std::size_t N>
const char* nameOf(E e, const std::pair<const char*, E> (&options)[N]) {
  for (const auto& [name, v] : options)
    if (v == e) return name;
  return "auto";
}

void checkChannelName(const JsonReader& r, const std::string& key, const std::string& name) {
  if (name.empty()) r.fail(key, "empty channel name", "name the channel, e.g. \"depth\", or set \"ignore\": true");
  if (name == "time") r.fail(key, "\"time\" is not a channel", "name the time column in \"time\": {\"column\": ...}");
  if (name.find_first_of(",[]\"\r\n#") != std::string::npos)
    r.fail(key, "channel name \"" + name + "\" contains one of , [ ] \" #", "use letters, digits and '_'");
}

}  // namespace

const char* toString(Delimiter d) { return nameOf(d, kDelimiters); }
const char* toString(DecimalMark d) { return nameOf(d, kDecimals); }
const char* toString(TimeFormat f) { return nameOf(f, kTimeFormats); }

ColumnMapping ColumnMapping::fromJson(const std::string& text, const std::string& sourceName) {
  const nlohmann::json doc = JsonReader::parseText(text, sourceName);
  const JsonReader r(doc, sourceName);
  refuseUnknownKeys(r, {"column_mapping_version", "vehicle", "description", "delimiter", "decimal", "time",
                        "columns", "metadata"});
  const double version = r.number("column_mapping_version");
  if (version != kVersion)
    r.fail("column_mapping_version", "version " + r.node().at("column_mapping_version").dump() + " is not supported",
           "this program reads version 1");
  ColumnMapping m;
  m.vehicle = r.text("vehicle", "");
  m.description = r.text("description", "");
  m.delimiter = choice(r, "delimiter", kDelimiters, Delimiter::kAuto);
  m.decimal = choice(r, "decimal", kDecimals, DecimalMark::kAuto);
  if (m.delimiter == Delimiter::kComma && m.decimal == DecimalMark::kComma)
    r.fail("decimal", "a decimal comma cannot be used with a comma delimiter", "use \".\" or another delimiter");
  if (auto t = r.optionalChild("time")) {
    refuseUnknownKeys(*t, {"column", "format", "unit", "date_column", "utc_offset_hours"});
    m.time.column = t->text("column", "");
    m.time.format = choice(*t, "format", kTimeFormats, TimeFormat::kAuto);
    m.time.unit = t->text("unit", "");
    if (!m.time.unit.empty() && !unitConversion(normaliseUnitSpelling(m.time.unit), "s"))
      t->fail("unit", "\"" + m.time.unit + "\" is not a time unit", "use s, ms, min or h");
    m.time.date_column = t->text("date_column", "");
    if (t->has("utc_offset_hours")) m.time.utc_offset_hours = t->numberIn("utc_offset_hours", -14.0, 14.0);
  }
  if (r.has("columns")) {
    for (const JsonReader& c : r.array("columns")) {
      refuseUnknownKeys(c, {"header", "channel", "unit", "scale", "offset", "ignore"});
      ColumnRule rule;
      rule.header = c.text("header");
      if (normaliseChannelKey(rule.header).empty()) c.fail("header", "empty header", "write the column's header text");
      rule.ignore = flag(c, "ignore", false);
      if (!rule.ignore) {
        rule.channel = c.text("channel");
        checkChannelName(c, "channel", rule.channel);
      }
      rule.unit = c.text("unit", "");
      rule.scale = c.number("scale", 1.0);
      if (rule.scale == 0.0) c.fail("scale", "scale 0 would erase the column", "use 1 (or -1 to flip a sign)");
      rule.offset = c.number("offset", 0.0);
      const std::string canonical(canonicalUnitFor(rule.channel));
      if (!canonical.empty() && !rule.unit.empty() &&
          !unitConversion(normaliseUnitSpelling(rule.unit), canonical)) {
        std::string accepted;
        for (const auto& u : unitsConvertibleTo(canonical)) accepted += (accepted.empty() ? "" : ", ") + u;
        c.fail("unit", "\"" + rule.unit + "\" cannot be converted to [" + canonical + "], the unit of " + rule.channel,
               "use one of: " + accepted);
      }
      m.columns.push_back(std::move(rule));
    }
  }
  if (r.has("metadata")) {
    const auto& md = doc.at("metadata");
    if (!md.is_object()) r.fail("metadata", "expected an object of strings", "write it as {\"key\": \"value\"}");
    for (const auto& [key, value] : md.items()) {
      if (!value.is_string())
        r.fail("metadata." + key, "expected a string", "write the value in double quotes");
      if (key.empty() || key.find(':') != std::string::npos || key.find('\n') != std::string::npos)
        r.fail("metadata." + key, "a metadata key must be non-empty and without ':'", "rename the key");
      m.metadata.push_back({key, value.get<std::string>()});
    }
  }
  return m;
}

ColumnMapping ColumnMapping::load(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw InputError("column mapping", "is a folder, FIFO or device, not a column-mapping file",
                     "give the path of the mapping .json file (docs/formats/column-mapping.md)", {path.string(), 0, 0});
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError("column mapping", "cannot open file", "check the path of the column mapping",
                     {path.string(), 0, 0});
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return fromJson(text, path.string());
}

std::string ColumnMapping::toJson() const {
  nlohmann::ordered_json j;
  j["column_mapping_version"] = kVersion;
  if (!vehicle.empty()) j["vehicle"] = vehicle;
  if (!description.empty()) j["description"] = description;
  j["delimiter"] = toString(delimiter);
  j["decimal"] = toString(decimal);
  nlohmann::ordered_json t;
  if (!time.column.empty()) t["column"] = time.column;
  t["format"] = toString(time.format);
  if (!time.unit.empty()) t["unit"] = time.unit;
  if (!time.date_column.empty()) t["date_column"] = time.date_column;
  if (time.utc_offset_hours) t["utc_offset_hours"] = *time.utc_offset_hours;
  j["time"] = t;
  j["columns"] = nlohmann::ordered_json::array();
  for (const auto& c : columns) {
    nlohmann::ordered_json o;
    o["header"] = c.header;
    if (c.ignore) {
      o["ignore"] = true;
    } else {
      o["channel"] = c.channel;
    }
    if (!c.unit.empty()) o["unit"] = c.unit;
    if (c.scale != 1.0) o["scale"] = c.scale;
    if (c.offset != 0.0) o["offset"] = c.offset;
    j["columns"].push_back(o);
  }
  if (!metadata.empty()) {
    nlohmann::ordered_json md = nlohmann::ordered_json::object();
    for (const auto& e : metadata) md[e.key] = e.value;
    j["metadata"] = md;
  }
  return j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

void ColumnMapping::save(const std::filesystem::path& path) const {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << toJson();
  out.flush();
  if (!out)
    throw InputError("column mapping", "cannot write file", "check that the folder exists and is writable",
                     {path.string(), 0, 0});
}

bool ColumnMapping::matches(const std::string& name, const HeaderField& field) {
  const std::string key = normaliseChannelKey(name);
  return !key.empty() && (key == normaliseChannelKey(field.text) || key == field.key);
}

const ColumnRule* ColumnMapping::ruleFor(const HeaderField& field) const {
  for (const auto& c : columns)  // the full header text first: "Depth (m)" vs "Depth (ft)"
    if (normaliseChannelKey(c.header) == normaliseChannelKey(field.text)) return &c;
  for (const auto& c : columns)
    if (normaliseChannelKey(c.header) == field.key) return &c;
  return nullptr;
}

}  // namespace auv
