#include <cmath>
#include <memory>

#include "discrepancy/auv_check_model.h"
#include "common/units.h"

// The AUV check's noise twin (check_model.h): the logged commands flown by
// the calibrated vehicle without any missing term, through the profile's
// autopilot steering on readings with the log's own noise, recorded where the
// log has rows. Depth, pitch, roll, speed, elevator, tunnel thrusters, the
// CTD pressure and (flown on depth commands) the autopilot's pitch demand are
// the twin's. The rest (propeller speed, depth commands, heading, the water)
// are the log's. Every actuator must be the twin's: with the log's thrusters,
// which held a vehicle growing heavier, the twins of the Delphin2 mass-drift
// truths showed the log's drift (0.045-0.057 kg/h against 0.06). A row the
// log is missing stays missing; rows the replay does not fly (surface
// intervals, across drop-outs) keep the log's values.
namespace auv::discrepancy {

namespace {

void replaceChannel(MissionLog& log, const char* name, const std::vector<double>& twin, double scale) {
  LogChannel* c = log.find(name);
  if (c == nullptr) return;
  for (std::size_t i = 0; i < c->values.size() && i < twin.size(); ++i)
    if (std::isfinite(c->values[i]) && std::isfinite(twin[i])) c->values[i] = twin[i] * scale;
}

}  // namespace

std::unique_ptr<CheckModel> AuvCheckModel::noiseTwin(const Params& p, std::uint64_t seed) const {
  TermReplayOptions o = replayOptions(p, 0.0);
  o.noise = noise_;
  o.noise_seed = seed;
  const TermReplayTrace tr = termReplay(calibratedModel(p), autopilot_, water_, log_, simAdjustment(total(p)), log_.time, o);
  MissionLog twin = log_;
  const double deg = units::radToDeg(1.0);
  replaceChannel(twin, "depth", tr.depth_m, 1.0);
  replaceChannel(twin, "pitch", tr.pitch_rad, deg);
  replaceChannel(twin, "roll", tr.roll_rad, deg);
  replaceChannel(twin, "speed", tr.speed_mps, 1.0);
  replaceChannel(twin, "elevator", tr.elevator_deg, 1.0);
  replaceChannel(twin, "pressure", tr.pressure_dbar, 1.0);
  replaceChannel(twin, "thruster_front_rpm", tr.thruster_front_rpm, 1.0);
  replaceChannel(twin, "thruster_aft_rpm", tr.thruster_aft_rpm, 1.0);
  replaceChannel(twin, "pitch_cmd", tr.pitch_cmd_deg, 1.0);
  // An independent measurement (the roll test's CG y) would have measured
  // the twin's vehicle: its prior is centred there. Centred on the log's, a
  // roll-sensor bias the base fit had put into CG y against that prior came
  // back in the twin as the same bias.
  AuvCheckOptions o2 = opt_;
  o2.cg_y_prior_shift_m = p.nuisance[2];
  return std::make_unique<AuvCheckModel>(twin, profile_, model_, autopilot_, o2);
}

}  // namespace auv::discrepancy
