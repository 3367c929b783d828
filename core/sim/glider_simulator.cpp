#include "sim/glider_simulator.h"

#include <algorithm>
#include <cmath>

#include "common/input_error.h"
#include "common/units.h"
#include "sim/sensor_noise.h"

namespace auv::sim {

double gliderScenarioDuration(const GliderScenario& sc) {
  double t = 0.0;
  for (const YoLeg& l : sc.legs) t += l.duration_s;
  return t;
}

namespace {

void validate(const GliderModel& g, const GliderScenario& sc, const SimOptions& opt) {
  if (!(opt.dt_s > 0.0 && opt.dt_s <= 10.0)) {
    throw InputError("dt_s", "model step must be in (0, 10] s for a glider", "use 0.5 s");
  }
  if (sc.legs.empty()) throw InputError("legs", "the glider scenario has no legs", "add a yo leg");
  for (std::size_t i = 0; i < sc.legs.size(); ++i) {
    const YoLeg& l = sc.legs[i];
    const std::string at = "legs[" + std::to_string(i) + "]";
    if (!(l.duration_s > 0.0)) throw InputError(at + ".duration_s", "must be positive", "give the leg a duration");
    if (!(l.dive_to_m > l.climb_to_m)) {
      throw InputError(at + ".dive_to_m", "must be deeper than climb_to_m", "e.g. dive to 100 m, climb to 10 m");
    }
    if (!std::isnan(l.pump_m3) && !(l.pump_m3 > 0.0 && l.pump_m3 <= g.pump_max_m3 + 1e-12)) {
      throw InputError(at + ".pump_cm3", "must be within the pump's travel (0, " +
                                             std::to_string(g.pump_max_m3 * 1e6) + "] cm3",
                       "give the pump volume of a dive or climb, e.g. 250");
    }
  }
}

double towards(double x, double target, double max_step) { return x + std::clamp(target - x, -max_step, max_step); }

}  // namespace

SimTrace simulateGlider(const GliderModel& g, const WaterColumn& water, const GliderScenario& sc,
                        const SimOptions& opt) {
  validate(g, sc, opt);
  const double dt = opt.dt_s;
  const long n_steps = std::lround(gliderScenarioDuration(sc) / dt);
  const long trace_every = std::max(1L, std::lround(opt.trace_interval_s / dt));
  const long control_every = std::max(1L, std::lround(g.control_interval_s / dt));

  double z = sc.initial_depth_m, x = 0.0, pump = 0.0, battery = 0.0, U = 0.0;
  WaterSample ws = water.at(std::max(0.0, z));
  const double B0 = ws.density_kgm3 * units::g0 * g.hull.volumeAt(ws.temperature_degC, ws.pressure_dbar);
  const FlownMass m =
      flownMass(g.mass_kg, g.r_g_m, g.cb_profile_m, sc.extra_masses, sc.net_buoyancy_n, sc.ballast_error, B0);
  const double W = m.mass_kg * units::g0;
  double theta = gliderStaticTrim(g, m, g.hull.volumeAt(ws.temperature_degC, ws.pressure_dbar),
                                  ws.density_kgm3, battery, pump).pitch_rad;
  const double a_theta = g.pitch_time_constant_s > 0.0 ? std::exp(-dt / g.pitch_time_constant_s) : 0.0;
  const double a_speed = g.speed_time_constant_s > 0.0 ? std::exp(-dt / g.speed_time_constant_s) : 0.0;

  std::vector<double> leg_end(sc.legs.size());
  double acc = 0.0;
  for (std::size_t i = 0; i < sc.legs.size(); ++i) leg_end[i] = (acc += sc.legs[i].duration_s);

  SimTrace tr;
  tr.reserve(static_cast<std::size_t>(n_steps / trace_every + 2));
  GaussianSource noise(opt.seed);
  bool diving = true;
  double pump_target = 0.0, battery_target = 0.0, pitch_target = 0.0, depth_target = 0.0;
  double nb0_sum = 0.0, energy = 0.0, hotel = 0.0;
  long nb0_n = 0;
  std::size_t leg = 0;
  for (long k = 0; k <= n_steps; ++k) {
    const double t = static_cast<double>(k) * dt;
    while (leg + 1 < sc.legs.size() && t >= leg_end[leg] - 1e-9) ++leg;
    const YoLeg& L = sc.legs[leg];
    ws = water.at(std::max(0.0, z));
    const double V_hull = g.hull.volumeAt(ws.temperature_degC, ws.pressure_dbar);
    const double F_B = ws.density_kgm3 * units::g0 * (V_hull + pump) - W;  // up positive

    if (k % control_every == 0) {
      if (diving && z >= L.dive_to_m) diving = false;
      if (!diving && z <= L.climb_to_m) diving = true;
      const double vol = std::isnan(L.pump_m3) ? g.pump_max_m3 : L.pump_m3;
      pump_target = diving ? -vol : vol;
      pitch_target = diving ? (std::isnan(L.dive_pitch_rad) ? g.dive_pitch_rad : L.dive_pitch_rad)
                            : (std::isnan(L.climb_pitch_rad) ? g.climb_pitch_rad : L.climb_pitch_rad);
      depth_target = diving ? L.dive_to_m : L.climb_to_m;
      battery_target = batteryForPitch(g, m, V_hull, ws.density_kgm3, pump_target, pitch_target);
    }
    const GliderTrim trim = gliderStaticTrim(g, m, V_hull, ws.density_kgm3, battery, pump);

    if (k % trace_every == 0 || k == n_steps) {
      tr.time_s.push_back(t);
      tr.depth_m.push_back(z + noise.next(opt.noise.depth_m));
      tr.depth_cmd_m.push_back(depth_target);
      tr.pitch_rad.push_back(theta + noise.next(opt.noise.pitch_rad));
      tr.pitch_cmd_rad.push_back(pitch_target);
      tr.roll_rad.push_back(trim.roll_rad + noise.next(opt.noise.roll_rad));
      tr.heading_rad.push_back(sc.initial_heading_rad);
      tr.heading_cmd_rad.push_back(std::numeric_limits<double>::quiet_NaN());
      tr.speed_mps.push_back(U);
      tr.x_m.push_back(x);
      tr.pump_volume_m3.push_back(pump);
      tr.battery_position_m.push_back(battery);
      tr.roll_mass_rad.push_back(0.0);
      tr.net_buoyancy_n.push_back(F_B);
      tr.temperature_degC.push_back(ws.temperature_degC + noise.next(opt.noise.temperature_degC));
      tr.salinity_psu.push_back(ws.salinity_psu + noise.next(opt.noise.salinity_psu));
      tr.pressure_dbar.push_back(ws.pressure_dbar + noise.next(opt.noise.pressure_dbar));
      const bool pumping = pump != pump_target, moving = battery != battery_target;
      tr.power_w.push_back(g.hotel_w + (pumping ? g.pump_w : 0.0) + (moving ? g.battery_w : 0.0));
      if (z > 10.0) {
        nb0_sum += ws.density_kgm3 * units::g0 * V_hull - W;
        ++nb0_n;
      }
    }
    if (k == n_steps) break;

    energy += (g.hotel_w + (pump != pump_target ? g.pump_w : 0.0) + (battery != battery_target ? g.battery_w : 0.0)) * dt;
    hotel += g.hotel_w * dt;
    // Steady glide of the current pitch and buoyancy, reached through the lags.
    const SteadyGlideSolution s = steadyGlide(g, ws.density_kgm3, F_B, theta);
    U = (s.gliding ? s.speed_mps : 0.0) + (U - (s.gliding ? s.speed_mps : 0.0)) * a_speed;
    const double path = theta + s.alpha_rad;
    z = std::max(0.0, z - U * std::sin(path) * dt);
    x += U * std::cos(path) * dt;
    theta = trim.pitch_rad + (theta - trim.pitch_rad) * a_theta;
    pump = towards(pump, pump_target, g.pump_rate_m3_per_s * dt);
    battery = towards(battery, battery_target, g.battery_rate_m_per_s * dt);
  }
  tr.energy_j = energy;
  tr.hotel_energy_j = hotel;
  tr.truth.mass_kg = m.mass_kg;
  tr.truth.cg_x_m = m.r_g_m.x();
  tr.truth.cg_y_m = m.r_g_m.y();
  tr.truth.cg_z_m = m.r_g_m.z();
  tr.truth.hull_volume_m3 = g.hull.volume_m3;
  tr.truth.net_buoyancy_start_n = B0 - W;
  if (nb0_n > 0) tr.truth.net_buoyancy_pump0_mean_n = nb0_sum / static_cast<double>(nb0_n);
  return tr;
}

}  // namespace auv::sim
