#pragma once
// Slocum tank method (Baird 2007, §4.1): the glider hangs submerged from two
// spring scales directly above its bow and aft ballast bottles. The dry mass
// minus the two readings is the mass it displaces in the tank water; thermal
// expansion of the aluminium hull carries that volume to the deployment
// water; the difference to the dry mass is the ballast to add, split between
// bow and aft so that the glider floats level (zero pitch).
#include <optional>
#include <string>
#include <vector>

#include "common/message.h"

#include "vehicle/vehicle_profile.h"
#include "weighing/roll_test.h"
#include "weighing/slocum_ballast.h"

namespace auv {

struct WaterSample {
  double density_kgm3 = 1000.0;
  double temperature_degC = 20.0;
};

struct TankReadings {
  double dry_mass_kg = 0.0;    // in air, as weighed
  double bow_scale_kg = 0.0;   // spring scale over the bow bottles, glider submerged
  double aft_scale_kg = 0.0;   // spring scale over the aft bottles
  WaterSample tank;            // water in the ballasting tank
  WaterSample target;          // deployment water
  double target_pressure_dbar = 0.0;  // 0 = neutral at the surface, as in the report
};

// Scale stations, x forward, measured from CB. The report splits the load
// half/half, which is these stations symmetric about CB.
struct ScaleStations {
  double bow_x_m = 0.5;
  double aft_x_m = -0.5;
};

struct TankBuoyancy {
  double scale_total_kg = 0.0;          // m_scale = bow + aft
  double tank_neutral_mass_kg = 0.0;    // m_buoy,tank = m_dry - m_scale = V_tank rho_tank
  double volume_tank_m3 = 0.0;
  double volume_target_m3 = 0.0;
  double target_neutral_mass_kg = 0.0;  // m_target = V_target rho_target
  double mass_change_kg = 0.0;          // m_target - m_dry; > 0 = add ballast
  double bow_change_kg = 0.0;           // ideal change at the bow bottles (continuous)
  double aft_change_kg = 0.0;
  double bow_share = 0.5;               // part of the apparent weight on the bow scale when level
  double level_bow_scale_kg = 0.0;      // tank readings once neutral and level
  double level_aft_scale_kg = 0.0;
  double cg_x_from_cb_m = 0.0;          // x_G - x_B as weighed (moments of the readings about CB)
};

// Report §4.1 equations, with the hull's volumetric expansion alpha and
// compressibility kappa: V_target = V_tank (1 + alpha (T_target - T_tank)) (1 - kappa p).
// Throws InputError naming the file field ("tank.bow_scale_g", ...).
TankBuoyancy tankBuoyancy(const TankReadings& r, const HullModel& hull, const ScaleStations& s);

// The readings the same tank would show with `mass_kg` added at station x_m
// (lever rule between the two scales; a mass at a scale station shows up
// entirely on that scale).
TankReadings withAddedMass(TankReadings r, const ScaleStations& s, double mass_kg, double x_m);

// The bottle changes in whole lead-shot pieces. The total is rounded down so
// the glider never ends heavier than neutral at the target; each pair keeps
// its port/starboard (upper/lower) split and shares the change equally,
// spilling into its partner (then into the other pair) at a full or empty
// bottle.
struct BottleStep {
  SlocumBallast after;
  double total_change_kg = 0.0;
  double bow_change_kg = 0.0;
  double aft_change_kg = 0.0;
  double mass_after_kg = 0.0;
  double net_buoyancy_after_kg = 0.0;  // m_target - mass after; >= 0 unless warned
  double bow_scale_after_kg = 0.0;     // predicted tank readings
  double aft_scale_after_kg = 0.0;
  std::vector<Message> warnings;  // weighing_messages.h ids
};

BottleStep planBottleStep(const TankBuoyancy& t, const TankReadings& r, const SlocumBallast& now,
                          const SlocumLayout& layout);

// The roll test as the technician records it: which rail the mass hung on,
// at what lever arm (default: the profile's hull radius, as in the report).
struct RollTestRecord {
  struct Hang {
    double mass_kg = 0.0;  // submerged mass
    bool starboard = false;
    double roll_rad = 0.0;
  };
  double initial_roll_rad = 0.0;
  std::optional<double> lever_arm_m;
  std::vector<Hang> applied;

  RollTest resolve(double default_lever_arm_m) const;
};

// One tank session as recorded in a weighing file
// (docs/formats/slocum-tank-weighing.md).
struct TankWeighing {
  std::string file;     // where it was read from ("" if built in code)
  std::string vehicle;  // profile id, "" = not stated
  std::string glider;   // serial / name, for the record
  TankReadings readings;
  double target_salinity_psu = 0.0;  // for the record only; density is the input
  SlocumBallast ballast;             // installed when weighed in the tank
  std::optional<double> battery_mass_kg;  // overrides the profile's roll battery
  // Bottle contents actually set after the tank step, if the technician has
  // already done it (report App. B). The roll test then refers to this state.
  std::optional<std::array<double, 4>> bottles_after_tank_step_kg;  // fore_port, fore_stbd, aft_upper, aft_lower
  std::optional<RollTestRecord> roll_test;
};

}  // namespace auv
