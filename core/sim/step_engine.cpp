#include "sim/step_engine.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/units.h"
#include "sim/simulator.h"

namespace auv::sim {

double buoyancyN(const VehicleModel& model, const WaterSample& ws, double z, bool surface) {
  const double V = model.body.hull.volumeAt(ws.temperature_degC, ws.pressure_dbar);
  const double frac = surface ? submergedFraction(z, model.body.hull.diameter_m) : 1.0;
  return ws.density_kgm3 * units::g0 * V * frac;
}

StepEngine::StepEngine(const VehicleModel& model, const WaterColumn& water, double dt, bool surface)
    : model_(&model), waterColumn_(&water), dt_(dt), surface_(surface), dyn_(model), actDyn_(model, dt), yawK_(yawConstants(model)) {}

void StepEngine::start(const InitialState& init, const VehicleLoading& loading) {
  s_ = StateVector::Zero();
  s_[kZ] = init.depth_m;
  s_[kTheta] = init.pitch_rad;
  s_[kPhi] = init.roll_rad;
  s_[kU] = init.speed_mps;
  if (init.depth_rate_mps) {
    // depth rate = -u sin(theta) + w cos(theta) cos(phi) (measure(), below)
    const double c = std::cos(init.pitch_rad) * std::cos(init.roll_rad);
    if (c > 0.1) s_[kW] = (*init.depth_rate_mps + init.speed_mps * std::sin(init.pitch_rad)) / c;
  }
  act_ = {};
  act_.prop_rps = init.prop_rps;
  act_.plane_rad = init.plane_rad;
  act_.thruster_rpm = init.thruster_rpm;
  yaw_ = {};
  yaw_.heading_rad = init.heading_rad;
  t_s_ = 0.0;
  sampleWater();
  fm_ = flownMass(*model_, loading.extra_masses, loading.net_buoyancy_n, loading.error, B_);
  dyn_.setMassProperties(fm_.mass_kg, fm_.r_g_m, fm_.extra_Ixx, fm_.extra_Iyy);
  W0_ = fm_.mass_kg * units::g0;
  B_start_ = B_;
  energy_j_ = hotel_j_ = prop_j_ = thruster_j_ = fins_j_ = 0.0;
}

void StepEngine::sampleWater() {
  ws_ = waterColumn_->at(std::max(0.0, s_[kZ]), t_s_);
  B_ = sim::buoyancyN(*model_, ws_, s_[kZ], surface_);
}

Measurement StepEngine::measure(GaussianSource& noise, const SensorNoise& n) const {
  const double sth = std::sin(s_[kTheta]), cth = std::cos(s_[kTheta]), cph = std::cos(s_[kPhi]);
  Measurement m;
  m.depth_m = s_[kZ] + noise.next(n.depth_m);
  m.depth_rate_mps = -s_[kU] * sth + s_[kW] * cth * cph + noise.next(n.depth_rate_mps);
  m.pitch_rad = s_[kTheta] + noise.next(n.pitch_rad);
  m.pitch_rate_radps = s_[kQ] * cph + noise.next(n.pitch_rate_radps);
  m.speed_mps = s_[kU] + noise.next(n.speed_mps);
  return m;
}

void StepEngine::record(SimTrace& tr, double t, const Measurement& meas, const SampleExtras& x, double W,
                        GaussianSource& noise, const SensorNoise& n) const {
  const PowerBreakdown P = electricalPower(*model_, act_, s_[kU]);
  tr.time_s.push_back(t);
  tr.depth_m.push_back(meas.depth_m);
  tr.depth_cmd_m.push_back(x.depth_cmd_m);
  tr.pitch_rad.push_back(meas.pitch_rad);
  tr.pitch_cmd_rad.push_back(x.pitch_cmd_rad);
  tr.roll_rad.push_back(s_[kPhi] + noise.next(n.roll_rad));
  tr.speed_mps.push_back(meas.speed_mps);
  tr.x_m.push_back(s_[kX]);
  tr.prop_rpm.push_back(act_.prop_rps * 60.0);
  tr.elevator_rad.push_back(-act_.plane_rad);
  tr.thruster_front_rpm.push_back(act_.thruster_rpm[0]);
  tr.thruster_aft_rpm.push_back(act_.thruster_rpm[1]);
  tr.power_w.push_back(P.total_w);
  tr.power_prop_w.push_back(P.prop_w);
  tr.power_thruster_front_w.push_back(P.thruster_w[0]);
  tr.power_thruster_aft_w.push_back(P.thruster_w[1]);
  tr.power_fins_w.push_back(P.fins_w);
  tr.net_buoyancy_n.push_back(B_ - W);
  tr.hover_force_n.push_back(x.hover_force_n);
  tr.temperature_degC.push_back(ws_.temperature_degC + noise.next(n.temperature_degC));
  tr.salinity_psu.push_back(ws_.salinity_psu + noise.next(n.salinity_psu));
  tr.pressure_dbar.push_back(ws_.pressure_dbar + noise.next(n.pressure_dbar));
  const double psi = yaw_.heading_rad + noise.next(n.heading_rad);
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  tr.heading_rad.push_back(psi >= kTwoPi ? psi - kTwoPi : (psi < 0.0 ? psi + kTwoPi : psi));
  tr.heading_cmd_rad.push_back(x.heading_cmd_rad);
  tr.rudder_rad.push_back(yaw_.rudder_rad);
}

void StepEngine::stepHeld(double W) {
  const PowerBreakdown P = electricalPower(*model_, act_, s_[kU]);
  energy_j_ += P.total_w * dt_;
  hotel_j_ += P.hotel_w * dt_;
  prop_j_ += P.prop_w * dt_;
  thruster_j_ += (P.thruster_w[0] + P.thruster_w[1]) * dt_;
  fins_j_ += P.fins_w * dt_;

  StepInputs in;
  in.water_density_kgm3 = ws_.density_kgm3;
  in.weight_n = W;
  in.buoyancy_n = B_;
  in.actuators = act_;
  dyn_.setStepInputs(in);
  const double u0 = s_[kU], q0 = s_[kQ];
  dyn_.rk4Step(s_, dt_);
  t_s_ += dt_;
  const Trig1& th = dyn_.lastStepPitch();
  const Trig1& ph = dyn_.lastStepRoll();
  advanceYaw(yawK_, ws_.density_kgm3, u0, q0, th.c, ph.s, ph.c, dt_, yaw_);
}

void StepEngine::step(double W, const ActuatorDemand& demand, double rudder_demand) {
  stepHeld(W);
  actDyn_.advance(act_, demand);
  advanceRudder(*model_, rudder_demand, dt_, yaw_);
}

void StepEngine::finish(SimTrace& tr) const {
  tr.energy_j = energy_j_;
  tr.hotel_energy_j = hotel_j_;
  tr.prop_energy_j = prop_j_;
  tr.thruster_energy_j = thruster_j_;
  tr.fins_energy_j = fins_j_;
  tr.truth.mass_kg = fm_.mass_kg;
  tr.truth.cg_x_m = fm_.r_g_m.x();
  tr.truth.cg_y_m = fm_.r_g_m.y();
  tr.truth.cg_z_m = fm_.r_g_m.z();
  tr.truth.hull_volume_m3 = model_->body.hull.volume_m3;
  tr.truth.net_buoyancy_start_n = B_start_ - W0_;
}

}  // namespace auv::sim
