#!/usr/bin/env bash
# One command for every figure of docs/results.md: the thesis's geodesic claims (a)-(d), exact MMP
# against CGAL, measurement, grading, drape and fabric figures, the peers' rows; one table and one
# plot per claim with its verdict, and the provenance of the run.
#   benchmarks/reproduce.sh [--quick|--full|--smoke] [--out DIR] [--tool PATH] [--data DIR]
#                           [--peers DIR] [--only PARTS]
# --quick (default): reduced sizes, at most 30 min on 2 cores; --full: the complete figures
# (hours); --smoke: tiny sizes, for CI. Writes DIR/results.md and DIR/results/ (default DIR: docs/)
# only once every part has run; exit 1 when a part failed (reported in results.md), 2 on a bad
# option (one line on stderr, nothing written). `--help` lists the options.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [ ! -x /usr/bin/python3 ]; then
  echo "reproduce.sh: error: /usr/bin/python3 not found (apt-get install python3 python3-matplotlib)" >&2
  exit 2
fi
exec /usr/bin/python3 "$root/benchmarks/scripts/reproduce.py" "$@"
