#include "missionlog/detail/slocum_file.h"

#include "common/input_error.h"
#include "missionlog/detail/ascii_text.h"
#include "missionlog/detail/slocum_cache.h"
#include "missionlog/detail/slocum_channels.h"
#include "missionlog/detail/slocum_lz4.h"

namespace auv::detail {
namespace fs = std::filesystem;

namespace {

std::string missingCacheFix(const std::string& crc) {
  return "copy the glider's sensor-list cache " + lower(crc) + ".cac (or .ccc) from the glider's or the dockserver's "
         "cache folder next to the file, into the per-user cache, or into a folder given with --cache-dir DIR; "
         "reading any file of the same glider that carries its own sensor list also fills the per-user cache";
}

long crcLine(const SlocumHeader& h) {
  for (std::size_t i = 0; i < h.tags.size(); ++i)
    if (h.tags[i].key == "sensor_list_crc") return static_cast<long>(i) + 1;
  return 0;
}

std::vector<SlocumSensor> sensorsFromCache(const SlocumHeader& h, const fs::path& file, const ReadOptions& o,
                                           std::string& source) {
  const std::string name = file.string();
  if (h.sensor_list_crc.empty())
    throw InputError("sensor_list_crc", "the sensor list is factored out but the header names no sensor_list_crc",
                     "the file is damaged; copy it from the glider again", {name, static_cast<long>(h.lines), 0});
  const auto dirs = slocumCacheSearchPath(o.slocum_cache_dir, file, o.slocum_user_cache);
  const auto cache = findSlocumCache(dirs, h.sensor_list_crc);
  if (!cache) {
    std::string looked;
    for (const auto& d : dirs) looked += (looked.empty() ? "" : ", ") + d.string();
    if (looked.empty()) looked = "nowhere (no cache folder given and no home folder)";
    throw InputError("sensor_list_crc",
                     "the sensor list is not in the file and no cache file for CRC " + h.sensor_list_crc +
                         " (" + lower(h.sensor_list_crc) + ".cac or .ccc, any case) was found; looked in: " + looked,
                     missingCacheFix(h.sensor_list_crc), {name, crcLine(h), 0});
  }
  source = cache->string();
  const std::string text = loadSlocumCache(*cache);
  return parseSlocumCache(text, h.sensors_per_cycle, source).sensors;
}

}  // namespace

bool looksLikeSlocumBinary(std::string_view head) {
  if (isSlocumBinaryHeader(head)) return true;
  if (!slocumLz4StartsWith(head, "dbd_label:")) return false;
  // The compressed dbd2asc output does not exist, but check the label anyway.
  return !slocumLz4StartsWith(head, "dbd_label: DBD_ASC") && !slocumLz4StartsWith(head, "dbd_label:    DBD_ASC");
}

SlocumFile decodeSlocumFile(std::string_view bytes, const fs::path& file, const ReadOptions& options) {
  SlocumFile f;
  const std::string name = file.string();
  std::string inflated;
  std::string_view data = bytes;
  if (!bytes.empty() && bytes.substr(0, 10) != "dbd_label:" && slocumLz4StartsWith(bytes, "dbd_label:")) {
    inflated = slocumLz4Decompress(bytes, name);
    data = inflated;
    f.compressed = true;
  }
  f.data_bytes = data.size();
  f.header = parseSlocumHeader(data, name);
  const SlocumHeader& h = f.header;
  std::size_t at = h.end;
  if (!h.sensor_list_factored) {
    const SlocumSensorList list = parseSlocumSensorList(data, at, h.total_num_sensors, h.sensors_per_cycle, name,
                                                        static_cast<long>(h.lines) + 1);
    if (options.slocum_user_cache)
      storeSlocumCache(slocumUserCacheDir(), h.sensor_list_crc, data.substr(at, list.end - at));
    at = list.end;
    f.sensors = list.sensors;
    f.sensor_list_source = "the file itself";
  } else {
    f.sensors = sensorsFromCache(h, file, options, f.sensor_list_source);
  }
  for (std::size_t k = 0; k < f.sensors.size(); ++k)
    if (isSlocumEngineeringTime(f.sensors[k].name)) f.time_sensor = static_cast<int>(k);
  if (f.time_sensor < 0)
    for (std::size_t k = 0; k < f.sensors.size(); ++k)
      if (isSlocumScienceTime(f.sensors[k].name)) {
        f.time_sensor = static_cast<int>(k);
        f.science = true;
      }
  f.cycles = decodeSlocumCycles(data, at, f.sensors, h.state_bytes_per_cycle, f.time_sensor, name);
  return f;
}

}  // namespace auv::detail
