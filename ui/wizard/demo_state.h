#pragma once
#include <string>

#include "wizard/wizard_state.h"

namespace auv::ui {

// A session pre-filled from the bundled example weighing
// (resources/examples/hugin1000_first_mission.json) so that every page shows
// real content: used by `auvballast-gui --demo` and the screenshot tests.
WizardState makeDemoState(const std::string& resource_dir);

// An empty session with sensible defaults (HUGIN rope spacing, sea water).
WizardState makeEmptyState(const std::string& resource_dir);

}  // namespace auv::ui
