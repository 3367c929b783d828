// Time per solve of the exact ballast solver on the thesis's first-mission
// cases (HUGIN 1000, App. F.1), with the standard kit and with the optional
// 0.5 kg piece. Prints one line per case: median ms per solve, and the result.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "../tests/core/ballast/hugin_thesis_cases.h"
#include "ballast/ballast_solver.h"

namespace {

double medianMs(const auv::BallastProblem& p, int repeats) {
  std::vector<double> ms;
  for (int i = 0; i < repeats; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    const auv::BallastSolution s = auv::solveBallast(p);
    const auto t1 = std::chrono::steady_clock::now();
    if (s.delta.empty()) std::printf("?");
    ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 21;
  std::printf("exact ballast solver, HUGIN 1000, thesis Table F.1 cases, median of %d solves\n", repeats);
  std::printf("%-8s %-22s %10s %9s %9s %9s  %s\n", "case", "kit", "ms/solve", "net kg", "pitch", "roll",
              "add kg (FS FP AS AP)");
  for (const bool optional : {false, true}) {
    for (const auto& c : auv::testing::tableF1()) {
      auv::BallastProblem p = auv::testing::thesisProblem(c);
      std::string kit = "1.2/2.4/4.8";
      if (optional) {
        p.piece_sizes_kg = {0.5, 1.2, 2.4, 4.8};
        kit = "0.5/1.2/2.4/4.8";
      }
      const double ms = medianMs(p, repeats);
      const auv::BallastSolution s = auv::solveBallast(p);
      std::printf("%-8s %-22s %10.3f %9.3f %9.3f %9.3f  %.1f %.1f %.1f %.1f\n", c.name.c_str(), kit.c_str(), ms,
                  s.net_buoyancy_kg, s.pitch_deg, s.roll_deg, s.add_kg[0], s.add_kg[1], s.add_kg[2], s.add_kg[3]);
      for (const auto& w : s.warnings) std::printf("           warning: %s\n", w.c_str());
    }
  }
  return 0;
}
