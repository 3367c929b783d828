#include "sim/flown_mass.h"

#include <string>

#include "common/input_error.h"
#include "common/units.h"
#include "vehicle/installed_check.h"

namespace auv::sim {

FlownMass flownMass(const VehicleModel& model, std::span<const MassItem> extra,
                    const std::optional<double>& net_buoyancy_n, const BallastError& error, double B0) {
  return flownMass(model.body.mass_kg, model.body.r_g_m, model.body.cb_profile_m, extra, net_buoyancy_n, error, B0);
}

FlownMass flownMass(double mass_kg, const Eigen::Vector3d& r_g_m, const Eigen::Vector3d& cb_profile_m,
                    std::span<const MassItem> extra, const std::optional<double>& net_buoyancy_n,
                    const BallastError& error, double B0) {
  FlownMass f;
  Eigen::Vector3d moment = mass_kg * r_g_m;
  f.mass_kg = mass_kg;
  for (const MassItem& item : extra) {
    const Eigen::Vector3d r = item.position_m - cb_profile_m;
    f.mass_kg += item.mass_kg;
    moment += item.mass_kg * r;
    f.extra_Ixx += item.mass_kg * (r.y() * r.y() + r.z() * r.z());
    f.extra_Iyy += item.mass_kg * (r.x() * r.x() + r.z() * r.z());
  }
  if (!(f.mass_kg > 0.0)) {
    throw InputError("extra_masses", "the vehicle mass would not be positive", "check the ballast changes");
  }
  f.r_g_m = moment / f.mass_kg;
  if (net_buoyancy_n) f.mass_kg = (B0 - *net_buoyancy_n) / units::g0;  // trim mass at the CG
  f.mass_kg -= error.net_buoyancy_kg;
  f.r_g_m += error.cg_shift_m;
  if (!(f.mass_kg > 0.0)) {
    throw InputError("net_buoyancy", "the vehicle mass would not be positive", "check the net buoyancy asked for");
  }
  return f;
}

std::vector<MassItem> installedWeights(const VehicleProfile& profile, std::span<const double> kg) {
  checkInstalledKg(profile, kg, "installed");
  std::vector<MassItem> items;
  for (std::size_t i = 0; i < kg.size(); ++i) {
    const AdjustmentPoint& p = profile.points[i];
    items.push_back({kg[i], p.position_m});
  }
  return items;
}

}  // namespace auv::sim
