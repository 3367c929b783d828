#!/usr/bin/env bash
# Sets up, builds and runs the main job on bundled example data: the HUGIN 1000
# first-mission recommendation for the weighing in resources/examples.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup-deps.sh
./scripts/build.sh
./build/app/cli/auvballast vehicles
