#include "sim/model_loader.h"

#include <cmath>

#include "common/units.h"
#include "vehicle/json_reader.h"

namespace auv::sim {
namespace {

constexpr std::string_view kDoc = "docs/formats/vehicle-profile.md";

RigidBody readBody(const VehicleProfile& profile, const JsonReader& hydro) {
  RigidBody b;
  b.mass_kg = profile.mass_kg;
  b.hull = profile.hull;
  // The simulator's origin is the CB; without a measured CG the vehicle is
  // taken as trimmed level with its CG bg_mm below the CB.
  const Eigen::Vector3d cg = profile.cg_m.value_or(profile.cb_m + Eigen::Vector3d(0, 0, profile.bg_m));
  b.r_g_m = cg - profile.cb_m;
  b.cb_profile_m = profile.cb_m;
  b.Iyy_kgm2 = hydro.numberIn("Iyy_kgm2", 1e-3, 1e6);
  b.reference_length_m = hydro.numberIn("reference_length_m", 0.1, 100.0, profile.hull.length_m);
  return b;
}

Hydrodynamics readHydro(const JsonReader& r) {
  r.refuseUnknownKeys({"source", "comment", "reference_length_m", "Iyy_kgm2", "Xudot_kg", "Zwdot_kg", "Mqdot_kgm2_per_rad",
                       "Xu_kg_per_s", "Zw_prime", "Zq_prime", "Mw_prime", "Mq_prime", "Xuu_kg_per_m", "Zww_kg_per_m",
                       "Zqq_kgm_per_rad2", "Mww_kg", "Mqq_kgm2_per_rad2", "munk_moment"},
                      kDoc);
  Hydrodynamics h;
  // Added masses and damping derivatives are <= 0 in SNAME sign convention.
  h.Xudot_kg = r.numberIn("Xudot_kg", -1e6, 0.0);
  h.Zwdot_kg = r.numberIn("Zwdot_kg", -1e6, 0.0);
  h.Mqdot_kgm2 = r.numberIn("Mqdot_kgm2_per_rad", -1e6, 0.0);
  h.Xu_kg_per_s = r.numberIn("Xu_kg_per_s", -1e6, 0.0, 0.0);
  h.Xuu_kg_per_m = r.numberIn("Xuu_kg_per_m", -1e6, 0.0);
  h.Zw_prime = r.numberIn("Zw_prime", -10.0, 0.0);
  h.Zq_prime = r.numberIn("Zq_prime", -10.0, 10.0);
  h.Mw_prime = r.numberIn("Mw_prime", -10.0, 10.0);
  h.Mq_prime = r.numberIn("Mq_prime", -10.0, 0.0);
  h.Zww_kg_per_m = r.numberIn("Zww_kg_per_m", -1e6, 0.0);
  h.Zqq_kgm = r.numberIn("Zqq_kgm_per_rad2", -1e6, 1e6);
  h.Mww_kg = r.numberIn("Mww_kg", -1e6, 1e6);
  h.Mqq_kgm2 = r.numberIn("Mqq_kgm2_per_rad2", -1e6, 0.0);
  const std::string munk = r.text("munk_moment", "added");
  if (munk != "added" && munk != "inside_Mw")
    r.fail("munk_moment", "unknown structure '" + munk + "'",
           "use \"added\" (Munk moment on top of M_w, the default) or \"inside_Mw\"");
  h.munk_factor = munk == "inside_Mw" ? 0.0 : 1.0;
  return h;
}

void readAssumptions(const JsonReader& r, VehicleModel& v) {
  r.refuseUnknownKeys({"source", "comment", "Ixx_kgm2", "Kpdot_kgm2", "Kp_kgm2_per_s", "Kpp_kgm2", "prop_KQ0",
                       "prop_torque_sign", "prop_max_demand", "prop_time_constant_s", "prop_max_rate_rps_per_s",
                       "thruster_deadband_rpm", "thruster_max_rpm", "thruster_time_constant_s", "stern_plane_max_deg",
                       "stern_plane_rate_deg_per_s", "hotel_w", "prop_w_per_rps2", "thruster_w_per_rpm3",
                       "thruster_idle_w", "fins_idle_w", "fins_w_per_m2s2_deg"},
                      kDoc);
  v.body.Ixx_kgm2 = r.numberIn("Ixx_kgm2", 1e-4, 1e6);
  v.hydro.Kpdot_kgm2 = r.numberIn("Kpdot_kgm2", -1e6, 0.0);
  v.hydro.Kp_kgm2_per_s = r.numberIn("Kp_kgm2_per_s", -1e6, 0.0);
  v.hydro.Kpp_kgm2 = r.numberIn("Kpp_kgm2", -1e6, 0.0);
  v.prop.KQ0 = r.numberIn("prop_KQ0", 0.0, 1.0);
  v.prop.torque_sign = r.numberIn("prop_torque_sign", -1.0, 1.0);
  v.prop.max_demand = r.numberIn("prop_max_demand", 0.0, 1e4);
  v.prop.time_constant_s = r.numberIn("prop_time_constant_s", 0.0, 100.0);
  v.prop.max_rate_rps_per_s = r.numberIn("prop_max_rate_rps_per_s", 1e-3, 1e4);
  for (int i = 0; i < v.thruster_count; ++i) {
    v.thrusters[i].deadband_rpm = r.numberIn("thruster_deadband_rpm", 0.0, 1e4);
    v.thrusters[i].max_rpm = r.numberIn("thruster_max_rpm", 1.0, 1e5);
    v.thrusters[i].time_constant_s = r.numberIn("thruster_time_constant_s", 0.0, 100.0);
  }
  v.planes.max_deg = r.numberIn("stern_plane_max_deg", 0.0, 90.0);
  v.planes.rate_deg_per_s = r.numberIn("stern_plane_rate_deg_per_s", 1e-3, 1e4);
  v.power.hotel_w = r.numberIn("hotel_w", 0.0, 1e5);
  v.power.prop_w_per_rps2 = r.numberIn("prop_w_per_rps2", 0.0, 1e6);
  v.power.thruster_w_per_rpm3 = r.numberIn("thruster_w_per_rpm3", 0.0, 1.0, 0.0);
  v.power.thruster_idle_w = r.numberIn("thruster_idle_w", 0.0, 1e4, 0.0);
  v.power.fins_idle_w = r.numberIn("fins_idle_w", 0.0, 1e4);
  v.power.fins_w_per_m2s2_deg = r.numberIn("fins_w_per_m2s2_deg", 0.0, 1e4);
}

void readActuators(const JsonReader& r, VehicleModel& v) {
  r.refuseUnknownKeys({"source", "comment", "propeller", "tunnel_thrusters", "stern_planes"}, kDoc);
  const JsonReader p = r.child("propeller");
  p.refuseUnknownKeys({"KT0", "diameter_m", "c_prop1", "c_prop2", "wake_fraction", "thrust_deduction",
                       "rps_from_demand_poly"},
                      kDoc);
  v.prop.KT0 = p.numberIn("KT0", 0.0, 2.0);
  v.prop.diameter_m = p.numberIn("diameter_m", 0.01, 10.0);
  v.prop.c1 = p.numberIn("c_prop1", 1e-3, 10.0);
  v.prop.c2 = p.numberIn("c_prop2", 1e-3, 10.0);
  v.prop.wake_fraction = p.numberIn("wake_fraction", 0.0, 0.9);
  v.prop.thrust_deduction = p.numberIn("thrust_deduction", 0.0, 0.9);
  const auto poly = p.numbers("rps_from_demand_poly");
  if (poly.size() != 3) {
    p.fail("rps_from_demand_poly", "needs exactly 3 coefficients", "give [a2, a1, a0] of n = a2 d^2 + a1 d + a0");
  }
  v.prop.rps_a2 = poly[0];
  v.prop.rps_a1 = poly[1];
  v.prop.rps_a0 = poly[2];

  if (auto t = r.optionalChild("tunnel_thrusters")) {
    t->refuseUnknownKeys({"KT_th_per_rpm2", "diameter_m", "spacing_m", "front_x_m", "aft_x_m", "c_th1_s2_per_m2", "c_th2",
                          "drag_fit_eq8"},
                         kDoc);
    v.thruster_count = 2;
    TunnelThruster th;
    th.KT_per_rpm2 = t->numberIn("KT_th_per_rpm2", 0.0, 1.0);
    th.diameter_m = t->numberIn("diameter_m", 0.005, 2.0);
    th.c_th1_s2_per_m2 = t->numberIn("c_th1_s2_per_m2", 0.0, 100.0);
    th.c_th2 = t->numberIn("c_th2", 0.0, 100.0);
    v.thrusters[0] = th;
    v.thrusters[1] = th;
    v.thrusters[0].x_m = t->numberIn("front_x_m", 0.0, 50.0);
    v.thrusters[1].x_m = t->numberIn("aft_x_m", -50.0, 0.0);
    const double spacing = t->numberIn("spacing_m", 0.01, 100.0);
    if (std::abs(spacing - (v.thrusters[0].x_m - v.thrusters[1].x_m)) > 1e-6) {
      t->fail("spacing_m", "differs from front_x_m - aft_x_m", "make the three lengths consistent");
    }
    const auto fit = t->numbers("drag_fit_eq8");
    if (fit.size() != 4) t->fail("drag_fit_eq8", "needs 4 numbers", "give [a1, b1, a2, b2] of eq. 8");
    v.thruster_drag = {fit[0], fit[1], fit[2], fit[3]};
  }

  const JsonReader s = r.child("stern_planes");
  s.refuseUnknownKeys({"X_uudd_kg_per_m_deg2", "Z_uud_kg_per_m_deg", "M_uud_kg_per_deg"}, kDoc);
  v.planes.X_uudd_per_deg2 = s.numberIn("X_uudd_kg_per_m_deg2", -100.0, 0.0);
  v.planes.Z_uud_per_deg = s.numberIn("Z_uud_kg_per_m_deg", -1e4, 1e4);
  v.planes.M_uud_per_deg = s.numberIn("M_uud_kg_per_deg", -1e4, 1e4);
}

PidGains readGains(const JsonReader& r, const std::string& key, const std::string& p_unit,
                   const std::string& i_unit, const std::string& d_unit, double to_si) {
  const JsonReader g = r.child(key);
  g.refuseUnknownKeys({"K_P_" + p_unit, "K_I_" + i_unit, "K_D_" + d_unit}, kDoc);
  return {g.number("K_P_" + p_unit) * to_si, g.number("K_I_" + i_unit) * to_si, g.number("K_D_" + d_unit) * to_si};
}

}  // namespace

VehicleModel loadVehicleModel(const VehicleProfile& profile, const nlohmann::json& doc, const std::string& file) {
  const JsonReader root(doc, file);
  VehicleModel v;
  v.id = profile.id;
  const JsonReader hydro = root.child("hydrodynamics");
  v.body = readBody(profile, hydro);
  v.hydro = readHydro(hydro);
  readActuators(root.child("actuators"), v);
  readAssumptions(root.child("sim_assumptions"), v);
  // Yaw by symmetry with pitch (axisymmetric hull, cruciform tail).
  v.yaw.Izz_kgm2 = v.body.Iyy_kgm2;
  v.yaw.Nrdot_kgm2 = v.hydro.Mqdot_kgm2;
  v.yaw.Nr_prime = v.hydro.Mq_prime;
  v.yaw.Nrr_kgm2 = v.hydro.Mqq_kgm2;
  v.yaw.N_uud_per_deg = std::abs(v.planes.M_uud_per_deg);
  v.yaw.rudder_max_deg = v.planes.max_deg;
  v.yaw.rudder_rate_deg_per_s = v.planes.rate_deg_per_s;
  return v;
}

VehicleModel loadVehicleModel(const VehicleProfile& profile) {
  return loadVehicleModel(profile, profile.sections, profile.file);
}

DepthAutopilotConfig loadAutopilotConfig(const nlohmann::json& doc, const std::string& file) {
  const JsonReader a = JsonReader(doc, file).child("autopilot");
  a.refuseUnknownKeys({"source", "comment", "sample_time_s", "hover_depth_force", "hover_cr_shift", "cr0_x_m",
                       "cr_shift_max_m", "anti_windup_depth_error_m", "anti_windup_depth_rate_mps", "hover_preload_factor",
                       "pitch_bias", "pitch_bias_max_deg", "stern_plane", "thruster_mid_speed_mps",
                       "thruster_transition_width_mps", "plane_mid_speed_mps", "plane_transition_width_mps", "heading",
                       "heading_max_rudder_deg", "heading_integrate_within_deg"},
                      kDoc);
  DepthAutopilotConfig c;
  c.sample_time_s = a.numberIn("sample_time_s", 1e-3, 10.0);
  const double deg = units::degToRad(1.0);
  if (a.has("hover_depth_force")) {
    c.hover_force = readGains(a, "hover_depth_force", "N_per_m", "N_per_m_s", "N_s_per_m", 1.0);
    c.hover_cr = readGains(a, "hover_cr_shift", "m_per_rad", "m_per_rad_s", "m_s_per_rad", 1.0);
    c.cr0_x_m = a.numberIn("cr0_x_m", -50.0, 50.0);
    c.cr_shift_max_m = a.numberIn("cr_shift_max_m", 0.0, 50.0);
    c.aw_depth_error_m = a.numberIn("anti_windup_depth_error_m", 0.0, 1e4);
    c.aw_depth_rate_mps = a.numberIn("anti_windup_depth_rate_mps", 0.0, 100.0);
    c.hover_preload_factor = a.numberIn("hover_preload_factor", 0.0, 10.0, 1.0);
  }
  c.pitch_bias = readGains(a, "pitch_bias", "deg_per_m", "deg_per_m_s", "deg_s_per_m", deg);
  if (c.pitch_bias.kp > 0.0) {
    a.fail("pitch_bias.K_P_deg_per_m", "must be <= 0 (a vehicle above its depth must pitch nose down)",
           "flip the sign");
  }
  c.pitch_bias_max_rad = a.numberIn("pitch_bias_max_deg", 0.0, 60.0) * deg;
  c.plane = readGains(a, "stern_plane", "deg_per_deg", "deg_per_deg_s", "deg_s_per_deg", 1.0);
  c.u_th_mid_mps = a.numberIn("thruster_mid_speed_mps", 0.0, 20.0, c.u_th_mid_mps);
  c.u_th_width_mps = a.numberIn("thruster_transition_width_mps", 1e-4, 20.0, c.u_th_width_mps);
  c.u_s_mid_mps = a.numberIn("plane_mid_speed_mps", 0.0, 20.0);
  c.u_s_width_mps = a.numberIn("plane_transition_width_mps", 1e-4, 20.0);
  if (a.has("heading")) {
    c.heading.enabled = true;
    c.heading.gains = readGains(a, "heading", "deg_per_deg", "deg_per_deg_s", "deg_s_per_deg", 1.0);
    if (c.heading.gains.kp < 0.0) {
      a.fail("heading.K_P_deg_per_deg", "must be >= 0 (positive rudder turns the bow to starboard)", "flip the sign");
    }
    c.heading.max_rudder_rad = a.numberIn("heading_max_rudder_deg", 0.0, 90.0, 20.0) * deg;
    c.heading.integrate_within_rad = a.numberIn("heading_integrate_within_deg", 0.0, 180.0, 10.0) * deg;
  }
  return c;
}

DepthAutopilotConfig loadAutopilotConfig(const VehicleProfile& profile) {
  return loadAutopilotConfig(profile.sections, profile.file);
}

}  // namespace auv::sim
