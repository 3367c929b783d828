// The model check's noise twin (discrepancy/noise_twin_test.h) on drawn HUGIN
// truths (hugin_concealed_bench): a term the closed loop makes of sensor
// noise is refused because the log flown again by the fitted vehicle, without
// the term and with the log's noise, gives it the same value; a term the
// vehicle has is kept because there it does not.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "discrepancy/model_check.h"
#include "discrepancy/vehicle_check.h"
#include "identification_harness.h"

namespace auv::identification {
namespace {

struct TwinRuns {
  discrepancy::ModelCheckResult with_twin, without_twin;
};

// The check as the CLI runs it on the first log of drawn truth `seed`, with
// and without the noise twin.
TwinRuns checkBothWays(std::uint64_t seed, const discrepancy::SyntheticAuvTruth& concealed = {}) {
  Harness h;
  h.concealed = concealed;
  TwinRuns out;
  int called = 0;
  h.on_first_log = [&](const MissionLog& log, const analysis::AnalysisReport& rep, double, double) {
    ++called;
    discrepancy::CheckSetup setup;
    setup.analysis = &rep;
    const auto model = discrepancy::makeCheckModel(log, h.profile(), AUV_RESOURCE_DIR, setup);
    out.with_twin = discrepancy::runModelCheck(*model);
    discrepancy::ModelCheckOptions off;
    off.noise_twin = false;
    out.without_twin = discrepancy::runModelCheck(*model, off);
  };
  h.run(seed, false);
  EXPECT_EQ(called, 1);
  return out;
}

const discrepancy::CandidateReport& candidate(const discrepancy::ModelCheckResult& r, const std::string& id) {
  for (const discrepancy::CandidateReport& c : r.candidates)
    if (c.id == id) return c;
  throw std::runtime_error("no candidate " + id);
}

std::string ids(const discrepancy::ModelCheckResult& r) {
  std::string s;
  for (const discrepancy::MissingPhysics& m : r.missing_physics) s += m.id + " ";
  return s;
}

// Control 5101 (Munk moment inside M_w, no concealed effect): without the
// twin the check named a quadratic pitch damping of 2.9 (3.05 +- 0.35 alone);
// the twin, which has none, gives 3.3 +- 0.4.
TEST(NoiseTwin, AControlsClosedLoopAnswerToNoiseIsNotNamed) {
  const TwinRuns r = checkBothWays(5101);
  EXPECT_EQ(ids(r.without_twin), "quadratic_pitch_damping ");  // the test's teeth
  EXPECT_TRUE(r.with_twin.missing_physics.empty()) << ids(r.with_twin);
  const discrepancy::CandidateReport& c = candidate(r.with_twin, "quadratic_pitch_damping");
  ASSERT_TRUE(std::isfinite(c.twin_value));
  EXPECT_LT(std::abs(c.value - c.twin_value), 2.0 * std::hypot(c.sigma, c.twin_sigma));
  EXPECT_EQ(c.status.rfind("what the closed loop makes of this log's sensor noise", 0), 0u) << c.status;
}

// Truth 5600 has a quadratic pitch damping twice the profile's: the log
// gives 1.26 +- 0.18 (alone), its twin 0.2 +- 0.18; named either way.
TEST(NoiseTwin, ATermTheVehicleHasIsKept) {
  discrepancy::SyntheticAuvTruth t;
  t.pitch_damping_scale = 1.0;
  const TwinRuns r = checkBothWays(5600, t);
  ASSERT_FALSE(r.with_twin.missing_physics.empty());
  EXPECT_EQ(r.with_twin.missing_physics.front().id, "quadratic_pitch_damping");
  EXPECT_EQ(ids(r.with_twin), ids(r.without_twin));
  const discrepancy::CandidateReport& c = candidate(r.with_twin, "quadratic_pitch_damping");
  EXPECT_LT(std::abs(c.twin_value), 0.5 * std::abs(c.value));
}

}  // namespace
}  // namespace auv::identification
