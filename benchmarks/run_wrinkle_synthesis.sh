#!/usr/bin/env bash
# Wrinkle synthesis from data (issue 21, W2) on the demo tank top, one core per step:
#  1. coarse drapes (20 mm) of the tank top graded to three bodies: the bundled average female
#     body and population bodies 011 and 003 (../shared/data/bodies/population, CC0);
#  2. fine drapes refined from them (`tapeline wrinkles refine`: subdivided twice to 3.4 mm edges,
#     the static solve from there), and the average body's coarse drape refined again in a fabric
#     27 times as stiff in bending (bending length 3 times the cotton jersey's);
#  3. a database from the average body and body 011 (`tapeline wrinkles train`, with the body
#     distance), applied to body 003, held out (`tapeline wrinkles apply --against` its fine drape);
#  4. the fabric test: the dominant wavelengths of the two fabrics' fine drapes over the same
#     coarse drape (databases with 200 and 400 mm windows), against the law's ratio 27^(1/4).
# Writes docs/wrinkles/synthesis_pop003.{json,png} and docs/wrinkles/synthesis_fabrics.json and
# prints the tables of docs/wrinkles.md. About 25 minutes (the four refinements take 3-5 each).
#   usage: benchmarks/run_wrinkle_synthesis.sh [path/to/tapeline] [work directory]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tapeline=${1:-$root/build/apps/tapeline}
work=${2:-$(mktemp -d)}
out=$root/docs/wrinkles
pop=$root/../shared/data/bodies/population
mkdir -p "$out" "$work"
cd "$work"
pattern=$root/data/patterns/aaron_cisFemaleAdult36.json
set_from=$root/data/patterns/aaron_cisFemaleAdult36_measurements.json
declare -A body=([avg]=$root/data/bodies/mh_female_average.obj [pop011]=$pop/mh_pop_011.ply
                 [pop003]=$pop/mh_pop_003.ply)
for b in avg pop011 pop003; do
  echo "coarse drape on $b" >&2
  "$tapeline" dress "${body[$b]}" --units dm "$pattern" --to-body --from "$set_from" --seed 7 \
    --without aaron.armBinding --without aaron.neckBinding --resolution 20 --substeps 40 \
    --threads 1 --out "aaron_$b.obj" >/dev/null 2>&1
  echo "refined drape on $b" >&2
  "$tapeline" wrinkles refine "aaron_$b.obj" --body "${body[$b]}" --units dm --threads 1 \
    --out "aaron_${b}_fine.obj" --report "refine_$b.json" >/dev/null
done
"$tapeline" fabric show cotton_jersey > jersey.json
/usr/bin/python3 - <<'PY'
import json
f = json.load(open("jersey.json"))
f["name"] = "jersey_stiff27"
for k in ("bending_un_m", "bending_weft_un_m", "bending_bias_un_m"):
    if f.get(k, -1) > 0:
        f[k] *= 27
json.dump(f, open("jersey_stiff.json", "w"), indent=1)
PY
echo "refined drape on avg, stiff fabric" >&2
"$tapeline" wrinkles refine aaron_avg.obj --body "${body[avg]}" --units dm --threads 1 \
  --fabric jersey_stiff.json --out aaron_avg_stiff.obj --report refine_avg_stiff.json >/dev/null
"$tapeline" wrinkles train aaron_avg.obj aaron_avg_fine.obj aaron_pop011.obj aaron_pop011_fine.obj \
  --bodies "${body[avg]}" "${body[pop011]}" --units dm --out db.json
"$tapeline" wrinkles apply aaron_pop003.obj --db db.json --body "${body[pop003]}" --units dm \
  --against aaron_pop003_fine.obj --out aaron_pop003_wrinkled.obj \
  --report "$out/synthesis_pop003.json" --picture "$out/synthesis_pop003.png" >/dev/null
