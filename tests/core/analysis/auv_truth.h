#pragma once
// Synthetic AUV missions with known truth: steady legs solved from the full
// Fossen-form force balance (g(eta) from core hydrostatics, hydrodynamic
// derivatives read straight from the profile JSON in the paper's sign), then
// sampled like a real log with autocorrelated noise. Independent of the
// analysis code: it solves the forward problem (attitude and plane angle
// from mass properties), the analysis solves the inverse.
#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

#include "common/units.h"
#include "hydrostatics/restoring.h"
#include "log_builder.h"
#include "missionlog/mission_log.h"
#include "seawater/seawater.h"
#include "vehicle/vehicle_profile.h"

namespace auv::analysis::test {

struct Leg {
  double depth_m;
  double speed_mps;
  double duration_s;
};

struct AuvTruth {
  double mass_kg = 81.4;      // as flown
  double net_buoyancy_kg = 0.6;  // rho V - m at the mean leg density
  Eigen::Vector3d cg_m{0.008, 0.003, 0.060};  // CG - CB (z = BG)
  double elevator_bias_deg = 0.0;  // logged = true + bias (interchange sign)
  double depth_offset_m = 0.0;     // measured = commanded + offset
  std::vector<Leg> legs = {{10, 1.0, 600}, {20, 1.3, 600}, {15, 1.6, 600}};
  double dt = 0.2;
  double temperature_degC = 12.0, salinity_psu = 35.0;
  bool log_elevator = true, log_speed = true, log_rpm = true;
  double prop_torque_nm_per_rps2 = 0.0;  // reaction torque, starboard down positive
  // AR(1) noise: standard deviation and correlation time.
  double pitch_sd_deg = 0.3, roll_sd_deg = 0.2, elevator_sd_deg = 0.8, speed_sd = 0.02, depth_sd = 0.05;
  double tau_s = 5.0;
  unsigned seed = 1;
};

struct SteadyAttitude {
  double pitch_rad = 0, roll_rad = 0, plane_paper_deg = 0;
};

// Steady level flight at speed u: solve heave, pitch and roll balance for
// (theta, delta_paper, phi) with Newton's method.
inline SteadyAttitude solveSteady(const VehicleProfile& v, double W, double B, const Eigen::Vector3d& rg, double u,
                                  double rho, double torque) {
  const auto& h = v.sections["hydrodynamics"];
  const auto& sp = v.sections["actuators"]["stern_planes"];
  const double L = h["reference_length_m"].get<double>();
  const double kZw = 0.5 * rho * L * L * h["Zw_prime"].get<double>();
  const double kMw = 0.5 * rho * L * L * L * h["Mw_prime"].get<double>();
  const double Zww = h["Zww_kg_per_m"].get<double>(), Mww = h["Mww_kg"].get<double>();
  const double munk = h["Xudot_kg"].get<double>() - h["Zwdot_kg"].get<double>();
  const double Zd = sp["Z_uud_kg_per_m_deg"].get<double>(), Md = sp["M_uud_kg_per_deg"].get<double>();
  auto F = [&](const Eigen::Vector3d& x) {
    const double th = x(0), d = x(1), ph = x(2);
    const double w = u * std::sin(th) / (std::cos(th) * std::cos(ph));
    const Vector6d g = restoringForces(W, B, rg, Eigen::Vector3d::Zero(), ph, th);
    const double Z = kZw * u * w + Zww * std::abs(w) * w + Zd * u * u * d;
    const double M = kMw * u * w + Mww * std::abs(w) * w + munk * u * w + Md * u * u * d;
    return Eigen::Vector3d(Z - g[2], M - g[4], torque - g[3]);
  };
  Eigen::Vector3d x(-0.05, 0.0, 0.0);
  for (int it = 0; it < 50; ++it) {
    const Eigen::Vector3d f = F(x);
    if (f.norm() < 1e-12) break;
    Eigen::Matrix3d J;
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d xp = x;
      xp(j) += 1e-7;
      J.col(j) = (F(xp) - f) / 1e-7;
    }
    x -= J.lu().solve(f);
  }
  return {x(0), x(2), x(1)};
}

inline double legDensity(const AuvTruth& t, double depth) {
  return seawater::densityAtDepth(t.salinity_psu, t.temperature_degC, depth);
}

inline double meanLegDensity(const AuvTruth& t) {
  double s = 0, w = 0;
  for (const Leg& l : t.legs) {
    s += legDensity(t, l.depth_m) * l.duration_s;
    w += l.duration_s;
  }
  return s / w;
}

