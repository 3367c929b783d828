#pragma once
#include <QWizardPage>
#include <optional>

#include "wizard/pre_mission_inputs.h"
#include "wizard/wizard_state.h"

class QCheckBox;
class QGroupBox;
class QLabel;
class QRadioButton;

namespace auv::ui {

class NumberInput;

class OperatorWizard;

// Pre mission, step 1 (thesis §5.4.2): what the plan starts from - the
// estimate of the last analysed mission with its uncertainty and where it
// comes from - the next mission's water (the last mission's CTD or the
// operator's values; a temperature older than one month must be measured
// again, thesis §5.5.3) and the policy. A preview of the plan follows every
// change; Next stores the plan (core planPreMission) in the state.
class PreMissionPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit PreMissionPage(WizardState& state);
  void initializePage() override;
  void cleanupPage() override;
  bool validatePage() override;
  bool isComplete() const override;
  int nextId() const override;

  // Whether the last mission's temperature is too old to reuse.
  bool temperatureStale() const { return stale_; }
  // A post-mission session whose analysis cannot be planned from (e.g. net
  // buoyancy not identifiable from the log): this page is then the last
  // one and Finish saves the mission alone.
  bool saveOnly() const { return state_.mode == SessionMode::kPostMission && !basis_; }

 private:
  OperatorWizard* wiz() const;
  void loadBasis();
  void showBasis();
  void applySource();
  void store();
  void updatePreview();
  std::optional<PreMissionPlan> computePlan(QString& error);
  bool temperatureEntered() const;

  WizardState& state_;
  std::optional<PlanBasis> basis_;
  QString basis_error_;
  bool stale_ = false;
  bool plan_ok_ = false;
  bool loading_ = false;

  QLabel* estimate_;
  QLabel* estimate_source_;
  QLabel* installed_;
  QRadioButton* src_ctd_;
  QRadioButton* src_operator_;
  NumberInput* temperature_;
  NumberInput* salinity_;
  NumberInput* depth_;
  NumberInput* deepest_;
  NumberInput* latitude_;
  QLabel* stale_label_;
  QLabel* density_;
  QLabel* water_error_;
  QRadioButton* policy_exact_;
  QRadioButton* policy_half_;
  QRadioButton* policy_classic_;
  QCheckBox* optional_;
  QLabel* preview_;
  QLabel* error_;
  QLabel* save_status_;
  QGroupBox* water_box_;
  QGroupBox* policy_box_;
};

}  // namespace auv::ui
