#include "discrepancy/glider_check_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/mission_analysis.h"
#include "analysis/segments.h"
#include "analysis/series_tools.h"
#include "common/input_error.h"
#include "common/units.h"
#include "discrepancy/check_messages.h"
#include "discrepancy/log_features.h"
#include "seawater/seawater.h"

namespace auv::discrepancy {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kStep = 0.05 * std::numbers::pi / 180.0;
constexpr double kLo = 0.5 * std::numbers::pi / 180.0;
constexpr double kHi = 85.0 * std::numbers::pi / 180.0;

// Samples whose mean vertical speed over `window_s` around them is below
// `min_rate`: the glider hovers (a stall) and is not gliding. The 20 s rate
// of a slow glide dips below that often in internal waves; a 300 s mean
// does not, unless the glider has stopped.
std::vector<bool> stalledSamples(const TimeSeries& obs, double window_s, double min_rate) {
  std::vector<bool> out(obs.size(), false);
  if (!(window_s > 0.0)) return out;
  std::size_t a = 0, b = 0;
  for (std::size_t i = 0; i < obs.size(); ++i) {
    while (obs.t[i] - obs.t[a] > 0.5 * window_s) ++a;
    while (b + 1 < obs.size() && obs.t[b + 1] - obs.t[i] <= 0.5 * window_s) ++b;
    const double dt = obs.t[b] - obs.t[a];
    if (dt < 0.5 * window_s || std::isnan(obs.v[a]) || std::isnan(obs.v[b])) continue;
    out[i] = std::abs(obs.v[b] - obs.v[a]) / dt < min_rate;  // dbar ~ m
  }
  return out;
}

}  // namespace

// alpha(|theta|) tabulated per Cd0; the fits evaluate thousands of samples
// for each of a few Cd0 values at a time.
class GliderCheckModel::AlphaCache {
 public:
  explicit AlphaCache(const analysis::GliderFlightConstants& c) : c_(c) {
    c_.pitch_scale = 1.0;
    c_.pitch_offset_rad = 0.0;
  }
  // Keyed on the drag coefficient and the lift slope (both may be fitted).
  const std::vector<double>& table(double Cd0, double a) const {
    for (auto& e : entries_)
      if (e.Cd0 == Cd0 && e.a == a) return e.alpha;
    if (entries_.size() >= 12) entries_.erase(entries_.begin());
    analysis::GliderFlightConstants c = c_;
    c.lift_slope_per_rad = a;
    const auto n = static_cast<std::size_t>((kHi - kLo) / kStep) + 2;
    std::vector<double> t(n);
    t[0] = analysis::steadyAngleOfAttack(c, kLo, Cd0);
    for (std::size_t i = 1; i < n; ++i) t[i] = analysis::steadyAngleOfAttackNear(c, kLo + static_cast<double>(i) * kStep, Cd0, t[i - 1]);
    entries_.push_back({Cd0, a, std::move(t)});
    return entries_.back().alpha;
  }
  double alphaAbs(const std::vector<double>& t, double Cd0, double a, double phi) const {
    const double x = (phi - kLo) / kStep;
    if (!(x >= 0.0) || x >= static_cast<double>(t.size() - 1)) {
      analysis::GliderFlightConstants c = c_;
      c.lift_slope_per_rad = a;
      return analysis::steadyAngleOfAttack(c, phi, Cd0);
    }
    const auto i = static_cast<std::size_t>(x);
    const double f = x - static_cast<double>(i);
    return t[i] + f * (t[i + 1] - t[i]);
  }

 private:
  analysis::GliderFlightConstants c_;
  struct Entry {
    double Cd0, a;
    std::vector<double> alpha;
  };
  mutable std::vector<Entry> entries_;
};

GliderCheckModel::~GliderCheckModel() = default;

