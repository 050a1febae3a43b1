#!/usr/bin/env bash
# The time/error front of the distance methods (docs/benchmarks.md, "Time against error"): every
# distance method side by side in one run, single thread, two sources, medians of three, errors
# against exact-mmp, on the meshes of the performance targets: the 41k-vertex icosphere and
# jittered triaxial ellipsoid, three scanned shared meshes (armadillo, bunny, fertility), and the
# 164k-vertex icosphere (one source, one repetition). bench_report.py writes the tables and
# time_vs_error.png (one panel per mesh) beside the JSON lines; repair_share.py writes repair.md,
# the curvature-flow field's repair share and flow work on every shared mesh; scaling/ the time
# exponents and memory of fmm, dijkstra and heat from 10k to 655k vertices.
#   benchmarks/run_geodesic_front.sh [build/apps/tapeline] [out-dir]
# geometry-central's methods (gc-mmp, gc-heat, gc-fmm) join ours on the front in the peers part
# of benchmarks/reproduce.sh (--peers DIR).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build/apps/tapeline}
out=${2:-$root/docs/bench_front}
shared=$root/../shared/data/meshes
mkdir -p "$out"
jsonl="$out/front.jsonl"
# gcf-window:8/faces/steps:200: the curvature-flow field with the window flows' former step limit
# (CurvatureFlowDistanceOptions::window_max_iterations), beside today's 20.
methods=exact-mmp,heat,heat-idt,dijkstra,fmm,fmm-no-unfold,gcf-window:8,gcf-window:8/faces
methods+=,gcf-window:8/faces/steps:200
common=(--timeout 900 --memory-limit 16 --seed 1 --reference exact-mmp --threads 1 --methods "$methods")

meshes=(--surface icosphere:6 --surface ellipsoid:1,0.6,0.3:6:0.25)
for m in armadillo.obj bunny_decimated.off fertility.off; do
  if [ -f "$shared/$m" ]; then
    meshes+=(--mesh "$shared/$m")
  else
    echo "run_geodesic_front: $shared/$m not found; left out" >&2
  fi
done
"$bin" bench geodesic "${common[@]}" --sources 2 --repeat 3 "${meshes[@]}" --out "$jsonl"
"$bin" bench geodesic "${common[@]}" --sources 1 --repeat 1 --append --surface icosphere:7 \
  --out "$jsonl"
/usr/bin/python3 "$root/benchmarks/scripts/bench_report.py" "$jsonl" --out-dir "$out" \
  --title "Distance methods: time against error"
# Where the curvature-flow field's time goes on every shared mesh up to 43k vertices (bob_loop3,
# 342k, left out): gcf-window:8/faces beside exact-mmp, one source, one repetition.
repair="$out/repair.jsonl"
all=()
for m in spot.obj bob_tri.obj blub_triangulated.obj kitten.off fandisk.obj decimated-knight.off \
  3holes.off bunny_decimated.off fertility.off elephant.obj rocker-arm.obj armadillo.obj; do
  [ -f "$shared/$m" ] && all+=(--mesh "$shared/$m")
done
"$bin" bench geodesic --timeout 900 --memory-limit 16 --seed 1 --reference exact-mmp --threads 1 \
  --methods exact-mmp,gcf-window:8/faces --sources 1 --repeat 1 "${all[@]}" --out "$repair"
/usr/bin/python3 "$root/benchmarks/scripts/repair_share.py" "$repair" "$out/repair.md"
# Scaling of the fast methods, 10k -> 655k vertices (icospheres 5-8), errors against the great
# circle: time exponents and memory per vertex.
mkdir -p "$out/scaling"
"$bin" bench geodesic --timeout 900 --memory-limit 16 --seed 1 --reference none --threads 1 \
  --methods fmm,dijkstra,heat --sources 1 --repeat 3 --surface icosphere:5 --surface icosphere:6 \
  --surface icosphere:7 --surface icosphere:8 --out "$out/scaling/scaling.jsonl"
/usr/bin/python3 "$root/benchmarks/scripts/bench_report.py" "$out/scaling/scaling.jsonl" \
  --out-dir "$out/scaling" --title "Fast marching, Dijkstra and heat: 10k to 655k vertices"
