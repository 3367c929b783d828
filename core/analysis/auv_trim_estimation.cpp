#include "analysis/auv_trim_estimation.h"

#include "analysis/analysis_messages.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "analysis/auv_roll_estimation.h"
#include "analysis/level_flight.h"
#include "analysis/trimmed_cruise.h"
#include "common/units.h"

namespace auv::analysis {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kNotId = "not identifiable from this log because ";

// Measured quantities of one segment, in model units, and their standard errors.
struct Meas {
  std::array<double, 5> v;   // speed, pitch rad, roll rad, elevator deg, depth rate
  std::array<double, 5> se;
};
enum { kSpeed = 0, kPitch, kRoll, kElev, kRate };

double seOr0(const MeanEstimate& m, double scale = 1.0) {
  return std::isfinite(m.se) ? m.se * scale : 0.0;
}

Meas measOf(const SteadySegmentMeans& s, bool use_elevator) {
  Meas m;
  const double d2r = units::degToRad(1.0);
  m.v = {s.speed_mps.mean, s.pitch_deg.mean * d2r, s.roll_deg.valid() ? s.roll_deg.mean * d2r : 0.0,
         use_elevator ? s.elevator_deg.mean : 0.0, s.depth_rate_mps.valid() ? s.depth_rate_mps.mean : 0.0};
  m.se = {seOr0(s.speed_mps), seOr0(s.pitch_deg, d2r), s.roll_deg.valid() ? seOr0(s.roll_deg, d2r) : 0.0,
          use_elevator ? seOr0(s.elevator_deg) : 0.0, s.depth_rate_mps.valid() ? seOr0(s.depth_rate_mps) : 0.0};
  return m;
}

struct Model {
  SteadyHydroCoefficients c;
  double W = 0.0, BG = 0.0, rho = 1025.0;
  bool fit_bias = false;
  int k() const { return fit_bias ? 3 : 2; }

