#include "page_walk.h"

#include "history/store.h"
#include "missionlog/interchange_csv.h"
#include "vehicle/vehicle_catalog.h"
#include "wizard/demo_state.h"

namespace auv::testing {
namespace {

const std::string kRes = AUV_RESOURCE_DIR;
const std::string kExamples = kRes + "/examples/";

void seedHugin(const QString& file) {
  HistoryStore store(file.toStdString());
  ui::seedDemoHistory(store, kRes, makeUtc(2026, 5, 10, 9, 0, 0));
}

// A post-mission session on a bundled log, already read (as after Browse).
ui::WizardState readLog(ui::WizardState s, const std::string& file) {
  s.mode = ui::SessionMode::kPostMission;
  s.log = std::make_shared<MissionLog>(readInterchangeCsv(file));
  s.log_file = file;
  s.log_format = "mission-log CSV v1";
  s.log_report = ReadReport{};
  return s;
}

ui::WizardState withVehicle(ui::WizardState s, const std::string& id, std::size_t points) {
  s.vehicle = VehicleCatalog(s.vehicles_dir).load(id);
  s.crane.installed_kg.resize(points, 0.0);
  return s;
}

}  // namespace

std::vector<WizardSequence> everyWizardSequence() {
  return {
      {"HUGIN first mission (crane)", [](const QString&) { return ui::makeDemoState(kRes); }, nullptr},
      {"Delphin2 first mission (crane)",
       [](const QString&) {
         ui::WizardState s = withVehicle(ui::makeDemoState(kRes), "delphin2", 2);
         s.crane.installed_kg = {0.4, 0.6};  // within the trim points' 1 kg
         s.configuration_id = "02-01-01";
         return s;
       },
       nullptr},
      {"Slocum first mission (tank and roll test)", [](const QString&) { return ui::makeSlocumDemoState(kRes); },
       nullptr},
      {"Seaglider first mission (tank and roll test)",
       [](const QString&) {
         ui::WizardState s = ui::makeSlocumDemoState(kRes);
         s.vehicle = VehicleCatalog(s.vehicles_dir).load("seaglider");
         s.configuration_id = "171-1-1";
         return s;
       },
       // The tank and roll-test pages are Slocum's (they refuse a profile
       // without a "slocum" section); the Seaglider's own first-mission
       // pages are being built with the glider pre-mission pages.
       nullptr, ui::OperatorWizard::kVehicle},
      {"HUGIN post mission (import, plots, model check, plan, adjustment, summary)",
       [](const QString& dir) {
         return ui::makePostMissionDemoState(kRes, (dir + "/hugin1000-survey-sim.csv").toStdString());
       },
       seedHugin},
      {"Slocum post mission",
       [](const QString&) {
         return readLog(ui::makeSlocumDemoState(kRes), kExamples + "slocum_g2_model-check_compressibility.csv");
       },
       // Through the glider pre-mission pages (target water, where the grams go) to Finish.
       nullptr},
      {"Delphin2 post mission",
       [](const QString&) {
         ui::WizardState s = ui::makeEmptyState(kRes);
         s.vehicle = VehicleCatalog(s.vehicles_dir).load("delphin2");
         s.configuration_id = "02-01-01";
         return readLog(s, kExamples + "delphin2_model-check_propeller-torque.csv");
       },
       nullptr},
  };
}

}  // namespace auv::testing
