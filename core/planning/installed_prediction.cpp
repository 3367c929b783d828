#include "planning/installed_prediction.h"

#include <cmath>

#include "common/input_error.h"
#include "common/units.h"
#include "hydrostatics/static_trim.h"
#include "planning/flight_pitch.h"

namespace auv {
namespace {

struct Attitude {
  double pitch_deg = 0.0, roll_deg = 0.0;
};

// The plan's vehicle (mass and CG as the last mission showed them, the
// pieces then installed included) plus the change, in the operating water.
Attitude attitude(const VehicleProfile& v, double mass_kg, const Eigen::Vector3d& cg_m, const std::vector<double>& add_kg,
                  double displaced_kg) {
  double W = mass_kg;
  Eigen::Vector3d moment = mass_kg * cg_m;
  for (std::size_t p = 0; p < add_kg.size(); ++p) {
    W += add_kg[p];
    moment += add_kg[p] * v.points[p].position_m;
  }
  const StaticTrim t = staticTrim(units::g0 * W, units::g0 * displaced_kg, moment / W, v.cb_m);
  return {units::radToDeg(t.pitch_rad), units::radToDeg(t.roll_rad)};
}

}  // namespace

InstalledPrediction predictInstalled(const VehicleProfile& v, const PreMissionPlan& plan,
                                     const std::vector<double>& installed_before_kg,
                                     const std::vector<double>& installed_after_kg) {
  if (installed_after_kg.size() != v.points.size()) {
    throw InputError("installed", "expected " + std::to_string(v.points.size()) + " values, got " +
                                      std::to_string(installed_after_kg.size()),
                     "give one installed mass per adjustment point, in profile order");
  }
  if (!installed_before_kg.empty() && installed_before_kg.size() != v.points.size()) {
    throw InputError("installed before", "expected one mass per adjustment point", "give the plan's installed masses");
  }
  if (plan.at_points.empty()) throw InputError("plan", "has no planned water", "compute the plan first");
  InstalledPrediction out;
  double added = 0.0;
  for (std::size_t p = 0; p < v.points.size(); ++p) {
    const double after = installed_after_kg[p];
    const AdjustmentPoint& ap = v.points[p];
    if (!std::isfinite(after) || after < 0.0) {
      throw InputError("installed." + ap.name, "must be a mass >= 0 kg", "enter the kit pieces now in '" + ap.label + "'");
    }
    if (ap.capacity_kg > 0.0 && after > ap.capacity_kg + 1e-9) {
      throw InputError("installed." + ap.name, "more than the point holds (" + std::to_string(ap.capacity_kg) + " kg)",
                       "check the mass entered for '" + ap.label + "'");
    }
    const double dm = after - (installed_before_kg.empty() ? 0.0 : installed_before_kg[p]);
    out.add_kg.push_back(dm);
    added += dm;
  }

  const MassProperties& m = plan.vehicle.mass;
  const double b_op = plan.at_points.front().displaced_kg;
  out.net_buoyancy_kg = b_op - m.mass_kg - added;
  const Attitude a = attitude(v, m.mass_kg, m.cg_m, out.add_kg, b_op);
  out.pitch_deg = a.pitch_deg;
  out.roll_deg = a.roll_deg;

  // The same uncertainty as the plan: the water's and the estimate's for
  // net buoyancy (the move itself is known), and the attitude's from the
  // estimate's mass and CG sigmas by central differences.
  out.net_sigma_kg = plan.net_sigma_kg;
  double vp = 0.0, vr = 0.0;
  auto vary = [&](double dm, const Eigen::Vector3d& dr) {
    if (dm == 0.0 && dr.isZero()) return;
    const Attitude hi = attitude(v, m.mass_kg + dm, m.cg_m + dr, out.add_kg, b_op);
    const Attitude lo = attitude(v, m.mass_kg - dm, m.cg_m - dr, out.add_kg, b_op);
    vp += std::pow(0.5 * (hi.pitch_deg - lo.pitch_deg), 2);
    vr += std::pow(0.5 * (hi.roll_deg - lo.roll_deg), 2);
  };
  vary(plan.vehicle.mass_sigma_kg, Eigen::Vector3d::Zero());
  vary(0.0, Eigen::Vector3d(plan.estimate.cg_x_sigma_m, 0, 0));
  vary(0.0, Eigen::Vector3d(0, plan.estimate.cg_y_sigma_m, 0));
  out.pitch_sigma_deg = std::sqrt(vp);
  out.roll_sigma_deg = std::sqrt(vr);

  const TrimSpec& spec = v.spec;
  constexpr double kKg = 1e-6, kDeg = 1e-9;  // the solver's closeness (0.1 g quanta)
  out.buoyancy_in_band = out.net_buoyancy_kg >= std::max(0.0, spec.net_buoyancy_min_kg) - kKg &&
                         out.net_buoyancy_kg <= spec.net_buoyancy_max_kg + kKg;
  out.pitch_in_band = std::abs(out.pitch_deg) <= spec.pitch_tolerance_deg + kDeg;
  out.roll_in_band = std::abs(out.roll_deg) <= spec.roll_tolerance_deg + kDeg;
  if (plan.flight_speed_mps > 0.0) {
    Eigen::Vector3d moment = m.mass_kg * m.cg_m;
    for (std::size_t p = 0; p < out.add_kg.size(); ++p) moment += out.add_kg[p] * v.points[p].position_m;
    out.flight_pitch_deg =
        flightPitchDeg(v, plan.flight_speed_mps, m.mass_kg + added, moment / (m.mass_kg + added), plan.at_points.front(),
                       plan.estimate.calibrated_hydrodynamics);  // the plan's own (calibrated) vehicle
    if (out.flight_pitch_deg) out.flight_pitch_in_band = std::abs(*out.flight_pitch_deg) <= spec.pitch_tolerance_deg + kDeg;
  }
  out.safe = true;
  for (const auto& r : plan.at_points) {
    const double net = r.displaced_kg - m.mass_kg - added;
    out.net_at_points_kg.push_back(net);
    if (net < plan.margin_kg - 1e-6) out.safe = false;
  }
  return out;
}

}  // namespace auv
