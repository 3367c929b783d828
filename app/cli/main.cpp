// auvballast: the command-line front end. Every number comes from core/; this
// file only maps flags to core calls and errors to exit codes:
//   0 success, 1 internal failure, 2 bad input (message names field and fix).
#include <iostream>
#include <map>

#include "commands.h"
#include "common/input_error.h"

int main(int argc, char** argv) {
  CLI::App app{"auvballast: tells you which ballast weights to add, remove or move on an AUV or glider", "auvballast"};
  app.set_version_flag("--version", std::string("auvballast ") + AUV_VERSION);
  app.require_subcommand(1);

  std::map<CLI::App*, auv::cli::Action> actions;
  using auv::cli::Command;
  const std::initializer_list<Command (*)(CLI::App&)> commands = {
      auv::cli::addVehiclesCommand,
      auv::cli::addDensityCommand,
      auv::cli::addFirstMissionCommand,
      auv::cli::addAnalyzeCommand,
      auv::cli::addConvertCommand,
      auv::cli::addPlanCommand,
      auv::cli::addHistoryCommand,
      auv::cli::addSimulateCommand,
      auv::cli::addModelCheckCommand,
      auv::cli::addProfileCommand,
  };
  for (auto add : commands) {
    auto cmd = add(app);
    actions[cmd.sub] = std::move(cmd.run);
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "auvballast: " << e.what() << "; see 'auvballast --help'\n";
    return 2;
  }
  try {
    for (auto* sub : app.get_subcommands()) return actions.at(sub)();
  } catch (const auv::InputError& e) {
    std::cerr << "auvballast: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "auvballast: internal error: " << e.what() << "\n";
    return 1;
  }
  return 1;
}
