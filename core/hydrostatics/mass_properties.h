#pragma once
// Mass and centre of gravity of a system of particles (thesis eq. 2.8 / 4.1).
#include <Eigen/Core>
#include <span>

namespace auv {

struct MassItem {
  double mass_kg = 0.0;  // may be negative for a removed piece
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
};

struct MassProperties {
  double mass_kg = 0.0;
  Eigen::Vector3d cg_m = Eigen::Vector3d::Zero();
  // First moment sum(m_i r_i); kept so that items can be added exactly.
  Eigen::Vector3d moment_kgm = Eigen::Vector3d::Zero();

  MassProperties& add(const MassItem& item);
};

// Throws InputError if the total mass is not positive (a CG is then undefined).
MassProperties massProperties(std::span<const MassItem> items);

}  // namespace auv
