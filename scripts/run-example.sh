#!/usr/bin/env bash
# Sets up, builds and runs the main job on bundled example data:
#  1. HUGIN 1000 first mission from a crane weighing (resources/examples/hugin1000_first_mission.json),
#  2. Slocum G2 first mission from the report's tank session (resources/examples/slocum_tank_weighing.json).
# JSON reports are written to ./example-output/.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup-deps.sh
./scripts/build.sh
exe=./build/app/cli/auvballast
out=example-output; mkdir -p "$out"
echo "== Vehicles"; $exe vehicles
echo; echo "== HUGIN 1000, first mission (crane weighing)"
$exe first-mission --weighing resources/examples/hugin1000_first_mission.json --json "$out/hugin1000_first_mission.json"
echo; echo "== HUGIN 1000, same weighing with the optional 0.5 kg piece"
$exe first-mission --weighing resources/examples/hugin1000_first_mission.json --optional-pieces
echo; echo "== Slocum G2, first mission (tank weighing, Baird 2007 App. B)"
$exe first-mission --weighing resources/examples/slocum_tank_weighing.json --json "$out/slocum_g2_first_mission.json"
echo; echo "JSON reports in $out/"
