#pragma once
// "Model it": accepted terms written into a copy of the vehicle profile, so
// that the simulator and the analysis use them from then on. A term goes
// where the stock loaders already read it (hull compressibility and thermal
// expansion into "hull"; propeller torque into "sim_assumptions.prop_KQ0";
// quadratic pitch damping into "hydrodynamics.Mqq_kgm2_per_rad2"; a glider's
// pitch bias into "flight_model.pitch_offset_deg"), everything else into
// "model_check.terms" {id: value}, which the model check's own models read
// (acceptedTermsFromProfile). Every accepted term is also listed under
// "model_check.accepted" with its value, sigma, unit, where it was written and
// the log it came from. Identified calibration constants (result.calibration)
// go into the sections the simulator reads them from (propeller torque into
// sim_assumptions.prop_KQ0, group scales into the hydrodynamics, roll-damping
// and stern-plane fields), listed under "model_check.calibrated".
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "discrepancy/model_check.h"
#include "vehicle/vehicle_profile.h"

namespace auv::discrepancy {

// `profile_doc` is the complete profile JSON (profileToJson(v): with the
// companion sections, so that the written profile is a whole vehicle).
nlohmann::json profileWithAcceptedTerms(const nlohmann::json& profile_doc, const VehicleProfile& v,
                                        const ModelCheckResult& result, const std::string& log_name);

// Whether the check identified calibration constants that --accept would write.
bool hasCalibrationToWrite(const ModelCheckResult& result);

// The configuration's vehicle after a model check, with only the terms the
// technician accepted (`accepted_ids`, MissingPhysics ids; the others are
// dropped from `result`). `doc` is the profile's JSON; sections the loaded
// profile has from companion files (resources/sim/<id>_hydrodynamics.json)
// are carried over, so the returned profile is complete. Also returns the
// profile JSON as written (for the history), via `profile_doc_out`.
VehicleProfile vehicleWithAcceptedTerms(const nlohmann::json& doc, const VehicleProfile& v, const ModelCheckResult& result,
                                        const std::vector<std::string>& accepted_ids, const std::string& log_name,
                                        nlohmann::json* profile_doc_out = nullptr);

// A vehicle profile from a stored profile JSON (the history's model), with
// the companion sections of `base` it lacks. Throws InputError naming the
// field when the stored JSON is not a valid profile.
VehicleProfile vehicleFromStoredProfile(const nlohmann::json& profile_doc, const VehicleProfile& base,
                                        const std::string& source_name);

}  // namespace auv::discrepancy
