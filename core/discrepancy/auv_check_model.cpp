#include "discrepancy/auv_check_model.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/mission_analysis.h"
#include "analysis/segments.h"
#include "analysis/series_tools.h"
#include "common/input_error.h"
#include "common/units.h"
#include "discrepancy/check_messages.h"
#include "discrepancy/log_features.h"
#include "discrepancy/savitzky_golay.h"
#include "discrepancy/sensor_noise_estimate.h"
#include "seawater/seawater.h"
#include "sim/actuator_forces.h"
#include "sim/dynamics.h"
#include "sim/flown_mass.h"
#include "sim/water_from_log.h"

namespace auv::discrepancy {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRhoRef = 1025.0;

void require(const MissionLog& log, const char* name, const char* why) {
  if (!hasChannel(log, name, 10))
    throw InputError(name, std::string("the log has no ") + name + " channel, needed " + why,
                     "a model check of an AUV needs depth, pitch, roll, speed, prop_rpm and elevator");
}
}  // namespace

AuvCheckModel::AuvCheckModel(const MissionLog& log, const VehicleProfile& v, const sim::VehicleModel& model,
                             const sim::DepthAutopilotConfig& autopilot, const AuvCheckOptions& o)
    : profile_(v), model_(model), autopilot_(autopilot), opt_(o) {
  require(log, "depth", "for the depth rate");
  require(log, "pitch", "for the attitude");
  require(log, "roll", "for the roll balance");
  require(log, "speed", "for the hydrodynamic loads");
  require(log, "prop_rpm", "for the propeller");
  require(log, "elevator", "for the stern-plane loads");
  if (!hasChannel(log, "depth_cmd", 2) && !hasChannel(log, "pitch_cmd", 2))
    notes_.push_back("no depth_cmd or pitch_cmd: the simulation replays the logged elevator open loop");
  latitude_ = analysis::latitudeFromMetadata(log).value_or(seawater::kDefaultLatitude_deg);
  log_.metadata = log.metadata;
  log_.time = log.time;
  for (const char* name : {"depth", "pitch", "roll", "heading", "speed", "prop_rpm", "elevator", "thruster_front_rpm",
                           "thruster_aft_rpm", "depth_cmd", "pitch_cmd", "temperature", "salinity", "density", "pressure"})
    if (const LogChannel* c = log.find(name)) log_.channels.push_back(*c);
  noise_ = estimateSensorNoise(log);
  baseline_ = acceptedTermsFromProfile(v.sections, v.file);
  for (const AuvCheckOptions::HeldTerm& h : o.held_terms)
    if (const auto k = findTerm(h.id))
      baseline_[*k] += (h.value - h.profile_value) / termLibrary()[*k].display_scale;
  if (!o.installed_kg.empty()) installed_ = sim::installedWeights(v, o.installed_kg);
  profile_bg_m_ = sim::flownMass(model_, installed_, std::nullopt, {}, 0.0).r_g_m.z();
  if (!(profile_bg_m_ > 1e-4))
    throw InputError(v.file, "the profile's CG is not below its CB (BG " + std::to_string(profile_bg_m_ * 1e3) + " mm as flown)",
                     "give bg_mm (or cg_mm) so the CG lies below the CB: an AUV without static stability cannot be checked");

  // Uniform grid.
  const TimeSeries pitchS = log.series("pitch");
  double dt = o.row_interval_s > 0 ? o.row_interval_s : std::max(0.2, analysis::medianInterval(pitchS.t));
  // The recorded span without its logger drop-outs: a gap of days must not
  // coarsen the grid (nor fill it with empty points).
  const std::vector<double>& rowT = log.time;
  double span = 0.0;
  for (std::size_t i = 1; i < rowT.size(); ++i) span += std::min(rowT[i] - rowT[i - 1], std::max(5.0, 5.0 * dt));
  dt = std::max(dt, span / static_cast<double>(std::max<std::size_t>(100, o.max_rows)));
  dt_ = dt;
  const double gap = std::max(5.0, 5.0 * dt);
  const int half = std::max(2, static_cast<int>(std::lround(o.state_half_window_s / dt)));
  // Uniform at dt over the recorded stretches; across a gap longer than `gap`
  // only a few points are kept (every channel is NaN there), so the fits on
  // either side never meet and the grid follows the rows.
  std::vector<double> grid;
  std::size_t row = 0;
  for (double t = rowT.front(); t <= rowT.back() + 1e-9;) {
    grid.push_back(t);
    double next = t + dt;
    while (row + 1 < rowT.size() && rowT[row + 1] <= next) ++row;
    if (row + 1 < rowT.size() && rowT[row + 1] - rowT[row] > gap && next > rowT[row] + gap)
      next = std::max(next, rowT[row + 1] - static_cast<double>(half + 2) * dt);
    t = next;
  }
  gridT_ = grid;
  const std::size_t G = grid.size();
  k_ = std::max(1, static_cast<int>(std::lround(o.integral_half_window_s / dt)));
  auto smooth = [&](const char* name, double scale) {
    std::vector<double> y = channelAt(log, name, grid, false, gap);
    for (double& x : y) x *= scale;
    return savitzkyGolay(y, dt, half, o.state_fit_order);
  };
  // Propeller and thruster forces go with n |n|: smooth that, not n, so the
  // mean force over the window is kept.
  auto smoothSquare = [&](const char* name) {
    std::vector<double> y = channelAt(log, name, grid, false, gap);
    for (double& x : y) x *= std::abs(x);
    Smoothed r = savitzkyGolay(y, dt, half, o.state_fit_order);
    for (double& x : r.value) x = std::copysign(std::sqrt(std::abs(x)), x);
    return r;
  };
  const double deg = units::degToRad(1.0);
  const Smoothed u = smooth("speed", 1.0), th = smooth("pitch", deg), ph = smooth("roll", deg);
  const Smoothed rpm = smoothSquare("prop_rpm"), el = smooth("elevator", deg);
  const bool thr = model_.thruster_count > 0;
  const Smoothed tf = thr && hasChannel(log, "thruster_front_rpm") ? smoothSquare("thruster_front_rpm") : Smoothed{};
  const Smoothed ta = thr && hasChannel(log, "thruster_aft_rpm") ? smoothSquare("thruster_aft_rpm") : Smoothed{};
  if (thr && (tf.value.empty() || ta.value.empty()))
    notes_.push_back("no tunnel-thruster channels: thrusters taken as off in the equation error");
  const std::vector<double> zRaw = channelAt(log, "depth", grid, false, gap);
  const std::vector<double> pRaw = channelAt(log, "pitch", grid, false, gap);
  const std::vector<double> rRaw = channelAt(log, "roll", grid, false, gap);
  const std::vector<double> uRaw = channelAt(log, "speed", grid, false, gap);
  // w cos(theta) cos(phi) = z_dot + u sin(theta) = d/dt [z + integral of u
  // sin(theta)]: fitting that sum as one signal keeps the depth rate and the
  // speed along the pitched axis on the same fit.
  Smoothed X;
  {
    std::vector<double> x(G, kNaN);
    double acc = 0.0;
    bool open = false;
    for (std::size_t i = 0; i < G; ++i) {
      const double f = uRaw[i] * std::sin(units::degToRad(pRaw[i]));
      if (!std::isfinite(f) || !std::isfinite(zRaw[i])) {
        open = false;
        continue;
      }
      if (open) acc += 0.5 * dt * (f + uRaw[i - 1] * std::sin(units::degToRad(pRaw[i - 1])));
      open = true;
      x[i] = zRaw[i] + acc;
    }
    X = savitzkyGolay(x, dt, half, o.state_fit_order);
  }
  const std::vector<double> T = channelAt(log, "temperature", grid, false, gap);
  const std::vector<double> S = channelAt(log, "salinity", grid, false, gap);
  const std::vector<double> rhoC = channelAt(log, "density", grid, false, gap);
  const std::vector<double> pC = channelAt(log, "pressure", grid, false, gap);
  const std::vector<double> heading = channelAt(log, "heading", grid, false, gap);
  has_depth_ref_ = !pC.empty();

  grid_.resize(G);
  for (std::size_t i = 0; i < G; ++i) {
    GridState& g = grid_[i];
    g.u = u.value[i];
    g.A = X.d1[i];
    g.th = th.value[i];
    g.thdot = th.d1[i];
    g.ph = ph.value[i];
    g.phdot = ph.d1[i];
    g.rpm = rpm.value[i];
    g.elev_rad = el.value[i];
    g.th_front = tf.value.empty() ? 0.0 : tf.value[i];
    g.th_aft = ta.value.empty() ? 0.0 : ta.value[i];
    g.T = T.empty() || std::isnan(T[i]) ? v.hull.reference_temperature_degC : T[i];
    // Across a logger drop-out the resampled depth is NaN: no pressure there,
    // and the grid point is left out below (g.valid) instead of failing the log.
    g.p = !pC.empty() && std::isfinite(pC[i]) ? pC[i]
          : std::isfinite(zRaw[i])            ? seawater::pressureFromDepth(std::clamp(zRaw[i], 0.0, 10600.0), latitude_)
                                              : kNaN;
    g.rho = !rhoC.empty() && std::isfinite(rhoC[i]) ? rhoC[i] : kNaN;
    if (std::isnan(g.rho) && !T.empty() && !S.empty() && std::isfinite(T[i]) && std::isfinite(S[i])) {
      try {
        g.rho = seawater::density(S[i], T[i], std::max(0.0, g.p));
      } catch (const InputError&) {
      }
    }
    if (std::isnan(g.rho)) g.rho = kRhoRef;
    g.valid = true;
    for (double x : {g.u, g.A, g.th, g.thdot, g.ph, g.phdot, g.rpm, g.elev_rad, g.th_front, g.th_aft, g.p})
      g.valid = g.valid && std::isfinite(x);
  }

  analysis::SegmentOptions so;
  const analysis::Segmentation seg = analysis::detectSegments(log, so);
  const std::vector<double> since = sinceLastChange(log, {{"depth_cmd", 0.2}, {"prop_rpm", 10.0}, {"pitch_cmd", 2.0}}, grid);

  std::size_t phaseIdx = 0;
  int leg = -1;
  double lastCmd = kNaN;
  const std::vector<double> depthCmd = channelAt(log, "depth_cmd", grid, true, 1e9);
  const auto K = static_cast<std::size_t>(k_);
  for (std::size_t i = K; i + K < G; ++i) {
    bool ok = std::isfinite(zRaw[i]) && std::isfinite(pRaw[i]) && std::isfinite(rRaw[i]) && std::isfinite(uRaw[i]) &&
              zRaw[i] >= o.min_depth_m;
    for (std::size_t j = i - K; ok && j <= i + K; ++j) ok = grid_[j].valid;
    if (!ok) continue;
    // Legs: a depth command change starts a new unit of cross-validation.
    if (!depthCmd.empty() && std::isfinite(depthCmd[i]) && !(std::abs(depthCmd[i] - lastCmd) < 0.2)) {
      lastCmd = depthCmd[i];
      ++leg;
    }
    if (depthCmd.empty()) leg = static_cast<int>((grid[i] - grid.front()) / 600.0);  // 10-minute pieces
    rowGrid_.push_back(i);
    depthSensor_.push_back(zRaw[i]);
    zRef_.push_back(has_depth_ref_ && std::isfinite(pC[i])
                        ? seawater::depthFromPressure(std::clamp(pC[i], 0.0, 11000.0), latitude_)
                        : kNaN);
    table_.t.push_back(grid[i]);
    table_.block.push_back(std::max(leg, 0));
    table_.unit.push_back(std::max(leg, 0));
    while (phaseIdx + 1 < seg.phases.size() && seg.phases[phaseIdx].end_s < grid[i]) ++phaseIdx;
    Phase phase = Phase::kLevel;
    if (!seg.phases.empty()) {
      switch (seg.phases[phaseIdx].kind) {
        case analysis::SegmentKind::kSurface: phase = Phase::kSurface; break;
        case analysis::SegmentKind::kDive: phase = Phase::kDive; break;
        case analysis::SegmentKind::kClimb: phase = Phase::kClimb; break;
        default: phase = Phase::kLevel;
      }
    }
    if (!heading.empty() && std::isfinite(heading[i - 1]) && std::isfinite(heading[i + 1])) {
      double d = heading[i + 1] - heading[i - 1];
      d -= 360.0 * std::round(d / 360.0);
      if (std::abs(d / (2 * dt)) > 1.0) phase = Phase::kTurn;
    }
    const GridState& g = grid_[i];
    table_.phase.push_back(phase);
    table_.pressure_dbar.push_back(g.p);
    table_.temperature_degC.push_back(T.empty() ? kNaN : g.T);
    table_.speed_mps.push_back(g.u);
    table_.rpm.push_back(g.rpm);
    table_.pitch_deg.push_back(units::radToDeg(g.th));
    table_.since_actuator_s.push_back(since[i]);
    obs_depth_.push_back(zRaw[i]);
    obs_pitch_.push_back(units::degToRad(pRaw[i]));
    obs_roll_.push_back(units::degToRad(rRaw[i]));
    obs_speed_.push_back(uRaw[i]);
    obs_vv_.push_back(-(g.A - g.u * std::sin(g.th)));
  }
  if (rowGrid_.size() < 50)
    throw InputError("depth", "fewer than 50 usable samples below " + std::to_string(o.min_depth_m) + " m",
                     "a model check needs a submerged record of several minutes");
  // Renumber units densely; merge units too short to matter (< 30 rows) into the previous one.
  {
    int next = -1, last = -1;
    std::size_t count = 0;
    for (std::size_t i = 0; i < table_.unit.size(); ++i) {
      if (table_.unit[i] != last) {
        if (next < 0 || count >= 30) {
          ++next;
          count = 0;
        }
        last = table_.unit[i];
      }
      table_.unit[i] = next;
      table_.block[i] = next;
      ++count;
    }
  }
  t_ref_ = 0.5 * (table_.t.front() + table_.t.back());
  double sr = 0, sT = 0, sp = 0;
  for (std::size_t g : rowGrid_) {
    sr += grid_[g].rho;
    sT += grid_[g].T;
    sp += grid_[g].p;
  }
  const double n = static_cast<double>(rowGrid_.size());
  ref_rho_ = sr / n;
  ref_T_ = sT / n;
  ref_p_ = sp / n;
  eq_ = {Channel::kVerticalForce, Channel::kPitchMoment, Channel::kRollMoment, Channel::kSurgeForce};
  if (has_depth_ref_) eq_.push_back(Channel::kDepth);
  if (hasChannel(log, "temperature", 10) && hasChannel(log, "salinity", 10)) {
    water_ = sim::waterColumnFromLog(log, 1.0, latitude_);
  } else {
    water_ = sim::WaterColumn::uniform(ref_rho_, ref_T_);
    notes_.push_back("the log has no temperature and salinity: the replay flies in uniform water of the mean density");
  }
}

