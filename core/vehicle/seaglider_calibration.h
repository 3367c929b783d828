#pragma once
// A Seaglider's calibration and piloting constants as the basestation's
// per-dive NetCDF (p<glider><dive>.nc) carries them: the sg_cal_* flight
// model (mass, volmax, vbdbias, hd_a/b/c/s, abs_compress, therm_expan,
// temp_ref, rho0) and the log_* parameters that place the VBD and pitch
// mass ($C_VBD, $VBD_MIN/MAX, $VBD_CNV, $C_PITCH, $PITCH_CNV, ...). The
// mission-log reader puts them into the log's metadata
// (MissionLog::seagliderConstants(); analysis::seagliderCalibrationOf builds
// this struct from a log). `seagliderProfile` turns them into a vehicle
// profile document the technician can edit (resources/vehicles/seaglider.json
// is the template).
#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace auv {

struct SeagliderCalibration {
  std::string file;
  std::map<std::string, double> values;  // "sg_cal_mass", "log_C_VBD", ... as stored (log_MASS in g)
  double get(const std::string& name) const;  // throws InputError naming the file and the variable
  bool has(const std::string& name) const { return values.count(name) > 0; }
};

// Profile JSON for this glider from `template_profile` (the seaglider
// template): mass, hull volume at the VBD set point (volmax + (C_VBD -
// VBD_MIN) VBD_CNV - vbdbias), compressibility, thermal expansion, the
// hydrodynamic form and the VBD/pitch piloting constants.
nlohmann::json seagliderProfile(const SeagliderCalibration& cal, const nlohmann::json& template_profile);

}  // namespace auv
