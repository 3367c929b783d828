#pragma once
// A tiny writer of Slocum binary files for tests, fixtures, fuzz seeds and the
// benchmark, written from the same format description as the reader but
// independently of it: header tags, sensor lines, known-bytes cycle in either
// byte order, data cycles from explicit state bits and values, end tag 'X'.
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace auv::test {

struct SlocumWriterSensor {
  std::string name, unit;
  int bytes = 8;
};

// Per sensor: 0 not written, 1 same value as before, 2 new value (from `value`).
struct SlocumWriterCycle {
  std::vector<int> state;
  std::vector<double> value;
};

struct SlocumWriterFile {
  std::vector<SlocumWriterSensor> sensors;
  std::vector<SlocumWriterCycle> cycles;
  bool big_endian = false;
  bool factored = false;  // sensor list left out (then it goes into <crc>.cac)
  std::string crc = "1a2b3c4d";
  std::string extension = "dbd";
  std::string name = "unit_042-2024-100-1-0";
  int encoding = 5;
  bool end_tag = true;
};

inline std::string slocumSensorLines(const SlocumWriterFile& f) {
  std::string s;
  for (std::size_t k = 0; k < f.sensors.size(); ++k)
    s += "s: T " + std::to_string(k) + " " + std::to_string(k) + " " + std::to_string(f.sensors[k].bytes) + " " +
         f.sensors[k].name + " " + f.sensors[k].unit + "\n";
  return s;
}

namespace detail_writer {
template <class U>
void put(std::string& out, U u, bool big) {
  unsigned char b[sizeof(U)];
  std::memcpy(b, &u, sizeof u);  // the host is little-endian (checked by the reader)
  if (big)
    for (std::size_t i = 0; i < sizeof(U) / 2; ++i) std::swap(b[i], b[sizeof(U) - 1 - i]);
  out.append(reinterpret_cast<const char*>(b), sizeof b);
}
inline void putValue(std::string& out, double v, int bytes, bool big) {
  switch (bytes) {
    case 1: out += static_cast<char>(static_cast<std::int8_t>(v)); break;
    case 2: put(out, static_cast<std::uint16_t>(static_cast<std::int16_t>(v)), big); break;
    case 4: put(out, std::bit_cast<std::uint32_t>(static_cast<float>(v)), big); break;
    default: put(out, std::bit_cast<std::uint64_t>(v), big); break;
  }
}
}  // namespace detail_writer

inline std::string writeSlocumBinary(const SlocumWriterFile& f) {
  const std::size_t n = f.sensors.size();
  const std::size_t stateBytes = (n + 3) / 4;
  std::string out = "dbd_label:    DBD(dinkum_binary_data)file\n";
  out += "encoding_ver:    " + std::to_string(f.encoding) + "\n";
  out += "num_ascii_tags:    14\n";
  out += "all_sensors:    F\n";
  out += "the8x3_filename:    00420000\n";
  out += "full_filename:    " + f.name + "\n";
  out += "filename_extension:    " + f.extension + "\n";
  out += "mission_name:    TEST.MI\n";
  out += "fileopen_time:    Tue_Apr_09_12:00:00_2024\n";
  out += "total_num_sensors:    " + std::to_string(n) + "\n";
  out += "sensors_per_cycle:    " + std::to_string(n) + "\n";
  out += "state_bytes_per_cycle:    " + std::to_string(stateBytes) + "\n";
  out += "sensor_list_crc:    " + f.crc + "\n";
  out += "sensor_list_factored:    " + std::string(f.factored ? "1" : "0") + "\n";
  if (!f.factored) out += slocumSensorLines(f);
  out += "sa";
  detail_writer::put(out, std::uint16_t{0x1234}, f.big_endian);
  detail_writer::put(out, std::bit_cast<std::uint32_t>(123.456f), f.big_endian);
  detail_writer::put(out, std::bit_cast<std::uint64_t>(123456789.12345), f.big_endian);
  for (const auto& c : f.cycles) {
    out += 'd';
    std::string state(stateBytes, '\0');
    for (std::size_t k = 0; k < n; ++k)
      state[k / 4] = static_cast<char>(static_cast<unsigned char>(state[k / 4]) | (c.state[k] & 3) << (6 - 2 * (k % 4)));
    out += state;
    for (std::size_t k = 0; k < n; ++k)
      if (c.state[k] == 2) detail_writer::putValue(out, c.value[k], f.sensors[k].bytes, f.big_endian);
  }
  if (f.end_tag) out += 'X';
  return out;
}

}  // namespace auv::test
