#include "history/first_mission_record.h"

namespace auv {

RecordId recordFirstMission(HistoryStore& store, const std::string& config_id, const FirstMissionRecord& r,
                            TimePoint now) {
  Weighing w;
  w.at = now;
  w.method = r.tank ? WeighingMethod::kTank : WeighingMethod::kCrane;
  w.inputs = r.inputs;
  w.results = r.results;
  store.addWeighing(config_id, w);

  WaterCondition water;
  water.measured_at = now;
  water.temperature_degC = r.temperature_degC;
  water.salinity_psu = r.salinity_psu;
  water.depth_m = r.depth_m;
  water.density_kg_m3 = r.density_kg_m3;
  water.source = "operator";
  store.addWaterCondition(config_id, water);

  Recommendation rec;
  rec.at = now;
  rec.policy = r.policy;
  rec.recommendation = r.results;
  rec.accepted = r.accepted;
  return store.addRecommendation(config_id, rec);
}

}  // namespace auv
