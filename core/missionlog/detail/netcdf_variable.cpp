#include "missionlog/detail/netcdf_variable.h"

#include <cmath>
#include <limits>

#include "common/input_error.h"
#include "missionlog/detail/report_problem.h"
#include "missionlog/log_table.h"

namespace auv::detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kMaxAttributeChars = 200;

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

}  // namespace

bool isNumericType(nc_type t) {
  switch (t) {
    case NC_BYTE: case NC_UBYTE: case NC_SHORT: case NC_USHORT: case NC_INT: case NC_UINT:
    case NC_INT64: case NC_UINT64: case NC_FLOAT: case NC_DOUBLE: return true;
    default: return false;
  }
}

void NetcdfFile::check(int status, const std::string& what) const {
  if (status != NC_NOERR)
    throw InputError("netcdf", what + ": " + nc_strerror(status),
                     "the file is damaged or not a NetCDF file; copy it again or re-export it", {file_, 0, 0});
}

std::optional<std::string> NetcdfFile::textAttribute(int varid, const char* name) const {
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

std::vector<double> NetcdfFile::numberAttribute(int varid, const char* name) const {
  nc_type t = NC_NAT;
  size_t len = 0;
  if (nc_inq_att(nc_, varid, name, &t, &len) != NC_NOERR || !isNumericType(t) || len == 0 || len > 64) return {};
  std::vector<double> v(len);
  if (nc_get_att_double(nc_, varid, name, v.data()) != NC_NOERR) return {};
  return v;
}

NcVariable NetcdfFile::describe(int varid) const {
  NcVariable v;
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

std::vector<double> NetcdfFile::values(const NcVariable& v, std::size_t n, bool packing) {
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
    reportProblem(rep_, opt_, ReadProblemKind::kValueOutOfRange, {file_, 0, 0}, v.name,
                  std::to_string(outOfRange) + " values outside the variable's valid_min/valid_max; treated as not sampled",
                  "nothing to do if the file's valid range is right");
    rep_.counts[static_cast<std::size_t>(ReadProblemKind::kValueOutOfRange)] += outOfRange - 1;
  }
  return data;
}

// QC flags (Argo / OG1 / basestation): 0 not checked, 1 good, 2 probably
// good, 5 changed, 8 interpolated are kept; 3 probably bad, 4 bad,
// 6 unsampled, 7 nominal, 9 missing are blanked.
void NetcdfFile::applyQc(const NcVariable& v, const NcVariable& qc, std::vector<double>& data, std::size_t n) {
  std::vector<double> flags(n, 0.0);
  if (qc.type == NC_CHAR) {
    std::string text(n, '0');
    if (n && nc_get_var_text(nc_, qc.id, text.data()) != NC_NOERR) return;
    for (std::size_t i = 0; i < n; ++i) flags[i] = text[i] >= '0' && text[i] <= '9' ? text[i] - '0' : 0;
  } else if (isNumericType(qc.type)) {
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
  if (quietQc_) {
    qcSummary_ += (qcSummary_.empty() ? "" : ", ") + v.name + " " + std::to_string(blanked);
    return;
  }
  reportProblem(rep_, opt_, ReadProblemKind::kValueOutOfRange, {file_, 0, 0}, v.name,
                std::to_string(blanked) + " values flagged bad in " + qc.name + " (3, 4, 6, 7 or 9); treated as not sampled",
                "nothing to do: the file's own quality control rejected them");
}

void NetcdfFile::globalMetadata(std::vector<MetadataEntry>& out) const {
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

}  // namespace auv::detail
