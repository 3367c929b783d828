#pragma once
// Runs the model check (core/discrepancy) in a worker thread so the page
// stays responsive: the check model for the vehicle (vehicle_check.h), the
// check itself and the recording-against-simulation overlay. The core
// functions cannot be interrupted; a check takes about a second on the
// bundled logs, and the destructor waits for a running one.
#include <QFutureWatcher>
#include <QObject>
#include <memory>
#include <optional>
#include <string>

#include "discrepancy/model_check.h"
#include "discrepancy/simulation_overlay.h"
#include "discrepancy/vehicle_check.h"
#include "missionlog/mission_log.h"
#include "vehicle/vehicle_profile.h"

namespace auv::ui {

struct ModelCheckOutcome {
  bool ok = false;
  std::optional<discrepancy::ModelCheckResult> result;
  discrepancy::SimulationOverlay overlay;
  std::shared_ptr<const discrepancy::CheckModel> model;  // the model the result belongs to
  Message description;  // the check model's own description
  std::string error;        // InputError text when !ok
  std::shared_ptr<const MissionLog> log;  // the log it was run on
};

class ModelCheckJob : public QObject {
  Q_OBJECT
 public:
  explicit ModelCheckJob(QObject* parent = nullptr);
  ~ModelCheckJob() override;

  // Ignored while a check is running. `analysis`: the same log's analysis
  // (an AUV's check then holds its calibration and states its net buoyancy
  // in the same water; CheckSetup::analysis), copied for the job.
  void start(std::shared_ptr<const MissionLog> log, VehicleProfile vehicle, std::string resource_dir,
             discrepancy::CheckSetup setup, discrepancy::ModelCheckOptions options = {},
             std::optional<analysis::AnalysisReport> analysis = std::nullopt);
  bool running() const;
  void waitForFinished();

 signals:
  void finished(const auv::ui::ModelCheckOutcome& outcome);

 private:
  QFutureWatcher<ModelCheckOutcome> watcher_;
  // From start() until `finished` has been emitted. The future stops running
  // before its finished event reaches this thread; a caller that saw it
  // stop could read the page before the outcome arrived.
  bool busy_ = false;
};

}  // namespace auv::ui
