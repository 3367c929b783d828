#pragma once
#include <QWizardPage>

#include "wizard/glider_answer.h"
#include "wizard/wizard_state.h"

class QLabel;
class QRadioButton;

namespace auv::ui {

class NumberInput;

// Glider pre mission (issue 12): what the log showed - the grams to add with
// their uncertainty and the model-check terms the answer used - and the water
// of the next deployment where the glider must be neutral with its pump at
// zero: the log's own water at its deepest yo (default, said so), a density,
// a pressure and temperature (+ salinity), or a depth read from the log's own
// CTD profile. The answer follows every change (wizard/glider_answer.h, the
// same core calls as `model-check --target-...`); Next keeps it for the
// ballast page.
class GliderPreMissionPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit GliderPreMissionPage(WizardState& state);
  void initializePage() override;
  void cleanupPage() override;
  bool validatePage() override;
  bool isComplete() const override;
  int nextId() const override;

  // The log does not show the glider's net buoyancy: nothing to plan, this
  // page is the last one and Finish saves the mission alone.
  bool saveOnly() const { return !state_.analysis || !state_.analysis->mass_to_add_g.known; }

  GliderTargetChoice choice() const;
  const GliderAnswer& answer() const { return answer_; }

 private:
  void showLogAnswer();
  void loadInstalled();
  void applyKind();
  void update();

  WizardState& state_;
  GliderAnswer answer_;
  bool loading_ = false;

  QLabel* log_answer_;
  QLabel* terms_;
  QLabel* installed_;
  QRadioButton* kind_log_;
  QRadioButton* kind_density_;
  QRadioButton* kind_pt_;
  QRadioButton* kind_depth_;
  NumberInput* density_;
  NumberInput* pressure_;
  NumberInput* temperature_;
  NumberInput* salinity_;
  NumberInput* depth_;
  QLabel* target_;
  QLabel* result_;
  QLabel* error_;
};

}  // namespace auv::ui