GliderCheckModel::GliderCheckModel(const MissionLog& log, const VehicleProfile& v, const GliderCheckOptions& o) {
  latitude_ = analysis::latitudeFromMetadata(log).value_or(seawater::kDefaultLatitude_deg);
  std::vector<Message> cnotes;
  c_ = analysis::gliderConstantsFromProfile(v, cnotes);
  // The check decides whether the log needs a compressibility: 0 stays 0.
  c_.compressibility_per_dbar = v.hull.compressibility_per_dbar;
  if (v.sections.contains("flight_model") && v.sections["flight_model"].contains("compressibility_per_dbar"))
    c_.compressibility_per_dbar = v.sections["flight_model"]["compressibility_per_dbar"].get<double>();
  for (const auto& n : cnotes)
    if (n.find("compressibility") == std::string::npos) notes_.push_back(n);
  baseline_ = acceptedTermsFromProfile(v.sections, v.file);
  alpha_ = std::make_unique<AlphaCache>(c_);

  if (!hasChannel(log, "pitch", 10)) throw InputError("pitch", "the log has no pitch channel", "a glider model check needs pitch");
  if (!hasChannel(log, "pump_volume", 10))
    throw InputError("pump_volume", "the log has no pump_volume channel (the buoyancy engine)",
                     "a glider model check needs the buoyancy engine's volume");
  const bool hasP = hasChannel(log, "pressure", 10), hasZ = hasChannel(log, "depth", 10);
  if (!hasP && !hasZ) throw InputError("depth", "the log has neither depth nor pressure", "log depth or CTD pressure");

  analysis::SegmentOptions so;
  so.glider = true;
  so.level_rate_mps = o.glide_end_rate_mps;
  so.dive_rate_mps = o.glide_start_rate_mps;
  const analysis::Segmentation seg = analysis::detectSegments(log, so);
  const auto& win = seg.operating;
  if (win.empty()) throw InputError("depth", "no steady dive or climb was found in the log", "check the depth channel");

  const bool usePressure = hasP && (!hasZ || log.find("pressure")->validCount() >= log.find("depth")->validCount());
  obs_channel_ = usePressure ? "pressure" : "depth";
  const TimeSeries obs = log.series(obs_channel_);
  const std::vector<double> rate = analysis::localRate(obs, o.rate_window_s, so.max_gap_s, 1.0);

  const std::vector<bool> stalled = stalledSamples(obs, o.stall_window_s, o.glide_end_rate_mps);
  // Observation samples inside glides, with their window.
  std::vector<double> times;
  std::vector<std::size_t> obsIndex, winIndex;
  {
    std::size_t w = 0;
    for (std::size_t i = 0; i < obs.size(); ++i) {
      while (w < win.size() && win[w].end_s < obs.t[i]) ++w;
      if (w == win.size()) break;
      if (obs.t[i] < win[w].start_s || std::isnan(rate[i])) continue;
      if (stalled[i]) continue;
      times.push_back(obs.t[i]);
      obsIndex.push_back(i);
      winIndex.push_back(w);
    }
  }
  const double gap = 60.0;
  const std::vector<double> pitch = channelAt(log, "pitch", times, false, gap);
  const std::vector<double> pump = channelAt(log, "pump_volume", times, false, gap);
  const std::vector<double> rhoC = channelAt(log, "density", times, false, gap);
  const std::vector<double> TC = channelAt(log, "temperature", times, false, gap);
  const std::vector<double> SC = channelAt(log, "salinity", times, false, gap);
  const std::vector<double> pC = hasP ? channelAt(log, "pressure", times, false, gap) : std::vector<double>{};
  const std::vector<double> zC = hasZ ? channelAt(log, "depth", times, false, gap) : std::vector<double>{};
  const std::vector<double> speed = channelAt(log, "speed", times, false, gap);
  const std::vector<double> roll = channelAt(log, "roll", times, false, gap);
  std::size_t rolled = 0;
  has_depth_ref_ = hasP && hasZ;
  if (!hasChannel(log, "density", 10) && !(hasChannel(log, "temperature", 10) && hasChannel(log, "salinity", 10)))
    notes_.push_back("the log has no density (nor temperature and salinity): " + std::to_string(o.default_density_kgm3) +
                     " kg/m3 assumed");

  const double minPitch = units::degToRad(o.min_pitch_deg);
  std::vector<std::size_t> keep;
  std::vector<Row> rows;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double x = obs.v[obsIndex[k]];
    Row r{};
    r.p = usePressure ? x : (hasP && !std::isnan(pC[k]) ? pC[k] : seawater::pressureFromDepth(std::clamp(x, 0.0, 10600.0), latitude_));
    if (!std::isfinite(r.p)) continue;
    r.z_ref = hasP ? seawater::depthFromPressure(std::clamp(hasP && !usePressure ? pC[k] : x, 0.0, 11000.0), latitude_) : x;
    if (!(r.z_ref >= o.min_depth_m && r.z_ref <= o.max_depth_m)) continue;
    r.pitch_rad = c_.pitch_scale * units::degToRad(pitch[k]) + c_.pitch_offset_rad;
    const bool dive = win[winIndex[k]].phase == analysis::SegmentKind::kDive;
    if (!(std::abs(r.pitch_rad) >= minPitch) || dive != (r.pitch_rad < 0)) continue;
    if (!roll.empty() && std::isfinite(roll[k]) && std::abs(roll[k]) > o.max_roll_deg) {
      ++rolled;
      continue;
    }
    r.pump_m3 = pump[k] * 1e-6;
    r.T = TC.empty() ? c_.reference_temperature_degC : TC[k];
    r.rho = !rhoC.empty() && std::isfinite(rhoC[k]) ? rhoC[k] : kNaN;
    if (std::isnan(r.rho) && !TC.empty() && !SC.empty() && std::isfinite(TC[k]) && std::isfinite(SC[k])) {
      try {
        r.rho = seawater::density(SC[k], TC[k], std::max(0.0, r.p));
      } catch (const InputError&) {
      }
    }
    if (std::isnan(r.rho) && rhoC.empty() && (TC.empty() || SC.empty())) r.rho = o.default_density_kgm3;
    if (!(r.rho > 900.0) || std::isnan(r.pump_m3) || std::isnan(r.T)) continue;
    r.w_obs = usePressure ? -rate[obsIndex[k]] * 1e4 / (r.rho * units::g0) : -rate[obsIndex[k]];
    r.depth_sensor = has_depth_ref_ ? zC[k] : kNaN;
    keep.push_back(k);
    rows.push_back(r);
  }
  if (rows.size() < 20)
    throw InputError(obs_channel_, "fewer than 20 steady-glide samples deeper than " + std::to_string(o.min_depth_m) + " m",
                     "a model check needs several dives and climbs");
  const std::size_t stride = std::max<std::size_t>(1, (rows.size() + o.max_rows - 1) / std::max<std::size_t>(1, o.max_rows));
  std::vector<double> rowTimes;
  for (std::size_t j = 0; j < rows.size(); j += stride) {
    rows_.push_back(rows[j]);
    rowTimes.push_back(times[keep[j]]);
    const std::size_t k = keep[j];
    table_.block.push_back(static_cast<int>(winIndex[k]));
    table_.phase.push_back(win[winIndex[k]].phase == analysis::SegmentKind::kDive ? Phase::kDive : Phase::kClimb);
    table_.speed_mps.push_back(speed.empty() ? kNaN : speed[k]);
  }
  table_.t = rowTimes;
  // Cross-validation units: a yo is a dive and the climb after it. With
  // too few yos, pieces of the glides instead (each half of the data then
  // still holds dives and climbs).
  {
    // A dive split in two (it slowed, then sped up again) is still one yo.
    int yo = -1;
    int lastBlock = -1;
    bool lastDive = false;
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      const int b = table_.block[i];
      const bool dive = table_.phase[i] == Phase::kDive;
      if (b != lastBlock && ((dive && !lastDive) || yo < 0)) ++yo;
      lastBlock = b;
      lastDive = dive;
      table_.unit.push_back(yo);
    }
    if (yo + 1 < o.min_yos_for_yo_units) {
      int piece = -1;
      double start = 0.0;
      for (std::size_t i = 0; i < rows_.size(); ++i) {
        if (i == 0 || table_.block[i] != table_.block[i - 1] || rowTimes[i] - start >= o.piece_s) {
          ++piece;
          start = rowTimes[i];
        }
        table_.unit[i] = piece;
      }
      notes_.push_back("only " + std::to_string(yo + 1) + " yo(s): cross-validation over " +
                       std::to_string(static_cast<int>(o.piece_s / 60.0)) + "-minute pieces of the glides");
    }
  }
  table_.pressure_dbar.resize(rows_.size());
  table_.temperature_degC.resize(rows_.size());
  table_.pitch_deg.resize(rows_.size());
  table_.rpm.assign(rows_.size(), kNaN);
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    table_.pressure_dbar[i] = rows_[i].p;
    table_.temperature_degC[i] = TC.empty() ? kNaN : rows_[i].T;
    table_.pitch_deg[i] = units::radToDeg(rows_[i].pitch_rad);
  }
  table_.since_actuator_s =
      sinceLastChange(log, {{"pump_volume_cmd", 1.0}, {"battery_position_cmd", 0.5}, {"pitch_cmd", 0.5}}, rowTimes);
  {
    std::size_t b0 = 0;
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      if (i == 0 || table_.block[i] != table_.block[i - 1]) b0 = i;
      if (std::isnan(table_.since_actuator_s[i])) table_.since_actuator_s[i] = rowTimes[i] - rowTimes[b0];
    }
  }
  {
    // The lift slope is fitted only when the glides span enough pitch: with
    // one pitch it trades off exactly against Cd0 and the volume.
    std::vector<double> ph;
    for (const Row& r : rows_) ph.push_back(std::abs(r.pitch_rad));
    std::sort(ph.begin(), ph.end());
    const double spread = ph[ph.size() * 9 / 10] - ph[ph.size() / 10];
    fit_lift_ = o.fit_lift_slope && spread >= units::degToRad(o.lift_slope_min_pitch_spread_deg);
    notes_.push_back(fit_lift_ ? "lift slope fitted with the ballast state (pitch spread " +
                                     std::to_string(static_cast<int>(std::lround(units::radToDeg(spread)))) + " deg)"
                               : "lift slope held at the profile's value (the glides span only " +
                                     std::to_string(static_cast<int>(std::lround(units::radToDeg(spread)))) + " deg of pitch)");
  }
  t_ref_ = 0.5 * (rowTimes.front() + rowTimes.back());
  t_end_ = log.time.empty() ? rowTimes.back() : log.time.back();
  double sr = 0, sp = 0, sT = 0;
  for (const Row& r : rows_) {
    sr += r.rho;
    sp += r.p;
    sT += r.T;
  }
  const double n = static_cast<double>(rows_.size());
  ref_ = {sr / n, sp / n, sT / n};
  if (rolled > 0)
    notes_.push_back(std::to_string(rolled) + " samples banked beyond " + std::to_string(static_cast<int>(o.max_roll_deg)) +
                     " deg of roll (turns) were left out: the steady glide is 2-D");
  if (!has_depth_ref_)
    notes_.push_back(hasP ? "no separate depth sensor: depth_sensor_offset cannot be checked"
                          : "no CTD pressure besides the depth sensor: depth_sensor_offset cannot be checked");
}

