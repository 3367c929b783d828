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
// the log it came from.
#include <string>

#include <nlohmann/json.hpp>

#include "discrepancy/model_check.h"
#include "vehicle/vehicle_profile.h"

namespace auv::discrepancy {

// `profile_doc` is the profile file's JSON as read (JsonReader::parseFile(v.file)).
nlohmann::json profileWithAcceptedTerms(const nlohmann::json& profile_doc, const VehicleProfile& v,
                                        const ModelCheckResult& result, const std::string& log_name);

}  // namespace auv::discrepancy
