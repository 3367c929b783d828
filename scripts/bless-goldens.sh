#!/usr/bin/env bash
# Re-bless the golden screenshots of the operator wizard (tests/ui/golden/).
#
# Only after you have LOOKED at the new screenshots and they are right: a
# golden is a claim that this is what the page must look like. The script
# builds ui_test, runs it offscreen with AUV_BLESS_GOLDENS=1 (each test then
# writes its screenshot as the golden, including the deliberately wrong one,
# which is re-rendered from a deliberately wrong session), runs the suite
# again normally to prove the new goldens pass, and lists what changed.
#
#   scripts/bless-goldens.sh [build-dir]        (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
cmake -S . -B "$build" -G Ninja >/dev/null
cmake --build "$build" --target ui_test
export QT_QPA_PLATFORM=offscreen
AUV_BLESS_GOLDENS=1 "$build/tests/ui/ui_test" --gtest_brief=1
"$build/tests/ui/ui_test" --gtest_brief=1
git status --short tests/ui/golden || true
echo "Goldens re-blessed. Check the changed PNGs (git diff --stat tests/ui/golden) before committing."
