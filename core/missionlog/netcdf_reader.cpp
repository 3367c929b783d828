// The glider NetCDF reader: every dimension with a CF time coordinate
// (detail/netcdf_time_coordinate.h) becomes one table of its variables
// (detail/netcdf_variable.h) under their channel names
// (detail/netcdf_channel_names.h); the tables are tidied and merged like any
// other reader's. Classic-format headers are checked before libnetcdf sees
// them (detail/netcdf_header_check.h).
#include "missionlog/netcdf_reader.h"

#include <netcdf.h>
#include <netcdf_mem.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <vector>

#include "common/input_error.h"
#include "missionlog/detail/arrival_order.h"
#include "missionlog/detail/memory_guard.h"
#include "missionlog/detail/netcdf_channel_names.h"
#include "missionlog/detail/netcdf_header_check.h"
#include "missionlog/detail/netcdf_time_coordinate.h"
#include "missionlog/detail/netcdf_variable.h"
#include "missionlog/log_table.h"
#include "missionlog/unit_spelling.h"

namespace auv {
namespace {

using detail::decodeCfTime;
using detail::findTimeCoordinate;
using detail::guardMemory;
using detail::isNumericType;
using detail::listTimeLikeVariables;
using detail::missingChannels;
using detail::nameChannels;
using detail::NcVariable;
using detail::NetcdfFile;
using detail::refuseDamagedHeader;
using detail::requireGregorianCalendar;

// Far beyond any glider log (a year at 10 Hz is 3e8 samples would not fit
// anyway); a larger dimension is a damaged header, not data.
constexpr std::size_t kMaxSamples = 200'000'000;

struct NcHandle {
  int id = -1;
  ~NcHandle() {
    if (id >= 0) nc_close(id);
  }
};

class NetcdfParser {
 public:
  NetcdfParser(int ncid, std::string file, const ReadOptions& o, ReadReport& r)
      : file_(std::move(file)), opt_(o), rep_(r), nc_(ncid, file_, o, r) {}
  MissionLog read();

