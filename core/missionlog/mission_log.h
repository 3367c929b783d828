#pragma once
// A recorded or simulated mission as channels on one row time base. Storage is
// by column (one contiguous vector per channel, no per-sample objects) because
// logs run to millions of rows and every analysis reads whole channels.
// Sensors run at different rates, so a channel is sparse: NaN marks a row at
// which it was not sampled, and each channel's own time base is the set of
// rows where it is valid (see `series`).
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace auv {

// One `# key: value` line. Order and unknown keys are kept; a line without a
// colon is kept with an empty key.
struct MetadataEntry {
  std::string key;
  std::string value;
};

struct LogChannel {
  std::string name;
  std::string unit;         // after import conversion (canonical for table channels)
  std::string source_unit;  // as written in the file (equal to unit when nothing was converted)
  std::vector<double> values;  // one per log row; NaN = not sampled at that row

  std::size_t validCount() const;
};

// The valid samples of one channel on its own time base.
struct TimeSeries {
  std::vector<double> t;  // s since mission start, strictly increasing
  std::vector<double> v;
  std::size_t size() const { return t.size(); }
  bool empty() const { return t.empty(); }
};

class MissionLog {
 public:
  // Invariants (kept by the readers, checked by the writer): `time` is
  // strictly increasing and finite, every channel has time.size() values.
  std::vector<MetadataEntry> metadata;
  std::vector<double> time;  // s since `# start:`
  std::vector<LogChannel> channels;

  std::size_t rowCount() const { return time.size(); }
  double duration() const { return time.empty() ? 0.0 : time.back() - time.front(); }

  // First value for `key`, or nullptr.
  const std::string* metadataValue(std::string_view key) const;
  // Replaces the first entry with this key or appends one.
  void setMetadata(std::string key, std::string value);
  // The metadata entries whose key starts with `prefix` and whose value is a
  // finite number, by their whole key.
  std::map<std::string, double> numericMetadata(std::string_view prefix) const;
  // The constants a Seaglider log carries (GliderNetcdfReader puts them in
  // the metadata, so they also survive the interchange CSV): the basestation
  // calibration `sg_cal_*` (sg_cal_mass [kg], sg_cal_volmax [cm3],
  // sg_cal_hd_a/b/c, sg_cal_abs_compress [1/dbar], sg_cal_therm_expan
  // [1/degC], sg_cal_temp_ref [degC], sg_cal_rho0 [kg/m3] ...) and the
  // parameters the glider flew with, `log_*` (log_C_VBD, log_VBD_CNV,
  // log_C_PITCH, log_PITCH_CNV, log_MASS [g], log_HD_A ...), by their names
  // in the file and in the file's units. A mission of several dives has the
  // first dive's values (readMission keeps the first file's metadata). Empty
  // for logs of other vehicles.
  std::map<std::string, double> seagliderConstants() const;
  // `# start:` as seconds since 1970 UTC, if present and a valid ISO 8601 time.
  std::optional<double> startEpochSeconds() const;

  const LogChannel* find(std::string_view name) const;
  LogChannel* find(std::string_view name);
  bool has(std::string_view name) const { return find(name) != nullptr; }
  // Throws InputError naming the channel and listing what the log has.
  const LogChannel& channel(std::string_view name) const;
  // A new all-NaN channel of rowCount() values; throws std::invalid_argument
  // if the name is taken.
  LogChannel& addChannel(std::string name, std::string unit);

  // The channel's valid samples and their times (its own time base).
  TimeSeries series(std::string_view name) const;
  // Times at which the channel was sampled.
  std::vector<double> validTimes(std::string_view name) const;
};

}  // namespace auv
