#include "planning/change_explanation.h"

#include <cmath>
#include <cstdio>

#include "ballast/solution_text.h"
#include "common/units.h"
#include "planning/planning_messages.h"

namespace auv {
namespace {

using ballast::kgText;
using ballast::signedDegText;
using ballast::signedKgText;

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v == 0.0 ? 0.0 : v);
  return b;
}

std::string shift(double mm, const char* pos, const char* neg) {
  return fmt("%.2f mm ", std::abs(mm)) + (mm >= 0 ? pos : neg);
}

std::string waterText(const PlannedWater& w, const WaterState& s) {
  return fmt("%.2f degC", w.temperature_degC) + ", " + fmt("%.2f PSU", w.salinity_psu) + ", " +
         fmt("%.0f m", w.depth_m) + " (" + fmt("%.2f kg/m3", s.density_kgm3) + ")";
}

// The pieces to remove and to add ("1 × 2.4 kg and 2 × 1.2 kg"; empty if none).
std::pair<std::string, std::string> pieceLists(const PointRecommendation& p) {
  std::string add, rem;
  for (auto it = p.pieces.rbegin(); it != p.pieces.rend(); ++it) {
    std::string& s = it->count > 0 ? add : rem;
    s += (s.empty() ? "" : " and ") + std::to_string(std::abs(it->count)) + " \u00d7 " + ballast::sizeText(it->size_kg);
  }
  return {rem, add};
}

std::string pieceList(const std::string& rem, const std::string& add) {
  std::string out;
  if (!rem.empty()) out = "remove " + rem;
  if (!add.empty()) out += (out.empty() ? "add " : ", then add ") + add;
  return out;
}


}  // namespace

