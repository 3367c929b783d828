#include "analysis/mission_analysis.h"

#include "analysis/analysis_messages.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "analysis/auv_steady_model.h"
#include "analysis/averaged_legs.h"
#include "analysis/flight_envelope.h"
#include "analysis/hull_law_levers.h"
#include "analysis/auv_transient_fit.h"
#include "analysis/transient_replay.h"
#include "analysis/auv_trim_estimation.h"
#include "analysis/classic_thesis.h"
#include "analysis/glider_trim.h"
#include "analysis/profile_constants.h"
#include "analysis/series_tools.h"
#include "analysis/statistics.h"
#include "analysis/steady_segment_json.h"
#include "analysis/water_at_depth.h"
#include "analysis/window_samples.h"
#include "common/input_error.h"
#include "common/units.h"
#include "seawater/seawater.h"
#include "sim/model_loader.h"
#include "vehicle/json_reader.h"
#include "vehicle/installed_check.h"

namespace auv::analysis {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string fmt(const char* f, double v) {
  char buf[128];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// Per-window and overall accumulators for one quantity; the overall one
// starts a new block at every window so no lag pair spans two windows.
struct WindowStats {
  std::vector<MeanAccumulator> per;
  MeanAccumulator all;
  std::size_t last = static_cast<std::size_t>(-1);
  explicit WindowStats(std::size_t n) : per(n) {}
  // in_all = false: the window's own mean only (an AUV's steady dive or
  // climb estimates the trim but is not "at steady depth").
  void add(std::size_t w, double x, bool in_all = true) {
    if (std::isnan(x)) return;
    if (!in_all) {
      per[w].add(x);
      return;
    }
    if (w != last) {
      all.endBlock();
      last = w;
    }
    per[w].add(x);
    all.add(x);
  }
  MeanEstimate at(std::size_t w) const { return per[w].result(); }
};

void simpleStats(const MissionLog& log, const char* channel, const std::vector<Segment>& win, WindowStats& st) {
  if (!log.has(channel)) return;
  const TimeSeries s = log.series(channel);
  forEachInWindows(s, win, [&](std::size_t w, double, double v) { st.add(w, v); });
}

// Per window: the largest mean |rpm| of the tunnel-thruster channels when it
// is above the thrusters' deadband (the profile's, 0 without a simulator
// model), else 0.
std::vector<double> thrusterRpmAboveDeadband(const MissionLog& log, const VehicleProfile& v,
                                             const std::vector<Segment>& win) {
  std::vector<double> out(win.size(), 0.0);
  const char* channels[] = {"thruster_front_rpm", "thruster_aft_rpm"};
  if (!hasSamples(log, channels[0]) && !hasSamples(log, channels[1])) return out;
  double deadband = 0.0;  // without simulator sections any running thruster counts
  if (const auto m = simModelFromProfile(v))
    for (int i = 0; i < m->thruster_count; ++i) deadband = std::max(deadband, m->thrusters[static_cast<std::size_t>(i)].deadband_rpm);
  for (const char* c : channels) {
    if (!hasSamples(log, c)) continue;
    std::vector<double> sum(win.size(), 0.0), n(win.size(), 0.0);
    forEachInWindows(log.series(c), win, [&](std::size_t w, double, double x) {
      if (std::isnan(x)) return;
      sum[w] += std::abs(x);
      n[w] += 1.0;
    });
    for (std::size_t w = 0; w < win.size(); ++w)
      if (n[w] > 0 && sum[w] / n[w] > deadband) out[w] = std::max(out[w], sum[w] / n[w]);
  }
  return out;
}

nlohmann::json numOrNull(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

AnalysisReport detail::analyzeRecordedLog(const MissionLog& log, const VehicleProfile& v, const AnalysisOptions& o) {
  AnalysisReport rep;
  rep.vehicle_id = v.id;
  rep.vehicle_kind = v.kind;
  rep.log_name = o.log_name;
  rep.rows = log.rowCount();
  rep.duration_s = log.duration();
  const bool glider = v.kind == "glider";
  if (!o.installed_kg.empty()) checkInstalledKg(v, o.installed_kg, "installed");
  const double latitude = latitudeFromMetadata(log).value_or(seawater::kDefaultLatitude_deg);

  SegmentOptions so = o.segments;
  so.glider = glider;
  Segmentation seg = detectSegments(log, so);
  for (const Message& n : seg.notes) rep.notes.push_back(n);
  const std::vector<Segment>& win = seg.operating;
  const TimeSeries depth = depthSeries(log, latitude);
  const FlightEnvelope envelope = glider ? FlightEnvelope{} : flightEnvelope(log, depth, seg.command_cuts, win, so);
  if (!glider) reportFlightEnvelope(envelope, rep);
  // A porpoising vehicle's dives and climbs join legs the steady balance
  // only approximates (cycle means of a limit cycle): identification truth
  // 2148 put its two dives 1.3 kg above its level legs, and the estimate
  // moved 0.4 kg away from the truth with them. Its legs stand alone,
  // and its glides only where there is nothing else.
  const bool has_legs = std::any_of(win.begin(), win.end(), [](const Segment& s) { return s.kind != SegmentKind::kGlide; });
  if (envelope.porpoising && has_legs)
    std::erase_if(seg.operating, [](const Segment& s) { return s.kind == SegmentKind::kGlide; });
  if (win.empty())
    rep.warnings.push_back(glider ? Message(msg::kNoSteadyGlide) : Message(msg::kNoSteadyLevel, {fmt("%.0f", so.min_steady_s)}));
  const std::size_t nw = win.size();
  // Where the replay of the transients is not trusted (see below).
  const bool replay_unfit = envelope.too_light.has_value() || envelope.porpoising.has_value();

  // --- per-window statistics, one channel at a time --------------------------
  WindowStats zS(nw), zRate(nw), dErr(nw), pitch(nw), pErr(nw), roll(nw), speed(nw), rpm(nw), elev(nw);
  const TimeSeries depthRate{depth.t, localRate(depth, so.rate_window_s, so.max_gap_s)};
  const TimeSeries depthRateFast{depth.t, localRate(depth, so.cycle_rate_window_s, so.max_gap_s)};
  // An AUV's steady dives and climbs (averaged_legs.h) feed the estimation,
  // not the depth and pitch errors at steady depth.
  auto atDepth = [&](std::size_t w) { return glider || win[w].kind != SegmentKind::kGlide; };
  {
    std::size_t i = 0;
    forEachInWindows(depth, win, [&](std::size_t w, double t, double z) {
      while (depth.t[i] < t) ++i;
      zS.add(w, z, atDepth(w));
      zRate.add(w, depthRate.v[i], atDepth(w));
    });
  }
  const bool hasDepthCmd = hasSamples(log, "depth_cmd");
  if (hasDepthCmd) {
    const TimeSeries c = log.series("depth_cmd");
    SeriesCursor cur(c, true, kInf);
    forEachInWindows(depth, win, [&](std::size_t w, double t, double z) { dErr.add(w, cur.at(t) - z, atDepth(w)); });
  }
  const bool hasPitchCmd = hasSamples(log, "pitch_cmd");
  if (hasSamples(log, "pitch")) {
    const TimeSeries p = log.series("pitch");
    const TimeSeries c = hasPitchCmd ? log.series("pitch_cmd") : TimeSeries{};
    SeriesCursor cur(c, true, kInf);
    forEachInWindows(p, win, [&](std::size_t w, double t, double x) {
      pitch.add(w, x, atDepth(w));
      if (!hasPitchCmd) return;
      const double cmd = cur.at(t);
      // A glider's pitch command belongs to one phase (dive < 0, climb > 0).
      if (glider && !((win[w].phase == SegmentKind::kDive && cmd < 0) || (win[w].phase == SegmentKind::kClimb && cmd > 0)))
        return;
      pErr.add(w, x - cmd, atDepth(w));
    });
  }
  simpleStats(log, "roll", win, roll);
  simpleStats(log, "speed", win, speed);
  simpleStats(log, "prop_rpm", win, rpm);
  simpleStats(log, "elevator", win, elev);

  rep.depth_m = glider ? MeanEstimate{} : zS.all.result();
  rep.depth_error_m = dErr.all.result();
  rep.roll_deg = roll.all.result();
  rep.pitch_at_steady_depth_deg = glider ? MeanEstimate{} : pitch.all.result();
  if (hasPitchCmd) {
    rep.pitch_error_deg = pErr.all.result();
    rep.pitch_error_basis = Message(glider ? msg::kPitchBasisGlide : msg::kPitchBasisLevel);
  } else if (!glider) {
    rep.pitch_error_deg = rep.pitch_at_steady_depth_deg;
    rep.pitch_error_basis = Message(msg::kPitchBasisNoCommand);
  }
  if (!hasDepthCmd && !glider) rep.warnings.push_back(Message(msg::kNoDepthCommand));

  // --- water at operating depth ------------------------------------------------
  std::vector<Segment> waterWin = win;
  double waterMinDepth = -kInf;
  if (glider || win.empty()) {
    waterWin.clear();
    for (const Segment& p : seg.phases)
      if (p.kind != SegmentKind::kSurface) waterWin.push_back(p);
    if (glider) waterMinDepth = o.glider_min_depth_m;
  }
  // An AUV's reference water is that of its legs at depth; its steady dives
  // and climbs keep their own water (unless there is nothing else).
  std::vector<bool> atDepthMask;
  for (std::size_t w = 0; w < win.size() && !glider; ++w) atDepthMask.push_back(atDepth(w));
  const bool maskWater = !glider && !win.empty() &&
                         std::find(atDepthMask.begin(), atDepthMask.end(), true) != atDepthMask.end();
  // Gliders profile through the water column: its stratification is signal.
  const WaterAtDepth water = waterProperties(log, waterWin, depth, latitude, waterMinDepth,
                                            glider ? SeriesModel::kProfile : SeriesModel::kStationary,
                                            maskWater ? &atDepthMask : nullptr);
  rep.temperature_degC = water.T;
  rep.salinity_psu = water.S;
  rep.density_kgm3 = water.rho;
  rep.pressure_dbar = water.p;
  if (glider) rep.depth_m = water.z;
  rep.salinity_source = water.salinity_source;
  rep.density_source = water.density_source;
  if (water.skipped > 0)
    rep.warnings.push_back(Message(msg::kCtdOutOfRange, {std::to_string(water.skipped)}));
  double rho = water.rho.valid() ? water.rho.mean : kNaN;
  if (!water.rho.valid()) {
    rep.warnings.push_back(Message(msg::kNoDensity, {fmt("%.1f", o.default_density_kgm3)}));
    rho = o.default_density_kgm3;
  }

  double installed = 0.0;
  for (double m : o.installed_kg) installed += m;
  if (!o.installed_kg.empty()) rep.details["installed_kg"] = o.installed_kg;

  // --- physical estimation -------------------------------------------------
  std::vector<double> segNb(nw, kNaN), segX(nw, kNaN);
  std::vector<bool> segDropped(nw, false);  // glides the calibration left out
  if (!glider) {
    std::string why;
    const std::optional<SteadyHydroCoefficients> coeffs = steadyHydroFromProfile(v, why);
    std::vector<SteadySegmentMeans> means(nw);
    // Each segment's own water: a leg at another depth flies a known change
    // of buoyancy (in-situ density and the profile's hull law).
    const bool perWindowWater = water.win_rho.size() == nw && water.rho.valid();
    const double Tref = water.T.valid() ? water.T.mean : v.hull.reference_temperature_degC;
    const double pref = water.p.valid() ? water.p.mean : 0.0;
    const double Bref = rho * v.hull.volumeAt(Tref, pref);  // kg
    const HullLawReference hullRef{rho, Tref, pref};
    const std::vector<double> thrusterRpm = thrusterRpmAboveDeadband(log, v, win);
    for (std::size_t w = 0; w < nw; ++w) {
      means[w] = {win[w].start_s, win[w].end_s, speed.at(w), pitch.at(w), roll.at(w), elev.at(w), zRate.at(w), rpm.at(w)};
      means[w].thruster_rpm = thrusterRpm[w];
      means[w].glide = win[w].kind == SegmentKind::kGlide;
      if (win[w].averaged()) averageOverCycles(log, win[w], depthRate, depthRateFast, means[w]);
      if (perWindowWater && std::isfinite(water.win_rho[w])) {
        const double Ti = std::isfinite(water.win_T[w]) ? water.win_T[w] : Tref;
        const double pi = std::isfinite(water.win_p[w]) ? water.win_p[w] : pref;
        means[w].density_kgm3 = water.win_rho[w];
        means[w].buoyancy_n = units::g0 * water.win_rho[w] * v.hull.volumeAt(Ti, pi);
        means[w].buoyancy_change_n = means[w].buoyancy_n - units::g0 * Bref;
        means[w].pressure_dbar = pi;
        means[w].temperature_degC = Ti;
        setHullLawLevers(v.hull, hullRef, means[w]);
      }
    }
    setDriftLevers(means);
    AuvTrimContext ctx;
    ctx.profile_torque_nm_per_100rpm2 = profileTorqueAt100Rpm(v, rho);
    ctx.propeller = propellerLawFromProfile(v);
    ctx.surge_model = simModelFromProfile(v);  // none: the cruise roll stays the logged speed's
    ctx.weight_n = (v.mass_kg + installed) * units::g0;
    ctx.density_kgm3 = rho;
    ctx.bg_measured_m = o.bg_m;
    ctx.bg_profile_m = v.bg_m;
    ctx.bg_profile_rel_sigma = o.bg_profile_rel_sigma;
    ctx.hull_compressibility_per_dbar = v.hull.compressibility_per_dbar;
    ctx.hull_thermal_expansion_per_degC = v.hull.thermal_expansion_per_degC;
    ctx.coefficient_rel_sigma = o.coefficient_rel_sigma;
    ctx.pitch_alignment_sigma_deg = o.pitch_alignment_sigma_deg;
    ctx.log_has_speed = hasSamples(log, "speed");
    ctx.log_has_elevator = hasSamples(log, "elevator");
    ctx.log_has_rpm = hasSamples(log, "prop_rpm");
    // History: the same vehicle with other pieces. Its segments join the
    // calibration with the known mass and moment changes since.
    for (const HistoryMission& h : o.history) {
      if (!h.installed_kg.empty() && h.installed_kg.size() != v.points.size())
        throw InputError("history.installed", "has " + std::to_string(h.installed_kg.size()) + " values",
                         "give one kg value per adjustment point, in profile order");
      double dm = 0.0, moment = 0.0, then = 0.0;
      for (std::size_t i = 0; i < v.points.size(); ++i) {
        const double now_i = o.installed_kg.empty() ? 0.0 : o.installed_kg[i];
        const double then_i = h.installed_kg.empty() ? 0.0 : h.installed_kg[i];
        then += then_i;
        dm += now_i - then_i;
        moment += units::g0 * (now_i - then_i) * (v.points[i].position_m.x() - v.cb_m.x());
      }
      for (SteadySegmentMeans s : h.segments) {
        if (!std::isfinite(s.buoyancy_n)) continue;
        s.buoyancy_change_n = s.buoyancy_n - units::g0 * Bref + units::g0 * dm;
        s.weight_n = (v.mass_kg + then) * units::g0;
        s.moment_offset_nm = -moment;
        s.from_history = true;
        setHullLawLevers(v.hull, hullRef, s);
        ctx.history.push_back(s);
      }
    }
    // The transients (depth steps, propeller-speed changes) flown again
    // through the profile's simulator model join the calibration.
    std::optional<TransientFit> transient_fit;
    if (o.use_transients)
      attachTransientReplay(log, v, o.installed_kg, replay_unfit, coeffs && coeffs->has_planes, rho, Bref, transient_fit,
                            ctx, rep);
    const AuvTrimEstimate e = estimateAuvTrim(means, coeffs ? &*coeffs : nullptr, why, ctx);
    if (!e.segment_dropped.empty()) segDropped = e.segment_dropped;
    for (std::size_t w = 0; w < nw; ++w)
      if (std::isfinite(e.segment_net_buoyancy_kg.empty() ? kNaN : e.segment_net_buoyancy_kg[w]) && !segDropped[w])
        rep.steady_segments.push_back(means[w]);
    rep.net_buoyancy_kg = {e.buoyancy_identified, e.buoyancy_identified ? e.net_buoyancy_kg : kNaN,
                           e.buoyancy_identified ? e.net_buoyancy_sigma_kg : kNaN, e.buoyancy_why};
    rep.cg_x_mm = {e.x_identified, e.x_identified ? units::mToMm(e.x_m) : kNaN,
                   e.x_identified ? units::mToMm(e.x_sigma_m) : kNaN, e.x_why};
    rep.cg_y_mm = {e.y_identified, e.y_identified ? units::mToMm(e.y_m) : kNaN,
                   e.y_identified ? units::mToMm(e.y_sigma_m) : kNaN, e.y_why};
    rep.cg_y_basis = e.y_basis;
    if (e.cruise_known) {
      rep.cruise_rpm = e.cruise_rpm;
      rep.cruise_speed_mps = e.cruise_speed_mps;
      rep.cruise_roll_deg = {true, e.cruise_roll_deg, e.cruise_roll_sigma_deg, ""};
      rep.cruise_cg_y_mm = {e.y_cruise_identified, e.y_cruise_identified ? units::mToMm(e.y_cruise_m) : kNaN,
                            e.y_cruise_identified ? units::mToMm(e.y_cruise_sigma_m) : kNaN, e.y_why};
      rep.cruise_trimmed = e.trimmed_cruise;
    }
    rep.calibration = e.calibration;
    segNb = e.segment_net_buoyancy_kg;
    segX = e.segment_x_m;
    for (const auto& n : e.notes) rep.notes.push_back(n);
    for (const auto& w : e.warnings) rep.warnings.push_back(w);
    nlohmann::json d;
    d["model"] = "steady level flight: heave and pitch balance (Fossen form, CB origin) with the profile's hydrodynamics";
    d["weight_kg"] = v.mass_kg + installed;
    d["density_kgm3"] = rho;
    d["bg_mm"] = units::mToMm(o.bg_m.value_or(v.bg_m));
    d["bg_source"] = o.bg_m ? "--bg-mm" : "profile";
    d["segments_used"] = e.segments_used;
    if (e.history_segments_used > 0) d["history_segments_used"] = e.history_segments_used;
    d["chi2_per_dof"] = e.chi2_per_dof;
    if (e.buoyancy_identified) d["net_cg_x_correlation"] = e.net_x_correlation;
    if (e.after_move)
      d["after_move_expected_sigma"] = {{"net_buoyancy_kg", e.after_move->net_sigma_kg},
                                        {"cg_x_mm", units::mToMm(e.after_move->x_sigma_m)},
                                        {"assumed_net_buoyancy_kg", e.after_move->net_kg},
                                        {"assumed_cg_x_mm", units::mToMm(e.after_move->x_g_m)}};
    if (e.manoeuvre) {
      nlohmann::json flight = nlohmann::json::array();
      for (const auto& l : e.manoeuvre->flight)
        flight.push_back({{"prop_rpm", l.rpm}, {"depth_rate_mps", l.depth_rate_mps}, {"duration_s", l.duration_s}});
      d["calibration_manoeuvre"] = {{"legs", e.manoeuvre->legs},
                                    {"flight", flight},
                                    {"expected_sigma", {{"net_buoyancy_kg", e.manoeuvre->net_sigma_kg},
                                                        {"cg_x_mm", units::mToMm(e.manoeuvre->x_sigma_m)}}}};
    }
    if (e.calibrated) {
      // The calibrated steady coefficients (Munk moment inside M_w), for
      // forward prediction by the planner.
      const SteadyHydroCoefficients& k = *e.calibrated;
      d["calibrated_hydrodynamics"] = {{"reference_length_m", k.reference_length_m}, {"Zw_prime", k.Zw_prime},
                                        {"Mw_prime", k.Mw_prime}, {"Zww_kg_per_m", k.Zww_kg_per_m},
                                        {"Mww_kg", k.Mww_kg}, {"Xudot_kg", k.Xudot_kg}, {"Zwdot_kg", k.Zwdot_kg},
                                        {"munk_moment", "inside_Mw"},
                                        {"Z_uud_kg_per_m_deg", k.Z_e_per_deg}, {"M_uud_kg_per_deg", k.M_e_per_deg},
                                        {"positive_deflection", "trailing_edge_down"}};
    }
    if (e.roll_static_known) d["roll_static_deg"] = {{"value", e.roll_static_deg}, {"sigma", e.roll_static_sigma_deg}};
    if (e.elevator_bias_fitted)
      d["elevator_zero_offset_deg"] = {{"value", e.elevator_bias_deg}, {"sigma", e.elevator_bias_sigma_deg}};
    if (e.moment_combination_nm)
      d["moment_about_planes"] = {{"definition", "W * x_G - l * (B - W), N m"},
                                  {"value_nm", *e.moment_combination_nm},
                                  {"sigma_nm", *e.moment_combination_sigma_nm},
                                  {"plane_lever_m", *e.plane_lever_m}};
    // What a later mission of this configuration calibrates jointly with.
    if (!rep.steady_segments.empty()) d["steady_segments"] = steadySegmentsJson(rep.steady_segments);
    rep.details["auv_estimate"] = d;
  } else {
    rep.cg_x_mm.why_not = Message(msg::kGliderCgX);
    rep.cg_y_mm.why_not = Message(msg::kGliderCgY);
    std::vector<Message> cnotes;
    const GliderFlightConstants c = gliderConstantsFromProfile(v, cnotes);
    for (const auto& n : cnotes) rep.notes.push_back(n);
    Message why;
    if (!hasSamples(log, "pump_volume", 10)) why = Message(msg::kNoPumpVolume);
    else if (!hasSamples(log, "pitch", 10)) why = Message(msg::kNoPitch);
    else if (win.empty()) why = Message(msg::kNoSteadyDiveOrClimb);
    if (const std::string* m = log.metadataValue("mass_kg")) {
      const double lm = parseNumberAfter(*m, 0);
      if (lm > 0 && std::abs(lm - v.mass_kg) > 0.05 * v.mass_kg)
        rep.warnings.push_back(Message(msg::kLogMassDiffers, {fmt("%.2f", lm), fmt("%.2f", v.mass_kg)}));
    }
    GliderFitResult fit;
    ReferenceState ref;
    double pitchBiasSigma = 0.0;
    std::string obsChannel;
    if (why.empty()) {
      // Observation time base: CTD pressure when it is at least as dense as
      // depth (w = -dp/dt / (rho g), hydrostatic with the local density),
      // else depth.
      const LogChannel* pc = log.find("pressure");
      const LogChannel* dc = log.find("depth");
      const bool usePressure = pc && (!dc || pc->validCount() >= dc->validCount());
      obsChannel = usePressure ? "pressure" : "depth";
      const TimeSeries obs = log.series(obsChannel);
      const std::vector<double> rate = localRate(obs, o.glider_rate_window_s, so.max_gap_s, 1.0);
      const TimeSeries sPitch = log.series("pitch"), sPump = log.series("pump_volume");
      const bool hasRho = hasSamples(log, "density"), hasT = hasSamples(log, "temperature");
      const TimeSeries sRho = hasRho ? log.series("density") : TimeSeries{};
      const TimeSeries sT = hasT ? log.series("temperature") : TimeSeries{};
      const double gap = 60.0;
      SeriesCursor cPitch(sPitch, false, gap), cPump(sPump, false, gap), cRho(sRho, false, gap), cT(sT, false, gap);
      const double minPitch = units::degToRad(o.glider_min_pitch_deg);
      std::vector<GlideSample> samples;
      samples.reserve(obs.size() / 2);
      std::size_t i = 0;
      forEachInWindows(obs, win, [&](std::size_t w, double t, double x) {
        while (obs.t[i] < t) ++i;
        const double z = usePressure ? seawater::depthFromPressure(std::clamp(x, 0.0, 11000.0), latitude) : x;
        if (!(z >= o.glider_min_depth_m && z <= o.glider_max_depth_m) || std::isnan(rate[i])) return;
        GlideSample s;
        s.pitch_rad = units::degToRad(cPitch.at(t));
        const double th = c.pitch_scale * s.pitch_rad + c.pitch_offset_rad;
        if (!(std::abs(th) >= minPitch)) return;
        if ((win[w].phase == SegmentKind::kDive) != (th < 0)) return;
        s.pump_m3 = cPump.at(t) * 1e-6;
        s.density_kgm3 = hasRho ? cRho.at(t) : rho;
        s.temperature_degC = hasT ? cT.at(t) : c.reference_temperature_degC;
        s.pressure_dbar = usePressure ? x : seawater::pressureFromDepth(std::clamp(x, 0.0, 10600.0), latitude);
        if (std::isnan(s.pump_m3) || !(s.density_kgm3 > 900) || std::isnan(s.temperature_degC)) return;
        s.w_obs_mps = usePressure ? -rate[i] * 1e4 / (s.density_kgm3 * units::g0) : -rate[i];
        s.block = static_cast<int>(w);
        samples.push_back(s);
      });
      ref.density_kgm3 = rho;
      ref.pressure_dbar = water.p.valid() ? water.p.mean : 0.0;
      ref.temperature_degC = water.T.valid() ? water.T.mean : c.reference_temperature_degC;
      if (!water.p.valid() || !water.T.valid()) {
        double sp = 0, sT2 = 0;
        for (const auto& s : samples) {
          sp += s.pressure_dbar;
          sT2 += s.temperature_degC;
        }
        if (!samples.empty()) {
          if (!water.p.valid()) ref.pressure_dbar = sp / static_cast<double>(samples.size());
          if (!water.T.valid()) ref.temperature_degC = sT2 / static_cast<double>(samples.size());
        }
      }
      GliderFitOptions fo = o.glider_fit;
      if (c.form == GlideForm::kSeaglider) fo.Cd0_start = c.drag_start;
      fit = fitSteadyGlide(samples, c, ref, fo);
      if (fit.samples >= 10 && o.glider_pitch_bias_sigma_deg > 0) {
        GliderFlightConstants biased = c;
        biased.pitch_offset_rad += units::degToRad(o.glider_pitch_bias_sigma_deg);
        GliderFitOptions quick = o.glider_fit;
        quick.max_jackknife_groups = 0;
        quick.Cd0_start = fo.Cd0_start;
        const GliderFitResult b = fitSteadyGlide(samples, biased, ref, quick);
        pitchBiasSigma = std::abs(b.net_buoyancy_kg - fit.net_buoyancy_kg);
        fit.net_buoyancy_sigma_kg = std::hypot(fit.net_buoyancy_sigma_kg, pitchBiasSigma);
      }
      if (fit.samples < 10)
        why = Message(msg::kFewGlideSamples, {fmt("%.0f", o.glider_min_depth_m), fmt("%.0f", o.glider_min_pitch_deg)});
    }
    if (!why.empty()) {
      rep.net_buoyancy_kg.why_not = why;
      rep.mass_to_add_g.why_not = rep.net_buoyancy_kg.why_not;
    } else {
      if (!fit.converged) rep.warnings.push_back(Message(msg::kGliderFitNotConverged, {fit.message}));
      rep.net_buoyancy_kg = {true, fit.net_buoyancy_kg, fit.net_buoyancy_sigma_kg, ""};
      GliderTargetRequest tq = o.glider_target;
      if (!tq.density_kgm3) tq.density_kgm3 = o.target_density_kgm3;
      GliderTarget target;
      try {
        target = resolveGliderTarget(log, tq, latitude);
      } catch (const InputError& e) {
        if (tq.any()) throw;
        // The log cannot place its own deepest water: the fit's reference state.
        target = {ref.density_kgm3, ref.pressure_dbar, ref.temperature_degC, kNaN,
                  "the log's mean operating water (" + e.problem() + ")"};
      }
      rep.target_density_kgm3 = target.density_kgm3;
      rep.target_pressure_dbar = target.pressure_dbar;
      rep.target_temperature_degC = target.temperature_degC;
      rep.target_basis = target.basis;
      // Ballast goes inside the hull (no volume change): neutral when
      // m' = rho_t V(p_t, T_t) with the profile's compressibility and
      // thermal expansion carrying the fitted volume to the target.
      const double add = gliderMassToAddKg(fit.hull_volume_m3, c.compressibility_per_dbar, c.thermal_expansion_per_degC,
                                           c.reference_temperature_degC, target, c.mass_kg);
      const double k = (add + c.mass_kg) / (c.mass_kg + fit.net_buoyancy_kg);
      rep.mass_to_add_g = {true, 1000.0 * add, 1000.0 * k * fit.net_buoyancy_sigma_kg, ""};
      const double Vop = (c.mass_kg + fit.net_buoyancy_kg) / ref.density_kgm3;
      nlohmann::json d;
      d["model"] = "steady glide (Merckelbach et al. 2010, gliderflight steady state), fitted net buoyancy and Cd0";
      d["observation_channel"] = obsChannel;
      d["mass_kg"] = c.mass_kg;
      d["Cd0"] = fit.Cd0;
      d["drag_parameter"] = c.form == GlideForm::kSeaglider ? "hd_b (Seaglider form, Eriksen et al. 2001)" : "Cd0";
      d["Cd0_sigma"] = fit.Cd0_sigma;
      d["hull_volume_m3"] = fit.hull_volume_m3;
      d["neutral_density_kgm3"] = c.mass_kg / Vop;
      d["rms_start_mps"] = fit.rms_start_mps;
      d["rms_mps"] = fit.rms_mps;
      d["residual_lag1"] = fit.residual_lag1;
      d["samples"] = fit.samples;
      d["jackknife_groups"] = fit.groups;
      d["sigma_ar1_kg"] = fit.sigma_ar1_kg;
      d["sigma_jackknife_kg"] = fit.sigma_jackknife_kg;
      d["sigma_pitch_bias_kg"] = pitchBiasSigma;
      d["pitch_bias_sigma_deg"] = o.glider_pitch_bias_sigma_deg;
      d["reference"] = {{"density_kgm3", ref.density_kgm3}, {"pressure_dbar", ref.pressure_dbar},
                        {"temperature_degC", ref.temperature_degC}};
      d["constants"] = {{"wing_area_m2", c.wing_area_m2}, {"lift_slope_per_rad", c.lift_slope_per_rad},
                        {"induced_drag_per_rad2", c.induced_drag_per_rad2},
                        {"compressibility_per_dbar", c.compressibility_per_dbar},
                        {"thermal_expansion_per_degC", c.thermal_expansion_per_degC},
                        {"reference_temperature_degC", c.reference_temperature_degC},
                        {"pitch_scale", c.pitch_scale}, {"pitch_offset_deg", units::radToDeg(c.pitch_offset_rad)}};
      rep.details["glider_fit"] = d;
    }
    {
      const GliderTrim t = estimateGliderTrim(log, win);
      nlohmann::json d;
      d["pitch"] = t.pitch_known
                       ? nlohmann::json{{"model", "tan(pitch) = T1 pump_cm3 + T2 battery_mm + T3 (gliderflight glidertrim)"},
                                        {"T1_per_cm3", t.T1_per_cm3}, {"T2_per_mm", t.T2_per_mm}, {"T3", t.T3},
                                        {"rms_tan", t.rms_tan}, {"samples", t.pitch_samples},
                                        {"battery_for_level_mm", t.battery_for_level_mm},
                                        {"battery_min_mm", t.battery_min_mm}, {"battery_max_mm", t.battery_max_mm}}
                       : nlohmann::json{{"why_not", t.pitch_why_not}};
      d["roll"] = t.roll_known ? nlohmann::json{{"roll_deg", t.roll_deg}, {"roll_sigma_deg", t.roll_sigma_deg},
                                                {"samples", t.roll_samples}, {"basis", t.roll_basis}}
                               : nlohmann::json{{"why_not", t.roll_why_not}};
      rep.details["glider_trim"] = d;
    }
  }

  // --- classic mode ------------------------------------------------------------
  if (o.classic) {
    const classic::ClassicReport cr = classic::classicAnalysis(log);
    auto val = [](const classic::ClassicValue& x, bool has) {
      if (!has) return nlohmann::json(nullptr);
      nlohmann::json j = {{"value", numOrNull(x.value)}, {"samples", x.samples}};
      if (x.index_clamped) j["index_clamped"] = true;
      return j;
    };
    rep.details["classic"] = {{"source", "Lillemoen 2014 App. D.1-D.4 as written (40-60 % window, exact equality tests)"},
                              {"depth_error_m", val(cr.depth_error_m, cr.has_depth)},
                              {"pitch_error_deg", val(cr.pitch_error_deg, cr.has_pitch)},
                              {"pitch_at_stable_depth_deg", val(cr.pitch_at_stable_depth_deg, cr.has_pitch_depth)},
                              {"roll_error_deg", val(cr.roll_error_deg, cr.has_roll)}};
  }

  // --- segments ------------------------------------------------------------------
  for (const Segment& p : seg.phases) rep.segments.push_back({p.kind, p.start_s, p.end_s, false});
  for (std::size_t w = 0; w < nw; ++w) {
    SegmentReport s;
    s.kind = win[w].kind;
    s.start_s = win[w].start_s;
    s.end_s = win[w].end_s;
    s.used = true;
    s.depth_m = zS.at(w).mean;
    s.depth_error_m = dErr.at(w).mean;
    s.pitch_deg = pitch.at(w).mean;
    s.pitch_error_deg = pErr.at(w).mean;
    s.roll_deg = roll.at(w).mean;
    s.depth_error_ci95_m = dErr.at(w).ci95;
    s.pitch_error_ci95_deg = pErr.at(w).ci95;
    s.roll_ci95_deg = roll.at(w).ci95;
    s.speed_mps = speed.at(w).mean;
    s.prop_rpm = rpm.at(w).mean;
    s.elevator_deg = elev.at(w).mean;
    s.net_buoyancy_kg = segNb[w];
    s.cg_x_mm = units::mToMm(segX[w]);
    s.calibration_dropped = segDropped[w];
    rep.segments.push_back(s);
  }
  std::stable_sort(rep.segments.begin(), rep.segments.end(),
                   [](const SegmentReport& a, const SegmentReport& b) { return a.start_s < b.start_s; });
  return rep;
}

}  // namespace auv::analysis
