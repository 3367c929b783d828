#include "wizard/advice_text.h"

#include "widgets/inputs.h"

#include <QCoreApplication>
#include <QHash>
#include <QRegularExpression>
#include <cmath>

namespace auv::ui {
namespace {

// id -> the wizard's English sentence (%1.. as in core's format; a sentence
// may leave out an argument the page shows elsewhere).
struct Advice {
  const char* id;
  const char* text;
};

// clang-format off
constexpr Advice kAdvice[] = {
  // Analysis (core/analysis/analysis_messages.h).
  {"analysis.no_steady_glide", QT_TRANSLATE_NOOP("Advice", "No steady dive or climb long enough was found: nothing to estimate from.")},
  {"analysis.no_steady_level", QT_TRANSLATE_NOOP("Advice", "No steady level flight of at least %1 s was found: errors and estimates are not available.")},
  {"analysis.window_excluded", QT_TRANSLATE_NOOP("Advice", "%1: %2 interval(s), %3 s left out of the steady windows.")},
  {"analysis.averaged_legs", QT_TRANSLATE_NOOP("Advice", "%1 leg(s) where the vehicle swung slowly up and down were averaged over whole swings.")},
  {"analysis.depth_not_held_light", QT_TRANSLATE_NOOP("Advice", "For %1 min the vehicle stayed about %2 m above its commanded depth with the elevator at its stop (%3°): it is too light or too tail-heavy for its planes at this speed, so this log says little about its ballast. Add weight at the front in a small step and make a short test dive before a survey.")},
  {"analysis.depth_not_held_heavy", QT_TRANSLATE_NOOP("Advice", "For %1 min the vehicle stayed about %2 m below its commanded depth with the elevator at its stop (%3°): it is too heavy or too nose-heavy for its planes at this speed, so this log says little about its ballast. Remove weight at the front in a small step and make a short test dive before a survey.")},
  {"analysis.porpoising", QT_TRANSLATE_NOOP("Advice", "In %1 leg(s), %2 min in all, the vehicle porpoised (pitch swinging by up to %3° every %4 s or so) and never flew steadily: the depth autopilot overreacts on this vehicle, so the estimate comes from the rest of the log. Lower the depth autopilot's gains or lower the centre of gravity; moving weights forward or aft will not stop it.")},
  {"analysis.pitch_sensor_bias_found", QT_TRANSLATE_NOOP("Advice", "The legs fit one steady balance only with the pitch sensor reading %1 ± %2° more than the vehicle's pitch (reading minus true; its prior 0 ± %3°). The net buoyancy, CG and predicted flight pitch are of the true attitude; the logged pitch is not. Align the sensor, or keep the bias by accepting it in the model check.")},
  {"analysis.attitude_bias_removed", QT_TRANSLATE_NOOP("Advice", "The logged pitch and roll were corrected by the attitude sensor errors an earlier model check found and you accepted: pitch %1 ± %2°, roll %3 ± %4° (reading minus true). Their uncertainty is included in the net buoyancy and CG uncertainty.")},
  {"analysis.pitch_basis_glide", QT_TRANSLATE_NOOP("Advice", "measured minus commanded, during glides whose command has the phase's sign")},
  {"analysis.pitch_basis_level", QT_TRANSLATE_NOOP("Advice", "measured minus commanded, in steady level flight")},
  {"analysis.pitch_basis_no_command", QT_TRANSLATE_NOOP("Advice", "pitch at steady depth (the log has no commanded pitch; level flight should be at 0°)")},
  {"analysis.no_depth_command", QT_TRANSLATE_NOOP("Advice", "The log has no commanded depth: the depth error is not available.")},
  {"analysis.ctd_out_of_range", QT_TRANSLATE_NOOP("Advice", "%1 CTD samples outside the EOS-80 range were not used for the density.")},
  {"analysis.no_density", QT_TRANSLATE_NOOP("Advice", "No in-situ density could be computed (no temperature and salinity or density in the log): %1 kg/m³ assumed.")},
  {"analysis.glider_cg_x", QT_TRANSLATE_NOOP("Advice", "Not identifiable from this log: a glider's pitch is set by its battery position, not by a fixed CG (use the tank or pitch-trim procedure).")},
  {"analysis.glider_cg_y", QT_TRANSLATE_NOOP("Advice", "Not identifiable from this log: the glider's roll is set by its roll mass (use the tank procedure).")},
  {"analysis.no_pump_volume", QT_TRANSLATE_NOOP("Advice", "Not identifiable from this log: it has no pump volume (the buoyancy engine's volume).")},
  {"analysis.no_pitch", QT_TRANSLATE_NOOP("Advice", "Not identifiable from this log: it has no pitch.")},
  {"analysis.no_steady_dive_or_climb", QT_TRANSLATE_NOOP("Advice", "Not identifiable from this log: no steady dive or climb was found.")},
  {"analysis.few_glide_samples", QT_TRANSLATE_NOOP("Advice", "Not identifiable from this log: fewer than 10 steady-glide samples deeper than %1 m with a pitch of at least %2°.")},
  {"analysis.log_mass_differs", QT_TRANSLATE_NOOP("Advice", "The log gives the mass as %1 kg but the vehicle profile has %2 kg: the fit uses the profile's mass (it matters only through density changes).")},
  {"analysis.glider_fit_not_converged", QT_TRANSLATE_NOOP("Advice", "The glider flight-model fit did not converge: %1")},
  {"analysis.glider_default_constants", QT_TRANSLATE_NOOP("Advice", "The glider flight-model constants are the Slocum defaults (wing area 0.1 m², lift slope 7.53 per rad, induced drag 10.5 per rad²): give this glider's flight model in its vehicle profile.")},
  {"analysis.glider_default_compressibility", QT_TRANSLATE_NOOP("Advice", "The hull compressibility is not in the vehicle profile: 5e-6 per dbar is used.")},
  {"analysis.no_roll_samples", QT_TRANSLATE_NOOP("Advice", "Not identifiable from this log: no steady segment has roll samples.")},
  {"analysis.no_prop_rpm", QT_TRANSLATE_NOOP("Advice", "The log has no propeller speed: CG y assumes the roll at cruise is static; any propeller reaction torque is included in it.")},
  {"analysis.one_cruise_rpm", QT_TRANSLATE_NOOP("Advice", "All steady segments run the propeller at about the same speed, so its reaction torque cannot be told from a CG offset: CG y is the offset that levels the vehicle at this cruise speed, not the static CG.")},
  {"analysis.cg_y_needs_bg", QT_TRANSLATE_NOOP("Advice", "Not identifiable from this log: a steady roll gives y = BG tan(roll), and BG (the CG height below the CB) cannot be measured from the log. Enter BG from an inclining or roll test for this configuration (static roll %1°).")},
  {"analysis.no_steady_level_segment", QT_TRANSLATE_NOOP("Advice", "Not identifiable from this log: no steady level flight long enough was found.")},
  {"analysis.no_speed", QT_TRANSLATE_NOOP("Advice", "Not identifiable from this log: it has no speed (the lift and moment that balance the buoyancy grow with the speed squared).")},
  {"analysis.no_speed_and_pitch", QT_TRANSLATE_NOOP("Advice", "Not identifiable from this log: no steady segment has both speed and pitch.")},
  {"analysis.no_elevator", QT_TRANSLATE_NOOP("Advice", "Not identifiable from this log: it has no elevator (stern-plane) angle, so each steady segment only fixes a moment about the planes' centre of pressure (%1 m from the CB). Record the elevator angle.")},
  {"analysis.history_calibration", QT_TRANSLATE_NOOP("Advice", "Calibrated with %1 steady segments of earlier missions of this configuration and the known weight changes since.")},
  {"analysis.history_unreadable", QT_TRANSLATE_NOOP("Advice", "The earlier mission of configuration %1 could not be read from the history (%2): this log is analysed alone, without the known weight change since.")},
  {"analysis.thruster_segments_left_out", QT_TRANSLATE_NOOP("Advice", "%1 steady segment(s) left out: the tunnel thrusters ran there (up to %2 rpm), and the steady balance has no thruster term (the model check replays them).")},
  {"analysis.thrusters_in_every_segment", QT_TRANSLATE_NOOP("Advice", "Not identifiable from this log: the tunnel thrusters ran in all %1 steady segment(s) (up to %2 rpm) and carry an unknown part of the net buoyancy, which the steady balance has no term for. Fly steady legs above the thrusters' hand-over speed, or use the model check, which replays them.")},
  {"analysis.glides_dropped", QT_TRANSLATE_NOOP("Advice", "%1 dive(s) or climb(s) held a steady pitch but did not fit the balance the other legs calibrated (the depth changed at a pitch and elevator no steady flight has): left out of the estimate.")},
  {"analysis.transients_dropped", QT_TRANSLATE_NOOP("Advice", "The depth steps and speed changes disagreed among themselves more than they added (net buoyancy ± %1 kg with them, ± %2 kg from the steady segments alone): the estimate is the steady segments'.")},
  {"analysis.calibration_prior_conflict", QT_TRANSLATE_NOOP("Advice", "The log put %1 at %2 where the profile has %3 ± %4: more than three prior sigmas away, which no vehicle of this class has, so the steady balance did not describe this log (a pitch sensor bias, legs that were not steady, or a profile of another vehicle). The net buoyancy and CG rest on that balance: check the attitude sensor's alignment and the profile before moving weights.")},
  {"analysis.transients_not_flown_as_commanded", QT_TRANSLATE_NOOP("Advice", "The depth steps and speed changes were not flown again: the vehicle did not fly as commanded (too light or porpoising), and there the replay fits the plane stop and the autopilot instead of the hydrodynamics. The estimate is the steady segments'.")},
  {"analysis.transients_with_history", QT_TRANSLATE_NOOP("Advice", "The depth steps and speed changes were not flown again: the earlier missions and the known weight changes calibrate the vehicle, and the replay added model error, not information.")},
  {"analysis.degenerate", QT_TRANSLATE_NOOP("Advice", "Not identifiable from this log: the steady segments do not determine the heave and pitch balance.")},
  {"analysis.elevator_offset_prior", QT_TRANSLATE_NOOP("Advice", "Elevator zero offset assumed 0 ± %1° (included in the uncertainties): the steady segments do not span enough speeds to tell it from the net buoyancy.")},
  {"analysis.plane_sign_converted", QT_TRANSLATE_NOOP("Advice", "The plane coefficients were converted to the log's elevator sign (trailing edge down positive).")},
  {"analysis.joint_calibration", QT_TRANSLATE_NOOP("Advice", "The vehicle's hydrodynamics were calibrated together with the ballast state (%1 parameters determined by the log).")},
  {"analysis.posterior_sigmas", QT_TRANSLATE_NOOP("Advice", "The uncertainties come from that calibration (%1 % prior uncertainty per group of hydrodynamic coefficients).")},
  {"analysis.posterior_sigmas_munk", QT_TRANSLATE_NOOP("Advice", "The uncertainties come from that calibration (%1 % prior uncertainty per group of hydrodynamic coefficients; the Munk moment's form unknown).")},
  {"analysis.bg_from_profile", QT_TRANSLATE_NOOP("Advice", "BG from the vehicle profile (%1 mm ± %2 %) sets the scale of the pitch moments; BG from a roll test sharpens CG x.")},
  {"analysis.trimmed_cruise", QT_TRANSLATE_NOOP("Advice", "Once trimmed, the vehicle should cruise at %1 m/s at %2 rpm (this log: %3 m/s); the propeller torque there changes by %4 N m, and the roll the plan levels includes it (CG y at cruise %5 mm).")},
  // Ballast solver (core/ballast/ballast_messages.h).
  {"ballast.stays_heavy", QT_TRANSLATE_NOOP("Advice", "The vehicle stays %1 heavy even with every removable piece out: it needs added buoyancy or a lighter payload.")},
  {"ballast.node_limit", QT_TRANSLATE_NOOP("Advice", "The search stopped at its limit: this is the best change found, not a proved optimum.")},
  {"ballast.capsize", QT_TRANSLATE_NOOP("Advice", "The CG is not below the CB after the change: the vehicle would capsize. Check BG and the payload.")},
  {"ballast.point_no_change", QT_TRANSLATE_NOOP("Advice", "%1: no change (%2 stays).")},
  {"ballast.priorities", QT_TRANSLATE_NOOP("Advice", "Priorities (thesis §5.4): net buoyancy %1 to %2 and never negative, then pitch within ±%3, then roll within ±%4; %5 piece(s) to handle.")},
  {"ballast.after_move", QT_TRANSLATE_NOOP("Advice", "After the move: net buoyancy %1, pitch %2, roll %3.")},
  {"ballast.half_way", QT_TRANSLATE_NOOP("Advice", "Half-way policy: this move aims at about half of the needed change (net buoyancy %1 to %2, pitch %3, roll %4); check the vehicle again and repeat.")},
  // Weighing checks (core/weighing/weighing_messages.h).
  {"weighing.sum_mismatch", QT_TRANSLATE_NOOP("Advice", "The four scale readings add up to %1 but the hook reads %2 (tolerance %3): the CG uses the four readings, the mass uses the hook.")},
  {"weighing.roll_test_h_large", QT_TRANSLATE_NOOP("Advice", "h = %1 is implausibly large for a glider (about 6 mm is usual): check the roll signs and which rail the mass hung on.")},
  {"weighing.roll_test_spread", QT_TRANSLATE_NOOP("Advice", "The single h values spread by %1 (%2 of the mean): repeat the roll test.")},
  {"weighing.bottles_not_level", QT_TRANSLATE_NOOP("Advice", "The bottles cannot hold the level split (bow %1, aft %2): the glider will not float level. Move a disk or rail weight.")},
  {"weighing.bottles_full", QT_TRANSLATE_NOOP("Advice", "The bottles are full: %1 more is needed for neutral, so the glider stays light. Add ballast elsewhere.")},
  {"weighing.bottles_empty", QT_TRANSLATE_NOOP("Advice", "The bottles are empty: %1 more must come out, so the glider stays HEAVY. Remove a disk or rail weight.")},
  // First mission (core/firstmission/first_mission_messages.h).
  {"first_mission.capsize", QT_TRANSLATE_NOOP("Advice", "The CG is not below the CB with the BG of the vehicle profile: the vehicle would capsize. Check BG in the vehicle profile.")},
  {"first_mission.tank_displaces", QT_TRANSLATE_NOOP("Advice", "In the tank (%1, %2) the glider displaces %3 (%4); at %5 the hull measures %6 and is neutral at %7 in %8 water.")},
  {"first_mission.weighs_light", QT_TRANSLATE_NOOP("Advice", "It weighs %1, so it is %2 light: the bottles change by %3 (rounded down to whole grams so it never ends heavy).")},
  {"first_mission.weighs_heavy", QT_TRANSLATE_NOOP("Advice", "It weighs %1, so it is %2 heavy: the bottles change by %3 (rounded down to whole grams so it never ends heavy).")},
  {"first_mission.bow_bottles", QT_TRANSLATE_NOOP("Advice", "Bow bottles: %1 in %2 and %3 in %4 (%5), so the bow scale would read %6 and the glider floats level.")},
  {"first_mission.aft_bottles", QT_TRANSLATE_NOOP("Advice", "Aft bottles: %1 in %2 and %3 in %4 (%5), so the aft scale would read %6 and the glider floats level.")},
  {"first_mission.no_roll_test", QT_TRANSLATE_NOOP("Advice", "No roll test recorded: set the bottles, hang the glider for the roll test (report 4.2) and enter it on the roll-test page; until then the CG height is the profile's BG.")},
  {"first_mission.roll_test", QT_TRANSLATE_NOOP("Advice", "Roll test: h = %1 from %2 hung masses, so G sits %3 to %4 of B and %5 below it.")},
  {"first_mission.move_rail", QT_TRANSLATE_NOOP("Advice", "Move %1 of rail weight from the %2 wing rail: the battery alone cannot reach the roll.")},
  {"first_mission.move_bow_bottle", QT_TRANSLATE_NOOP("Advice", "Move %1 of lead from the %2 bow bottle: the battery cannot reach the roll.")},
  {"first_mission.move_bow_bottle_rails", QT_TRANSLATE_NOOP("Advice", "Move %1 of lead from the %2 bow bottle: the battery and wing rails cannot reach the roll.")},
  {"first_mission.roll_battery", QT_TRANSLATE_NOOP("Advice", "Set the roll battery to %1 (%2, toward %3; now %4) to bring G straight below B.")},
  {"first_mission.roll_remains", QT_TRANSLATE_NOOP("Advice", "The battery, wing rails and bow bottles together cannot cancel the roll: %1 remains. Move other masses sideways.")},
  {"first_mission.swap_disks", QT_TRANSLATE_NOOP("Advice", "Swap disk column %1 (%2 top, %3 bottom), which %4 G by %5.")},
  {"first_mission.move_aft_bottle", QT_TRANSLATE_NOOP("Advice", "Move %1 of lead from the %2 aft bottle, so h goes from %3 to %4 (target %5).")},
  {"first_mission.h_arm_unreachable", QT_TRANSLATE_NOOP("Advice", "The h-arm target %1 cannot be reached with the disk weights and aft bottles; best is %2 (arrangement %3).")},
  {"first_mission.ends_heavy", QT_TRANSLATE_NOOP("Advice", "The predicted net buoyancy %1 is below the profile's band: the glider would end HEAVY.")},
  {"first_mission.above_band", QT_TRANSLATE_NOOP("Advice", "The predicted net buoyancy %1 is above the profile's band.")},
  {"first_mission.pitch_outside", QT_TRANSLATE_NOOP("Advice", "The predicted pitch %1 is outside ±%2.")},
  {"first_mission.roll_outside", QT_TRANSLATE_NOOP("Advice", "The predicted roll %1 is outside ±%2.")},
  // Glider plan (core/planning/glider_plan_messages.h).
  {"glider_plan.contents_unknown", QT_TRANSLATE_NOOP("Advice", "What is in the bottles was not given: their capacities are checked against half-full bottles. Enter what is installed to check them.")},
  {"glider_plan.rails_short", QT_TRANSLATE_NOOP("Advice", "The wing rails cannot take the whole roll correction (%1 g); move the roll battery or a disk weight for the rest.")},
  {"glider_plan.no_pitch_trim", QT_TRANSLATE_NOOP("Advice", "the pitch trim (the log has no battery position, or it varies too little): the bottle split is Baird's level split only")},
  {"glider_plan.no_roll", QT_TRANSLATE_NOOP("Advice", "the roll (the log has no roll in glides)")},
  {"glider_plan.no_c_pitch", QT_TRANSLATE_NOOP("Advice", "C_PITCH (the log has no pitch-mass position with enough variation)")},
  {"glider_plan.no_geometry", QT_TRANSLATE_NOOP("Advice", "where the grams go: the log carries no geometry of the ballast places; add %1 g at the vehicle's ballast places so that it stays level")},
  {"glider_plan.no_zero_offset", QT_TRANSLATE_NOOP("Advice", "the ballast (pump) zero offset in the vendor's setting: only the mass change is known")},
  {"ballast.thesis_heavy", QT_TRANSLATE_NOOP("Advice", "The thesis mapping leaves the vehicle %1 heavy.")},
  // Pre-mission plan (core/planning/planning_messages.h).
  {"plan.no_change", QT_TRANSLATE_NOOP("Advice", "No change: the vehicle is already as good as the kit allows.")},
  {"plan.next_mission", QT_TRANSLATE_NOOP("Advice", "Next mission at %1: from net buoyancy %2, pitch %3, roll %4 to %5 ± %6, pitch %7 ± %8, roll %9 ± %10 (1 σ).")},
  {"plan.mass_from_last_mission", QT_TRANSLATE_NOOP("Advice", "Mass %1 from the last mission: %2 displaced at %3, %4, %5 minus the measured net buoyancy %6.")},
  {"plan.safety_margin", QT_TRANSLATE_NOOP("Advice", "Safety margin %1 = %2 × σ %3 (estimate and water): the change keeps at least that much net buoyancy at every planned point.")},
  {"plan.cg_x_assumed", QT_TRANSLATE_NOOP("Advice", "CG x was not identified from the log: the plan assumes it at the CB and keeps the fore-aft balance. Check pitch on the next mission.")},
  {"plan.cg_y_assumed", QT_TRANSLATE_NOOP("Advice", "CG y was not identified from the log: the plan assumes it at the CB and keeps the side balance. Check roll on the next mission.")},
  {"plan.unsafe", QT_TRANSLATE_NOOP("Advice", "UNSAFE: at the %1 point (%2) the vehicle would have %3 net buoyancy, less than the safety margin %4.")},
  {"plan.unsafe_sinks", QT_TRANSLATE_NOOP("Advice", "UNSAFE: at the %1 point (%2) the vehicle would have %3 net buoyancy, less than the safety margin %4: it would sink if it lost power there.")},
  {"plan.above_band_for_margin", QT_TRANSLATE_NOOP("Advice", "Net buoyancy %1 at the operating depth is above the band (%2) because the safety margin (%3) and the less buoyant planned points (%4 less) come first.")},
  {"plan.band_not_reachable", QT_TRANSLATE_NOOP("Advice", "The net buoyancy band cannot be reached with this kit while keeping the safety margin: no combination of pieces lands between %1 and %2; the nearest safe one is %3.")},
  {"plan.optional_pieces", QT_TRANSLATE_NOOP("Advice", "The kit has optional pieces (%1) not used in this plan; allowing them may reach the missed band.")},
  {"plan.wide_sigma", QT_TRANSLATE_NOOP("Advice", "The estimate's own uncertainty (pitch %1, roll %2) is wider than a tolerance band; the next mission will tell.")},
  {"plan.classic_table", QT_TRANSLATE_NOOP("Advice", "Classic table (thesis App. E): %1, pitch error %2, roll error %3; it moves one %4 piece per point and mission, whatever the size of the error.")},
  {"plan.classic_blocked", QT_TRANSLATE_NOOP("Advice", "The classic table asks to remove a piece where none is installed, so it changes nothing.")},
  {"plan.classic_standard_kit", QT_TRANSLATE_NOOP("Advice", "The classic table uses the standard kit only.")},
  {"plan.manoeuvre", QT_TRANSLATE_NOOP("Advice", "The net buoyancy uncertainty (%1 kg) is too wide for the %2 kg band: add the calibration manoeuvre to the next mission (%3 short leg(s)); with this log alone it would bring the uncertainty to about %4 kg.")},
  {"plan.after_move", QT_TRANSLATE_NOOP("Advice", "This move is also a calibration: flown after it and analysed with the last log as history (the known change of mass and moment between them), the next mission's survey should tell the net buoyancy to about ±%1 kg and CG x to about ±%2 mm, enough for a second move into the band.")},
  {"plan.log_not_as_commanded", QT_TRANSLATE_NOOP("Advice", "The analysed log was not flown as commanded (see its warnings), so this move rests on a net buoyancy uncertainty of ±%2 kg: after the move, make a short test dive at the survey's speeds before the survey.")},
  {"plan.after_move_still_wide", QT_TRANSLATE_NOOP("Advice", "This move is also a calibration, but flown after it and analysed with the last log as history the next mission's survey would still leave the net buoyancy at about ±%1 kg (CG x about ±%2 mm), too wide for the band: fly the calibration manoeuvre as well.")},
  {"plan.roll_at_cruise", QT_TRANSLATE_NOOP("Advice", "Roll is planned and predicted at cruise (%1 rpm, propeller torque included): the side balance that levels the vehicle there, as the thesis judges roll (§5.3.3).")},
  // Model check (core/discrepancy/check_messages.h).
  {"check.constant", QT_TRANSLATE_NOOP("Advice", "%1 is a constant %2 %3 everywhere (all phases, depths and speeds)")},
  {"check.grows", QT_TRANSLATE_NOOP("Advice", "%1 grows %2 %3 per %4 (%5 %3, %6 % of its variance)")},
  {"check.shrinks", QT_TRANSLATE_NOOP("Advice", "%1 shrinks %2 %3 per %4 (%5 %3, %6 % of its variance)")},
  {"check.grows_beyond", QT_TRANSLATE_NOOP("Advice", "%1 grows %2 %3 per %4 %5 %6 %7 (%8 %3, %9 % of its variance)")},
  {"check.shrinks_beyond", QT_TRANSLATE_NOOP("Advice", "%1 shrinks %2 %3 per %4 %5 %6 %7 (%8 %3, %9 % of its variance)")},
  {"check.concentrates", QT_TRANSLATE_NOOP("Advice", "%1 concentrates at %2 %3 (mean %4 %5 against %6 overall)")},
  {"check.no_factor", QT_TRANSLATE_NOOP("Advice", "%1: no factor of the log explains it")},
  {"check.model_auv", QT_TRANSLATE_NOOP("Advice", "AUV rigid-body model of the simulator (Fossen form) on smoothed logged states; simulation: replay of the logged commands through the model's autopilot; ballast state: net buoyancy and CG x/y")},
  {"check.model_glider", QT_TRANSLATE_NOOP("Advice", "steady glide (Merckelbach et al. 2010) on vertical velocity from the %1; ballast state: net buoyancy at the mean operating state and Cd0")},
  {"check.model_glider_lift", QT_TRANSLATE_NOOP("Advice", "steady glide (Merckelbach et al. 2010) on vertical velocity from the %1; ballast state: net buoyancy at the mean operating state, Cd0 and the lift slope")},
};

// Words core passes as arguments; translated one by one.
[[maybe_unused]] constexpr const char* kWords[] = {
  QT_TRANSLATE_NOOP("AdviceWord", "operating"), QT_TRANSLATE_NOOP("AdviceWord", "deepest"),
  QT_TRANSLATE_NOOP("AdviceWord", "surface"), QT_TRANSLATE_NOOP("AdviceWord", "transit"),
  QT_TRANSLATE_NOOP("AdviceWord", "none"),
  // Steady windows (core/analysis/segments.cpp).
  QT_TRANSLATE_NOOP("AdviceWord", "depth command steps"), QT_TRANSLATE_NOOP("AdviceWord", "pitch command steps"),
  QT_TRANSLATE_NOOP("AdviceWord", "speed changes"), QT_TRANSLATE_NOOP("AdviceWord", "propeller speed changes"),
  // Model check (core/discrepancy/localisation.cpp): residuals, factors,
  // trend steps, relations, mission phases, observed channels.
  QT_TRANSLATE_NOOP("AdviceWord", "vertical-velocity error"), QT_TRANSLATE_NOOP("AdviceWord", "vertical-force error"),
  QT_TRANSLATE_NOOP("AdviceWord", "pitch-moment error"), QT_TRANSLATE_NOOP("AdviceWord", "roll-moment error"),
  QT_TRANSLATE_NOOP("AdviceWord", "depth error"), QT_TRANSLATE_NOOP("AdviceWord", "pitch error"),
  QT_TRANSLATE_NOOP("AdviceWord", "roll error"), QT_TRANSLATE_NOOP("AdviceWord", "speed error"),
  QT_TRANSLATE_NOOP("AdviceWord", "surge-force error"), QT_TRANSLATE_NOOP("AdviceWord", "error"),
  QT_TRANSLATE_NOOP("AdviceWord", "pressure"), QT_TRANSLATE_NOOP("AdviceWord", "temperature"),
  QT_TRANSLATE_NOOP("AdviceWord", "time"), QT_TRANSLATE_NOOP("AdviceWord", "speed"),
  QT_TRANSLATE_NOOP("AdviceWord", "propeller speed"), QT_TRANSLATE_NOOP("AdviceWord", "pitch"),
  QT_TRANSLATE_NOOP("AdviceWord", "time since an actuator change"), QT_TRANSLATE_NOOP("AdviceWord", "depth"),
  QT_TRANSLATE_NOOP("AdviceWord", "100 dbar"), QT_TRANSLATE_NOOP("AdviceWord", "degC"),
  QT_TRANSLATE_NOOP("AdviceWord", "hour"), QT_TRANSLATE_NOOP("AdviceWord", "0.1 m/s"),
  QT_TRANSLATE_NOOP("AdviceWord", "100 rpm"), QT_TRANSLATE_NOOP("AdviceWord", "10 deg of pitch"),
  QT_TRANSLATE_NOOP("AdviceWord", "10 s since an actuator change"),
  QT_TRANSLATE_NOOP("AdviceWord", "below"), QT_TRANSLATE_NOOP("AdviceWord", "above"),
  QT_TRANSLATE_NOOP("AdviceWord", "after"), QT_TRANSLATE_NOOP("AdviceWord", "before"),
  QT_TRANSLATE_NOOP("AdviceWord", "within"),
  QT_TRANSLATE_NOOP("AdviceWord", "surfaces"), QT_TRANSLATE_NOOP("AdviceWord", "dives"),
  QT_TRANSLATE_NOOP("AdviceWord", "climbs"), QT_TRANSLATE_NOOP("AdviceWord", "levels"),
  QT_TRANSLATE_NOOP("AdviceWord", "turns"),
  // First mission, Slocum (core/firstmission/slocum_first_mission.cpp).
  QT_TRANSLATE_NOOP("AdviceWord", "starboard"), QT_TRANSLATE_NOOP("AdviceWord", "port"),
  QT_TRANSLATE_NOOP("AdviceWord", "port to the starboard"), QT_TRANSLATE_NOOP("AdviceWord", "starboard to the port"),
  QT_TRANSLATE_NOOP("AdviceWord", "lower to the upper"), QT_TRANSLATE_NOOP("AdviceWord", "upper to the lower"),
  QT_TRANSLATE_NOOP("AdviceWord", "lowers"), QT_TRANSLATE_NOOP("AdviceWord", "raises"),
};
// clang-format on

const QHash<QString, const char*>& table() {
  static const QHash<QString, const char*> t = [] {
    QHash<QString, const char*> h;
    for (const Advice& a : kAdvice) h.insert(QString::fromLatin1(a.id), a.text);
    return h;
  }();
  return t;
}

// Core formats its numbers with '.'; in the wizard's language they read
// as the pages do ("+9,90°" under nb).
QString localNumbers(QString s) {
  const QString dp = displayLocale().decimalPoint();
  if (dp == QStringLiteral(".")) return s;
  static const QRegularExpression re(QStringLiteral("(\\d)\\.(\\d)"));
  return s.replace(re, QStringLiteral("\\1") + dp + QStringLiteral("\\2"));
}

QString word(const std::string& arg) {
  const QByteArray utf8 = QByteArray::fromStdString(arg);
  return localNumbers(QCoreApplication::translate("AdviceWord", utf8.constData()));
}

QString fill(QString text, const std::vector<std::string>& args) {
  // All at once (QString::arg with a list would re-scan substituted text).
  QString out;
  for (qsizetype i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 1 < text.size() && text[i + 1].isDigit() && text[i + 1] != '0') {
      qsizetype k = text[i + 1].digitValue(), used = 1;
      if (i + 2 < text.size() && text[i + 2].isDigit() && k * 10 + text[i + 2].digitValue() <= qsizetype(args.size()))
        k = k * 10 + text[i + 2].digitValue(), used = 2;
      if (k <= qsizetype(args.size())) {
        out += word(args[static_cast<std::size_t>(k - 1)]);
        i += used;
        continue;
      }
    }
    out += text[i];
  }
  return out;
}

// plan.explain_point: label, removed, added, signed kg, |kg|, x mm, y mm,
// lowers/raises, x/y, back/balanced (core/planning/planning_messages.h).
QString explainPoint(const std::vector<std::string>& a) {
  if (a.size() < 10) return {};
  auto q = [](const std::string& s) { return localNumbers(QString::fromStdString(s)); };
  const QString and_ = QCoreApplication::translate("Advice", " and ");
  const QString rem = q(a[1]).replace(" and ", and_), add = q(a[2]).replace(" and ", and_);
  QString pieces;
  if (!rem.isEmpty() && !add.isEmpty())
    pieces = QCoreApplication::translate("Advice", "remove %1, then add %2").arg(rem, add);
  else if (!rem.isEmpty())
    pieces = QCoreApplication::translate("Advice", "remove %1").arg(rem);
  else
    pieces = QCoreApplication::translate("Advice", "add %1").arg(add);
  const double x = QString::fromStdString(a[5]).toDouble(), y = QString::fromStdString(a[6]).toDouble();  // core writes "."
  const QString xs = (x >= 0 ? QCoreApplication::translate("Advice", "%1 mm forward")
                             : QCoreApplication::translate("Advice", "%1 mm aft"))
                         .arg(fixed(std::abs(x), 2));
  const QString ys = (y >= 0 ? QCoreApplication::translate("Advice", "%1 mm to starboard")
                             : QCoreApplication::translate("Advice", "%1 mm to port"))
                         .arg(fixed(std::abs(y), 2));
  const bool back = a[9] == "back", along_x = a[8] == "x";
  const char* tail = along_x ? (back ? QT_TRANSLATE_NOOP("Advice", "bringing the CG back towards the CB fore-aft")
                                     : QT_TRANSLATE_NOOP("Advice", "balanced by the other points' fore-aft shares"))
                             : (back ? QT_TRANSLATE_NOOP("Advice", "bringing the CG back towards the CB sideways")
                                     : QT_TRANSLATE_NOOP("Advice", "balanced by the other points' sideways shares"));
  const QString sentence =
      a[7] == "lowers"
          ? QCoreApplication::translate("Advice", "%1: %2 (%3), which lowers the net buoyancy by %4 and moves the CG %5 and %6, %7.")
          : QCoreApplication::translate("Advice", "%1: %2 (%3), which raises the net buoyancy by %4 and moves the CG %5 and %6, %7.");
  return sentence.arg(q(a[0]), pieces, q(a[3]), q(a[4]), xs, ys, QCoreApplication::translate("Advice", tail));
}

// ballast.band_unreachable: band, low end or tolerance, high end, best,
// extra-piece kind, its size(s), "pitch_ok"; pitch may add speed, flight
// pitch, "inside"/"outside" (core/ballast/ballast_messages.h).
QString bandUnreachable(const std::vector<std::string>& a) {
  if (a.size() < 7) return {};
  auto q = [](const std::string& s) { return localNumbers(QString::fromStdString(s)); };
  QString s;
  if (a[0] == "net buoyancy")
    s = QCoreApplication::translate("Advice", "The net buoyancy band %1 to %2 cannot be reached with this kit; best %3").arg(q(a[1]), q(a[2]), q(a[3]));
  else if (a[0] == "pitch")
    s = QCoreApplication::translate("Advice", "The pitch band ±%1 cannot be reached with this kit (at rest); best %2").arg(q(a[1]), q(a[3]));
  else if (a[6] == "pitch_ok")
    s = QCoreApplication::translate("Advice", "The roll band ±%1 cannot be reached with this kit while pitch stays in band; best %2").arg(q(a[1]), q(a[3]));
  else
    s = QCoreApplication::translate("Advice", "The roll band ±%1 cannot be reached with this kit; best %2").arg(q(a[1]), q(a[3]));
  if (a.size() >= 10)
    s += (a[9] == "inside" ? QCoreApplication::translate("Advice", "; flying level at %1 m/s it pitches %2°, inside the band")
                           : QCoreApplication::translate("Advice", "; flying level at %1 m/s it pitches %2°, outside the band"))
             .arg(q(a[7]), q(a[8]));
  if (a[4] == "out_of_reach")
    s += QCoreApplication::translate("Advice", "; out of reach whatever the piece sizes: the points' capacities, the installed pieces and the higher "
           "priorities limit it");
  else if (a[4] == "piece")
    s += QCoreApplication::translate("Advice", "; a %1 piece would reach it").arg(q(a[5]));
  else if (a[4] == "none_tried")
    s += QCoreApplication::translate("Advice", "; no single extra piece size tried (%1) would reach it").arg(q(a[5]));
  else if (a[4] == "none_tried_undecided")
    s += QCoreApplication::translate("Advice", "; no single extra piece size tried (%1) would reach it (some were not searched to the end)").arg(q(a[5]));
  return s + ".";
}

// ballast.point: name, signed change, before, after, capacity, number of
// removals, then the pieces, removals first (core/ballast/solution_text.cpp).
QString pointText(const std::vector<std::string>& a) {
  if (a.size() < 7) return {};
  auto q = [](const std::string& s) { return localNumbers(QString::fromStdString(s)); };
  const std::size_t n_remove = std::min<std::size_t>(std::stoul(a[5]), a.size() - 6);
  auto joined = [&](std::size_t from, std::size_t to) {
    QString out;
    for (std::size_t i = from; i < to; ++i) {
      if (i > from) out += i + 1 == to ? QCoreApplication::translate("Advice", " and ") : QStringLiteral(", ");
      out += q(a[i]);
    }
    return out;
  };
  const QString removes = joined(6, 6 + n_remove), adds = joined(6 + n_remove, a.size());
  QString what;
  if (!removes.isEmpty() && !adds.isEmpty())
    what = QCoreApplication::translate("Advice", "remove %1, then add %2").arg(removes, adds);
  else if (!removes.isEmpty())
    what = QCoreApplication::translate("Advice", "remove %1").arg(removes);
  else
    what = QCoreApplication::translate("Advice", "add %1").arg(adds);
  return QCoreApplication::translate("Advice", "%1: %2 (%3; %4 → %5 of %6).")
      .arg(q(a[0]), what, q(a[1]), q(a[2]), q(a[3]), q(a[4]));
}

// check.largest_during: what, phase, mean, unit, then (phase, mean) pairs of
// the other phases (core/discrepancy/check_messages.h).
QString largestDuring(const std::vector<std::string>& a) {
  if (a.size() < 4) return {};
  auto q = [](const std::string& s) { return localNumbers(QString::fromStdString(s)); };
  QString s = QCoreApplication::translate("Advice", "%1 is largest during %2: mean %3 %4")
                  .arg(word(a[0]), word(a[1]), q(a[2]), q(a[3]));
  QStringList others;
  for (std::size_t i = 4; i + 1 < a.size(); i += 2) others << word(a[i]) + " " + q(a[i + 1]);
  if (!others.isEmpty()) s += " (" + others.join(", ") + ")";
  return s;
}

// check.summary: the top finding's id and arguments, then the factor the
// error does not depend on ("" when none).
QString checkSummary(const std::vector<std::string>& a) {
  if (a.size() < 2) return {};
  const Message finding(a.front(), std::string(), std::vector<std::string>(a.begin() + 1, a.end() - 1));
  QString s = adviceText(finding);
  if (s.isEmpty()) return {};
  if (!a.back().empty()) s += QCoreApplication::translate("Advice", "; independent of %1").arg(word(a.back()));
  return s;
}

}  // namespace

QString adviceText(const Message& m) {
  // Sentences core builds in pieces (a variable number of arguments): their
  // own formatters; an empty result falls back to core's English.
  using Builder = QString (*)(const std::vector<std::string>&);
  static const std::pair<const char*, Builder> kBuilt[] = {
      {"ballast.point", pointText},         {"check.largest_during", largestDuring},
      {"check.summary", checkSummary},      {"plan.explain_point", explainPoint},
      {"ballast.band_unreachable", bandUnreachable}};
  for (const auto& [id, build] : kBuilt) {
    if (m.id() != id) continue;
    const QString s = build(m.args());
    if (!s.isEmpty()) return s;
  }
  const auto it = table().find(QString::fromStdString(m.id()));
  if (it == table().end()) return QString::fromStdString(m.text());
  return fill(QCoreApplication::translate("Advice", it.value()), m.args());
}

QStringList adviceIds() {
  QStringList ids;
  for (const Advice& a : kAdvice) ids << QString::fromLatin1(a.id);
  return ids;
}

QString adviceSource(const QString& id) {
  const auto it = table().find(id);
  return it == table().end() ? QString() : QString::fromUtf8(it.value());
}

}  // namespace auv::ui
