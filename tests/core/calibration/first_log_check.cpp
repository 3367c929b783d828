#include "first_log_check.h"

#include <gtest/gtest.h>

#include "discrepancy/vehicle_check.h"

namespace auv::identification {

void checkFirstLogWithItsAnalysis(std::uint64_t seed, const FirstLogCheck& expect,
                                  const discrepancy::SyntheticAuvTruth& concealed, double pitch_alignment_sigma_deg) {
  Harness h;
  h.concealed = concealed;
  h.pitch_alignment_sigma_deg = pitch_alignment_sigma_deg;
  int called = 0;
  h.on_first_log = [&](const MissionLog& log, const analysis::AnalysisReport& rep, double net_truth, double) {
    ++called;
    discrepancy::CheckSetup setup;
    setup.analysis = &rep;
    expect(discrepancy::runModelCheck(*discrepancy::makeCheckModel(log, h.profile(), AUV_RESOURCE_DIR, setup)), rep,
           net_truth, h);
  };
  h.run(seed, false);
  EXPECT_EQ(called, 1);
}

}  // namespace auv::identification