double GliderCheckModel::volumeFactor(const TermValues& terms, double p_dbar, double T, double hours) const {
  TermInputs in;
  in.hours_from_reference = hours;
  in.pressure_dbar = p_dbar;
  in.temperature_degC = T;
  in.reference_temperature_degC = c_.reference_temperature_degC;
  Effects e;
  applyEffects(terms, in, e);
  return (1.0 - c_.compressibility_per_dbar * p_dbar) *
         (1.0 + c_.thermal_expansion_per_degC * (T - c_.reference_temperature_degC)) * e.volume_factor;
}

GliderCheckModel::Prepared GliderCheckModel::prepare(const Params& p) const {
  Prepared q;
  q.terms = baseline_;
  for (std::size_t k = 0; k < kTermCount; ++k) q.terms[k] += p.terms[k];
  q.Cd0 = p.nuisance[1];
  // V0 such that the net buoyancy at the reference state is nb, whatever
  // the terms do to the volume there.
  q.V0 = (c_.mass_kg + p.nuisance[0]) /
         (ref_.density_kgm3 * volumeFactor(q.terms, ref_.pressure_dbar, ref_.temperature_degC, 0.0));
  q.lift_scale = fit_lift_ ? p.nuisance[2] : 1.0;
  q.a = c_.lift_slope_per_rad * q.lift_scale;
  if (c_.form == analysis::GlideForm::kSlocum) q.alpha = &alpha_->table(q.Cd0, q.a);
  return q;
}

