#pragma once
// The model check: when a recording and the model disagree, find where,
// name the physics the model left out, fit it and show the fit improve.
//
//   1. Base fit: the ballast state alone (always estimated), by
//      Levenberg-Marquardt on the equation error.
//   2. Linearise every applicable library term around it; forward stepwise
//      selection with BIC on the effective sample size, t-test and
//      cross-validation across dives/legs; bootstrap inclusion probabilities.
//   3. Identifiability: correlation of the candidate regressors after the
//      ballast state is projected out; pairs that this log cannot separate are
//      reported with the manoeuvre that would separate them.
//   4. Each selected term must also improve the SIMULATION error on data not
//      used to fit it (two halves of the dives/legs, each fitted on one half
//      and scored on the other); only then is it accepted.
//   The ballast state includes the model's calibration constants (hydrodynamic
//   group scales, propeller torque) under their priors: fitted from step 1 on,
//   reported under `calibration`, never as missing physics.
//   5. Final joint fit (ballast state + accepted terms), uncertainties, RMS
//      before/after per channel on fitted and held-out data, and where each
//      residual and each accepted term concentrates (localisation.h).
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "discrepancy/check_model.h"
#include "discrepancy/localisation.h"
#include "discrepancy/sparse_selection.h"

namespace auv::discrepancy {

struct ModelCheckOptions {
  SelectionOptions selection;
  int bootstrap_replicates = 60;
  double min_inclusion = 0.6;    // bootstrap inclusion probability to go on to the simulation check
  // ... or, for a term the full data selected whose replicates split with a
  // rival (another term picked instead, hardly ever both): its own inclusion
  // at least min_inclusion_with_rivals, each rival's at least
  // min_rival_inclusion and co-selected in at most rival_max_together of
  // the smaller one's replicates, and term or a rival in min_inclusion.
  double min_inclusion_with_rivals = 0.3;
  double min_rival_inclusion = 0.2;
  double rival_max_together = 0.25;
  double min_sim_gain = 0.01;    // relative drop of the held-out simulation cost to accept
  // ... or, when a calibrated constant already mimics the term in simulation
  // (a calibrated linear pitch damping flies like an extra quadratic one),
  // a held-out simulation cost no worse than this and a relative drop of the
  // held-out equation error (weighted, the other half of the units) of at least min_eq_gain.
  double max_sim_loss = 0.06;
  double min_eq_gain = 0.05;
  // A term must also stand out from what the held calibration (the analysis's
  // groups, each within its sigma) could put into it: |increment| at least
  // this many hypot(formal sigma, calibration_sigma).
  double min_calibration_z = 2.0;
  // And from what the same check fits on the log's noise twin (noise_twin_test.h):
  // |log value - twin value| at least this many hypot(their sigmas).
  bool noise_twin = true;
  double min_twin_z = 2.0;
  // Stop after the selection (step 3): the candidates' fits and statistics
  // only, no held-out test (what the noise twin needs).
  bool selection_only = false;
  double collinear_threshold = 0.95;  // reported as "cannot be told apart"
  double degenerate_r2 = 0.995;       // share of a regressor the ballast state explains beyond which the term is not tried
  double stlsq_threshold = 0.5;  // in units of each term's typical value (comparison only)
  std::size_t max_fit_rows = 30000;
  std::uint64_t seed = 1;
  std::vector<std::string> only_terms;  // empty = every applicable term
};

struct ChannelRms {
  Channel channel = Channel::kDepth;
  std::string source;  // "equation" or "simulation"
  double fitted_before = 0.0, fitted_after = 0.0;    // display unit; before = ballast state only
  double heldout_before = 0.0, heldout_after = 0.0;  // fitted on one half of the units, scored on the other
  std::size_t samples = 0;
};

// A term the bootstrap picked instead of a found one, hardly ever with it:
// the log says something is there but cannot say firmly which of the two.
struct TermRival {
  std::string id;
  double inclusion_probability = 0.0;
};

struct MissingPhysics {
  std::string id, unit;
  double value = 0.0, sigma = 0.0;  // display unit: what the vehicle has (profile_value + the fitted increment)
  double profile_value = 0.0;       // what the profile assumed, display unit
  // Half the difference of the values fitted on the two held-out halves
  // (display unit): the spread the formal sigma misses where the model's
  // structure, not the noise, limits the fit. `sigma` is never below it.
  double split_half_sigma = 0.0;
  // The value's spread from the calibration constants the check holds (the
  // analysis's groups), each one of its sigmas up, in quadrature (display
  // unit). `sigma` includes it.
  double calibration_sigma = 0.0;
  Channel channel = Channel::kDepth;   // simulation channel it improves most
  double rms_before = 0.0, rms_after = 0.0;  // held-out simulation RMS on `channel`, display unit
  Message where;
  double inclusion_probability = 0.0;
  double delta_bic = 0.0;
  double t_value = 0.0;
  double heldout_gain = 0.0;  // relative drop of the held-out simulation cost
  std::vector<std::string> confused_with;  // candidates this log cannot tell it from
  std::vector<TermRival> rivals;           // picked instead of it in part of the bootstrap (also in confused_with)
  std::string evidence;  // set when a prior (an independent measurement) is what separates it
};

struct CandidateReport {
  std::string id;
  std::string status;  // "accepted" or why not
  double value = 0.0, sigma = 0.0;  // linearised full-data fit with the ballast state, display unit
  double t_value = 0.0;
  double inclusion_probability = 0.0;
  double nuisance_r2 = 0.0;  // share of its regressor the ballast state explains
  // The same fit on the log's noise twin (noise_twin_test.h), where one was
  // flown: the value noise in the closed loop gives a vehicle without it.
  double twin_value = std::numeric_limits<double>::quiet_NaN(), twin_sigma = std::numeric_limits<double>::quiet_NaN();
};

// A calibration constant as fitted with the ballast state (check_model.h).
struct CalibrationValue {
  std::string id, unit, label;
  double value = 0.0, sigma = 0.0;  // posterior, reported unit
  double profile_value = 0.0, prior_sigma = 0.0;
  bool identified = false;  // posterior sigma below half the prior's: the log, not the prior, says it
  std::string finding;      // set when the log puts it far from the profile's value, in words
  bool from_analysis = false;  // held at the analysis's calibration, not fitted by the check
};

struct IdentifiabilityIssue {
  std::string a, b;  // term ids ("ballast_state" for the nuisance)
  double correlation = 0.0;
  std::string message;
};

// The fit with a found term swapped for one of its rivals, for answers that
// must carry the doubt (glider_ballast_answer.h: model averaging).
struct RivalFit {
  std::string term, rival;
  double weight = 0.0;  // the rival's share of the replicates that picked either
  Params params;
};

struct ModelCheckResult {
  Message model;
  std::size_t samples = 0;
  int units = 0;
  double neff_ratio = 1.0;
  std::vector<MissingPhysics> missing_physics;  // best first
  std::vector<CalibrationValue> calibration;    // constants the profile only assumes, fitted; never missing physics
  std::vector<CandidateReport> candidates;
  std::vector<IdentifiabilityIssue> identifiability;
  std::vector<std::string> stlsq_selected;      // SINDy-style comparison
  std::vector<ChannelRms> rms;
  std::vector<Localisation> localisation;       // residuals of the ballast-only model
  // Ballast state, jointly with the accepted terms (and without, for comparison).
  double net_buoyancy_kg = 0.0, net_buoyancy_sigma_kg = 0.0, net_buoyancy_base_kg = 0.0;
  std::optional<ReferenceWater> reference_water;  // the water the net buoyancy is stated in
  bool has_cg = false;
  double cg_x_mm = 0.0, cg_y_mm = 0.0, cg_x_sigma_mm = 0.0, cg_y_sigma_mm = 0.0;
  std::vector<std::string> nuisance_names;
  std::vector<double> nuisance, nuisance_sigma;
  TermValues accepted{};  // SI, fitted increments over the profile's baseline
  Params final_params, base_params;
  std::vector<RivalFit> rival_fits;
  std::vector<std::string> notes, warnings;
  // The log's analysis again with the pitch sensor bias the check found
  // taken out, its sigma carried (followFoundPitchBias, held_law_retest.h):
  // where that term is accepted, the analysis side of the plan's estimate.
  struct BiasFreeAnalysis {
    double pitch_bias_deg = 0.0, pitch_bias_sigma_deg = 0.0;
    double net_buoyancy_kg = 0.0, net_buoyancy_sigma_kg = 0.0;
    bool has_cg_x = false;
    double cg_x_mm = 0.0, cg_x_sigma_mm = 0.0;
  };
  std::optional<BiasFreeAnalysis> analysis_without_pitch_bias;
};

ModelCheckResult runModelCheck(const CheckModel& model, const ModelCheckOptions& options = {});

}  // namespace auv::discrepancy
