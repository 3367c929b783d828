#pragma once
// A glider's static trim as its log shows it, for placing ballast:
//  - pitch trim, tan(pitch) = T1 pump + T2 battery + T3 (gliderflight's
//    glidertrim): the pitch a pump volume and a pitch-battery position give in
//    steady glides. T3 / T2 is where the battery must sit for level trim with
//    the pump at zero, which says how much of the mass change belongs forward;
//  - roll: mean roll over the glides with the roll actuator at its zero
//    (roll_mass_cmd 0 when logged), for a wing-rail change.
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/segments.h"
#include "missionlog/mission_log.h"

namespace auv::analysis {

struct GliderTrim {
  bool pitch_known = false;
  double T1_per_cm3 = 0.0, T2_per_mm = 0.0, T3 = 0.0;  // tan(pitch) model
  double rms_tan = 0.0;
  std::size_t pitch_samples = 0;
  double battery_for_level_mm = 0.0;  // -T3 / T2: battery position level at pump 0
  double battery_min_mm = 0.0, battery_max_mm = 0.0;  // range flown in the glides
  std::string pitch_why_not;

  bool roll_known = false;
  double roll_deg = 0.0, roll_sigma_deg = 0.0;
  std::size_t roll_samples = 0;
  std::string roll_basis, roll_why_not;
};

GliderTrim estimateGliderTrim(const MissionLog& log, const std::vector<Segment>& glides);

}  // namespace auv::analysis
