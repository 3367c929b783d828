#pragma once
// The thesis's first-mission method, kept for comparison (Lillemoen 2014,
// §5.4.1 and §5.5.4): the mass to add is m_dif = B - W (eq. 5.1-5.2); it is
// split over the four points so that the *added mass's* centroid equals
// CB - CG (eq. 5.7-5.16); each point's share is then floored onto the
// pieces, largest first (eq. 5.22-5.26). Two details follow Tables G.1/G.2
// rather than the prose; see docs/decisions/ballast-thesis-greedy.md:
//   - alternative 4 (CG off in x and y) is solved like alternative 2: the
//     Figure 5.11 table needs an m_adjust the thesis never defines, and its
//     Table G.1 rows for cases 5a/5b split fore and aft pairs equally;
//   - each share is rounded to 0.1 kg before the floor mapping (case 5b's
//     12.0 kg in Table G.2 is floor(round(11.98, 0.1)), not floor(11.98)).
#include <Eigen/Core>
#include <vector>

#include "ballast/ballast_problem.h"

namespace auv {

struct ThesisAdjustment {
  int alternative = 0;          // §5.4.1 list: 1 coincide, 2 x only, 3 y only, 4 both
  double required_kg = 0;       // m_dif (eq. 5.2); <= 0 means the thesis adds nothing
  Eigen::Vector2d cg_shift_m = Eigen::Vector2d::Zero();  // eq. 5.4: CB - CG in x, y
  std::vector<double> continuous_kg;  // per point, problem order (Table G.1)
  std::vector<double> mapped_kg;      // after rounding to 0.1 kg and flooring onto pieces (Table G.2)
};

// Needs exactly four points, two fore and two aft, each pair one starboard
// and one port (the HUGIN layout); throws InputError otherwise.
ThesisAdjustment thesisAdjustment(const BallastProblem& problem);

// Points closer than this (m) count as coinciding in the thesis's case split.
inline constexpr double kThesisCoincideM = 1e-4;

}  // namespace auv
