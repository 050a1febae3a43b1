#!/usr/bin/env bash
# libFuzzer over every file reader (meshes, point files, pattern JSON importers, Seamly2D XML,
# the database's pattern blob, fabric / KES-F / FAST JSON, landmark overrides), built with clang 14 (Debian clang-14 + libfuzzer-14-dev) under
# AddressSanitizer and UndefinedBehaviorSanitizer, seeded from tests/corpus/ and data/.
#   benchmarks/fuzz.sh [SECONDS_PER_TARGET (default 600)] [TARGET...]
# Prints one line per target: executions, coverage (edges) and features reached, crashes. A
# crashing input is kept in build/fuzz/findings/TARGET/; reduce it, fix the reader and add it to
# tests/corpus/ so that the corpus driver replays it on every test run.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(mesh points pattern_json measurements pattern_blob fabric_landmarks)
cxx=${CXX_FUZZ:-clang++-14}
command -v "$cxx" >/dev/null || { echo "fuzz.sh: $cxx not found (apt-get install clang-14 libfuzzer-14-dev)" >&2; exit 2; }
out=build/fuzz
mkdir -p "$out"
flags=(-std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined
       -Icore/include -Isizes/include -Ipattern/include -Imeasurement/include -Igarment/include
       -I/usr/include/eigen3)

seeds() {  # seeds of target $1 into directory $2 (first byte: the format selector)
  local t=$1 dir=$2 i=0
  mkdir -p "$dir"
  add() { { printf "\\x$(printf %02x "$1")"; cat "$2"; } >"$dir/seed$((i++))"; }
  case $t in
    mesh)
      for f in tests/corpus/mesh/* data/spot.obj; do
        case ${f##*.} in off) add 0 "$f" ;; obj) add 1 "$f" ;; ply) add 2 "$f" ;; stl) add 3 "$f" ;; esac
      done ;;
    points)
      for f in tests/corpus/points/*; do case ${f##*.} in csv) add 1 "$f" ;; *) add 0 "$f" ;; esac; done ;;
    pattern_json)
      for f in tests/corpus/pattern/* data/patterns/*.json; do add 0 "$f"; add 1 "$f"; add 2 "$f"; done ;;
    measurements)
      for f in tests/corpus/measurement/*.vit data/patterns/*.vit; do add 0 "$f"; done
      for f in tests/corpus/measurement/*.vst data/patterns/*.vst; do add 1 "$f"; done ;;
    fabric_landmarks)  # landmark overrides (0), a fabric file (1), KES-F (2), FAST (3)
      local raw=$out/raw_seeds
      mkdir -p "$raw"
      printf '%s' '{"frame": "input", "landmarks": {"crotch": [0.1, 8.2, 0.3], "neck_back": [0, 13.9, -0.8]}}' >"$raw/landmarks.json"
      printf '%s' '{"W": 16.8, "LT_warp": 0.65, "LT_weft": 0.7, "WT_warp": 6.5, "WT_weft": 10.5, "RT_warp": 65, "RT_weft": 60, "EMT_warp": 4.0, "EMT_weft": 6.0, "B_warp": 0.09, "B_weft": 0.07, "2HB_warp": 0.04, "2HB_weft": 0.03, "G_warp": 0.8, "G_weft": 0.7, "2HG_warp": 0.9, "2HG_weft": 0.8, "2HG5_warp": 1.9, "2HG5_weft": 1.7}' >"$raw/kes.json"
      printf '%s' '{"name": "wool", "W": 168, "C_warp": 15, "C_weft": 12, "E5_warp": 0.67, "E20_warp": 1.87, "E100_warp": 4.9, "E5_weft": 0.9, "E20_weft": 2.6, "E100_weft": 6.8, "EB5": 4.7, "T2": 0.62, "T100": 0.51}' >"$raw/fast.json"
      add 0 "$raw/landmarks.json"; add 2 "$raw/kes.json"; add 3 "$raw/fast.json"
      if [ -x build/apps/tapeline ]; then  # a fabric file as the tool writes it
        build/apps/tapeline fabric convert --fast "$raw/fast.json" --out "$raw/fabric.json" >/dev/null
        add 1 "$raw/fabric.json"
      fi ;;
    pattern_blob)  # the blobs of the bundled patterns, stored by the tool when it is built
      printf 'TPZ\001\000' >"$dir/seed0"
      if [ -x build/apps/tapeline ]; then
        rm -f "$out/seed.sqlite"
        build/apps/tapeline pattern import $(ls data/patterns/*.json | grep -v _measurements) \
          --db "$out/seed.sqlite" >/dev/null
        /usr/bin/python3 -c 'import sqlite3, sys
for i, (b,) in enumerate(sqlite3.connect(sys.argv[1]).execute("SELECT data FROM patterns")):
    open("%s/blob%d" % (sys.argv[2], i), "wb").write(b)' "$out/seed.sqlite" "$dir"
      fi ;;
  esac
}

for t in "${targets[@]}"; do
  bin=$out/fuzz_$t
  libs=()
  [ "$t" = pattern_blob ] || [ "$t" = pattern_json ] && libs=(-lzstd)
  [ "$t" = fabric_landmarks ] && libs=(-ltbb)
  # Rebuilt when the target or any header it may include changed since.
  if [ ! -x "$bin" ] || [ -n "$(find benchmarks/fuzz core/include sizes/include pattern/include \
                                    measurement/include garment/include \
                                    -newer "$bin" -print -quit)" ]; then
    nice "$cxx" "${flags[@]}" "benchmarks/fuzz/fuzz_$t.cpp" -o "$bin" "${libs[@]}" -lgmp -lmpfr
  fi
  corpus=$out/corpus/$t findings=$out/findings/$t
  mkdir -p "$corpus" "$findings"
  [ -n "$(ls -A "$corpus")" ] || seeds "$t" "$corpus"
  log=$out/$t.log
  set +e
  nice "$bin" "$corpus" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 \
    -max_len=65536 -artifact_prefix="$findings/" -print_final_stats=1 >"$log" 2>&1
  rc=$?
  set -e
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo 0)
  ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo 0)
  crashes=$(ls "$findings" | wc -l)
  echo "fuzz_$t: ${seconds} s, $execs executions, coverage $cov edges, $ft features, $crashes findings (exit $rc)"
done
