#pragma once
// Flies a glider mission: saw-tooth yos between two depths. At each
// inflection the buoyancy pump runs to its dive or climb volume and the
// pitch battery to the position that trims the dive or climb pitch (closed
// form through core hydrostatics' static trim, re-evaluated every control
// interval as the water changes, like a pitch servo at steady state). The
// glider flies the steady glide of its current pitch and net buoyancy, with
// first-order lags for pitch and speed so the inflections take time.
#include <limits>
#include <optional>
#include <vector>

#include "sim/flown_mass.h"
#include "sim/glider_model.h"
#include "sim/simulator.h"
#include "sim/sim_trace.h"
#include "sim/water_column.h"

namespace auv::sim {

struct YoLeg {
  double duration_s = 0.0;
  double dive_to_m = 0.0;   // inflect to climb here
  double climb_to_m = 0.0;  // inflect to dive here
  // NaN: the model's defaults (full pump travel, dive/climb pitch).
  double pump_m3 = std::numeric_limits<double>::quiet_NaN();
  double dive_pitch_rad = std::numeric_limits<double>::quiet_NaN();
  double climb_pitch_rad = std::numeric_limits<double>::quiet_NaN();
};

struct GliderScenario {
  std::vector<YoLeg> legs;
  std::vector<MassItem> extra_masses;   // installed at the profile's points, other changes
  std::optional<double> net_buoyancy_n;  // trim at the start depth with the pump at zero
  BallastError ballast_error;
  double initial_depth_m = 1.0;
  double initial_heading_rad = 0.0;
};

double gliderScenarioDuration(const GliderScenario& scenario);

// Uses options.dt_s (0.5 s is plenty for a glider), trace_interval_s, noise
// (depth, pitch, roll, heading, CTD) and seed.
SimTrace simulateGlider(const GliderModel& model, const WaterColumn& water, const GliderScenario& scenario,
                        const SimOptions& options = {});

}  // namespace auv::sim
