#pragma once
// A vehicle as the ballast tools see it: its hull (volume, CB, how the volume
// changes with pressure and temperature), its mass properties in the reference
// configuration, the points where weights can be placed and the kit of pieces.
// All quantities SI (m, kg, 1/dbar, 1/degC); files use unit-suffixed names.
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace auv {

struct AdjustmentPoint {
  std::string name;          // stable id, e.g. "fore_starboard"
  std::string label;         // for people, e.g. "Fore / starboard"
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  // body axes: x fwd, y stbd, z down
  double capacity_kg = 0.0;  // most adjustment mass the point can hold
};

struct WeightKit {
  std::vector<double> pieces_kg;           // standard sizes, available in any number
  std::vector<double> optional_pieces_kg;  // sizes the operator may enable (e.g. 0.5 kg)
};

// Hull volume V(T, p) = V0 * (1 + alpha (T - T0)) * (1 - kappa p).
struct HullModel {
  double volume_m3 = 0.0;                   // V0 at reference temperature, p = 0
  double reference_temperature_degC = 20.0;  // T0
  double thermal_expansion_per_degC = 0.0;   // alpha, volumetric
  double compressibility_per_dbar = 0.0;     // kappa
  double length_m = 0.0;
  double diameter_m = 0.0;

  double volumeAt(double temperature_degC, double pressure_dbar) const {
    return volume_m3 * (1.0 + thermal_expansion_per_degC * (temperature_degC - reference_temperature_degC)) *
           (1.0 - compressibility_per_dbar * pressure_dbar);
  }
};

// Acceptance bands for a ballasted vehicle (thesis §5.1 item 7 by default).
struct TrimSpec {
  double net_buoyancy_min_kg = 0.0;  // never negative
  double net_buoyancy_max_kg = 1.2;
  double pitch_tolerance_deg = 0.5;
  double roll_tolerance_deg = 0.1;
};

struct VehicleProfile {
  std::string id;
  std::string name;
  std::string kind;    // "auv" or "glider"
  std::string source;  // where the numbers come from
  std::string file;    // the profile file it was loaded from

  HullModel hull;
  double mass_kg = 0.0;                                   // in air, reference configuration
  Eigen::Vector3d cb_m = Eigen::Vector3d::Zero();         // centre of buoyancy
  std::optional<Eigen::Vector3d> cg_m;                    // nominal CG if known
  double bg_m = 0.0;  // z_G - z_B, CG below CB positive (static stability)

  std::vector<AdjustmentPoint> points;
  WeightKit kit;
  TrimSpec spec;

  // Vehicle-specific sections ("slocum", "hydrodynamics", ...) that the
  // module owning them parses and validates with JsonReader.
  nlohmann::json sections = nlohmann::json::object();
  std::string sections_file;  // companion file the estimated sections came from, if any

  const AdjustmentPoint* findPoint(const std::string& point_name) const;
};

}  // namespace auv
