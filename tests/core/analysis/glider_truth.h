#pragma once
// Synthetic glider yos with known hull volume and mass: the depth is
// integrated from the steady-glide vertical speed (angle of attack by the
// fixed-point iteration gliderflight uses, not the analysis's solver), plus
// an internal-wave vertical velocity and sensor noise.
#include <cmath>
#include <random>

#include "common/units.h"
#include "log_builder.h"
#include "missionlog/mission_log.h"
#include "seawater/seawater.h"

namespace auv::analysis::test {

struct GliderTruth {
  double mass_kg = 52.2;
  double V0_m3 = 0.0;  // set by the caller; V0 (1 - kappa p)(1 + alpha (T - T0)) + pump
  double kappa_per_dbar = 5e-6, alpha_per_degC = 7e-5, T0_degC = 18.5;
  double S_m2 = 0.1, a_per_rad = 7.53, Cd1 = 10.5, Cd0 = 0.15;
  double pump_cm3 = 230.0;
  double dive_pitch_deg = -26.0, climb_pitch_deg = 24.0;
  double max_depth_m = 150.0;
  int yos = 8;
  double wave_sd_mps = 0.01, wave_tau_s = 60.0;  // vertical water velocity
  double pitch_sd_deg = 0.5, pressure_sd_dbar = 0.01;
  bool log_pump = true;
  unsigned seed = 4;
};

inline double waterT(double z) { return 5.0 + 10.0 * std::exp(-z / 30.0); }
inline double waterRho(double z) {
  return seawater::densityAtDepth(35.0, waterT(z), z);
}

inline double truthW(const GliderTruth& g, double pitch_rad, double z, double pump_m3) {
  const double phi = std::abs(pitch_rad);
  double a = phi / 50;
  for (int i = 0; i < 500; ++i) a = (g.Cd0 + g.Cd1 * a * a) / (g.a_per_rad * std::tan(a + phi));
  const double alpha = std::copysign(a, pitch_rad);
  const double p = seawater::pressureFromDepth(z);
  const double rho = waterRho(z);
  const double V = g.V0_m3 * (1 - g.kappa_per_dbar * p) * (1 + g.alpha_per_degC * (waterT(z) - g.T0_degC)) + pump_m3;
  const double FB = units::g0 * (rho * V - g.mass_kg);
  const double q = FB * std::sin(pitch_rad + alpha) / (g.Cd0 + g.Cd1 * alpha * alpha);
  if (q <= 0) return 0.0;
  return std::sqrt(2 * q / (rho * g.S_m2)) * std::sin(pitch_rad + alpha);
}

inline MissionLog makeGliderLog(const GliderTruth& g) {
  std::mt19937 rng(g.seed);
  std::normal_distribution<double> nd(0.0, 1.0);
  const double dt = 1.0;
  const double aw = std::exp(-dt / g.wave_tau_s), bw = std::sqrt(1 - aw * aw);
  std::vector<double> t, z, pitch, pump;
  double zz = 0.3, wave = 0, tt = 0, pn = 0;
  int phase = 0;  // 0 surface, 1 dive, 2 climb
  double surface_until = 120;
  int yo = 0;
  while (yo < g.yos || phase != 0 || tt < surface_until) {
    double th = 0, pv = g.pump_cm3 * 1e-6;
    if (phase == 0) {
      if (tt >= surface_until) {
        if (yo >= g.yos) break;
        phase = 1;
      }
    } else if (phase == 1 && zz >= g.max_depth_m) {
      phase = 2;
    } else if (phase == 2 && zz <= 2.0) {
      phase = 0;
      ++yo;
      surface_until = tt + 120;
    }
    pn = 0.9 * pn + std::sqrt(1 - 0.81) * nd(rng);
    if (phase == 1) {
      th = units::degToRad(g.dive_pitch_deg);
      pv = -pv;
    } else if (phase == 2) {
      th = units::degToRad(g.climb_pitch_deg);
    }
    wave = aw * wave + bw * g.wave_sd_mps * nd(rng);
    const double w = phase == 0 ? 0.0 : truthW(g, th, std::max(zz, 0.0), pv) + wave;
    t.push_back(tt);
    z.push_back(zz);
    pitch.push_back(units::radToDeg(th) + g.pitch_sd_deg * pn);
    pump.push_back(pv * 1e6);
    zz = phase == 0 ? 0.3 : std::max(0.3, zz - w * dt);
    tt += dt;
  }
  MissionLog log;
  log.time = t;
  // addChannel returns a reference into the channel vector: reserve so it stays valid.
  log.channels.reserve(log.channels.size() + 16);
  LogChannel& cP = log.addChannel("pressure", "dbar");
  LogChannel& cD = log.addChannel("depth", "m");
  LogChannel& cPitch = log.addChannel("pitch", "deg");
  LogChannel* cPump = g.log_pump ? &log.addChannel("pump_volume", "cm3") : nullptr;
  LogChannel& cT = log.addChannel("temperature", "degC");
  LogChannel& cS = log.addChannel("salinity", "PSU");
  for (std::size_t i = 0; i < t.size(); ++i) {
    cP.values[i] = seawater::pressureFromDepth(z[i]) + g.pressure_sd_dbar * nd(rng);
    cT.values[i] = waterT(z[i]);
    cS.values[i] = 35.0;
    if (i % 4 == 0) {  // engineering channels every 4 s, like a Slocum
      cD.values[i] = z[i];
      cPitch.values[i] = pitch[i];
      if (cPump) cPump->values[i] = pump[i];
    }
  }
  return log;
}

}  // namespace auv::analysis::test
