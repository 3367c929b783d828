#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) in ./build-fuzz and
# runs each for a bounded time on its seed corpus. Usage:
#   scripts/fuzz.sh [seconds per target, default 30]
#   FUZZ_TARGETS="fuzz_json_inputs" FUZZ_MAX_LEN=1048576 scripts/fuzz.sh 60
# Exits non-zero on a crash, sanitizer report or broken invariant; the
# reproducer is left in build-fuzz/artifacts/.
#
# Large inputs are reached on purpose: besides the committed seeds each target
# gets generated seeds with long lines (300 kB), large headers (5,000 columns)
# and many rows (build-fuzz/seeds-large-*), -max_len is 1 MB, and a dictionary
# of the format's tokens (tests/fuzz/dict/) guides the mutations. The summary
# line per target gives executions, peak RSS and the largest input run.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER_TARGET="${1:-30}"
MAX_LEN="${FUZZ_MAX_LEN:-1048576}"
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
TARGETS=(fuzz_interchange_csv fuzz_delimited_text fuzz_slocum_ascii fuzz_glider_netcdf fuzz_json_inputs fuzz_slocum_binary fuzz_seaexplorer_raw)
CORPORA=(tests/data/missionlog/corpus tests/data/missionlog/corpus-delimited tests/data/missionlog/corpus-slocum
         tests/data/missionlog/corpus-netcdf tests/fuzz/corpus-json tests/data/missionlog/corpus-slocum-binary
         tests/data/missionlog/corpus-seaexplorer)
DICTS=(tests/fuzz/dict/interchange.dict tests/fuzz/dict/delimited.dict tests/fuzz/dict/delimited.dict
       "" tests/fuzz/dict/json.dict "" "")
# FUZZ_TARGETS="fuzz_json_inputs fuzz_interchange_csv" runs only those.
SELECTED=("${TARGETS[@]}")
[ -n "${FUZZ_TARGETS:-}" ] && read -r -a SELECTED <<< "$FUZZ_TARGETS"
cmake --build build-fuzz --target "${SELECTED[@]}" -j"$(nproc)"
mkdir -p build-fuzz/artifacts

# Generated large seeds (not committed: they are big and cheap to make).
large_seeds() {
  local t="$1" dir="build-fuzz/seeds-large-$1"
  rm -rf "$dir"
  mkdir -p "$dir"
  python3 - "$t" "$dir" <<'PY'
import json, sys
t, d = sys.argv[1], sys.argv[2]
def w(name, text):
    open(d + "/" + name, "wb").write(text if isinstance(text, bytes) else text.encode())
if t in ("fuzz_interchange_csv", "fuzz_delimited_text"):
    sep = "," 
    unit = (lambda n, u: "%s [%s]" % (n, u)) if t == "fuzz_interchange_csv" else (lambda n, u: "%s (%s)" % (n, u))
    hdr = sep.join([unit("time", "s")] + [unit("c%d" % i, "m") for i in range(5000)])
    w("wide_header.csv", hdr + "\n" + "\n".join(sep.join(str(r + k) for k in range(5001)) for r in range(3)) + "\n")
    w("long_line.csv", unit("time", "s") + sep + unit("depth", "m") + "\n0" + sep + "1" * 300000 + "\n1" + sep + "2\n")
    w("many_rows.csv", "# start: 2026-05-14T08:12:00Z\n" + unit("time", "s") + sep + unit("depth", "m") + sep +
      unit("pitch", "deg") + "\n" + "".join("%d,%.2f,%.2f\n" % (i, i * 0.01, (i % 40) - 20) for i in range(20000)))
elif t == "fuzz_slocum_ascii":
    names = ["m_present_time"] + ["s%d" % i for i in range(3000)]
    head = ("dbd_label: DBD_ASC(dinkum_binary_data_ascii)file\nencoding_ver: 2\nnum_ascii_tags: 14\n"
            "all_sensors: 0\nfilename: x\nthe8x3_filename: x\nfilename_extension: dbd\nfilename_label: x\n"
            "mission_name: x\nfileopen_time: x\nsensors_per_cycle: %d\nnum_label_lines: 3\nnum_segments: 1\n"
            "segment_filename_0: x\n" % len(names))
    w("wide.asc", head + " ".join(names) + "\n" + " ".join(["rad"] * len(names)) + "\n" +
      " ".join(["8"] * len(names)) + "\n" + "\n".join(" ".join(str(r + 1e9) for _ in names) for r in range(3)) + "\n")
elif t == "fuzz_json_inputs":
    doc = {"method": "crane", "vehicle": "hugin1000", "comment": "x" * 300000,
           "scales_kg": {"fore_starboard": 1, "fore_port": 1, "aft_starboard": 1, "aft_port": 1}}
    w("big_comment.json", b"\x00" + json.dumps(doc).encode())
    w("many_keys.json", b"\x02" + json.dumps({"k%d" % i: i for i in range(20000)}).encode())
    w("long_array.json", b"\x03" + json.dumps({"format": "auvballast-mission-plan", "version": 1, "vehicle": "x",
      "water": {"density_kgm3": 1025}, "legs": [{"type": "depth", "depth_m": 10, "prop_demand": 100,
      "duration_s": 1}] * 5000}).encode())
PY
}

for i in "${!TARGETS[@]}"; do
  t="${TARGETS[$i]}"
  [[ " ${SELECTED[*]} " == *" $t "* ]] || continue
  exe="$(find build-fuzz -type f -name "$t" -perm -u+x | head -n1)"
  work="build-fuzz/corpus-$t"
  mkdir -p "$work"
  large_seeds "$t"
  dict=()
  [ -n "${DICTS[$i]}" ] && dict=(-dict="${DICTS[$i]}")
  echo "fuzz.sh: running $t for ${SECONDS_PER_TARGET}s"
  # New inputs go to a scratch corpus so the committed seeds stay small.
  "$exe" -max_total_time="$SECONDS_PER_TARGET" -timeout=10 -rss_limit_mb=2048 \
    -max_len="$MAX_LEN" "${dict[@]}" -print_final_stats=1 -artifact_prefix=build-fuzz/artifacts/ \
    "$work" "${CORPORA[$i]}" "build-fuzz/seeds-large-$t" > "build-fuzz/$t.log" 2>&1 || {
      echo "fuzz.sh: $t FAILED; last lines of build-fuzz/$t.log:"; tail -n 60 "build-fuzz/$t.log"; exit 1; }
  # The full libFuzzer log stays in build-fuzz/; print the run's totals.
  execs="$(grep -oE "stat::number_of_executed_units: *[0-9]+" "build-fuzz/$t.log" | grep -oE "[0-9]+$" || echo 0)"
  rss="$(grep -oE "stat::peak_rss_mb: *[0-9]+" "build-fuzz/$t.log" | grep -oE "[0-9]+$" || echo 0)"
  largest="$(find "$work" "${CORPORA[$i]}" "build-fuzz/seeds-large-$t" -type f -printf '%s\n' | sort -n | tail -n1)"
  echo "  $t executions $execs peak_rss_mb $rss largest_input_bytes $largest max_len $MAX_LEN"
done
