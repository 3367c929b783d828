#pragma once
// Typed, path-aware access to a JSON document. Every failure names the file,
// the JSON path of the field and what a valid value looks like, so a typo in a
// vehicle profile reads as "hugin1000.json: adjustment_points[2].capacity_kg:
// must be >= 0; ..." instead of a library exception.
#include <nlohmann/json.hpp>
#include <optional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "common/input_error.h"

namespace auv {

class JsonReader {
 public:
  JsonReader(const nlohmann::json& node, std::string file, std::string path = {});

  // Parse a whole file; syntax errors carry line and column.
  static nlohmann::json parseFile(const std::string& file);
  static nlohmann::json parseText(const std::string& text, const std::string& file);

  bool has(const std::string& key) const;
  JsonReader child(const std::string& key) const;  // required object
  std::optional<JsonReader> optionalChild(const std::string& key) const;
  std::vector<JsonReader> array(const std::string& key) const;  // required array of objects

  double number(const std::string& key) const;
  double number(const std::string& key, double fallback) const;
  // Number with an inclusive admissible range; the message states the range.
  double numberIn(const std::string& key, double lo, double hi) const;
  double numberIn(const std::string& key, double lo, double hi, double fallback) const;
  std::vector<double> numbers(const std::string& key) const;
  std::string text(const std::string& key) const;
  std::string text(const std::string& key, const std::string& fallback) const;

  // Strict schema: every key of this object must be in `known`. An unknown key
  // is refused with the nearest known one ("did you mean installed_kg?") and
  // the format document (`doc`, an in-repo path) that lists the optional keys,
  // because a misspelt optional key would otherwise silently take its default.
  void refuseUnknownKeys(std::initializer_list<std::string_view> known, std::string_view doc) const;
  void refuseUnknownKeys(const std::vector<std::string>& known, std::string_view doc) const;

  const nlohmann::json& node() const { return node_; }
  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }
  std::string fieldPath(const std::string& key) const;
  [[noreturn]] void fail(const std::string& key, const std::string& problem,
                         const std::string& fix) const;

 private:
  const nlohmann::json& at(const std::string& key) const;
  const nlohmann::json& node_;
  std::string file_;
  std::string path_;
};

}  // namespace auv