 private:
  void addSeagliderConstants(const std::vector<NcVariable>& vars,
                             const std::map<int, std::pair<std::string, std::size_t>>& dims,
                             std::vector<MetadataEntry>& meta);
  std::string file_;
  const ReadOptions& opt_;
  ReadReport& rep_;
  NetcdfFile nc_;
};

// The Seaglider's constants into the metadata, under their names in the
// file: the calibration (`sg_cal_mass`, `sg_cal_volmax`, `sg_cal_hd_a` ...)
// and the parameters the glider flew the dive with (`log_C_VBD`, `log_MASS`,
// `log_HD_A` ...; text ones such as `log_ID` as text). MissionLog::
// seagliderConstants() gives the numeric ones back as a map.
void NetcdfParser::addSeagliderConstants(const std::vector<NcVariable>& vars,
                                         const std::map<int, std::pair<std::string, std::size_t>>& dims,
                                         std::vector<MetadataEntry>& meta) {
  constexpr std::size_t kMaxText = 200;
  for (const NcVariable& v : vars) {
    const bool cal = v.name.rfind("sg_cal_", 0) == 0, log = v.name.rfind("log_", 0) == 0;
    if (!cal && !log) continue;
    if (v.dims.empty() && isNumericType(v.type)) {
      double x = 0;
      if (nc_get_var_double(nc_.id(), v.id, &x) == NC_NOERR && std::isfinite(x)) {
        meta.push_back({v.name, numberText(x)});
        if (v.name == "sg_cal_mass") meta.push_back({"mass_kg", numberText(x)});
      }
    } else if (v.type == NC_CHAR && v.dims.size() == 1) {
      const auto d = dims.find(v.dims[0]);
      if (d == dims.end() || d->second.second == 0 || d->second.second > kMaxText) continue;
      std::string text(d->second.second, '\0');
      if (nc_get_var_text(nc_.id(), v.id, text.data()) != NC_NOERR) continue;
      text.resize(std::strlen(text.c_str()));
      for (char& c : text)
        if (static_cast<unsigned char>(c) < 0x20) c = ' ';
      meta.push_back({v.name, text});
    }
  }
}

MissionLog NetcdfParser::read() {
  int ndims = 0, nvars = 0;
  nc_.check(nc_inq_ndims(nc_.id(), &ndims), "cannot read the dimensions");
  nc_.check(nc_inq_nvars(nc_.id(), &nvars), "cannot read the variables");
  if (ndims < 0 || nvars < 0 || ndims > 100000 || nvars > 100000)
    throw InputError("netcdf", "implausible header (" + std::to_string(ndims) + " dimensions, " +
                                   std::to_string(nvars) + " variables)",
                     "the file is damaged", {file_, 0, 0});
  std::map<int, std::pair<std::string, std::size_t>> dims;  // id -> name, length
  {
    std::vector<int> ids(static_cast<std::size_t>(ndims));
    int got = 0;
    if (ndims) nc_.check(nc_inq_dimids(nc_.id(), &got, ids.data(), 0), "cannot read the dimensions");
    for (int i = 0; i < got && i < ndims; ++i) {
      char name[NC_MAX_NAME + 1] = {};
      size_t len = 0;
      nc_.check(nc_inq_dim(nc_.id(), ids[static_cast<std::size_t>(i)], name, &len), "cannot read a dimension");
      dims[ids[static_cast<std::size_t>(i)]] = {name, len};
    }
  }
  bool seaglider = false;
  for (const auto& [id, d] : dims) seaglider |= d.first == "sg_data_point";

  std::vector<NcVariable> vars;
  std::map<std::string, std::size_t> byName;
  for (int i = 0; i < nvars; ++i) {
    vars.push_back(nc_.describe(i));
    byName[vars.back().name] = vars.size() - 1;
  }

  std::vector<MetadataEntry> meta;
  meta.push_back({"netcdf_flavour", seaglider ? "Seaglider basestation" : "IOOS/OG1 trajectory"});
  nc_.globalMetadata(meta);
  nc_.setQuietQc(seaglider);
  addSeagliderConstants(vars, dims, meta);

  // One table per dimension that has a CF time coordinate.
  std::vector<LogTable> tables;
  std::string notImported, timeCandidates;
  std::set<std::string> channelsFound;
  for (const auto& [dimId, dim] : dims) {
    const std::string& dimName = dim.first;
    const std::size_t length = dim.second;
    std::vector<std::size_t> members;
    for (std::size_t k = 0; k < vars.size(); ++k)
      if (vars[k].dims.size() == 1 && vars[k].dims[0] == dimId && isNumericType(vars[k].type)) members.push_back(k);
    if (members.empty()) continue;
    const auto time = findTimeCoordinate(vars, members, dimName);
    if (!time) {
      notImported += (notImported.empty() ? "" : "; ") + dimName + " (" + std::to_string(members.size()) + " variables)";
      listTimeLikeVariables(vars, members, timeCandidates);
      continue;
    }
    if (length > kMaxSamples)
      throw InputError(dimName, "dimension of " + std::to_string(length) + " samples", "the file header is damaged",
                       {file_, 0, 0});
    const NcVariable& tv = vars[time->variable];
    requireGregorianCalendar(tv, file_);
    LogTable t;
    t.file = file_;
    t.epoch = true;
    t.record_dimension = dimName;
    t.tag = dimName;
    t.time = nc_.values(tv, length, true);
    decodeCfTime(t.time, time->units);
    t.row_where.resize(length);
    for (std::size_t i = 0; i < length; ++i) t.row_where[i] = static_cast<long long>(i);

    for (auto& [k, name] : nameChannels(vars, byName, members, time->variable, seaglider)) {
      const NcVariable& v = vars[k];
      TableColumn c;
      c.source_name = v.name;
      c.where = {file_, 0, 0};
      c.source_unit = v.units;
      c.unit = normaliseUnitSpelling(v.units);
      c.name = std::move(name.name);
      c.scale = name.scale;
      c.to_unit = std::move(name.to_unit);
      if (!name.force_unit.empty()) c.unit = std::move(name.force_unit);
      c.values = nc_.values(v, length, true);
      for (const char* suffix : {"_qc", "_QC"})
        if (auto q = byName.find(v.name + suffix); q != byName.end()) {
          const NcVariable& qv = vars[q->second];
          if (qv.dims.size() == 1 && qv.dims[0] == dimId) nc_.applyQc(v, qv, c.values, length);
        }
      channelsFound.insert(c.name);
      t.columns.push_back(std::move(c));
    }
    // A GC state change is logged as two records at one instant (the state
    // left, the state entered); the entered one holds from then on.
    if (seaglider && dimName == "gc_state") detail::mergeSameTimeRows(t, detail::SameTimeRows::kLaterWins, rep_);
    if (seaglider && dimName == "sg_data_point")
      for (const auto& e : meta)
        if (e.key == "nc_dive_number") {
          TableColumn c;
          c.name = "dive_number";
          c.source_name = "dive_number (global attribute)";
          c.unit = "1";
          c.values.assign(length, std::strtod(e.value.c_str(), nullptr));
          t.columns.push_back(std::move(c));
        }
    rep_.data_lines += static_cast<long long>(length);
    rep_.lines += static_cast<long long>(length);
    tables.push_back(std::move(t));
  }
  if (tables.empty()) {
    std::string have;
    for (std::size_t k = 0; k < vars.size() && k < 40; ++k) have += (have.empty() ? "" : ", ") + vars[k].name;
    if (vars.size() > 40) have += ", ...";
    throw InputError("time",
                     "no time coordinate: no 1-D variable has CF time units \"<unit> since <date>\"" +
                         (timeCandidates.empty() ? std::string() : " (time-like: " + timeCandidates + ")") +
                         "; variables: " + (have.empty() ? std::string("none") : have),
                     "the file needs a time variable such as TIME with units \"seconds since 1970-01-01T00:00:00Z\"",
                     {file_, 0, 0});
  }
  bool anyRows = false;
  for (auto& t : tables) {
    tidyTable(t, opt_, rep_);
    anyRows |= !t.time.empty();
  }
  if (!anyRows)
    throw InputError("time", "no sample has a valid time (all fill values or NaN)",
                     "the file holds no usable data", {file_, 0, 0});
  tables.erase(std::remove_if(tables.begin(), tables.end(), [](const LogTable& t) { return t.time.empty(); }),
               tables.end());
  LogTable merged = mergeTables(std::move(tables), MergeNames::kRename, opt_, rep_);
  const std::string missing = missingChannels(channelsFound);
  if (!missing.empty()) meta.push_back({"missing_channels", missing});
  if (!notImported.empty()) meta.push_back({"not_imported", "dimensions without a time coordinate: " + notImported});
  if (!nc_.qcSummary().empty()) meta.push_back({"qc_blanked", nc_.qcSummary() + " values flagged bad by the file's own QC"});
  merged.metadata = std::move(meta);
  return finishTable(std::move(merged), rep_, false);
}

MissionLog runParser(int ncid, const std::string& name, const ReadOptions& options, ReadReport& report) {
  NcHandle h;
  h.id = ncid;
  if (options.progress && !options.progress(0.0)) throw ReadCancelled(name);
  return guardMemory(name, [&] {
    NetcdfParser p(ncid, name, options, report);
    MissionLog log = p.read();
    if (options.progress && !options.progress(1.0)) throw ReadCancelled(name);
    return log;
  });
}

void openFailed(int status, const std::string& name) {
  throw InputError("netcdf", std::string("cannot open as NetCDF: ") + nc_strerror(status),
                   status == NC_ENOTNC || status == NC_ETRUNC
                       ? "the file is damaged or cut short; copy it again from the glider's basestation or data server"
                       : "check the file",
                   {name, 0, 0});
}

}  // namespace

bool GliderNetcdfReader::canRead(const std::filesystem::path&, std::string_view head) const {
  if (head.size() >= 4 && head.substr(0, 3) == "CDF" && (head[3] == '\x01' || head[3] == '\x02' || head[3] == '\x05'))
    return true;
  return head.size() >= 8 && head.substr(0, 8) == std::string_view("\x89HDF\r\n\x1a\n", 8);
}

MissionLog GliderNetcdfReader::read(const std::filesystem::path& path, const ReadOptions& options,
                                    ReadReport& report) const {
  return readGliderNetcdf(path, options, report);
}

MissionLog readGliderNetcdf(const std::filesystem::path& path, const ReadOptions& options, ReadReport& report) {
  report = ReadReport{};
  const std::string name = path.string();
  report.file = name;
  report.format = "glider NetCDF";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError("log", std::filesystem::exists(path, ec) ? "not a regular file" : "cannot open file: no such file",
                     "check the path of the NetCDF file", {name, 0, 0});
  {
    const std::string head = readFirstBytes(path, std::size_t{8} << 20);
    refuseDamagedHeader(head, std::filesystem::file_size(path, ec), name);
  }
  int id = -1;
  const int st = nc_open(name.c_str(), NC_NOWRITE, &id);
  if (st != NC_NOERR) openFailed(st, name);
  return runParser(id, name, options, report);
}

MissionLog parseGliderNetcdf(const void* data, std::size_t size, const std::string& sourceName,
                             const ReadOptions& options, ReadReport& report) {
  report = ReadReport{};
  report.file = sourceName;
  report.format = "glider NetCDF";
  if (size < 4) throw InputError("netcdf", "too short for a NetCDF file", "check the file", {sourceName, 0, 0});
  refuseDamagedHeader(std::string_view(static_cast<const char*>(data), size), size, sourceName);
  std::vector<char> copy(static_cast<const char*>(data), static_cast<const char*>(data) + size);
  int id = -1;
  const int st = nc_open_mem(sourceName.c_str(), NC_NOWRITE, size, copy.data(), &id);
  if (st != NC_NOERR) openFailed(st, sourceName);
  // nc_open_mem reads the image in place: `copy` must outlive the handle.
  return runParser(id, sourceName, options, report);
}

}  // namespace auv
