#pragma once
// The binary part of a Slocum file: the known-bytes cycle ('s', 'a', int16
// 0x1234, float32 123.456, float64 123456789.12345), which fixes the byte
// order, then data cycles ('d', 2 state bits per sensor, then the new values
// in sensor order) until 'X' (or the end of the data: newer gliders do not
// write the 'X'). State bits: 00 not written, 01 written again with the value
// it had, 10 written with a new value (the only one that carries bytes). Both
// 01 and 10 are samples, as the vendor's dbd2asc prints them
// (docs/decisions/slocum-binary-repeated-values.md).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "missionlog/detail/slocum_sensor_list.h"

namespace auv::detail {

// The values written (states 01 and 10) of one sensor, as stored (inf and nan
// kept); 01 repeats the sensor's last 10 value of the same file, and a 01
// before any 10 is no sample.
struct SlocumSensorValues {
  std::vector<std::uint32_t> cycle;  // 0-based data cycle
  std::vector<double> value;
};

struct SlocumCycles {
  bool little_endian = true;
  std::size_t cycles = 0;                  // complete data cycles decoded
  std::vector<double> time;                // per cycle: the time sensor's value, NaN if not written
  std::vector<std::size_t> cycle_offset;   // per cycle: byte offset of its 'd'
  std::vector<SlocumSensorValues> sensors;  // parallel to the sensor list
  bool ended_cleanly = false;              // 'X' (or the end of the data right after a whole cycle)
  bool saw_end_tag = false;
  std::string damage;                      // why decoding stopped early, "" if it did not
  std::size_t damage_at = 0;               // byte offset of the damage
};

// Decodes from byte `at` of `data`. `timeSensor` is the index of
// m_present_time / sci_m_present_time in `sensors`, or -1. Throws InputError
// only when the known-bytes cycle is missing or wrong (nothing can be read);
// damage after it stops decoding and is described in `damage`.
SlocumCycles decodeSlocumCycles(std::string_view data, std::size_t at, const std::vector<SlocumSensor>& sensors,
                                long stateBytes, int timeSensor, const std::string& file);

}  // namespace auv::detail
