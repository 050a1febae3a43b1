#!/usr/bin/env bash
# Virtual fabric tests (issue 20) for every library fabric: the Peirce cantilever at 20, 10 and
# 5 mm, the tensile strip and the bias extension at 5 mm, the Cusick drape test at 20 mm and from
# three perturbed starts at 10 mm (at 5 mm, one to three minutes a run, for jersey, shirting and
# denim only). Writes one report per run to docs/fabric/runs/ (a run whose report is there is
# not run again: delete the directory for a fresh run), pictures to docs/fabric/, and prints the
# Markdown tables of docs/fabric.md (target, simulated, error %).
#   usage: benchmarks/run_fabric.sh [path/to/tapeline] [jobs]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tapeline=${1:-$root/build/apps/tapeline}
jobs=${2:-2}
out=$root/docs/fabric
runs=$out/runs
mkdir -p "$runs"
fabrics=$("$tapeline" fabric list | awk 'NR > 1 { print $1 }')
{
  for f in $fabrics; do
    for r in 20 10 5; do
      echo "$f cantilever $r --report $runs/$f.cantilever.$r.json"
    done
    echo "$f tensile 5 --report $runs/$f.tensile.5.json"
    echo "$f bias 5 --report $runs/$f.bias.5.json"
    echo "$f cusick 20 --report $runs/$f.cusick.20.json"
    echo "$f cusick 10 --repeats 3 --perturbation 0.5 --report $runs/$f.cusick.10.json"
  done
  for f in cotton_jersey cotton_shirting denim; do
    echo "$f cusick 5 --report $runs/$f.cusick.5.json --picture $out/$f.cusick.png"
  done
  for f in cotton_jersey cotton_shirting denim 11oz-black-denim; do
    echo "$f cantilever 5 --picture $out/$f.cantilever.png --report $runs/$f.cantilever_picture.5.json"
  done
} | while read -r f t r rest; do
  report=$(echo "$rest" | sed -n 's/.*--report \([^ ]*\).*/\1/p')
  [ -n "$report" ] && [ -f "$report" ] && continue
  echo "$f $t $r $rest"
done | xargs -P "$jobs" -L 1 sh -c 'b=$0 f=$1 t=$2 r=$3; shift 3
  "$b" fabric test "$f" --test "$t" --resolution "$r" --threads 1 "$@" >/dev/null' "$tapeline"
/usr/bin/python3 "$root/benchmarks/scripts/fabric_table.py" "$runs"
