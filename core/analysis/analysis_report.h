#pragma once
// What a post-mission analysis hands to every front end (CLI text, JSON, GUI,
// the ballast solver). The JSON names are a contract (issue #3):
// net_buoyancy_kg, net_buoyancy_sigma_kg, cg_offset_mm {x, y} (CG - CB, body
// axes), errors {depth_m, pitch_deg, roll_deg}, water {temperature_degC,
// salinity_psu, density_kgm3}, segments [{kind, start_s, end_s}], warnings,
// and for gliders mass_to_add_g / mass_to_add_sigma_g. A quantity the log
// cannot determine is null and `not_identifiable` says why.
#include <limits>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/analysis_options.h"
#include "analysis/auv_trim_estimation.h"
#include "analysis/calibration_parameter.h"
#include "common/message.h"
#include "analysis/segments.h"
#include "analysis/statistics.h"

namespace auv::analysis {

struct EstimatedValue {
  bool known = false;
  double value = std::numeric_limits<double>::quiet_NaN();
  double sigma = std::numeric_limits<double>::quiet_NaN();
  Message why_not;  // "not identifiable from this log because ..." when !known
};

struct SegmentReport {
  SegmentKind kind = SegmentKind::kLevel;
  double start_s = 0.0, end_s = 0.0;
  bool used = false;  // an operating window the errors and estimates come from
  // Means over the segment (NaN where the log lacks the channel); only
  // operating windows carry them.
  double depth_m = std::numeric_limits<double>::quiet_NaN();
  double depth_error_m = std::numeric_limits<double>::quiet_NaN();
  double pitch_deg = std::numeric_limits<double>::quiet_NaN();
  double pitch_error_deg = std::numeric_limits<double>::quiet_NaN();
  double roll_deg = std::numeric_limits<double>::quiet_NaN();
  // 95 % half-widths of the three means above (statistics.h, per segment).
  double depth_error_ci95_m = std::numeric_limits<double>::quiet_NaN();
  double pitch_error_ci95_deg = std::numeric_limits<double>::quiet_NaN();
  double roll_ci95_deg = std::numeric_limits<double>::quiet_NaN();
  double speed_mps = std::numeric_limits<double>::quiet_NaN();
  double prop_rpm = std::numeric_limits<double>::quiet_NaN();
  double elevator_deg = std::numeric_limits<double>::quiet_NaN();
  double net_buoyancy_kg = std::numeric_limits<double>::quiet_NaN();
  double cg_x_mm = std::numeric_limits<double>::quiet_NaN();
  // An AUV dive or climb the calibration left out: its balance is not the
  // level legs' (note analysis.glides_dropped).
  bool calibration_dropped = false;
};

struct AnalysisReport {
  std::string vehicle_id, vehicle_kind, log_name;
  std::size_t rows = 0;
  double duration_s = 0.0;

  EstimatedValue net_buoyancy_kg;  // positive = too light
  EstimatedValue cg_x_mm, cg_y_mm;  // CG - CB
  std::string cg_y_basis;
  // Roll at the cruise propeller speed and the CG y that levels the vehicle
  // there (propeller torque included): what the planner zeroes (thesis
  // §5.3.3 judges roll at 160 rpm, not at rest).
  double cruise_rpm = std::numeric_limits<double>::quiet_NaN();
  double cruise_speed_mps = std::numeric_limits<double>::quiet_NaN();
  EstimatedValue cruise_roll_deg, cruise_cg_y_mm;
  // The cruise once trimmed, when its speed (and so the torque) differs from
  // the log's: cruise_cg_y_mm then includes the torque change.
  std::optional<TrimmedCruise> cruise_trimmed;
  // Gliders: signed grams to add for neutral buoyancy, pump at zero, in the
  // target water (density, pressure, temperature; `target_basis` says where
  // they came from).
  EstimatedValue mass_to_add_g;
  double target_density_kgm3 = std::numeric_limits<double>::quiet_NaN();
  double target_pressure_dbar = std::numeric_limits<double>::quiet_NaN();
  double target_temperature_degC = std::numeric_limits<double>::quiet_NaN();
  std::string target_basis;

  // Errors (thesis sign conventions): depth commanded - measured, pitch
  // measured - commanded (or pitch at steady depth without a command), roll
  // at cruise (starboard down positive).
  MeanEstimate depth_error_m, pitch_error_deg, pitch_at_steady_depth_deg, roll_deg;
  Message pitch_error_basis;
  // Water at operating depth (in situ).
  MeanEstimate temperature_degC, salinity_psu, density_kgm3, pressure_dbar, depth_m;
  std::string salinity_source, density_source;

  // Vehicle constants the analysis calibrated with the ballast state (JSON
  // `calibration`), empty when there was nothing to calibrate.
  std::vector<CalibrationParameter> calibration;
  // AUVs: the steady segments the estimate used, with their absolute
  // buoyancy, so a later mission can calibrate from this one (typed, not JSON).
  std::vector<SteadySegmentMeans> steady_segments;
  // AUVs: the accepted attitude sensor biases (attitude_sensor_bias.h) taken
  // out of the log before the analysis, so out of steady_segments too, deg
  // (JSON details.auv_estimate.attitude_bias_removed_deg). A later mission
  // analysed with another accepted bias re-references these segments.
  double pitch_bias_removed_deg = 0.0, roll_bias_removed_deg = 0.0;

  std::vector<SegmentReport> segments;  // phases, then operating windows, in time order
  // Advice with message ids (common/message.h): the English is what the CLI prints.
  std::vector<Message> warnings;
  std::vector<Message> notes;
  nlohmann::json details = nlohmann::json::object();  // model-specific extras (fit, classic mode)
  // What analyzeMission was asked (typed, not JSON): a later re-analysis of
  // the same log (the model check's, with a found sensor bias taken out)
  // runs with the same history, BG, priors and options. Unset for a report
  // not made by analyzeMission here.
  std::optional<AnalysisOptions> options;
};

nlohmann::json toJson(const AnalysisReport& r);
std::string toText(const AnalysisReport& r);

// The calibration parameter `id` of the report; null when it has none.
const CalibrationParameter* calibrationParameter(const AnalysisReport& r, std::string_view id);

}  // namespace auv::analysis