void explainPlan(const VehicleProfile& v, const BallastProblem& pr, PreMissionPlan& plan) {
  const double w_before = plan.vehicle.mass.mass_kg;
  double added = 0.0;
  for (const auto& p : plan.points) added += p.add_kg;
  const double w_after = w_before + added;
  for (std::size_t i = 0; i < plan.points.size(); ++i) {
    const PointRecommendation& p = plan.points[i];
    if (p.pieces.empty()) continue;
    // This point's share of the CG shift; the shares add up to the total.
    const Eigen::Vector3d d = p.add_kg * (pr.points[i].position_m - plan.vehicle.mass.cg_m) / w_after;
    const double x_mm = units::mToMm(d.x()), y_mm = units::mToMm(d.y());
    const auto [rem, add] = pieceLists(p);
    const std::string label = p.label.empty() ? p.name : p.label;
    std::string s = label + ": " + pieceList(rem, add) + " (" + signedKgText(p.add_kg) +
                    "), which " + (p.add_kg > 0 ? "lowers" : "raises") + " net buoyancy by " +
                    kgText(std::abs(p.add_kg)) + " and moves the CG " + shift(x_mm, "forward", "aft") + " and " +
                    shift(y_mm, "to starboard", "to port");
    const Eigen::Vector3d off = plan.vehicle.mass.cg_m - plan.vehicle.cb_m;
    const bool along_x = std::abs(x_mm) >= std::abs(y_mm);
    const bool back = along_x ? d.x() * off.x() < 0 : d.y() * off.y() < 0;
    if (along_x) {
      s += back ? ", bringing the CG back towards the CB fore-aft" : ", balanced by the other points' fore-aft shares";
    } else {
      s += back ? ", bringing the CG back towards the CB sideways" : ", balanced by the other points' sideways shares";
    }
    plan.explanations.push_back(Message(planning::msg::kExplainPointId, s + ".",
                                        {label, rem, add, signedKgText(p.add_kg), kgText(std::abs(p.add_kg)),
                                         fmt("%.2f", x_mm), fmt("%.2f", y_mm), p.add_kg > 0 ? "lowers" : "raises",
                                         along_x ? "x" : "y", back ? "back" : "balanced"}));
  }
  if (plan.explanations.empty()) plan.explanations.push_back(Message(planning::msg::kNoChange));

  const PlannedPointResult& op = plan.at_points.front();
  plan.notes.push_back(Message(
      planning::msg::kNextMission,
      {waterText(op.water, op.state), signedKgText(plan.net_before_kg), signedDegText(plan.pitch_before_deg),
       signedDegText(plan.roll_before_deg), signedKgText(plan.predicted.net_buoyancy_kg), kgText(plan.net_sigma_kg),
       signedDegText(plan.predicted.pitch_deg), ballast::degText(plan.pitch_sigma_deg),
       signedDegText(plan.predicted.roll_deg), ballast::degText(plan.roll_sigma_deg)}));
  plan.notes.push_back(Message(planning::msg::kMassFromLastMission,
                               {kgText(plan.vehicle.mass.mass_kg), kgText(plan.vehicle.log_displaced_kg),
                                fmt("%.2f kg/m3", plan.estimate.water.density_kgm3),
                                fmt("%.2f degC", plan.estimate.water.temperature_degC),
                                fmt("%.1f dbar", plan.estimate.water.pressure_dbar),
                                signedKgText(plan.estimate.net_buoyancy_kg)}));
  plan.notes.push_back(Message(planning::msg::kSafetyMargin,
                               {kgText(plan.margin_kg),
                                fmt("%.3g", plan.net_sigma_kg > 0 ? plan.margin_kg / plan.net_sigma_kg : 0.0),
                                kgText(plan.net_sigma_kg)}));

  if (plan.vehicle.cg_x_assumed) plan.warnings.push_back(Message(planning::msg::kCgXAssumed));
  if (plan.vehicle.cg_y_assumed) plan.warnings.push_back(Message(planning::msg::kCgYAssumed));
  for (const PlannedPointResult& r : plan.at_points) {
    if (r.net_after_kg < plan.margin_kg - 1e-6) {
      plan.warnings.push_back(Message(r.net_after_kg < 0 ? planning::msg::kUnsafeSinks : planning::msg::kUnsafe,
                                      {r.role, waterText(r.water, r.state), signedKgText(r.net_after_kg),
                                       kgText(plan.margin_kg)}));
    }
  }
  if (!plan.buoyancy_in_band && plan.safe && plan.predicted.net_buoyancy_kg > v.spec.net_buoyancy_max_kg) {
    const double spread = plan.band_lo_kg - plan.margin_kg;
    if (plan.band_lo_kg > v.spec.net_buoyancy_max_kg - 1e-9) {
      plan.warnings.push_back(Message(planning::msg::kAboveBandForMargin,
                                      {signedKgText(plan.predicted.net_buoyancy_kg), kgText(v.spec.net_buoyancy_max_kg),
                                       kgText(plan.margin_kg), kgText(spread)}));
    } else {
      plan.warnings.push_back(Message(planning::msg::kBandNotReachable,
                                      {kgText(plan.band_lo_kg), kgText(v.spec.net_buoyancy_max_kg),
                                       signedKgText(plan.predicted.net_buoyancy_kg)}));
    }
  }
  // Name the kit's optional pieces when a band is missed and they were not used.
  if ((!plan.buoyancy_in_band || !plan.pitch_in_band || !plan.roll_in_band) && !v.kit.optional_pieces_kg.empty() &&
      plan.piece_sizes_kg.size() == v.kit.pieces_kg.size() && plan.policy != PlanPolicy::Classic) {
    std::string sizes;
    for (double s : v.kit.optional_pieces_kg) sizes += (sizes.empty() ? "" : ", ") + ballast::sizeText(s);
    plan.notes.push_back(Message(planning::msg::kOptionalPieces, {sizes}));
  }
  if (plan.roll_sigma_deg > v.spec.roll_tolerance_deg || plan.pitch_sigma_deg > v.spec.pitch_tolerance_deg) {
    plan.notes.push_back(
        Message(planning::msg::kWideSigma, {ballast::degText(plan.pitch_sigma_deg), ballast::degText(plan.roll_sigma_deg)}));
  }
}

}  // namespace auv
