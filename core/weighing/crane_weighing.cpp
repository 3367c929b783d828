#include "weighing/crane_weighing.h"

#include <cmath>
#include <cstdio>

#include "common/input_error.h"
#include "weighing/weighing_messages.h"

namespace auv {
namespace {

const char* kScaleNames[4] = {"scales.fore_starboard", "scales.fore_port", "scales.aft_starboard",
                              "scales.aft_port"};

void requireReading(double v, const char* field) {
  if (!std::isfinite(v)) throw InputError(field, "reading is not a number", "enter the scale reading in kg");
  if (v < 0.0) throw InputError(field, "reading is negative", "enter the scale reading in kg (>= 0)");
}

std::string kg(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f kg", v);
  return buf;
}

}  // namespace

CraneResult weighCrane(const CraneWeighing& in) {
  for (int i = 0; i < 4; ++i) requireReading(in.scales_kg[i], kScaleNames[i]);
  requireReading(in.total_kg, "total");
  if (!(in.total_kg > 0.0)) throw InputError("total", "total mass is zero", "enter the hook scale reading in kg");
  if (!std::isfinite(in.rope_x_fore_m) || !std::isfinite(in.rope_x_aft_m)) {
    throw InputError("rope-x", "rope position is not a number", "give FORE_M,AFT_M in metres");
  }
  if (!(in.rope_x_fore_m > in.rope_x_aft_m)) {
    throw InputError("rope-x", "the fore rope must be forward of the aft rope",
                     "give FORE_M,AFT_M with FORE_M > AFT_M (x forward)");
  }
  if (!(in.rope_y_m > 0.0) || !std::isfinite(in.rope_y_m)) {
    throw InputError("rope-y", "rope half-spacing must be positive", "give the lateral offset in metres, e.g. 0.25");
  }

  CraneResult r;
  const double x[4] = {in.rope_x_fore_m, in.rope_x_fore_m, in.rope_x_aft_m, in.rope_x_aft_m};
  const double y[4] = {in.rope_y_m, -in.rope_y_m, in.rope_y_m, -in.rope_y_m};
  double parts = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (int i = 0; i < 4; ++i) {
    parts += in.scales_kg[i];
    moment += in.scales_kg[i] * Eigen::Vector3d(x[i], y[i], in.cg_z_m);
  }
  if (!(parts > 0.0)) throw InputError("scales", "all part readings are zero", "enter the four scale readings");
  r.sum_of_parts_kg = parts;
  r.sum_mismatch_kg = parts - in.total_kg;
  const double mismatch = std::abs(r.sum_mismatch_kg);
  if (mismatch > 5.0 * in.sum_tolerance_kg) {
    // Up to 5x the tolerance is accepted with a warning (below); say so, so
    // the refusal and the acceptance are one rule.
    throw InputError("scales",
                     "the four readings add up to " + kg(parts) + " but the total is " + kg(in.total_kg) + " (" +
                         kg(mismatch) + " apart, more than 5 x the " + kg(in.sum_tolerance_kg) + " tolerance)",
                     "re-read the scales; they must agree within " + kg(5.0 * in.sum_tolerance_kg) +
                         " to be used (within " + kg(in.sum_tolerance_kg) + " without a warning)");
  }
  if (mismatch > in.sum_tolerance_kg) {
    r.warnings.push_back(Message(weighing::msg::kSumMismatch, {kg(parts), kg(in.total_kg), kg(in.sum_tolerance_kg)}));
  }
  // The CG is a ratio of the parts, so it does not depend on which total we
  // trust; the mass is the hook reading (one scale, one rounding).
  const Eigen::Vector3d cg = moment / parts;
  r.mass.mass_kg = in.total_kg;
  r.mass.cg_m = cg;
  r.mass.moment_kgm = in.total_kg * cg;

  // Uncertainty: each reading has a uniform rounding error of +-res/2,
  // sigma = res/sqrt(12); propagate through x_G = sum(m_i x_i)/sum(m_i).
  const double s = in.scale_resolution_kg / std::sqrt(12.0);
  double vx = 0.0, vy = 0.0;
  for (int i = 0; i < 4; ++i) {
    vx += std::pow((x[i] - cg.x()) / parts * s, 2);
    vy += std::pow((y[i] - cg.y()) / parts * s, 2);
  }
  r.cg_sigma_m = {std::sqrt(vx), std::sqrt(vy), 0.0};
  return r;
}

}  // namespace auv