double GliderCheckModel::rowW(const Prepared& q, std::size_t i, double p_dbar, Effects& e) const {
  const Row& r = rows_[i];
  TermInputs in;
  in.hours_from_reference = (table_.t[i] - t_ref_) / 3600.0;
  in.pressure_dbar = p_dbar;
  in.temperature_degC = r.T;
  in.reference_temperature_degC = c_.reference_temperature_degC;
  e = Effects{};
  applyEffects(q.terms, in, e);
  const double th = r.pitch_rad - e.pitch_bias_rad;
  if (c_.form == analysis::GlideForm::kSeaglider) {
    const double f = (1.0 - c_.compressibility_per_dbar * p_dbar) *
                     (1.0 + c_.thermal_expansion_per_degC * (r.T - c_.reference_temperature_degC)) * e.volume_factor;
    const double FB = units::g0 * (r.rho * (q.V0 * f + r.pump_m3) - (c_.mass_kg + e.extra_mass_kg));
    analysis::GliderFlightConstants c = c_;
    c.hd_a_per_deg *= q.lift_scale;
    return analysis::seagliderVerticalSpeed(c, FB, th, q.Cd0) + e.vertical_current_mps;
  }
  const double a = std::copysign(alpha_->alphaAbs(*q.alpha, q.Cd0, q.a, std::abs(th)), th);
  const double path = th + a;
  const double f = (1.0 - c_.compressibility_per_dbar * p_dbar) *
                   (1.0 + c_.thermal_expansion_per_degC * (r.T - c_.reference_temperature_degC)) * e.volume_factor;
  const double FB = units::g0 * (r.rho * (q.V0 * f + r.pump_m3) - (c_.mass_kg + e.extra_mass_kg));
  const double U2 = 2.0 * FB * std::sin(path) / (r.rho * c_.wing_area_m2 * (q.Cd0 + c_.induced_drag_per_rad2 * a * a));
  const double w = U2 > 0.0 ? std::sqrt(U2) * std::sin(path) : 0.0;
  return w + e.vertical_current_mps;
}

