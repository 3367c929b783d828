#include "vehicle/json_reader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

#include "vehicle/nearest_key.h"

namespace auv {

JsonReader::JsonReader(const nlohmann::json& node, std::string file, std::string path)
    : node_(node), file_(std::move(file)), path_(std::move(path)) {}

nlohmann::json JsonReader::parseFile(const std::string& file) {
  // A folder would read as empty text ("invalid JSON at 1:1") and a FIFO would
  // block forever: only a regular file is a JSON input.
  struct stat st {};
  if (::stat(file.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    throw InputError("", S_ISDIR(st.st_mode) ? "is a folder, not a JSON file" : "is not a regular file (FIFO or device)",
                     "give the path of the .json file itself", {file, 0, 0});
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw InputError("", "cannot open file '" + file + "'",
                     "check the path and that the file is readable");
  }
  std::stringstream ss;
  ss << in.rdbuf();
  return parseText(ss.str(), file);
}

nlohmann::json JsonReader::parseText(const std::string& text, const std::string& file) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // Turn the byte offset into line/column for the operator's editor.
    long line = 1, col = 1;
    const std::size_t stop = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    for (std::size_t i = 0; i < stop; ++i) {
      if (text[i] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
    std::string what = e.what();
    const auto pos = what.rfind(": ");
    if (pos != std::string::npos) what = what.substr(pos + 2);
    throw InputError("", "invalid JSON (" + what + ")",
                     "fix the syntax at this position", {file, line, col});
  } catch (const nlohmann::json::out_of_range& e) {
    // A number beyond double range (1e999): the library names the token only.
    std::string what = e.what();
    const auto q1 = what.find('\'');
    const auto q2 = q1 == std::string::npos ? q1 : what.find('\'', q1 + 1);
    const std::string token = q2 == std::string::npos ? std::string() : what.substr(q1 + 1, q2 - q1 - 1);
    long line = 1, col = 1;
    const std::size_t at = token.empty() ? std::string::npos : text.find(token);
    for (std::size_t i = 0; at != std::string::npos && i < at; ++i) {
      if (text[i] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
    throw InputError("", "number " + (token.empty() ? std::string("") : token + " ") + "is beyond the range of a double",
                     "write a physical value (e.g. 12.5)", {file, at == std::string::npos ? 0 : line,
                                                          at == std::string::npos ? 0 : col});
  }
}

void JsonReader::refuseUnknownKeys(std::initializer_list<std::string_view> known, std::string_view doc) const {
  refuseUnknownKeys(std::vector<std::string>(known.begin(), known.end()), doc);
}

void JsonReader::refuseUnknownKeys(const std::vector<std::string>& known, std::string_view doc) const {
  if (!node_.is_object()) fail("", "expected a JSON object", "wrap the fields in { }");
  for (const auto& [key, value] : node_.items()) {
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    const std::string near = nearestKey(key, known);
    std::string fix = near.empty() ? std::string() : "did you mean " + near + "? ";
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    fix += "remove or rename it; the fields allowed here are: " + list;
    if (!doc.empty()) fix += " (see " + std::string(doc) + ")";
    const std::string shown = key.size() > 60 ? key.substr(0, 60) + "..." : key;
    throw InputError(fieldPath(shown), "unknown field", fix, {file_, 0, 0});
  }
}

std::string JsonReader::fieldPath(const std::string& key) const {
  if (path_.empty()) return key;
  if (!key.empty() && key.front() == '[') return path_ + key;
  return path_ + "." + key;
}

void JsonReader::fail(const std::string& key, const std::string& problem,
                      const std::string& fix) const {
  throw InputError(fieldPath(key), problem, fix, {file_, 0, 0});
}

bool JsonReader::has(const std::string& key) const {
  return node_.is_object() && node_.contains(key) && !node_.at(key).is_null();
}

const nlohmann::json& JsonReader::at(const std::string& key) const {
  if (!node_.is_object()) fail("", "expected a JSON object", "wrap the fields in { }");
  if (!has(key)) fail(key, "missing required field", "add \"" + key + "\" to the file");
  return node_.at(key);
}

JsonReader JsonReader::child(const std::string& key) const {
  const auto& n = at(key);
  if (!n.is_object()) fail(key, "expected an object", "write it as { ... }");
  return JsonReader(n, file_, fieldPath(key));
}

std::optional<JsonReader> JsonReader::optionalChild(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  return child(key);
}

std::vector<JsonReader> JsonReader::array(const std::string& key) const {
  const auto& n = at(key);
  if (!n.is_array()) fail(key, "expected an array", "write it as [ {...}, ... ]");
  std::vector<JsonReader> out;
  for (std::size_t i = 0; i < n.size(); ++i) {
    out.emplace_back(n[i], file_, fieldPath(key) + "[" + std::to_string(i) + "]");
    if (!n[i].is_object()) out.back().fail("", "expected an object", "write it as { ... }");
  }
  return out;
}

double JsonReader::number(const std::string& key) const {
  const auto& n = at(key);
  if (!n.is_number()) fail(key, "expected a number, got " + n.dump(), "write a plain number such as 12.5");
  const double v = n.get<double>();
  if (!std::isfinite(v)) fail(key, "value is not finite", "write a finite number");
  return v;
}

double JsonReader::number(const std::string& key, double fallback) const {
  return has(key) ? number(key) : fallback;
}

double JsonReader::numberIn(const std::string& key, double lo, double hi) const {
  const double v = number(key);
  if (v < lo || v > hi) {
    std::ostringstream range;
    range << "use a value between " << lo << " and " << hi;
    std::ostringstream got;
    got << "value " << v << " is out of range";
    fail(key, got.str(), range.str());
  }
  return v;
}

double JsonReader::numberIn(const std::string& key, double lo, double hi, double fallback) const {
  return has(key) ? numberIn(key, lo, hi) : fallback;
}

std::vector<double> JsonReader::numbers(const std::string& key) const {
  const auto& n = at(key);
  if (!n.is_array()) fail(key, "expected an array of numbers", "write it as [1.2, 2.4]");
  std::vector<double> out;
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (!n[i].is_number()) {
      fail(key + "[" + std::to_string(i) + "]", "expected a number", "write a plain number");
    }
    out.push_back(n[i].get<double>());
  }
  return out;
}

std::string JsonReader::text(const std::string& key) const {
  const auto& n = at(key);
  if (!n.is_string()) fail(key, "expected a string", "write it in double quotes");
  return n.get<std::string>();
}

std::string JsonReader::text(const std::string& key, const std::string& fallback) const {
  return has(key) ? text(key) : fallback;
}

}  // namespace auv
