#!/usr/bin/env bash
# The crowd batch (issue: crowds on MPI): `tapeline batch` over the 40 population bodies of
# ../shared/data × 2 designs (the GarmentCode shirt as drafted; the FreeSewing tank top graded to
# each body), run with 1 rank, 2 ranks, 4 ranks on the 2 cores (oversubscribed) and 1 rank with 2
# TBB threads per job; throughput, speed-up, the time per job, the coordinator's cost per job, and
# a projection to a cluster from the measured costs. Writes docs/bench_batch/population.md.
#   usage: benchmarks/run_batch.sh [path/to/tapeline] [resolution mm] [work folder]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tapeline=${1:-$root/build/apps/tapeline}
resolution=${2:-30}
work=${3:-/tmp/tapeline_batch_bench}
data=$root/../shared/data
if [ ! -d "$data/bodies/population" ]; then
  echo "run_batch.sh: $data/bodies/population not found; skipped" >&2
  exit 0
fi
mkdir -p "$root/docs/bench_batch"
exec /usr/bin/python3 "$root/benchmarks/scripts/batch_bench.py" "$tapeline" "$root" "$data" \
  "$work" "$root/docs/bench_batch/population.md" --resolution "$resolution"
