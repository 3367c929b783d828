#pragma once
// Glider NetCDF through libnetcdf: IOOS glider-DAC / OG1 trajectory files
// (TIME or time, DEPTH/PRES, PITCH, ROLL, HEADING, TEMP, CNDC, PSAL with CF
// `units`) and Seaglider basestation per-dive files p<glider><dive>.nc
// (sg_data_point: time, depth, eng_pitchAng, eng_rollAng, eng_head,
// eng_vbdCC, eng_pitchCtl ...; ctd_data_point: ctd_time, temperature,
// salinity ...). Every dimension that has a CF time coordinate becomes one
// table, the tables are merged onto one time base, and each 1-D numeric
// variable on them becomes a channel: the known ones under the format's names
// and units (docs/decisions/readers-netcdf-variables.md), all others under their
// own names. _FillValue / missing_value / valid_range / the type's default
// fill mean "not sampled"; scale_factor and add_offset are applied; values
// whose <name>_qc / <NAME>_QC flag says bad (3, 4, 6, 7, 9) are blanked.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "missionlog/log_reader.h"

namespace auv {

class GliderNetcdfReader final : public LogReader {
 public:
  std::string formatName() const override { return "glider NetCDF (IOOS/OG1, Seaglider basestation)"; }
  // NetCDF classic / 64-bit offset / CDF-5 or HDF5 (netCDF-4) magic bytes.
  bool canRead(const std::filesystem::path& path, std::string_view firstBytes) const override;
  MissionLog read(const std::filesystem::path& path, const ReadOptions& options,
                  ReadReport& report) const override;
};

MissionLog readGliderNetcdf(const std::filesystem::path& path, const ReadOptions& options, ReadReport& report);
// The same on a file image in memory (nc_open_mem); `sourceName` is used in messages.
MissionLog parseGliderNetcdf(const void* data, std::size_t size, const std::string& sourceName,
                             const ReadOptions& options, ReadReport& report);

}  // namespace auv
