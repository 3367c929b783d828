#pragma once
#include <string>

#include "history/store.h"
#include "wizard/wizard_state.h"

namespace auv::ui {

// Sessions pre-filled from the bundled example data so that every page shows
// real content: used by `auvballast-gui --demo [hugin|slocum|post]` and the
// screenshot tests.

// HUGIN 1000 crane weighing (resources/examples/hugin1000_first_mission.json).
WizardState makeDemoState(const std::string& resource_dir);

// Slocum G2 tank session of Baird 2007 App. B
// (resources/examples/slocum_tank_weighing.json), with its roll test.
WizardState makeSlocumDemoState(const std::string& resource_dir);

// Post mission: the HUGIN demo configuration (expected in the history, see
// seedDemoHistory) with a mission log to import.
// The log is simulated by core/sim from resources/examples/hugin1000_survey.plan.json
// and written as an interchange CSV to `log_path` (deterministic: seeded noise).
WizardState makePostMissionDemoState(const std::string& resource_dir, const std::string& log_path);

// Fills a (demo or test) history with the HUGIN demo configuration as if its
// first mission had been computed and saved at `when`, with the pieces
// installed as weighed, so the start page and post mission have a past.
void seedDemoHistory(HistoryStore& store, const std::string& resource_dir, TimePoint when);

// Writes the simulated survey log (see above); returns the number of rows.
std::size_t writeDemoSurveyLog(const std::string& resource_dir, const std::string& log_path);

// An empty session with sensible defaults (HUGIN rope spacing, sea water,
// fresh tank water).
WizardState makeEmptyState(const std::string& resource_dir);

}  // namespace auv::ui
