#!/usr/bin/env bash
# Sets up, builds and runs the main job on bundled example data:
#  1. HUGIN 1000 first mission from a crane weighing (resources/examples/hugin1000_first_mission.json),
#  2. Slocum G2 first mission from the report's tank session (resources/examples/slocum_tank_weighing.json),
#  3. post mission: a simulated HUGIN mission with a known ballast error, analysed (recommendation included),
#  4. model check of a shipped glider log whose hull compressibility the model lacks,
#  5. the operator wizard on the same demo data: every page rendered offscreen into
#     ./example-output/wizard/*.png (with the work orders as PNG and PDF), and, on a
#     machine with a display, the wizard opened on the HUGIN demo.
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
echo; echo "== HUGIN 1000, post mission: simulate a mission with a known ballast error (truth in the log header), then analyse it"
$exe simulate --vehicle hugin1000 --plan resources/examples/hugin1000_ballast_error.plan.json --out "$out/hugin1000_mission.csv"
grep -E "^# truth_(net_buoyancy_kg|cg_x_mm)" "$out/hugin1000_mission.csv"
$exe analyze --vehicle hugin1000 --log "$out/hugin1000_mission.csv" --installed 7.2,7.2,25.2,25.2 --bg-mm 20 \
    --json "$out/hugin1000_analysis.json"
echo; echo "== Slocum G2, model check of a log with concealed hull compressibility"
$exe model-check --vehicle slocum_g2 --log resources/examples/slocum_g2_model-check_compressibility.csv \
    --json "$out/slocum_g2_model_check.json"
echo; echo "JSON reports in $out/"
gui=./build/app/gui/auvballast-gui
if [ -x "$gui" ]; then
  echo; echo "== The operator wizard on the demo sessions"
  # The offscreen platform says it cannot propagate size hints once per window: noise, not a problem.
  "$gui" --demo --render-pages "$out/wizard" 2> >(grep -v "propagateSizeHints" >&2)
  if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
    echo "Opening the wizard on the HUGIN demo (auvballast-gui --demo); it stays open after this script."
    nohup "$gui" --demo >/dev/null 2>&1 &
  else
    echo "No display here: look at the wizard's pages in $out/wizard/*.png (work orders also as PDF)."
  fi
fi
