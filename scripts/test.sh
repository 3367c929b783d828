#!/usr/bin/env bash
# The whole test suite: installs dependencies, builds, runs every CTest test,
# then builds the packages. This is what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup-deps.sh
./scripts/build.sh
export QT_QPA_PLATFORM=offscreen
export XDG_RUNTIME_DIR="$PWD/build/xdg-runtime"; mkdir -p -m 0700 "$XDG_RUNTIME_DIR"
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
(cd build && cpack -B packages >/dev/null && ls packages/*.deb packages/*.tar.gz)
