#!/usr/bin/env bash
# Drapes (issue: dress the character): `tapeline dress` for every GarmentCode and FreeSewing
# pattern of ../shared/data/patterns on the bundled MakeHuman bodies (or another body set), with
# the quality gates per drape, the success rate, the median time and every failure with its reason.
# Writes docs/bench_drape/<bodies>.md and .jsonl.
# `scaling` instead of a body set: one graded T-shirt on the bundled body at 20, 10 and 5 mm with
# 1 and 2 threads (time per step, thread scaling, determinism, convergence of the hem and the
# silhouette), written to docs/bench_drape/scaling.md.
#   usage: benchmarks/run_drape.sh [path/to/tapeline] [bundled|dev|holdout|all|scaling]
#                                  [resolution mm] [substeps]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tapeline=${1:-$root/build/apps/tapeline}
bodies=${2:-bundled}
resolution=${3:-10}
substeps=${4:-40}
data=$root/../shared/data
if [ ! -d "$data/bodies" ]; then
  echo "run_drape.sh: $data/bodies not found; skipped" >&2
  exit 0
fi
mkdir -p "$root/docs/bench_drape"
if [ "$bodies" = scaling ]; then
  exec /usr/bin/python3 "$root/benchmarks/scripts/drape_scaling.py" "$tapeline" "$data" \
    "$root/docs/bench_drape/scaling.md"
fi
/usr/bin/python3 "$root/benchmarks/scripts/drape_population.py" "$tapeline" "$data" \
  "$root/docs/bench_drape/$bodies.md" --bodies "$bodies" --resolution "$resolution" \
  --substeps "$substeps" --json "$root/docs/bench_drape/$bodies.jsonl"
