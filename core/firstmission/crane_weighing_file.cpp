#include "firstmission/crane_weighing_file.h"

#include "vehicle/json_reader.h"

namespace auv {

namespace {

CraneWeighingFile fromJson(const nlohmann::json& doc, const std::string& file) {
  const JsonReader root(doc, file);
  constexpr std::string_view kDoc = "docs/formats/crane-weighing.md";
  root.refuseUnknownKeys({"method", "vehicle", "comment", "scales_kg", "total_kg", "rope_x_m", "rope_y_m", "installed_kg",
                          "use_optional_pieces", "water"},
                         kDoc);
  CraneWeighingFile out;
  const std::string method = root.text("method");
  if (method != "crane") root.fail("method", "expected \"crane\", got \"" + method + "\"", "use a crane weighing file");
  out.vehicle = root.text("vehicle");
  const JsonReader s = root.child("scales_kg");
  s.refuseUnknownKeys({"fore_starboard", "fore_port", "aft_starboard", "aft_port"}, kDoc);
  const char* keys[4] = {"fore_starboard", "fore_port", "aft_starboard", "aft_port"};
  for (std::size_t i = 0; i < 4; ++i) out.input.weighing.scales_kg[i] = s.numberIn(keys[i], 0.0, 1e5);
  out.input.weighing.total_kg = root.numberIn("total_kg", 0.0, 1e5);
  const JsonReader rope = root.child("rope_x_m");
  rope.refuseUnknownKeys({"fore", "aft"}, kDoc);
  out.input.weighing.rope_x_fore_m = rope.numberIn("fore", -100.0, 100.0);
  out.input.weighing.rope_x_aft_m = rope.numberIn("aft", -100.0, 100.0);
  out.input.weighing.rope_y_m = root.numberIn("rope_y_m", 0.001, 10.0, out.input.weighing.rope_y_m);
  if (root.has("installed_kg")) out.input.installed_kg = root.numbers("installed_kg");
  const JsonReader w = root.child("water");
  w.refuseUnknownKeys({"temperature_degC", "salinity_psu", "depth_m", "latitude_deg"}, kDoc);
  out.input.water.temperature_degC = w.numberIn("temperature_degC", -2.0, 40.0);
  out.input.water.salinity_psu = w.numberIn("salinity_psu", 0.0, 42.0);
  out.input.water.depth_m = w.numberIn("depth_m", 0.0, 11000.0, 0.0);
  out.input.water.latitude_deg = w.numberIn("latitude_deg", -90.0, 90.0, 45.0);
  if (root.has("use_optional_pieces")) {
    const auto& flag = root.node().at("use_optional_pieces");
    if (!flag.is_boolean()) root.fail("use_optional_pieces", "expected true or false", "write true or false without quotes");
    out.input.use_optional_pieces = flag.get<bool>();
  }
  return out;
}

}  // namespace

CraneWeighingFile loadCraneWeighingFile(const std::string& file) { return fromJson(JsonReader::parseFile(file), file); }

CraneWeighingFile parseCraneWeighingFile(const std::string& json_text, const std::string& file) {
  return fromJson(JsonReader::parseText(json_text, file), file);
}

}  // namespace auv
