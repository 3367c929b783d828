// libFuzzer target for every JSON input a person or another tool hands us:
// crane and Slocum tank weighings, vehicle profiles (with their simulation
// sections), mission plans, column mappings and analysis reports given to
// `plan`. The first byte picks the reader. The promise checked on every
// input: the reader returns or throws auv::InputError with a non-empty
// message; any other exception (a library's json.exception escaping, say)
// or a crash is a bug.
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string>

#include "common/input_error.h"
#include "firstmission/crane_weighing_file.h"
#include "missionlog/column_mapping.h"
#include "planning/report_consistency.h"
#include "planning/trim_estimate.h"
#include "sim/mission_plan.h"
#include "sim/model_loader.h"
#include "vehicle/json_reader.h"
#include "vehicle/profile_loader.h"
#include "weighing/tank_weighing_file.h"

namespace {

void readOne(std::uint8_t which, const std::string& text) {
  switch (which % 6) {
    case 0:
      auv::parseCraneWeighingFile(text, "fuzz.json");
      break;
    case 1:
      auv::parseTankWeighing(text, "fuzz.json");
      break;
    case 2: {
      const auv::VehicleProfile v = auv::parseVehicleProfile(text, "fuzz.json");
      if (v.sections.contains("hydrodynamics")) {
        auv::sim::loadVehicleModel(v);
        auv::sim::loadAutopilotConfig(v);
      }
      break;
    }
    case 3:
      auv::sim::parseMissionPlan(auv::JsonReader::parseText(text, "fuzz.json"), "fuzz.json");
      break;
    case 4:
      auv::ColumnMapping::fromJson(text, "fuzz.json");
      break;
    default: {
      const nlohmann::json doc = auv::JsonReader::parseText(text, "fuzz.json");
      auv::refuseUnknownReportKeys(doc, "fuzz.json");
      auv::trimEstimateFromReport(doc, "fuzz.json");
      break;
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    readOne(data[0], text);
  } catch (const auv::InputError& e) {
    if (e.what()[0] == '\0') std::abort();
  } catch (const std::exception&) {
    std::abort();  // every bad input must be an InputError naming file and field
  }
  return 0;
}