inline MissionLog makeAuvLog(const VehicleProfile& v, const AuvTruth& tr) {
  const double volume = (tr.mass_kg + tr.net_buoyancy_kg) / meanLegDensity(tr);
  const double W = tr.mass_kg * units::g0;
  // Timeline: 60 s surface, then per leg a transition at 0.3 m/s vertical
  // (at least 60 s) and the leg, then climb and 60 s at the surface.
  struct Piece {
    double t0, t1, z0, z1, speed, cmd;
    int leg;  // -1 transition/surface
  };
  std::vector<Piece> pieces;
  double t = 0, z = 0.1;
  pieces.push_back({0, 60, 0.1, 0.1, 0.0, 0.0, -1});
  t = 60;
  for (std::size_t i = 0; i < tr.legs.size(); ++i) {
    const Leg& l = tr.legs[i];
    const double dur = std::max(60.0, std::abs(l.depth_m - z) / 0.3);
    pieces.push_back({t, t + dur, z, l.depth_m, l.speed_mps, l.depth_m, -1});
    t += dur;
    pieces.push_back({t, t + l.duration_s, l.depth_m, l.depth_m, l.speed_mps, l.depth_m, static_cast<int>(i)});
    t += l.duration_s;
    z = l.depth_m;
  }
  const double up = std::max(60.0, z / 0.3);
  pieces.push_back({t, t + up, z, 0.1, 1.0, 0.0, -1});
  t += up;
  pieces.push_back({t, t + 60, 0.1, 0.1, 0.0, 0.0, -1});
  t += 60;

  std::vector<SteadyAttitude> att;
  for (const Leg& l : tr.legs) {
    const double rho = legDensity(tr, l.depth_m);
    const double n = 10.0 * l.speed_mps;  // propeller rev/s
    att.push_back(solveSteady(v, W, rho * volume * units::g0, tr.cg_m, l.speed_mps, rho,
                              tr.prop_torque_nm_per_rps2 * n * n));
  }

  MissionLog log = makeLog(0, t, tr.dt);
  const std::size_t N = log.rowCount();
  std::mt19937 rng(tr.seed);
  std::normal_distribution<double> nd(0.0, 1.0);
  const double a = std::exp(-tr.dt / tr.tau_s), b = std::sqrt(1 - a * a);
  auto ar1 = [&](double sd) {
    std::vector<double> x(N);
    double s = nd(rng);
    for (std::size_t i = 0; i < N; ++i) {
      s = a * s + b * nd(rng);
      x[i] = sd * s;
    }
    return x;
  };
  const auto nPitch = ar1(tr.pitch_sd_deg), nRoll = ar1(tr.roll_sd_deg), nElev = ar1(tr.elevator_sd_deg),
             nSpeed = ar1(tr.speed_sd), nDepth = ar1(tr.depth_sd);
  std::size_t k = 0;
  auto pieceAt = [&](double tt) -> const Piece& {
    while (k + 1 < pieces.size() && tt >= pieces[k].t1) ++k;
    return pieces[k];
  };
  // addChannel returns a reference into the channel vector: reserve so it stays valid.
  log.channels.reserve(log.channels.size() + 16);
  LogChannel& cDepth = log.addChannel("depth", "m");
  LogChannel& cCmd = log.addChannel("depth_cmd", "m");
  LogChannel& cPitch = log.addChannel("pitch", "deg");
  LogChannel& cRoll = log.addChannel("roll", "deg");
  LogChannel* cSpeed = tr.log_speed ? &log.addChannel("speed", "m/s") : nullptr;
  LogChannel* cElev = tr.log_elevator ? &log.addChannel("elevator", "deg") : nullptr;
  LogChannel* cRpm = tr.log_rpm ? &log.addChannel("prop_rpm", "rpm") : nullptr;
  LogChannel& cT = log.addChannel("temperature", "degC");
  LogChannel& cS = log.addChannel("salinity", "PSU");
  LogChannel& cP = log.addChannel("pressure", "dbar");
  double lastCmd = -1;
  for (std::size_t i = 0; i < N; ++i) {
    const double tt = log.time[i];
    const Piece& p = pieceAt(tt);
    const double f = (tt - p.t0) / (p.t1 - p.t0);
    const double zt = p.z0 + f * (p.z1 - p.z0);
    const bool atSurface = p.speed == 0.0;
    double pitch, roll, elev, speed = p.speed;
    if (p.leg >= 0) {
      const SteadyAttitude& s = att[static_cast<std::size_t>(p.leg)];
      pitch = units::radToDeg(s.pitch_rad);
      roll = units::radToDeg(s.roll_rad);
      elev = -s.plane_paper_deg + tr.elevator_bias_deg;  // interchange sign: trailing edge down positive
    } else {
      const double rate = (p.z1 - p.z0) / (p.t1 - p.t0);
      pitch = atSurface ? 0.0 : -units::radToDeg(std::atan2(rate, std::max(speed, 0.3)));
      roll = 0.0;
      elev = atSurface ? 0.0 : 0.5 * pitch;
    }
    cDepth.values[i] = zt + (atSurface ? 0.0 : tr.depth_offset_m) + nDepth[i] * (atSurface ? 0.2 : 1.0);
    if (p.cmd != lastCmd) {
      cCmd.values[i] = p.cmd;
      lastCmd = p.cmd;
    }
    cPitch.values[i] = pitch + nPitch[i];
    cRoll.values[i] = roll + nRoll[i];
    if (cElev) cElev->values[i] = elev + nElev[i];
    if (cSpeed && i % 2 == 0) cSpeed->values[i] = std::max(0.0, speed + nSpeed[i]);
    if (cRpm && i % 2 == 0) cRpm->values[i] = 600.0 * speed;
    if (i % 5 == 0) {
      cT.values[i] = tr.temperature_degC;
      cS.values[i] = tr.salinity_psu;
      cP.values[i] = seawater::pressureFromDepth(std::max(0.0, zt));
    }
  }
  return log;
}

}  // namespace auv::analysis::test
