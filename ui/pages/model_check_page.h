#pragma once
#include <QWizardPage>
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "wizard/model_check_job.h"
#include "wizard/wizard_state.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QProgressBar;
class QTableWidget;
QT_BEGIN_NAMESPACE
class QChart;
class QChartView;
class QLineSeries;
class QValueAxis;
QT_END_NAMESPACE

namespace auv::ui {
class CalibrationTable;

// Post mission, step 3: the model check (core/discrepancy) on the imported
// log, in a worker thread with a busy indicator. Shows the recording against
// the model's replay (ballast state alone, and with the terms the check
// accepted) on the channel with the largest mismatch, where the misfit
// concentrates (time, depth/pressure, speed, phase...), and each physics term
// the model lacks with its value ± sigma and the held-out RMS before and
// after. The technician ticks the terms to accept (state.accepted_terms).
// Without a pre-mission page this is the last page and Finish saves the
// mission to the history.
class ModelCheckPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit ModelCheckPage(WizardState& state);
  void initializePage() override;
  bool isComplete() const override;
  bool validatePage() override;
  // state.vehicle = the configuration's model + the accepted terms.
  bool adoptAcceptedTerms();
  // The catalog's profile with the history's model for this configuration.
  VehicleProfile configurationVehicle() const;
  int nextId() const override;

  ModelCheckJob& job() { return job_; }
  // The overlay of the last check (empty before one finished).
  const discrepancy::SimulationOverlay& overlay() const { return outcome_.overlay; }
  const ModelCheckOutcome& outcome() const { return outcome_; }
  // Index into overlay().channels shown in the chart.
  int shownChannel() const;
  void showChannel(int index);
  // The chart shows recorded - model (before and after) instead of the values.
  void setShowDifference(bool on);
  // Points handed to the chart: 0 recorded, 1 ballast only, 2 with the accepted terms.
  int pointsDrawn(int series) const;
  // Accept or reject a found term (as its check box does).
  void setTermAccepted(const std::string& id, bool accepted);

 private:
  void onFinished(const ModelCheckOutcome& out);
  void showResult();
  void showTerms();
  void showSummary();  // the ballast state the plan uses, and which estimate it is
  void showWhere();
  void updateAccepted();
  WizardState& state_;
  ModelCheckJob job_;
  ModelCheckOutcome outcome_;
  std::shared_ptr<const MissionLog> decided_for_;  // log whose term choices the technician made
  bool filling_ = false;
  QProgressBar* busy_;
  QLabel* status_;
  QLabel* summary_;
  QComboBox* channel_;
  QCheckBox* difference_;
  QChart* chart_;
  QChartView* chart_view_;
  QValueAxis* x_;
  QValueAxis* y_;
  std::array<QLineSeries*, 3> series_{};
  QTableWidget* terms_;
  CalibrationTable* calibration_;  // what the check calibrated
  QLabel* where_;
  QLabel* save_status_;
};

}  // namespace auv::ui
