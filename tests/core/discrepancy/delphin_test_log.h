#pragma once
// The short Delphin2 log several check tests share: three 2-minute legs,
// 0.2 kg light, default noise, seed 4.
#include "discrepancy/synthetic_auv.h"
#include "missionlog/mission_log.h"
#include "sim/model_loader.h"

namespace auv::discrepancy::test_logs {

inline MissionLog delphinTestLog(const sim::SimVehicle& vehicle) {
  SyntheticAuvTruth t;
  t.ballast_error.net_buoyancy_kg = 0.2;
  SyntheticAuvMission m;
  m.legs_count = 3;
  m.leg_s = 120.0;
  m.seed = 4;
  return synthesizeAuvLog(vehicle, "delphin2", t, m);
}

}  // namespace auv::discrepancy::test_logs
