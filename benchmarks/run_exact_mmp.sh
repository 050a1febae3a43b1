#!/usr/bin/env bash
# Our exact MMP against CGAL's exact Surface_mesh_shortest_path, side by side (issue 3): time
# ratio and memory at ~10k, ~41k and ~164k vertices on the icosphere and the jittered triaxial
# ellipsoid, and exact-mmp alone at ~655k vertices for the scaling exponent.
#   benchmarks/run_exact_mmp.sh [build/apps/tapeline] [out-dir]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build/apps/tapeline}
out=${2:-$root/docs/bench_mmp}
mkdir -p "$out"
jsonl="$out/exact_mmp.jsonl"
common=(--timeout 1800 --seed 1 --memory-limit 20)

# exact-cgal is the reference here so that every exact-mmp line carries its disagreement with it.
"$bin" bench geodesic "${common[@]}" --methods exact-mmp,exact-cgal --reference exact-cgal --sources 3 --repeat 3 \
  --surface icosphere:5 --surface icosphere:6 \
  --surface ellipsoid:1,0.6,0.3:5:0.25 --surface ellipsoid:1,0.6,0.3:6:0.25 --out "$jsonl"
"$bin" bench geodesic "${common[@]}" --methods exact-mmp,exact-cgal --reference exact-cgal --sources 1 --repeat 1 \
  --append --surface icosphere:7 --surface ellipsoid:1,0.6,0.3:7:0.25 --out "$jsonl"
"$bin" bench geodesic "${common[@]}" --methods exact-mmp --reference none --sources 1 --repeat 1 \
  --append --surface icosphere:8 --surface ellipsoid:1,0.6,0.3:8:0.25 --out "$jsonl"
/usr/bin/python3 "$root/benchmarks/scripts/bench_report.py" "$jsonl" --out-dir "$out" \
  --title "Exact geodesics: exact-mmp against exact-cgal"
