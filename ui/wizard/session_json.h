#pragma once
// The unfinished session as JSON, so a crash or a closed laptop loses nothing:
// the wizard writes it on every page change and offers to resume it on the
// next start. The Slocum part is written in the documented tank-weighing file
// format (docs/formats/slocum-tank-weighing.md) and read back through core's
// own parser, so the autosave and the weighing file cannot drift apart.
#include <nlohmann/json.hpp>
#include <string>

#include "wizard/wizard_state.h"

namespace auv::ui {

struct SavedSession {
  WizardState state;
  int page_id = 0;       // the page the operator was on
  std::string saved_at;  // ISO 8601 UTC, for the resume offer
};

nlohmann::json sessionToJson(const WizardState& s, int page_id, const std::string& saved_at);
// `file` names the source in errors; the vehicle profile is reloaded from
// `resource_dir`. Throws InputError for a damaged or foreign file.
SavedSession sessionFromJson(const std::string& json_text, const std::string& file, const std::string& resource_dir);

// A TankWeighing in the tank-weighing file format (masses in grams).
nlohmann::json tankWeighingToJson(const TankWeighing& w, bool salt_water);
// Same for the crane session, in the crane-weighing file format.
nlohmann::json craneInputToJson(const CraneFirstMissionInput& in, const std::string& vehicle_id);

// Writes atomically (temporary file + rename), so a crash while saving never
// leaves a half-written session. Throws InputError when the file cannot be written.
void writeSessionFile(const std::string& path, const nlohmann::json& j);
SavedSession readSessionFile(const std::string& path, const std::string& resource_dir);

}  // namespace auv::ui
