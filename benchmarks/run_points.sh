#!/usr/bin/env bash
# The point-cloud benchmark of issue 5: gcf-points (the thesis' Algorithm 3 on the vertices of a
# mesh taken as a point cloud) side by side with gcf-window:8 (Algorithm 2 on the mesh itself) and
# exact-mmp (the reference: exact polyhedral distance on the mesh the points came from), with the
# smooth truth (great circle, GeographicLib) where the surface has one. One run per part:
#   1. accuracy on clean points: MLS and plane projections;
#   2. noisy points (sigma = 0.1 % and 0.5 % of the bounding-box diagonal, seeded), errors still
#      against the clean surface;
#   3. time against the number of points (icospheres level 4 to 7: 2.5k to 164k points), with
#      gcf-window:8 on the same meshes;
#   4. error against the cell size and the window (icosphere:5).
# The gcf-points lines of each configuration get a label appended to `method` (gcf-points/mls,
# gcf-points/noise0.1%, ...) so that the table keeps them apart; all lines: points_raw.jsonl.
#   benchmarks/run_points.sh [build/apps/tapeline] [out-dir]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build/apps/tapeline}
out=${2:-$root/docs/bench_points}
mkdir -p "$out"
raw="$out/points_raw.jsonl"
rm -f "$raw"
common=(--timeout 900 --memory-limit 16 --seed 1 --threads 1 --append)
surfaces=(--surface icosphere:5 --surface ellipsoid:1,1,0.5:5:0.3 --mesh "$root/data/spot.obj")

run() {  # run LABEL ARGS...: one bench run, its gcf-points lines labelled
  local label=$1; shift
  "$bin" bench geodesic "${common[@]}" "$@" --out "$out/part.jsonl"
  /usr/bin/python3 - "$label" "$out/part.jsonl" "$raw" <<'PY'
import json, sys
label, part, raw = sys.argv[1:4]
with open(raw, "a") as f:
    for line in open(part):
        rec = json.loads(line)
        if rec["method"].startswith("gcf-points") and label:
            rec["method"] = rec["method"] + "/" + label
        f.write(json.dumps(rec) + "\n")
PY
  rm -f "$out/part.jsonl"
}

# 1. Clean points, both projections, against exact-mmp and gcf-window:8 on the same meshes.
run mls --sources 2 --repeat 2 --reference exact-mmp --methods exact-mmp,gcf-window:8,gcf-points \
  "${surfaces[@]}"
run plane --sources 2 --repeat 2 --reference exact-mmp --methods exact-mmp,gcf-points \
  --projection plane "${surfaces[@]}"
# 2. Noise.
run noise0.1% --sources 2 --repeat 2 --reference exact-mmp --methods exact-mmp,gcf-points \
  --noise 0.001 "${surfaces[@]}"
run noise0.5%,d32 --sources 2 --repeat 2 --reference exact-mmp --methods exact-mmp,gcf-points \
  --noise 0.005 --neighbours 32 "${surfaces[@]}"
# 3. Scaling (no reference: exact-mmp at 164k vertices takes minutes and GBs).
run scaling --sources 1 --repeat 3 --reference none --methods gcf-window:8,gcf-points \
  --surface icosphere:4 --surface icosphere:5 --surface icosphere:6 --surface icosphere:7
# 4. Cell size and window on icosphere:5 (default cell there: ~0.064).
for cell in 0.03 0.05 0.08 0.12; do
  run "cell$cell" --sources 1 --repeat 1 --reference none \
    --methods gcf-points:4,gcf-points:8,gcf-points:16 --cell "$cell" --surface icosphere:5
done
/usr/bin/python3 "$root/benchmarks/scripts/bench_report.py" "$raw" --out-dir "$out" \
  --title "Geodesics on point clouds (gcf-points) against exact MMP and gcf-window on the mesh"
