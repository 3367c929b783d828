#pragma once
// Shared by the concealed-effect tests: run the model check on several seeds
// of a synthetic recording with one truth effect switched on, collect
// detection, false positives and parameter error, print them as a table row
// and check them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "discrepancy/check_model.h"
#include "discrepancy/model_check.h"
#include "missionlog/mission_log.h"

namespace auv::discrepancy::test {

struct CaseOutcome {
  int seeds = 0, detected = 0, false_positives = 0, sim_improved = 0;
  std::vector<double> rel_error;  // |fitted - truth| / |truth| per detected seed
  std::vector<std::string> others;
};

// `expected_id` empty = a control (nothing may be found).
inline CaseOutcome runConcealedCase(const std::string& label, const std::string& expected_id, double truth_display,
                                    const std::vector<std::uint64_t>& seeds,
                                    const std::function<std::unique_ptr<CheckModel>(std::uint64_t)>& make,
                                    const ModelCheckOptions& options = {}) {
  CaseOutcome o;
  for (std::uint64_t seed : seeds) {
    const std::unique_ptr<CheckModel> m = make(seed);
    const ModelCheckResult r = runModelCheck(*m, options);
    ++o.seeds;
    bool found = false;
    for (const MissingPhysics& mp : r.missing_physics) {
      if (mp.id == expected_id) {
        found = true;
        // The reported value is the vehicle's (profile + effect); the truth here is the effect.
        o.rel_error.push_back(std::abs(mp.value - mp.profile_value - truth_display) / std::abs(truth_display));
        if (mp.rms_after < mp.rms_before) ++o.sim_improved;
      } else {
        ++o.false_positives;
        o.others.push_back(mp.id + "=" + std::to_string(mp.value) + " (seed " + std::to_string(seed) + ")");
      }
    }
    o.detected += found;
    if (!found && !expected_id.empty())
      for (const CandidateReport& c : r.candidates)
        if (c.id == expected_id) std::printf("    seed %llu: %s %s\n", static_cast<unsigned long long>(seed), c.id.c_str(), c.status.c_str());
  }
  double maxErr = 0.0, meanErr = 0.0;
  for (double e : o.rel_error) {
    maxErr = std::max(maxErr, e);
    meanErr += e / static_cast<double>(o.rel_error.size());
  }
  std::printf("[model-check rates] %-28s detected %d/%d  false positives %d  parameter error mean %.1f %% max %.1f %%  "
              "held-out sim improved %d/%d\n",
              label.c_str(), expected_id.empty() ? o.seeds - (o.false_positives > 0) : o.detected, o.seeds,
              o.false_positives, 100 * meanErr, 100 * maxErr, o.sim_improved, o.detected);
  for (const auto& s : o.others) std::printf("    also found: %s\n", s.c_str());
  return o;
}

inline void expectAllFound(const CaseOutcome& o) {
  EXPECT_EQ(o.detected, o.seeds);
  EXPECT_EQ(o.false_positives, 0);
  EXPECT_EQ(o.sim_improved, o.detected);
  for (double e : o.rel_error) EXPECT_LE(e, 0.30);
}

}  // namespace auv::discrepancy::test
