#include "wizard/model_check_job.h"

#include <QtConcurrent/QtConcurrent>

#include "common/input_error.h"
#include "discrepancy/held_law_retest.h"
#include "wizard/worker_pool.h"

namespace auv::ui {

ModelCheckJob::ModelCheckJob(QObject* parent) : QObject(parent) {
  connect(&watcher_, &QFutureWatcher<ModelCheckOutcome>::finished, this, [this] {
    busy_ = false;
    emit finished(watcher_.result());
  });
}

ModelCheckJob::~ModelCheckJob() { waitForFinished(); }

bool ModelCheckJob::running() const { return busy_; }

void ModelCheckJob::waitForFinished() { watcher_.waitForFinished(); }

void ModelCheckJob::start(std::shared_ptr<const MissionLog> log, VehicleProfile vehicle, std::string resource_dir,
                          discrepancy::CheckSetup setup, discrepancy::ModelCheckOptions options,
                          std::optional<analysis::AnalysisReport> analysis) {
  if (running() || !log) return;
  busy_ = true;
  watcher_.setFuture(QtConcurrent::run(workerPool(), [log, vehicle = std::move(vehicle), dir = std::move(resource_dir),
                                        base_setup = std::move(setup), options = std::move(options),
                                        analysis = std::move(analysis)]() {
    // The job's own copy of the analysis: the page's may change while it runs.
    discrepancy::CheckSetup job_setup = base_setup;
    if (analysis) job_setup.analysis = &*analysis;
    lowerWorkerPriority();
    ModelCheckOutcome out;
    out.log = log;
    try {
      const std::shared_ptr<discrepancy::CheckModel> model = discrepancy::makeCheckModel(*log, vehicle, dir, job_setup);
      out.model = model;
      out.description = model->description();
      out.result = discrepancy::runModelCheck(*model, options);
      if (analysis) discrepancy::followFoundPitchBias(*log, vehicle, *analysis, *out.result);
      out.overlay = discrepancy::simulationOverlay(*model, *out.result, *log);
      out.ok = true;
    } catch (const std::exception& e) {
      // InputError (the log lacks what the model needs) and anything else:
      // the page says why; the rest of the wizard goes on without the check.
      out.ok = false;
      out.error = e.what();
    }
    return out;
  }));
}

}  // namespace auv::ui
