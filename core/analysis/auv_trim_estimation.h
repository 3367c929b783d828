#pragma once
// Net buoyancy and CG offset of an AUV from its steady level-flight segments:
// the heave force and pitch moment balance of auv_steady_model.h, one pair of
// equations per segment, solved by generalised least squares for
// (B - W, x_G) and, when the segments fly at different speeds, the elevator
// zero offset. CG y comes from the roll moment balance, y = BG tan(roll),
// with the propeller reaction torque (proportional to rpm^2) separated when
// the log has several propeller speeds. Whatever the log cannot separate is
// reported as not identifiable with the reason, never guessed.
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "common/message.h"
#include "analysis/auv_calibration.h"
#include "analysis/auv_steady_model.h"
#include "analysis/statistics.h"
#include "sim/vehicle_model.h"

namespace auv::analysis {

// Means of one steady segment (each from its own channel's samples).
struct SteadySegmentMeans {
  double start_s = 0.0, end_s = 0.0;
  MeanEstimate speed_mps, pitch_deg, roll_deg, elevator_deg, depth_rate_mps, prop_rpm;
  // In-situ density over the segment and the buoyancy change relative to the
  // reference water (density and hull law), known from the CTD: a segment at
  // another depth is a known change of the net buoyancy.
  double density_kgm3 = std::numeric_limits<double>::quiet_NaN();
  double buoyancy_change_n = 0.0;
  double buoyancy_n = std::numeric_limits<double>::quiet_NaN();  // rho_i V_i g, absolute
  // The segment's mean pressure and temperature (NaN = not logged): the
  // calibration's levers on the hull law (hullLawLevers), which the
  // profile may have wrong.
  double pressure_dbar = std::numeric_limits<double>::quiet_NaN();
  double temperature_degC = std::numeric_limits<double>::quiet_NaN();
  // d buoyancy_change_n / d(extra compressibility) [N dbar], / d(extra
  // thermal expansion) [N degC] and / d(mass drift) [N per kg/h]: set by
  // the caller (0 = none).
  double compressibility_lever_n = 0.0, thermal_lever_n = 0.0, drift_lever_n = 0.0;
  // Averaged legs (averaged_legs.h): the cycle means of the balance's
  // products (auv_steady_model.h); unset = a steady window.
  std::optional<BalanceRegressors> regressors = std::nullopt;
  // History segments only (see CalibrationSegment): set by the caller.
  double weight_n = 0.0, moment_offset_nm = 0.0;
  bool from_history = false;
  bool glide = false;  // a steady dive or climb (kGlide), not a level leg
  // The largest mean |rpm| of the vehicle's tunnel thrusters over the
  // segment, when they ran above their deadband: the steady balance has no
  // thruster term, so such a segment is left out (0 = they did not run).
  double thruster_rpm = 0.0;
};

struct AuvTrimContext {
  double weight_n = 0.0;        // as flown (profile mass + installed adjustment weights)
  double density_kgm3 = 1025.0;
  std::optional<double> bg_measured_m;  // --bg-mm: needed for CG y
  double bg_profile_m = 0.0;            // used for the small BG sin(theta) term of x
  double bg_profile_rel_sigma = 0.25;
  double hull_compressibility_per_dbar = 0.0, hull_thermal_expansion_per_degC = 0.0;  // the profile's hull law
  double bg_measured_sigma_m = 0.0005;  // a roll test's accuracy
  // Prior width of every hydrodynamic derivative group; unset = 30 % and an
  // unknown Munk structure (0.5 +- 0.5) unless the profile states it; set
  // (--coefficient-sigma) = that width for every group, Munk as the profile says.
  std::optional<double> coefficient_rel_sigma;
  double pitch_alignment_sigma_deg = 1.0;  // CalibrationPriors::pitch_alignment_sigma_deg
  // Open-water law of the propeller (the simulator's K_T = K_T0 (1 - (J/c1)^c2),
  // torque taken proportional to K_T): the torque regressor is rpm^2 K_T/K_T0
  // at each segment's advance ratio, not rpm^2 alone. Unset = rpm^2.
  struct PropellerLaw {
    double diameter_m = 0.0, c1 = 1.0, c2 = 1.0, wake_fraction = 0.0;
  };
  std::optional<PropellerLaw> propeller;
  // Steady segments of earlier missions of this configuration with their
  // known weight changes (calibration from the history): they share the
  // vehicle's hydrodynamics, not its roll.
  std::vector<SteadySegmentMeans> history;
  // Propeller torque at 100 rpm the profile assumes (sim_assumptions), N m; 0 = none.
  double profile_torque_nm_per_100rpm2 = 0.0;
  double min_speed2_spread = 1.3;       // max(u^2)/min(u^2) needed to fit the elevator zero offset
  bool log_has_speed = false, log_has_elevator = false, log_has_rpm = false;
  // The log's transients through the simulator (auv_transient_fit.h), fitted
  // jointly with the steady segments; empty = steady segments only.
  TransientResiduals transients;
  std::size_t transient_windows = 0;
  // The simulator's model of the vehicle, for the surge balance of the
  // trimmed cruise (trimmed_cruise.h); unset = the logged cruise speed stays.
  std::optional<sim::VehicleModel> surge_model;
};

// The cruise speed after a move that trims the vehicle, and the torque change
// it brings (trimmed_cruise.h).
struct TrimmedCruise {
  double rpm = 0.0;
  double logged_speed_mps = 0.0;  // mean of the cruise-rpm level segments
  double speed_mps = 0.0;         // predicted: level at the planned net buoyancy and CG x
  // The drag the log shows beyond the model's, as k u^2 (N s^2/m^2): the
  // surge balance of the model at the logged segments, which hold speed.
  double extra_drag_n_per_mps2 = 0.0;
  double torque_change_nm = 0.0;  // reaction torque at the trimmed speed minus at the logged one, roll sign
  double y_shift_m = 0.0;         // what that adds to the cruise-equivalent CG y (torque / weight)
};

struct AuvTrimEstimate {
  bool buoyancy_identified = false, x_identified = false, y_identified = false;
  Message buoyancy_why, x_why, y_why;  // "not identifiable from this log because ..."
  double net_buoyancy_kg = 0.0, net_buoyancy_sigma_kg = 0.0;
  double x_m = 0.0, x_sigma_m = 0.0;
  double y_m = 0.0, y_sigma_m = 0.0;
  std::string y_basis;  // "static", "static (propeller torque fitted)", "cruise_equivalent", "static_assumed"
  double roll_static_deg = 0.0, roll_static_sigma_deg = 0.0;
  bool roll_static_known = false;
  // Roll at the cruise propeller speed (the highest rpm flown 10 min or more),
  // thesis's roll criterion (§5.3.3: zero at 160 rpm), and the CG y that
  // would give that roll at rest: zeroing it levels the vehicle in cruise,
  // propeller torque included. From the torque fit where there is one, so
  // the fit's own bias cancels when the plan zeroes it.
  bool cruise_known = false, y_cruise_identified = false;
  double cruise_rpm = 0.0, cruise_roll_deg = 0.0, cruise_roll_sigma_deg = 0.0;
  double cruise_speed_mps = std::numeric_limits<double>::quiet_NaN();
  double y_cruise_m = 0.0, y_cruise_sigma_m = 0.0;
  bool elevator_bias_fitted = false;
  double elevator_bias_deg = 0.0, elevator_bias_sigma_deg = 0.0;
  double chi2_per_dof = 0.0;
  std::size_t segments_used = 0;
  std::size_t history_segments_used = 0;  // steady segments of earlier missions in the calibration
  std::vector<double> segment_net_buoyancy_kg, segment_x_m;  // NaN where not computable
  // Per segment: a glide the calibration left out (its balance is not the
  // other legs'); not written to the steady segments a later mission reads.
  std::vector<bool> segment_dropped;
  // Without an elevator channel only W x_G - l (B - W) is determined (l = M_e/Z_e).
  std::optional<double> moment_combination_nm, moment_combination_sigma_nm, plane_lever_m;
  // Identified hydrodynamic groups and propeller torque (issue 11), and the
  // steady coefficients with the calibrated groups for forward prediction.
  std::vector<CalibrationParameter> calibration;
  std::optional<SteadyHydroCoefficients> calibrated;
  double net_x_correlation = 0.0;
  // A short addition to the next mission that would identify the rest
  // (issue 11 item 5), with the sigmas predicted after it from the Fisher
  // information of the same model.
  struct Manoeuvre {
    // What to fly, for a mission planner: propeller speed, depth rate
    // (positive down; 0 = level at the operating depth) and duration.
    struct Leg {
      double rpm = 0.0, depth_rate_mps = 0.0, duration_s = 0.0;
    };
    std::vector<std::string> legs;  // the same, in words for the technician
    std::vector<Leg> flight;
    double net_sigma_kg = 0.0, x_sigma_m = 0.0;
  };
  std::optional<Manoeuvre> manoeuvre;
  // The move is itself a calibration (item 3): the next mission's survey,
  // flown after a move to mid-band (or the safety margin) and level flight
  // and analysed with this log as history, predicted from the same Fisher
  // information.
  struct AfterMove {
    double net_sigma_kg = 0.0, x_sigma_m = 0.0;
    double net_kg = 0.0, x_g_m = 0.0;  // the state assumed after the move
  };
  std::optional<AfterMove> after_move;
  // Set when the trimmed vehicle cruises at another speed than the log's:
  // y_cruise_m then holds the torque change (y_shift_m).
  std::optional<TrimmedCruise> trimmed_cruise;
  std::vector<Message> notes, warnings;
};

AuvTrimEstimate estimateAuvTrim(std::span<const SteadySegmentMeans> segments, const SteadyHydroCoefficients* coeffs,
                                const std::string& no_coefficients_reason, const AuvTrimContext& ctx);

}  // namespace auv::analysis
