#include "analysis/transient_replay.h"

#include <exception>

#include <Eigen/Core>

#include "analysis/analysis_messages.h"
#include "common/units.h"
#include "sim/model_loader.h"

namespace auv::analysis {

void attachTransientReplay(const MissionLog& log, const VehicleProfile& v, const std::vector<double>& installed_kg,
                           bool replay_unfit, bool has_planes, double rho_kgm3, double buoyancy_ref_kg,
                           std::optional<TransientFit>& fit, AuvTrimContext& ctx, AnalysisReport& rep) {
  // Not on a log flown too light or porpoising: there the plane loop sat at
  // its stop near the surface or limit-cycled, and the replay fitted the
  // truth's stop and anti-windup instead of its hydrodynamics (the 4-6
  // sigma misses and the one negative vehicle of the bench). Logs flown too
  // heavy keep it: that is where it gained most. Not with a history
  // calibration either: that joint fit pins the vehicle, and the replay
  // brought its coverage under 90 % (docs/decisions/analysis-calibration.md).
  const bool with_history = !ctx.history.empty();
  if (replay_unfit) {
    rep.details["transients_skipped"] = "log not flown as commanded";
    rep.notes.push_back(Message(msg::kTransientsNotFlownAsCommanded));
  } else if (with_history) {
    rep.details["transients_skipped"] = "history calibration";
    rep.notes.push_back(Message(msg::kTransientsWithHistory));
  }
  if (!replay_unfit && !with_history && has_planes && ctx.log_has_elevator && ctx.log_has_speed) {
    std::optional<sim::VehicleModel> model;
    sim::DepthAutopilotConfig autopilot;
    try {
      model = sim::loadVehicleModel(v);
      autopilot = sim::loadAutopilotConfig(v);
    } catch (const std::exception&) {
      // No simulator sections in this profile: steady segments only (the trim estimate says so in its notes).
    }
    if (model) {
      TransientFitContext tc;
      tc.weight_n = ctx.weight_n;
      tc.density_ref_kgm3 = rho_kgm3;
      tc.buoyancy_ref_n = units::g0 * buoyancy_ref_kg;
      tc.autopilot = autopilot;
      for (std::size_t i = 0; i < installed_kg.size() && i < v.points.size(); ++i) {
        const Eigen::Vector3d r = v.points[i].position_m - model->body.cb_profile_m;
        tc.extra_Iyy_kgm2 += installed_kg[i] * (r.x() * r.x() + r.z() * r.z());
      }
      fit.emplace(log, *model, tc);
      if (fit->residualCount() > 0) {
        ctx.transients.residuals = [&f = *fit](const Eigen::VectorXd& p) { return f.residuals(p); };
        ctx.transients.group_ends = fit->windowEnds();
        ctx.transients.reweight = [&f = *fit](const Eigen::VectorXd& p) { f.rescaleChannels(p); };
        ctx.transient_windows = fit->windowCount();
      }
    }
    rep.details["transient_windows"] = ctx.transient_windows;
  }
}

}  // namespace auv::analysis
