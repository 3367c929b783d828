#pragma once
// Vertical-plane rigid-body dynamics of the Delphin2 paper (eq. 1-9) in the
// Fossen/SNAME form  M nu_dot + C(nu) nu + D(nu) nu + g(eta) = tau + d_tau,
// nu = [u, w, q], eta = [x, z, theta], plus a roll degree of freedom p/phi
// with its own restoring moment, damping and the propeller reaction torque.
// Restoring forces are core hydrostatics' g(eta) (restoringForces, checked
// term by term in the tests), so the simulator and the ballast analysis share
// one definition.
// M is diagonal as in the paper's eq. 2 (m z_g coupling neglected, see
// docs/decisions/sim-dynamics-form.md).
#include <Eigen/Core>

#include "sim/actuator_state.h"
#include "sim/vehicle_model.h"

namespace auv::sim {

// [u, w, q, p, x, z, theta, phi]
using StateVector = Eigen::Matrix<double, 8, 1>;
enum StateIndex { kU = 0, kW, kQ, kP, kX, kZ, kTheta, kPhi };

// Generalised forces [X, Z, M, K] in body axes.
using Force4 = Eigen::Vector4d;

// An angle with its sine and cosine.
struct Trig1 {
  double angle = 0.0, s = 0.0, c = 1.0;
};

// Quantities held constant over one model step (0.05 s): water density at the
// current depth, weight and buoyancy, and the actuator state (zero-order hold).
struct StepInputs {
  double water_density_kgm3 = 1000.0;
  double weight_n = 0.0;
  double buoyancy_n = 0.0;
  ActuatorState actuators;
  Force4 external = Force4::Zero();  // e.g. a disturbance, body axes
};

// Every term of the equation at one state, for tests and traces.
struct ForceBreakdown {
  Force4 actuators = Force4::Zero();   // tau: propeller, tunnel thrusters, stern planes
  Force4 tunnel_drag = Force4::Zero(); // d_tau, eq. 9
  Force4 damping = Force4::Zero();     // -D(nu) nu
  Force4 coriolis = Force4::Zero();    // -C(nu) nu
  Force4 restoring = Force4::Zero();   // -g(eta)
  double prop_thrust_n = 0.0;
  std::array<double, kMaxThrusters> thruster_n{};
};

class Dynamics {
 public:
  explicit Dynamics(const VehicleModel& model);

  // Mass and CG (relative to CB) of the vehicle as flown, e.g. after a ballast
  // change; extra inertia from the moved masses is added to I_xx and I_yy.
  void setMassProperties(double mass_kg, const Eigen::Vector3d& r_g_m, double extra_Ixx_kgm2 = 0.0,
                         double extra_Iyy_kgm2 = 0.0);
  void setStepInputs(const StepInputs& in);

  StateVector derivative(const StateVector& s) const;
  ForceBreakdown breakdown(const StateVector& s) const;
  // Classical fourth-order Runge-Kutta over dt with the step inputs held.
  void rk4Step(StateVector& s, double dt) const;
  // Pitch and roll with their sines and cosines at the start of the last
  // rk4Step, for the heading kinematics that ride along with the step.
  const Trig1& lastStepPitch() const { return last_theta_; }
  const Trig1& lastStepRoll() const { return last_phi_; }

  double massKg() const { return mass_; }
  const Eigen::Vector3d& cgRelativeToCb() const { return r_g_; }
  // Diagonal of M: [m - X_udot, m - Z_wdot, I_yy - M_qdot, I_xx - K_pdot].
  const Eigen::Vector4d& massDiagonal() const { return m_diag_; }

 private:
  // theta0/phi0: sines and cosines at the start of the RK4 step, or null.
  template <bool kBreakdown>
  StateVector evaluate(const StateVector& s, const Trig1* theta0, const Trig1* phi0, ForceBreakdown* out) const;
  void updateConstants();

  // Products that are constant over one step, so that an evaluation only
  // does the work that depends on the state.
  struct StepConstants {
    double Zw = 0.0, Zq = 0.0, Mw = 0.0, Mq = 0.0;  // 0.5 rho L^k X' (times u at evaluation)
    double half_rho_vol23 = 0.0;
    double m_xg = 0.0, m_zg = 0.0, m_minus_Zwdot = 0.0, m_minus_Xudot = 0.0;
    double W_minus_B = 0.0;
    Eigen::Vector3d Wrg = Eigen::Vector3d::Zero();
    double prop_J_per_u = 0.0, prop_thrust0 = 0.0, prop_torque0 = 0.0;
    double plane_X = 0.0, plane_Z = 0.0, plane_M = 0.0;
    std::array<double, kMaxThrusters> th_static{}, th_axial{}, th_jet{};
  };

  const VehicleModel* model_;
  double vol23_ = 0.0;  // V^(2/3) of eq. 9
  double mass_ = 0.0, Ixx_ = 0.0, Iyy_ = 0.0;
  Eigen::Vector3d r_g_ = Eigen::Vector3d::Zero();
  StepInputs in_;
  Eigen::Vector4d m_diag_ = Eigen::Vector4d::Ones(), m_inv_ = Eigen::Vector4d::Ones();
  StepConstants k_;
  mutable Trig1 last_theta_, last_phi_;
};

}  // namespace auv::sim