bool AuvCheckModel::applicable(std::size_t term) const {
  const PhysicsTerm& t = termLibrary()[term];
  if (!(t.families & kAuvFamily)) return false;
  if (t.id == "depth_sensor_offset") return has_depth_ref_;
  if (t.id == "quadratic_pitch_damping") return model_.hydro.Mqq_kgm2 != 0.0;
  if (t.id == "propeller_torque") return false;  // a calibration constant of the AUV, not missing physics
  for (const AuvCheckOptions::HeldTerm& h : opt_.held_terms)
    if (h.id == t.id) return false;  // calibrated by the analysis, held
  // A steady vertical current over a survey is not ocean physics; here it only stood in for the
  // calibrated groups (docs/decisions/model-check-selection.md).
  return t.id != "vertical_current";
}

void AuvCheckModel::equationError(const Params& prm, std::span<const std::uint32_t> rows, double* out) const {
  const TermValues tv = total(prm);
  const sim::VehicleLoading L = loading(prm);
  const sim::FlownMass fm = sim::flownMass(model_, L.extra_masses, std::nullopt, L.error, 0.0);
  const sim::VehicleModel cal = calibratedModel(prm);
  sim::Dynamics dyn(cal);
  dyn.setMassProperties(fm.mass_kg, fm.r_g_m, fm.extra_Ixx, fm.extra_Iyy);
  const Eigen::Vector4d M = dyn.massDiagonal();
  const std::size_t C = eq_.size();
  const sim::Propeller& prop = model_.prop;
  const HullModel& hull = model_.body.hull;
  const std::size_t G = grid_.size();
  const auto K = static_cast<std::size_t>(k_);
  // Grid points the requested rows need.
  std::vector<char> need(G, 0);
  for (std::uint32_t r : rows)
    for (std::size_t j = rowGrid_[r] - K; j <= rowGrid_[r] + K; ++j) need[j] = 1;
  // Velocities (heave, pitch, roll, surge) and model forces at each needed point.
  constexpr std::size_t D = 4;
  std::vector<double> vel(D * G, 0.0), force(D * G, 0.0), depthOffset(G, 0.0);
  for (std::size_t j = 0; j < G; ++j) {
    if (!need[j]) continue;
    const GridState& g = grid_[j];
    const double n = std::max(0.0, g.rpm) / 60.0;
    double kt = 1.0;
    if (g.u > 0.0 && n > 1e-9 && prop.KT0 > 0.0) {
      const double J = g.u * (1.0 - prop.wake_fraction) / (n * prop.diameter_m);
      kt = 1.0 - (prop.c2 == 1.0 ? J / prop.c1 : std::pow(J / prop.c1, prop.c2));
    }
    const double q0 = g.thdot / std::cos(g.ph);
    TermInputs in;
    in.hours_from_reference = (gridT_[j] - t_ref_) / 3600.0;
    in.pressure_dbar = g.p;
    in.temperature_degC = g.T;
    in.reference_temperature_degC = hull.reference_temperature_degC;
    in.prop_torque_basis = g.rpm * g.rpm * (g.rho / kRhoRef) * kt;
    // M_|q|q as the calibrated model has it: the replay and --accept scale that one.
    in.pitch_damping_basis = cal.hydro.Mqq_kgm2 * std::abs(q0) * q0;
    Effects e;
    applyEffects(tv, in, e);
    depthOffset[j] = e.depth_offset_m;

    const double th = g.th - e.pitch_bias_rad, ph = g.ph - e.roll_bias_rad;
    const double sth = std::sin(th), cth = std::cos(th), sph = std::sin(ph), cph = std::cos(ph);
    // z_dot through the water + u sin(true theta).
    const double A = g.A + e.vertical_current_mps + g.u * (sth - std::sin(g.th));
    const double w = A / (cth * cph);
    const double q = g.thdot / cph;
    const double p = g.phdot - q * sph * sth / cth;

    sim::StepInputs si;
    si.water_density_kgm3 = g.rho;
    si.weight_n = (fm.mass_kg + e.extra_mass_kg) * units::g0;
    si.buoyancy_n = g.rho * units::g0 * hull.volumeAt(g.T, g.p) * e.volume_factor;
    si.actuators.prop_rps = n;
    si.actuators.plane_rad = -g.elev_rad;  // log sign -> paper sign
    si.actuators.thruster_rpm[0] = g.th_front;
    si.actuators.thruster_rpm[1] = g.th_aft;
    si.external = sim::Force4(0.0, 0.0, e.pitch_moment_nm, e.roll_moment_nm);
    dyn.setStepInputs(si);
    sim::StateVector s;
    s << g.u, w, q, p, 0.0, 0.0, th, ph;
    const sim::StateVector d = dyn.derivative(s);
    vel[D * j] = w;
    vel[D * j + 1] = q;
    vel[D * j + 2] = p;
    vel[D * j + 3] = g.u;
    force[D * j] = M[1] * d[sim::kW];
    force[D * j + 1] = M[2] * d[sim::kQ];
    force[D * j + 2] = M[3] * d[sim::kP];
    force[D * j + 3] = M[0] * d[sim::kU];
  }
  const double span = 2.0 * static_cast<double>(K) * dt_;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const std::size_t i = rows[r];
    const std::size_t g = rowGrid_[i];
    double* o = out + r * C;
    constexpr Eigen::Index kMassIndex[D] = {1, 2, 3, 0};  // heave, pitch, roll, surge in M
    for (std::size_t c = 0; c < D; ++c) {
      // Momentum change over the window against the impulse of the model's force.
      double impulse = 0.0;
      for (std::size_t j = g - K; j < g + K; ++j) impulse += 0.5 * (force[D * j + c] + force[D * (j + 1) + c]) * dt_;
      o[c] = (M[kMassIndex[c]] * (vel[D * (g + K) + c] - vel[D * (g - K) + c]) - impulse) / span;
    }
    if (C == D + 1) o[D] = depthSensor_[i] - (zRef_[i] + depthOffset[g]);
  }
}

