#include "ballast/ballast_messages.h"
#include "ballast/thesis_greedy.h"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>

#include "ballast/ballast_solver.h"
#include "ballast/mass_quanta.h"
#include "ballast/solution_text.h"
#include "common/input_error.h"

namespace auv {
namespace {

using ballast::toKg;
using ballast::toQuanta;

enum Corner { FS = 0, FP = 1, AS = 2, AP = 3 };

std::array<std::size_t, 4> hugInLayout(const BallastProblem& pr) {
  const InputError bad("points", "the thesis method needs four points: two fore, two aft, each pair one starboard and "
                       "one port", "use solveBallast for other layouts");
  if (pr.points.size() != 4) throw bad;
  std::array<std::size_t, 4> idx{0, 1, 2, 3};
  std::sort(idx.begin(), idx.end(),
            [&](std::size_t a, std::size_t b) { return pr.points[a].position_m.x() > pr.points[b].position_m.x(); });
  if (!(pr.points[idx[1]].position_m.x() > pr.points[idx[2]].position_m.x())) throw bad;
  auto byY = [&](std::size_t& a, std::size_t& b) {
    if (pr.points[a].position_m.y() < pr.points[b].position_m.y()) std::swap(a, b);
    if (!(pr.points[a].position_m.y() > pr.points[b].position_m.y())) throw bad;
  };
  byY(idx[0], idx[1]);
  byY(idx[2], idx[3]);
  return idx;  // FS, FP, AS, AP
}

}  // namespace

ThesisAdjustment thesisAdjustment(const BallastProblem& pr) {
  validateBallastProblem(pr);
  const std::array<std::size_t, 4> at = hugInLayout(pr);
  ThesisAdjustment out;
  out.required_kg = pr.displaced_mass_kg - pr.vehicle.mass_kg;
  out.cg_shift_m = (pr.cb_m - pr.vehicle.cg_m).head<2>();
  const bool x_off = std::abs(out.cg_shift_m.x()) > kThesisCoincideM;
  const bool y_off = std::abs(out.cg_shift_m.y()) > kThesisCoincideM;
  out.alternative = x_off ? (y_off ? 4 : 2) : (y_off ? 3 : 1);
  out.continuous_kg.assign(4, 0.0);
  out.mapped_kg.assign(4, 0.0);
  if (!(out.required_kg > 0.0)) return out;

  auto x = [&](int c) { return pr.points[at[static_cast<std::size_t>(c)]].position_m.x(); };
  auto y = [&](int c) { return pr.points[at[static_cast<std::size_t>(c)]].position_m.y(); };
  const double m = out.required_kg;
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  Eigen::Vector4d b = Eigen::Vector4d::Zero();
  A.row(0) << 1, 1, 1, 1;  // eq. 5.10
  b(0) = m;
  if (out.alternative == 3) {
    A.row(1) << y(FS), y(FP), y(AS), y(AP);  // eq. 5.9
    b(1) = m * out.cg_shift_m.y();
    // eq. 5.12, moments about the origin balanced along each side (the
    // printed m5 x5 = m7 x7 has no positive solution with x7 < 0)
    A(2, FS) = x(FS);
    A(2, AS) = x(AS);
    A(3, FP) = x(FP);
    A(3, AP) = x(AP);
  } else {
    A.row(1) << x(FS), x(FP), x(AS), x(AP);  // eq. 5.8, or 5.13 with zero shift
    b(1) = out.alternative == 1 ? 0.0 : m * out.cg_shift_m.x();
    // eq. 5.11 as moments (tau5 = tau6, tau7 = tau8): no y shift per pair
    A(2, FS) = y(FS);
    A(2, FP) = y(FP);
    A(3, AS) = y(AS);
    A(3, AP) = y(AP);
  }
  const Eigen::FullPivLU<Eigen::Matrix4d> lu(A);
  if (!lu.isInvertible()) {
    throw InputError("points", "the thesis equations are singular for this layout", "use solveBallast");
  }
  const Eigen::Vector4d share = lu.solve(b);

  std::vector<std::int64_t> sizes_q;
  for (double s : pr.piece_sizes_kg) sizes_q.push_back(toQuanta(s));
  for (int c = 0; c < 4; ++c) {
    const std::size_t p = at[static_cast<std::size_t>(c)];
    out.continuous_kg[p] = share(c);
    // The thesis only adds and knows no capacities; keep its result within them.
    const double room = std::max(0.0, pr.points[p].capacity_kg - installedMassKg(pr, p));
    const double wanted = std::clamp(std::round(share(c) * 10.0) / 10.0, 0.0, room);
    std::int64_t rest = toQuanta(wanted);
    std::int64_t mapped = 0;
    for (std::size_t s = sizes_q.size(); s-- > 0;) {  // eq. 5.22-5.26: largest first, floor
      mapped += (rest / sizes_q[s]) * sizes_q[s];
      rest %= sizes_q[s];
    }
    out.mapped_kg[p] = toKg(mapped);
  }
  return out;
}

BallastSolution thesisGreedyMapping(const BallastProblem& pr) {
  const ThesisAdjustment adj = thesisAdjustment(pr);
  std::vector<std::vector<int>> delta(4, std::vector<int>(pr.piece_sizes_kg.size(), 0));
  for (std::size_t p = 0; p < 4; ++p) {
    std::int64_t rest = toQuanta(adj.mapped_kg[p]);
    for (std::size_t s = pr.piece_sizes_kg.size(); s-- > 0;) {
      const std::int64_t size_q = toQuanta(pr.piece_sizes_kg[s]);
      delta[p][s] = static_cast<int>(rest / size_q);
      rest %= size_q;
    }
  }
  BallastSolution sol = evaluateMove(pr, delta);
  sol.notes.push_back("Thesis method (\u00a75.4.1), alternative " + std::to_string(adj.alternative) +
                      ": add m_dif = " + ballast::kgText(adj.required_kg) +
                      " with the added mass centred at CB - CG, then floor each share onto the pieces.");
  for (std::size_t p = 0; p < 4; ++p) {
    const double before = installedMassKg(pr, p);
    sol.notes.push_back(ballast::pointNote(pr.points[p], pr.piece_sizes_kg, delta[p].data(), before,
                                           before + sol.add_kg[p]) +
                        " Continuous share " + ballast::kgText(adj.continuous_kg[p]) + ".");
  }
  if (sol.net_buoyancy_kg < -1e-9) {
    sol.warnings.push_back(Message(ballast::msg::kThesisHeavy, {ballast::kgText(-sol.net_buoyancy_kg)}));
  }
  return sol;
}

}  // namespace auv
