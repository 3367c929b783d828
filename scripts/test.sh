#!/usr/bin/env bash
# The whole test suite: installs dependencies, builds, runs every CTest test,
# fuzzes each log reader for a bounded time, then builds and checks the packages.
# This is what CI runs. FUZZ_SECONDS (default 20) sets the time per fuzz target.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup-deps.sh
./scripts/build.sh
export QT_QPA_PLATFORM=offscreen
export XDG_RUNTIME_DIR="$PWD/build/xdg-runtime"; mkdir -p -m 0700 "$XDG_RUNTIME_DIR"
ctest --test-dir build --output-on-failure --parallel "$(nproc)" 2>&1 | tee build/ctest.log
[ "${PIPESTATUS[0]}" -eq 0 ] || exit 1
./scripts/fuzz.sh "${FUZZ_SECONDS:-20}"
(cd build && cpack -B packages >/dev/null && ls packages/*.deb packages/*.tar.gz)
# The .deb as a Debian desktop program: copyright, man pages, metainfo, lintian.
./packaging/check-package.sh build
# Smoke-test the packaged CLI: it must find its bundled profiles when installed.
pkgtest="$(mktemp -d)"; tar -xzf build/packages/auvballast-*.tar.gz -C "$pkgtest"
"$pkgtest"/auvballast-*/bin/auvballast vehicles | grep -q hugin1000 && echo "package smoke test: ok"
rm -rf "$pkgtest"
# Repeat the test count last, so it is the closing line of the run.
grep -E "tests passed|tests failed" build/ctest.log | tail -n1
