#!/usr/bin/env bash
# Wrinkle wavelength law (issue 21): virtual buckling experiments through
# `tapeline wrinkles buckling`, one core each, one after the other.
#  - foundation: a 600 × 30 mm cotton-jersey strip on a Winkler foundation K = 5000 N/m³ at
#    2.5 mm edges, compressed by 1 %, B = 0.5 … 50 µN·m (predicted λ 20–63 mm);
#  - cylinder: a cotton-jersey tube R = 40 mm, 80 mm long, at 1.5 mm edges, compressed by 2 %,
#    B = 2 … 50 µN·m (predicted axisymmetric λ 9–20 mm).
# Writes docs/wrinkles/buckling_{foundation,cylinder}.json and the pictures next to them, and
# prints the Markdown tables of docs/wrinkles/scaling.md.
#   usage: benchmarks/run_wrinkles.sh [path/to/tapeline]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tapeline=${1:-$root/build/apps/tapeline}
out=$root/docs/wrinkles
mkdir -p "$out"
"$tapeline" wrinkles buckling --test foundation --bending 0.5,1,2,5,10,20,50 \
  --foundation 5000 --resolution 2.5 --threads 1 \
  --report "$out/buckling_foundation.json" --picture "$out/foundation_scaling.png" \
  --profile "$out/foundation_profile.png" >/dev/null
"$tapeline" wrinkles buckling --test cylinder --bending 2,5,20,50 \
  --radius 40 --height 160 --resolution 1.5 --threads 1 \
  --report "$out/buckling_cylinder.json" --picture "$out/cylinder_scaling.png" \
  --profile "$out/cylinder_profile.png" >/dev/null
/usr/bin/python3 - "$out/buckling_foundation.json" "$out/buckling_cylinder.json" <<'PY'
import json, sys
for path in sys.argv[1:]:
    r = json.load(open(path))
    tube = r["test"] == "cylinder"
    print(f"\n{r['test']} ({r['fabric']}, edge {r['resolution_mm']} mm, strain {r['strain']}):\n")
    head = "| B (µN·m) | predicted λ (mm) | measured λ (mm) | error % | peak share |"
    rule = "|---:|---:|---:|---:|---:|"
    if tube:
        head += " axisymmetric share | lobes | pattern |"
        rule += "---:|---:|:---|"
    print(head + " seconds |")
    print(rule + "---:|")
    for p in r["points"]:
        row = (f"| {p['bending_un_m']:g} | {p['predicted_wavelength_mm']:.2f} | "
               f"{p['measured_wavelength_mm']:.2f} | {p['error_percent']:+.1f} | "
               f"{p['peak_share']:.2f} |")
        if tube:
            row += (f" {p['axisymmetric_share']:.2f} | {p['circumferential_lobes']:.1f} | "
                    f"{p['pattern']} |")
        print(row + f" {p['seconds']:.0f} |")
    print(f"\nlog–log slope {r['slope']:.3f} (law 0.25), largest |error| "
          f"{r['max_abs_error_percent']:.1f} %, {r['seconds']:.0f} s")
PY