TermReplayOptions AuvCheckModel::replayOptions(const Params& p, double restart_every_s) const {
  TermReplayOptions o;
  o.drive = hasChannel(log_, "depth_cmd", 2)   ? sim::ReplayDrive::DepthCommands
            : hasChannel(log_, "pitch_cmd", 2) ? sim::ReplayDrive::PitchCommands
                                                : sim::ReplayDrive::Actuators;
  o.dt_s = opt_.replay_dt_s;
  o.loading = loading(p);
  o.mass_reference_time_s = t_ref_;
  o.restart_every_s = restart_every_s;
  o.surface_depth_m = opt_.min_depth_m;  // the rows the equation error leaves out as surface rows
  o.surface_model = true;
  return o;
}

void AuvCheckModel::replayError(const Params& p, double restart_every_s, double settle_s, std::vector<double>& out) const {
  const TermReplayTrace tr = termReplay(calibratedModel(p), autopilot_, water_, log_, simAdjustment(total(p)), table_.t,
                                        replayOptions(p, restart_every_s));
  const std::size_t N = rowGrid_.size();
  out.assign(5 * N, kNaN);
  // The replay settles after every (re)start: the log's start, a drop-out,
  // a surface interval and, for short horizons, every restart.
  for (std::size_t i = 0; i < N; ++i) {
    if (!(tr.since_start_s[i] >= settle_s)) continue;
    out[5 * i + 0] = obs_depth_[i] - tr.depth_m[i];
    out[5 * i + 1] = obs_pitch_[i] - tr.pitch_rad[i];
    out[5 * i + 2] = obs_roll_[i] - tr.roll_rad[i];
    out[5 * i + 3] = obs_speed_[i] - tr.speed_mps[i];
    out[5 * i + 4] = obs_vv_[i] - tr.vertical_velocity_mps[i];
  }
}

