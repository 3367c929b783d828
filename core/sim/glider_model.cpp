#include "sim/glider_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/input_error.h"
#include "common/units.h"
#include "hydrostatics/static_trim.h"
#include "vehicle/json_reader.h"

namespace auv::sim {

GliderModel loadGliderModel(const VehicleProfile& p) {
  if (!p.sections.contains("glider_flight")) {
    throw InputError("glider_flight", "vehicle '" + p.id + "' has no glider flight parameters",
                     "add a \"glider_flight\" section to " + p.file, {p.file, 0, 0});
  }
  const JsonReader f(p.sections["glider_flight"], p.file, "glider_flight");
  f.refuseUnknownKeys({"source", "comment", "hull_compressibility_per_dbar", "wing_area_m2", "lift_slope_per_rad",
                       "induced_drag_per_rad2", "Cd0", "pump_max_cm3", "pump_rate_cm3_per_s", "pump_x_mm",
                       "pitch_battery_mass_kg", "pitch_battery_travel_mm", "pitch_battery_rate_mm_per_s",
                       "pitch_time_constant_s", "speed_time_constant_s", "dive_pitch_deg", "climb_pitch_deg",
                       "control_interval_s", "hotel_w", "pump_w", "pitch_battery_w"},
                      "docs/formats/vehicle-profile.md");
  GliderModel g;
  g.id = p.id;
  g.mass_kg = p.mass_kg;
  const Eigen::Vector3d cg = p.cg_m.value_or(p.cb_m + Eigen::Vector3d(0, 0, p.bg_m));
  g.r_g_m = cg - p.cb_m;
  g.cb_profile_m = p.cb_m;
  g.hull = p.hull;
  if (f.has("hull_compressibility_per_dbar")) {
    g.hull.compressibility_per_dbar = f.numberIn("hull_compressibility_per_dbar", 0.0, 1e-3);
  }
  g.wing_area_m2 = f.numberIn("wing_area_m2", 1e-3, 10.0);
  g.lift_slope_per_rad = f.numberIn("lift_slope_per_rad", 0.1, 50.0);
  g.induced_drag_per_rad2 = f.numberIn("induced_drag_per_rad2", 0.0, 1000.0);
  g.Cd0 = f.numberIn("Cd0", 1e-3, 10.0);
  g.pump_max_m3 = f.numberIn("pump_max_cm3", 1.0, 1e5) * 1e-6;
  g.pump_rate_m3_per_s = f.numberIn("pump_rate_cm3_per_s", 0.01, 1e4) * 1e-6;
  g.pump_x_m = units::mmToM(f.numberIn("pump_x_mm", -1e4, 1e4));
  g.battery_mass_kg = f.numberIn("pitch_battery_mass_kg", 0.01, 1e3);
  g.battery_travel_m = units::mmToM(f.numberIn("pitch_battery_travel_mm", 0.1, 1e3));
  g.battery_rate_m_per_s = units::mmToM(f.numberIn("pitch_battery_rate_mm_per_s", 0.01, 1e3));
  g.pitch_time_constant_s = f.numberIn("pitch_time_constant_s", 0.0, 1e3);
  g.speed_time_constant_s = f.numberIn("speed_time_constant_s", 0.0, 1e3);
  g.dive_pitch_rad = units::degToRad(f.numberIn("dive_pitch_deg", -80.0, -1.0));
  g.climb_pitch_rad = units::degToRad(f.numberIn("climb_pitch_deg", 1.0, 80.0));
  g.control_interval_s = f.numberIn("control_interval_s", 0.05, 600.0);
  g.hotel_w = f.numberIn("hotel_w", 0.0, 1e3);
  g.pump_w = f.numberIn("pump_w", 0.0, 1e4);
  g.battery_w = f.numberIn("pitch_battery_w", 0.0, 1e3);
  return g;
}

namespace {

// Smallest root of h(x) = a x tan(x + phi) - Cd0 - Cd1 x^2 on (0, pi/2 - phi):
// h(0) = -Cd0 < 0 and h grows without bound towards the top, so a scan and
// bisection always find the unstalled glide (as gliderflight's iteration).
double angleOfAttackAbs(const GliderModel& g, double phi) {
  const double top = 0.5 * std::numbers::pi - phi;
  auto h = [&](double x) {
    return g.lift_slope_per_rad * x * std::tan(x + phi) - g.Cd0 - g.induced_drag_per_rad2 * x * x;
  };
  const double step = std::min(0.002, 0.25 * top);
  double lo = 0.0, hi = top;
  for (double x = step; x < top; x += step) {
    if (h(x) > 0.0) {
      hi = x;
      lo = x - step;
      break;
    }
  }
  for (int i = 0; i < 60 && hi - lo > 1e-14; ++i) {
    const double mid = 0.5 * (lo + hi);
    (h(mid) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

SteadyGlideSolution steadyGlide(const GliderModel& g, double rho, double F_B, double theta) {
  SteadyGlideSolution s;
  if (!(F_B * theta > 0.0)) return s;  // nose up needs lift from buoyancy, nose down from weight
  const double phi = std::abs(theta);
  const double a = angleOfAttackAbs(g, phi);
  const double Cd = g.Cd0 + g.induced_drag_per_rad2 * a * a;
  const double gamma = phi + a;
  s.gliding = true;
  s.alpha_rad = std::copysign(a, theta);
  s.speed_mps = std::sqrt(2.0 * std::abs(F_B) * std::sin(gamma) / (rho * g.wing_area_m2 * Cd));
  s.w_up_mps = s.speed_mps * std::sin(theta + s.alpha_rad);
  return s;
}

namespace {

// d = W r_g - B r_b of core hydrostatics for this battery and pump.
Eigen::Vector3d trimVector(const GliderModel& g, const FlownMass& m, double V_hull, double rho, double battery,
                           double pump) {
  const double W = m.mass_kg * units::g0;
  const double V = V_hull + pump;
  const double B = rho * units::g0 * V;
  const Eigen::Vector3d r_g = m.r_g_m + Eigen::Vector3d(g.battery_mass_kg * battery / m.mass_kg, 0, 0);
  const Eigen::Vector3d r_b(pump * g.pump_x_m / V, 0, 0);
  return W * r_g - B * r_b;
}

}  // namespace

GliderTrim gliderStaticTrim(const GliderModel& g, const FlownMass& m, double V_hull, double rho, double battery,
                            double pump) {
  const StaticTrim t = staticTrimFromOffset(trimVector(g, m, V_hull, rho, battery, pump));
  return {t.pitch_rad, t.roll_rad};
}

double batteryForPitch(const GliderModel& g, const FlownMass& m, double V_hull, double rho, double pump,
                       double pitch) {
  // pitch = atan2(-d_x, hypot(d_y, d_z)) and d_x is linear in the battery
  // position with slope g0 M_b.
  const Eigen::Vector3d d0 = trimVector(g, m, V_hull, rho, 0.0, pump);
  const double dx_target = -std::tan(pitch) * std::hypot(d0.y(), d0.z());
  const double x = (dx_target - d0.x()) / (units::g0 * g.battery_mass_kg);
  return std::clamp(x, -g.battery_travel_m, g.battery_travel_m);
}

}  // namespace auv::sim
