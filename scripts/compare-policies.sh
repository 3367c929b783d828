#!/usr/bin/env bash
# Reproduces the pre-mission policy comparison of docs/decisions/planning-closed-loop.md:
# exact, half-way and the thesis's classic table in the closed loop (analytic
# truth, analysis errors at several noise levels), one table on stdout.
#   scripts/compare-policies.sh [--cases N] [--seed S] [--max-missions M]
# Defaults: 200 cases, seed 2026, 40 missions for the classic table.
# BUILD_DIR (default build) selects the CMake build tree.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${BUILD_DIR:-build}"
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -G Ninja -DAUV_BUILD_GUI=OFF >/dev/null
fi
cmake --build "$build" --target policy_compare >/dev/null
exec "$build/bench/policy_compare" "$@"