  // Rows A (2 x k) and right-hand side b of one segment: A p = b.
  void rows(const std::array<double, 5>& v, Eigen::MatrixXd& A, Eigen::Vector2d& b) const {
    SteadyFlight f{v[kSpeed], v[kPitch], v[kRoll], v[kElev], v[kRate], rho};
    const HydroLoads h = steadyHydroLoads(c, f);
    const double cc = std::cos(v[kPitch]) * std::cos(v[kRoll]);
    const double uu = std::abs(v[kSpeed]) * v[kSpeed];
    A.setZero(2, k());
    A(0, 0) = cc;
    A(1, 1) = W * cc;
    if (fit_bias) {
      A(0, 2) = c.Z_e_per_deg * uu;
      A(1, 2) = c.M_e_per_deg * uu;
    }
    b << h.Z(), h.M() - W * BG * std::sin(v[kPitch]);
  }
  Eigen::Vector2d residual(const std::array<double, 5>& v, const Eigen::VectorXd& p) const {
    Eigen::MatrixXd A;
    Eigen::Vector2d b;
    rows(v, A, b);
    return A * p - b;
  }
};

std::string fmt(const char* f, double v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// The calibrated vehicle in steady flight at net buoyancy net_n and CG x
// x_g (BG as calibrated, this log's water): what a planned segment would log.
LevelFlight plannedFlight(const SteadyHydroCoefficients& calibrated, const Model& m, const SteadyCalibration& cal,
                          double net_n, double x_g, double speed_mps, double depth_rate_mps) {
  LevelFlightInput in;
  in.weight_n = m.W;
  in.buoyancy_n = m.W + net_n;
  in.x_g_m = x_g;
  in.bg_m = cal.p(kBg);
  in.speed_mps = speed_mps;
  in.density_kgm3 = m.rho;
  in.depth_rate_mps = depth_rate_mps;
  return solveLevelFlight(calibrated, in);
}

// The manoeuvre: a descent and a climb of 30 m at 160 rpm at a steady
// 0.25 m/s, plus 5-min level legs at 130/160/190 rpm at one depth when the
// log has fewer than three speeds; flown as the calibrated model predicts,
// with this log's measurement noise scaled to their length: the sigmas
// after adding them to this log. A climb and a descent fly the hull at
// another angle of attack at the same speed, which separates hull lift
// from plane lift and both from the net buoyancy; more level speeds do
// not (in level flight trim angle and elevator change together with
// speed): on the drawn identification truths three more level legs left
// a 1.5 kg sigma at 1.5 kg, the climb and descent brought it to 0.17.
std::optional<AuvTrimEstimate::Manoeuvre> planManoeuvre(const SteadyHydroCoefficients& nominal, const Model& m,
                                                        const SteadyCalibration& cal, const std::vector<Meas>& meas,
                                                        std::span<const SteadySegmentMeans> segments,
                                                        const std::vector<std::size_t>& seg_index,
                                                        const AuvTrimEstimate& est) {
  if (!est.calibrated || meas.empty()) return std::nullopt;
  // Speed per rpm and noise per segment from this log.
  double su = 0.0, sn = 0.0, dur = 0.0;
  std::array<double, 5> se{};
  std::vector<double> rpms;
  for (std::size_t j = 0; j < meas.size(); ++j) {
    const SteadySegmentMeans& g = segments[seg_index[j]];
    if (g.prop_rpm.valid() && g.prop_rpm.mean > 1.0) {
      su += g.speed_mps.mean, sn += g.prop_rpm.mean;
      if (std::none_of(rpms.begin(), rpms.end(), [&](double r) { return std::abs(r - g.prop_rpm.mean) < 5.0; }))
        rpms.push_back(g.prop_rpm.mean);
    }
    dur += g.end_s - g.start_s;
    for (int k = 0; k < 5; ++k) se[static_cast<std::size_t>(k)] += meas[j].se[static_cast<std::size_t>(k)];
  }
  if (!(sn > 0.0)) return std::nullopt;
  const double per_rpm = su / sn, mean_dur = dur / static_cast<double>(meas.size());
  for (double& x : se) x /= static_cast<double>(meas.size());
  auto scaledTo = [&](double seconds) {
    std::array<double, 5> out = se;
    for (double& x : out) x *= std::sqrt(mean_dur / seconds);
    return out;
  };
  AuvTrimEstimate::Manoeuvre man;
  std::vector<CalibrationSegment> planned;
  auto add = [&](double rpm, double depth_rate_mps, double seconds) {
    const double speed_mps = per_rpm * rpm;
    const LevelFlight f = plannedFlight(*est.calibrated, m, cal, cal.p(kNet), cal.p(kXg), speed_mps, depth_rate_mps);
    if (!f.ok) return false;
    CalibrationSegment c;
    c.v = {speed_mps, f.pitch_rad, 0.0, f.elevator_deg + est.elevator_bias_deg, depth_rate_mps};
    c.se = scaledTo(seconds);
    c.density_kgm3 = m.rho;
    planned.push_back(c);
    man.flight.push_back({rpm, depth_rate_mps, seconds});
    return true;
  };
  if (rpms.size() < 3) {
    for (double rpm : {130.0, 160.0, 190.0})
      if (add(rpm, 0.0, 300.0))
        man.legs.push_back("5 min level at " + fmt("%.0f", rpm) + " rpm (about " + fmt("%.1f", per_rpm * rpm) +
                           " m/s) at the operating depth");
  }
  constexpr double kRate = 0.25, kDepthChange = 30.0;
  const std::size_t before = planned.size();
  if (!(add(160.0, kRate, kDepthChange / kRate) && add(160.0, -kRate, kDepthChange / kRate))) {
    planned.resize(before);  // both or neither
    man.flight.resize(before);
  } else {
    man.legs.push_back("descend " + fmt("%.0f", kDepthChange) + " m at 160 rpm (about " + fmt("%.1f", per_rpm * 160.0) +
                       " m/s) at a steady " + fmt("%.2f", kRate) +
                       " m/s, then climb back the same way (2 min each; the steady middle of each counts)");
  }
  if (planned.empty()) return std::nullopt;
  const Eigen::MatrixXd cov = covarianceAfter(nominal, m.W, m.rho, cal, planned);
  man.net_sigma_kg = std::sqrt(cov(kNet, kNet)) / units::g0;
  man.x_sigma_m = std::sqrt(cov(kXg, kXg));
  return man;
}

// The next mission after the move: this log's level segments flown again
// (same speeds, durations and noise) at the state a plan aims for, net
// buoyancy mid-band (0.6 kg) or the safety margin, and the CG x that flies
// level at the log's mean speed. Analysed with this log as history, the
// known change of mass and moment between them separates what this log
// alone cannot: on the identification truths a second mission so analysed
// reached 0.02-0.03 kg (median) where the manoeuvre predicted 0.6-0.9
// (docs/decisions/analysis-calibration.md). Only the regressors enter the
// covariance, so the known offsets of the move are not needed.
std::optional<AuvTrimEstimate::AfterMove> predictAfterMove(const SteadyHydroCoefficients& nominal, const Model& m,
                                                           const SteadyCalibration& cal, const std::vector<Meas>& meas,
                                                           const AuvTrimEstimate& est) {
  if (!est.calibrated || meas.empty()) return std::nullopt;
  // Where a plan with this sigma lands: mid-band, or at the safety margin
  // (1.645 sigma) when that is higher. Assumed at mid-band alone, the
  // prediction was up to 14 times too sharp for vehicles the margin sent
  // 5-7 kg light (seed 3122), at the margin at most 2.9.
  const double kNetAfter_kg = std::max(0.6, 1.645 * std::sqrt(cal.cov(kNet, kNet)) / units::g0);
  constexpr double kLevelRate_mps = 0.02;  // SegmentOptions::level_rate_mps: below it a segment is level
  double su = 0.0;
  int level = 0;
  for (const Meas& q : meas)
    if (std::abs(q.v[kRate]) < kLevelRate_mps) su += q.v[kSpeed], ++level;
  if (level == 0 || !(su > 0.0)) return std::nullopt;
  auto flight = [&](double x_g, double u) {
    return plannedFlight(*est.calibrated, m, cal, kNetAfter_kg * units::g0, x_g, u, 0.0);
  };
  // CG x for level flight: secant steps on the pitch at the mean speed.
  const double u_mean = su / level;
  double x0 = cal.p(kXg), x1 = x0 - 0.005;
  LevelFlight f0 = flight(x0, u_mean), f1 = flight(x1, u_mean);
  for (int it = 0; it < 8 && f0.ok && f1.ok && std::abs(f1.pitch_rad) > 1e-6; ++it) {
    const double d = f1.pitch_rad - f0.pitch_rad;
    if (!(std::abs(d) > 1e-12)) break;
    const double x2 = x1 - f1.pitch_rad * (x1 - x0) / d;
    x0 = x1, f0 = f1, x1 = x2, f1 = flight(x1, u_mean);
  }
  if (!f1.ok) return std::nullopt;
  std::vector<CalibrationSegment> planned;
  for (const Meas& q : meas) {
    if (!(std::abs(q.v[kRate]) < kLevelRate_mps)) continue;
    const LevelFlight f = flight(x1, q.v[kSpeed]);
    if (!f.ok) continue;
    CalibrationSegment c;
    c.v = {q.v[kSpeed], f.pitch_rad, 0.0, f.elevator_deg + est.elevator_bias_deg, 0.0};
    c.se = q.se;
    c.density_kgm3 = m.rho;
    planned.push_back(c);
  }
  if (planned.empty()) return std::nullopt;
  const Eigen::MatrixXd cov = covarianceAfter(nominal, m.W, m.rho, cal, planned);
  AuvTrimEstimate::AfterMove out;
  out.net_sigma_kg = std::sqrt(cov(kNet, kNet)) / units::g0;
  out.x_sigma_m = std::sqrt(cov(kXg, kXg));
  out.net_kg = kNetAfter_kg;
  out.x_g_m = x1;
  return out;
}

// The plan levels the roll the trimmed vehicle flies: at its own cruise
// speed, where the propeller torque differs from the log's (trimmed_cruise.h).
void applyTrimmedCruise(std::span<const SteadySegmentMeans> segments, const AuvTrimContext& ctx, AuvTrimEstimate& out) {
  if (!ctx.surge_model || !out.y_cruise_identified) return;
  out.trimmed_cruise = trimmedCruise(*ctx.surge_model, segments, out, ctx, out.after_move ? out.after_move->net_kg : 0.6);
  if (!out.trimmed_cruise) return;
  const TrimmedCruise& t = *out.trimmed_cruise;
  out.y_cruise_m += t.y_shift_m;
  if (std::abs(t.speed_mps - t.logged_speed_mps) < 0.05) return;  // said only where it matters to the technician
  out.notes.push_back(Message(msg::kTrimmedCruise, {fmt("%.2f", t.speed_mps), fmt("%.0f", t.rpm), fmt("%.2f", t.logged_speed_mps),
                                                    fmt("%+.3f", t.torque_change_nm), fmt("%+.2f", units::mToMm(out.y_cruise_m))}));
}

}  // namespace

AuvTrimEstimate estimateAuvTrim(std::span<const SteadySegmentMeans> segments, const SteadyHydroCoefficients* coeffs,
                                const std::string& no_coefficients_reason, const AuvTrimContext& ctx) {
  AuvTrimEstimate out;
  estimateRoll(segments, ctx, out);

  auto notIdentifiable = [&](const Message& why) { out.buoyancy_why = out.x_why = why; };
  if (segments.empty()) {
    notIdentifiable(Message(msg::kNoSteadyLevelSegment));
    return out;
  }
  if (!coeffs) {
    notIdentifiable(Message(std::string(kNotId) + no_coefficients_reason));
    return out;
  }
  if (!ctx.log_has_speed) {
    notIdentifiable(Message(msg::kNoSpeed));
    return out;
  }
  const bool use_elevator = coeffs->has_planes && ctx.log_has_elevator;
  std::vector<Meas> meas;
  std::vector<std::size_t> seg_index;
  std::size_t thrust_left_out = 0;
  double thrust_rpm = 0.0;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const auto& s = segments[i];
    if (!s.speed_mps.valid() || !s.pitch_deg.valid()) continue;
    if (use_elevator && !s.elevator_deg.valid()) continue;
    if (s.thruster_rpm > 0.0) {
      ++thrust_left_out;
      thrust_rpm = std::max(thrust_rpm, s.thruster_rpm);
      continue;
    }
    meas.push_back(measOf(s, use_elevator));
    seg_index.push_back(i);
  }
  out.segment_net_buoyancy_kg.assign(segments.size(), kNaN);
  out.segment_x_m.assign(segments.size(), kNaN);
  if (thrust_left_out > 0) {
    const Message m(meas.empty() ? msg::kThrustersInEverySegment : msg::kThrusterSegmentsLeftOut,
                    {std::to_string(thrust_left_out), fmt("%.0f", thrust_rpm)});
    if (meas.empty()) {
      notIdentifiable(m);
      return out;
    }
    out.notes.push_back(m);
  }
  if (meas.empty()) {
    notIdentifiable(Message(msg::kNoSpeedAndPitch));
    return out;
  }
  out.segments_used = meas.size();

