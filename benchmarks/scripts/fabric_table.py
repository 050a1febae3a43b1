#!/usr/bin/python3
"""Markdown tables of the virtual fabric tests (benchmarks/run_fabric.sh): one report per run in
RUNS (FABRIC.TEST.RESOLUTION.json), printed as target vs simulated with the error in % and a
mark where a figure misses its tolerance (cantilever 5 %, tensile 5 %, bias 10 %)."""
import glob
import json
import os
import sys


def load(runs):
    out = {}
    for path in sorted(glob.glob(os.path.join(runs, "*.json"))):
        name = os.path.basename(path)[:-5]
        fabric, test, res = name.rsplit(".", 2)
        out[(fabric, test, res)] = json.load(open(path))
    return out


def mark(err, tol):
    return "" if abs(err) <= tol else " ✗"


def ranks(values):
    order = sorted(range(len(values)), key=lambda i: values[i])
    r = [0.0] * len(values)
    i = 0
    while i < len(order):
        j = i
        while j + 1 < len(order) and values[order[j + 1]] == values[order[i]]:
            j += 1
        for k in range(i, j + 1):
            r[order[k]] = (i + j) / 2 + 1
        i = j + 1
    return r


def spearman(x, y):
    rx, ry = ranks(x), ranks(y)
    n = len(x)
    mx, my = sum(rx) / n, sum(ry) / n
    sxy = sum((a - mx) * (b - my) for a, b in zip(rx, ry))
    sxx = sum((a - mx) ** 2 for a in rx)
    syy = sum((b - my) ** 2 for b in ry)
    return sxy / (sxx * syy) ** 0.5


def main():
    runs = sys.argv[1]
    r = load(runs)
    fabrics = sorted({k[0] for k in r})
    print("### Peirce cantilever: bending length C (mm), simulated at 20 / 10 / 5 mm\n")
    print("| fabric | dir | target | 20 mm | 10 mm | 5 mm |")
    print("|---|---|---:|---:|---:|---:|")
    misses = {"20": 0, "10": 0, "5": 0}
    for f in fabrics:
        for d in ("warp", "weft"):
            cells = []
            target = None
            for res in ("20", "10", "5"):
                j = r.get((f, "cantilever", res))
                if not j:
                    cells.append("–")
                    continue
                target = j["target_bending_length_%s_mm" % d]
                e = j["error_%s_pct" % d]
                misses[res] += abs(e) > 5
                cells.append("%.2f (%+.1f %%)%s" % (j["bending_length_%s_mm" % d], e, mark(e, 5)))
            print("| %s | %s | %s | %s |" % (f, d, "%.2f" % target if target else "–", " | ".join(cells)))
    print("\nOutside 5 %%: %d at 20 mm, %d at 10 mm, %d at 5 mm (of %d).\n"
          % (misses["20"], misses["10"], misses["5"], 2 * len(fabrics)))

    print("### Tensile strip (5 mm): strain % at 5 / 20 / 100 gf/cm\n")
    print("Simulated with the secant stiffness of each load; *single k*: with the fabric's one "
          "solver stiffness (what a drape uses).\n")
    print("| fabric | dir | target | simulated | error % | single k: error % at 20 / 100 |")
    print("|---|---|---|---|---|---|")
    for f in fabrics:
        j = r.get((f, "tensile", "5"))
        if not j:
            continue
        for d in ("warp", "weft"):
            t = [j["target_strain_%s_at_%d_gf_cm_pct" % (d, l)] for l in (5, 20, 100)]
            s = [j["strain_%s_at_%d_gf_cm_pct" % (d, l)] for l in (5, 20, 100)]
            e = [j["error_%s_at_%d_gf_cm_pct" % (d, l)] for l in (5, 20, 100)]
            le = [j["linear_error_%s_at_%d_gf_cm_pct" % (d, l)] for l in (20, 100)]
            print("| %s | %s | %s | %s | %s | %s |" % (
                f, d, " / ".join("%.3f" % v for v in t), " / ".join("%.3f" % v for v in s),
                " / ".join("%+.2f%s" % (v, mark(v, 5)) for v in e),
                " / ".join("%+.1f" % v for v in le)))
    print("\n### Bias extension (5 mm) at 5 gf/cm: shear rigidity G (N/m)\n")
    print("| fabric | target G | simulated G | error % | shear angle ° | bias strain % | FAST 123/G % |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for f in fabrics:
        j = r.get((f, "bias", "5"))
        if not j:
            continue
        print("| %s | %.2f | %.2f | %+.2f%s | %.2f | %.2f | %.2f |" % (
            f, j["target_shear_rigidity_n_m"], j["shear_rigidity_n_m"], j["error_pct"],
            mark(j["error_pct"], 10), j["shear_angle_deg"], j["bias_extension_pct"],
            j["target_bias_extension_pct"]))
    print("\n### Cusick drape test: DC % (nodes)\n")
    print("10 mm: mean of three starts perturbed by ±0.5 mm (min–max; nodes of each). Spreads in "
          "percentage points: over the three starts at 10 mm, and between resolutions. † marks a "
          "run whose static solve (or one of whose three) stopped at its iteration limit before "
          "its 0.001 mm tolerance.\n")
    print("| fabric | bending length mm | 20 mm | 10 mm | 5 mm | starts pp | 10 vs 5 mm pp "
          "| 20 vs 10 mm pp |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    cs, dc20, dc10 = [], [], []
    for f in fabrics:
        j20, j10, j5 = (r.get((f, "cusick", x)) for x in ("20", "10", "5"))
        if not (j20 and j10):
            continue
        def dagger(j):
            return "" if j.get("equilibrium", True) else " †"
        c5 = "–"
        if j5:
            c5 = "%.1f (%s)%s" % (j5["drape_coefficient_pct"], j5["nodes"][0], dagger(j5))
        cs.append(j10["bending_length_mm"])
        dc20.append(j20["drape_coefficient_pct"])
        dc10.append(j10["drape_coefficient_pct"])
        starts = j10["drape_coefficient_max_pct"] - j10["drape_coefficient_min_pct"]
        d5 = abs(j5["drape_coefficient_pct"] - j10["drape_coefficient_pct"]) if j5 else None
        d20 = abs(j20["drape_coefficient_pct"] - j10["drape_coefficient_pct"])
        print("| %s | %.1f | %.1f (%s)%s | %.1f (%.1f–%.1f; %s)%s | %s | %.1f%s | %s | %.1f%s |" % (
            f, j10["bending_length_mm"], j20["drape_coefficient_pct"], j20["nodes"][0],
            dagger(j20), j10["drape_coefficient_pct"], j10["drape_coefficient_min_pct"],
            j10["drape_coefficient_max_pct"], ",".join(str(n) for n in j10["nodes"]), dagger(j10),
            c5,
            starts, mark(starts, 2), "–" if d5 is None else "%.1f%s" % (d5, mark(d5, 2)),
            d20, mark(d20, 2)))
    if len(cs) > 2:
        print("\nSpearman ρ of DC against bending length (geometric mean of warp and weft) over %d "
              "fabrics: %.3f at 10 mm (mean of three starts), %.3f at 20 mm."
              % (len(cs), spearman(cs, dc10), spearman(cs, dc20)))


if __name__ == "__main__":
    main()
