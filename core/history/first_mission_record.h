#pragma once
// What a first mission leaves in the history, written the same way by the
// CLI (`first-mission --config`) and the wizard's Finish: the weighing with
// its inputs and results, the water it was computed for, and the
// recommendation. The caller holds the transaction and adds the installed
// state, which the two front ends learn differently.
#include <nlohmann/json.hpp>
#include <string>

#include "history/records.h"
#include "history/store.h"
#include "history/timestamp.h"

namespace auv {

struct FirstMissionRecord {
  bool tank = false;          // Slocum tank weighing, else crane
  nlohmann::json inputs;      // the weighing as entered
  nlohmann::json results;     // the first-mission report (JSON)
  double temperature_degC = 0.0, salinity_psu = 0.0, depth_m = 0.0, density_kg_m3 = 0.0;
  std::string policy;         // "exact", "half", "tank"
  bool accepted = false;      // the technician confirmed the recommendation
};

// Returns the recommendation's id (an installed state refers to it).
RecordId recordFirstMission(HistoryStore& store, const std::string& config_id, const FirstMissionRecord& r,
                            TimePoint now);

}  // namespace auv
