#include "analysis/auv_transient_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <cstdio>
#include <cstdlib>

#include "analysis/auv_calibration.h"
#include "common/units.h"
#include "seawater/depth_pressure.h"
#include "seawater/eos80.h"
#include "sim/dynamics.h"

namespace auv::analysis {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<double> valuesOf(const MissionLog& log, const char* name) {
  const LogChannel* c = log.find(name);
  return c ? c->values : std::vector<double>(log.rowCount(), kNaN);
}

// Rows r0..r1 of `v` with NaN gaps filled linearly (ends held); false when
// the range holds fewer than two valid values.
bool filled(const std::vector<double>& v, std::size_t r0, std::size_t r1, std::vector<double>& out) {
  out.assign(v.begin() + static_cast<long>(r0), v.begin() + static_cast<long>(r1));
  std::vector<std::size_t> ok;
  for (std::size_t i = 0; i < out.size(); ++i)
    if (std::isfinite(out[i])) ok.push_back(i);
  if (ok.size() < 2) return false;
  std::size_t j = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (std::isfinite(out[i])) continue;
    while (j + 1 < ok.size() && ok[j + 1] < i) ++j;
    if (i < ok.front()) out[i] = out[ok.front()];
    else if (i > ok.back()) out[i] = out[ok.back()];
    else {
      const std::size_t a = ok[j], b = ok[j + 1];
      const double f = static_cast<double>(i - a) / static_cast<double>(b - a);
      out[i] = out[a] * (1 - f) + out[b] * f;
    }
  }
  return true;
}

// Linear in time between rows (t sorted, values filled).
double at(const std::vector<double>& t, const std::vector<double>& v, double x) {
  const auto it = std::upper_bound(t.begin(), t.end(), x);
  if (it == t.begin()) return v.front();
  if (it == t.end()) return v.back();
  const auto i = static_cast<std::size_t>(it - t.begin());
  const double f = (x - t[i - 1]) / (t[i] - t[i - 1]);
  return v[i - 1] * (1 - f) + v[i] * f;
}

// Times of depth-command steps and propeller-speed changes, at least one
// window apart.
std::vector<double> eventTimes(const MissionLog& log, double min_gap_s) {
  const std::vector<double> dc = valuesOf(log, "depth_cmd"), rpm = valuesOf(log, "prop_rpm");
  std::vector<double> ev;
  double last_dc = kNaN, last_rpm = kNaN;
  for (std::size_t i = 0; i < log.rowCount(); ++i) {
    bool step = false;
    if (std::isfinite(dc[i])) {
      step = step || (std::isfinite(last_dc) && std::abs(dc[i] - last_dc) > 0.5);
      last_dc = dc[i];
    }
    if (std::isfinite(rpm[i])) {
      step = step || (std::isfinite(last_rpm) && std::abs(rpm[i] - last_rpm) > 3.0);
      last_rpm = rpm[i];
    }
    if (step && (ev.empty() || log.time[i] - ev.back() > min_gap_s)) ev.push_back(log.time[i]);
  }
  return ev;
}

// Noise of a channel from second differences of its valid consecutive samples.
double noiseSigma(const std::vector<double>& v, const std::vector<std::size_t>& rows) {
  double s = 0.0;
  std::size_t n = 0;
  for (std::size_t r : rows) {
    if (r == 0 || r + 1 >= v.size()) continue;
    const double d = v[r + 1] - 2 * v[r] + v[r - 1];
    if (std::isfinite(d)) s += d * d, ++n;
  }
  return n > 10 ? std::sqrt(s / static_cast<double>(n) / 6.0) : kNaN;
}

}  // namespace

