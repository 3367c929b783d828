#pragma once
// What a pre-mission plan takes from the history of one configuration, for
// `auvballast plan --config` and the wizard's pre-mission page alike: the
// configuration's vehicle model (terms accepted and constants calibrated in
// model checks, over the catalogue profile), the pieces installed now, the
// latest analysis (calibrated jointly with the earlier missions when it was
// made with them) and the last measured water.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "history/records.h"
#include "history/timestamp.h"
#include "planning/plan_sources.h"
#include "vehicle/vehicle_profile.h"

namespace auv {

class HistoryStore;

struct HistoryPlanInputs {
  bool configuration_known = false;
  VehicleProfile vehicle;          // the configuration's model, else the base profile
  std::size_t model_terms = 0;     // accepted model-check terms in that model
  std::size_t model_calibrated = 0;  // constants calibrated by model checks in it (hydrodynamics, torque)
  bool model_from_history = false;
  std::optional<InstalledState> installed;  // the latest (installedKg: in profile order)
  std::optional<double> total_mass_kg;  // recorded vehicle mass with those pieces
  std::optional<AnalysisResult> analysis;  // the latest
  std::optional<MeasuredWater> measured_water;  // last water with a temperature
  std::optional<TimePoint> measured_water_at;
};

// InputError("vehicle") when the configuration belongs to another vehicle.
// An unknown configuration gives configuration_known = false and the base
// profile.
HistoryPlanInputs planInputsFromHistory(HistoryStore& store, const std::string& config_id, const VehicleProfile& base,
                                        TimePoint now);

// A recorded installed state in the vehicle's point order; InputError
// ("installed") when it names a point the vehicle does not have.
std::vector<double> installedKg(const InstalledState& state, const VehicleProfile& v, const std::string& config_id);

}  // namespace auv
