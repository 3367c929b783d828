#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) in ./build-fuzz and
# runs each for a bounded time on its seed corpus. Usage:
#   scripts/fuzz.sh [seconds per target, default 30]
# Exits non-zero on a crash, sanitizer report or broken invariant; the
# reproducer is left in build-fuzz/artifacts/.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER_TARGET="${1:-30}"
CXX_BIN="$(command -v clang++ || command -v clang++-14 || true)"
if [ -z "$CXX_BIN" ]; then
  echo "fuzz.sh: clang++ not found; skipping fuzzing" >&2
  exit 0
fi
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER="$CXX_BIN" -DAUV_BUILD_GUI=OFF -DAUV_BUILD_BENCH=OFF \
  -DAUV_BUILD_FUZZERS=ON \
  -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined" \
  >/dev/null
TARGETS=(fuzz_interchange_csv fuzz_delimited_text fuzz_slocum_ascii fuzz_slocum_binary fuzz_glider_netcdf fuzz_seaexplorer_raw)
CORPORA=(tests/data/missionlog/corpus tests/data/missionlog/corpus-delimited tests/data/missionlog/corpus-slocum
         tests/data/missionlog/corpus-slocum-binary tests/data/missionlog/corpus-netcdf tests/data/missionlog/corpus-seaexplorer)
cmake --build build-fuzz --target "${TARGETS[@]}" -j"$(nproc)"
mkdir -p build-fuzz/artifacts
for i in "${!TARGETS[@]}"; do
  t="${TARGETS[$i]}"
  exe="$(find build-fuzz -type f -name "$t" -perm -u+x | head -n1)"
  work="build-fuzz/corpus-$t"
  mkdir -p "$work"
  echo "fuzz.sh: running $t for ${SECONDS_PER_TARGET}s"
  # New inputs go to a scratch corpus so the committed seeds stay small.
  "$exe" -max_total_time="$SECONDS_PER_TARGET" -timeout=10 -rss_limit_mb=2048 \
    -max_len=65536 -print_final_stats=1 -artifact_prefix=build-fuzz/artifacts/ \
    "$work" "${CORPORA[$i]}" > "build-fuzz/$t.log" 2>&1 || {
      echo "fuzz.sh: $t FAILED; last lines of build-fuzz/$t.log:"; tail -n 60 "build-fuzz/$t.log"; exit 1; }
  # The full libFuzzer log stays in build-fuzz/; print the run's totals.
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "build-fuzz/$t.log" | sed "s/^/  $t /"
done
