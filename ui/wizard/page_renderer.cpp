#include "wizard/page_renderer.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QPixmap>
#include <functional>

#include "common/input_error.h"
#include "history/store.h"
#include "pages/log_import_page.h"
#include "pages/model_check_page.h"
#include "missionlog/interchange_csv.h"
#include "wizard/demo_state.h"
#include "wizard/glider_work_order.h"
#include "wizard/operator_wizard.h"
#include "wizard/pre_mission_inputs.h"
#include "wizard/work_order.h"

namespace auv::ui {
namespace {

// Lets queued work (imports, model checks, plots) finish, at most a minute.
void settle(const std::function<bool()>& busy) {
  QElapsedTimer t;
  t.start();
  while (busy() && t.elapsed() < 60000) QApplication::processEvents(QEventLoop::AllEvents, 20);
  QApplication::processEvents();
}

void settlePage(OperatorWizard& wiz) {
  QWizardPage* page = wiz.currentPage();
  if (auto* import = qobject_cast<LogImportPage*>(page)) settle([import] { return import->job().running(); });
  if (auto* check = qobject_cast<ModelCheckPage*>(page)) settle([check] { return check->job().running(); });
  settle([page] { return page && !page->isComplete(); });
}

class Walk {
 public:
  Walk(const QString& out_dir, RenderedPages& result) : out_(out_dir), result_(result) {}

  // Saves the wizard as it is now as <name>.png.
  bool shot(OperatorWizard& wiz, const QString& name) {
    settlePage(wiz);
    const QString file = out_ + "/" + name + ".png";
    if (!wiz.grab().toImage().save(file)) return fail(QString("cannot write %1: check the folder").arg(file));
    result_.files << file;
    return true;
  }
  // Next, and the page it must land on.
  bool next(OperatorWizard& wiz, int expected) {
    settlePage(wiz);
    const int from = wiz.currentId();
    wiz.next();
    settlePage(wiz);
    if (wiz.currentId() == expected) return true;
    return fail(QString("the demo stopped on page %1 (%2)%3")
                    .arg(from)
                    .arg(wiz.currentPage() ? wiz.currentPage()->title() : QString())
                    .arg(wiz.state().last_error.empty() ? QString() : ": " + QString::fromStdString(wiz.state().last_error)));
  }
  bool workOrder(const WorkOrder& order, const QString& name) {
    const QString png = out_ + "/" + name + ".png", pdf = out_ + "/" + name + ".pdf";
    if (!renderWorkOrder(order, 96).save(png)) return fail(QString("cannot write %1: check the folder").arg(png));
    const QString why = writeWorkOrderPdf(order, pdf);
    if (!why.isEmpty()) return fail(why);
    result_.files << png << pdf;
    return true;
  }
  bool fail(const QString& why) {
    if (result_.error.isEmpty()) result_.error = why;
    return false;
  }

