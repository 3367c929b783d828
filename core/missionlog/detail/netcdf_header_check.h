#pragma once
// libnetcdf allocates what a classic-format header claims before it checks
// anything, so a damaged count (4 GB of "dimensions" in a 1 kB file) must be
// refused before the file is handed to it.
#include <cstdint>
#include <string>
#include <string_view>

namespace auv::detail {

// Walks the header of a classic / 64-bit-offset / CDF-5 file and checks that
// every count and length fits in the bytes there are. `bytes` is the start of
// the file, `fileSize` its full size. Returns a description of the damage, or
// "" when nothing is wrong as far as `bytes` reaches (and for HDF5 files).
std::string classicHeaderDamage(std::string_view bytes, std::uint64_t fileSize);

// Throws InputError naming `name` when classicHeaderDamage finds damage.
void refuseDamagedHeader(std::string_view bytes, std::uint64_t fileSize, const std::string& name);

}  // namespace auv::detail
