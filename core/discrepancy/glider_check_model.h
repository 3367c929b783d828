#pragma once
// The model check's view of a glider: the steady-glide model of
// core/analysis/glider_flight.h (Merckelbach et al. 2010) with the library
// terms switched in, compared with the log in two ways:
//  - equation error per sample: observed vertical velocity (from CTD pressure
//    or depth over a 10 s boxcar) minus the steady-glide value at the logged
//    pitch, pump volume and water; and, when the log has both a depth sensor
//    and an independent CTD pressure, depth reading minus CTD depth;
//  - simulation error: each glide flown forward in time from its first
//    sample (depth integrated from the model's vertical velocity, pressure
//    from the simulated depth), compared with the recorded depth and vertical
//    velocity.
// Ballast state: net buoyancy at the log's mean operating state (pump at its
// zero reference, as in core/analysis) and the drag coefficient Cd0, both
// always fitted, and the lift slope when the pitch range allows. The model's own constants (lift slope, Cd1, wing area, pitch
// correction, hull compressibility and thermal expansion) come from the
// profile; a compressibility of 0 in the profile is taken as 0, so the check
// can say whether the log needs one.
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "analysis/glider_flight.h"
#include "analysis/glider_target.h"
#include "discrepancy/check_model.h"
#include "missionlog/mission_log.h"
#include "vehicle/vehicle_profile.h"

namespace auv::discrepancy {

struct GliderCheckOptions {
  double min_depth_m = 10.0;
  double max_depth_m = std::numeric_limits<double>::infinity();
  double min_pitch_deg = 10.0;
  double max_roll_deg = 15.0;    // steeper banks (turns) are outside the 2-D steady glide
  int min_yos_for_yo_units = 4;  // fewer yos: cross-validate over 10-minute pieces of the glides instead
  double piece_s = 600.0;
  double rate_window_s = 10.0;
  // A glide ends when its vertical speed (20 s boxcar) falls below this, not
  // at the AUV's level band (2 cm/s): a glide near its neutral depth is slow
  // but still steady, and those samples pin the buoyancy (and the volume
  // terms and drift that change it) most sharply; a glider that makes less
  // than 5 m in 600 s (0.8 cm/s) is stalled and aborts.
  double glide_end_rate_mps = 0.005;
  // ... and starts (again) above this: a slow glide that an internal wave
  // stopped for a moment goes on being used when it moves again.
  double glide_start_rate_mps = 0.02;
  // Samples whose mean vertical speed over this window is below
  // glide_end_rate_mps hover (a stall before the abort): no steady glide.
  double stall_window_s = 300.0;
  std::size_t max_rows = 30000;  // evenly decimated beyond this (the rate is a 10 s boxcar)
  double default_density_kgm3 = 1025.0;  // only when the log has no density
  // Lift slope (Seaglider: hd_a) fitted as a scale of the profile's value
  // when the glides' |pitch| spans at least this much (10th-90th percentile).
  bool fit_lift_slope = false;  // off: on synthetic logs it trades against pitch bias and mass drift
  double lift_slope_min_pitch_spread_deg = 5.0;
};

class GliderCheckModel final : public CheckModel {
 public:
  // Throws InputError when the log lacks pitch, pump volume or depth/pressure,
  // or has no steady glide.
  GliderCheckModel(const MissionLog& log, const VehicleProfile& profile, const GliderCheckOptions& options = {});
  ~GliderCheckModel() override;

  unsigned family() const override { return kGliderFamily; }
  const SampleTable& samples() const override { return table_; }
  std::vector<std::string> nuisanceNames() const override;
  Eigen::VectorXd nuisanceStart() const override;
  Eigen::VectorXd nuisanceScale() const override;
  Eigen::VectorXd nuisanceLower() const override;
  Eigen::VectorXd nuisanceUpper() const override;
  bool applicable(std::size_t term) const override;
  std::vector<Channel> equationChannels() const override;
  void equationError(const Params& p, std::span<const std::uint32_t> rows, double* out) const override;
  std::vector<Channel> simulationChannels() const override;
  void simulationError(const Params& p, std::vector<double>& out) const override;
  double netBuoyancyKg(const Params& p) const override { return p.nuisance[0]; }
  Message description() const override;
  std::vector<std::string> notes() const override { return notes_; }

  const analysis::GliderFlightConstants& constants() const { return c_; }
  const analysis::ReferenceState& reference() const { return ref_; }
  const TermValues& baseline() const { return baseline_; }
  bool hasDepthReference() const { return has_depth_ref_; }

  // Mass (kg) to add for neutral at `target` with the pump at zero: the
  // hull volume of these parameters carried to the target's pressure and
  // temperature by the profile's and the fitted volume terms, against the
  // mass at the END of the log (a fitted mass drift included).
  double massToAddKg(const Params& p, const analysis::GliderTarget& target) const;
  // Hull volume at p = 0, the reference temperature and pump zero (m3).
  double hullVolumeM3(const Params& p) const;
  // Mass the vehicle has at the end of the log minus its profile mass.
  double massChangeAtEndKg(const Params& p) const;
  double hoursFromReferenceToEnd() const { return (t_end_ - t_ref_) / 3600.0; }

  // Model vertical velocity (up positive, through the water plus current)
  // at a row for the given parameters, with pressure `p_dbar`.
  double modelW(const Params& p, std::size_t row, double p_dbar) const;

 private:
  struct Row {
    double pitch_rad, pump_m3, rho, T, p, w_obs, depth_sensor, z_ref;
  };
  class AlphaCache;
  struct Prepared {
    TermValues terms{};
    double V0 = 0.0, Cd0 = 0.0, lift_scale = 1.0, a = 0.0;
    const std::vector<double>* alpha = nullptr;
  };
  Prepared prepare(const Params& p) const;
  double rowW(const Prepared& q, std::size_t row, double p_dbar, Effects& e) const;
  double volumeFactor(const TermValues& terms, double p_dbar, double T, double hours) const;

  analysis::GliderFlightConstants c_;
  analysis::ReferenceState ref_;
  TermValues baseline_{};
  std::vector<Row> rows_;
  SampleTable table_;
  bool has_depth_ref_ = false;
  bool fit_lift_ = false;  // a depth sensor and an independent CTD pressure
  double latitude_ = 45.0;
  double t_ref_ = 0.0;
  double t_end_ = 0.0;  // last instant of the log
  std::string obs_channel_;
  std::vector<std::string> notes_;
  std::unique_ptr<AlphaCache> alpha_;
};

}  // namespace auv::discrepancy
