// The glider model check on the real recordings in ../shared/data/real
// (skipped with a message when they are not there), against the reference
// calibrations in their READMEs. The test profiles (tests/core/discrepancy/
// data/*.json) deliberately have no hull compressibility and no thermal
// expansion: the check is asked whether the log needs them. Results are
// printed for docs/decisions/model-check-real-gliders.md.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "discrepancy/model_check.h"
#include "discrepancy/vehicle_check.h"
#include "missionlog/interchange_csv.h"
#include "vehicle/profile_loader.h"

namespace auv::discrepancy {
namespace {

const std::string kReal = std::string(AUV_SHARED_DIR) + "/data/real/";
const std::string kProfiles = std::string(AUV_TEST_DATA_DIR) + "/../core/discrepancy/data/";

}  // namespace
std::vector<std::string> r_candidates(const ModelCheckResult& r);
namespace {

struct RealRun {
  ModelCheckResult r;
  bool ok = false;
};

RealRun check(const std::string& log_file, const std::string& profile, const CheckSetup& setup = {},
          const ModelCheckOptions& options = {}) {
  RealRun run;
  if (!std::filesystem::exists(kReal + log_file)) return run;
  const MissionLog log = readInterchangeCsv(kReal + log_file);
  const VehicleProfile v = loadVehicleProfile(kProfiles + profile);
  const auto model = makeCheckModel(log, v, AUV_RESOURCE_DIR, setup);
  run.r = runModelCheck(*model, options);
  run.ok = true;
  std::printf("[model-check real] %s:\n", log_file.c_str());
  for (const auto& m : run.r.missing_physics)
    std::printf("    found %-22s %.4g +- %.2g %s, held-out %s RMS %.3g -> %.3g\n", m.id.c_str(), m.value, m.sigma, m.unit.c_str(),
                channelName(m.channel), m.rms_before, m.rms_after);
  for (const auto& c : r_candidates(run.r)) std::printf("    %s\n", c.c_str());
  for (const auto& x : run.r.rms)
    if (x.channel == Channel::kVerticalVelocity && x.source == "equation")
      std::printf("    vertical velocity RMS %.3f -> %.3f cm/s (held-out %.3f -> %.3f), %zu samples\n", x.fitted_before,
                  x.fitted_after, x.heldout_before, x.heldout_after, x.samples);
  for (const auto& l : run.r.localisation) std::printf("    where (%s, %s): %s\n", l.source.c_str(), channelName(l.channel), l.summary.c_str());
  for (const auto& i : run.r.identifiability) std::printf("    identifiability: %s\n", i.message.c_str());
  return run;
}

}  // namespace

std::vector<std::string> r_candidates(const ModelCheckResult& r) {
  std::vector<std::string> out;
  for (const auto& c : r.candidates) {
    char b[256];
    std::snprintf(b, sizeof b, "candidate %-22s alone %.3g +- %.2g (t %.1f, inclusion %.2f): %s", c.id.c_str(), c.value, c.sigma,
                  c.t_value, c.inclusion_probability, c.status.c_str());
    out.push_back(b);
  }
  return out;
}

namespace {

const CandidateReport* candidate(const ModelCheckResult& r, const std::string& id) {
  for (const auto& c : r.candidates)
    if (c.id == id) return &c;
  return nullptr;
}
const MissingPhysics* found(const ModelCheckResult& r, const std::string& id) {
  for (const auto& m : r.missing_physics)
    if (m.id == id) return &m;
  return nullptr;
}

TEST(RealGliders, AmmoniteNeedsHullCompressibilityLikeGliderflightFound) {
  const RealRun run = check("slocum-ammonite-ligurian-2008/ammonite-2008-028-01-000.csv", "ammonite_slocum.json");
  if (!run.ok) GTEST_SKIP() << "the real recordings are not in " << kReal;
  // README run C2 (gliderflight, Cd0, Vg, epsilon): epsilon = 6.26e-10 1/Pa = 6.26e-6 1/dbar.
  const MissingPhysics* k = found(run.r, "hull_compressibility");
  ASSERT_NE(k, nullptr);
  EXPECT_NEAR(k->value, 6.26e-6, 1.5e-6);
  EXPECT_LT(k->rms_after, k->rms_before);
  EXPECT_EQ(run.r.missing_physics.size(), 1u);
}

TEST(RealGliders, SeaExplorerDepthSensorReadsAboutFourMetresDeep) {
  const RealRun run = check("seaexplorer-sea046-calvert-2020/sea046-m45-yos10-14.csv", "sea046_seaexplorer.json");
  if (!run.ok) GTEST_SKIP() << "the real recordings are not in " << kReal;
  // README: depth reads 4.3 m more than the GPCTD pressure (median depth - pressure 4.26 m on dives,
  // 4.72 m on climbs); against the UNESCO depth of that pressure (~0.7 % less than dbar) a little more.
  const MissingPhysics* d = found(run.r, "depth_sensor_offset");
  ASSERT_NE(d, nullptr);
  EXPECT_GT(d->value, 4.0);
  EXPECT_LT(d->value, 5.6);
  EXPECT_LT(d->rms_after, d->rms_before);
}

TEST(RealGliders, CometShallowBalticCompressibilityAndThermalExpansionAreConfounded) {
  const RealRun run = check("slocum-comet-baltic-2016/comet-2016-174-05.csv", "comet_slocum.json");
  if (!run.ok) GTEST_SKIP() << "the real recordings are not in " << kReal;
  // Ten yos to 40 m through one thermocline: temperature follows depth, the
  // check must say that the two volume terms cannot be told apart.
  bool flagged = false;
  for (const auto& i : run.r.identifiability)
    flagged = flagged || ((i.a == "hull_compressibility" && i.b == "thermal_expansion") ||
                          (i.b == "hull_compressibility" && i.a == "thermal_expansion"));
  EXPECT_TRUE(flagged);
  for (const auto& m : run.r.missing_physics) {
    EXPECT_TRUE(m.id == "hull_compressibility" || m.id == "thermal_expansion") << m.id;
    EXPECT_LT(m.rms_after, m.rms_before);
  }
  // The README's comparison: gliderflight on 10-35 m, dP/dt on the CTD time base.
  CheckSetup s;
  s.glider.max_depth_m = 35.0;
  s.glider.rate_window_s = 2.0;
  const RealRun cmp = check("slocum-comet-baltic-2016/comet-2016-174-05.csv", "comet_slocum.json", s);
  ASSERT_TRUE(cmp.ok);
}

TEST(RealGliders, Seaglider171AgainstTheBasestationConstants) {
  const RealRun run = check("seaglider-sg171-bay-of-bengal-2024/sg171-dives100-109.csv", "sg171_seaglider.json");
  if (!run.ok) GTEST_SKIP() << "the real recordings are not in " << kReal;
  // Basestation: therm_expan 7.05e-5 1/degC, abs_compress 8.6e-7 .. 1.3e-6 1/dbar (default 4.1e-6).
  const CandidateReport* a = candidate(run.r, "thermal_expansion");
  ASSERT_NE(a, nullptr);
  EXPECT_NEAR(a->value, 7.05e-5, 3.0 * a->sigma);
  const CandidateReport* k = candidate(run.r, "hull_compressibility");
  ASSERT_NE(k, nullptr);
  EXPECT_GT(k->value, 0.0);
  // Whatever it accepts must improve the held-out simulation.
  for (const auto& m : run.r.missing_physics) EXPECT_LT(m.rms_after, m.rms_before);
}

}  // namespace
}  // namespace auv::discrepancy
