#include "vehicle/vehicle_catalog.h"

#include <algorithm>
#include <filesystem>

#include "common/input_error.h"
#include "vehicle/json_reader.h"
#include "vehicle/profile_loader.h"

namespace fs = std::filesystem;

namespace auv {

VehicleCatalog::VehicleCatalog(std::string vehicles_dir) : dir_(std::move(vehicles_dir)) {}

std::vector<std::string> VehicleCatalog::ids() const {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir_, ec)) {
    if (e.path().extension() == ".json") out.push_back(e.path().stem().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

VehicleProfile VehicleCatalog::load(const std::string& id_or_path) const {
  if (id_or_path.find('/') != std::string::npos || id_or_path.ends_with(".json")) {
    return loadVehicleProfile(id_or_path);
  }
  const fs::path file = fs::path(dir_) / (id_or_path + ".json");
  if (!fs::exists(file)) {
    std::string known;
    for (const auto& id : ids()) known += (known.empty() ? "" : ", ") + id;
    throw InputError("vehicle", "unknown vehicle '" + id_or_path + "'",
                     "use one of: " + (known.empty() ? std::string("(none found in ") + dir_ + ")" : known) +
                         ", or a path to a profile .json");
  }
  VehicleProfile v = loadVehicleProfile(file.string());
  mergeCompanionSections(v, (fs::path(dir_).parent_path() / "sim" / (id_or_path + "_hydrodynamics.json")).string());
  return v;
}

void mergeCompanionSections(VehicleProfile& v, const std::string& companion_file) {
  if (v.sections.contains("hydrodynamics") || !fs::exists(companion_file)) return;
  const nlohmann::json doc = JsonReader::parseFile(companion_file);
  JsonReader(doc, companion_file)
      .refuseUnknownKeys({"vehicle", "source", "comment", "hydrodynamics", "actuators", "sim_assumptions", "autopilot"},
                         "docs/formats/vehicle-profile.md");
  for (const auto& [key, value] : doc.items()) {
    if (value.is_object() && !v.sections.contains(key)) v.sections[key] = value;
  }
  v.sections_file = companion_file;
}

}  // namespace auv
