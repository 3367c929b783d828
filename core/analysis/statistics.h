#pragma once
// Means of logged quantities with honest confidence intervals. Logged samples
// are strongly autocorrelated (a 10 Hz pitch record does not hold 10
// independent values per second), so the interval uses an effective sample
// size from the lag-1 autocorrelation (AR(1) model: n_eff = n (1 - r)/(1 + r))
// and, when the samples come in several blocks (steady legs, yos), is never
// narrower than the scatter of the block means. See
// docs/decisions/analysis-confidence-intervals.md.
#include <cstddef>
#include <limits>
#include <vector>

namespace auv::analysis {

// Two-sided 95 % quantile of Student's t with nu degrees of freedom (nu >= 1,
// fractional allowed because effective sample sizes are fractional).
double studentT975(double nu);

struct MeanEstimate {
  double mean = std::numeric_limits<double>::quiet_NaN();
  double sd = std::numeric_limits<double>::quiet_NaN();  // sample standard deviation
  double se = std::numeric_limits<double>::quiet_NaN();  // standard error of the mean
  double ci95 = std::numeric_limits<double>::quiet_NaN();  // half-width
  double lag1 = 0.0;     // lag-1 autocorrelation within blocks, clamped to [0, 0.9999]
  double n_eff = 0.0;    // effective sample size
  std::size_t n = 0;
  std::size_t blocks = 0;
  bool valid() const { return n > 0; }
};

// How the samples vary within a block. kStationary: noise about a constant
// (a steady leg); the AR(1) effective size applies. kProfile: a deterministic
// trend plus noise (water properties while a glider profiles through a
// stratified column); the trend is signal, so the within-block part of the
// interval comes from the sample-to-sample noise (variance of first
// differences / 2) and the between-block term carries the rest.
enum class SeriesModel { kStationary, kProfile };

// Single pass, no per-sample allocation (one small entry per block). Values
// are shifted by the first sample so that sums of squares do not cancel for
// offsets like a 300 m depth with centimetre noise.
class MeanAccumulator {
 public:
  void add(double x);
  // The next add() starts a new block: no lag pair spans the break.
  void endBlock();
  MeanEstimate result(SeriesModel model = SeriesModel::kStationary) const;
  std::size_t count() const { return n_; }

 private:
  // Sums of shifted values per block; the lag-1 autocorrelation is taken
  // about each block's own mean so that differences between blocks show up
  // in the between-block term, not as a correlation of 1.
  struct Block {
    double s1 = 0.0, s2 = 0.0;
    double pair_prod = 0.0, pair_first = 0.0, pair_second = 0.0, diff2 = 0.0;
    std::size_t n = 0, pairs = 0;
  };
  double shift_ = 0.0;
  double s1_ = 0.0, s2_ = 0.0;
  std::size_t n_ = 0;
  double prev_ = 0.0;
  Block open_;
  std::vector<Block> closed_;
};

}  // namespace auv::analysis