  Model m;
  m.c = *coeffs;
  m.W = ctx.weight_n;
  m.BG = ctx.bg_measured_m.value_or(ctx.bg_profile_m);
  m.rho = ctx.density_kgm3;

  if (coeffs->has_planes && !ctx.log_has_elevator) {
    // Eliminating the unknown elevator angle from each pair leaves one
    // equation in W x_G - l (B - W), l = M_e / Z_e, whatever the speeds.
    const double l = coeffs->M_e_per_deg / coeffs->Z_e_per_deg;
    MeanAccumulator acc;
    double sw = 0, swq = 0;
    for (const Meas& s : meas) {
      auto q = [&](const std::array<double, 5>& v) {
        const HydroLoads h = steadyHydroLoads(m.c, {v[kSpeed], v[kPitch], v[kRoll], 0.0, v[kRate], m.rho});
        return (h.M_lift + h.M_munk - l * h.Z_lift - m.W * m.BG * std::sin(v[kPitch])) /
               (std::cos(v[kPitch]) * std::cos(v[kRoll]));
      };
      double var = 1e-12;
      for (int j = 0; j < 5; ++j) {
        if (!(s.se[j] > 0)) continue;
        std::array<double, 5> hi = s.v, lo = s.v;
        hi[j] += s.se[j];
        lo[j] -= s.se[j];
        var += 0.25 * (q(hi) - q(lo)) * (q(hi) - q(lo));
      }
      sw += 1.0 / var;
      swq += q(s.v) / var;
      acc.add(q(s.v));
      acc.endBlock();
    }
    out.plane_lever_m = l;
    out.moment_combination_nm = swq / sw;
    out.moment_combination_sigma_nm = std::max(std::sqrt(1.0 / sw), meas.size() >= 3 ? acc.result().sd / std::sqrt(static_cast<double>(meas.size())) : 0.0);
    notIdentifiable(Message(msg::kNoElevator, {fmt("%.3f", l)}));
    return out;
  }

