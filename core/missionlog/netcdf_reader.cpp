#include "missionlog/netcdf_reader.h"

#include <netcdf.h>
#include <netcdf_mem.h>

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string_view>
#include <vector>

#include "common/input_error.h"
#include "missionlog/log_table.h"
#include "missionlog/time_text.h"
#include "missionlog/unit_conversion.h"
#include "missionlog/unit_spelling.h"

namespace auv {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Far beyond any glider log (a year at 10 Hz is 3e8 samples would not fit
// anyway); a larger dimension is a damaged header, not data.
constexpr std::size_t kMaxSamples = 200'000'000;
constexpr std::size_t kMaxAttributeChars = 200;

// Known variables: name (exact) -> channel. Order matters: the first one
// present in a dimension wins its channel, later ones keep their own names.
struct VarRule {
  std::string_view variable;
  std::string_view channel;
  double scale = 1.0;
  std::string_view to_unit = {};       // extra channels: convert to this
  std::string_view force_unit = {};    // the file's unit label is known to be wrong
};

constexpr VarRule kSeagliderRules[] = {
    {"depth", "depth"},
    {"pressure", "pressure"},
    {"eng_pitchAng", "pitch"},
    {"eng_rollAng", "roll"},
    {"eng_head", "heading"},
    {"eng_vbdCC", "pump_volume"},
    // Seaglider counts the pitch mass positive aft (nose up); the format
    // counts battery_position positive forward (nose down).
    {"eng_pitchCtl", "battery_position", -1.0},
    {"eng_rollCtl", "roll_mass"},
    {"temperature", "temperature"},
    {"salinity", "salinity"},
    {"conductivity", "conductivity"},
    // basestation labels in-situ density "g/m^3" but writes kg/m^3 (~1025).
    {"density_insitu", "density", 1.0, {}, "kg/m3"},
    {"speed", "speed_flightmodel"},
    {"glide_angle", "glide_angle_flightmodel"},
    {"vert_speed", "vert_speed_flightmodel", 1.0, "m/s"},
    {"buoyancy", "buoyancy_flightmodel"},
};

constexpr VarRule kTrajectoryRules[] = {
    {"DEPTH", "depth"},         {"depth", "depth"},
    {"PRES", "pressure"},       {"pressure", "pressure"},       {"PRESSURE", "pressure"},
    {"PITCH", "pitch"},         {"pitch", "pitch"},
    {"ROLL", "roll"},           {"roll", "roll"},
    {"HEADING", "heading"},     {"heading", "heading"},
    {"TEMP", "temperature"},    {"temperature", "temperature"}, {"TEMPERATURE", "temperature"},
    {"CNDC", "conductivity"},   {"conductivity", "conductivity"},
    {"PSAL", "salinity"},       {"salinity", "salinity"},
    {"DENSITY", "density"},     {"density", "density"},
};

// CF standard names, for variables the tables above do not name.
constexpr std::pair<std::string_view, std::string_view> kStandardNames[] = {
    {"depth", "depth"},
    {"sea_water_pressure", "pressure"},
    {"platform_pitch", "pitch"},
    {"platform_pitch_fore_up", "pitch"},
    {"platform_roll", "roll"},
    {"platform_roll_starboard_down", "roll"},
    {"platform_orientation", "heading"},
    {"platform_yaw", "heading"},
    {"sea_water_temperature", "temperature"},
    {"sea_water_practical_salinity", "salinity"},
    {"sea_water_salinity", "salinity"},
    {"sea_water_electrical_conductivity", "conductivity"},
    {"sea_water_density", "density"},
};

// The channels an analysis looks for, to say which ones a file lacks.
constexpr std::string_view kExpected[] = {"depth", "pitch", "roll", "heading", "temperature", "salinity", "pressure"};

struct NcHandle {
  int id = -1;
  ~NcHandle() {
    if (id >= 0) nc_close(id);
  }
};

struct Var {
  int id = 0;
  std::string name;
  nc_type type = NC_NAT;
  std::vector<int> dims;
  std::string units, standard_name, calendar;
  std::optional<double> fill, missing, valid_min, valid_max;
  double scale = 1.0, add_offset = 0.0;
};

bool numericType(nc_type t) {
  switch (t) {
    case NC_BYTE: case NC_UBYTE: case NC_SHORT: case NC_USHORT: case NC_INT: case NC_UINT:
    case NC_INT64: case NC_UINT64: case NC_FLOAT: case NC_DOUBLE: return true;
    default: return false;
  }
}

double defaultFill(nc_type t) {
  switch (t) {
    case NC_BYTE: return NC_FILL_BYTE;
    case NC_UBYTE: return NC_FILL_UBYTE;
    case NC_SHORT: return NC_FILL_SHORT;
    case NC_USHORT: return NC_FILL_USHORT;
    case NC_INT: return NC_FILL_INT;
    case NC_UINT: return NC_FILL_UINT;
    case NC_INT64: return static_cast<double>(NC_FILL_INT64);
    case NC_UINT64: return static_cast<double>(NC_FILL_UINT64);
    case NC_FLOAT: return static_cast<double>(NC_FILL_FLOAT);
    default: return NC_FILL_DOUBLE;
  }
}

// Walks the header of a classic / 64-bit-offset / CDF-5 file and checks
// that every count and length fits in the bytes there are. libnetcdf
// allocates what a header claims before it checks anything, so a damaged
// count (4 GB of "dimensions" in a 1 kB file) must be refused first.
// `bytes` is the start of the file, `fileSize` its full size. Returns a
// description of the damage, or "" when nothing is wrong as far as `bytes`
// reaches.
std::string classicHeaderDamage(std::string_view bytes, std::uint64_t fileSize) {
  if (bytes.size() < 4 || bytes.substr(0, 3) != "CDF") return {};
  const int version = bytes[3];
  if (version != 1 && version != 2 && version != 5) return "unknown NetCDF version byte " + std::to_string(version);
  const bool cdf5 = version == 5;
  const bool complete = bytes.size() >= fileSize;
  std::size_t at = 4;
  bool ranOut = false;
  auto take = [&](std::size_t n, std::uint64_t& v) {
    if (at + n > bytes.size()) {
      ranOut = true;
      return false;
    }
    v = 0;
    for (std::size_t i = 0; i < n; ++i) v = v << 8 | static_cast<unsigned char>(bytes[at + i]);
    at += n;
    return true;
  };
  auto skip = [&](std::uint64_t n) {
    if (n > bytes.size() - at) {
      ranOut = true;
      return false;
    }
    at += static_cast<std::size_t>(n);
    return true;
  };
  const std::size_t countBytes = cdf5 ? 8 : 4;
  const std::uint64_t left = fileSize;
  std::uint64_t v = 0;
  if (!take(countBytes, v)) return complete ? "the header is cut short" : "";  // numrecs
  // A list: tag (4 bytes), count; each element at least `minSize` bytes.
  auto list = [&](std::uint64_t tag, std::uint64_t minSize, std::uint64_t& count) -> std::string {
    std::uint64_t t = 0;
    count = 0;
    if (!take(4, t) || !take(countBytes, count)) return {};
    if (t == 0 && count == 0) return {};
    if (t != tag) return "a header list has tag " + std::to_string(t) + " instead of " + std::to_string(tag);
    if (count > left / minSize) return "the header claims " + std::to_string(count) + " entries in a " +
                                       std::to_string(fileSize) + "-byte file";
    return {};
  };
  auto name = [&]() {
    std::uint64_t len = 0;
    if (!take(countBytes, len)) return std::string();
    if (len > left) return std::string("a name of ") + std::to_string(len) + " bytes";
    skip((len + 3) / 4 * 4);
    return std::string();
  };
  auto attributes = [&]() -> std::string {
    std::uint64_t n = 0;
    if (auto e = list(0x0C, 12, n); !e.empty()) return e;
    for (std::uint64_t i = 0; i < n && !ranOut; ++i) {
      if (auto e = name(); !e.empty()) return e;
      std::uint64_t type = 0, count = 0;
      if (!take(4, type) || !take(countBytes, count)) break;
      static constexpr std::uint64_t kSize[] = {0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8};
      if (type == 0 || type > 11) return "an attribute of unknown type " + std::to_string(type);
      if (count > left / kSize[type]) return "an attribute of " + std::to_string(count) + " values";
      skip((count * kSize[type] + 3) / 4 * 4);
    }
    return {};
  };
  std::uint64_t ndims = 0;
  if (auto e = list(0x0A, 8, ndims); !e.empty()) return e;
  for (std::uint64_t i = 0; i < ndims && !ranOut; ++i) {
    if (auto e = name(); !e.empty()) return e;
    if (!take(countBytes, v)) break;
  }
  if (!ranOut)
    if (auto e = attributes(); !e.empty()) return e;
  std::uint64_t nvars = 0;
  if (!ranOut)
    if (auto e = list(0x0B, 24, nvars); !e.empty()) return e;
  for (std::uint64_t i = 0; i < nvars && !ranOut; ++i) {
    if (auto e = name(); !e.empty()) return e;
    std::uint64_t rank = 0;
    if (!take(countBytes, rank)) break;
    if (rank > NC_MAX_VAR_DIMS) return "a variable with " + std::to_string(rank) + " dimensions";
    for (std::uint64_t d = 0; d < rank; ++d) {
      if (!take(countBytes, v)) break;
      if (v >= ndims) return "a variable on dimension " + std::to_string(v) + " of " + std::to_string(ndims);
    }
    if (auto e = attributes(); !e.empty()) return e;
    if (!skip(4 + (cdf5 ? 8 : 4) + (version == 1 ? 4 : 8))) break;  // type, vsize, begin
  }
  if (ranOut && complete) return "the header is cut short";
  return {};
}

void refuseDamagedHeader(std::string_view bytes, std::uint64_t fileSize, const std::string& name) {
  const std::string damage = classicHeaderDamage(bytes, fileSize);
  if (!damage.empty())
    throw InputError("netcdf", "damaged NetCDF header: " + damage,
                     "the file is damaged or cut short; copy it again from the glider's basestation or data server",
                     {name, 0, 0});
}

class NetcdfParser {
 public:
  NetcdfParser(std::string file, const ReadOptions& o, ReadReport& r) : file_(std::move(file)), opt_(o), rep_(r) {}
  MissionLog read(int ncid);

 private:
  void check(int status, const std::string& what) const {
    if (status != NC_NOERR)
      throw InputError("netcdf", what + ": " + nc_strerror(status),
                       "the file is damaged or not a NetCDF file; copy it again or re-export it", {file_, 0, 0});
  }
  std::optional<std::string> textAttribute(int varid, const char* name) const;
  std::vector<double> numberAttribute(int varid, const char* name) const;
  Var describe(int varid) const;
  std::vector<double> values(const Var& v, std::size_t n, bool applyPacking);
  void applyQc(const Var& v, const Var& qc, std::vector<double>& data, std::size_t n);
  void metadataFromGlobals(std::vector<MetadataEntry>& out) const;

  std::string file_;
  const ReadOptions& opt_;
  ReadReport& rep_;
  int nc_ = -1;
};

std::optional<std::string> NetcdfParser::textAttribute(int varid, const char* name) const {
  nc_type t = NC_NAT;
  size_t len = 0;
  if (nc_inq_att(nc_, varid, name, &t, &len) != NC_NOERR) return std::nullopt;
  if (t == NC_CHAR) {
    if (len > (1u << 20)) return std::nullopt;
    std::string s(len, '\0');
    if (len && nc_get_att_text(nc_, varid, name, s.data()) != NC_NOERR) return std::nullopt;
    while (!s.empty() && s.back() == '\0') s.pop_back();
    return s;
  }
  if (t == NC_STRING && len >= 1 && len < 4096) {
    std::vector<char*> ptrs(len, nullptr);
    if (nc_get_att_string(nc_, varid, name, ptrs.data()) != NC_NOERR) return std::nullopt;
    std::string s = ptrs[0] ? ptrs[0] : "";
    nc_free_string(len, ptrs.data());
    return s;
  }
  return std::nullopt;
}

std::vector<double> NetcdfParser::numberAttribute(int varid, const char* name) const {
  nc_type t = NC_NAT;
  size_t len = 0;
  if (nc_inq_att(nc_, varid, name, &t, &len) != NC_NOERR || !numericType(t) || len == 0 || len > 64) return {};
  std::vector<double> v(len);
  if (nc_get_att_double(nc_, varid, name, v.data()) != NC_NOERR) return {};
  return v;
}

Var NetcdfParser::describe(int varid) const {
  Var v;
  v.id = varid;
  char name[NC_MAX_NAME + 1] = {};
  int ndims = 0;
  check(nc_inq_var(nc_, varid, name, &v.type, &ndims, nullptr, nullptr), "cannot read variable " + std::to_string(varid));
  v.name = name;
  if (ndims > 0 && ndims <= NC_MAX_VAR_DIMS) {
    v.dims.resize(static_cast<std::size_t>(ndims));
    check(nc_inq_vardimid(nc_, varid, v.dims.data()), "cannot read the dimensions of " + v.name);
  } else if (ndims > NC_MAX_VAR_DIMS) {
    v.dims.assign(2, -1);  // not a 1-D variable; never imported
  }
  v.units = textAttribute(varid, "units").value_or("");
  v.standard_name = textAttribute(varid, "standard_name").value_or("");
  v.calendar = textAttribute(varid, "calendar").value_or("");
  if (auto f = numberAttribute(varid, "_FillValue"); !f.empty()) v.fill = f[0];
  if (auto f = numberAttribute(varid, "missing_value"); !f.empty()) v.missing = f[0];
  if (auto f = numberAttribute(varid, "valid_min"); !f.empty()) v.valid_min = f[0];
  if (auto f = numberAttribute(varid, "valid_max"); !f.empty()) v.valid_max = f[0];
  if (auto f = numberAttribute(varid, "valid_range"); f.size() == 2) {
    v.valid_min = f[0];
    v.valid_max = f[1];
  }
  if (auto f = numberAttribute(varid, "scale_factor"); !f.empty() && std::isfinite(f[0]) && f[0] != 0.0) v.scale = f[0];
  if (auto f = numberAttribute(varid, "add_offset"); !f.empty() && std::isfinite(f[0])) v.add_offset = f[0];
  return v;
}

// The variable as doubles, with every kind of "no value" as NaN. Values out
// of valid_range are blanked and counted; fills are not (they are the file's
// way of saying "not sampled").
std::vector<double> NetcdfParser::values(const Var& v, std::size_t n, bool packing) {
  std::vector<double> data(n);
  if (n) check(nc_get_var_double(nc_, v.id, data.data()), "cannot read variable " + v.name);
  const double typeFill = defaultFill(v.type);
  long long outOfRange = 0;
  for (double& x : data) {
    if (std::isnan(x)) continue;
    if ((v.fill && x == *v.fill) || (v.missing && x == *v.missing) || (!v.fill && x == typeFill)) {
      x = kNaN;
      continue;
    }
    if ((v.valid_min && x < *v.valid_min) || (v.valid_max && x > *v.valid_max)) {
      x = kNaN;
      ++outOfRange;
      continue;
    }
    if (packing) x = x * v.scale + v.add_offset;
  }
  if (outOfRange) {
    rep_.cells_blanked += outOfRange;
    ReadProblem p;
    p.kind = ReadProblemKind::kValueOutOfRange;
    p.where = {file_, 0, 0};
    p.column = v.name;
    p.problem = std::to_string(outOfRange) + " values outside the variable's valid_min/valid_max; treated as not sampled";
    p.fix = "nothing to do if the file's valid range is right";
    rep_.add(std::move(p), opt_.max_problems_per_kind);
    rep_.counts[static_cast<std::size_t>(ReadProblemKind::kValueOutOfRange)] += outOfRange - 1;
  }
  return data;
}

// QC flags (Argo / OG1 / basestation): 0 not checked, 1 good, 2 probably
// good, 5 changed, 8 interpolated are kept; 3 probably bad, 4 bad,
// 6 unsampled, 7 nominal, 9 missing are blanked.
void NetcdfParser::applyQc(const Var& v, const Var& qc, std::vector<double>& data, std::size_t n) {
  std::vector<double> flags(n, 0.0);
  if (qc.type == NC_CHAR) {
    std::string text(n, '0');
    if (n && nc_get_var_text(nc_, qc.id, text.data()) != NC_NOERR) return;
    for (std::size_t i = 0; i < n; ++i) flags[i] = text[i] >= '0' && text[i] <= '9' ? text[i] - '0' : 0;
  } else if (numericType(qc.type)) {
    if (n && nc_get_var_double(nc_, qc.id, flags.data()) != NC_NOERR) return;
  } else {
    return;
  }
  long long blanked = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double f = flags[i];
    if (std::isnan(data[i])) continue;
    if (f == 3 || f == 4 || f == 6 || f == 7 || f == 9) {
      data[i] = kNaN;
      ++blanked;
    }
  }
  if (!blanked) return;
  rep_.cells_blanked += blanked;
  ReadProblem p;
  p.kind = ReadProblemKind::kValueOutOfRange;
  p.where = {file_, 0, 0};
  p.column = v.name;
  p.problem = std::to_string(blanked) + " values flagged bad in " + qc.name + " (3, 4, 6, 7 or 9); treated as not sampled";
  p.fix = "nothing to do: the file's own quality control rejected them";
  rep_.add(std::move(p), opt_.max_problems_per_kind);
}

void NetcdfParser::metadataFromGlobals(std::vector<MetadataEntry>& out) const {
  int natts = 0;
  if (nc_inq_natts(nc_, &natts) != NC_NOERR) return;
  for (int i = 0; i < natts && i < 500; ++i) {
    char name[NC_MAX_NAME + 1] = {};
    if (nc_inq_attname(nc_, NC_GLOBAL, i, name) != NC_NOERR) continue;
    std::string key = name;
    for (char& c : key)
      if (c == ':' || static_cast<unsigned char>(c) < 0x20) c = '_';
    if (key.empty()) continue;
    std::string value;
    if (auto t = textAttribute(NC_GLOBAL, name)) {
      value = *t;
    } else {
      const auto v = numberAttribute(NC_GLOBAL, name);
      if (v.size() != 1) continue;
      value = numberText(v[0]);
    }
    for (char& c : value)
      if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    if (value.size() > kMaxAttributeChars) value = value.substr(0, kMaxAttributeChars) + "...";
    out.push_back({"nc_" + key, value});
  }
}

MissionLog NetcdfParser::read(int ncid) {
  nc_ = ncid;
  int ndims = 0, nvars = 0;
  check(nc_inq_ndims(nc_, &ndims), "cannot read the dimensions");
  check(nc_inq_nvars(nc_, &nvars), "cannot read the variables");
  if (ndims < 0 || nvars < 0 || ndims > 100000 || nvars > 100000)
    throw InputError("netcdf", "implausible header (" + std::to_string(ndims) + " dimensions, " +
                                   std::to_string(nvars) + " variables)",
                     "the file is damaged", {file_, 0, 0});
  std::map<int, std::pair<std::string, std::size_t>> dims;  // id -> name, length
  {
    std::vector<int> ids(static_cast<std::size_t>(ndims));
    int got = 0;
    if (ndims) check(nc_inq_dimids(nc_, &got, ids.data(), 0), "cannot read the dimensions");
    for (int i = 0; i < got && i < ndims; ++i) {
      char name[NC_MAX_NAME + 1] = {};
      size_t len = 0;
      check(nc_inq_dim(nc_, ids[static_cast<std::size_t>(i)], name, &len), "cannot read a dimension");
      dims[ids[static_cast<std::size_t>(i)]] = {name, len};
    }
  }
  bool seaglider = false;
  for (const auto& [id, d] : dims) seaglider |= d.first == "sg_data_point";

  std::vector<Var> vars;
  std::map<std::string, std::size_t> byName;
  for (int i = 0; i < nvars; ++i) {
    vars.push_back(describe(i));
    byName[vars.back().name] = vars.size() - 1;
  }

  std::vector<MetadataEntry> meta;
  meta.push_back({"netcdf_flavour", seaglider ? "Seaglider basestation" : "IOOS/OG1 trajectory"});
  metadataFromGlobals(meta);
  for (const Var& v : vars)  // Seaglider calibration constants: sg_cal_mass etc.
    if (v.dims.empty() && numericType(v.type) && v.name.rfind("sg_cal_", 0) == 0) {
      double x = 0;
      if (nc_get_var_double(nc_, v.id, &x) == NC_NOERR && std::isfinite(x)) {
        meta.push_back({v.name, numberText(x)});
        if (v.name == "sg_cal_mass") meta.push_back({"mass_kg", numberText(x)});
      }
    }

  // One table per dimension that has a CF time coordinate.
  std::vector<LogTable> tables;
  std::string notImported, timeCandidates;
  std::set<std::string> channelsFound;
  for (const auto& [dimId, dim] : dims) {
    const std::string& dimName = dim.first;  // not a structured binding: lambdas below capture it
    const std::size_t length = dim.second;
    std::vector<std::size_t> members;
    for (std::size_t k = 0; k < vars.size(); ++k)
      if (vars[k].dims.size() == 1 && vars[k].dims[0] == dimId && numericType(vars[k].type)) members.push_back(k);
    if (members.empty()) continue;
    std::optional<std::size_t> timeVar;
    std::optional<CfTimeUnits> cf;
    auto preference = [&](const Var& v) {
      static constexpr std::string_view kNames[] = {"TIME", "time", "ctd_time"};
      for (std::size_t i = 0; i < 3; ++i)
        if (v.name == kNames[i]) return static_cast<int>(i);
      return v.name == dimName ? 3 : 4;
    };
    for (std::size_t k : members) {
      const auto units = parseCfTimeUnits(vars[k].units);
      if (!units) continue;
      if (!timeVar || preference(vars[k]) < preference(vars[*timeVar])) {
        timeVar = k;
        cf = units;
      }
    }
    if (!timeVar) {
      notImported += (notImported.empty() ? "" : "; ") + dimName + " (" + std::to_string(members.size()) + " variables)";
      for (std::size_t k : members) {
        const std::string l = vars[k].name;
        if (l == "time" || l == "TIME" || l.find("time") != std::string::npos)
          timeCandidates += (timeCandidates.empty() ? "" : ", ") + l + " [" + vars[k].units + "]";
      }
      continue;
    }
    if (length > kMaxSamples)
      throw InputError(dimName, "dimension of " + std::to_string(length) + " samples", "the file header is damaged",
                       {file_, 0, 0});
    const Var& tv = vars[*timeVar];
    if (!tv.calendar.empty() && tv.calendar != "standard" && tv.calendar != "gregorian" &&
        tv.calendar != "proleptic_gregorian")
      throw InputError(tv.name, "calendar \"" + tv.calendar + "\" is not the standard Gregorian calendar",
                       "write the time with calendar \"standard\" (every real clock uses it)", {file_, 0, 0});
    LogTable t;
    t.file = file_;
    t.epoch = true;
    t.record_dimension = dimName;
    t.tag = dimName;
    t.time = values(tv, length, true);
    for (double& x : t.time)
      if (!std::isnan(x)) x = x * cf->scale + cf->offset;
    t.row_where.resize(length);
    for (std::size_t i = 0; i < length; ++i) t.row_where[i] = static_cast<long long>(i);

    // Channel names for the members: table rules first, by their order.
    std::map<std::size_t, const VarRule*> ruleOf;
    std::set<std::string> taken;
    const auto rules = seaglider ? std::span<const VarRule>(kSeagliderRules) : std::span<const VarRule>(kTrajectoryRules);
    for (const VarRule& r : rules) {
      auto it = byName.find(std::string(r.variable));
      if (it == byName.end() || taken.count(std::string(r.channel))) continue;
      if (std::find(members.begin(), members.end(), it->second) == members.end()) continue;
      ruleOf[it->second] = &r;
      taken.insert(std::string(r.channel));
    }
    std::map<std::size_t, std::string> standardOf;
    for (std::size_t k : members) {
      if (ruleOf.count(k) || k == *timeVar) continue;
      for (const auto& [sn, ch] : kStandardNames)
        if (vars[k].standard_name == sn && !taken.count(std::string(ch))) {
          standardOf[k] = std::string(ch);
          taken.insert(std::string(ch));
          break;
        }
    }
    for (std::size_t k : members) {
      const Var& v = vars[k];
      if (k == *timeVar) continue;
      const std::string lname = v.name.size() > 3 ? v.name.substr(v.name.size() - 3) : "";
      if (lname == "_qc" || lname == "_QC") continue;  // applied to their variable below
      TableColumn c;
      c.source_name = v.name;
      c.where = {file_, 0, 0};
      c.source_unit = v.units;
      c.unit = normaliseUnitSpelling(v.units);
      if (auto r = ruleOf.find(k); r != ruleOf.end()) {
        c.name = std::string(r->second->channel);
        c.scale = r->second->scale;
        c.to_unit = std::string(r->second->to_unit);
        if (!r->second->force_unit.empty()) c.unit = std::string(r->second->force_unit);
      } else if (auto s = standardOf.find(k); s != standardOf.end()) {
        c.name = s->second;
      } else {
        c.name = safeChannelName(v.name);
        if (taken.count(c.name) || canonicalUnitFor(c.name).size()) c.name = "nc_" + c.name;
      }
      taken.insert(c.name);
      c.values = values(v, length, true);
      for (const char* suffix : {"_qc", "_QC"})
        if (auto q = byName.find(v.name + suffix); q != byName.end()) {
          const Var& qv = vars[q->second];
          if (qv.dims.size() == 1 && qv.dims[0] == dimId) applyQc(v, qv, c.values, length);
        }
      channelsFound.insert(c.name);
      t.columns.push_back(std::move(c));
    }
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
  std::string missing;
  for (auto ch : kExpected)
    if (!channelsFound.count(std::string(ch))) missing += (missing.empty() ? "" : ", ") + std::string(ch);
  if (!missing.empty()) meta.push_back({"missing_channels", missing});
  if (!notImported.empty()) meta.push_back({"not_imported", "dimensions without a time coordinate: " + notImported});
  merged.metadata = std::move(meta);
  return finishTable(std::move(merged), rep_, false);
}

MissionLog runParser(int ncid, const std::string& name, const ReadOptions& options, ReadReport& report) {
  NcHandle h;
  h.id = ncid;
  if (options.progress && !options.progress(0.0)) throw ReadCancelled(name);
  try {
    NetcdfParser p(name, options, report);
    MissionLog log = p.read(ncid);
    if (options.progress && !options.progress(1.0)) throw ReadCancelled(name);
    return log;
  } catch (const std::bad_alloc&) {
    throw InputError("log", "not enough memory to hold this log", "split the file or use a larger machine", {name, 0, 0});
  }
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
