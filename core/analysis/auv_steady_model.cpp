#include "analysis/auv_steady_model.h"

#include "analysis/analysis_messages.h"

#include <cmath>

#include "vehicle/json_reader.h"

namespace auv::analysis {

std::optional<SteadyHydroCoefficients> steadyHydroFromProfile(const VehicleProfile& v, std::string& why_not) {
  if (!v.sections.contains("hydrodynamics")) {
    why_not = "the vehicle profile '" + v.id +
              "' has no \"hydrodynamics\" section, so the lift and pitching moment that balance a net buoyancy "
              "at speed are unknown";
    return std::nullopt;
  }
  const JsonReader h(v.sections["hydrodynamics"], v.file, "hydrodynamics");
  SteadyHydroCoefficients c;
  c.reference_length_m = h.numberIn("reference_length_m", 0.01, 1000.0, v.hull.length_m > 0 ? v.hull.length_m : 0.0);
  if (!(c.reference_length_m > 0.0)) h.fail("reference_length_m", "missing", "give the length the derivatives are made nondimensional with");
  c.Zw_prime = h.number("Zw_prime");
  c.Mw_prime = h.number("Mw_prime");
  c.Zww_kg_per_m = h.number("Zww_kg_per_m", 0.0);
  c.Mww_kg = h.number("Mww_kg", 0.0);
  c.Xudot_kg = h.number("Xudot_kg", 0.0);
  c.Zwdot_kg = h.number("Zwdot_kg", 0.0);
  if (h.has("munk_moment")) {
    const std::string munk = h.text("munk_moment");
    if (munk != "added" && munk != "inside_Mw")
      h.fail("munk_moment", "unknown structure '" + munk + "'", "use \"added\" or \"inside_Mw\"");
    c.munk_factor = munk == "inside_Mw" ? 0.0 : 1.0;
    c.munk_stated = true;
  }

  // Plane derivatives: in "hydrodynamics" or in "actuators.stern_planes".
  auto readPlanes = [&c](const JsonReader& planes) {
    if (!planes.has("Z_uud_kg_per_m_deg") || !planes.has("M_uud_kg_per_deg")) return;
    const double Z = planes.number("Z_uud_kg_per_m_deg");
    const double M = planes.number("M_uud_kg_per_deg");
    // Interchange logs count the elevator trailing edge down positive, which
    // on planes aft of the CG lifts the tail and pitches the nose down (M_e
    // < 0). A profile may state its convention; otherwise the sign of M
    // tells it (a positive M per degree means trailing edge up positive, as
    // in the Delphin2 paper).
    std::string conv = planes.text("positive_deflection", "");
    if (conv.empty()) conv = M > 0 ? "trailing_edge_up" : "trailing_edge_down";
    if (conv != "trailing_edge_up" && conv != "trailing_edge_down")
      planes.fail("positive_deflection", "unknown convention '" + conv + "'",
                  "use \"trailing_edge_down\" or \"trailing_edge_up\"");
    const double s = conv == "trailing_edge_up" ? -1.0 : 1.0;
    c.Z_e_per_deg = s * Z;
    c.M_e_per_deg = s * M;
    c.has_planes = true;
    if (s < 0) c.note = Message(msg::kPlaneSignConverted);
  };
  if (h.has("Z_uud_kg_per_m_deg")) {
    readPlanes(h);
  } else if (v.sections.contains("actuators")) {
    const JsonReader a(v.sections["actuators"], v.file, "actuators");
    if (auto planes = a.optionalChild("stern_planes")) readPlanes(*planes);
  }
  return c;
}

HydroLoads steadyHydroLoads(const SteadyHydroCoefficients& c, const SteadyFlight& f) {
  const double u = f.speed_mps, au = std::abs(u);
  // Heave kinematics of the simulator: z_dot = -u sin(theta) + w cos(theta) cos(phi).
  const double w = (u * std::sin(f.pitch_rad) + f.depth_rate_mps) / (std::cos(f.pitch_rad) * std::cos(f.roll_rad));
  const double L = c.reference_length_m, L2 = L * L;
  const double kZw = 0.5 * f.density_kgm3 * L2 * c.Zw_prime;
  const double kMw = 0.5 * f.density_kgm3 * L2 * L * c.Mw_prime;
  HydroLoads h;
  h.Z_lift = (kZw * au + c.Zww_kg_per_m * std::abs(w)) * w;
  h.M_lift = (kMw * u + c.Mww_kg * std::abs(w)) * w;
  h.M_munk = c.munk_factor * (c.Xudot_kg - c.Zwdot_kg) * u * w;
  if (c.has_planes) {
    h.Z_planes = c.Z_e_per_deg * au * u * f.elevator_deg;
    h.M_planes = c.M_e_per_deg * au * u * f.elevator_deg;
  }
  return h;
}

BalanceRegressors balanceRegressors(const SteadyFlight& f) {
  const double u = f.speed_mps, au = std::abs(u);
  const double cc = std::cos(f.pitch_rad) * std::cos(f.roll_rad);
  const double w = (u * std::sin(f.pitch_rad) + f.depth_rate_mps) / cc;
  return {cc, std::sin(f.pitch_rad), au * w, u * w, std::abs(w) * w, au * u, au * u * f.elevator_deg};
}

}  // namespace auv::analysis
