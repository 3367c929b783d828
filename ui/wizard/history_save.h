#pragma once
// What Finish writes into the history. Each function is ONE transaction: the
// configuration (if it is new) and every record of the session are saved
// together or not at all (history/transaction.h), so a failure halfway - a
// full disk, a duplicate log - never leaves half a session in the history.
#include "history/store.h"
#include "wizard/pre_mission_inputs.h"
#include "wizard/wizard_state.h"

namespace auv::ui {

// First mission: weighing (inputs as entered + the report), the planned or
// target water, and the recommendation (the report), accepted by Finish.
// Throws InputError (nothing saved) when a record is refused.
void saveFirstMissionToHistory(HistoryStore& store, const WizardState& s, TimePoint now);

// Post mission: the imported log (content hash, read summary). Throws
// InputError (nothing saved) e.g. when this log is already in the configuration.
RecordId saveMissionToHistory(HistoryStore& store, const WizardState& s, TimePoint now);

// The read summary stored with a mission: format, rows, channels, what was skipped.
nlohmann::json missionSummaryJson(const WizardState& s);

// Pre mission (and a post-mission session that went on to plan): the
// mission if this session imported one, the next mission's water, the plan
// as an accepted recommendation (linked to its analysis) and what the
// technician actually installed, with its kit pieces, all in ONE transaction.
// Throws InputError (nothing saved) when a record is refused or the actually
// installed masses are not sums of kit pieces.
struct PreMissionSaveIds {
  std::optional<RecordId> mission;
  RecordId water = 0, recommendation = 0, installed = 0;
};
PreMissionSaveIds savePreMissionToHistory(HistoryStore& store, const WizardState& s, const PlanBasis& basis,
                                          TimePoint now);

}  // namespace auv::ui
