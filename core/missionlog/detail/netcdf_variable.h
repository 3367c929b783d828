#pragma once
// The variables of an open NetCDF file as the glider reader needs them: name,
// type, dimensions and CF attributes, values as doubles with every kind of
// "no value" (fill, missing_value, valid_range, bad QC flag) as NaN and the
// packing (scale_factor, add_offset) applied.
#include <netcdf.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "missionlog/mission_log.h"
#include "missionlog/read_options.h"
#include "missionlog/read_report.h"

namespace auv::detail {

struct NcVariable {
  int id = 0;
  std::string name;
  nc_type type = NC_NAT;
  std::vector<int> dims;
  std::string units, standard_name, calendar;
  std::optional<double> fill, missing, valid_min, valid_max;
  double scale = 1.0, add_offset = 0.0;
};

bool isNumericType(nc_type t);

// Reads from the file `ncid` (which the caller opens and closes); `file`
// names it in messages, and blanked values are counted in `report`.
class NetcdfFile {
 public:
  NetcdfFile(int ncid, std::string file, const ReadOptions& options, ReadReport& report)
      : nc_(ncid), file_(std::move(file)), opt_(options), rep_(report) {}

  int id() const { return nc_; }
  // Throws InputError ("<what>: <libnetcdf message>") unless `status` is NC_NOERR.
  void check(int status, const std::string& what) const;
  // A text attribute (NC_CHAR or the first NC_STRING) of a variable or NC_GLOBAL.
  std::optional<std::string> textAttribute(int varid, const char* name) const;
  // A numeric attribute of up to 64 values; empty when absent or not numeric.
  std::vector<double> numberAttribute(int varid, const char* name) const;
  NcVariable describe(int varid) const;
  // The first `n` values; values outside valid_range are blanked and noted,
  // fills are not (they are the file's way of saying "not sampled").
  std::vector<double> values(const NcVariable& v, std::size_t n, bool applyPacking);
  // Blanks the values whose QC flag in `qc` says bad, and notes how many
  // (as a problem, or only in qcSummary() once setQuietQc(true)).
  void applyQc(const NcVariable& v, const NcVariable& qc, std::vector<double>& data, std::size_t n);
  // Seaglider basestation files flag the surface and apogee samples of every
  // dive: routine, nothing a technician can act on, so not a problem.
  void setQuietQc(bool quiet) { quietQc_ = quiet; }
  // "temperature 23, salinity 32" for the quietly blanked values ("" = none).
  const std::string& qcSummary() const { return qcSummary_; }
  // The global attributes as `nc_<name>` metadata (text, or one number).
  void globalMetadata(std::vector<MetadataEntry>& out) const;

 private:
  int nc_;
  std::string file_;
  const ReadOptions& opt_;
  ReadReport& rep_;
  bool quietQc_ = false;
  std::string qcSummary_;
};

}  // namespace auv::detail
