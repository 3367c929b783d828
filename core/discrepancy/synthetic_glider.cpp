#include "discrepancy/synthetic_glider.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/units.h"
#include "seawater/seawater.h"
#include "sim/sensor_noise.h"
#include "sim/sim_log.h"

namespace auv::discrepancy {

namespace {

struct Water {
  double T, S, p, rho;
};

// The water column of one yo: temperature and salinity of a tanh
// thermocline at depth zTc, pressure integrated hydrostatically from the
// local density (p = integral of rho g0 dz, as a pressure sensor measures
// it), tabulated every 0.5 m.
class Column {
 public:
  Column(const SyntheticGliderMission& m, double zTc) : m_(&m), zTc_(zTc) {
    const double dz = 0.5;
    const auto n = static_cast<std::size_t>((m.max_depth_m + 50.0) / dz) + 2;  // NOLINT
    p_.resize(n);
    double p = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      p_[i] = p;
      const double z = static_cast<double>(i) * dz;
      const double rho = seawater::density(S(z + 0.5 * dz), T(z + 0.5 * dz), p);
      p += rho * units::g0 * dz * 1e-4;
    }
  }
  double T(double z) const { return m_->deep_temperature_degC + f(z) * (m_->surface_temperature_degC - m_->deep_temperature_degC); }
  double S(double z) const { return m_->deep_salinity_psu + f(z) * (m_->surface_salinity_psu - m_->deep_salinity_psu); }
  Water at(double z) const {
    const double zz = std::max(z, 0.0);
    const double x = std::min(zz / 0.5, static_cast<double>(p_.size() - 2));
    const auto i = static_cast<std::size_t>(x);
    Water w;
    w.T = T(zz);
    w.S = S(zz);
    w.p = p_[i] + (x - static_cast<double>(i)) * (p_[i + 1] - p_[i]);
    w.rho = seawater::density(w.S, w.T, w.p);
    return w;
  }

 private:
  double f(double z) const { return 0.5 * (1.0 - std::tanh((std::max(z, 0.0) - zTc_) / m_->thermocline_width_m)); }
  const SyntheticGliderMission* m_;
  double zTc_;
  std::vector<double> p_;
};

double volumeFactor(const analysis::GliderFlightConstants& c, double p, double T) {
  return (1.0 - c.compressibility_per_dbar * p) * (1.0 + c.thermal_expansion_per_degC * (T - c.reference_temperature_degC));
}

}  // namespace

