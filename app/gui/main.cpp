// auvballast-gui: the operator wizard. Thin: builds the session state and
// shows the wizard; every number comes from core/.
//   auvballast-gui                 start page (history, resume offer)
//   auvballast-gui --demo [hugin|slocum|post]   a ready session on the bundled data
//   auvballast-gui --demo --render-pages DIR   every demo page as DIR/*.png, no window
#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QFile>
#include <QStandardPaths>
#include <cstring>
#include <iostream>

#include "common/input_error.h"
#include "history/store.h"
#include "resource_paths.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"
#include "wizard/page_renderer.h"
#include "wizard/pinned_fonts.h"
#include "wizard/translations.h"
#include "wizard/worker_pool.h"

namespace {

bool renderPagesRequested(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], "--render-pages", 14) == 0) return true;
  return false;
}

// `--render-pages DIR`: the demo pages as images, with the look of the
// screenshot tests (offscreen, DejaVu Sans, Fusion), then exit.
int renderPages(const QString& out_dir) {
  const QString scratch = QStandardPaths::writableLocation(QStandardPaths::TempLocation) + "/auvballast-render";
  const auv::ui::RenderedPages r =
      // The demo's own day (its survey log is of 2026-05-14, as in the
      // screenshot tests): the pages look the same whenever they are rendered.
      auv::ui::renderDemoPages(auv::app::resourceDir(), out_dir, scratch, auv::makeUtc(2026, 5, 20, 12, 0, 0));
  std::cout << "Rendered " << r.files.size() << " wizard pages and work orders of the demo into "
            << out_dir.toStdString() << "/\n";
  if (!r.error.isEmpty()) {
    std::cerr << "auvballast-gui: " << r.error.toStdString() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const bool render = renderPagesRequested(argc, argv);
  if (render) {
    // No window is shown: offscreen works with or without a display, and
    // the fonts are pinned so the images match the tests' on any machine.
    qputenv("QT_QPA_PLATFORM", "offscreen");
    const QString why = auv::ui::pinFontsToDejaVu(QDir::tempPath() + "/auvballast-render-fonts");
    if (!why.isEmpty()) std::cerr << "auvballast-gui: " << why.toStdString() << " (rendering with other fonts)\n";
  }
  QApplication app(argc, argv);
  // Starting Qt GUI leaves this thread's upper AVX state dirty, and every
  // thread started from it would inherit that (worker_pool.h).
  auv::ui::clearAvxUpperState();
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
  QCommandLineOption render_pages("render-pages", "With --demo: do not open a window; walk the three demo sessions "
                                                  "page by page and save every page (and each work order as PNG "
                                                  "and PDF) into the folder <dir>.", "dir");
  cli.addOption(demo);
  cli.addOption(lang);
  cli.addOption(render_pages);
  cli.addPositionalArgument("demo-kind", "With --demo: hugin, slocum or post.", "[hugin|slocum|post]");
  cli.process(app);
  auv::ui::installTranslation(cli.isSet(lang) ? QLocale(cli.value(lang)) : QLocale::system());
  if (render) {
    auv::ui::pinRenderingLook();
    try {
      return renderPages(cli.value(render_pages));
    } catch (const auv::InputError& e) {
      std::cerr << "auvballast-gui: " << e.what() << "\n";
      return 2;
    }
  }
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
