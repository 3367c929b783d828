#include "wizard/glider_answer.h"

#include "analysis/profile_constants.h"
#include "common/input_error.h"
#include "discrepancy/glider_ballast_answer.h"
#include "discrepancy/glider_check_model.h"
#include "discrepancy/model_check_report.h"
#include "planning/glider_ballast_plan.h"
#include "seawater/depth_pressure.h"
#include "seawater/seawater.h"

namespace auv::ui {

analysis::GliderTargetRequest targetRequest(const GliderTargetChoice& c) {
  analysis::GliderTargetRequest q;
  using K = GliderTargetChoice::Kind;
  switch (c.kind) {
    case K::kLogDeepest:
      break;
    case K::kDensity:
      q.density_kgm3 = c.density_kgm3;
      break;
    case K::kPressureTemperature:
      q.pressure_dbar = c.pressure_dbar;
      q.temperature_degC = c.temperature_degC;
      // With a salinity the water is complete: its EOS-80 density, as
      // --target-density would give it.
      if (std::isfinite(c.salinity_psu)) q.density_kgm3 = seawater::density(c.salinity_psu, c.temperature_degC, c.pressure_dbar);
      break;
    case K::kDepth:
      q.depth_m = c.depth_m;
      break;
  }
  return q;
}

namespace {

// The analysis's own target when the log cannot place its deepest water
// (as analyzeMission falls back to it).
analysis::GliderTarget reportTarget(const analysis::AnalysisReport& r) {
  return {r.target_density_kgm3, r.target_pressure_dbar, r.target_temperature_degC, NAN, r.target_basis};
}

}  // namespace

GliderAnswer gliderAnswer(const WizardState& s, const GliderTargetChoice& c) {
  GliderAnswer a;
  try {
    if (!s.vehicle || !s.log || !s.analysis)
      throw InputError("log", "no glider log analysed in this session", "go back and import the mission's log");
    if (!s.analysis->mass_to_add_g.known)
      throw InputError("log", s.analysis->mass_to_add_g.why_not, "import a log with pitch, pump volume and depth in glides");
    const analysis::GliderTargetRequest q = targetRequest(c);
    const double latitude = analysis::latitudeFromMetadata(*s.log).value_or(seawater::kDefaultLatitude_deg);
    try {
      a.target = analysis::resolveGliderTarget(*s.log, q, latitude);
    } catch (const InputError&) {
      if (q.any()) throw;
      a.target = reportTarget(*s.analysis);
    }
    a.report = analysis::toJson(*s.analysis);
    // What the bottles and rails hold now (the history's installed state),
    // so the capacities are checked against it; empty = not known.
    const std::vector<double> installed =
        s.mission_installed_kg.size() == s.vehicle->points.size() ? s.mission_installed_kg : std::vector<double>{};
    const auto* model = dynamic_cast<const discrepancy::GliderCheckModel*>(s.check_model.get());
    if (model && s.model_check) {
      discrepancy::mergeIntoAnalysisJson(a.report, *s.model_check);
      const discrepancy::GliderBallastAnswer g = discrepancy::gliderBallastAnswer(*model, *s.model_check, a.target);
      discrepancy::mergeGliderAnswer(a.report, g);
      a.joint = true;
      a.terms_used = g.terms_used;
      a.mass_drift_g_per_h = g.mass_drift_g_per_h;
      a.plan = planGliderBallast(*s.vehicle, {a.report, installed, std::nullopt});
    } else {
      // The analysis alone: its fitted volume carried to the target.
      a.plan = planGliderBallast(*s.vehicle, {a.report, installed, a.target});
    }
    a.ok = true;
  } catch (const InputError& e) {
    a.error = e.what();
  }
  return a;
}

}  // namespace auv::ui
