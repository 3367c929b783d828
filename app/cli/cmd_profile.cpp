// auvballast profile --from p1710100.nc --out sg171.json: a vehicle profile
// made from a Seaglider's own per-dive file (core/vehicle/seaglider_calibration.h)
// read through the mission-log reader (MissionLog::seagliderConstants()),
// the bundled seaglider profile as template. This file only maps flags.
#include <iostream>
#include <memory>

#include "cli_context.h"
#include "commands.h"
#include "analysis/profile_constants.h"
#include "common/input_error.h"
#include "missionlog/log_reader.h"
#include "vehicle/json_reader.h"
#include "vehicle/profile_loader.h"
#include "vehicle/seaglider_calibration.h"

namespace auv::cli {
namespace {

struct ProfileOpts {
  std::string from, out;
};

int runProfile(const ProfileOpts& o) {
  if (o.from.empty()) throw InputError("from", "missing", "give --from p<glider><dive>.nc (a Seaglider basestation per-dive file)");
  if (o.out.empty()) throw InputError("out", "missing", "give --out sgNNN.json");
  // The constants come from the log's metadata, as the NetCDF reader fills it.
  ReadReport report;
  const MissionLog log = LogReaderRegistry::withBuiltinReaders().read(o.from, ReadOptions{}, report);
  const SeagliderCalibration cal = analysis::seagliderCalibrationOf(log, o.from);
  const nlohmann::json tpl = JsonReader::parseFile(vehiclesDir() + "/seaglider.json");
  const nlohmann::json p = seagliderProfile(cal, tpl);
  writeJson(p, o.out);
  if (o.out == "-") return 0;
  // Read back through the loader: what was written must be a valid profile.
  const VehicleProfile v = loadVehicleProfile(o.out);
  std::cout << "Wrote " << o.out << ": " << v.name << ", " << v.mass_kg << " kg, hull " << v.hull.volume_m3 * 1e6
              << " cm3 at $C_VBD " << p["seaglider"]["C_VBD"].get<double>() << " (edit length, diameter and lead place)\n";
  return 0;
}

}  // namespace

Command addProfileCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("profile", "Make a vehicle profile from a glider's own files (Seaglider p*.nc: sg_cal_* and log_*)");
  auto o = std::make_shared<ProfileOpts>();
  cmd->add_option("--from", o->from, "Seaglider basestation per-dive NetCDF, e.g. p1710100.nc")->required();
  cmd->add_option("--out", o->out, "Where to write the profile JSON")->required();
  return {cmd, [o]() { return runProfile(*o); }};
}

}  // namespace auv::cli