MissionLog synthesizeGliderLog(const SyntheticGliderTruth& truth, const SyntheticGliderMission& m) {
  analysis::GliderFlightConstants c = truth.constants;
  c.pitch_scale = 1.0;
  c.pitch_offset_rad = 0.0;
  sim::GaussianSource noise(m.seed);
  sim::GaussianSource env(m.seed * 7919 + 17);

  // Hull volume from the net buoyancy at the reference depth in the mean water.
  const Water ref = Column(m, m.thermocline_depth_m).at(truth.reference_depth_m);
  const double V0 = (c.mass_kg + truth.net_buoyancy_kg) / (ref.rho * volumeFactor(c, ref.p, ref.T));

  // One yo: dive to max depth, climb to 2 m, surface interval.
  const double yoGuess = 2.0 * m.max_depth_m / 0.15 + m.surface_s;
  const double tEnd = m.yos * yoGuess * 1.3;
  const double tMid = 0.5 * m.yos * yoGuess;

  MissionLog log;
  log.metadata = {{"vehicle", "synthetic glider"},
                  {"source", "auvballast model-check synthetic glider (steady-glide truth)"},
                  {"seed", std::to_string(m.seed)},
                  {"mass_kg", sim::formatNumber(c.mass_kg)},
                  {"truth_net_buoyancy_kg", sim::formatNumber(truth.net_buoyancy_kg)},
                  {"truth_reference_depth_m", sim::formatNumber(truth.reference_depth_m)},
                  {"truth_Cd0", sim::formatNumber(truth.Cd0)},
                  {"truth_hull_compressibility_per_dbar", sim::formatNumber(c.compressibility_per_dbar)},
                  {"truth_thermal_expansion_per_degC", sim::formatNumber(c.thermal_expansion_per_degC)},
                  {"truth_mass_drift_kg_per_h", sim::formatNumber(truth.mass_drift_kg_per_h)},
                  {"truth_pitch_sensor_bias_deg", sim::formatNumber(truth.pitch_bias_deg)},
                  {"truth_depth_sensor_offset_m", sim::formatNumber(truth.depth_offset_m)},
                  {"truth_vertical_current_mps", sim::formatNumber(truth.vertical_current_mps)},
                  {"truth_hull_volume_m3", sim::formatNumber(V0)},
                  {"truth_reference_temperature_degC", sim::formatNumber(c.reference_temperature_degC)},
                  {"truth_mass_mid_time_s", sim::formatNumber(tMid)},
                  {"position", "lat " + sim::formatNumber(m.latitude_deg) + " lon 0"}};
  const char* names[] = {"depth", "pressure", "pitch", "pump_volume", "pump_volume_cmd", "temperature", "salinity", "density"};
  const char* unitsOf[] = {"m", "dbar", "deg", "cm3", "cm3", "degC", "PSU", "kg/m3"};
  std::vector<std::vector<double>> col(8);

  enum { kDive, kClimb, kSurface } phase = kSurface;
  int yo = 0;
  auto cyc = [](const std::vector<double>& v, int i) { return v[static_cast<std::size_t>(i) % v.size()]; };
  double z = 0.0, pump = 250.0, theta = units::degToRad(cyc(m.pitch_climb_deg, 0)), wander = 0.0, wiw = 0.0;
  double surfaceLeft = 10.0, pumpCmd = 250.0, thetaCmd = theta;
  Column column(m, m.thermocline_depth_m);
  const double aw = std::exp(-m.step_s / m.internal_wave_tau_s);
  const double ap = std::exp(-m.step_s / 60.0);
  const auto every = std::max<long>(1, std::lround(m.sample_interval_s / m.step_s));
  long k = 0;
  double stallZ = 0.0, stallT = 0.0, abortT = -1.0;
  for (double t = 0.0; t <= tEnd; t += m.step_s, ++k) {
    // Stall abort: no progress for stall_abort_s in a dive or climb.
    if (phase != kSurface) {
      if (std::abs(z - stallZ) >= m.stall_min_progress_m) {
        stallZ = z;
        stallT = t;
      } else if (t - stallT > m.stall_abort_s) {
        if (abortT >= 0.0) break;  // the abort climb stalls too: the log ends
        abortT = t;
        phase = kClimb;
        pumpCmd = m.abort_pump_cm3;
        thetaCmd = units::degToRad(cyc(m.pitch_climb_deg, 0));
        stallT = t;
      }
    }
    // Mission logic.
    const auto prevPhase = phase;
    if (abortT >= 0.0 && phase == kClimb && z <= 2.0) break;  // surfaced after the abort: the log ends
    if (phase == kSurface) {
      surfaceLeft -= m.step_s;
      z = 0.0;
      if (surfaceLeft <= 0.0) {
        if (yo >= m.yos) break;
        phase = kDive;
        pumpCmd = cyc(m.pump_dive_cm3, yo);
        thetaCmd = units::degToRad(cyc(m.pitch_dive_deg, yo));
        column = Column(m, m.thermocline_depth_m + m.thermocline_heave_m * (2.0 * env.next() / 3.0));
      }
    } else if (phase == kDive && z >= m.max_depth_m) {
      phase = kClimb;
      pumpCmd = m.pump_climb_cm3[static_cast<std::size_t>(yo) % m.pump_climb_cm3.size()];
      thetaCmd = units::degToRad(cyc(m.pitch_climb_deg, yo));
    } else if (phase == kClimb && z <= 2.0) {
      phase = kSurface;
      surfaceLeft = m.surface_s;
      pumpCmd = 250.0;
      ++yo;
    }
    if (phase != prevPhase) {
      stallZ = z;
      stallT = t;
    }
    // Actuators and environment.
    const double dp = std::clamp(pumpCmd - pump, -m.pump_rate_cm3_per_s * m.step_s, m.pump_rate_cm3_per_s * m.step_s);
    pump += dp;
    wander = ap * wander + std::sqrt(1.0 - ap * ap) * env.next(units::degToRad(m.pitch_wander_deg));
    theta += (thetaCmd + wander - theta) * (1.0 - std::exp(-m.step_s / m.pitch_time_constant_s));
    wiw = aw * wiw + std::sqrt(1.0 - aw * aw) * env.next(m.internal_wave_sigma_mps);
    const Water w = column.at(z);

    // Steady glide through the water (0 while the net force opposes the pitch).
    double wThrough = 0.0;
    {
      const double mass = c.mass_kg + truth.mass_drift_kg_per_h * (t - tMid) / 3600.0;
      const double FB = units::g0 * (w.rho * (V0 * volumeFactor(c, w.p, w.T) + pump * 1e-6) - mass);
      const double a = analysis::steadyAngleOfAttack(c, theta, truth.Cd0);
      const double path = theta + a;
      const double U2 = 2.0 * FB * std::sin(path) / (w.rho * c.wing_area_m2 * (truth.Cd0 + c.induced_drag_per_rad2 * a * a));
      if (U2 > 0.0) wThrough = std::sqrt(U2) * std::sin(path);
    }
    if (k % every == 0) {
      log.time.push_back(t);
      const double T = w.T + noise.next(m.temperature_noise_degC), S = w.S + noise.next(m.salinity_noise_psu);
      const double p = std::max(0.0, w.p + noise.next(m.pressure_noise_dbar));
      // The depth sensor is a pressure sensor converted with the standard ocean (UNESCO).
      col[0].push_back(seawater::depthFromPressure(w.p, m.latitude_deg) + truth.depth_offset_m + noise.next(m.depth_noise_m));
      col[1].push_back(p);
      col[2].push_back(units::radToDeg(theta) + truth.pitch_bias_deg + noise.next(m.pitch_noise_deg));
      col[3].push_back(pump + noise.next(m.pump_noise_cm3));
      col[4].push_back(pumpCmd);
      col[5].push_back(T);
      col[6].push_back(S);
      col[7].push_back(seawater::density(S, T, p));
    }
    if (phase != kSurface) z = std::max(0.0, z - (wThrough + truth.vertical_current_mps + wiw) * m.step_s);
  }
  if (abortT >= 0.0) log.metadata.push_back({"truth_abort_time_s", sim::formatNumber(abortT)});
  for (std::size_t i = 0; i < 8; ++i) {
    LogChannel& ch = log.addChannel(names[i], unitsOf[i]);
    ch.values = col[i];
  }
  return log;
}

}  // namespace auv::discrepancy
