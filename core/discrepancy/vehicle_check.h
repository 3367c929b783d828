#pragma once
// The right check model for a vehicle: the steady-glide model for a glider
// profile, the simulator's rigid-body model (its profile's sim sections or
// <resource_dir>/sim/<id>_hydrodynamics.json) for an AUV.
#include <memory>
#include <string>

#include "analysis/analysis_report.h"
#include "discrepancy/auv_check_model.h"
#include "discrepancy/glider_check_model.h"
#include "missionlog/mission_log.h"
#include "vehicle/vehicle_profile.h"

namespace auv::discrepancy {

struct CheckSetup {
  GliderCheckOptions glider;
  AuvCheckOptions auv;
  // The same log's analysis: an AUV's check then states its net buoyancy in
  // the analysis's water and starts from the analysis's calibration (its
  // groups as priors: analysisCalibrationPriors). Not owned; may be null.
  const analysis::AnalysisReport* analysis = nullptr;
};

// The analysis's calibrated groups as the check's priors, in the check's ids
// and units (the net u w pitch moment made nondimensional with the
// simulator's reference length).
std::vector<AuvCheckOptions::CalibrationPrior> analysisCalibrationPriors(const analysis::AnalysisReport& r,
                                                                         double reference_length_m);

// The analysis's buoyancy laws (hull law, mass drift), when they replaced
// the profile's (significant change, CalibrationParameter::used), as terms
// the check holds.
std::vector<AuvCheckOptions::HeldTerm> analysisHeldTerms(const analysis::AnalysisReport& r);

// The analysis's mean water, for AuvCheckOptions::report_water: the check's
// net buoyancy then is the same quantity as the analysis's (empty when the
// analysis has no mean density, temperature or pressure).
std::optional<ReferenceWater> analysisWater(const analysis::AnalysisReport& r);

// Throws InputError when the log lacks what the vehicle's model needs.
std::unique_ptr<CheckModel> makeCheckModel(const MissionLog& log, const VehicleProfile& v, const std::string& resource_dir,
                                           const CheckSetup& setup = {});

}  // namespace auv::discrepancy
