#pragma once
// Shared set-up for the store tests: a fresh history file with one HUGIN
// configuration, and record builders with recognisable values.
#include <gtest/gtest.h>

#include "history/store.h"
#include "temp_dir.h"

namespace auv::test {

inline Configuration hugin(const std::string& id, TimePoint created) {
  Configuration c;
  c.config_id = id;
  c.vehicle_key = "hugin1000";
  c.vehicle_name = "HUGIN1000";
  c.payload_note = "SSS + MBE payload";
  c.area = "Horten";
  c.water_type = "fjord";
  c.created_at = created;
  return c;
}

inline WaterCondition water(TimePoint at, double t_degC, double s_psu, const char* source = "ctd") {
  WaterCondition w;
  w.measured_at = at;
  w.temperature_degC = t_degC;
  w.salinity_psu = s_psu;
  w.depth_m = 50.0;
  w.source = source;
  return w;
}

inline InstalledState installed(TimePoint at, double fs, double fp, double as, double ap) {
  InstalledState s;
  s.installed_at = at;
  s.points = {{"fore_starboard", fs, {}}, {"fore_port", fp, {}}, {"aft_starboard", as, {}},
              {"aft_port", ap, {}}};
  return s;
}

class StoreTest : public ::testing::Test {
 protected:
  TempDir dir;
  std::string db_path = dir.file("history.db");
};

}  // namespace auv::test