TransientFit::TransientFit(const MissionLog& log, const sim::VehicleModel& nominal, const TransientFitContext& ctx)
    : nominal_(nominal), ctx_(ctx) {
  const std::size_t nrow = log.rowCount();
  if (nrow < 10 || !log.has("elevator") || !log.has("prop_rpm") || !log.has("depth") || !log.has("pitch") ||
      !log.has("speed") || !log.has("pitch_cmd") || !(ctx.autopilot.plane.ki != 0.0))
    return;
  const double span = ctx.window_before_s + ctx.window_after_s;
  std::vector<double> events = eventTimes(log, span);
  if (events.size() > ctx.max_windows) {
    std::vector<double> pick;
    for (std::size_t k = 0; k < ctx.max_windows; ++k)
      pick.push_back(events[k * events.size() / ctx.max_windows]);
    events = pick;
  }
  const std::vector<double> depth = valuesOf(log, "depth"), pitch = valuesOf(log, "pitch"),
                            roll = valuesOf(log, "roll"), speed = valuesOf(log, "speed"),
                            elev = valuesOf(log, "elevator"), rpm = valuesOf(log, "prop_rpm"),
                            temp = valuesOf(log, "temperature"), sal = valuesOf(log, "salinity"),
                            pres = valuesOf(log, "pressure"), pcmd = valuesOf(log, "pitch_cmd");
  const bool has_ctd = log.has("temperature") && log.has("salinity");
  std::vector<std::size_t> quiet_rows;  // rows before each event (for the noise levels)
  for (double te : events) {
    const double t0 = te - ctx.window_before_s, t1 = te + ctx.window_after_s;
    const auto r0 = static_cast<std::size_t>(std::lower_bound(log.time.begin(), log.time.end(), t0) - log.time.begin());
    const auto r1 = static_cast<std::size_t>(std::upper_bound(log.time.begin(), log.time.end(), t1) - log.time.begin());
    if (r1 <= r0 + 10 || log.time[r0] > t0 + 2.0 || r1 >= nrow) continue;
    bool gap = false;
    for (std::size_t r = r0 + 1; r < r1; ++r) gap = gap || log.time[r] - log.time[r - 1] > 3.0;
    if (gap) continue;
    std::vector<double> t(log.time.begin() + static_cast<long>(r0), log.time.begin() + static_cast<long>(r1));
    std::vector<double> fc, fr, fs, fd, fp, fT, fS, fP, fphi;
    if (!filled(pcmd, r0, r1, fc) || !filled(rpm, r0, r1, fr) || !filled(speed, r0, r1, fs) ||
        !filled(depth, r0, r1, fd) || !filled(pitch, r0, r1, fp))
      continue;
    // Near the surface the hull breaks it (waves, partial buoyancy): not the
    // submerged model the replay integrates.
    if (*std::min_element(fd.begin(), fd.end()) < ctx.min_depth_m) continue;
    const bool ctd = has_ctd && filled(temp, r0, r1, fT) && filled(sal, r0, r1, fS);
    const bool has_p = filled(pres, r0, r1, fP);
    if (!filled(roll, r0, r1, fphi)) fphi.assign(t.size(), 0.0);

    Window w;
    const double T0 = t.front();
    const auto steps = static_cast<std::size_t>(std::floor((t.back() - T0) / ctx.dt_s)) + 1;
    w.pitch_cmd_rad.resize(steps);
    w.prop_rps.resize(steps);
    w.buoyancy_change_n.resize(steps);
    w.density_kgm3.resize(steps);
    w.roll_rad.resize(steps);
    for (std::size_t k = 0; k < steps; ++k) {
      const double x = T0 + static_cast<double>(k) * ctx.dt_s;
      w.pitch_cmd_rad[k] = units::degToRad(at(t, fc, x));
      w.prop_rps[k] = std::max(0.0, at(t, fr, x) / 60.0);
      w.roll_rad[k] = units::degToRad(at(t, fphi, x));
      double rho = ctx.density_ref_kgm3, dB = 0.0;
      if (ctd) {
        const double z = at(t, fd, x);
        const double p = std::max(0.0, has_p ? at(t, fP, x) : seawater::pressureFromDepth(std::max(0.0, z)));
        const double T = at(t, fT, x);
        rho = seawater::density(at(t, fS, x), T, p);
        dB = units::g0 * rho * nominal_.body.hull.volumeAt(T, p) - ctx.buoyancy_ref_n;
      }
      w.density_kgm3[k] = rho;
      w.buoyancy_change_n[k] = dB;
    }
    // Initial state from the steady flight before the event: means over the
    // first 5 s, depth rate from a line through the first 10 s.
    double sp = 0, sth = 0, sphi = 0;
    int n5 = 0;
    double st = 0, sz = 0, stt = 0, stz = 0;
    int n10 = 0;
    for (std::size_t i = 0; i < t.size() && t[i] - T0 <= 10.0; ++i) {
      if (t[i] - T0 <= 5.0) sp += fs[i], sth += fp[i], sphi += fphi[i], ++n5;
      const double dt = t[i] - T0;
      st += dt, sz += fd[i], stt += dt * dt, stz += dt * fd[i], ++n10;
      if (te - log.time[r0 + i] > 1.0) quiet_rows.push_back(r0 + i);
    }
    if (n5 == 0 || n10 < 3) continue;
    const double den = n10 * stt - st * st;
    const double zrate = den > 0 ? (n10 * stz - st * sz) / den : 0.0;
    const double z_at0 = (sz - zrate * st) / n10;
    w.u0 = sp / n5;
    w.theta0 = units::degToRad(sth / n5);
    w.phi0 = units::degToRad(sphi / n5);
    w.z0 = z_at0;
    w.w0 = (zrate + w.u0 * std::sin(w.theta0)) / std::cos(w.theta0);

    // Observations about once a second.
    double next_t = T0 + 1.0;
    for (std::size_t r = r0; r < r1; ++r) {
      if (log.time[r] < next_t) continue;
      next_t = log.time[r] + 0.999;
      const auto k = static_cast<std::size_t>(std::lround((log.time[r] - T0) / ctx.dt_s));
      if (k >= steps) break;
      w.obs_step.push_back(k);
      w.obs_pitch_rad.push_back(std::isfinite(pitch[r]) ? units::degToRad(pitch[r]) : kNaN);
      w.obs_depth_m.push_back(depth[r]);
      w.obs_elevator_deg.push_back(elev[r]);
    }
    windows_.push_back(std::move(w));
  }
  // Sensor noise from the data (floors: model steps and a 1 Hz grid).
  const double sp = noiseSigma(pitch, quiet_rows), sd = noiseSigma(depth, quiet_rows),
               se = noiseSigma(elev, quiet_rows);
  sigma_elevator_deg_ = std::max(0.02, std::isfinite(se) ? se : 0.3);
  sigma_pitch_rad_ = units::degToRad(std::max(0.02, std::isfinite(sp) ? sp : 0.1));
  sigma_depth_m_ = std::max(0.01, std::isfinite(sd) ? sd : 0.05);
  for (const Window& w : windows_) n_residuals_ += 3 * w.obs_step.size();
}

