#pragma once
// Each subcommand registers its flags on the shared CLI11 app and returns the
// action to run when it was chosen. Actions return the process exit code.
#include <CLI/CLI.hpp>
#include <functional>

namespace auv::cli {

using Action = std::function<int()>;
struct Command {
  CLI::App* sub = nullptr;
  Action run;
};

Command addVehiclesCommand(CLI::App& app);
Command addDensityCommand(CLI::App& app);
Command addFirstMissionCommand(CLI::App& app);
Command addSimulateCommand(CLI::App& app);
Command addAnalyzeCommand(CLI::App& app);
Command addConvertCommand(CLI::App& app);
Command addPlanCommand(CLI::App& app);
Command addHistoryCommand(CLI::App& app);
Command addModelCheckCommand(CLI::App& app);
Command addProfileCommand(CLI::App& app);
// History database: the flag, else $AUVBALLAST_HISTORY, else $XDG_DATA_HOME/auvballast/history.sqlite.
std::string historyPath(const std::string& flag);

}  // namespace auv::cli