  // Joint calibration of the hydrodynamic groups with the ballast state
  // (auv_calibration.h): every group has a prior from the profile, the log
  // narrows what it can, and the sigmas are the posterior's.
  CalibrationPriors pri;
  if (ctx.coefficient_rel_sigma) {
    pri.group_rel_sigma = *ctx.coefficient_rel_sigma;
    pri.munk_factor = coeffs->munk_factor;
    pri.munk_sigma = *ctx.coefficient_rel_sigma;
  } else if (coeffs->munk_stated) {
    pri.munk_factor = coeffs->munk_factor;
    pri.munk_sigma = pri.group_rel_sigma;
  }
  pri.pitch_alignment_sigma_deg = ctx.pitch_alignment_sigma_deg;
  pri.bg_m = m.BG;
  pri.bg_sigma_m = ctx.bg_measured_m ? ctx.bg_measured_sigma_m : ctx.bg_profile_rel_sigma * m.BG;
  pri.compressibility_per_dbar = ctx.hull_compressibility_per_dbar;
  pri.thermal_expansion_per_degC = ctx.hull_thermal_expansion_per_degC;
  pri.compressibility_sigma_per_dbar = std::max(pri.compressibility_sigma_per_dbar, 0.5 * std::abs(pri.compressibility_per_dbar));
  pri.thermal_expansion_sigma_per_degC =
      std::max(pri.thermal_expansion_sigma_per_degC, 0.5 * std::abs(pri.thermal_expansion_per_degC));
  pri.mass_drift_sigma_kg_per_h = std::max(pri.mass_drift_sigma_kg_per_h, 1e-4 * ctx.weight_n / units::g0);
  std::vector<CalibrationSegment> cs;
  for (std::size_t j = 0; j < meas.size(); ++j) {
    const SteadySegmentMeans& g = segments[seg_index[j]];
    CalibrationSegment c;
    c.v = meas[j].v;
    c.se = meas[j].se;
    c.density_kgm3 = std::isfinite(g.density_kgm3) ? g.density_kgm3 : ctx.density_kgm3;
    c.buoyancy_change_n = std::isfinite(g.buoyancy_change_n) ? g.buoyancy_change_n : 0.0;
    c.regressors = g.regressors;
    c.glide = g.glide;
    c.weight_n = g.weight_n;
    c.moment_offset_nm = g.moment_offset_nm;
    c.compressibility_lever_n = g.compressibility_lever_n;
    c.thermal_lever_n = g.thermal_lever_n;
    c.drift_lever_n = g.drift_lever_n;
    cs.push_back(c);
  }
  std::size_t history_used = 0;
  for (const SteadySegmentMeans& g : ctx.history) {
    if (!g.speed_mps.valid() || !g.pitch_deg.valid() || (use_elevator && !g.elevator_deg.valid())) continue;
    const Meas hm = measOf(g, use_elevator);
    CalibrationSegment c;
    c.v = hm.v;
    c.se = hm.se;
    c.density_kgm3 = std::isfinite(g.density_kgm3) ? g.density_kgm3 : ctx.density_kgm3;
    c.buoyancy_change_n = g.buoyancy_change_n;
    c.regressors = g.regressors;
    c.weight_n = g.weight_n;
    c.moment_offset_nm = g.moment_offset_nm;
    c.compressibility_lever_n = g.compressibility_lever_n;
    c.thermal_lever_n = g.thermal_lever_n;
    c.drift_lever_n = g.drift_lever_n;
    cs.push_back(c);
    ++history_used;
  }
  const SteadyCalibration cal = calibrateSteady(*coeffs, m.W, m.rho, cs, pri, ctx.transients);
  out.history_segments_used = history_used;
  if (history_used > 0)
    out.notes.push_back(Message(msg::kHistoryCalibration, {std::to_string(history_used)}));
  if (!cal.ok) {
    notIdentifiable(Message(msg::kDegenerate));
    return out;
  }
  if (cal.glides_dropped > 0) out.notes.push_back(Message(msg::kGlidesDropped, {std::to_string(cal.glides_dropped)}));
  out.segment_dropped.assign(segments.size(), false);
  for (std::size_t j = 0; j < meas.size() && j < cal.segment_kept.size(); ++j)
    out.segment_dropped[seg_index[j]] = !cal.segment_kept[j];
  if (cal.transient_residuals > 0 && !cal.transients_kept)
    out.notes.push_back(Message(msg::kTransientsDropped, {fmt("%.2f", cal.transient_net_sigma_n / units::g0),
                                                          fmt("%.2f", std::sqrt(cal.cov(kNet, kNet)) / units::g0)}));
  out.chi2_per_dof = cal.chi2_per_dof;
  out.buoyancy_identified = out.x_identified = true;
  out.net_buoyancy_kg = cal.p(kNet) / units::g0;
  out.net_buoyancy_sigma_kg = std::sqrt(cal.cov(kNet, kNet)) / units::g0;
  out.x_m = cal.p(kXg);
  out.x_sigma_m = std::sqrt(cal.cov(kXg, kXg));
  out.net_x_correlation = cal.cov(kNet, kXg) / std::sqrt(cal.cov(kNet, kNet) * cal.cov(kXg, kXg));
  if (coeffs->has_planes) {
    // Reported as fitted only where the log narrowed it; otherwise it stays
    // at its prior (0 +- elevator_offset_sigma_deg, in the sigmas).
    out.elevator_bias_deg = cal.elevator_offset_deg;
    out.elevator_bias_sigma_deg = cal.elevator_offset_sigma_deg;
    out.elevator_bias_fitted = out.elevator_bias_sigma_deg < 0.5 * pri.elevator_offset_sigma_deg;
    if (!out.elevator_bias_fitted)
      out.notes.push_back(Message(msg::kElevatorOffsetPrior, {fmt("%.0f", pri.elevator_offset_sigma_deg)}));
  }
  for (const auto& q : cal.parameters) out.calibration.push_back(q);
  for (const auto& q : cal.parameters)
    if (conflictsWithPrior(q))
      out.warnings.push_back(Message(msg::kCalibrationPriorConflict, {q.id, fmt("%.3g", q.value), fmt("%.3g", q.prior_value),
                                                                      fmt("%.2g", q.prior_sigma)}));
  for (const auto& q : cal.parameters)
    if (pitchBiasFound(q))
      out.notes.push_back(Message(msg::kPitchSensorBiasFound, {fmt("%+.2f", q.value), fmt("%.2f", q.sigma),
                                                                fmt("%.1f", pri.pitch_alignment_sigma_deg)}));
  out.calibrated = calibratedCoefficients(*coeffs, m.rho, cal.p);
  // Per-segment values at each segment's own water, calibrated model.
  Model one = m;
  one.c = *out.calibrated;
  one.BG = cal.p(kBg);
  for (std::size_t j = 0; j < meas.size(); ++j) {
    std::array<double, 5> v = meas[j].v;
    v[kElev] -= out.elevator_bias_deg;
    v[kPitch] -= units::degToRad(cal.pitch_sensor_bias_deg);
    Eigen::MatrixXd A;
    Eigen::Vector2d b;
    one.rows(v, A, b);
    out.segment_net_buoyancy_kg[seg_index[j]] = b(0) / A(0, 0) / units::g0;
    out.segment_x_m[seg_index[j]] = b(1) / A(1, 1);
  }
  out.manoeuvre = planManoeuvre(*coeffs, m, cal, meas, segments, seg_index, out);
  out.after_move = predictAfterMove(*coeffs, m, cal, meas, out);
  applyTrimmedCruise(segments, ctx, out);
  if (!m.c.note.empty()) out.notes.push_back(m.c.note);
  std::string ident, prior;
  for (const auto& q : cal.parameters) (q.identified ? ident : prior) += (q.identified ? ident : prior).empty() ? q.id : ", " + q.id;
  out.notes.push_back(Message(msg::kJointCalibration,
                              {fmt("%.1f", cal.data_parameters), ident.empty() ? "none" : ident, prior.empty() ? "none" : prior}));
  out.notes.push_back(Message(pri.munk_sigma >= 0.5 ? msg::kPosteriorSigmasMunk : msg::kPosteriorSigmas,
                              {fmt("%.0f", 100 * pri.group_rel_sigma)}));
  if (!ctx.bg_measured_m)
    out.notes.push_back(Message(msg::kBgFromProfile, {fmt("%.1f", units::mToMm(m.BG)), fmt("%.0f", 100 * ctx.bg_profile_rel_sigma)}));
  return out;
}

}  // namespace auv::analysis