sim::VehicleModel TransientFit::modelFor(const Eigen::VectorXd& p) const {
  sim::VehicleModel m = nominal_;
  sim::Hydrodynamics& h = m.hydro;
  const double L = m.body.reference_length_m;
  h.Zw_prime *= p(kHeave);
  h.Zq_prime *= p(kHeave);
  // The whole linear pitch moment in w (M_w with the Munk moment inside).
  h.Mw_prime = p(kPitchUw) / (0.5 * ctx_.density_ref_kgm3 * L * L * L);
  h.munk_factor = 0.0;
  h.Mq_prime *= p(kPitchDamping);
  h.Zww_kg_per_m *= p(kCrossflow);
  h.Mww_kg *= p(kCrossflow);
  h.Mqq_kgm2 *= p(kCrossflow);
  m.planes.Z_uud_per_deg *= p(kPlanes);
  m.planes.M_uud_per_deg *= p(kPlanes);
  m.planes.X_uudd_per_deg2 *= p(kPlanes);
  m.body.r_g_m = Eigen::Vector3d(p(kXg), 0.0, p(kBg));
  return m;
}

void TransientFit::simulate(const Window& w, const sim::VehicleModel& model, const Eigen::VectorXd& p,
                            double* out) const {
  sim::Dynamics dyn(model);
  dyn.setMassProperties(ctx_.weight_n / units::g0, Eigen::Vector3d(p(kXg), 0.0, p(kBg)), 0.0, ctx_.extra_Iyy_kgm2);
  sim::StateVector s = sim::StateVector::Zero();
  s[sim::kU] = w.u0;
  s[sim::kW] = w.w0;
  s[sim::kZ] = w.z0;
  s[sim::kTheta] = w.theta0;
  s[sim::kPhi] = w.phi0;
  // Elevator zero offset: the logged angle is the acting one plus c / s_e.
  const double offset_deg = std::abs(p(kPlanes)) > 1e-6 ? p(kPlaneOffset) / p(kPlanes) : 0.0;
  sim::StepInputs in;
  in.weight_n = ctx_.weight_n;
  auto inputsAt = [&](std::size_t k, double plane_rad) {
    in.water_density_kgm3 = w.density_kgm3[k];
    in.buoyancy_n = ctx_.weight_n + p(kNet) + w.buoyancy_change_n[k];
    in.actuators.prop_rps = w.prop_rps[k];
    in.actuators.plane_rad = plane_rad;
    dyn.setStepInputs(in);
  };
  // The plane that holds the initial attitude (dq/dt = 0) is where the
  // loop's integrator stood: the model at p decides it, not the noisy log.
  inputsAt(0, 0.0);
  const double q0 = dyn.derivative(s)[sim::kQ];
  inputsAt(0, units::degToRad(1.0));
  const double q1 = dyn.derivative(s)[sim::kQ];
  const double plane_max = units::degToRad(model.planes.max_deg);
  double plane = std::abs(q1 - q0) > 1e-12 ? std::clamp(-q0 / (q1 - q0) * units::degToRad(1.0), -plane_max, plane_max) : 0.0;
  // The stern-plane loop of the autopilot (eq. 27) tracks the logged pitch
  // command; its integral starts where it held the attitude.
  const sim::PidGains& g = ctx_.autopilot.plane;
  const double control_dt = ctx_.autopilot.sample_time_s;
  double integral = (plane - g.kp * (w.pitch_cmd_rad[0] - s[sim::kTheta])) / g.ki;
  double demand = plane;
  const auto every = static_cast<std::size_t>(std::max(1L, std::lround(control_dt / ctx_.dt_s)));
  const double max_step = units::degToRad(model.planes.rate_deg_per_s) * ctx_.dt_s;
  std::size_t o = 0;
  const std::size_t n_obs = w.obs_step.size();
  for (std::size_t k = 0; k < w.pitch_cmd_rad.size() && o < n_obs; ++k) {
    s[sim::kPhi] = w.roll_rad[k];
    s[sim::kP] = 0.0;
    if (k % every == 0) {  // at the controller's rate, on the model's own pitch
      const double err = w.pitch_cmd_rad[k] - s[sim::kTheta];
      const double bound = std::abs(plane_max / g.ki);
      integral = std::clamp(integral + err * control_dt, -bound, bound);
      demand = std::clamp(g.kp * err + g.ki * integral + g.kd * s[sim::kQ] * std::cos(s[sim::kPhi]), -plane_max, plane_max);
    }
    while (o < n_obs && w.obs_step[o] == k) {
      out[o] = std::isfinite(w.obs_pitch_rad[o]) ? (s[sim::kTheta] - w.obs_pitch_rad[o]) / sigma_pitch_rad_ : 0.0;
      out[n_obs + o] = std::isfinite(w.obs_depth_m[o]) ? (s[sim::kZ] - w.obs_depth_m[o]) / sigma_depth_m_ : 0.0;
      const double e_log = -units::radToDeg(plane) + offset_deg;  // paper sign -> log sign
      out[2 * n_obs + o] =
          std::isfinite(w.obs_elevator_deg[o]) ? (e_log - w.obs_elevator_deg[o]) / sigma_elevator_deg_ : 0.0;
      ++o;
    }
    inputsAt(k, plane);
    dyn.rk4Step(s, ctx_.dt_s);
    plane += std::clamp(demand - plane, -max_step, max_step);
    if (!s.allFinite()) break;
  }
  for (; o < n_obs; ++o) out[o] = out[n_obs + o] = out[2 * n_obs + o] = 1e3;  // diverged: a large, finite misfit
}