double GliderCheckModel::massChangeAtEndKg(const Params& p) const {
  TermValues terms = baseline_;
  for (std::size_t k = 0; k < kTermCount; ++k) terms[k] += p.terms[k];
  TermInputs in;
  in.hours_from_reference = hoursFromReferenceToEnd();
  in.reference_temperature_degC = c_.reference_temperature_degC;
  Effects e;
  applyEffects(terms, in, e);
  return e.extra_mass_kg;
}

double GliderCheckModel::hullVolumeM3(const Params& p) const { return prepare(p).V0; }

double GliderCheckModel::massToAddKg(const Params& p, const analysis::GliderTarget& t) const {
  const Prepared q = prepare(p);
  const double V = q.V0 * volumeFactor(q.terms, t.pressure_dbar, t.temperature_degC, 0.0);
  return t.density_kgm3 * V - (c_.mass_kg + massChangeAtEndKg(p));
}

double GliderCheckModel::modelW(const Params& p, std::size_t i, double p_dbar) const {
  Effects e;
  return rowW(prepare(p), i, p_dbar, e);
}

Eigen::VectorXd GliderCheckModel::nuisanceStart() const {
  // Coarse scan so that the fit starts on the right side of the sign change
  // (with the wrong sign the model cannot glide and the cost is flat).
  const std::size_t stride = std::max<std::size_t>(1, rows_.size() / 3000);
  const Eigen::Index n = fit_lift_ ? 3 : 2;
  Params p;
  p.nuisance = Eigen::VectorXd::Ones(n);
  double best = std::numeric_limits<double>::infinity();
  Eigen::VectorXd bestX = p.nuisance;
  for (double Cd0 : {0.005, 0.01, 0.02, 0.04, 0.08, 0.15, 0.3, 0.6, c_.drag_start}) {
    for (double nb = -1.5; nb <= 1.5 + 1e-9; nb += 0.025) {
      p.nuisance[0] = nb;
      p.nuisance[1] = Cd0;
      double ss = 0.0;
      const Prepared q = prepare(p);
      Effects e;
      for (std::size_t i = 0; i < rows_.size(); i += stride) {
        const double r = rows_[i].w_obs - rowW(q, i, rows_[i].p, e);
        ss += r * r;
      }
      if (ss < best) {
        best = ss;
        bestX = p.nuisance;
      }
    }
  }
  return bestX;
}