 private:
  QString out_;
  RenderedPages& result_;
};

void prepare(OperatorWizard& wiz, TimePoint now) {
  wiz.setClock([now] { return now; });
  wiz.setAutosaveEnabled(false);
  wiz.resize(1000, 760);
  wiz.show();
  QApplication::processEvents();
}

bool huginFirstMission(Walk& w, const std::string& res, TimePoint now) {
  OperatorWizard wiz(makeDemoState(res));
  prepare(wiz, now);
  using W = OperatorWizard;
  return w.shot(wiz, "01_start") && w.next(wiz, W::kVehicle) && w.shot(wiz, "02_vehicle") &&
         w.next(wiz, W::kCraneWeighing) && w.shot(wiz, "03_crane_weighing") && w.next(wiz, W::kWater) &&
         w.shot(wiz, "04_water") && w.next(wiz, W::kFirstMissionResult) && w.shot(wiz, "05_first_mission_result") &&
         w.workOrder(makeFirstMissionWorkOrder(wiz.state(), now), "06_first_mission_work_order");
}

bool slocumFirstMission(Walk& w, const std::string& res, TimePoint now) {
  OperatorWizard wiz(makeSlocumDemoState(res));
  prepare(wiz, now);
  using W = OperatorWizard;
  return w.shot(wiz, "10_start_slocum") && w.next(wiz, W::kVehicle) && w.shot(wiz, "11_vehicle_slocum") &&
         w.next(wiz, W::kTankWeighing) && w.shot(wiz, "12_tank_weighing") && w.next(wiz, W::kRollTest) &&
         w.shot(wiz, "13_roll_test") && w.next(wiz, W::kFirstMissionResult) && w.shot(wiz, "14_slocum_result") &&
         w.workOrder(makeFirstMissionWorkOrder(wiz.state(), now), "15_slocum_work_order");
}

// The post-mission demo (as `--demo post`) and on to the next mission's
// plan with the water of the analysed mission.
bool postAndPreMission(Walk& w, const std::string& res, const QString& scratch, TimePoint now) {
  OperatorWizard wiz(makePostMissionDemoState(res, (scratch + "/hugin1000-survey-sim.csv").toStdString()));
  prepare(wiz, now);
  using W = OperatorWizard;
  if (!(w.shot(wiz, "20_start_post_mission") && w.next(wiz, W::kVehicle) && w.next(wiz, W::kLogImport) &&
        w.shot(wiz, "21_log_import") && w.next(wiz, W::kDeviationPlots) && w.shot(wiz, "22_deviation_plots") &&
        w.next(wiz, W::kModelCheck) && w.shot(wiz, "23_model_check") && w.next(wiz, W::kPreMission) &&
        w.shot(wiz, "24_pre_mission") && w.next(wiz, W::kAdjustment) && w.shot(wiz, "25_adjustment") &&
        w.next(wiz, W::kSummary) && w.shot(wiz, "26_summary"))) {
    return false;
  }
  try {
    const PlanBasis basis = planBasis(wiz.state(), wiz.history(), now, wiz.state().policy);
    return w.workOrder(makeWorkOrder(wiz.state(), basis, now), "27_work_order");
  } catch (const InputError& e) {
    return w.fail(QString::fromStdString(e.what()));
  }
}

// A Slocum after a mission (the bundled model-check log), on to the grams
// per bottle for the log's own deepest water.
bool gliderPostAndPreMission(Walk& w, const std::string& res, TimePoint now) {
  WizardState s = makeSlocumDemoState(res);
  s.mode = SessionMode::kPostMission;
  s.log_file = res + "/examples/slocum_g2_model-check_compressibility.csv";
  s.log = std::make_shared<MissionLog>(readInterchangeCsv(s.log_file));
  s.log_format = "mission-log CSV v1";
  s.log_report = ReadReport{};
  OperatorWizard wiz(std::move(s));
  prepare(wiz, now);
  using W = OperatorWizard;
  return w.next(wiz, W::kVehicle) && w.next(wiz, W::kLogImport) && w.next(wiz, W::kDeviationPlots) &&
         w.next(wiz, W::kModelCheck) && w.shot(wiz, "30_model_check_slocum") && w.next(wiz, W::kGliderPreMission) &&
         w.shot(wiz, "31_glider_pre_mission") && w.next(wiz, W::kGliderBallast) && w.shot(wiz, "32_glider_ballast") &&
         w.workOrder(makeGliderWorkOrder(wiz.state(), now), "33_glider_work_order");
}

}  // namespace

RenderedPages renderDemoPages(const std::string& resource_dir, const QString& out_dir, const QString& scratch_dir,
                              TimePoint now) {
  RenderedPages result;
  if (!QDir().mkpath(out_dir) || !QDir().mkpath(scratch_dir)) {
    result.error = QString("cannot create %1: check the folder and its permissions").arg(out_dir);
    return result;
  }
  Walk walk(out_dir, result);
  // Each demo gets a fresh history of its own; post mission starts from the
  // seeded HUGIN configuration, as `--demo post` does.
  auto freshHistory = [&](const QString& name) {
    const QString file = scratch_dir + "/" + name;
    for (const char* suffix : {"", "-wal", "-shm"}) QFile::remove(file + suffix);
    qputenv("AUVBALLAST_HISTORY", file.toLocal8Bit());
    return file;
  };
  try {
    freshHistory("history-hugin.sqlite");
    if (!huginFirstMission(walk, resource_dir, now)) return result;
    freshHistory("history-slocum.sqlite");
    if (!slocumFirstMission(walk, resource_dir, now)) return result;
    const QString post = freshHistory("history-post.sqlite");
    {
      HistoryStore store(post.toStdString());
      seedDemoHistory(store, resource_dir, now - std::chrono::days(10));
    }
    if (!postAndPreMission(walk, resource_dir, scratch_dir, now)) return result;
    freshHistory("history-glider.sqlite");
    gliderPostAndPreMission(walk, resource_dir, now);
  } catch (const InputError& e) {
    walk.fail(QString::fromStdString(e.what()));
  }
  return result;
}

}  // namespace auv::ui
