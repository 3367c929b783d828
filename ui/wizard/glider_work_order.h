#pragma once
// A glider's answer in the words a technician acts on, and its work order:
// from planGliderBallast's JSON (state.glider_plan), never recomputed.
//  - Slocum: grams per bottle and wing rail (1 g steps), the roll transfer,
//  - Seaglider: the lead change and the new $C_VBD / $C_PITCH,
//  - SeaExplorer: the mass change and what its log cannot tell.
#include <QStringList>

#include <nlohmann/json.hpp>

#include "wizard/work_order.h"
#include "wizard/wizard_state.h"

namespace auv::ui {

struct GliderInstructions {
  Q_DECLARE_TR_FUNCTIONS(auv::ui::GliderInstructions)

 public:
  QString headline;    // "Add +69 ± 12 g for neutral ... at 1026.43 kg/m³, 512 dbar, 8.20 °C"
  QString target;      // where the target water came from
  QStringList steps;   // one action per line, in the order to do them
  QStringList cannot_tell;
  QStringList warnings;
};

// `vehicle` (may be null) supplies the ranges a setting must stay inside
// (Seaglider PITCH_MIN..PITCH_MAX): a value outside is said, not asked for.
GliderInstructions gliderInstructions(const nlohmann::json& plan, const VehicleProfile* vehicle = nullptr);

// The glider's work order (the same page drawWorkOrder prints): a row per
// ballast place, the steps, the top-down map. Throws InputError when the
// session has no glider answer yet.
WorkOrder makeGliderWorkOrder(const WizardState& s, TimePoint now);

}  // namespace auv::ui
