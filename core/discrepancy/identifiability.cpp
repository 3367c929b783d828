#include "discrepancy/identifiability.h"

#include <array>

#include "discrepancy/physics_terms.h"

namespace auv::discrepancy {

namespace {

struct PairAdvice {
  std::string_view a, b, why, manoeuvre;
};

constexpr std::array<PairAdvice, 10> kPairs = {{
    {"pitch_sensor_bias", "vertical_current",
     "with one pitch angle per phase a pitch offset changes dive and climb speeds by the same amount, like a current",
     "fly dives and climbs at two different pitch angles"},
    {"hull_compressibility", "thermal_expansion", "water temperature here is a function of depth (one thermocline)",
     "fly the same dives where the thermocline sits at another depth (internal waves, a front, another day), or hold "
     "a level leg while the temperature changes"},
    {"vertical_current", "ballast_state",
     "dives and climbs use the same buoyancy-engine volume, so a net-buoyancy error changes their vertical speeds "
     "like a current does",
     "fly some yos with a different pump volume (e.g. half stroke on the climbs)"},
    {"roll_sensor_bias", "ballast_state", "a constant roll reading is also what a CG y offset produces",
     "do a roll test (known lateral weight shift) to fix CG y independently"},
    {"pitch_sensor_bias", "ballast_state", "at one speed a pitch offset looks like a net-buoyancy or CG x error",
     "fly legs at two or more speeds (AUV) or dives and climbs at different pitch angles (glider)"},
    {"mass_drift", "thermal_expansion", "the water warmed or cooled steadily during the log",
     "repeat the same dive at the start and at the end of the mission in the same water"},
    {"mass_drift", "hull_compressibility", "the dives got steadily deeper or shallower",
     "keep the dive depth constant, or repeat a shallow dive at the end"},
    {"propeller_torque", "ballast_state", "the log has a single propeller speed, so the reaction torque rolls the "
                                          "vehicle like a CG y offset",
     "fly legs at two or more propeller speeds"},
    {"quadratic_pitch_damping", "pitch_sensor_bias", "pitch rates are too small to excite quadratic damping",
     "add depth steps or hover pitch manoeuvres with fast pitch changes"},
    {"depth_sensor_offset", "ballast_state", "there is no independent pressure to compare the depth sensor with",
     "log the CTD pressure, or a surface reading with the vehicle at rest"},
}};

std::string excitation(std::string_view id) {
  if (id == "ballast_state") return "flight at several speeds, pitch angles and buoyancy-engine settings";
  if (const auto k = findTerm(id)) return std::string(termLibrary()[*k].excitation);
  return "a different manoeuvre";
}

}  // namespace

std::string separationAdvice(std::string_view a, std::string_view b) {
  for (const PairAdvice& p : kPairs) {
    if ((p.a == a && p.b == b) || (p.a == b && p.b == a))
      return "because " + std::string(p.why) + "; to separate them: " + std::string(p.manoeuvre);
  }
  return "to separate them the log needs " + excitation(a) + " for " + std::string(a) + ", and " + excitation(b) +
         " for " + std::string(b);
}

}  // namespace auv::discrepancy
