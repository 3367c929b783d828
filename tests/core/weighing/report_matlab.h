#pragma once
// Literal transcriptions of Baird 2007 App. A (MATLAB), bugs included, used
// only to show that we read the report's printed session numbers right. Our
// physics lives in core/weighing; docs/decisions/slocum-report-code-bugs.md
// lists where and why the two differ.
#include <algorithm>
#include <cmath>

namespace auv::report {

// h_a = (mass_a * cos(sensor_a)) * glider_r / (new_mass * sin(sensor_a + roll_angle))
inline double hArm(double mass, double sensor, double roll_angle, double new_mass, double glider_r = 0.1065) {
  return mass * std::cos(sensor) * glider_r / (new_mass * std::sin(sensor + roll_angle));
}

struct PosnCalc {
  double theta;
  double h_out;
};

// posncalc.m: note `theta = -sin(...)` where asin is meant.
inline PosnCalc posncalc(double h, double beta, double total_mass, double battery_mass) {
  const double battery_r = 0.0635;
  const double total_x = -h * std::sin(beta);
  const double total_y = -h * std::cos(beta);
  const double glider_mass = total_mass - battery_mass;
  const double glider_x = total_x * total_mass / glider_mass;
  const double glider_y = (total_y * total_mass + battery_r * battery_mass) / glider_mass;
  const double battery_x = -(glider_x * glider_mass) / battery_mass;
  const double battery_y = -std::sqrt(battery_r * battery_r - battery_x * battery_x);
  return {-std::sin(battery_x / battery_r), -(glider_y * glider_mass + battery_y * battery_mass) / total_mass};
}

struct CgChange {
  double beta_new, h_new, m_p_new, m_s_new;  // masses in kg (inputs were grams)
};

// cgchange.m: x_s and x_p are never defined in the printed function; the
// logged App. C values are reproduced (to ~3e-5 rad) with them zero, i.e.
// with the moved masses dropped. Note also x/y built from cos/sin swapped.
inline CgChange cgchange(double beta, double h, double m_t, double m_p, double m_s, double m_max, double r,
                         double delta) {
  const double x_s = 0.0, x_p = 0.0;
  const double x_t = -h * std::cos(beta);
  const double y_t = h * std::sin(beta);
  const double m_g = m_t - (m_p + m_s) / 1000.0;
  const double x_g = (m_t * x_t + r * ((m_p - m_s) / 1000.0) * std::cos(delta)) / m_g;
  double m_p_new = 0.0, m_s_new = 0.0;
  if (beta < 0) {
    m_p_new = m_max / 1000.0;
    m_s_new = ((m_p + m_s) - m_max) / 1000.0;
  } else if (beta > 0) {
    m_s_new = m_max / 1000.0;
    m_p_new = ((m_p + m_s) - m_max) / 1000.0;
  }
  const double x_t_new = (x_g * m_g + x_s * m_s_new + x_p * m_p_new) / m_t;
  return {std::atan(x_t_new / y_t), std::sqrt(x_t_new * x_t_new + y_t * y_t), m_p_new, m_s_new};
}

// newhcalc.m (disk weights, r = 0.07): physically right, h + 2 r dm / m_t.
inline double newhcalc(double m_top, double m_bottom, double mass_change, double m_t, double h) {
  const double r = 0.07;
  const double m_g = m_t - (m_top + m_bottom);
  const double y_g = -(m_t * h + r * (m_top - m_bottom)) / m_g;
  const double m_top_new = m_top - mass_change;
  const double m_bottom_new = m_bottom + mass_change;
  return ((m_bottom_new - m_top_new) * r - m_g * y_g) / m_t;
}

struct Last {
  double h_out, upper_out, lower_out;  // grams for the bottles
};

// last.m: y_g adds the bottle moments instead of removing them, and the ideal
// case moves `del` into both bottles (lower + del instead of lower - del).
inline Last last(double m_t, double upper, double lower, double h) {
  const double h_opt = 0.006, r_upper = 0.072, r_lower = -0.058;
  const double m_max = std::min(upper + lower, 450.0);
  const double m_g = m_t - (lower + upper) / 1000.0;
  const double y_g = ((lower / 1000.0) * r_lower + (upper / 1000.0) * r_upper - m_t * h) / m_g;
  const double del =
      -(m_t * h_opt + m_g * y_g + (upper / 1000.0) * r_upper + (lower / 1000.0) * r_lower) / (r_upper - r_lower);
  double upper_out = upper + del * 1000.0;
  double lower_out = lower + del * 1000.0;
  if (upper_out > 450 || upper_out < 0 || lower_out > 450 || lower_out < 0) {
    if (h > h_opt) {
      upper_out = m_max;
      lower_out = upper + lower - m_max;
    } else if (h < h_opt) {
      lower_out = m_max;
      upper_out = upper + lower - m_max;
    }
    return {-(m_g * y_g + (upper_out / 1000.0) * r_upper + (lower_out / 1000.0) * r_lower) / m_t, upper_out,
            lower_out};
  }
  return {h_opt, upper_out, lower_out};
}

}  // namespace auv::report
