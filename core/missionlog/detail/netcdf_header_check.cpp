#include "missionlog/detail/netcdf_header_check.h"

#include <netcdf.h>

#include "common/input_error.h"

namespace auv::detail {

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

}  // namespace auv::detail
