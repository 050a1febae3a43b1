#!/usr/bin/env bash
# Body measurement speed (issue 6): `tapeline measure` on MakeHuman bodies (13.4k vertices) and on
# their midpoint subdivision (53.5k vertices, the same surface: benchmarks/scripts/subdivide_obj.py),
# each run `repeat` times; the table gives the median of every stage of the CLI's
# timings_seconds (load, frame, landmarks, girths, lengths along the skin, total) and checks that
# the girths of the subdivided body equal the original's. Writes docs/bench_measure/table.md.
#   usage: benchmarks/run_measure.sh [path/to/tapeline] [repeat]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tapeline=${1:-$root/build/apps/tapeline}
repeat=${2:-5}
data=$root/../shared/data/bodies
out=$root/docs/bench_measure
if [ ! -d "$data" ]; then
  echo "run_measure.sh: $data not found; skipped" >&2
  exit 0
fi
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for body in mh_female_average mh_male_average; do
  cp "$data/$body.obj" "$work/$body.obj"
  /usr/bin/python3 "$root/benchmarks/scripts/subdivide_obj.py" "$data/$body.obj" \
    "$work/${body}_x4.obj" > /dev/null
  for mesh in "$body" "${body}_x4"; do
    for i in $(seq "$repeat"); do
      /usr/bin/time -f "%U %S" -o "$work/$mesh.$i.cpu" \
        "$tapeline" measure "$work/$mesh.obj" --units dm --out "$work/$mesh.$i.json" > /dev/null 2>&1
    done
  done
done
/usr/bin/python3 - "$work" "$out" "$repeat" "$(git -C "$root" rev-parse --short HEAD)" \
  "$tapeline" <<'PY'
import glob, json, os, statistics, sys, datetime
work, out, repeat, rev, exe = sys.argv[1:]
stages = ["load", "frame", "landmarks", "girths", "lengths", "total"]
rows, checks = [], []
for body in ["mh_female_average", "mh_male_average"]:
    girths = {}
    for mesh in [body, body + "_x4"]:
        files = sorted(glob.glob(os.path.join(work, mesh + ".*.json")))
        runs = [json.load(open(f)) for f in files]
        med = {s: statistics.median(r["timings_seconds"][s] for r in runs) for s in stages}
        med["cpu"] = statistics.median(
            sum(map(float, open(f[:-len("json")] + "cpu").read().split()[-2:])) for f in files)
        rows.append((mesh, runs[0]["report"]["vertices"], len(runs), med))
        girths[mesh] = {m["name"]: m["value_mm"] for m in runs[0]["measurements"]
                        if m["kind"] == "girth"}
    a, b = girths[body], girths[body + "_x4"]
    worst = max(abs(b[k] - a[k]) for k in a)
    checks.append("%s: largest girth difference after subdivision %.2f mm over %d girths"
                  % (body, worst, len(a)))
lines = ["# Body measurement speed", "",
         "Median of %s runs of `tapeline measure BODY --units dm --out m.json` per mesh, seconds "
         "(wall clock, from the CLI's `timings_seconds`). `_x4`: midpoint subdivision "
         "(benchmarks/scripts/subdivide_obj.py), the same surface with 4x the triangles. Measured "
         "on a shared 2-core machine while others compiled: absolute seconds drift, the medians "
         "and the 13k/53k ratio hold better; `cpu` is the process's user + system time "
         "(/usr/bin/time) for the whole command, what it costs on an idle core." % repeat, "",
         "| mesh | vertices | runs | " + " | ".join(stages) + " | cpu |",
         "|---|---:|---:|" + "---:|" * (len(stages) + 1)]
for mesh, nv, n, med in rows:
    lines.append("| %s | %d | %d | " % (mesh, nv, n)
                 + " | ".join("%.3f" % med[s] for s in stages + ["cpu"]) + " |")
lines += ["", "Same surface, same values: " + "; ".join(checks) + ".", "",
          "Made by `benchmarks/run_measure.sh %s %s` at git %s, %s." %
          (os.path.relpath(exe), repeat, rev, datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC"))]
tmp = os.path.join(out, "table.md.tmp")
open(tmp, "w").write("\n".join(lines) + "\n")
os.replace(tmp, os.path.join(out, "table.md"))
print(os.path.join(out, "table.md"))
PY
