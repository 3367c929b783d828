#include "sim/ballast_cost.h"

#include "sim/simulator.h"

namespace auv::sim {
namespace {

struct Averages {
  double power_w = 0.0, pitch_rad = 0.0, speed_mps = 0.0;
};

Averages settledAverages(const VehicleModel& model, const DepthAutopilotConfig& ap, const WaterColumn& water,
                         double net_n, double demand, double depth, double settle_s, double average_s) {
  Scenario sc;
  sc.net_buoyancy_n = net_n;
  sc.initial_depth_m = depth;  // start at depth: the cost of holding it, not of diving
  sc.legs = {{settle_s + average_s, depth, demand}};
  SimOptions opt;
  const SimTrace tr = simulate(model, ap, water, sc, opt);
  Averages a;
  int n = 0;
  for (std::size_t i = 0; i < tr.size(); ++i) {
    if (tr.time_s[i] < settle_s) continue;
    a.power_w += tr.power_w[i];
    a.pitch_rad += tr.pitch_rad[i];
    a.speed_mps += tr.speed_mps[i];
    ++n;
  }
  if (n > 0) {
    a.power_w /= n;
    a.pitch_rad /= n;
    a.speed_mps /= n;
  }
  return a;
}

}  // namespace

BallastErrorCost ballastErrorCost(const VehicleModel& model, const DepthAutopilotConfig& ap, const WaterColumn& water,
                                  double net_buoyancy_n, double prop_demand, double depth_m, double settle_s,
                                  double average_s) {
  const Averages with = settledAverages(model, ap, water, net_buoyancy_n, prop_demand, depth_m, settle_s, average_s);
  const Averages neutral = settledAverages(model, ap, water, 0.0, prop_demand, depth_m, settle_s, average_s);
  BallastErrorCost c;
  c.power_w = with.power_w;
  c.neutral_power_w = neutral.power_w;
  c.extra_power_w = with.power_w - neutral.power_w;
  c.mean_pitch_rad = with.pitch_rad;
  c.mean_speed_mps = with.speed_mps;
  c.extra_energy_per_hour_wh = c.extra_power_w;
  return c;
}

}  // namespace auv::sim
