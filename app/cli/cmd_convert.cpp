// auvballast convert: any supported mission log -> the interchange CSV
// (docs/formats in ../shared/formats/mission-log-csv.md). Reading and writing
// live in core/missionlog; this maps flags and prints the import summary.
#include <iostream>
#include <memory>

#include "cli_context.h"
#include "commands.h"
#include "common/input_error.h"
#include "missionlog/interchange_csv.h"
#include "missionlog/log_reader.h"

namespace auv::cli {

Command addConvertCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("convert", "Read any supported mission log and write it as interchange CSV");
  struct Opts {
    std::vector<std::string> in;
    std::string out, cache_dir;
  };
  auto o = std::make_shared<Opts>();
  cmd->add_option("--log", o->in,
                  "Input log (interchange CSV, delimited text, Slocum ASCII, glider NetCDF, SeaExplorer raw, Slocum binary) or a "
                  "folder of a mission's files; repeat for several files")
      ->required();
  cmd->add_option("--cache-dir", o->cache_dir, kCacheDirHelp);
  cmd->add_option("--out", o->out, "Output interchange CSV")->required();
  return {cmd, [o]() {
            ReadReport report;
            const MissionLog log = readLogArgument(o->in, logReadOptions(o->cache_dir), report);
            writeInterchangeCsv(log, o->out);
            std::cout << "wrote " << o->out << ": " << log.rowCount() << " rows, " << log.channels.size()
                      << " channels (read as " << report.format << ")\n";
            if (!report.clean()) std::cout << report.summary() << "\n";
            return 0;
          }};
}

}  // namespace auv::cli
