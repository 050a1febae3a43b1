#!/usr/bin/env bash
# Grading validation (issue 8): grade each FreeSewing design from cisFemaleAdult36 to the
# cisFemaleAdult42 set (and back, 42 → 36) and compare with FreeSewing's own draft of that size.
# Writes one JSON report per run under docs/bench_grading/ and the table docs/bench_grading/table.md.
#   usage: benchmarks/run_grading.sh [path/to/tapeline] [threads]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tapeline=${1:-$root/build-grade/apps/tapeline}
threads=${2:-2}
data=$root/../shared/data/patterns/freesewing
out=$root/docs/bench_grading
mkdir -p "$out"
if [ ! -d "$data" ]; then
  echo "run_grading.sh: $data not found; skipped" >&2
  exit 0
fi
for design in aaron brian simon teagan titan; do
  for pair in "36 42" "42 36"; do
    set -- $pair
    from=cisFemaleAdult$1 to=cisFemaleAdult$2
    tag=${design}_${1}to${2}
    start=$(date +%s.%N)
    if "$tapeline" grade "$data/${design}_$from.json" --from "$data/measurement_sets.json" \
         --from-set "$from" --to "$data/measurement_sets.json" --to-set "$to" \
         --out "$out/$tag.json" --report "$out/${tag}_report.json" \
         --compare "$data/${design}_$to.json" --threads "$threads" > "$out/$tag.log" 2>&1; then
      end=$(date +%s.%N)
      echo "$tag $(echo "$end - $start" | bc)" >> "$out/wall.txt.tmp"
    else
      echo "$tag failed: $(grep -m1 'tapeline:' "$out/$tag.log" || true)" >&2
    fi
    rm -f "$out/$tag.json"
  done
done
mv "$out/wall.txt.tmp" "$out/wall.txt"
/usr/bin/python3 - "$out" <<'PY'
import json, sys, glob, os
out = sys.argv[1]
wall = dict(l.split() for l in open(os.path.join(out, "wall.txt")))
rows = []
for f in sorted(glob.glob(os.path.join(out, "*_report.json"))):
    r = json.load(open(f))
    tag = os.path.basename(f)[:-len("_report.json")]
    c = r.get("comparison", [])
    n = max(1, len(c))
    mean = lambda k: sum(p[k] for p in c) / n
    mx = lambda k: max([p[k] for p in c] or [0])
    fit = r["fit"]
    errs = ", ".join("%s %.2f" % (x["measurement"], x["error_mm"]) for x in fit)
    seams = max([s["mismatch_mm"] for s in r["seams"]] or [float("nan")])
    rows.append("| %s | %d | %.2f | %s | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f | %.2f | %s |" % (
        tag, len(fit), max([abs(x["error_mm"]) for x in fit] or [0]),
        "n/a (no seams)" if not r["seams"] else "%.2f" % seams,
        mean("graded_mean_mm"), mx("graded_max_mm"),
        mean("unchanged_mean_mm"), mx("unchanged_max_mm"),
        mean("uniform_oracle_mean_mm"), mx("uniform_oracle_max_mm"),
        r["timings_s"]["total"], errs))
with open(os.path.join(out, "table.md"), "w") as t:
    t.write("# Grading FreeSewing drafts to the other size, against FreeSewing's own draft\n\n")
    t.write("Made by `benchmarks/run_grading.sh` (2 threads). Outline deviation: per piece, 400 "
            "arc-length samples, centred, best rotation, mean symmetric nearest-point distance; "
            "the columns give the mean over pieces / the max over pieces of the max distance. "
            "Oracle: each base piece scaled uniformly by the reference perimeter ratio. "
            "Seams: derived per design from FreeSewing's point names (grading/README.md); "
            "mismatch = |a − ratio·b|, max over the seams. The target-size draft is read only "
            "here, for validation: grading sees the base draft and the two measurement sets.\n\n")
    t.write("| run | bindings | max binding error mm | seam mismatch mm | graded mean / max mm "
            "| unchanged mean / max mm | uniform oracle mean / max mm | grading s | binding "
            "errors mm |\n|---|---|---|---|---|---|---|---|---|\n")
    t.write("\n".join(rows) + "\n")
print(open(os.path.join(out, "table.md")).read())
PY
