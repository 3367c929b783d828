// libFuzzer target for the glider NetCDF reader. Two modes, chosen by the
// first byte:
//  - structured: the input drives the libnetcdf C API to build a classic
//    NetCDF file in memory (dimensions, OG1 / IOOS / Seaglider variable
//    names, types, CF units, fill values, packing, QC flags, and values
//    including NaN, inf, fills and wild times), optionally corrupted by a few
//    flipped bytes or a cut, then reads it: this explores the reader's own
//    logic on files libnetcdf accepts;
//  - raw: the input after a "CDF\x01" / "CDF\x02" magic goes straight to
//    nc_open_mem, for damaged headers.
// Checks fuzz_checks.h on every log.
#include <netcdf.h>
#include <netcdf_mem.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "fuzz_checks.h"
#include "missionlog/netcdf_reader.h"

namespace {

struct Input {
  const std::uint8_t* p;
  std::size_t n;
  std::size_t i = 0;
  std::uint8_t byte() { return i < n ? p[i++] : 0; }
  double number() {
    static const double kInteresting[] = {0.0, 1.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                                          std::numeric_limits<double>::infinity(), -1e300, 1e30, 9.969209968386869e36,
                                          -999.0, 1.7e9, 1.7e9 + 10, 1.7e9 - 5, 5.0, 90.0, 400.0, -127.0};
    const std::uint8_t b = byte();
    if (b < 200) return kInteresting[b % 16] + (b >= 16 ? static_cast<double>(b) : 0.0);
    double v = 0;
    std::uint8_t raw[8];
    for (auto& r : raw) r = byte();
    std::memcpy(&v, raw, 8);
    return v;
  }
};

constexpr const char* kDims[] = {"N_MEASUREMENTS", "time", "sg_data_point", "ctd_data_point", "gc_event", "profile"};
constexpr const char* kVars[] = {"TIME",        "time",         "ctd_time",     "DEPTH",       "PRES",
                                 "PITCH",       "ROLL",         "HEADING",      "TEMP",        "TEMP_QC",
                                 "CNDC",        "PSAL",         "depth",        "eng_pitchAng", "eng_pitchCtl",
                                 "eng_vbdCC",   "temperature",  "temperature_qc", "density_insitu", "speed",
                                 "LATITUDE",    "profile_time", "dive_number",  "sg_cal_mass", "x"};
constexpr const char* kUnits[] = {"seconds since 1970-01-01T00:00:00Z", "days since 1950-01-01", "s", "m", "degrees",
                                  "rad", "mS/cm", "S m-1", "1", "cm", "dbar", "bar", "furlong", "",
                                  "seconds since 1970-1-1 00:00:00", "hours since 2024-05-27 09:05:16 +02:00"};
constexpr nc_type kTypes[] = {NC_DOUBLE, NC_FLOAT, NC_INT, NC_BYTE, NC_SHORT, NC_CHAR};

// Builds a classic-format file image from the input; empty when libnetcdf
// refused a definition (that is not what is being fuzzed).
std::vector<char> build(Input& in) {
  int id = -1;
  if (nc_create_mem("fuzz.nc", NC_CLOBBER, 4096, &id) != NC_NOERR) return {};
  std::vector<int> dims;
  std::vector<std::size_t> lens;
  const int ndims = 1 + in.byte() % 3;
  for (int d = 0; d < ndims; ++d) {
    int dim = -1;
    const std::size_t len = in.byte() % 12;
    if (nc_def_dim(id, kDims[in.byte() % 6], len, &dim) == NC_NOERR) {
      dims.push_back(dim);
      lens.push_back(len);
    }
  }
  struct V {
    int id;
    nc_type type;
    std::size_t len;
  };
  std::vector<V> vars;
  const int nvars = in.byte() % 12;
  for (int k = 0; k < nvars && !dims.empty(); ++k) {
    const nc_type type = kTypes[in.byte() % 6];
    const std::uint8_t shape = in.byte();
    std::vector<int> vd;
    std::size_t len = 1;
    if (shape % 4 != 0) {
      const std::size_t a = shape % dims.size();
      vd.push_back(dims[a]);
      len = lens[a];
      if (shape % 4 == 3) {
        vd.push_back(dims[(a + 1) % dims.size()]);
        len *= lens[(a + 1) % dims.size()];
      }
    }
    int v = -1;
    if (nc_def_var(id, kVars[in.byte() % 25], type, static_cast<int>(vd.size()), vd.data(), &v) != NC_NOERR) continue;
    const char* units = kUnits[in.byte() % 16];
    nc_put_att_text(id, v, "units", std::strlen(units), units);
    const std::uint8_t extras = in.byte();
    if (extras & 1) {
      const double fill = in.number();
      nc_put_att_double(id, v, "_FillValue", type == NC_CHAR ? NC_DOUBLE : type, 1, &fill);
    }
    if (extras & 2) {
      const double scale = in.number();
      nc_put_att_double(id, v, "scale_factor", NC_DOUBLE, 1, &scale);
    }
    if (extras & 4) {
      const double range[2] = {in.number(), in.number()};
      nc_put_att_double(id, v, "valid_range", NC_DOUBLE, 2, range);
    }
    if (extras & 8) nc_put_att_text(id, v, "calendar", 7, "360_day");
    if (extras & 16) nc_put_att_text(id, v, "standard_name", 21, "sea_water_temperature");
    vars.push_back({v, type, len});
  }
  const double dive = in.number();
  nc_put_att_double(id, NC_GLOBAL, "dive_number", NC_DOUBLE, 1, &dive);
  if (nc_enddef(id) != NC_NOERR) {
    nc_abort(id);
    return {};
  }
  for (const V& v : vars) {
    if (v.type == NC_CHAR) {
      std::string text(v.len, '1');
      for (char& c : text) c = static_cast<char>('0' + in.byte() % 10);
      if (v.len) nc_put_var_text(id, v.id, text.data());
      continue;
    }
    std::vector<double> values(v.len);
    for (double& x : values) x = in.number();
    if (v.len) nc_put_var_double(id, v.id, values.data());  // out-of-range for small types: refused, fine
  }
  NC_memio mem{};
  if (nc_close_memio(id, &mem) != NC_NOERR || !mem.memory) return {};
  std::vector<char> bytes(static_cast<char*>(mem.memory), static_cast<char*>(mem.memory) + mem.size);
  std::free(mem.memory);
  return bytes;
}

void readAndCheck(const std::vector<char>& bytes) {
  auv::ReadOptions options;
  options.max_problems_per_kind = 3;
  auv::ReadReport report;
  try {
    const auv::MissionLog log = auv::parseGliderNetcdf(bytes.data(), bytes.size(), "fuzz.nc", options, report);
    auv::fuzz::checkLog(log, report, options.max_abs_value);
    auv::fuzz::roundTrip(log);
  } catch (const auv::InputError& e) {
    check(e.what()[0] != '\0');
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t mode = data[0];
  if (mode % 4 == 3) {  // raw
    std::vector<char> bytes = {'C', 'D', 'F', (mode & 4) ? '\x02' : '\x01'};
    bytes.insert(bytes.end(), data + 1, data + size);
    readAndCheck(bytes);
    return 0;
  }
  Input in{data + 1, size - 1};
  std::vector<char> bytes = build(in);
  if (bytes.empty()) return 0;
  if (mode % 4 == 1) {  // a few flipped bytes
    for (int k = 0; k < 3; ++k) {
      const std::size_t at = (static_cast<std::size_t>(in.byte()) << 8 | in.byte()) % bytes.size();
      bytes[at] = static_cast<char>(in.byte());
    }
  } else if (mode % 4 == 2) {  // cut short
    bytes.resize((static_cast<std::size_t>(in.byte()) << 8 | in.byte()) % bytes.size());
    if (bytes.size() < 4) return 0;
  }
  readAndCheck(bytes);
  return 0;
}
