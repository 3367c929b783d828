#pragma once
// The mass and CG the simulated vehicle flies with: its profile's reference
// configuration, plus the adjustment weights installed at the profile's points
// and any other ballast changes, optionally trimmed to a net buoyancy, plus a
// deliberate ballast error (the vehicle as built differs from what its
// owner believes). Shared by plan simulation and replay so that both fly the
// same vehicle for the same description.
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "hydrostatics/mass_properties.h"
#include "sim/vehicle_model.h"
#include "vehicle/vehicle_profile.h"

namespace auv::sim {

// Applied last. Positive net buoyancy = lighter: a mass of -net_buoyancy_kg
// at the CG (the CG stays put); the CG then moves by cg_shift_m with the
// total mass unchanged (weight moved inside the hull). This is the "known
// error" a round-trip test expects the analysis to recover.
struct BallastError {
  double net_buoyancy_kg = 0.0;
  Eigen::Vector3d cg_shift_m = Eigen::Vector3d::Zero();
};

struct VehicleLoading {
  // Masses relative to the profile's reference configuration, positions in
  // the profile's frame (installed adjustment weights, ballast changes).
  std::vector<MassItem> extra_masses;
  // If set: trim with a mass at the CG so that B - W equals this [N] at the
  // start depth, as when a vehicle is ballasted in a test tank.
  std::optional<double> net_buoyancy_n;
  BallastError error;
};

struct FlownMass {
  double mass_kg = 0.0;
  Eigen::Vector3d r_g_m = Eigen::Vector3d::Zero();  // CG relative to CB, body axes
  double extra_Ixx = 0.0, extra_Iyy = 0.0;
};

// `buoyancy_at_start_n` is used only for the net-buoyancy trim. Throws
// InputError if the mass would not be positive.
FlownMass flownMass(const VehicleModel& model, std::span<const MassItem> extra_masses,
                    const std::optional<double>& net_buoyancy_n, const BallastError& error,
                    double buoyancy_at_start_n);
// The same from a reference mass, its CG relative to the CB and the CB in
// the profile's frame (vehicles without a VehicleModel, e.g. gliders).
FlownMass flownMass(double mass_kg, const Eigen::Vector3d& r_g_m, const Eigen::Vector3d& cb_profile_m,
                    std::span<const MassItem> extra_masses, const std::optional<double>& net_buoyancy_n,
                    const BallastError& error, double buoyancy_at_start_n);

// Adjustment weights at the profile's points, in profile order ("--installed
// FS,FP,AS,AP"). Throws InputError("installed") on a count mismatch or a
// negative or over-capacity mass.
std::vector<MassItem> installedWeights(const VehicleProfile& profile, std::span<const double> kg);

}  // namespace auv::sim
