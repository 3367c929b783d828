#include "planning/change_explanation.h"

#include <cmath>
#include <cstdio>

#include "ballast/solution_text.h"
#include "common/units.h"

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

std::string pieceList(const PointRecommendation& p) {
  std::string add, rem;
  for (auto it = p.pieces.rbegin(); it != p.pieces.rend(); ++it) {
    std::string& s = it->count > 0 ? add : rem;
    s += (s.empty() ? "" : " and ") + std::to_string(std::abs(it->count)) + " \u00d7 " + ballast::sizeText(it->size_kg);
  }
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
    std::string s = (p.label.empty() ? p.name : p.label) + ": " + pieceList(p) + " (" + signedKgText(p.add_kg) +
                    "), which " + (p.add_kg > 0 ? "lowers" : "raises") + " net buoyancy by " +
                    kgText(std::abs(p.add_kg)) + " and moves the CG " + shift(x_mm, "forward", "aft") + " and " +
                    shift(y_mm, "to starboard", "to port");
    const Eigen::Vector3d off = plan.vehicle.mass.cg_m - plan.vehicle.cb_m;
    if (std::abs(x_mm) >= std::abs(y_mm)) {
      s += d.x() * off.x() < 0 ? ", bringing the CG back towards the CB fore-aft"
                               : ", balanced by the other points' fore-aft shares";
    } else {
      s += d.y() * off.y() < 0 ? ", bringing the CG back towards the CB sideways"
                               : ", balanced by the other points' sideways shares";
    }
    plan.explanations.push_back(s + ".");
  }
  if (plan.explanations.empty()) plan.explanations.push_back("No change: the vehicle is already as good as the kit allows.");

  const PlannedPointResult& op = plan.at_points.front();
  plan.notes.push_back("Next mission at " + waterText(op.water, op.state) + ": from net buoyancy " +
                       signedKgText(plan.net_before_kg) + ", pitch " + signedDegText(plan.pitch_before_deg) +
                       ", roll " + signedDegText(plan.roll_before_deg) + " to " +
                       signedKgText(plan.predicted.net_buoyancy_kg) + " \u00b1 " + kgText(plan.net_sigma_kg) +
                       ", pitch " + signedDegText(plan.predicted.pitch_deg) + " \u00b1 " +
                       ballast::degText(plan.pitch_sigma_deg) + ", roll " + signedDegText(plan.predicted.roll_deg) +
                       " \u00b1 " + ballast::degText(plan.roll_sigma_deg) + " (1 sigma).");
  plan.notes.push_back("Mass " + kgText(plan.vehicle.mass.mass_kg) + " from the last mission: " +
                       kgText(plan.vehicle.log_displaced_kg) + " displaced at " +
                       fmt("%.2f kg/m3", plan.estimate.water.density_kgm3) + ", " +
                       fmt("%.2f degC", plan.estimate.water.temperature_degC) + ", " +
                       fmt("%.1f dbar", plan.estimate.water.pressure_dbar) + " minus the measured net buoyancy " +
                       signedKgText(plan.estimate.net_buoyancy_kg) + ".");
  plan.notes.push_back("Safety margin " + kgText(plan.margin_kg) + " = " +
                       fmt("%.3g", plan.net_sigma_kg > 0 ? plan.margin_kg / plan.net_sigma_kg : 0.0) +
                       " \u00d7 sigma " + kgText(plan.net_sigma_kg) +
                       " (estimate and water); the move keeps at least that much net buoyancy at every planned point.");

  if (plan.vehicle.cg_x_assumed) {
    plan.warnings.push_back("CG x was not identified from the log: the plan assumes it at the CB and keeps the "
                            "fore-aft balance; check pitch on the next mission");
  }
  if (plan.vehicle.cg_y_assumed) {
    plan.warnings.push_back("CG y was not identified from the log: the plan assumes it at the CB and keeps the "
                            "side balance; check roll on the next mission");
  }
  for (const PlannedPointResult& r : plan.at_points) {
    if (r.net_after_kg < plan.margin_kg - 1e-6) {
      plan.warnings.push_back("UNSAFE: at the " + r.role + " point (" + waterText(r.water, r.state) +
                              ") the vehicle would have " + signedKgText(r.net_after_kg) +
                              " net buoyancy, less than the safety margin " + kgText(plan.margin_kg) +
                              (r.net_after_kg < 0 ? ": it would sink if it lost power there" : ""));
    }
  }
  if (!plan.buoyancy_in_band && plan.safe && plan.predicted.net_buoyancy_kg > v.spec.net_buoyancy_max_kg) {
    const double spread = plan.band_lo_kg - plan.margin_kg;
    if (plan.band_lo_kg > v.spec.net_buoyancy_max_kg - 1e-9) {
      plan.warnings.push_back("net buoyancy " + signedKgText(plan.predicted.net_buoyancy_kg) +
                              " at the operating depth is above the band " + kgText(v.spec.net_buoyancy_max_kg) +
                              " because the safety margin (" + kgText(plan.margin_kg) +
                              ") and the less buoyant planned points (" + kgText(spread) + " less) come first");
    } else {
      plan.warnings.push_back("net buoyancy band not reachable with this kit while keeping the safety margin: no "
                              "combination of pieces lands between " + kgText(plan.band_lo_kg) + " and " +
                              kgText(v.spec.net_buoyancy_max_kg) + "; the nearest safe one is " +
                              signedKgText(plan.predicted.net_buoyancy_kg));
    }
  }
  // Name the kit's optional pieces when a band is missed and they were not used.
  if ((!plan.buoyancy_in_band || !plan.pitch_in_band || !plan.roll_in_band) && !v.kit.optional_pieces_kg.empty() &&
      plan.piece_sizes_kg.size() == v.kit.pieces_kg.size() && plan.policy != PlanPolicy::Classic) {
    std::string sizes;
    for (double s : v.kit.optional_pieces_kg) sizes += (sizes.empty() ? "" : ", ") + ballast::sizeText(s);
    plan.notes.push_back("The kit has optional pieces (" + sizes + ") not used in this plan; enabling them "
                         "(--optional-pieces) may reach the missed band.");
  }
  if (plan.roll_sigma_deg > v.spec.roll_tolerance_deg || plan.pitch_sigma_deg > v.spec.pitch_tolerance_deg) {
    plan.notes.push_back("The estimate's own uncertainty (pitch " + ballast::degText(plan.pitch_sigma_deg) +
                         ", roll " + ballast::degText(plan.roll_sigma_deg) +
                         ") is wider than a tolerance band; the next mission will tell.");
  }
}

}  // namespace auv