void AuvCheckModel::simulationError(const Params& p, std::vector<double>& out) const {
  replayError(p, 0.0, opt_.settle_s, out);
}

// Measured on drawn truths (model_check_truths_bench): a whole-log replay
// driven by the logged depth commands scored the true vehicle (quadratic
// pitch damping included) worse than the fitted base without it (depth 0.072
// against 0.058 m^2 on truth 700): the replayed autopilot does not meet the
// noise the real one steered on, and an oscillation flown out of phase costs
// twice. Short horizons keep a damping's effect and drop the drift, so a
// transient term the whole-log test refuses is judged again here; slow terms
// (mass drift, currents) stay on the whole log, where short horizons lost
// them (mass drift 4 -> 3 of 6, a vertical current on a control).
void AuvCheckModel::shortHorizonSimulationError(const Params& p, std::vector<double>& out) const {
  replayError(p, opt_.short_horizon_s, opt_.short_settle_s, out);
}

std::optional<ReferenceWater> AuvCheckModel::referenceWater() const {
  return opt_.report_water ? *opt_.report_water : ReferenceWater{ref_rho_, ref_T_, ref_p_};
}

double AuvCheckModel::netBuoyancyKg(const Params& p) const {
  const sim::VehicleLoading L = loading(p);
  const sim::FlownMass fm = sim::flownMass(model_, L.extra_masses, std::nullopt, L.error, 0.0);
  const ReferenceWater w = *referenceWater();
  TermInputs in;
  in.pressure_dbar = w.pressure_dbar;
  in.temperature_degC = w.temperature_degC;
  in.reference_temperature_degC = model_.body.hull.reference_temperature_degC;
  Effects e;
  applyEffects(total(p), in, e);
  const double B = w.density_kgm3 * model_.body.hull.volumeAt(w.temperature_degC, w.pressure_dbar) * e.volume_factor;
  return B - fm.mass_kg;
}

double AuvCheckModel::cgX(const Params& p) const {
  const sim::VehicleLoading L = loading(p);
  return sim::flownMass(model_, L.extra_masses, std::nullopt, L.error, 0.0).r_g_m.x();
}

double AuvCheckModel::cgY(const Params& p) const {
  const sim::VehicleLoading L = loading(p);
  return sim::flownMass(model_, L.extra_masses, std::nullopt, L.error, 0.0).r_g_m.y();
}

Message AuvCheckModel::description() const { return Message(msg::kModelAuv); }

}  // namespace auv::discrepancy
