#pragma once
// The analysis's advice (notes, warnings, why an estimate is unknown) as
// message ids with English formats: the CLI prints the English, the wizard
// translates by id (ui/wizard/advice_text.*). The English is the text the
// CLI printed before the ids existed; keep it when rewording the wizard's.
#include "common/message.h"

namespace auv::analysis::msg {

#define AUV_NOT_ID "not identifiable from this log because "
inline constexpr MessageFormat kNoSteadyGlide{
    "analysis.no_steady_glide", "no steady dive or climb long enough was found: nothing to estimate from"};
inline constexpr MessageFormat kNoSteadyLevel{
    "analysis.no_steady_level",
    "no steady level-flight segment of at least %1 s was found: errors and estimates are not available"};
inline constexpr MessageFormat kWindowExcluded{"analysis.window_excluded",
                                               "%1: %2 interval(s), %3 s excluded from steady windows"};
inline constexpr MessageFormat kAveragedLegs{
    "analysis.averaged_legs",
    "%1 leg(s) flown in a slow oscillation were averaged over whole cycles instead of steady windows"};
inline constexpr MessageFormat kDepthNotHeldLight{
    "analysis.depth_not_held_light",
    "for %1 min at constant commands the vehicle stayed %2 m shallower than commanded (median) with its elevator at the "
    "stop (%3 deg): it is too light or too stern-heavy for its planes at this speed, so this log measures little of its "
    "ballast. Add weight forward in a small step and make a short test dive before a survey"};
inline constexpr MessageFormat kDepthNotHeldHeavy{
    "analysis.depth_not_held_heavy",
    "for %1 min at constant commands the vehicle stayed %2 m deeper than commanded (median) with its elevator at the "
    "stop (%3 deg): it is too heavy or too bow-heavy for its planes at this speed, so this log measures little of its "
    "ballast. Remove weight forward in a small step and make a short test dive before a survey"};
inline constexpr MessageFormat kPorpoising{
    "analysis.porpoising",
    "%1 constant-command leg(s), %2 min in all, were flown porpoising (pitch standard deviation up to %3 deg, period "
    "about %4 s) and hold no steady flight: the depth autopilot limit-cycles on this vehicle, and the estimate rests on "
    "the rest of the log. Retune the depth loop (lower gains) or raise BG; moving weights along the hull will not stop it"};
inline constexpr MessageFormat kAttitudeBiasRemoved{
    "analysis.attitude_bias_removed",
    "the logged pitch and roll were corrected by the attitude sensor biases the profile holds (accepted from a model "
    "check): pitch %1 +- %2 deg, roll %3 +- %4 deg (reading minus true); their sigmas are in the ballast state's"};
inline constexpr MessageFormat kPitchSensorBiasFound{
    "analysis.pitch_sensor_bias_found",
    "the legs fit one steady balance only with the pitch sensor reading %1 +- %2 deg more than the vehicle's pitch "
    "(reading minus true; its prior 0 +- %3 deg): the net buoyancy, CG and predicted flight pitch are of the true "
    "attitude, the logged pitch is not. Align the sensor, or keep the bias with 'model-check --accept'"};
inline constexpr MessageFormat kPitchBasisGlide{"analysis.pitch_basis_glide",
                                                "measured - commanded, during glides whose command has the phase's sign"};
inline constexpr MessageFormat kPitchBasisLevel{"analysis.pitch_basis_level", "measured - commanded, in steady level flight"};
inline constexpr MessageFormat kPitchBasisNoCommand{
    "analysis.pitch_basis_no_command", "pitch at steady depth (the log has no pitch_cmd; level flight should be at 0 deg)"};
inline constexpr MessageFormat kNoDepthCommand{"analysis.no_depth_command",
                                               "the log has no depth_cmd channel: errors.depth_m is not available"};
inline constexpr MessageFormat kCtdOutOfRange{"analysis.ctd_out_of_range",
                                              "%1 CTD samples outside the EOS-80 range were not used for density"};
inline constexpr MessageFormat kNoDensity{
    "analysis.no_density",
    "no in-situ density could be computed (no temperature/salinity or density channel): %1 kg/m3 assumed"};
inline constexpr MessageFormat kGliderCgX{
    "analysis.glider_cg_x", AUV_NOT_ID "a glider's pitch is set by its battery position, "
                                       "not by a fixed CG (use the tank or pitch-trim procedure)"};
inline constexpr MessageFormat kGliderCgY{
    "analysis.glider_cg_y", AUV_NOT_ID "the glider's roll is set by its roll mass (use the tank procedure)"};
inline constexpr MessageFormat kNoPumpVolume{"analysis.no_pump_volume",
                                             AUV_NOT_ID "the log has no pump_volume channel (the buoyancy engine's volume)"};
inline constexpr MessageFormat kNoPitch{"analysis.no_pitch", AUV_NOT_ID "the log has no pitch channel"};
inline constexpr MessageFormat kNoSteadyDiveOrClimb{"analysis.no_steady_dive_or_climb",
                                                   AUV_NOT_ID "no steady dive or climb was found"};
inline constexpr MessageFormat kFewGlideSamples{
    "analysis.few_glide_samples", AUV_NOT_ID "fewer than 10 steady-glide samples deeper than %1 m with |pitch| >= %2 deg"};
inline constexpr MessageFormat kLogMassDiffers{
    "analysis.log_mass_differs",
    "the log says mass_kg %1 but the profile has %2 kg: the fit uses the profile mass (it matters only through "
    "density changes)"};
inline constexpr MessageFormat kGliderFitNotConverged{"analysis.glider_fit_not_converged", "glider flight-model fit: %1"};
inline constexpr MessageFormat kGliderDefaultConstants{
    "analysis.glider_default_constants",
    "glider flight-model constants are gliderflight's Slocum defaults (S = 0.1 m2, lift slope 7.53 /rad, "
    "Cd1 = 10.5 /rad2): add a \"flight_model\" section to the profile for another glider"};
inline constexpr MessageFormat kGliderDefaultCompressibility{
    "analysis.glider_default_compressibility",
    "hull compressibility not in the profile: gliderflight's 5e-10 1/Pa (5e-6 1/dbar) is used"};
// AUV trim (auv_trim_estimation.cpp).
inline constexpr MessageFormat kNoRollSamples{"analysis.no_roll_samples", AUV_NOT_ID "no steady segment has roll samples"};
inline constexpr MessageFormat kNoPropRpm{
    "analysis.no_prop_rpm",
    "the log has no prop_rpm channel: CG y assumes the roll at cruise is static; any propeller reaction torque is "
    "included in it"};
inline constexpr MessageFormat kOneCruiseRpm{
    "analysis.one_cruise_rpm",
    "all steady segments run the propeller at about the same speed, so its reaction torque cannot be separated "
    "from a CG offset: cg_offset_mm.y is the offset that levels the vehicle at this cruise rpm, not the static CG"};
inline constexpr MessageFormat kCgYNeedsBg{
    "analysis.cg_y_needs_bg",
    AUV_NOT_ID "a steady roll gives y = BG tan(roll) and BG (the CG height below the CB) cannot be measured from the "
               "log: give --bg-mm from an inclining or roll test (static roll %1 deg)"};
inline constexpr MessageFormat kNoSteadyLevelSegment{"analysis.no_steady_level_segment",
                                                     AUV_NOT_ID "no steady level-flight segment long enough was found"};
inline constexpr MessageFormat kNoSpeed{
    "analysis.no_speed",
    AUV_NOT_ID "the log has no speed channel (the lift and moment that balance them scale with speed squared)"};
inline constexpr MessageFormat kNoSpeedAndPitch{"analysis.no_speed_and_pitch",
                                                AUV_NOT_ID "no steady segment has both speed and pitch samples"};
inline constexpr MessageFormat kNoElevator{
    "analysis.no_elevator",
    AUV_NOT_ID "the log has no elevator channel: with the plane angle unknown, each steady segment only fixes the "
               "moment W x_G - l (B - W) about the planes' centre of pressure (l = %1 m), at any speed; record the "
               "elevator (stern-plane) angle"};
inline constexpr MessageFormat kHistoryCalibration{
    "analysis.history_calibration",
    "calibrated with %1 steady segments of earlier missions of this configuration and the known weight changes since"};
inline constexpr MessageFormat kHistoryUnreadable{
    "analysis.history_unreadable",
    "the earlier mission of configuration %1 could not be read from the history (%2): this log is analysed alone, "
    "without the known weight change since"};
inline constexpr MessageFormat kThrusterSegmentsLeftOut{
    "analysis.thruster_segments_left_out",
    "%1 steady segment(s) left out: the tunnel thrusters ran there (up to %2 rpm), and the steady balance has no "
    "thruster term (the model check replays them)"};
inline constexpr MessageFormat kThrustersInEverySegment{
    "analysis.thrusters_in_every_segment",
    AUV_NOT_ID "the tunnel thrusters ran in all %1 steady segment(s) (up to %2 rpm) and carry an unknown part of the "
    "net buoyancy, which the steady balance has no term for; fly steady legs above the thrusters' hand-over speed, "
    "or use the model check, which replays them"};
inline constexpr MessageFormat kGlidesDropped{
    "analysis.glides_dropped",
    "%1 dive(s) or climb(s) held a steady pitch but did not fit the balance the other legs calibrated (the depth "
    "changed at a pitch and elevator no steady flight has): left out of the estimate"};
inline constexpr MessageFormat kTransientsDropped{
    "analysis.transients_dropped",
    "the depth steps and speed changes disagreed among themselves more than they added (net buoyancy +- %1 kg with "
    "them, +- %2 kg from the steady segments alone): the estimate is the steady segments'"};
inline constexpr MessageFormat kCalibrationPriorConflict{
    "analysis.calibration_prior_conflict",
    "the log put %1 at %2 where the profile has %3 +- %4: more than three prior sigmas away, which no vehicle of "
    "this class has, so "
    "the steady balance did not describe this log (a pitch sensor bias, legs that were not steady, or a profile "
    "of another vehicle); the net buoyancy and CG rest on that balance, so check the attitude sensor's alignment "
    "and the profile before moving weights"};
inline constexpr MessageFormat kTransientsNotFlownAsCommanded{
    "analysis.transients_not_flown_as_commanded",
    "the depth steps and speed changes were not flown again (--transients): the vehicle did not fly as commanded "
    "(too light or porpoising), and there the replay fits its plane stop and autopilot instead of its hydrodynamics; "
    "the estimate is the steady segments'"};
inline constexpr MessageFormat kTransientsWithHistory{
    "analysis.transients_with_history",
    "the depth steps and speed changes were not flown again (--transients): the earlier missions and the known "
    "weight changes calibrate the vehicle, and the replay added model error, not information"};
inline constexpr MessageFormat kDegenerate{
    "analysis.degenerate",
    AUV_NOT_ID "the steady segments do not determine the heave and pitch balance (degenerate geometry)"};
inline constexpr MessageFormat kElevatorOffsetPrior{
    "analysis.elevator_offset_prior",
    "elevator zero offset assumed 0 +- %1 deg (its prior, in the sigmas): " AUV_NOT_ID
    "the steady segments do not span enough speeds to separate it from the net buoyancy"};
inline constexpr MessageFormat kPlaneSignConverted{
    "analysis.plane_sign_converted",
    "plane derivatives converted from trailing-edge-up-positive to the log's trailing-edge-down-positive elevator"};
inline constexpr MessageFormat kJointCalibration{
    "analysis.joint_calibration",
    "hydrodynamics calibrated jointly with the ballast state (%1 parameters determined by the log); identified: %2; "
    "at their prior: %3"};
inline constexpr MessageFormat kPosteriorSigmas{
    "analysis.posterior_sigmas", "sigmas are the calibration's posterior (prior %1 % per group of hydrodynamic derivatives)"};
inline constexpr MessageFormat kPosteriorSigmasMunk{
    "analysis.posterior_sigmas_munk",
    "sigmas are the calibration's posterior (prior %1 % per group of hydrodynamic derivatives, Munk moment inside "
    "M_w or on top unknown)"};
inline constexpr MessageFormat kBgFromProfile{
    "analysis.bg_from_profile",
    "BG from the profile (%1 mm +- %2 %) sets the scale of the pitch moments; --bg-mm from a roll test sharpens CG x"};
inline constexpr MessageFormat kTrimmedCruise{
    "analysis.trimmed_cruise",
    "trimmed, the vehicle should cruise at %1 m/s at %2 rpm (the log: %3 m/s); the propeller torque there changes by "
    "%4 N m, which the cruise CG y for the plan includes (%5 mm)"};
#undef AUV_NOT_ID

// Every analysis message, for completeness checks of the translations.
inline constexpr const MessageFormat* kAll[] = {
    &kNoSteadyGlide, &kNoSteadyLevel, &kWindowExcluded, &kAveragedLegs, &kDepthNotHeldLight, &kDepthNotHeldHeavy, &kPorpoising, &kPitchSensorBiasFound, &kPitchBasisGlide, &kPitchBasisLevel, &kPitchBasisNoCommand,
    &kNoDepthCommand, &kCtdOutOfRange, &kNoDensity, &kGliderCgX, &kGliderCgY, &kNoPumpVolume, &kNoPitch, &kNoSteadyDiveOrClimb, &kFewGlideSamples,
    &kLogMassDiffers, &kGliderFitNotConverged, &kGliderDefaultConstants, &kGliderDefaultCompressibility,
    &kNoRollSamples, &kNoPropRpm, &kOneCruiseRpm, &kCgYNeedsBg, &kNoSteadyLevelSegment, &kNoSpeed, &kNoSpeedAndPitch,
    &kNoElevator, &kHistoryCalibration, &kHistoryUnreadable, &kThrusterSegmentsLeftOut, &kThrustersInEverySegment, &kTransientsDropped, &kGlidesDropped, &kCalibrationPriorConflict, &kTransientsNotFlownAsCommanded, &kTransientsWithHistory, &kDegenerate, &kElevatorOffsetPrior, &kPlaneSignConverted, &kJointCalibration,
    &kPosteriorSigmas, &kPosteriorSigmasMunk, &kBgFromProfile, &kTrimmedCruise};

}  // namespace auv::analysis::msg
