#include "planning/classic_table.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "ballast/mass_quanta.h"
#include "common/input_error.h"

namespace auv {
namespace {

using Pattern = std::array<int, 4>;  // multiples of w_small per point, FS FP AS AP

// Sign class of an error e = reference - deviation against its dead band.
int signOf(double e, double band) { return e < -band ? -1 : (e > band ? 1 : 0); }

const char* signName(int s) { return s < 0 ? "negative" : (s > 0 ? "positive" : "neutral"); }

// Index 0..8 for (pitch, roll) in {-1, 0, 1}^2.
std::size_t cell(int p, int r) { return static_cast<std::size_t>((p + 1) * 3 + (r + 1)); }

// App. E.1 / E.2, one pattern per (pitch e, roll e) cell. W = B and W > B
// remove only where pieces are present; W < B only adds.
Pattern balancedPattern(int p, int r) {
  static const std::array<Pattern, 9> t = {{
      {0, 1, -1, 0},    // p-, r-
      {1, 1, -1, -1},   // p-, r0
      {1, 0, 0, -1},    // p-, r+
      {-1, 1, -1, 1},   // p0, r-
      {0, 0, 0, 0},     // p0, r0
      {1, -1, 1, -1},   // p0, r+
      {-1, 0, 0, 1},    // p+, r-
      {-1, -1, 1, 1},   // p+, r0
      {0, -1, 1, 0},    // p+, r+
  }};
  return t[cell(p, r)];
}

Pattern lightPattern(int p, int r) {
  static const std::array<Pattern, 9> t = {{
      {1, 2, 0, 1},  // p-, r-
      {1, 1, 0, 0},  // p-, r0
      {2, 1, 1, 0},  // p-, r+
      {0, 1, 0, 1},  // p0, r-
      {1, 1, 1, 1},  // p0, r0
      {1, 0, 1, 0},  // p0, r+
      {0, 1, 1, 2},  // p+, r-
      {0, 0, 1, 1},  // p+, r0
      {1, 0, 2, 1},  // p+, r+
  }};
  return t[cell(p, r)];
}

// W > B: the full pattern, and for the combined cells the code's fallback
// that removes a single piece when the full pattern's pieces are not there.
struct HeavyRow {
  Pattern full;
  Pattern fallback;  // all zero = none
};

HeavyRow heavyRow(int p, int r) {
  static const std::array<HeavyRow, 9> t = {{
      {{-1, 0, -2, -1}, {0, 0, -1, 0}},   // p-, r-
      {{0, 0, -1, -1}, {0, 0, 0, 0}},     // p-, r0
      {{0, -1, -1, -2}, {0, 0, 0, -1}},   // p-, r+
      {{-1, 0, -1, 0}, {0, 0, 0, 0}},     // p0, r-
      {{-1, -1, -1, -1}, {0, 0, 0, 0}},   // p0, r0
      {{0, -1, 0, -1}, {0, 0, 0, 0}},     // p0, r+
      {{-2, -1, -1, 0}, {-1, 0, 0, 0}},   // p+, r-
      {{-1, -1, 0, 0}, {0, 0, 0, 0}},     // p+, r0
      {{0, -2, 0, -1}, {0, -1, 0, 0}},    // p+, r+
  }};
  return t[cell(p, r)];
}

bool isZero(const Pattern& x) { return std::all_of(x.begin(), x.end(), [](int v) { return v == 0; }); }

// The code's guards: every point the pattern removes from holds at least
// that many small pieces' worth of mass.
bool removable(const Pattern& x, const std::array<double, 4>& m, double w) {
  for (std::size_t i = 0; i < 4; ++i) {
    if (x[i] < 0 && m[i] < -x[i] * w - 1e-9) return false;
  }
  return true;
}

}  // namespace

double mapOntoPieces(double mass_kg, const std::vector<double>& sizes) {
  if (!(mass_kg > 0.0)) return 0.0;
  std::int64_t rest = ballast::toQuanta(mass_kg), mapped_q = 0;
  for (std::size_t s = sizes.size(); s-- > 0;) {
    const std::int64_t q = ballast::toQuanta(sizes[s]);
    mapped_q += (rest / q) * q;
    rest %= q;
  }
  return ballast::toKg(mapped_q);
}

ClassicResult classicAdjustment(const ClassicInput& in) {
  const double w = in.small_piece_kg;
  if (!(w > 0.0) || !std::isfinite(w)) {
    throw InputError("small_piece_kg", "the smallest piece must be positive", "e.g. 1.2 kg for HUGIN");
  }
  if (in.piece_sizes_kg.empty()) throw InputError("piece_sizes_kg", "no piece sizes", "list the kit, e.g. 1.2, 2.4, 4.8");
  for (double v : {in.depth_error_m, in.pitch_error_deg, in.roll_deg, in.computed_imbalance_kg}) {
    if (!std::isfinite(v)) throw InputError("errors", "deviations must be numbers", "give depth, pitch and roll deviations");
  }
  const ClassicThresholds& th = in.thresholds;
  // Errors as the code sees them: e = reference (0) - deviation.
  const double e_d = -in.depth_error_m;
  const double e_b = -in.computed_imbalance_kg;
  const int p = signOf(-in.pitch_error_deg, th.pitch_deg);
  const int r = signOf(-in.roll_deg, th.roll_deg);
  const std::array<double, 4>& m = in.installed_kg;

  ClassicResult out;
  out.pitch_sign = signName(p);
  out.roll_sign = signName(r);
  std::array<double, 4> extra{};  // w_1..w_4, the m_dif spread
  Pattern x{};
  int extra_sign = 0;
  const bool within = e_d <= -th.depth_lo_m && e_d >= -th.depth_hi_m;
  auto spread = [&](double m_dif) {
    const double xf = std::abs(in.x_fore_m), xa = std::abs(in.x_aft_m);
    const double m_f = xa / (xf + xa) * m_dif, m_a = xf / (xf + xa) * m_dif;
    extra = {m_f / 2, m_f / 2, m_a / 2, m_a / 2};
  };
  if (within) {
    out.weight_case = "W = B";
    x = balancedPattern(p, r);
    if (!removable(x, m, w)) {
      out.blocked = !isZero(x);
      x = {};
    }
  } else if (e_d < -th.depth_lo_m) {
    out.weight_case = "W < B";
    x = lightPattern(p, r);
    // e_b = W - B (eq. 5.19): the code adjusts only when the computation
    // contradicts the depth (light by depth, heavy by weight), and then by a
    // quarter of it less four small pieces, which can be negative.
    if (e_b > th.weight_kg) spread(e_b / 4 - 4 * w);
    extra_sign = 1;
  } else {
    out.weight_case = "W > B";
    const HeavyRow row = heavyRow(p, r);
    if (removable(row.full, m, w)) {
      x = row.full;
    } else if (!isZero(row.fallback) && removable(row.fallback, m, w)) {
      x = row.fallback;
    } else {
      out.blocked = true;
      x = {};
    }
    if (!out.blocked) {
      if (e_b < -th.weight_kg) spread(std::abs(std::abs(e_b) / 4 - 4 * w));
      extra_sign = -1;
    }
  }
  for (std::size_t i = 0; i < 4; ++i) {
    out.target_kg[i] = std::max(0.0, m[i] + extra_sign * extra[i] + x[i] * w);
    out.mapped_kg[i] = out.target_kg[i] == m[i] ? m[i] : mapOntoPieces(out.target_kg[i], in.piece_sizes_kg);
    out.change_kg[i] = ballast::toKg(ballast::toQuanta(out.mapped_kg[i] - m[i]));
  }
  return out;
}

}  // namespace auv
