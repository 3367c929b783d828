#include "analysis/trimmed_cruise.h"

#include <cmath>
#include <string>

#include "analysis/level_flight.h"
#include "common/units.h"
#include "sim/dynamics.h"

namespace auv::analysis {

namespace {

// Same propeller speed: within 2 % (as the roll estimation's cruise segments).
bool sameRpm(double a, double b) { return std::abs(a - b) <= 0.02 * std::max(std::abs(a), std::abs(b)); }

// K_T(J)/K_T0, the law the roll estimation fitted the torque with (torque
// taken proportional to K_T).
double torqueShape(const AuvTrimContext::PropellerLaw& p, double rpm, double u) {
  const double n = rpm / 60.0;
  if (!(n > 0.0) || !(p.diameter_m > 0.0) || !(p.c1 > 0.0)) return 1.0;
  const double J = u * (1.0 - p.wake_fraction) / (n * p.diameter_m);
  return J > 0.0 ? 1.0 - std::pow(J / p.c1, p.c2) : 1.0;
}

// Surge force of the model (N, forward positive) holding speed u at pitch
// th and roll ph with depth rate zdot (positive down): m u_dot of sim::Dynamics.
double surgeForce(sim::Dynamics& dyn, double rho, double W, double B, double rpm, double plane_rad, double u, double th,
                  double ph, double zdot) {
  sim::StepInputs si;
  si.water_density_kgm3 = rho;
  si.weight_n = W;
  si.buoyancy_n = B;
  si.actuators.prop_rps = rpm / 60.0;
  si.actuators.plane_rad = plane_rad;
  dyn.setStepInputs(si);
  sim::StateVector s = sim::StateVector::Zero();
  s[sim::kU] = u;
  s[sim::kW] = (zdot + u * std::sin(th)) / (std::cos(th) * std::cos(ph));  // heave kinematics
  s[sim::kTheta] = th;
  s[sim::kPhi] = ph;
  return dyn.massDiagonal()[0] * dyn.derivative(s)[sim::kU];
}

const CalibrationParameter* fittedTorque(const AuvTrimEstimate& e) {
  if (e.y_basis.rfind("static (propeller", 0) != 0) return nullptr;  // one propeller speed: torque not separated
  for (const CalibrationParameter& q : e.calibration)
    if (q.id == "propeller_torque") return &q;
  return nullptr;
}

double calibratedPlanes(const AuvTrimEstimate& e) {
  for (const CalibrationParameter& q : e.calibration)
    if (q.id == "stern_plane_effectiveness" && q.value > 0.0) return q.value;
  return 1.0;
}

}  // namespace

std::optional<TrimmedCruise> trimmedCruise(const sim::VehicleModel& model, std::span<const SteadySegmentMeans> segments,
                                           const AuvTrimEstimate& e, const AuvTrimContext& ctx, double net_after_kg) {
  const CalibrationParameter* torque = fittedTorque(e);
  if (!torque || !ctx.propeller || !e.cruise_known || !(e.cruise_rpm > 0.0) || !(ctx.weight_n > 0.0) || !(model.prop.KT0 > 0.0))
    return std::nullopt;
  sim::VehicleModel m = model;
  const double planes = calibratedPlanes(e);  // plane drag goes with the plane's lift
  m.planes.X_uudd_per_deg2 *= planes;
  m.planes.Z_uud_per_deg *= planes;
  m.planes.M_uud_per_deg *= planes;
  sim::Dynamics dyn(m);
  const double W = ctx.weight_n;
  const double bg = ctx.bg_measured_m.value_or(ctx.bg_profile_m);
  // Surge force in level flight at net buoyancy B - W and CG x: pitch and
  // planes from the calibrated steady model. Used for the logged segments as
  // for the trimmed state, so that what the model gets wrong about holding
  // depth cancels between them (a state the plan leaves as it was keeps its
  // speed); where that model has no balance, the segment's own means.
  // The trimmed state (g null) where the calibrated model has no balance is
  // NaN: no speed is predicted there (see the root search below).
  auto levelSurge = [&](double rho, double B, double x_g, double u, double rpm, const SteadySegmentMeans* g) {
    if (e.calibrated) {
      const LevelFlight f = solveLevelFlight(*e.calibrated, {W, B, x_g, bg, u, rho, 0.0, 0.0});
      if (f.ok) return surgeForce(dyn, rho, W, B, rpm, -units::degToRad(f.elevator_deg), u, f.pitch_rad, 0.0, 0.0);
      if (!g) return std::nan("");
    }
    if (!g) return surgeForce(dyn, rho, W, B, rpm, 0.0, u, 0.0, 0.0, 0.0);
    return surgeForce(dyn, rho, W, B, rpm, -units::degToRad(g->elevator_deg.mean - e.elevator_bias_deg), u,
                      units::degToRad(g->pitch_deg.mean), units::degToRad(g->roll_deg.valid() ? g->roll_deg.mean : 0.0),
                      g->depth_rate_mps.valid() ? g->depth_rate_mps.mean : 0.0);  // log sign -> paper sign
  };
  // The drag the model misses, from the cruise segments (which held speed)
  // that flew a state the model can balance: not with the elevator at its
  // stop or steeper than the level solver's 30 deg. Truth 2127 flew its
  // first survey 27 kg heavy at 0.2-0.5 m/s and 45-64 deg nose down; its
  // missing drag from there kept every speed over 1 m/s out of reach, and
  // the plan levelled the torque of 0.48 m/s: rolled -12.6 deg after the
  // move, at 1.75 m/s. Without such a segment the model's own drag.
  double sw = 0.0, su = 0.0, rho_sum = 0.0, sk_w = 0.0, sk = 0.0;
  const double stop_deg = model.planes.max_deg - 0.5;
  for (const SteadySegmentMeans& g : segments) {
    if (g.from_history || g.thruster_rpm > 0.0 || !sameRpm(g.prop_rpm.mean, e.cruise_rpm)) continue;
    if (!g.speed_mps.valid() || !g.pitch_deg.valid() || !g.elevator_deg.valid() || !(g.speed_mps.mean > 0.1)) continue;
    const double rho = std::isfinite(g.density_kgm3) ? g.density_kgm3 : ctx.density_kgm3;
    const double u = g.speed_mps.mean;
    const double w = g.end_s - g.start_s;
    sw += w, su += w * u, rho_sum += w * rho;
    if (std::abs(g.elevator_deg.mean - e.elevator_bias_deg) >= stop_deg || std::abs(g.pitch_deg.mean) > 30.0) continue;
    const double B = W + units::g0 * e.net_buoyancy_kg + g.buoyancy_change_n;
    sk_w += w, sk += w * levelSurge(rho, B, e.x_m, u, g.prop_rpm.mean, &g) / (u * u);
  }
  if (!(sw > 0.0)) return std::nullopt;
  TrimmedCruise out;
  out.rpm = e.cruise_rpm;
  out.logged_speed_mps = su / sw;
  out.extra_drag_n_per_mps2 = sk_w > 0.0 ? sk / sk_w : 0.0;
  const double rho = rho_sum / sw;
  const double B = W + units::g0 * net_after_kg;
  const double x_g = e.after_move ? e.after_move->x_g_m : e.x_m;  // the state the plan aims for
  auto balance = [&](double u) { return levelSurge(rho, B, x_g, u, e.cruise_rpm, nullptr) - out.extra_drag_n_per_mps2 * u * u; };
  // Thrust falls and drag grows with speed: the fastest speed where the
  // balance crosses zero between two speeds the model can trim at, refined
  // by bisection. A crossing onto speeds where the model has no balance is
  // no root: the extrapolation from a log flown with the elevator at its
  // stop put one there (truth 4131: 0.70 m/s at 156 rpm, logged 1.82, and
  // the plan's roll 1.6 deg off).
  // Up to twice the logged speed, and at least 4 m/s (more than an AUV's
  // top speed): a survey flown far from trim can be several times slower.
  const double u_min = out.logged_speed_mps / 3.0, u_max = std::max(2.0 * out.logged_speed_mps, 4.0);
  constexpr int kGrid = 80;
  double lo = 0.0, hi = 0.0, above = balance(u_max);
  for (int k = kGrid - 1; k >= 0 && hi == 0.0; --k) {
    const double u = u_min + (u_max - u_min) * k / kGrid, b = balance(u);
    if (b > 0.0 && above <= 0.0) lo = u, hi = u_min + (u_max - u_min) * (k + 1) / kGrid;
    above = b;
  }
  if (hi == 0.0) return std::nullopt;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (balance(mid) > 0.0 ? lo : hi) = mid;
  }
  out.speed_mps = 0.5 * (lo + hi);
  const double q_at = torque->value * std::pow(e.cruise_rpm / 100.0, 2);
  out.torque_change_nm = q_at * (torqueShape(*ctx.propeller, e.cruise_rpm, out.speed_mps) -
                                 torqueShape(*ctx.propeller, e.cruise_rpm, out.logged_speed_mps));
  out.y_shift_m = out.torque_change_nm / W;
  return out;
}

}  // namespace auv::analysis
