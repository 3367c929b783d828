#pragma once
// A crane weighing session saved as JSON (docs/formats/crane-weighing.md), so
// the CLI, the GUI demo and the tests can replay the same dockside numbers.
#include <string>

#include "firstmission/hugin_first_mission.h"

namespace auv {

struct CraneWeighingFile {
  std::string vehicle;  // profile id
  CraneFirstMissionInput input;
};

// Throws InputError naming the file and JSON path of a bad field.
CraneWeighingFile loadCraneWeighingFile(const std::string& file);
// The same from text (`file` names it in messages); for the GUI and fuzzing.
CraneWeighingFile parseCraneWeighingFile(const std::string& json_text, const std::string& file);

}  // namespace auv