void TransientFit::rescaleChannels(const Eigen::VectorXd& p) {
  const Eigen::VectorXd r = residuals(p);
  std::array<double, 3> ss{}, n{};
  const double* x = r.data();
  for (const Window& w : windows_) {
    const std::size_t m = w.obs_step.size();
    for (std::size_t c = 0; c < 3; ++c)
      for (std::size_t i = 0; i < m; ++i) ss[c] += x[c * m + i] * x[c * m + i], n[c] += 1;
    x += 3 * m;
  }
  double* sig[3] = {&sigma_pitch_rad_, &sigma_depth_m_, &sigma_elevator_deg_};
  for (std::size_t c = 0; c < 3; ++c)
    if (n[c] > 0) *sig[c] *= std::sqrt(std::max(1.0, ss[c] / n[c]));
}

std::vector<Eigen::Index> TransientFit::windowEnds() const {
  std::vector<Eigen::Index> ends;
  Eigen::Index n = 0;
  for (const Window& w : windows_) ends.push_back(n += static_cast<Eigen::Index>(3 * w.obs_step.size()));
  return ends;
}

Eigen::VectorXd TransientFit::residuals(const Eigen::VectorXd& p) const { return residualsOf(modelFor(p), p); }

Eigen::VectorXd TransientFit::residualsOf(const sim::VehicleModel& model, const Eigen::VectorXd& p) const {
  Eigen::VectorXd r(static_cast<Eigen::Index>(n_residuals_));
  double* out = r.data();
  for (const Window& w : windows_) {
    simulate(w, model, p, out);
    out += 3 * w.obs_step.size();
  }
  return r;
}

}  // namespace auv::analysis
