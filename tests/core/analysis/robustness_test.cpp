// Sparse, short, odd logs: the analysis degrades to "not identifiable" with a
// reason, or throws InputError naming the missing channel; it never crashes
// and never invents numbers.
#include <gtest/gtest.h>

#include "analysis/mission_analysis.h"
#include "auv_truth.h"
#include "common/input_error.h"
#include "vehicle/vehicle_catalog.h"

using namespace auv;
using namespace auv::analysis;
using namespace auv::analysis::test;

namespace {
VehicleProfile load(const char* id) { return VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load(id); }
}  // namespace

TEST(AnalysisRobustness, DepthOnlyLog) {
  MissionLog log = makeLog(0, 3000, 1.0);
  fill(log, "depth", "m", [](std::size_t, double t) { return t < 100 ? 0.2 : (t < 200 ? (t - 100) * 0.3 : 30.0); });
  const AnalysisReport r = analyzeMission(log, load("delphin2"), {});
  EXPECT_FALSE(r.net_buoyancy_kg.known);
  EXPECT_FALSE(r.cg_x_mm.known);
  EXPECT_FALSE(r.cg_y_mm.known);
  EXPECT_TRUE(std::isnan(r.depth_error_m.mean));
  EXPECT_FALSE(r.warnings.empty());
  const nlohmann::json j = toJson(r);
  EXPECT_TRUE(j["net_buoyancy_kg"].is_null());
  EXPECT_TRUE(j["water"]["density_kgm3"].is_null());
}

TEST(AnalysisRobustness, TooShortOrEmptyIsAnInputError) {
  MissionLog log = makeLog(0, 0, 1.0);
  fill(log, "depth", "m", [](std::size_t, double) { return 5.0; });
  EXPECT_THROW(analyzeMission(log, load("delphin2"), {}), InputError);
  MissionLog none;
  EXPECT_THROW(analyzeMission(none, load("slocum_g2"), {}), InputError);
}

TEST(AnalysisRobustness, PressureOnlyStillSegments) {
  MissionLog log = makeLog(0, 2000, 1.0);
  fill(log, "pressure", "dbar", [](std::size_t i, double t) {
    if (i % 3) return kNaN;
    return t < 100 ? 0.2 : std::min(40.0, (t - 100) * 0.2);
  });
  const AnalysisReport r = analyzeMission(log, load("slocum_g2"), {});
  ASSERT_GE(r.segments.size(), 2u);
  EXPECT_EQ(r.segments[0].kind, SegmentKind::kSurface);
  EXPECT_FALSE(r.net_buoyancy_kg.known);
  EXPECT_NE(r.net_buoyancy_kg.why_not.find("pump_volume"), std::string::npos);
}

TEST(AnalysisRobustness, OutOfRangeCtdValuesAreSkippedNotThrown) {
  const VehicleProfile v = load("delphin2");
  MissionLog log = makeAuvLog(v, AuvTruth{});
  LogChannel* s = log.find("salinity");
  std::size_t bad = 0;
  for (std::size_t i = 0; i < s->values.size(); ++i)
    if (!std::isnan(s->values[i]) && i % 7 == 0) {
      s->values[i] = 99.0;  // fill value that slipped through
      ++bad;
    }
  AnalysisOptions o;
  o.bg_m = 0.06;
  o.installed_kg = {1.0, 1.0};
  const AnalysisReport r = analyzeMission(log, v, o);
  EXPECT_TRUE(r.net_buoyancy_kg.known);
  bool warned = false;
  for (const auto& w : r.warnings) warned |= w.find("outside the EOS-80 range") != std::string::npos;
  EXPECT_TRUE(warned);
  EXPECT_GT(bad, 0u);
}

TEST(AnalysisRobustness, GliderLogWithAnAuvProfileAndViceVersa) {
  const VehicleProfile auvProfile = load("delphin2");
  MissionLog log = makeLog(0, 4000, 1.0);
  fill(log, "depth", "m", [](std::size_t, double t) { return 20 + 15 * std::sin(t / 300); });
  fill(log, "pitch", "deg", [](std::size_t, double t) { return 25 * std::cos(t / 300); });
  fill(log, "pump_volume", "cm3", [](std::size_t, double t) { return std::cos(t / 300) > 0 ? -200.0 : 200.0; });
  EXPECT_NO_THROW(analyzeMission(log, auvProfile, {}));
  EXPECT_NO_THROW(analyzeMission(makeAuvLog(auvProfile, AuvTruth{}), load("slocum_g2"), {}));
}
