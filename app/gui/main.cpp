// auvballast-gui: the operator wizard. Thin: builds the session state and
// shows the wizard; every number comes from core/.
#include <QApplication>
#include <QCommandLineParser>
#include <iostream>

#include "common/input_error.h"
#include "resource_paths.h"
#include "wizard/demo_state.h"
#include "wizard/operator_wizard.h"

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  QApplication::setApplicationName("auvballast");
  QApplication::setApplicationVersion(AUV_VERSION);
  QCommandLineParser cli;
  cli.setApplicationDescription("Operator wizard: weighing, water and the weight changes to make.");
  cli.addHelpOption();
  cli.addVersionOption();
  QCommandLineOption demo("demo", "Open a ready configuration from the bundled example data.");
  cli.addOption(demo);
  cli.process(app);
  try {
    const std::string res = auv::app::resourceDir();
    auv::ui::OperatorWizard wizard(cli.isSet(demo) ? auv::ui::makeDemoState(res) : auv::ui::makeEmptyState(res));
    wizard.show();
    return QApplication::exec();
  } catch (const auv::InputError& e) {
    std::cerr << "auvballast-gui: " << e.what() << "\n";
    return 2;
  }
}
