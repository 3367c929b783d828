// auvballast-gui: the operator wizard. Thin: builds the session state and
// shows the wizard; every number comes from core/.
//   auvballast-gui                 start page (history, resume offer)
//   auvballast-gui --demo [hugin|slocum|post]   a ready session on the bundled data
#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QFile>
#include <QStandardPaths>
#include <iostream>

#include "common/input_error.h"
#include "history/store.h"
#include "resource_paths.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"
#include "wizard/translations.h"

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  QApplication::setOrganizationName("auvballast");
  QApplication::setApplicationName("auvballast");
  QApplication::setApplicationVersion(AUV_VERSION);
  QCommandLineParser cli;
  cli.setApplicationDescription("Operator wizard: weighing, water, mission logs and the weight changes to make.");
  cli.addHelpOption();
  cli.addVersionOption();
  QCommandLineOption demo("demo", "Open a ready session on the bundled example data: hugin (crane weighing, "
                                  "default), slocum (tank weighing and roll test) or post (mission-log import).");
  QCommandLineOption lang("lang", "User interface language: en or nb (default: the system's).", "code");
  cli.addOption(demo);
  cli.addOption(lang);
  cli.addPositionalArgument("demo-kind", "With --demo: hugin, slocum or post.", "[hugin|slocum|post]");
  cli.process(app);
  auv::ui::installTranslation(cli.isSet(lang) ? QLocale(cli.value(lang)) : QLocale::system());
  try {
    const std::string res = auv::app::resourceDir();
    auv::ui::WizardState state;
    if (cli.isSet(demo)) {
      const QString kind = cli.positionalArguments().value(0, "hugin");
      // A demo never writes into the technician's history: it gets a fresh
      // one of its own (the post-mission demo with a past to continue).
      const QString dir = QStandardPaths::writableLocation(QStandardPaths::TempLocation) + "/auvballast-demo";
      QDir().mkpath(dir);
      if (qEnvironmentVariableIsEmpty("AUVBALLAST_HISTORY")) {
        const QString history = dir + "/history-" + kind + ".sqlite";
        for (const char* suffix : {"", "-wal", "-shm"}) QFile::remove(history + suffix);
        qputenv("AUVBALLAST_HISTORY", history.toLocal8Bit());
      }
      if (kind == "slocum") {
        state = auv::ui::makeSlocumDemoState(res);
      } else if (kind == "post") {
        auv::HistoryStore store(qEnvironmentVariable("AUVBALLAST_HISTORY").toStdString());
        if (!store.configuration("01-02-03")) {
          auv::ui::seedDemoHistory(store, res, auv::makeUtc(2026, 4, 30, 9, 0, 0));
        }
        state = auv::ui::makePostMissionDemoState(res, (dir + "/hugin1000-survey-sim.csv").toStdString());
      } else if (kind == "hugin") {
        state = auv::ui::makeDemoState(res);
      } else {
        std::cerr << "auvballast-gui: unknown demo '" << kind.toStdString() << "'; use hugin, slocum or post\n";
        return 2;
      }
    } else {
      state = auv::ui::makeEmptyState(res);
    }
    auv::ui::OperatorWizard wizard(state);
    // A demo is not a session to resume after a crash.
    wizard.setAutosaveEnabled(!cli.isSet(demo));
    wizard.show();
    return QApplication::exec();
  } catch (const auv::InputError& e) {
    std::cerr << "auvballast-gui: " << e.what() << "\n";
    return 2;
  }
}
