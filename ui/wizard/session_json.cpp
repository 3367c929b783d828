#include "wizard/session_json.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/input_error.h"
#include "discrepancy/profile_update.h"
#include "vehicle/json_reader.h"
#include "vehicle/vehicle_catalog.h"
#include "weighing/slocum_layout.h"
#include "weighing/tank_weighing_file.h"
#include "wizard/demo_state.h"

namespace auv::ui {
namespace {

constexpr int kSessionVersion = 1;
// Grams to the 1 mg the spin boxes show, so a reload reproduces the numbers exactly.
double g(double kg) { return std::round(kg * 1e6) / 1e3; }

}  // namespace

nlohmann::json tankWeighingToJson(const TankWeighing& w, bool salt_water) {
  nlohmann::json j;
  j["method"] = "tank";
  if (!w.vehicle.empty()) j["vehicle"] = w.vehicle;
  j["glider"] = w.glider;
  j["dry_mass_kg"] = w.readings.dry_mass_kg;
  nlohmann::json b;
  for (int i = 0; i < kSlocumItemCount; ++i) {
    b[slocumItemName(static_cast<SlocumItem>(i))] = g(w.ballast.item_kg[static_cast<std::size_t>(i)]);
  }
  const char* columns[3] = {"A", "B", "C"};
  for (std::size_t k = 0; k < 3; ++k) {
    b[std::string("disk_") + columns[k] + "_top"] = g(w.ballast.disks[k].top_kg);
    b[std::string("disk_") + columns[k] + "_bottom"] = g(w.ballast.disks[k].bottom_kg);
  }
  j["ballast_g"] = b;
  j["roll_battery"] = {{"angle_rad", w.ballast.battery_angle_rad}};
  if (w.battery_mass_kg) j["roll_battery"]["mass_kg"] = *w.battery_mass_kg;
  j["tank"] = {{"water", salt_water ? "salt" : "fresh"},
               {"density_kgm3", w.readings.tank.density_kgm3},
               {"temperature_degC", w.readings.tank.temperature_degC},
               {"bow_scale_g", g(w.readings.bow_scale_kg)},
               {"aft_scale_g", g(w.readings.aft_scale_kg)}};
  j["target"] = {{"density_kgm3", w.readings.target.density_kgm3},
                 {"temperature_degC", w.readings.target.temperature_degC},
                 {"pressure_dbar", w.readings.target_pressure_dbar},
                 {"salinity_psu", w.target_salinity_psu}};
  if (w.bottles_after_tank_step_kg) {
    nlohmann::json a;
    for (int i = 0; i <= kAftLower; ++i) {
      a[slocumItemName(static_cast<SlocumItem>(i))] = g((*w.bottles_after_tank_step_kg)[static_cast<std::size_t>(i)]);
    }
    j["after_tank_step_g"] = a;
  }
  if (w.roll_test) {
    nlohmann::json applied = nlohmann::json::array();
    for (const auto& h : w.roll_test->applied) {
      applied.push_back({{"mass_kg", h.mass_kg}, {"rail", h.starboard ? "starboard" : "port"}, {"roll_rad", h.roll_rad}});
    }
    j["roll_test"] = {{"initial_roll_rad", w.roll_test->initial_roll_rad}, {"applied", applied}};
    if (w.roll_test->lever_arm_m) j["roll_test"]["lever_arm_m"] = *w.roll_test->lever_arm_m;
  }
  return j;
}

nlohmann::json craneInputToJson(const CraneFirstMissionInput& in, const std::string& vehicle_id) {
  const auto& w = in.weighing;
  return {{"method", "crane"},
          {"vehicle", vehicle_id},
          {"scales_kg",
           {{"fore_starboard", w.scales_kg[0]}, {"fore_port", w.scales_kg[1]},
            {"aft_starboard", w.scales_kg[2]}, {"aft_port", w.scales_kg[3]}}},
          {"total_kg", w.total_kg},
          {"rope_x_m", {{"fore", w.rope_x_fore_m}, {"aft", w.rope_x_aft_m}}},
          {"rope_y_m", w.rope_y_m},
          {"installed_kg", in.installed_kg},
          {"use_optional_pieces", in.use_optional_pieces},
          {"water",
           {{"temperature_degC", in.water.temperature_degC}, {"salinity_psu", in.water.salinity_psu},
            {"depth_m", in.water.depth_m}, {"latitude_deg", in.water.latitude_deg}}}};
}

nlohmann::json sessionToJson(const WizardState& s, int page_id, const std::string& saved_at) {
  nlohmann::json j;
  j["format"] = "auvballast-gui-session";
  j["version"] = kSessionVersion;
  j["saved_at"] = saved_at;
  j["page"] = page_id;
  j["vehicle"] = s.vehicle ? s.vehicle->id : "";
  j["configuration"] = {{"id", s.configuration_id},
                        {"payload_note", s.payload_note},
                        {"area", s.area},
                        {"water_type", s.water_type},
                        {"in_history", s.configuration_in_history}};
  if (s.bg_mm) j["configuration"]["bg_mm"] = *s.bg_mm;
  j["mode"] = s.mode == SessionMode::kPostMission  ? "post_mission"
              : s.mode == SessionMode::kPreMission ? "pre_mission"
                                                   : "first_mission";
  j["crane"] = craneInputToJson(s.crane, s.vehicle ? s.vehicle->id : "");
  // Only a glider session has a tank weighing worth keeping (and valid to parse back).
  if (s.isGlider() && s.tank.readings.dry_mass_kg >= 1.0) j["tank"] = tankWeighingToJson(s.tank, s.tank_water_salt);
  j["log_file"] = s.log_file;
  // Pre mission: the next mission's water and policy, the ticks and the
  // masses actually installed (the plan itself is recomputed from them).
  if (s.next_water) {
    j["pre_mission"] = {{"water",
                         {{"temperature_degC", s.next_water->temperature_degC},
                          {"salinity_psu", s.next_water->salinity_psu},
                          {"depth_m", s.next_water->depth_m},
                          {"latitude_deg", s.next_water->latitude_deg}}},
                        {"deepest_m", s.next_deepest_m},
                        {"water_source", s.next_water_source},
                        {"policy", toString(s.policy)},
                        {"checklist_done", s.checklist_done},
                        {"actually_installed_kg", s.actually_installed_kg}};
  }
  // Post mission: what was installed during the logged mission and the
  // model-check terms accepted (analysis and check are recomputed from the log).
  j["mission_installed_kg"] = s.mission_installed_kg;
  if (s.pitch_alignment_sigma_deg) j["pitch_alignment_sigma_deg"] = *s.pitch_alignment_sigma_deg;
  j["accepted_terms"] = s.accepted_terms;
  if (!s.history_model.is_null()) j["history_model"] = s.history_model;
  if (!s.model_profile.is_null()) j["model_profile"] = s.model_profile;
  return j;
}

SavedSession sessionFromJson(const std::string& json_text, const std::string& file, const std::string& resource_dir) {
  const nlohmann::json doc = JsonReader::parseText(json_text, file);
  const JsonReader root(doc, file);
  if (root.text("format", "") != "auvballast-gui-session") {
    root.fail("format", "not an auvballast session file", "discard it and start a new session");
  }
  if (root.numberIn("version", 1, kSessionVersion) != kSessionVersion) {
    root.fail("version", "unknown session version", "discard it and start a new session");
  }
  SavedSession out;
  out.state = makeEmptyState(resource_dir);
  WizardState& s = out.state;
  out.saved_at = root.text("saved_at", "");
  out.page_id = static_cast<int>(root.numberIn("page", 0, 1000));
  const std::string vehicle = root.text("vehicle", "");
  if (!vehicle.empty()) s.vehicle = VehicleCatalog(s.vehicles_dir).load(vehicle);
  const JsonReader c = root.child("configuration");
  s.configuration_id = c.text("id", "");
  s.payload_note = c.text("payload_note", "");
  s.area = c.text("area", "");
  s.water_type = c.text("water_type", "");
  s.configuration_in_history = c.node().value("in_history", false);
  if (c.has("bg_mm")) s.bg_mm = c.numberIn("bg_mm", 0.1, 499.0);
  const std::string mode = root.text("mode", "first_mission");
  if (mode != "first_mission" && mode != "post_mission" && mode != "pre_mission") {
    root.fail("mode", "unknown mode '" + mode + "'", "use first_mission, post_mission or pre_mission");
  }
  s.mode = mode == "post_mission"  ? SessionMode::kPostMission
           : mode == "pre_mission" ? SessionMode::kPreMission
                                   : SessionMode::kFirstMission;

  const JsonReader cr = root.child("crane");
  auto& w = s.crane.weighing;
  const JsonReader scales = cr.child("scales_kg");
  const char* names[4] = {"fore_starboard", "fore_port", "aft_starboard", "aft_port"};
  for (std::size_t i = 0; i < 4; ++i) w.scales_kg[i] = scales.number(names[i], 0.0);
  w.total_kg = cr.number("total_kg", 0.0);
  const JsonReader rope = cr.child("rope_x_m");
  w.rope_x_fore_m = rope.number("fore", 0.0);
  w.rope_x_aft_m = rope.number("aft", 0.0);
  w.rope_y_m = cr.number("rope_y_m", w.rope_y_m);
  s.crane.installed_kg = cr.has("installed_kg") ? cr.numbers("installed_kg") : std::vector<double>{};
  s.crane.use_optional_pieces = cr.node().value("use_optional_pieces", false);
  const JsonReader water = cr.child("water");
  s.crane.water = {water.number("temperature_degC", 10.0), water.number("salinity_psu", 35.0),
                   water.number("depth_m", 0.0), water.number("latitude_deg", 60.0)};

  // The tank part goes through the weighing-file parser (same validation).
  if (root.has("tank")) {
    s.tank = parseTankWeighing(root.child("tank").node().dump(), file + " (tank)");
    s.tank_water_salt = root.child("tank").child("tank").text("water", "fresh") == "salt";
  }
  s.log_file = root.text("log_file", "");
  if (root.has("pre_mission")) {
    const JsonReader pm = root.child("pre_mission");
    const JsonReader pw = pm.child("water");
    s.next_water = PlannedWater{pw.number("temperature_degC", 10.0), pw.number("salinity_psu", 35.0),
                                pw.number("depth_m", 0.0), pw.number("latitude_deg", 45.0)};
    s.next_deepest_m = pm.number("deepest_m", 0.0);
    s.next_water_source = pm.text("water_source", "last mission");
    s.policy = planPolicyFromString(pm.text("policy", "exact"));
    if (pm.has("actually_installed_kg")) s.actually_installed_kg = pm.numbers("actually_installed_kg");
    if (pm.has("checklist_done")) {
      const nlohmann::json& done = pm.node().at("checklist_done");
      if (!done.is_array()) pm.fail("checklist_done", "must be a list of true/false", "discard the session");
      for (const auto& d : done) {
        if (!d.is_boolean()) pm.fail("checklist_done", "must be a list of true/false", "discard the session");
        s.checklist_done.push_back(d.get<bool>());
      }
    }
  }
  if (root.has("mission_installed_kg")) s.mission_installed_kg = root.numbers("mission_installed_kg");
  if (root.has("pitch_alignment_sigma_deg"))
    s.pitch_alignment_sigma_deg = root.numberIn("pitch_alignment_sigma_deg", kMinPitchAlignmentDeg, kMaxPitchAlignmentDeg);
  if (root.has("history_model")) s.history_model = root.node().at("history_model");
  if (root.has("model_profile")) s.model_profile = root.node().at("model_profile");
  if (s.vehicle && s.model_profile.is_object()) {
    s.vehicle = discrepancy::vehicleFromStoredProfile(s.model_profile, *s.vehicle, "session: model_profile");
  }
  if (root.has("accepted_terms")) {
    const nlohmann::json& terms = root.node().at("accepted_terms");
    if (!terms.is_array()) root.fail("accepted_terms", "must be a list of term names", "discard the session");
    for (const auto& t : terms) {
      if (!t.is_string()) root.fail("accepted_terms", "must be a list of term names", "discard the session");
      s.accepted_terms.push_back(t.get<std::string>());
    }
  }
  return out;
}

void writeSessionFile(const std::string& path, const nlohmann::json& j) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(fs::path(path).parent_path(), ec);
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << j.dump(2) << "\n";
    out.flush();
    if (!out) throw InputError("session file", "cannot write " + tmp, "check the disk space and permissions");
  }
  fs::rename(tmp, path, ec);
  if (ec) throw InputError("session file", "cannot replace " + path + ": " + ec.message(), "check the permissions");
}

SavedSession readSessionFile(const std::string& path, const std::string& resource_dir) {
  std::ifstream in(path);
  if (!in) throw InputError("session file", "cannot open " + path, "discard the session");
  std::stringstream ss;
  ss << in.rdbuf();
  return sessionFromJson(ss.str(), path, resource_dir);
}

}  // namespace auv::ui