for w in 200 400; do
  "$tapeline" wrinkles train aaron_avg.obj aaron_avg_fine.obj --units dm --window-length $w \
    --out "jersey_$w.json" >/dev/null
  "$tapeline" wrinkles train aaron_avg.obj aaron_avg_stiff.obj --units dm --window-length $w \
    --fabric jersey_stiff.json --out "stiff_$w.json" >/dev/null
done
/usr/bin/python3 - "$out" <<'PY'
import json, statistics, sys
out = sys.argv[1]
r = json.load(open(f"{out}/synthesis_pop003.json"))
s, c = r["synthesis"], r["check"]
refine = {b: json.load(open(f"refine_{b}.json")) for b in ("avg", "pop011", "pop003", "avg_stiff")}
print("\nheld out (body 003): | class | windows | simulation has a wave | both | wavelength error % |"
      " amplitude error % | r |")
print("|---|---:|---:|---:|---:|---:|---:|")
fmt = lambda v, f: "–" if v is None else f % v
for k in ("tension", "shear", "compression"):
    x = c["classes"][k]
    print(f"| {k} | {x['windows']} | {x['simulation_has_wave']} | {x['both_have_wave']} | "
          f"{fmt(x['median_wavelength_error_percent'], '%.1f')} | "
          f"{fmt(x['median_amplitude_error_percent'], '%.1f')} | {fmt(x['pearson_r'], '%.3f')} |")
x = c["compressed"]
print(f"| all compressed | {x['windows']} | {x['simulation_has_wave']} | {x['both_have_wave']} | "
      f"{fmt(x['median_wavelength_error_percent'], '%.1f')} | "
      f"{fmt(x['median_amplitude_error_percent'], '%.1f')} | {fmt(x['pearson_r'], '%.3f')} |")
print(f"\nrms height over the coarse drape: simulated {c['simulated_rms_height_mm']:.2f} mm, "
      f"synthesised {c['synthesised_rms_height_mm']:.2f} mm")
syn = s["synthesis_seconds"]
print(f"time: synthesis {syn:.3f} s, self-check {s['fix_seconds']:.2f} s; refinement of the same "
      f"coarse drape {refine['pop003']['seconds']:.0f} s: {refine['pop003']['seconds'] / syn:.0f} x "
      f"(synthesis), {refine['pop003']['seconds'] / (syn + s['fix_seconds']):.0f} x (with the check)")
for b, x in refine.items():
    q = x["quality"]
    print(f"refine {b}: {x['fine_vertices']} vertices, {x['seconds']:.0f} s, static solve "
          f"{x['relax_iterations']} iterations ({'converged' if x['relax_converged'] else 'not converged'}), "
          f"p95 stretch {q['before']['stretch_p95']:.3f} -> {q['after']['stretch_p95']:.3f}, "
          f"self-intersections {q['before']['self_intersections']} -> {q['after']['self_intersections']}")
fab = {"law_ratio": 27 ** 0.25, "windows": {}}
print("\nfabric test: | window mm | fabric | samples | with a wave | median λ (pattern mm) |"
      " median amplitude mm |")
print("|---:|---|---:|---:|---:|---:|")
for w in (200, 400):
    row = {}
    for name in ("jersey", "stiff"):
        d = json.load(open(f"{name}_{w}.json"))
        waves = [x for x in d["samples"] if x[-3] > 0]
        lam = statistics.median(x[-2] for x in waves)
        amp = statistics.median(x[-3] for x in waves)
        row[name] = {"fabric": d["fabric"], "samples": len(d["samples"]), "waves": len(waves),
                     "median_wavelength_mm": lam, "median_amplitude_mm": amp}
        print(f"| {w} | {d['fabric']} | {len(d['samples'])} | {len(waves)} | {lam:.1f} | {amp:.2f} |")
    row["ratio"] = row["stiff"]["median_wavelength_mm"] / row["jersey"]["median_wavelength_mm"]
    fab["windows"][str(w)] = row
    print(f"| {w} | ratio (law {fab['law_ratio']:.2f}) | | | {row['ratio']:.2f} | |")
json.dump(fab, open(f"{out}/synthesis_fabrics.json", "w"), indent=1)
PY
