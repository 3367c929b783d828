#pragma once
// The one-page work order a technician takes to the vehicle: vehicle,
// configuration, date, the water, what to change where (a table and the
// top-down weight map), the expected result against the spec bands, and a
// signature line. The same page for the first mission (from the weighing)
// and before any later mission (from the plan).
// Drawn by one function on any QPaintDevice, so the PDF, the on-screen
// preview and the tests' render check show the same page.
#include <QCoreApplication>
#include <QImage>
#include <QString>
#include <QStringList>
#include <vector>

#include "widgets/weight_map_model.h"
#include "wizard/pre_mission_inputs.h"
#include "wizard/wizard_state.h"

class QPainter;
class QPaintDevice;

namespace auv::ui {

struct WorkOrder {
  Q_DECLARE_TR_FUNCTIONS(auv::ui::WorkOrder)

 public:
  QString title;
  QStringList header;  // "Vehicle: ...", "Configuration: ...", "Date: ..."
  QString water_title;  // "Next mission's water" or the weighing's
  QStringList water;    // that water, one line each
  QStringList columns;
  std::vector<QStringList> rows;  // one per adjustment point
  QStringList expected;  // predicted results against the bands
  QStringList warnings;
  QStringList notes;     // steps and explanations (a glider's battery and rail moves)
  QStringList calibration;  // what the analysis calibrated, one constant a line
  QStringList manoeuvre;    // the calibration manoeuvre for the next mission, when asked for
  WeightMapModel map;    // the top-down map; length_m == 0: none
  QString signature;
};

// Everything shown comes from the state (the plan and the actually installed
// masses) and core's prediction for those masses. Throws InputError when
// nothing is planned.
WorkOrder makeWorkOrder(const WizardState& s, const PlanBasis& basis, TimePoint now);

// The first mission's work order from the weighing's report (state.report):
// the weighing water instead of the next mission's, no uncertainties (the
// weighing's are in the notes). Throws InputError when nothing was computed.
WorkOrder makeFirstMissionWorkOrder(const WizardState& s, TimePoint now);

// Installed mass per profile point as a first-mission report saw it: the
// crane input, or for a glider what core lists as "ballast now".
std::vector<double> firstMissionInstalledKg(const WizardState& s, const FirstMissionReport& r);

// Draws the page to fill `device` (A4 proportions expected); sizes follow
// the device's resolution, so a 300 dpi PDF and a 96 dpi image match.
void drawWorkOrder(QPainter& painter, const QPaintDevice& device, const WorkOrder& w);

// A4 PDF, one page. Returns an empty string on success, else why not.
QString writeWorkOrderPdf(const WorkOrder& w, const QString& path);
// The same page as an image at `dpi` (A4: 794 x 1123 px at 96 dpi).
QImage renderWorkOrder(const WorkOrder& w, int dpi = 96);

// The JSON report (preMissionReportJson) written to `path`, indented.
// Returns an empty string on success, else why not.
QString writePreMissionJson(const WizardState& s, const PlanBasis& basis, TimePoint now, const QString& path);

}  // namespace auv::ui
