#include "missionlog/detail/slocum_cycles.h"

#include <bit>
#include <cstring>
#include <limits>

#include "common/input_error.h"

namespace auv::detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kKnownBytesSize = 16;

inline std::uint16_t swapBytes(std::uint16_t u) { return __builtin_bswap16(u); }
inline std::uint32_t swapBytes(std::uint32_t u) { return __builtin_bswap32(u); }
inline std::uint64_t swapBytes(std::uint64_t u) { return __builtin_bswap64(u); }

template <class T>
T load(const unsigned char* p, bool swap) {
  using U = std::conditional_t<sizeof(T) == 1, std::uint8_t,
                               std::conditional_t<sizeof(T) == 2, std::uint16_t,
                                                  std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;
  U u;
  std::memcpy(&u, p, sizeof u);
  if constexpr (sizeof(T) > 1)
    if (swap) u = swapBytes(u);
  return std::bit_cast<T>(u);
}

// The host is little-endian on every platform this project builds for; the
// swap flag is relative to it.
static_assert(std::endian::native == std::endian::little, "the Slocum decoder assumes a little-endian host");

double value(const unsigned char* p, int bytes, bool swap) {
  switch (bytes) {
    case 1: return static_cast<double>(load<std::int8_t>(p, swap));
    case 2: return static_cast<double>(load<std::int16_t>(p, swap));
    case 4: return static_cast<double>(load<float>(p, swap));
    default: return load<double>(p, swap);
  }
}

// Calls f(sensor index, bits) for every sensor whose state bits are not 00,
// in sensor order. Most sensors are 00 in most cycles (a flight computer
// logs ~2000 and changes a few dozen), so zero words are skipped 8 bytes at
// a time.
template <class F>
inline void forEachWritten(const unsigned char* state, std::size_t stateBytes, F&& f) {
  std::size_t b = 0;
  while (b < stateBytes) {
    if (b + 8 <= stateBytes) {
      std::uint64_t w;
      std::memcpy(&w, state + b, sizeof w);
      if (!w) {
        b += 8;
        continue;
      }
    }
    const unsigned s = state[b];
    if (s)
      for (unsigned k = 0; k < 4; ++k) {
        const unsigned bits = (s >> (6 - 2 * k)) & 3u;
        if (bits) f(4 * b + k, bits);
      }
    ++b;
  }
}

bool knownBytes(const unsigned char* p, bool swap) {
  return load<std::int16_t>(p + 2, swap) == 0x1234 && load<float>(p + 4, swap) == 123.456f &&
         load<double>(p + 8, swap) == 123456789.12345;
}

}  // namespace

SlocumCycles decodeSlocumCycles(std::string_view data, std::size_t at, const std::vector<SlocumSensor>& sensors,
                                long stateBytesLong, int timeSensor, const std::string& file) {
  SlocumCycles out;
  const auto* base = reinterpret_cast<const unsigned char*>(data.data());
  const std::size_t size = data.size();
  if (size - at < kKnownBytesSize || base[at] != 's' || base[at + 1] != 'a')
    throw InputError("known_bytes",
                     "no known-bytes cycle ('s' 'a' ...) at byte " + std::to_string(at) + " after the header",
                     "the file is truncated or damaged right after its header; copy it from the glider again",
                     {file, 0, 0});
  const unsigned char* kb = base + at;
  if (knownBytes(kb, false)) out.little_endian = true;
  else if (knownBytes(kb, true)) out.little_endian = false;
  else
    throw InputError("known_bytes",
                     "the known-bytes cycle at byte " + std::to_string(at) +
                         " does not hold 0x1234, 123.456 and 123456789.12345 in either byte order",
                     "the file is damaged; copy it from the glider again", {file, 0, 0});
  const bool swap = !out.little_endian;
  at += kKnownBytesSize;

  const std::size_t n = sensors.size();
  const auto stateBytes = static_cast<std::size_t>(stateBytesLong);
  std::vector<int> width(n);
  for (std::size_t k = 0; k < n; ++k) width[k] = sensors[k].bytes;

  // Pass 1 walks the cycles, checks each is whole and sane, and counts every
  // sensor's samples, so that pass 2 writes into vectors reserved once (the
  // output is several times the input: growing vectors cost more than the
  // decoding).
  std::vector<std::uint32_t> count(n, 0);
  auto stop = [&](std::size_t where, std::string why) {
    out.damage = std::move(why);
    out.damage_at = where;
  };
  const unsigned char* end = base + size;
  while (at < size) {
    const unsigned char tag = base[at];
    if (tag == 'X') {
      out.saw_end_tag = true;
      out.ended_cleanly = true;
      break;
    }
    if (tag != 'd') {
      stop(at, "unknown cycle tag 0x" + std::string(1, "0123456789abcdef"[tag >> 4]) +
                   std::string(1, "0123456789abcdef"[tag & 15]) + " (expected 'd' or 'X'); the rest of the file is not read");
      break;
    }
    if (size - at - 1 < stateBytes) {
      stop(at, "the file ends inside the state bytes of a data cycle; that cycle is not read");
      break;
    }
    const unsigned char* state = base + at + 1;
    std::size_t need = 0;
    bool odd = false;
    forEachWritten(state, stateBytes, [&](std::size_t idx, unsigned bits) {
      if (bits == 3 || idx >= n) {
        odd = true;
        return;
      }
      ++count[idx];
      if (bits == 2) need += static_cast<std::size_t>(width[idx]);
    });
    if (odd) {
      // The counts of this cycle are only an over-estimate for the reserve.
      stop(at, "a data cycle has state bits 11 or a state for a sensor beyond the list; the rest of the file is not read");
      break;
    }
    if (static_cast<std::size_t>(end - (state + stateBytes)) < need) {
      stop(at, "the file ends inside a data cycle; that cycle is not read");
      break;
    }
    out.cycle_offset.push_back(at);
    at += 1 + stateBytes + need;
  }
  if (out.damage.empty()) out.ended_cleanly = true;  // 'X', or the data ended after a whole cycle

  // Pass 2: the values of the whole cycles found above.
  out.cycles = out.cycle_offset.size();
  out.sensors.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    out.sensors[k].cycle.reserve(count[k]);
    out.sensors[k].value.reserve(count[k]);
  }
  out.time.resize(out.cycles, kNaN);
  std::vector<double> held(n, kNaN);
  std::vector<char> known(n, 0);
  for (std::size_t c = 0; c < out.cycles; ++c) {
    const unsigned char* state = base + out.cycle_offset[c] + 1;
    const unsigned char* p = state + stateBytes;
    const auto cycle = static_cast<std::uint32_t>(c);
    forEachWritten(state, stateBytes, [&](std::size_t idx, unsigned bits) {
      double& h = held[idx];
      if (bits == 2) {
        h = value(p, width[idx], swap);
        p += width[idx];
      } else if (!known[idx]) {
        return;  // "same as before" with nothing before in this file
      }
      known[idx] = 1;
      auto& sv = out.sensors[idx];
      sv.cycle.push_back(cycle);
      sv.value.push_back(h);
    });
    if (timeSensor >= 0) {
      const auto ts = static_cast<std::size_t>(timeSensor);
      if (((state[ts / 4] >> (6 - 2 * (ts % 4))) & 3u) != 0 && known[ts]) out.time[c] = held[ts];
    }
  }
  return out;
}

}  // namespace auv::detail
