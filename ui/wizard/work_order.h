#pragma once
// The one-page work order a technician takes to the vehicle: vehicle,
// configuration, date, the next mission's water, what to change where (a
// table), the expected result against the spec bands, and a signature line.
// Drawn by one function on any QPaintDevice, so the PDF, the on-screen
// preview and the tests' render check show the same page.
#include <QCoreApplication>
#include <QImage>
#include <QString>
#include <QStringList>
#include <vector>

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
  QStringList water;   // the next mission's water, one line each
  QStringList columns;
  std::vector<QStringList> rows;  // one per adjustment point
  QStringList expected;  // predicted results against the bands
  QStringList warnings;
  QString signature;
};

// Everything shown comes from the state (the plan and the actually installed
// masses) and core's prediction for those masses. Throws InputError when
// nothing is planned.
WorkOrder makeWorkOrder(const WizardState& s, const PlanBasis& basis, TimePoint now);

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
