#!/usr/bin/env bash
# The foundation benchmark of docs/benchmarks.md: exact-cgal, heat, heat-idt and dijkstra side by
# side on icospheres (levels 4-8), a jittered triaxial ellipsoid (1, 0.6, 0.3) and a torus, with
# errors against the exact polyhedral distance (up to ~164k vertices, where exact-cgal still fits)
# and against the exact smooth distance where the surface has one (icospheres).
#   benchmarks/run_geodesic_baselines.sh [build/apps/tapeline] [out-dir]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build/apps/tapeline}
out=${2:-$root/docs/bench}
mkdir -p "$out"
jsonl="$out/geodesic_baselines.jsonl"
methods=exact-cgal,heat,heat-idt,dijkstra
common=(--timeout 1800 --seed 1)

# 2.5k-41k vertices: 3 sources x 3 repetitions.
"$bin" bench geodesic "${common[@]}" --methods $methods --reference exact-cgal --sources 3 --repeat 3 \
  --surface icosphere:4 --surface icosphere:5 --surface icosphere:6 \
  --surface ellipsoid:1,0.6,0.3:4:0.25 --surface ellipsoid:1,0.6,0.3:5:0.25 --surface ellipsoid:1,0.6,0.3:6:0.25 \
  --surface torus:1,0.4:80,32 --surface torus:1,0.4:160,64 --surface torus:1,0.4:320,128 \
  --out "$jsonl"
# ~164k vertices: exact-cgal is slow and memory hungry here (one source, one repetition).
"$bin" bench geodesic "${common[@]}" --methods $methods --reference exact-cgal --sources 1 --repeat 1 --append \
  --surface icosphere:7 --surface ellipsoid:1,0.6,0.3:7:0.25 --surface torus:1,0.4:640,256 \
  --out "$jsonl"
# ~655k vertices: approximate methods only, errors against analytic truth where there is one.
"$bin" bench geodesic "${common[@]}" --methods heat,heat-idt,dijkstra --reference none --sources 1 --repeat 1 --append \
  --surface icosphere:8 --surface ellipsoid:1,0.6,0.3:8:0.25 --surface torus:1,0.4:1280,512 \
  --out "$jsonl"
/usr/bin/python3 "$root/benchmarks/scripts/bench_report.py" "$jsonl" --out-dir "$out" \
  --title "Baseline geodesics, side by side"
