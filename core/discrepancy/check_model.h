#pragma once
// What the model check needs from a vehicle model, whatever the vehicle: the
// samples it compares (with the variables the localisation breaks residuals
// down by), the always-estimated ballast state ("nuisance" parameters), the
// equation error per sample and the simulation error of a whole-log replay,
// both for any combination of library terms. Two implementations: the
// glider steady-glide model (glider_check_model.h) and the AUV rigid-body
// model of core/sim (auv_check_model.h).
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "common/message.h"
#include "discrepancy/physics_terms.h"

namespace auv::discrepancy {

enum class Phase : std::uint8_t { kSurface, kDive, kClimb, kLevel, kTurn };
const char* phaseName(Phase p);

// One row per compared sample, in time order. NaN where the log cannot say.
// The water a net buoyancy is stated in: density, and the temperature and
// pressure the hull's volume is taken at.
struct ReferenceWater {
  double density_kgm3 = 1025.0;
  double temperature_degC = 10.0;
  double pressure_dbar = 0.0;
};

struct SampleTable {
  std::vector<double> t;               // s since the log start
  std::vector<int> block;              // glide or leg (a simulation restarts or is scored per block)
  std::vector<int> unit;               // dive/yo or leg: the unit of cross-validation
  std::vector<Phase> phase;
  std::vector<double> pressure_dbar, temperature_degC, speed_mps, rpm, pitch_deg, since_actuator_s;
  std::size_t size() const { return t.size(); }
  int unitCount() const;
};

struct Params {
  Eigen::VectorXd nuisance;
  TermValues terms{};  // fitted values, added to the model's accepted baseline
};

// A Gaussian prior on one nuisance parameter (e.g. CG y from a roll test).
// `measured`: an independent measurement the flight data must reproduce (the
// held-out check scores the fit against it); false for the soft priors of
// calibration constants, which only regularise.
struct NuisancePrior {
  int index = -1;
  double mean = 0.0;
  double sigma = std::numeric_limits<double>::infinity();
  bool measured = true;
};

// A calibration constant: a nuisance parameter (after the ballast state) that
// stands for a constant the profile only assumes (a hydrodynamic group scale,
// the propeller torque). Fitted with the ballast state under its prior, never
// reported as missing physics. Values in the reported unit are
// nuisance[index] * display_scale.
struct CalibrationConstant {
  std::string id, unit;
  std::string label;           // for people: "propeller torque"
  int index = -1;              // into the nuisance vector
  double display_scale = 1.0;  // nuisance -> reported unit
  double profile_value = 0.0;  // reported unit
  double prior_sigma = 0.0;    // reported unit
  // > 0: held at a value calibrated elsewhere (the analysis's, with this
  // sigma in the reported unit) instead of fitted here; the reported sigma.
  double held_sigma = 0.0;
  bool from_analysis = false;  // held at the same log's analysis's value (and grouping)
};

// A library term held at a value calibrated elsewhere (the analysis's hull
// law): in the model, not a candidate, reported with the calibration.
struct HeldTermValue {
  std::string id, unit, label;
  double value = 0.0, sigma = 0.0, profile_value = 0.0, prior_sigma = 0.0;  // display unit
  std::string rival;  // a law the calibration's data explain about as well (analysis::CalibrationParameter::rival)
};

class CheckModel {
 public:
  virtual ~CheckModel() = default;
  virtual unsigned family() const = 0;  // VehicleFamilyBits
  virtual const SampleTable& samples() const = 0;

  // Ballast state: names, start values, finite-difference steps, bounds.
  virtual std::vector<std::string> nuisanceNames() const = 0;
  virtual Eigen::VectorXd nuisanceStart() const = 0;
  virtual Eigen::VectorXd nuisanceScale() const = 0;
  virtual Eigen::VectorXd nuisanceLower() const = 0;
  virtual Eigen::VectorXd nuisanceUpper() const = 0;
  virtual std::vector<NuisancePrior> priors() const { return {}; }
  virtual std::vector<CalibrationConstant> calibrationConstants() const { return {}; }
  virtual std::vector<HeldTermValue> heldTerms() const { return {}; }
  // The profile's value of a library term in its display unit (a found
  // term's reported value is this plus the fitted increment: what the
  // vehicle has, not a correction).
  virtual double profileTermValue(std::size_t /*term*/) const { return 0.0; }
  // The plausible range of library term `term` in this model's units: the
  // library's, unless the model scales the term's basis by a calibration.
  virtual std::pair<double, double> termRange(std::size_t term) const {
    return {termLibrary()[term].lower, termLibrary()[term].upper};
  }

  // Whether this log can show the term at all (channels present, vehicle kind).
  virtual bool applicable(std::size_t term) const = 0;

  // Equation error, observed - model, at `rows` (ascending): out has
  // rows.size() * equationChannels().size() values, row-major, NaN where
  // the channel is not available.
  virtual std::vector<Channel> equationChannels() const = 0;
  virtual void equationError(const Params& p, std::span<const std::uint32_t> rows, double* out) const = 0;

  // Simulation error of a whole-log replay with these parameters, observed -
  // simulated, samples().size() * simulationChannels().size(), NaN where not
  // scored (channel missing, settling after a restart).
  virtual std::vector<Channel> simulationChannels() const = 0;
  virtual void simulationError(const Params& p, std::vector<double>& out) const = 0;
  // The same error from replays in short horizons, each restarted from the
  // logged state (same layout): the held-out test's second chance for a
  // transient term (PhysicsTerm::transient). Default: the whole-log replay.
  virtual void shortHorizonSimulationError(const Params& p, std::vector<double>& out) const { simulationError(p, out); }

  // The reported net buoyancy [kg] and CG offset [m] for a nuisance vector
  // (and term values, which may move the reference state's buoyancy).
  virtual double netBuoyancyKg(const Params& p) const = 0;
  // The water netBuoyancyKg is reported in (a net buoyancy means nothing
  // without it: in stratified water 0.3 kg/m^3 of density is 0.3 kg on a
  // one-tonne AUV). Empty where the model does not say.
  virtual std::optional<ReferenceWater> referenceWater() const { return std::nullopt; }
  virtual bool hasCg() const { return false; }
  virtual double cgX(const Params&) const { return std::numeric_limits<double>::quiet_NaN(); }
  virtual double cgY(const Params&) const { return std::numeric_limits<double>::quiet_NaN(); }
  virtual Message description() const = 0;
  virtual std::vector<std::string> notes() const { return {}; }

  // A noise twin of the log: the same commands flown by the model with these
  // parameters (no missing term), the log's own sensor noise on what the
  // autopilot steers on and what is recorded, checked the same way. What the
  // check fits there is what noise in the closed loop makes of a vehicle
  // without the term (model_check.cpp). nullptr where the model has none.
  virtual std::unique_ptr<CheckModel> noiseTwin(const Params& /*p*/, std::uint64_t /*seed*/) const { return nullptr; }
};

}  // namespace auv::discrepancy