std::vector<std::string> GliderCheckModel::nuisanceNames() const {
  if (fit_lift_) return {"net_buoyancy_kg", "Cd0", "lift_slope_scale"};
  return {"net_buoyancy_kg", "Cd0"};
}
Eigen::VectorXd GliderCheckModel::nuisanceScale() const {
  return fit_lift_ ? Eigen::VectorXd(Eigen::Vector3d(0.01, 0.01, 0.01)) : Eigen::VectorXd(Eigen::Vector2d(0.01, 0.01));
}
Eigen::VectorXd GliderCheckModel::nuisanceLower() const {
  return fit_lift_ ? Eigen::VectorXd(Eigen::Vector3d(-5.0, 1e-3, 0.5)) : Eigen::VectorXd(Eigen::Vector2d(-5.0, 1e-3));
}
Eigen::VectorXd GliderCheckModel::nuisanceUpper() const {
  return fit_lift_ ? Eigen::VectorXd(Eigen::Vector3d(5.0, 3.0, 2.0)) : Eigen::VectorXd(Eigen::Vector2d(5.0, 3.0));
}

bool GliderCheckModel::applicable(std::size_t term) const {
  const PhysicsTerm& t = termLibrary()[term];
  if (!(t.families & kGliderFamily)) return false;
  if (t.id == "depth_sensor_offset") return has_depth_ref_;
  return true;
}

std::vector<Channel> GliderCheckModel::equationChannels() const {
  if (has_depth_ref_) return {Channel::kVerticalVelocity, Channel::kDepth};
  return {Channel::kVerticalVelocity};
}

void GliderCheckModel::equationError(const Params& p, std::span<const std::uint32_t> rows, double* out) const {
  const std::size_t C = has_depth_ref_ ? 2 : 1;
  const Prepared q = prepare(p);
  Effects e;
  for (std::size_t j = 0; j < rows.size(); ++j) {
    const std::size_t i = rows[j];
    const Row& r = rows_[i];
    out[j * C] = r.w_obs - rowW(q, i, r.p, e);
    if (C == 2) out[j * C + 1] = r.depth_sensor - (r.z_ref + e.depth_offset_m);
  }
}

std::vector<Channel> GliderCheckModel::simulationChannels() const { return {Channel::kDepth, Channel::kVerticalVelocity}; }

void GliderCheckModel::simulationError(const Params& p, std::vector<double>& out) const {
  const Prepared q = prepare(p);
  Effects e;
  const std::size_t n = rows_.size();
  out.assign(2 * n, kNaN);
  // Each glide is flown from its first sample with the model's vertical
  // velocity (pressure from the simulated depth). Its starting depth is
  // then fitted to the CTD depth over the glide (output-error simulation
  // with an estimated initial state): the water's own vertical motion makes
  // a free run wander by metres, which would otherwise drown a sensor
  // offset of decimetres in the depth channel.
  std::vector<double> path(n), offset(n);
  std::size_t b0 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (i == 0 || table_.block[i] != table_.block[i - 1]) b0 = i;
    const double z = i == b0 ? rows_[i].z_ref : path[i];
    path[i] = z;
    const double pd = seawater::pressureFromDepth(std::clamp(z, 0.0, 10600.0), latitude_);
    const double w = rowW(q, i, pd, e);
    offset[i] = e.depth_offset_m;
    out[2 * i + 1] = rows_[i].w_obs - w;
    if (i + 1 < n && table_.block[i + 1] == table_.block[i]) path[i + 1] = z - w * (table_.t[i + 1] - table_.t[i]);
    if (i + 1 == n || table_.block[i + 1] != table_.block[i]) {
      double shift = 0.0;
      for (std::size_t k = b0; k <= i; ++k) shift += rows_[k].z_ref - path[k];
      shift /= static_cast<double>(i - b0 + 1);
      for (std::size_t k = b0; k <= i; ++k) {
        const double observed = has_depth_ref_ ? rows_[k].depth_sensor : rows_[k].z_ref;
        out[2 * k] = observed - (path[k] + shift + (has_depth_ref_ ? offset[k] : 0.0));
      }
    }
  }
}

Message GliderCheckModel::description() const {
  return Message(fit_lift_ ? msg::kModelGliderLift : msg::kModelGlider, {obs_channel_});
}

}  // namespace auv::discrepancy
