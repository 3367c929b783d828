#pragma once
#include <QWizardPage>

#include "wizard/wizard_state.h"

class QLabel;
class QPushButton;

namespace auv::ui {

class GliderBallastMap;

// Glider pre mission, the answer (issue 12): where the grams go, in words the
// technician acts on (Slocum: grams per bottle and wing rail; Seaglider: lead
// and the new $C_VBD / $C_PITCH; SeaExplorer: the mass and what its log
// cannot tell), the top and side map of the places, and the work order.
// Finish saves the mission (log and analysis) to the history.
class GliderBallastPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit GliderBallastPage(WizardState& state);
  void initializePage() override;
  bool validatePage() override;
  int nextId() const override { return -1; }

  // Writes the work order PDF; empty on success, else why not.
  QString exportWorkOrder(const QString& path);

 private:
  WizardState& state_;
  QLabel* headline_;
  QLabel* steps_;
  QLabel* notes_;
  GliderBallastMap* map_;
  QPushButton* export_;
  QLabel* save_status_;
};

}  // namespace auv::ui
