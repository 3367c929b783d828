#pragma once
// The model check on concealed-effect AUV logs whose truth is drawn away from
// the profile (auv_truth_draw.h): one effect per case, several drawn truths
// per effect, plus control logs with no effect (some with no propeller torque
// at all). The check is given only the nominal profile. Shared by the
// benchmark (bench/model_check_truths_bench.cpp) and its small CTest version
// (drawn_truths_test.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "auv_truth_draw.h"
#include "discrepancy/auv_check_model.h"
#include "discrepancy/model_check.h"
#include "discrepancy/synthetic_auv.h"
#include "sim/mission_plan.h"
#include "vehicle/profile_loader.h"

namespace auv::discrepancy::test {

struct DrawnCase {
  std::string label;
  std::string expected;  // term id; empty = control
  double truth = 0.0;    // the effect in the term's display unit (what the vehicle has beyond its profile)
  bool zero_torque = false;
  SyntheticAuvTruth effect;
};

// One concealed effect per case; magnitudes a survey log of this vehicle can show.
inline std::vector<DrawnCase> drawnCases() {
  std::vector<DrawnCase> c;
  c.push_back({"control", "", 0.0, false, {}});
  c.push_back({"control, no propeller torque", "", 0.0, true, {}});
  {
    DrawnCase d{"hull_compressibility", "hull_compressibility", 8e-6, false, {}};
    d.effect.extra_compressibility_per_dbar = 8e-6;
    c.push_back(d);
  }
  {
    DrawnCase d{"thermal_expansion", "thermal_expansion", 1e-4, false, {}};
    d.effect.extra_thermal_expansion_per_degC = 1e-4;
    c.push_back(d);
  }
  {
    DrawnCase d{"mass_drift", "mass_drift", 0.06, false, {}};
    d.effect.mass_drift_kg_per_h = 0.06;
    c.push_back(d);
  }
  {
    DrawnCase d{"pitch_sensor_bias", "pitch_sensor_bias", 1.0, false, {}};
    d.effect.pitch_bias_deg = 1.0;
    c.push_back(d);
  }
  {
    DrawnCase d{"quadratic_pitch_damping", "quadratic_pitch_damping", 1.0, false, {}};
    d.effect.pitch_damping_scale = 1.0;
    c.push_back(d);
  }
  return c;
}

// A survey-like mission for Delphin2: 16 legs of 5 min over 5 depths to 70 m
// and 3 propeller speeds, through a thermocline at 20 m.
inline SyntheticAuvMission drawnMission(std::uint64_t seed) {
  SyntheticAuvMission m;
  m.legs_count = 16;
  m.leg_s = 300.0;
  m.depths_m = {10.0, 45.0, 25.0, 70.0, 15.0};
  m.prop_demands = {14.0, 20.0, 26.0};
  m.cast = {{0.0, 16.0, 34.0}, {15.0, 15.5, 34.2}, {25.0, 10.0, 34.8}, {40.0, 8.5, 35.0}, {120.0, 7.5, 35.1}};
  m.seed = seed;
  m.surface_model = true;  // a drawn truth too buoyant for its slow legs floats, as a real one would
  return m;
}

struct DrawnOutcome {
  std::string label, expected;
  int logs = 0, top1 = 0, within30 = 0, false_terms = 0, torque_missing = 0;
  int named = 0, covered2 = 0;  // logs naming the effect; of those, its value within 2 stated sigmas of the truth
  std::vector<std::string> notes;
};

struct Delphin2Nominal {
  VehicleProfile profile = loadVehicleProfile(std::string(AUV_RESOURCE_DIR) + "/vehicles/delphin2.json");
  sim::SimVehicle vehicle = sim::loadSimVehicle(profile, AUV_RESOURCE_DIR);
};

// The value the check reports for the effect, as what the vehicle has beyond the profile.
inline double effectOf(const MissingPhysics& m) { return m.value - m.profile_value; }

inline DrawnOutcome runDrawnCase(const Delphin2Nominal& d, const DrawnCase& c, const std::vector<std::uint64_t>& seeds,
                                 bool verbose) {
  DrawnOutcome o;
  o.label = c.label;
  o.expected = c.expected;
  for (std::uint64_t seed : seeds) {
    const DrawnAuvTruth truth = drawAuvTruth(d.vehicle, seed, c.zero_torque);
    SyntheticAuvTruth t = c.effect;
    t.ballast_error = truth.ballast_error;
    const MissionLog log = synthesizeAuvLog(truth.vehicle, "delphin2", t, drawnMission(seed));
    const AuvCheckModel model(log, d.profile, d.vehicle.model, d.vehicle.autopilot);
    const ModelCheckResult r = runModelCheck(model);
    ++o.logs;
    std::string found;
    for (const MissingPhysics& m : r.missing_physics) {
      char b[160];
      std::snprintf(b, sizeof b, " %s=%.3g+-%.2g (halves %.2g, calibration %.2g)", m.id.c_str(), effectOf(m), m.sigma,
                    m.split_half_sigma, m.calibration_sigma);
      found += b;
      if (m.id == "propeller_torque") ++o.torque_missing;
      if (m.id != c.expected) ++o.false_terms;
      if (m.id == c.expected) ++o.named, o.covered2 += std::abs(effectOf(m) - c.truth) <= 2.0 * m.sigma;
    }
    if (!c.expected.empty() && !r.missing_physics.empty() && r.missing_physics[0].id == c.expected) {
      ++o.top1;
      if (std::abs(effectOf(r.missing_physics[0]) - c.truth) <= 0.3 * std::abs(c.truth)) ++o.within30;
    }
    if (verbose) {
      std::printf("    seed %-3llu %-70s found:%s\n", static_cast<unsigned long long>(seed), truth.describe().c_str(),
                  found.empty() ? " nothing" : found.c_str());
      for (const CandidateReport& k : r.candidates)
        if (k.id == c.expected)
          std::printf("      %s alone %.3g +- %.2g (t %.1f, inclusion %.2f, ballast r2 %.3f): %s\n", k.id.c_str(), k.value,
                      k.sigma, k.t_value, k.inclusion_probability, k.nuisance_r2, k.status.c_str());
      std::string cal;
      for (const CalibrationValue& k : r.calibration) {
        char b[96];
        std::snprintf(b, sizeof b, " %s %.3g+-%.2g%s", k.id.c_str(), k.value, k.sigma, k.identified ? "" : "(prior)");
        cal += b;
      }
      std::printf("      calibration:%s\n", cal.c_str());
    }
  }
  return o;
}

inline void printDrawnRow(const DrawnOutcome& o) {
  if (o.expected.empty())
    std::printf("%-30s logs %2d  false terms %2d  propeller_torque in missing_physics %2d\n", o.label.c_str(), o.logs,
                o.false_terms, o.torque_missing);
  else
    std::printf("%-30s logs %2d  top-1 %2d  within 30 %% %2d  within 2 sigma %2d of %2d named  other terms %2d  "
                "propeller_torque in missing_physics %2d\n",
                o.label.c_str(), o.logs, o.top1, o.within30, o.covered2, o.named, o.false_terms, o.torque_missing);
}

}  // namespace auv::discrepancy::test
