#!/usr/bin/env bash
# Drives the `tapeline` tool as a user does: exit codes, one-line messages, output files, and
# agreement of its outputs with independent truth (analytic distances, the exact path length).
#   run_cli_tests.sh TAPELINE_BINARY SOURCE_DIR WORK_DIR [SECTION]
# SECTION (default: all) runs one section below; tests/CMakeLists.txt makes one ctest test per
# section, so a failure names its section, and each check prints "ok" or "FAIL" with its name.
# A new section: `if in_section NAME; then ... fi` (self-contained: it makes the files it reads,
# in its own WORK_DIR) and NAME added to CLI_SECTIONS in tests/CMakeLists.txt.
set -u
bin=$1; root=$2; work=$3; section=${4:-all}
py=/usr/bin/python3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
passed=0; failed=0; sections_run=0
ok()   { passed=$((passed+1)); echo "ok   - $1"; }
fail() { failed=$((failed+1)); echo "FAIL - $1"; }
in_section() {
  if [ "$section" = all ] || [ "$section" = "$1" ]; then
    sections_run=$((sections_run+1)); echo "# section $1"; return 0
  fi
  return 1
}

# expect_fail NAME PATTERN CMD...: non-zero exit and exactly one error line, which matches PATTERN
# (warnings about the input may come before it).
expect_fail() {
  local name=$1 pattern=$2; shift 2
  "$@" >out.txt 2>err.txt; local rc=$?
  if [ $rc -ne 0 ] && [ "$(grep -c '^tapeline: error' err.txt)" -eq 1 ] &&
     grep '^tapeline: error' err.txt | grep -qE -- "$pattern"; then ok "$name"
  else fail "$name (exit $rc, stderr: $(head -c 300 err.txt))"; fi
}
expect_ok() {
  local name=$1; shift
  if "$@" >out.txt 2>err.txt; then ok "$name"; else fail "$name: $(head -c 300 err.txt)"; fi
}

spot="$root/data/spot.obj"
fs="$root/data/patterns/aaron_cisFemaleAdult36.json"; gc="$root/data/patterns/shirt_mean_specification.json"
base36='{"biceps": 286, "chest": 979, "hpsToBust": 286, "hpsToWaistBack": 410, "neck": 360,
 "shoulderToShoulder": 431, "shoulderSlope": 13, "waistToArmpit": 177, "waistToHips": 130,
 "hips": 953, "highBust": 916}'

# Inputs several sections read: the generated icosphere:3 with its great-circle truth and exact
# distances from vertex 0, and the exact distances on spot from vertex 0.
make_ico() {
  [ -f ico_exact.txt ] && return
  expect_ok "generate icosphere:3 with truth" "$bin" mesh generate icosphere:3 --out ico.off --truth-source 0 --truth-out truth.txt
  expect_ok "exact distances on the generated file" "$bin" geodesic distances ico.off --source 0 --out ico_exact.txt
}
make_spot_exact() {
  [ -f d_exact-cgal.txt ] && return
  expect_ok "distances exact-cgal on spot" "$bin" geodesic distances "$spot" --source 0 --method exact-cgal --out d_exact-cgal.txt
}

# --- help ---------------------------------------------------------------------------------------
if in_section help; then
for sub in "" "mesh generate" "mesh check" "mesh remesh" "mesh simplify" "geodesic distances" "geodesic path" "bench geodesic" \
           "measure"; do
  # shellcheck disable=SC2086
  if "$bin" $sub --help >help.txt 2>&1 && grep -q "Usage" help.txt; then ok "help: tapeline $sub"
  else fail "help: tapeline $sub"; fi
done
fi

# --- distances by every method ------------------------------------------------------------------
if in_section distances; then
for m in exact-mmp exact-cgal heat heat-idt dijkstra fmm; do
  expect_ok "distances $m on spot" "$bin" geodesic distances "$spot" --source 0 --method $m --out d_$m.txt
  if [ "$(wc -l <d_$m.txt)" -eq 2930 ] && [ "$(head -1 d_$m.txt)" = "0" ]; then ok "distances $m: 2930 lines, source at 0"
  else fail "distances $m: $(wc -l <d_$m.txt) lines, first '$(head -1 d_$m.txt)'"; fi
done
# Dijkstra walks along edges, so it is never shorter than the exact polyhedral distance.
if paste d_dijkstra.txt d_exact-cgal.txt | awk '{ if ($1 < $2 * (1 - 1e-12)) bad++ } END { exit bad > 0 }'; then
  ok "dijkstra >= exact-cgal on every vertex"; else fail "dijkstra shorter than exact somewhere"; fi
# Fast marching takes every edge update Dijkstra takes: never above it, and well below on average.
if paste d_fmm.txt d_dijkstra.txt d_exact-cgal.txt | awk '{ if ($1 > $2 * (1 + 1e-12)) bad++; f += ($1 - $3); g += ($2 - $3) } END { exit (bad > 0 || f * 2 > g) }'; then
  ok "fmm <= dijkstra on every vertex, half its excess over exact-cgal or less"; else fail "fmm above dijkstra somewhere, or not closer to exact"; fi
# Our exact method and CGAL's compute the same polyhedral distance.
if paste d_exact-mmp.txt d_exact-cgal.txt | awk '{ e = $1 - $2; if (e < 0) e = -e; if (e > 1e-9 * ($2 + 1e-300)) bad++ } END { exit bad > 0 }'; then
  ok "exact-mmp = exact-cgal on every vertex (1e-9 relative)"; else fail "exact-mmp differs from exact-cgal"; fi
expect_ok "distances to a coloured PLY" "$bin" geodesic distances "$spot" --source 0 --out d.ply
if head -c 3 d.ply | grep -q ply && grep -aq "property float distance" d.ply && grep -aq "property uchar red" d.ply; then
  ok "PLY has the distance and colours"; else fail "PLY header"; fi
expect_ok "several sources and a face point" "$bin" geodesic distances "$spot" --source 0 --source 100 \
  --source-point 5:0.2,0.3,0.5 --method dijkstra --out multi.txt
# Several sources give the pointwise minimum of the single-source fields (the same graph search).
expect_ok "dijkstra from vertex 100" "$bin" geodesic distances "$spot" --source 100 --method dijkstra --out d100.txt
expect_ok "dijkstra from the face point" "$bin" geodesic distances "$spot" --source-point 5:0.2,0.3,0.5 \
  --method dijkstra --out dface.txt
if paste multi.txt d_dijkstra.txt d100.txt dface.txt | awk '{ m = $2; if ($3 < m) m = $3; if ($4 < m) m = $4;
     e = $1 - m; if (e < 0) e = -e; if (e > 1e-12 * (m + 1)) bad++; n++ } END { exit !(n == 2930 && bad == 0) }'; then
  ok "several sources = minimum of the single-source fields"; else fail "multi-source field is not the minimum"; fi
# The distance matrix: row s is the exact field from source s; the geodesic distance is symmetric;
# the rows do not depend on how many threads computed them.
expect_ok "matrix of 4 sources, 1 thread" "$bin" geodesic matrix "$spot" --source 0 --source 100 --source 700 \
  --source 2100 --threads 1 --out m1.txt
expect_ok "matrix of 4 sources, 2 threads" "$bin" geodesic matrix "$spot" --source 0 --source 100 --source 700 \
  --source 2100 --threads 2 --out m2.txt
if cmp -s m1.txt m2.txt; then ok "matrix: 1 and 2 threads give the same file"; else fail "matrix differs with the thread count"; fi
if [ "$(wc -l <m1.txt)" -eq 4 ] && head -1 m1.txt | tr ' ' '\n' | paste - d_exact-mmp.txt |
   awk '{ e = $1 - $2; if (e < 0) e = -e; if (e > 1e-12 * ($2 + 1e-300)) bad++; n++ } END { exit !(n == 2930 && bad == 0) }'; then
  ok "matrix row 0 = geodesic distances --source 0"; else fail "matrix row 0 differs from the distance field"; fi
if $py - m1.txt <<'PYEOF'
import sys
rows = [[float(x) for x in l.split()] for l in open(sys.argv[1])]
src = [0, 100, 700, 2100]
bad = [(i, j) for i in range(4) for j in range(4)
       if abs(rows[i][src[j]] - rows[j][src[i]]) > 1e-12 * max(rows[i][src[j]], 1e-300)]
sys.exit(1 if bad or any(rows[i][src[i]] != 0 for i in range(4)) else 0)
PYEOF
then ok "matrix: d(a, b) = d(b, a), 0 on the diagonal"; else fail "matrix not symmetric"; fi
fi

# --- bad input: one line, non-zero exit, nothing written ------------------------------------------
if in_section bad_input; then
expect_fail "unknown method" "heatx" "$bin" geodesic distances "$spot" --source 0 --method heatx --out x.txt
expect_fail "vertex out of range" "99999" "$bin" geodesic distances "$spot" --source 99999 --out x.txt
expect_fail "missing mesh file" "nope.off" "$bin" geodesic distances nope.off --source 0 --out x.txt
expect_fail "unknown output format" "\.xyz" "$bin" geodesic distances "$spot" --source 0 --out x.xyz
expect_fail "matrix: not .txt" "written as \.txt" "$bin" geodesic matrix "$spot" --source 0 --out m.csv
expect_fail "matrix: vertex out of range" "99999" "$bin" geodesic matrix "$spot" --source 0 --source 99999 --out m.txt
if [ ! -e m.txt ] && [ ! -e m.csv ]; then ok "matrix: nothing written on bad input"; else fail "matrix wrote a file on bad input"; fi
expect_fail "bad face point" "source-point" "$bin" geodesic distances "$spot" --source-point 5:0.5,0.5 --out x.txt
expect_fail "face point on a missing face" "face 999999" "$bin" geodesic distances "$spot" --source-point 999999:1,0,0 --out x.txt
expect_fail "heat takes no face point" "face" "$bin" geodesic distances "$spot" --source-point 5:0.2,0.3,0.5 --method heat --out x.txt
if ls x.* >/dev/null 2>&1; then fail "a failed run left an output file: $(ls x.*)"; else ok "failed runs wrote nothing"; fi
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n0 1\n' > truncated.off
expect_fail "truncated OFF" "truncated.off" "$bin" geodesic distances truncated.off --source 0 --out x.txt
printf 'OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n' > nan.off
expect_fail "NaN coordinate" "nan.off.*(NaN|nan|finite)" "$bin" mesh check nan.off
expect_fail "bad surface spec" "icosphere:x" "$bin" mesh generate icosphere:x --out s.off
expect_fail "unknown mesh extension" "s.abc" "$bin" mesh generate icosphere:1 --out s.abc
expect_fail "no truth on a torus" "torus" "$bin" mesh generate torus:1,0.3:16,8 --out t.off --truth-source 0 --truth-out t.txt
if ls t.off s.off s.abc t.txt >/dev/null 2>&1; then fail "rejected generate wrote a file"; else ok "rejected generate wrote nothing"; fi
fi

# --- generated surfaces against their exact smooth distance ------------------------------------
if in_section generated; then
make_ico
# Polyhedral distances on an inscribed icosphere fall short of the great circle by O(h^2):
# at level 3 (h ~ 0.1) a mean relative gap of a few 1e-3; 1e-2 is the bound.
if paste ico_exact.txt truth.txt | awk 'NR > 1 && $2 > 0.3 { s += ($2 - $1) / $2; n++; if ($1 > $2 * (1 + 1e-9)) over++ }
     END { m = s / n; print "mean gap " m; exit !(m > 0 && m < 1e-2 && over == 0) }' >gap.txt; then
  ok "icosphere:3 exact vs great circle ($(cat gap.txt))"; else fail "icosphere:3 vs great circle ($(cat gap.txt))"; fi
expect_ok "mesh check" "$bin" mesh check ico.off
if grep -qi "642" out.txt; then ok "mesh check reports 642 vertices"; else fail "mesh check output: $(head -c 300 out.txt)"; fi
# The synthetic body of exactly known girths, measured by the tool: every girth of the truth file
# within its tolerance (the truth is the analytic sections' ellipse perimeters, computed apart
# from the mesh and the measuring), stature exact.
expect_ok "generate the synthetic body with its truth" "$bin" mesh generate body:40,10 --out body.obj --truth-out body_truth.json
expect_ok "measure the synthetic body" "$bin" measure body.obj --units mm --out body_m.json
if $py - <<'PY' >truth_cmp.txt
import json, sys
t = json.load(open("body_truth.json")); m = json.load(open("body_m.json"))
got = {x["name"]: x["value_mm"] for x in m["measurements"]}
bad = [g["name"] for g in t["girths"] if g["name"] not in got or abs(got[g["name"]] - g["value_mm"]) > g["tolerance_mm"]]
worst = max(abs(got.get(g["name"], 1e9) - g["value_mm"]) for g in t["girths"])
print(len(t["girths"]), "girths, worst", round(worst, 2), "mm, outside:", bad)
sys.exit(0 if len(t["girths"]) == 25 and not bad and abs(got["stature"] - t["stature"]) < 1e-6 else 1)
PY
then ok "synthetic body: $(cat truth_cmp.txt)"; else fail "synthetic body against its truth: $(cat truth_cmp.txt)"; fi
expect_fail "body spec: AROUND not whole" "AROUND" "$bin" mesh generate body:40.5,10 --out b.obj
expect_fail "body spec: one number" "body:AROUND" "$bin" mesh generate body:40 --out b.obj
expect_fail "body spec: not a number" "'x' is not a number" "$bin" mesh generate body:40,x --out b.obj
expect_fail "body truth as text" "as .json" "$bin" mesh generate body --out b.obj --truth-out b.txt
expect_fail "body with a distance source" "truth-source" "$bin" mesh generate body --out b.obj --truth-source 0 --truth-out b.json
if [ ! -e b.obj ] && [ ! -e b.json ] && [ ! -e b.txt ]; then ok "nothing written on a refused body"; else fail "a refused body left a file"; fi
fi

# --- exact path ---------------------------------------------------------------------------------
if in_section path; then
make_ico; make_spot_exact
expect_ok "exact path" "$bin" geodesic path "$spot" --from 0 --to 1500 --method exact-cgal --out path.json
want=$(sed -n 1501p d_exact-cgal.txt)
if $py - "$want" <<'PY'
import json, math, sys
p = json.load(open("path.json")); want = float(sys.argv[1])
pts = p["points"]; L = sum(math.dist(a, b) for a, b in zip(pts, pts[1:]))
ok = abs(p["length"] - want) <= 1e-9 * want and abs(L - want) <= 1e-9 * want and len(pts) >= 2
print("length", p["length"], "polyline", L, "distance", want); sys.exit(0 if ok else 1)
PY
then ok "path length = exact distance = polyline length"; else fail "path length"; fi
expect_ok "exact-mmp path" "$bin" geodesic path "$spot" --from 0 --to 1500 --method exact-mmp --out path.json
if $py - "$want" <<'PY'
import json, math, sys
p = json.load(open("path.json")); want = float(sys.argv[1])
pts = p["points"]; L = sum(math.dist(a, b) for a, b in zip(pts, pts[1:]))
sys.exit(0 if abs(p["length"] - want) <= 1e-9 * want and abs(L - want) <= 1e-9 * want else 1)
PY
then ok "exact-mmp path length = exact distance = polyline length"; else fail "exact-mmp path length"; fi
# The curvature-flow path on the generated icosphere: traced on the mesh it is no shorter than the
# exact polyhedral distance (a path on the faces) and close to it; the smooth polyline is closer to
# the great circle than the polyhedral distance is (O(h^2) gap, measured ~4x smaller).
# Curvature-flow distances (Algorithm 1) on the generated icosphere:3: close to the exact
# polyhedral distance (they approach the smooth sphere, ~0.3 % above the polyhedron at this level).
expect_ok "gcf-exact distances" "$bin" geodesic distances ico.off --source 0 --method gcf-exact --out gcf_d.txt
if paste gcf_d.txt ico_exact.txt | awk 'NR > 1 && $2 > 0.3 { e = ($1 - $2) / $2; if (e < 0) e = -e; s += e; n++ }
     END { m = s / n; print "mean rel diff " m; exit !(m < 1e-2) }' >gcf_gap.txt; then
  ok "gcf-exact within 1 % of exact ($(cat gcf_gap.txt))"; else fail "gcf-exact vs exact ($(cat gcf_gap.txt))"; fi
expect_ok "gcf-window distances" "$bin" geodesic distances ico.off --source 0 --method gcf-window --window 8 --out gcf_w.txt
expect_fail "gcf takes one vertex source" "one vertex source" "$bin" geodesic distances ico.off --source 0 --source 5 --method gcf-exact --out x.txt
# Field-anchored windows stay within 1 % of the whole-path flow; the thesis' prefix rule does not.
expect_ok "gcf-window-thesis distances" "$bin" geodesic distances ico.off --source 0 --method gcf-window-thesis --window 8 --out gcf_t.txt
if paste gcf_w.txt gcf_t.txt gcf_d.txt | awk 'NR > 1 { w = ($1 - $3) / $3; t = ($2 - $3) / $3;
     if (w < 0) w = -w; if (t < 0) t = -t; if (w > mw) mw = w; if (t > mt) mt = t }
     END { print "max rel diff window " mw ", thesis " mt; exit !(mw < 1e-2 && mt > mw) }' >gcf_win.txt; then
  ok "gcf-window close to gcf-exact, thesis rule farther ($(cat gcf_win.txt))"; else fail "gcf-window vs gcf-exact ($(cat gcf_win.txt))"; fi
expect_fail "gcf-window with window 0" "--window: Value 0 not in range 1 to 4096" "$bin" geodesic distances ico.off --source 0 --method gcf-window --window 0 --out x.txt
expect_ok "gcf path" "$bin" geodesic path ico.off --from 0 --to 300 --method gcf --out gcf.json
if $py - "$(sed -n 301p ico_exact.txt)" "$(sed -n 301p truth.txt)" <<'PY'
import json, sys
p = json.load(open("gcf.json")); exact = float(sys.argv[1]); truth = float(sys.argv[2])
L, S = p["length"], p["smooth"]["length"]
ok = exact * (1 - 1e-9) <= L <= exact * 1.01 and abs(S - truth) < abs(exact - truth) and p["report"]["status"] == "converged"
print("on mesh", L, "smooth", S, "exact", exact, "truth", truth, p["report"]["status"]); sys.exit(0 if ok else 1)
PY
then ok "gcf path: on-mesh >= exact, smooth closer to the great circle"; else fail "gcf path lengths"; fi
# The unfolded strip (--svg): a valid SVG with one polygon per face, and the lengths in the JSON.
# The exact path is straight in its unfolding (when it passes no vertex); the flow's traced path
# is no shorter than the unfolded straight segment.
expect_ok "gcf path --svg" "$bin" geodesic path ico.off --from 0 --to 300 --method gcf --out gcf_u.json --svg gcf_u.svg
expect_ok "exact path --svg" "$bin" geodesic path ico.off --from 0 --to 300 --out mmp_u.json --svg mmp_u.svg
if $py - <<'PY'
import json, sys, xml.etree.ElementTree as ET
ns = "{http://www.w3.org/2000/svg}"
for name in ("gcf_u", "mmp_u"):
    u = json.load(open(name + ".json"))["unfold"]
    root = ET.parse(name + ".svg").getroot()
    polys = root.findall(ns + "g/" + ns + "polygon")
    ok = root.tag == ns + "svg" and len(polys) == u["faces"] > 0 and len(root.findall(ns + "polyline")) == 1
    ok = ok and u["straight_length"] <= u["traced_length"] * (1 + 1e-12)
    if name == "mmp_u" and u["vertex_points"] == 0:
        ok = ok and abs(u["traced_length"] - u["straight_length"]) <= 1e-9 * u["traced_length"]
    print(name, u)
    if not ok:
        sys.exit(1)
PY
then ok "--svg: valid SVG, one polygon per unfolded face, exact path straight"; else fail "--svg output"; fi
rm -f bad_u.json
expect_fail "--svg to an unwritable place" "no_such_dir/u.svg" "$bin" geodesic path ico.off --from 0 --to 300 --method gcf --out bad_u.json --svg no_such_dir/u.svg
if [ ! -e bad_u.json ] && [ ! -e no_such_dir ]; then ok "--svg failure: no JSON, no picture"; else fail "--svg failure left files"; fi
fi

# --- benchmark harness --------------------------------------------------------------------------
if in_section bench; then
expect_ok "bench geodesic" "$bin" bench geodesic --surface icosphere:2 --surface cylinder:1,2:24,8 \
  --methods heat,dijkstra --reference exact-cgal --sources 2 --repeat 2 --out bench.jsonl
if $py - <<'PY'
import json, sys
lines = [json.loads(l) for l in open("bench.jsonl")]
need = ["method","mesh","vertices","source","options","pre_seconds","query_seconds","peak_rss_bytes",
        "mean_rel_error","max_rel_error","mean_rel_error_truth","max_rel_error_truth","status","git"]
assert len(lines) == 2 * 2 * 3 * 2, len(lines)
for l in lines:
    missing = [k for k in need if k not in l]
    assert not missing, missing
    assert l["status"] == "ok", l
    assert l["peak_rss_bytes"] > 0
    assert l["mean_rel_error_truth"] is not None      # both surfaces have exact truth
ref = [l for l in lines if l["method"] == "exact-cgal"]
assert all(l["mean_rel_error"] == 0 for l in ref)
dij = [l for l in lines if l["method"] == "dijkstra"]
assert all(l["mean_rel_error"] > 1e-3 for l in dij)   # edge paths zig-zag: clearly longer
PY
then ok "bench lines complete and consistent"; else fail "bench lines"; fi
[ ! -e bench.jsonl.partial ] && ok "no partial bench file left" || fail "partial bench file left"
# A run beyond --memory-limit is a crash with an out-of-memory message, and the benchmark goes on.
expect_ok "bench with a memory limit" "$bin" bench geodesic --surface icosphere:6 --methods exact-cgal,dijkstra \
  --reference exact-cgal --memory-limit 0.5 --out oom.jsonl
if grep -q '"status":"crash"' oom.jsonl && grep -q 'out of memory (--memory-limit 0.5 GB)' oom.jsonl \
   && grep -q '"method":"dijkstra".*"status":"ok"' oom.jsonl; then ok "memory limit: crash recorded, next method ran"
else fail "memory limit lines: $(cat oom.jsonl | head -c 400)"; fi
expect_fail "bench unknown method" "nomethod" "$bin" bench geodesic --surface icosphere:1 --methods nomethod --out b2.jsonl
expect_fail "bench window on another method" "only gcf-window" "$bin" bench geodesic --surface icosphere:1 --methods dijkstra:4 --out b2.jsonl
expect_fail "bench window not a number" "gcf-window:x" "$bin" bench geodesic --surface icosphere:1 --methods gcf-window:x --out b2.jsonl
expect_fail "bench /raw without /faces" "goes after '/faces' on a gcf" "$bin" bench geodesic --surface icosphere:1 --methods gcf-window:4/raw --out b2.jsonl
expect_fail "bench /raw on another method" "distance methods take '/faces'" "$bin" bench geodesic --surface icosphere:1 --methods dijkstra/faces/raw --out b2.jsonl
expect_fail "bench /steps on another method" "goes last on gcf-window" "$bin" bench geodesic --surface icosphere:1 --methods gcf-exact/steps:20 --out b2.jsonl
expect_fail "bench /steps not a number" "'/steps:N'" "$bin" bench geodesic --surface icosphere:1 --methods gcf-window:4/steps:0 --out b2.jsonl
expect_ok "bench window sweep" "$bin" bench geodesic --surface icosphere:2 --methods gcf-window:2,gcf-window:6,gcf-window:4/faces,gcf-window:4/faces/raw,gcf-window:4/faces/steps:200 \
  --reference gcf-exact --threads 2 --out sweep.jsonl
if $py - <<'PY'
import json
lines = [json.loads(l) for l in open("sweep.jsonl")]
w = {l["method"]: l for l in lines}
assert set(w) == {"gcf-exact", "gcf-window:2", "gcf-window:6", "gcf-window:4/faces", "gcf-window:4/faces/raw", "gcf-window:4/faces/steps:200"}, set(w)
assert w["gcf-window:4/faces"]["options"]["window_max_iterations"] == 20
assert w["gcf-window:4/faces/steps:200"]["options"]["window_max_iterations"] == 200
# "options" is the library's Options as run (every field), plus the method name's length/repair.
def opt(m, *keys): return {k: w[m]["options"].get(k) for k in keys}
assert opt("gcf-window:2", "window", "anchor", "length", "smooth_length") == {"window": 2, "anchor": "field", "length": "smooth", "smooth_length": True}
assert opt("gcf-window:4/faces", "window", "length", "repair", "smooth_length") == {"window": 4, "length": "faces", "repair": True, "smooth_length": False}
assert opt("gcf-window:4/faces/raw", "window", "length", "repair", "repair_tolerance") == {"window": 4, "length": "faces", "repair": False, "repair_tolerance": -1.0}
assert w["gcf-window:4/faces"]["options"]["repair_tolerance"] > 0 and "flow" in w["gcf-window:2"]["options"]
assert w["gcf-window:6"]["options"]["window"] == 6
assert all(l["threads"] == 2 and l["status"] == "ok" for l in lines)
assert all(w[m]["max_rel_error"] < 2e-2 for m in ("gcf-window:2", "gcf-window:6"))
PY
then ok "bench window sweep lines"; else fail "bench window sweep lines"; fi
[ ! -e b2.jsonl ] && ok "rejected bench wrote nothing" || fail "rejected bench wrote b2.jsonl"
fi

# --- geodesics on point clouds (gcf-points) -----------------------------------------------------
if in_section points; then
# Points on the unit sphere as .xyz, .csv (with a header) and a faceless .ply; distances against
# the great circle; the same points in R^5 (.csv); readers' line-numbered rejections.
$py - <<'PY'
import math, random
random.seed(3)
pts = []
while len(pts) < 3000:
    v = [random.gauss(0, 1) for _ in range(3)]
    n = math.sqrt(sum(c * c for c in v))
    if n > 1e-9:
        pts.append([c / n for c in v])
with open("sphere.xyz", "w") as f:
    f.write("# unit sphere\n")
    for p in pts:
        f.write("%.17g %.17g %.17g\n" % tuple(p))
with open("sphere.csv", "w") as f:
    f.write("x,y,z\n")
    for p in pts:
        f.write("%.17g, %.17g, %.17g\n" % tuple(p))
with open("sphere.ply", "w") as f:
    f.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty double x\nproperty double y\n"
            "property double z\nend_header\n" % len(pts))
    for p in pts:
        f.write("%.17g %.17g %.17g\n" % tuple(p))
# R^5: (x, y, z, 0, 0) rotated by a fixed orthogonal matrix (two Givens rotations).
c, s = math.cos(0.7), math.sin(0.7)
with open("sphere5.csv", "w") as f:
    for p in pts:
        q = [p[0], p[1], p[2], 0.0, 0.0]
        q[0], q[3] = c * q[0] - s * q[3], s * q[0] + c * q[3]
        q[2], q[4] = c * q[2] - s * q[4], s * q[2] + c * q[4]
        f.write(",".join("%.17g" % x for x in q) + "\n")
PY
check_sphere() {  # check_sphere NAME FILE: distances from point 0 against the great circle
  $py - "$2" <<'PY' && ok "$1" || fail "$1"
import math, sys
pts = [list(map(float, l.split())) for l in open("sphere.xyz") if not l.startswith("#")]
d = [float(l) for l in open(sys.argv[1])]
assert len(d) == len(pts), (len(d), len(pts))
s = pts[0]; errs = []
for p, x in zip(pts, d):
    t = math.atan2(math.sqrt(sum(c * c for c in [s[1]*p[2]-s[2]*p[1], s[2]*p[0]-s[0]*p[2], s[0]*p[1]-s[1]*p[0]])), sum(a * b for a, b in zip(s, p)))
    if t > 0.5:
        errs.append(abs(x - t) / t)
mean = sum(errs) / len(errs)
print("mean rel error %.2e max %.2e" % (mean, max(errs)))
assert mean < 1e-2, mean
PY
}
for f in sphere.xyz sphere.csv sphere.ply; do
  expect_ok "point-cloud distances from $f" "$bin" geodesic distances "$f" --point-cloud --source 0 \
    --cell 0 --neighbours 16 --window 8 --out "d_${f%.*}_${f##*.}.txt"
  check_sphere "point-cloud distances from $f match the great circle" "d_${f%.*}_${f##*.}.txt"
done
expect_ok "point-cloud distances in R^5" "$bin" geodesic distances sphere5.csv --point-cloud --source 0 \
  --out d5.txt
grep -q "R^5, k 2" out.txt && ok "R^5: manifold dimension 2 estimated" || fail "R^5 report: $(cat out.txt)"
check_sphere "point-cloud distances in R^5 match the great circle" d5.txt
expect_ok "gcf-points:W with the plane projection" "$bin" geodesic distances sphere.xyz --point-cloud \
  --source 0 --method gcf-points:4 --projection plane --out d_plane.txt
check_sphere "gcf-points:4 with the plane projection matches the great circle" d_plane.txt
printf '1 2 3\n4 5 6\n7 8\n' > bad_cols.xyz
expect_fail "xyz row of another length" "bad_cols.xyz: line 3: 2 coordinates, but line 1 has 3" \
  "$bin" geodesic distances bad_cols.xyz --point-cloud --source 0 --out x.txt
printf 'x,y,z\n1,2,3\n4,abc,6\n' > bad_num.csv
expect_fail "csv field that is not a number" "bad_num.csv: line 3: coordinate 2 'abc' is not a number" \
  "$bin" geodesic distances bad_num.csv --point-cloud --source 0 --out x.txt
printf '1 2 3\n4 nan 6\n' > nan.xyz
expect_fail "NaN coordinate" "nan.xyz: line 2: coordinate 2 is NaN" \
  "$bin" geodesic distances nan.xyz --point-cloud --source 0 --out x.txt
head -n 10 sphere.xyz > few.xyz
expect_fail "fewer points than neighbours" "9 points, fewer than neighbours \+ 1 = 17" \
  "$bin" geodesic distances few.xyz --point-cloud --source 0 --out x.txt
{ cat sphere.xyz; sed -n 2p sphere.xyz; } > dup.xyz
expect_fail "duplicate points" "points #0 and #3000 coincide" \
  "$bin" geodesic distances dup.xyz --point-cloud --source 0 --out x.txt
expect_fail "point index out of range" "point 5000 does not exist" \
  "$bin" geodesic distances sphere.xyz --point-cloud --source 5000 --out x.txt
expect_fail "mesh method on a point cloud" "point clouds take gcf-points" \
  "$bin" geodesic distances sphere.xyz --point-cloud --source 0 --method exact-mmp --out x.txt
expect_fail "point-cloud output format" "written as .txt" \
  "$bin" geodesic distances sphere.xyz --point-cloud --source 0 --out x.ply
expect_fail "unknown point-set format" "expected .xyz, .csv or .ply" \
  "$bin" geodesic distances "$spot" --point-cloud --source 0 --out x.txt
[ ! -e x.txt ] && [ ! -e x.ply ] && ok "rejected point-cloud runs wrote nothing" || fail "half-written output"
expect_ok "gcf-points in the benchmark, with noise" "$bin" bench geodesic --surface icosphere:3 \
  --methods gcf-points,gcf-points:4 --reference exact-mmp --noise 0.001 --cell 0.15 --out pts.jsonl
$py - <<'PY' && ok "gcf-points benchmark lines" || fail "gcf-points benchmark lines: $(head -c 300 pts.jsonl)"
import json
lines = [json.loads(l) for l in open("pts.jsonl")]
pts = [l for l in lines if l["method"].startswith("gcf-points")]
assert len(pts) == 2 and all(l["status"] == "ok" for l in pts), pts
assert pts[0]["options"]["noise"] == 0.001 and pts[0]["options"]["cell"] == 0.15
assert pts[1]["options"]["window"] == 4
assert all(l["mean_rel_error_truth"] < 0.05 for l in pts), [l["mean_rel_error_truth"] for l in pts]
PY
fi

# --- sewing patterns ----------------------------------------------------------------------------
if in_section pattern; then
expect_ok "pattern import" "$bin" pattern import "$fs" "$gc" --db p.sqlite
expect_ok "pattern list" "$bin" pattern list --db p.sqlite
if [ "$(wc -l <out.txt)" -eq 2 ] && grep -q "^shirt_mean" out.txt && grep -q "^aaron_cisFemaleAdult36" out.txt; then ok "list shows both"
else fail "list: $(cat out.txt)"; fi
expect_ok "pattern list --type" "$bin" pattern list --db p.sqlite --type "tank top"
[ "$(wc -l <out.txt)" -eq 1 ] && ok "search by garment type" || fail "search by type: $(cat out.txt)"
expect_fail "duplicate import" "shirt_mean.*--replace" "$bin" pattern import "$gc" --db p.sqlite
expect_ok "import --replace" "$bin" pattern import "$gc" --db p.sqlite --replace
expect_ok "pattern show" "$bin" pattern show shirt_mean --db p.sqlite
grep -q "pieces: 8" out.txt && ok "show: 8 pieces" || fail "show: $(head -c 300 out.txt)"
expect_ok "pattern export all formats" "$bin" pattern export shirt_mean --db p.sqlite --svg s.svg --png s.png \
  --dxf s.dxf --json s.json --mesh s.obj --edge-length 20
# Every export holds the stored pattern's 8 pieces: the JSON's outlines, one SVG piece group
# each (named as in the JSON), one DXF BLOCK each, a PNG, and a mesh whose every vertex has a UV
# (the 2D piece coordinates).
if $py - <<'PY'
import json, struct, xml.etree.ElementTree as ET
ns = "{http://www.w3.org/2000/svg}"
j = json.load(open("s.json"))
names = [p["name"] for p in j["pieces"]]
assert len(names) == 8, names
groups = [g for g in ET.parse("s.svg").getroot().iter(ns + "g") if g.get("class") == "piece"]
assert [g.get("data-name") for g in groups] == names, [g.get("data-name") for g in groups]
assert all(any(e.get("class") == "outline" for e in g) for g in groups)
dxf = open("s.dxf").read().splitlines()
blocks = [i for i in range(len(dxf) - 1) if dxf[i].strip() == "0" and dxf[i + 1].strip() == "BLOCK"]
assert dxf[dxf.index("$ACADVER") + 2].strip() == "AC1009" and len(blocks) == 8, len(blocks)
png = open("s.png", "rb").read()
assert png[:8] == b"\x89PNG\r\n\x1a\n" and png[12:16] == b"IHDR"
v = [l for l in open("s.obj") if l.startswith("v ")]
vt = [list(map(float, l.split()[1:3])) for l in open("s.obj") if l.startswith("vt ")]
f = [l for l in open("s.obj") if l.startswith("f ")]
assert len(v) == len(vt) > 0 and len(f) > 0, (len(v), len(vt), len(f))
PY
then ok "exports hold the 8 pieces (JSON, SVG groups, DXF blocks, PNG, mesh with UVs)"
else fail "export contents"; fi
expect_ok "exported JSON validates" "$bin" pattern validate s.json
expect_ok "export from a file" "$bin" pattern export "$fs" --svg f.svg --json f.json
$py - <<'PY' && ok "export from a file: one SVG group per piece of the file" || fail "export from a file"
import json, xml.etree.ElementTree as ET
ns = "{http://www.w3.org/2000/svg}"
names = [p["name"] for p in json.load(open("f.json"))["pieces"]]
groups = [g.get("data-name") for g in ET.parse("f.svg").getroot().iter(ns + "g") if g.get("class") == "piece"]
assert groups == names and len(names) == 4, (groups, names)
PY
printf '{"design": "x", "pieces": [' > broken.json
expect_fail "truncated pattern JSON" "broken.json" "$bin" pattern import broken.json --db p.sqlite
expect_ok "database unchanged after a rejected import" "$bin" pattern list --db p.sqlite
[ "$(wc -l <out.txt)" -eq 2 ] && ok "still 2 patterns" || fail "database changed: $(cat out.txt)"
expect_fail "unknown pattern" "nope" "$bin" pattern export nope --db p.sqlite --svg n.svg
expect_fail "export without output" "at least one" "$bin" pattern export shirt_mean --db p.sqlite
[ ! -e n.svg ] && ok "failed export wrote nothing" || fail "failed export wrote n.svg"
fi

# --- grade --------------------------------------------------------------------------------------
if in_section grade; then
echo "$base36" > base36.json
echo "$base36" | sed 's/"chest": 979/"chest": 1143/; s/"hips": 953/"hips": 1112/;
  s/"hpsToWaistBack": 410/"hpsToWaistBack": 455/; s/"shoulderToShoulder": 431/"shoulderToShoulder": 478/;
  s/"waistToHips": 130/"waistToHips": 144/' > target42.json
expect_ok "grade aaron 36 to 42" "$bin" grade "$fs" --from base36.json --to target42.json \
  --out g.json --svg g.svg --pareto front.png --rules rules.json --rul rules.rul --dxf g.dxf \
  --report report.json --seed 7 --threads 2 --generations 20
if grep -q '"tapeline-pattern"' g.json && grep -q "<svg" g.svg && head -c 8 front.png | grep -q PNG &&
   grep -q '"tapeline-grade-rules"' rules.json && grep -q "AC1009" g.dxf && grep -q "^RULE: DELTA" rules.rul
then ok "grade outputs look right"; else fail "grade outputs"; fi
# The grade rules: each outline vertex's rule goes from the base draft's vertex to the graded
# pattern's (edge N = start of outline edge N), and the .rul table lists the same offsets.
expect_ok "export the base draft as tapeline JSON" "$bin" pattern export "$fs" --json base.json
if $py - <<'PY'
import json
def start(e):
    return e["p"][0] if e["type"] == "cubic" else e["a"]
base = {p["name"]: p for p in json.load(open("base.json"))["pieces"]}
graded = {p["name"]: p for p in json.load(open("g.json"))["pieces"]}
r = json.load(open("rules.json"))
assert r["format"] == "tapeline-grade-rules" and r["units"] == "mm"
edge_rules = [x for x in r["rules"] if x["point"].startswith("edge ")]
assert len(edge_rules) == sum(len(p["outline"]) for p in base.values()), len(edge_rules)
for x in edge_rules:
    n = int(x["point"].split()[1])
    b, g = start(base[x["piece"]]["outline"][n]), start(graded[x["piece"]]["outline"][n])
    assert max(abs(x["base"][0] - b[0]), abs(x["base"][1] - b[1])) <= 1e-9, (x, b)
    assert max(abs(x["graded"][0] - g[0]), abs(x["graded"][1] - g[1])) <= 1e-9, (x, g)
    assert abs(x["offset"][0] - (g[0] - b[0])) <= 1e-9 and abs(x["offset"][1] - (g[1] - b[1])) <= 1e-9
moved = max(abs(c) for x in edge_rules for c in x["offset"])
assert moved > 5, moved  # 36 to 42 moves the outline by centimetres
rul = open("rules.rul").read().splitlines()
assert rul[0] == "RULE: DELTA" and rul[-1] == "END", (rul[0], rul[-1])
deltas = [tuple(map(float, rul[i + 1].split()[1].split(","))) for i in range(len(rul) - 1)
          if rul[i].startswith("RULE: ") and rul[i] != "RULE: DELTA"]
assert len(deltas) == len(edge_rules), (len(deltas), len(edge_rules))
for d, x in zip(deltas, edge_rules):
    assert abs(d[0] - x["offset"][0]) <= 5e-4 and abs(d[1] - x["offset"][1]) <= 5e-4, (d, x)
PY
then ok "grade rules: base and graded vertices of the outlines, .rul offsets the same"
else fail "grade rules"; fi
if $py - <<'PY'
import json, sys
r = json.load(open("report.json"))
worst = max(abs(f["error_mm"]) for f in r["fit"])
sys.exit(0 if r["fit"] and worst < 2.0 else 1)
PY
then ok "grade: every binding within 2 mm"; else fail "grade: fit $(head -c 400 report.json)"; fi
expect_ok "graded pattern validates" "$bin" pattern validate g.json
expect_ok "grade to a smaller size (42 back to 36)" "$bin" grade g.json --from target42.json \
  --to base36.json --out back.json --threads 2 --generations 10 --report back_report.json
$py - <<'PY' && ok "graded back to 36: targets are the 36 set, bindings within 2 mm" || fail "grade back to 36: $(head -c 300 back_report.json)"
import json
want = json.load(open("base36.json"))
rows = json.load(open("back_report.json"))["fit"]
assert rows and {"chest", "hips"} <= {r["measurement"] for r in rows}, rows
for r in rows:
    assert r["target_mm"] == want[r["measurement"]] and abs(r["error_mm"]) < 2.0, r
PY
$py -c 'import json; m = json.load(open("target42.json")); json.dump({"measurements": [{"name": "iso_" + k, "freesewing_name": k, "value_mm": v} for k, v in m.items()]}, open("measure.json", "w"))'
expect_ok "grade to a tapeline-measure JSON (Ceres only)" "$bin" grade "$fs" --from base36.json \
  --to measure.json --out gm.json --threads 2 --generations 0 --report gm_report.json
$py - <<'PY' && ok "grade to a measure JSON: its FreeSewing names are the targets, within 2 mm" || fail "grade to a measure JSON: $(head -c 300 gm_report.json)"
import json
want = json.load(open("target42.json"))
r = json.load(open("gm_report.json"))
assert r["fit"] and r["nsga2_evaluations"] == 0, r["nsga2_evaluations"]
for row in r["fit"]:
    assert row["target_mm"] == want[row["measurement"]] and abs(row["error_mm"]) < 2.0, row
PY
echo '{"measurements": [{"freesewing_name": "chest", "value_mm": 1000}]}' > m.json
expect_fail "target missing a bound measurement" "no measurement 'hips'" "$bin" grade "$fs" \
  --from base36.json --to m.json --out miss.json
[ ! -e miss.json ] && ok "failed grade wrote nothing" || fail "failed grade wrote miss.json"
echo '{"chest": -5, "hips": 1000}' > neg.json
expect_fail "negative target" "'chest' is -5" "$bin" grade "$fs" --from base36.json --to neg.json --out n.json
echo '{"waist": 1800, "height": 1600, "chest": 900}' > tall.json
expect_fail "waist bigger than height" "bigger than the height" "$bin" grade "$fs" --from base36.json \
  --to tall.json --out n.json
echo '{"units": "cubits", "chest": 40}' > unit.json
expect_fail "unknown unit" "unknown unit 'cubits'" "$bin" grade "$fs" --from base36.json --to unit.json --out n.json
expect_fail "unknown output extension" "\.xyz" "$bin" grade "$fs" --from base36.json --to target42.json --out n.xyz
[ ! -e n.json ] && ok "rejected grades wrote nothing" || fail "a rejected grade wrote n.json"
# The chain through Seamly2D: measure the bundled body, write its .vit, grade aaron to the .vit
# (Seamly2D names mapped to the FreeSewing names the pattern binds).
expect_ok "measure the bundled body to a .vit" "$bin" measure \
  "$root/data/bodies/mh_female_average.obj" --units dm --out vbody.json --vit vbody.vit
expect_ok "grade aaron to a .vit from tapeline measure" "$bin" grade "$fs" --from base36.json \
  --to vbody.vit --out gv.json --report gv_report.json --threads 2 --generations 10
if $py - <<'PY'
import json
j = json.load(open("vbody.json"))
want = {e["freesewing_name"]: e["value_mm"] for e in j["measurements"]
        if e.get("freesewing_name") and e["value_mm"] is not None}
r = json.load(open("gv_report.json"))
assert {"chest", "hips", "waistToHips"} <= {f["measurement"] for f in r["fit"]}, r["fit"]
for row in r["fit"]:
    assert abs(row["error_mm"]) <= 2.0, row
    assert abs(row["target_mm"] - want[row["measurement"]]) < 0.01, (row, want)
assert r["seams"] and all(s["mismatch_mm"] <= 1.0 for s in r["seams"]), r["seams"]
PY
then ok "grade to a .vit: targets are the measured values, bindings within 2 mm, seams within 1 mm"
else fail "grade to a .vit: $(head -c 300 gv_report.json)"; fi
# A formula referring to a name the file does not define leaves that measurement out, with a
# warning; the others stay usable (Valentina opens such files too).
sed 's|</body-measurements>|<m name="@dangling" value="@nowhere + 1"/></body-measurements>|' vbody.vit > vdangling.vit
expect_ok "grade to a .vit with a dangling formula" "$bin" grade "$fs" --from base36.json \
  --to vdangling.vit --out gd.json --threads 2 --generations 0
if grep -q "^tapeline: warning: vdangling.vit:[0-9]*: measurement '@dangling': formula '@nowhere + 1': refers to '@nowhere', which the file does not define; '@dangling' left out" err.txt
then ok "the dangling formula is named in a warning"; else fail "dangling formula warning: $(head -c 300 err.txt)"; fi
fi

# --- measure ------------------------------------------------------------------------------------
if in_section measure; then
# A closed octahedron 40 units tall: no unit makes it a human height, so --units is required.
printf 'v 3 20 0\nv -3 20 0\nv 0 20 3\nv 0 20 -3\nv 0 40 0\nv 0 0 0\n' > tall.obj
printf 'f 5 3 1\nf 5 2 3\nf 5 4 2\nf 5 1 4\nf 6 1 3\nf 6 3 2\nf 6 2 4\nf 6 4 1\n' >> tall.obj
expect_fail "measure: units not inferable" "tall.obj.*cannot be inferred.*--units" \
  "$bin" measure tall.obj --out mx.json
expect_fail "measure: unknown unit" "--units.*unknown length unit 'inch'" \
  "$bin" measure tall.obj --units inch --out mx.json
expect_fail "measure: unwritable output" "no_such_dir" \
  "$bin" measure tall.obj --units cm --out no_such_dir/mx.json
expect_fail "measure: --out must be JSON" "--out.*\.json" "$bin" measure tall.obj --units cm \
  --out mx.txt
expect_fail "measure: --vit must be .vit" "--vit.*\.vit" "$bin" measure tall.obj --units cm \
  --out mx.json --vit mx.xml
echo '{"landmarks": {"crotch": [0, 1' > bad_landmarks.json
expect_fail "measure: malformed landmarks file" "bad_landmarks.json" \
  "$bin" measure tall.obj --units cm --out mx.json --landmarks bad_landmarks.json
echo '{"landmarks": {"navel": [0, 1, 0]}}' > unknown_landmark.json
expect_fail "measure: unknown landmark" "unknown landmark 'navel'" \
  "$bin" measure tall.obj --units cm --out mx.json --landmarks unknown_landmark.json
expect_fail "measure: bad pose" "--pose.*'Y'" "$bin" measure tall.obj --units cm --pose Y \
  --out mx.json
expect_fail "measure: --picture must be .svg or .png" "--picture: mx\.jpg: expected a \.svg or \.png" \
  "$bin" measure tall.obj --units cm --out mx.json --picture mx.jpg
expect_fail "measure: --picture directory must exist" "--picture.*no_such_dir" \
  "$bin" measure tall.obj --units cm --out mx.json --picture no_such_dir/mx.svg
if ls mx.* no_such_dir >/dev/null 2>&1 || ls ./*.tmp-* >/dev/null 2>&1; then
  fail "a rejected measure wrote a file: $(ls mx.* ./*.tmp-* 2>/dev/null)"
else ok "rejected measures wrote nothing"; fi
# The picture of the bundled body: well-formed SVG with one labelled tape group per measurement
# of the JSON (values equal), two tapes each (front, side) with the JSON's points; a PNG.
expect_ok "measure with --picture (SVG and PNG)" "$bin" measure \
  "$root/data/bodies/mh_female_average.obj" --units dm --out pic.json --picture pic.svg \
  --picture pic.png
if $py - <<'PY'
import json, struct, xml.etree.ElementTree as ET
j = json.load(open("pic.json"))
root = ET.parse("pic.svg").getroot()
ns = "{http://www.w3.org/2000/svg}"
groups = {g.get("data-name"): g for g in root.iter(ns + "g") if g.get("class") == "measurement"}
assert set(groups) == {m["name"] for m in j["measurements"]}, set(groups) ^ {m["name"] for m in j["measurements"]}
for m in j["measurements"]:
    g = groups[m["name"]]
    if m["value_mm"] is not None:
        assert abs(float(g.get("data-value-mm")) - m["value_mm"]) < 0.006, m["name"]
    tapes = [e for e in g if e.get("class") == "tape"]
    assert sorted(t.get("data-view") for t in tapes) == ["front", "side"], m["name"]
    for t in tapes:
        assert t.tag == ns + ("polygon" if m["closed"] else "polyline"), m["name"]
        assert len(t.get("points").split()) == len(m["points"]), m["name"]
    label = [e for e in g if e.get("class") == "label"][0].text
    assert label.startswith(m["name"] + " "), label
import os
assert os.path.getsize("pic.svg") < 2 * 1024 * 1024
png = open("pic.png", "rb").read()
assert png[:8] == b"\x89PNG\r\n\x1a\n" and png[12:16] == b"IHDR"
w, h = struct.unpack(">II", png[16:24])
assert 800 < w < 10000 and 800 < h < 10000, (w, h)
PY
then ok "measure: picture SVG has every measurement's tapes and label, PNG header"
else fail "measure: picture $(head -c 300 pic.svg)"; fi
bodies="$root/../shared/data/bodies"
if [ -f "$bodies/mh_female_average.obj" ] && [ -f "$bodies/measurements.json" ]; then
  expect_ok "measure a MakeHuman body (dm)" "$bin" measure "$bodies/mh_female_average.obj" \
    --units dm --out body.json --vit body.vit
  if $py - "$bodies/measurements.json" <<'PY'
import json, sys
j = json.load(open("body.json"))
truth = json.load(open(sys.argv[1]))["bodies"]["mh_female_average"]
keys = ["format", "body", "frame", "measurements", "missing", "landmarks", "timings_seconds"]
assert set(keys) <= set(j), list(j)
assert j["frame"]["unit"] == "dm" and j["frame"]["unit_inferred"] is False
m = {e["name"]: e for e in j["measurements"]}
for e in j["measurements"]:
    keys = {"name", "kind", "value_mm", "iso_clause", "freesewing_name", "points", "closed"}
    assert keys <= set(e), e["name"]
    assert e["points"], e["name"]
chest = m["bust_girth"]
assert chest["freesewing_name"] == "chest" and chest["kind"] == "girth" and chest["closed"]
assert 700 < chest["value_mm"] < 1300, chest["value_mm"]
assert 550 < m["waist_girth"]["value_mm"] < chest["value_mm"] + 100, m["waist_girth"]["value_mm"]
assert 800 < m["hip_girth"]["value_mm"] < 1400, m["hip_girth"]["value_mm"]
height = m["stature"]["value_mm"]
assert abs(height - truth["height_cm"] * 10) <= 1.0, (height, truth["height_cm"])
lm = {l["name"]: l for l in j["landmarks"]}
assert len(lm) == 23 and all(l["status"] == "found" for l in lm.values()), \
    [l for l in lm.values() if l["status"] != "found"]
assert j["missing"] == [], j["missing"]
assert j["timings_seconds"]["total"] > 0 and "lengths" in j["timings_seconds"]
fs = {e["freesewing_name"]: e for e in j["measurements"] if e["kind"] == "length"}
for n in ["shoulderToShoulder", "hpsToWaistBack", "hpsToWaistFront", "shoulderToElbow",
          "shoulderToWrist", "inseam", "waistToFloor"]:
    assert n in fs and len(fs[n]) and len(fs[n]["points"]) >= 2 and not fs[n]["closed"], n
# A tape down the inside of the leg is at least the crotch height; the outseam is longer.
crotch_y = [l for l in j["landmarks"] if l["name"] == "crotch"][0]["point"][1]
assert fs["inseam"]["value_mm"] >= 0.99 * crotch_y, (fs["inseam"]["value_mm"], crotch_y)
assert fs["waistToFloor"]["value_mm"] > fs["inseam"]["value_mm"]
PY
  then ok "measure: JSON keys and plausible values"
  else fail "measure: JSON $(head -c 300 body.json)"; fi
  if grep -q '<m name="bust_circ" value=' body.vit && grep -q '<unit>mm</unit>' body.vit &&
     grep -q '<m name="leg_crotch_to_floor" value=' body.vit; then
    ok "measure: .vit has bust_circ in mm"; else fail "measure: .vit $(head -c 300 body.vit)"; fi
  # An override in the mesh's own coordinates: the found crotch moved 1 cm (0.1 dm) down.
  $py - <<'PY' > override.json
import json
j = json.load(open("body.json"))
crotch = [l for l in j["landmarks"] if l["name"] == "crotch"][0]["point_input"]
moved = [crotch[0], crotch[1] - 0.1, crotch[2]]
print(json.dumps({"frame": "input", "landmarks": {"crotch": moved}}))
PY
  expect_ok "measure with a landmark override" "$bin" measure "$bodies/mh_female_average.obj" \
    --units dm --out over.json --landmarks override.json
  if $py -c 'import json, sys
l = {e["name"]: e for e in json.load(open("over.json"))["landmarks"]}
sys.exit(l["crotch"]["status"] != "overridden")'
  then ok "measure: overridden landmark reported"; else fail "measure: override not reported"; fi
  # Holes as a scan has them: faces cut out around the crown and the lowest point of a sole
  # (19 mm, 1.2 % of the stature) are filled and reported; a hole about 200 mm across at the
  # left side of the waist is refused naming its height and place (TopologyError, exit 3), and
  # nothing is written.
  $py - "$bodies/mh_female_average.obj" <<'PY'
import json, math, sys
V, F = [], []
for line in open(sys.argv[1]):
    t = line.split()
    if t and t[0] == "v": V.append([float(x) for x in t[1:4]])
    if t and t[0] == "f": F.append([int(x.split("/")[0]) - 1 for x in t[1:]])
j = json.load(open("body.json"))
floor = j["frame"]["floor_mm"]
waist = [m for m in j["measurements"] if m["name"] == "waist_girth"][0]["points"]
side = max(waist, key=lambda p: p[0])  # canonical mm: the torso's left side at the waist
side = [side[0] / 100, (side[1] + floor) / 100, side[2] / 100]
top = max(V, key=lambda v: v[1])
sole = min(V, key=lambda v: v[1])
def write(name, balls):
    keep = [f for f in F if not any(math.dist(V[i], c) < r for i in f for c, r in balls)]
    used = sorted({i for f in keep for i in f})
    new = {i: k + 1 for k, i in enumerate(used)}
    with open(name, "w") as out:
        for i in used: out.write("v %.6f %.6f %.6f\n" % tuple(V[i]))
        for f in keep: out.write("f " + " ".join(str(new[i]) for i in f) + "\n")
write("holes.obj", [(top, 0.19), (sole, 0.19)])
write("big_hole.obj", [(side, 0.8)])
PY
  expect_ok "measure a body with holes at the crown and a sole" "$bin" measure holes.obj \
    --units dm --out holes.json
  if [ "$(grep -c '^tapeline: holes.obj: filled a hole .* mm across at .* mm height, ' err.txt)" -eq 2 ] &&
     grep -q 'the crown (faired' err.txt && grep -qE 'the (left|right) sole \(faired' err.txt &&
     $py - <<'PY'
import json
j = json.load(open("holes.json"))
holes = j["report"]["holes"]
assert sorted(h["region"].split()[-1] for h in holes) == ["crown", "sole"], holes
for h in holes:
    assert 0 < h["size_mm"] <= 0.05 * j["frame"]["height_mm"] and h["filling"] == "faired", h
    assert h["faces_added"] > 0, h
m = {e["name"]: e for e in j["measurements"]}
assert all("crosses_filled_hole" in e for e in j["measurements"])
assert m["stature"]["crosses_filled_hole"], "the top of the head is on the crown's patch"
assert not m["waist_girth"]["crosses_filled_hole"]
ref = {e["name"]: e["value_mm"] for e in json.load(open("body.json"))["measurements"]}
for e in j["measurements"]:
    if e["kind"] == "girth":
        assert abs(e["value_mm"] - ref[e["name"]]) <= 4, (e["name"], e["value_mm"], ref[e["name"]])
PY
  then ok "measure: holes filled, reported on stderr and in the JSON, girths within 4 mm"
  else fail "measure: holes $(head -c 400 err.txt)"; fi
  expect_fail "measure: a hole too big to fill is refused naming where" \
    "big_hole.obj: a hole [12][0-9]{2} mm across at 1,0[0-9]{2} mm height, the left side of the torso \(holes up to 79 mm, 5 % of the stature, are filled" \
    "$bin" measure big_hole.obj --units dm --out big_hole.json
  if [ -e big_hole.json ]; then fail "measure: the refused body wrote its JSON"
  else ok "measure: the refused body wrote nothing"; fi
  # The chain: grade the bundled aaron from its own base set to the measured body.
  expect_ok "grade aaron to the measured body" "$bin" grade "$fs" \
    --from "$root/data/patterns/aaron_cisFemaleAdult36_measurements.json" --to body.json \
    --out chain.json --report chain_report.json --seed 7 --threads 2
  if $py - <<'PY'
import json
j = json.load(open("body.json"))
want = {e["freesewing_name"]: e["value_mm"] for e in j["measurements"] if e.get("freesewing_name")}
rows = json.load(open("chain_report.json"))["fit"]
assert {"chest", "hips", "waistToHips"} <= {r["measurement"] for r in rows}, rows
for row in rows:
    assert abs(row["error_mm"]) <= 2.0, row
    assert abs(row["target_mm"] - want[row["measurement"]]) < 0.01, (row, want)
PY
  then ok "grade to the measured body: every binding within 2 mm"
  else fail "grade to the measured body: $(head -c 300 chain_report.json)"; fi
else
  echo "skip - measure on MakeHuman bodies ($bodies absent)"
fi
fi

# --- grade options: each against a known answer ----------------------------------------------
# Grading a pattern without bindings (GarmentCode): its girths found by laying it on the body it
# is graded from (--base-body); each graded girth, recomputed here from the graded pattern's points
# and the bindings file, is the target plus the base ease scaled (proportional ease); a bindings
# file given back replaces the found ones.
if in_section grade_infer; then
gcs="$root/data/patterns/shirt_mean_specification.json"
bodyf="$root/data/bodies/mh_female_average.obj"
expect_ok "measure the base body" "$bin" measure "$bodyf" --units dm --out base_m.json
$py - <<'PY'
import json
m = json.load(open("base_m.json"))
for e in m["measurements"]:
    if e["kind"] == "girth" and e["value_mm"]:
        e["value_mm"] *= 1.08
json.dump(m, open("target_m.json", "w"))
PY
expect_fail "grade: --from and --base-body" "either as a set \\(--from\\) or as a body" \
  "$bin" grade "$gcs" --from base_m.json --base-body "$bodyf" --to target_m.json --out x.json
expect_fail "grade: no base at all" "either as a set \\(--from\\) or as a body" \
  "$bin" grade "$gcs" --to target_m.json --out x.json
expect_ok "grade the GarmentCode shirt from its body" "$bin" grade "$gcs" --base-body "$bodyf" \
  --base-units dm --to target_m.json --out gi.json --bindings-out bi.json --generations 0
check_girths() {  # check_girths GRADED BINDINGS: every bound girth = target + scaled ease
  $py - "$1" "$2" <<'PY'
import json, math, sys
g, b = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
base = {e["name"]: e["value_mm"] for e in json.load(open("base_m.json"))["measurements"]}
target = {e["name"]: e["value_mm"] for e in json.load(open("target_m.json"))["measurements"]}
pieces = {p["name"]: p for p in g["pieces"]}
names = [x["measurement"] for x in b["bindings"]]
# The girths, then the lengths one per piece (two back and two front panels).
assert names == ["bust_girth", "underbust_girth", "waist_girth", "high_hip_girth",
                 "upper_arm_girth", "elbow_girth"] + ["hps_to_waist_back"] * 2 + \
    ["waist_to_armpit"] * 4 + ["waist_to_high_hip"] * 4, names
for x in b["bindings"]:
    got = 0
    for f in x["features"]:
        pts = pieces[f["piece"]]["points"]
        (ax, ay), (bx, by) = pts[f["from_point"]], pts[f["to_point"]]
        got += f["count"] * math.hypot(bx - ax, by - ay)
    m = x["measurement"]
    want = target[m] + x["ease"] * target[m] / base[m]
    assert abs(got - want) <= 2, (m, got, want)
PY
}
if check_girths gi.json bi.json; then ok "grade: the found girths graded to target + ease within 2 mm"
else fail "grade: found girths after grading"; fi
$py -c "
import json; b = json.load(open('bi.json'))
w = next(x for x in b['bindings'] if x['measurement'] == 'waist_girth'); w['ease'] += 50
json.dump(b, open('bi2.json', 'w'))"
expect_ok "grade with an edited bindings file" "$bin" grade "$gcs" --base-body "$bodyf" \
  --base-units dm --to target_m.json --out gi2.json --bindings bi2.json --generations 0
if check_girths gi2.json bi2.json && grep -q "bindings of bi2.json given" out.txt
then ok "grade: a given bindings file replaces the found bindings"
else fail "grade: --bindings"; fi
printf '{"format": "tapeline-bindings", "units": "mm", "points": {"collar": {"a": [0, 0]}}, "bindings": []}\n' >bad_b.json
expect_fail "grade: a bindings file naming a missing piece" "bad_b.json: .*has no piece 'collar'" \
  "$bin" grade "$gcs" --base-body "$bodyf" --base-units dm --to target_m.json --out x.json --bindings bad_b.json
if [ -e x.json ]; then fail "grade: a refusal wrote x.json"; else ok "grade: refusals write nothing"; fi
# A FreeSewing draft laid on a body other than its own: only the declared measurements are bound,
# eased against the declared values (the base set takes them), and every binding says where it
# came from (all found on the body: the chest below the armhole, the shoulder width across the
# back; the scooped neckline is a style line, left unbound, which the table does not bind
# either); a target set with FreeSewing's names (it has no underbust) grades it.
echo "$base36" | sed 's/"chest": 979/"chest": 1143/; s/"hips": 953/"hips": 1112/;
  s/"hpsToWaistBack": 410/"hpsToWaistBack": 455/; s/"waistToHips": 130/"waistToHips": 144/;
  s/"waistToArmpit": 177/"waistToArmpit": 190/' > fs_target.json
expect_ok "grade a FreeSewing draft from another body" "$bin" grade "$fs" --base-body "$bodyf" \
  --base-units dm --to fs_target.json --out fsg.json --report fsr.json --bindings-out fsb.json \
  --generations 0
if grep -q "^binding: origin: found on the body: chest, hips, shoulderToShoulder, hpsToWaistBack, waistToArmpit, waistToHips$" out.txt &&
   ! grep -q "^binding: origin: FreeSewing table" out.txt &&
   grep -q "^binding: neck_girth: not bound (the neckline, .* a style line" out.txt &&
   grep -q "^binding: underbust_girth: not bound (pattern 'aaron_cisFemaleAdult36' declares" out.txt &&
   $py - "$base36" <<'PY'
import json, math, sys
declared = json.loads(sys.argv[1])  # what aaron_cisFemaleAdult36 declares
r, b = json.load(open("fsr.json")), json.load(open("fsb.json"))
assert {x["origin"] for x in r["fit"]} == {"found on the body"}
for x in b["bindings"]:
    total = 0
    for f in x["features"]:
        (ax, ay), (bx, by) = (b["points"][f["piece"]][f[k]] for k in ("from_point", "to_point"))
        total += f["count"] * math.hypot(bx - ax, by - ay)
    assert abs(x["ease"] - (total - declared[x["measurement"]])) < 1e-6, x["measurement"]
PY
then ok "grade: declared measurements bound, eased against, origins reported"
else fail "grade: a FreeSewing draft from another body"; fi
# The design's seams without the table's bindings: the same found bindings, graded with the seams
# the design table adds (aaron's binding strips against the armhole and neckline) that
# --no-freesewing-bindings leaves out; the two flags together are refused.
seams_of() { $py -c "import json, sys; print(' '.join(sorted(s['name'].replace(' ', '_') for s in json.load(open(sys.argv[1]))['seams'])))" "$1"; }
expect_ok "grade --freesewing-seams-only" "$bin" grade "$fs" --base-body "$bodyf" --base-units dm \
  --to fs_target.json --out so.json --report so_r.json --generations 0 --freesewing-seams-only
cp out.txt so_out.txt
expect_ok "grade --no-freesewing-bindings" "$bin" grade "$fs" --base-body "$bodyf" --base-units dm \
  --to fs_target.json --out no.json --report no_r.json --generations 0 --no-freesewing-bindings
if [ "$(seams_of so_r.json)" = "armhole_binding neck_binding shoulder side" ] &&
   [ "$(seams_of no_r.json)" = "shoulder side" ] &&
   grep -q "^binding: origin: found on the body: chest, hips," so_out.txt &&
   ! grep -q "FreeSewing table" so_out.txt
then ok "grade: --freesewing-seams-only adds the design's seams, no table binding"
else fail "grade: --freesewing-seams-only (seams: $(seams_of so_r.json) / $(seams_of no_r.json))"; fi
expect_fail "grade: --freesewing-seams-only with --no-freesewing-bindings" \
  "excludes --freesewing-seams-only" "$bin" grade "$fs" --base-body "$bodyf" --base-units dm \
  --to fs_target.json --out x.json --freesewing-seams-only --no-freesewing-bindings
fi

if in_section grade_options; then
echo "$base36" > base36.json
echo "$base36" | sed 's/"chest": 979/"chest": 1143/; s/"hips": 953/"hips": 1112/;
  s/"hpsToWaistBack": 410/"hpsToWaistBack": 455/; s/"shoulderToShoulder": 431/"shoulderToShoulder": 478/;
  s/"waistToHips": 130/"waistToHips": 144/' > target42.json
quick=(--from base36.json --to target42.json --seed 7 --threads 2 --population 10 --generations 3)
expect_ok "grade with a fit table" "$bin" grade "$fs" "${quick[@]}" --out a.json --report a_report.json \
  --fit-table a_fit.txt
# The fit table has the report's rows: target, ease, achieved and error to its printed digits.
$py - <<'PY' && ok "--fit-table rows = the report's fit and seam rows" || fail "--fit-table: $(head -c 300 a_fit.txt)"
import json
r = json.load(open("a_report.json"))
rows = [l.split() for l in open("a_fit.txt").read().splitlines()[1:]]
fit = [l for l in rows if l[0] != "seam"]
seams = [l for l in rows if l[0] == "seam"]
assert len(fit) == len(r["fit"]) > 0 and len(seams) == len(r["seams"]), (len(fit), len(r["fit"]))
for l, f in zip(fit, r["fit"]):
    assert l[0] == f["measurement"], (l, f)
    target, ease, achieved, error = map(float, l[-4:])
    assert abs(target - f["target_mm"]) <= 0.05 and abs(ease - f["ease_mm"]) <= 0.05, (l, f)
    assert abs(achieved - f["achieved_mm"]) <= 0.005 and abs(error - f["error_mm"]) <= 0.005, (l, f)
for l, s in zip(seams, r["seams"]):  # seam NAME LA LB ratio R mismatch M mm
    assert " ".join(l[1:-7]) == s["name"] and abs(float(l[-2]) - s["mismatch_mm"]) <= 0.005, (l, s)
PY
# NSGA-II evaluates its population (--population rounded up to a multiple of 4, at least 8) once
# per generation and once at the start: 12 x (3 + 1) = 48.
$py -c 'import json, sys; r = json.load(open("a_report.json")); sys.exit(r["nsga2_evaluations"] != 48)' \
  && ok "--population 10 --generations 3: 48 NSGA-II evaluations" \
  || fail "--population: $($py -c 'import json; print(json.load(open("a_report.json"))["nsga2_evaluations"])')"
# Polishing adds Ceres-refined front members (origin nsga2+ceres); --no-polish adds none.
expect_ok "grade --no-polish" "$bin" grade "$fs" "${quick[@]}" --out np.json --report np_report.json --no-polish
$py - <<'PY' && ok "--no-polish: no polished candidates, polishing otherwise" || fail "--no-polish"
import json
a = [p["origin"] for p in json.load(open("a_report.json"))["front"]]
n = json.load(open("np_report.json"))
assert "nsga2+ceres" in a, a
assert "nsga2+ceres" not in [p["origin"] for p in n["front"]] and n["timings_s"]["polish"] == 0, n["front"]
PY
# Without the FreeSewing point-name bindings only the importer's bindings and seams are graded.
expect_ok "grade --no-freesewing-bindings" "$bin" grade "$fs" "${quick[@]}" --out nb.json \
  --report nb_report.json --no-freesewing-bindings
$py - <<'PY' && ok "--no-freesewing-bindings: fewer seams, fewer bindings" || fail "--no-freesewing-bindings"
import json
a, n = json.load(open("a_report.json")), json.load(open("nb_report.json"))
# The importer's own seams (pattern data) stay; the point-name table's multi-piece seams go.
sa, sn = {s["name"] for s in a["seams"]}, {s["name"] for s in n["seams"]}
assert sn < sa, (sa, sn)
fa, fn = {f["measurement"] for f in a["fit"]}, {f["measurement"] for f in n["fit"]}
assert fn < fa, (fa, fn)
PY
# --format: naming the format the file has gives the same result as recognising it.
expect_ok "grade --format freesewing" "$bin" grade "$fs" "${quick[@]}" --out fmt.json --format freesewing
cmp -s fmt.json a.json && ok "--format freesewing = recognised format" || fail "--format freesewing changed the result"
expect_fail "grade --format garmentcode on a FreeSewing file" "$(basename "$fs")" "$bin" grade "$fs" \
  "${quick[@]}" --out x.json --format garmentcode
# --store / --db / --replace: the graded pattern goes into the database, a second store needs
# --replace, and what is stored is what was written.
expect_ok "grade --store --db" "$bin" grade "$fs" "${quick[@]}" --out st.json --store --db g.sqlite
name=$($py -c 'import json; print(json.load(open("st.json"))["name"])')
expect_ok "stored graded pattern listed" "$bin" pattern list --db g.sqlite
grep -q "^$name" out.txt && ok "database lists the graded pattern '$name'" || fail "not stored: $(cat out.txt)"
expect_fail "grade --store twice" "is already stored" "$bin" grade "$fs" "${quick[@]}" --out st2.json --store --db g.sqlite
expect_ok "grade --store --replace" "$bin" grade "$fs" "${quick[@]}" --out st3.json --store --replace --db g.sqlite
expect_ok "export the stored pattern" "$bin" pattern export "$name" --db g.sqlite --json st_db.json
$py - <<'PY' && ok "stored pattern = written pattern" || fail "stored pattern differs"
import json
a, b = json.load(open("st3.json")), json.load(open("st_db.json"))
def numbers(o):
    if isinstance(o, dict): return [x for k in sorted(o) for x in numbers(o[k])]
    if isinstance(o, list): return [x for v in o for x in numbers(v)]
    return [o] if isinstance(o, (int, float)) and not isinstance(o, bool) else []
na, nb = numbers([p["outline"] for p in a["pieces"]]), numbers([p["outline"] for p in b["pieces"]])
# The database keeps coordinates on a 0.001 mm grid: stored = written within half a step.
assert len(na) == len(nb) > 0 and all(abs(x - y) <= 0.0005 + 1e-9 * (1 + abs(x)) for x, y in zip(na, nb))
PY
expect_ok "grade a pattern by its name in the database" "$bin" grade "$name" --db g.sqlite \
  --from target42.json --to target42.json --threads 2 --generations 0 --out same.json --report same_report.json
$py -c 'import json, sys; r = json.load(open("same_report.json")); sys.exit(not all(abs(f["error_mm"]) < 2 for f in r["fit"]))' \
  && ok "graded from the database: bindings within 2 mm" || fail "grade from the database"
# --compare against a reference that is the base scaled by 1.05 about the origin: the uniform
# oracle (each base piece scaled by the perimeter ratio) is the reference itself, so its
# deviation is the outline sampling's (< 0.01 mm); the unchanged base is 5 % off.
expect_ok "export the base as tapeline JSON" "$bin" pattern export "$fs" --json base.json
$py - <<'PY'
import json
j = json.load(open("base.json")); s = 1.05
def sc(p): return [s * p[0], s * p[1]]
for piece in j["pieces"]:
    for e in piece["outline"]:
        for k in ("a", "b"):
            if k in e: e[k] = sc(e[k])
        if "p" in e: e["p"] = [sc(q) for q in e["p"]]
        if "radius" in e: e["radius"] *= s
j["name"] = "reference"
json.dump(j, open("ref105.json", "w"))
PY
expect_ok "grade --compare" "$bin" grade "$fs" "${quick[@]}" --out c.json --report c_report.json --compare ref105.json
$py - <<'PY' && ok "--compare: uniform oracle 0 on a scaled reference, unchanged base 5 % off" || fail "--compare: $(head -c 300 c_report.json)"
import json
r = json.load(open("c_report.json"))
c = r["comparison"]
names = {p["name"] for p in json.load(open("base.json"))["pieces"]}
assert {p["piece"] for p in c} == names, c
for p in c:
    assert p["uniform_oracle_mean_mm"] < 0.01 and p["uniform_oracle_max_mm"] < 0.01, p
    assert p["unchanged_mean_mm"] > 1.0, p
    assert p["graded_mean_mm"] > 0, p
PY
fi

# --- geodesic and mesh options ----------------------------------------------------------------
if in_section geodesic_options; then
make_ico
# --surface builds the same mesh `mesh generate` writes: the same exact distances.
expect_ok "distances on --surface icosphere:3" "$bin" geodesic distances --surface icosphere:3 --source 0 --out surf.txt
if paste surf.txt ico_exact.txt | awk '{ e = $1 - $2; if (e < 0) e = -e; if (e > 1e-6 * ($2 + 1)) bad++; n++ }
     END { exit !(n == 642 && bad == 0) }'; then ok "--surface = the generated file"; else fail "--surface differs from the generated file"; fi
expect_ok "path on --surface" "$bin" geodesic path --surface icosphere:3 --from 0 --to 300 --out sp.json
$py -c 'import json, sys; w = float(open("ico_exact.txt").read().split()[300]); L = json.load(open("sp.json"))["length"]; sys.exit(abs(L - w) > 1e-6 * w)' \
  && ok "--surface path length = exact distance" || fail "--surface path length"
expect_fail "a file and --surface" "surface|excludes" "$bin" geodesic distances ico.off --surface icosphere:3 --source 0 --out x.txt
expect_fail "neither a file nor --surface" "give a mesh file or --surface SPEC" "$bin" geodesic distances --source 0 --out x.txt
# --strict: a quad is triangulated (with a warning) unless --strict, which rejects it by name.
printf 'OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n' > quad.off
expect_ok "a quad without --strict" "$bin" geodesic distances quad.off --source 0 --out q.txt
$py -c 'import math, sys; d = [float(x) for x in open("q.txt")]; sys.exit(not (len(d) == 4 and abs(d[2] - math.sqrt(2)) < 1e-9 and abs(d[1] - 1) < 1e-9))' \
  && ok "triangulated quad: flat distances" || fail "quad distances: $(cat q.txt)"
expect_fail "a quad with --strict" "quad.off.*4 vertices; strict mode accepts triangles only" "$bin" geodesic distances quad.off --strict --source 0 --out x.txt
[ ! -e x.txt ] && ok "rejected runs wrote nothing" || fail "a rejected run wrote x.txt"
# mesh generate --seed: the jitter follows the seed (default 1).
expect_ok "generate with the default seed" "$bin" mesh generate ellipsoid:1,1,0.5:2:0.2 --out e_default.off
expect_ok "generate --seed 1" "$bin" mesh generate ellipsoid:1,1,0.5:2:0.2 --seed 1 --out e1.off
expect_ok "generate --seed 2" "$bin" mesh generate ellipsoid:1,1,0.5:2:0.2 --seed 2 --out e2.off
expect_ok "generate --seed 2 again" "$bin" mesh generate ellipsoid:1,1,0.5:2:0.2 --seed 2 --out e2b.off
if cmp -s e_default.off e1.off && cmp -s e2.off e2b.off && ! cmp -s e1.off e2.off &&
   [ "$(sed -n 2p e1.off)" = "$(sed -n 2p e2.off)" ]; then ok "--seed: same seed same mesh, another seed another jitter"
else fail "--seed"; fi
fi

# --- bench options ----------------------------------------------------------------------------
if in_section bench_options; then
# --mesh: a file's lines name it; --reference none leaves the errors null.
expect_ok "bench --mesh --reference none" "$bin" bench geodesic --mesh "$spot" --methods dijkstra \
  --reference none --out m.jsonl
$py - "$spot" <<'PY' && ok "bench --mesh lines: the file, 2930 vertices, no reference errors" || fail "bench --mesh: $(head -c 300 m.jsonl)"
import json, sys
lines = [json.loads(l) for l in open("m.jsonl")]
assert lines and all(l["method"] == "dijkstra" for l in lines), lines
for l in lines:
    assert l["mesh_file"].endswith("spot.obj") and l["vertices"] == 2930 and l["status"] == "ok", l
    assert l["mean_rel_error"] is None and l["max_rel_error"] is None, l
PY
# --append adds to the file; without it the file is replaced.
one=$(wc -l <m.jsonl)
expect_ok "bench --append" "$bin" bench geodesic --mesh "$spot" --methods dijkstra --reference none --append --out m.jsonl
[ "$(wc -l <m.jsonl)" -eq $((2 * one)) ] && ok "--append: twice the lines" || fail "--append: $(wc -l <m.jsonl) lines, one run $one"
expect_ok "bench without --append" "$bin" bench geodesic --mesh "$spot" --methods dijkstra --reference none --out m.jsonl
[ "$(wc -l <m.jsonl)" -eq "$one" ] && ok "without --append the file is replaced" || fail "replace: $(wc -l <m.jsonl) lines"
# --timeout: a run that takes longer is killed and recorded as `timeout`; the next method runs.
# (exact-cgal needs ~10 s on icosphere:6, Dijkstra a few ms.)
expect_ok "bench --timeout" "$bin" bench geodesic --surface icosphere:6 --methods exact-cgal,dijkstra \
  --reference none --sources 1 --timeout 2 --out t.jsonl
$py - <<'PY' && ok "--timeout: timeout recorded, next method ran" || fail "--timeout: $(head -c 400 t.jsonl)"
import json
lines = {l["method"]: l for l in map(json.loads, open("t.jsonl"))}
assert lines["exact-cgal"]["status"] == "timeout", lines["exact-cgal"]
assert "killed after" in lines["exact-cgal"]["message"], lines["exact-cgal"]
assert lines["dijkstra"]["status"] == "ok", lines["dijkstra"]
PY
fi

# --- version and progress ------------------------------------------------------------------------
if in_section version; then
# --version: the CMake project version and the git revision, on stdout, exit 0.
want_version=$(sed -n 's/^project(tapeline VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")
if "$bin" --version >out.txt 2>err.txt && [ -n "$want_version" ] &&
   grep -qE "^tapeline $want_version \(git [0-9a-f]{7,}(-dirty)?\)$|^tapeline $want_version \(git unknown\)$" out.txt
then ok "--version prints version $want_version and the git revision"
else fail "--version: $(head -c 200 out.txt) $(head -c 200 err.txt)"; fi
# stderr is a pipe here: progress lines only with --progress, none with --quiet or by default.
prog_bench() { "$bin" "$@" bench geodesic --surface icosphere:2 --methods dijkstra,heat \
  --reference none --sources 2 --out prog.jsonl >out.txt 2>err.txt; }
if prog_bench --progress && grep -qE '^bench geodesic: [0-9]+/4 ' err.txt &&
   grep -qE '^bench geodesic: 4/4 .* done$' err.txt && [ "$(wc -l <prog.jsonl)" -eq 4 ]
then ok "--progress writes progress lines to a pipe"
else fail "--progress: $(head -c 300 err.txt)"; fi
if prog_bench --quiet && [ ! -s err.txt ] && [ "$(wc -l <prog.jsonl)" -eq 4 ]
then ok "--quiet writes no progress"; else fail "--quiet: $(head -c 300 err.txt)"; fi
if prog_bench && ! grep -q 'bench geodesic:' err.txt
then ok "no progress on a pipe by default"; else fail "default progress: $(head -c 300 err.txt)"; fi
expect_fail "--quiet and --progress together" "excludes" "$bin" --quiet --progress bench geodesic \
  --surface icosphere:1 --out prog2.jsonl
fi

# --- dress ---------------------------------------------------------------------------------------
# Refusals name what is wrong and write nothing; the placement-only run writes every output and its
# report agrees with the files (vertex count, openings).
if in_section dress; then
body="$root/data/bodies/mh_female_average.obj"
hoody="$root/../shared/data/patterns/garmentcode/hoody_mean_specification.json"
expect_fail "dress: unknown fabric" "unknown fabric 'tweed'" "$bin" dress "$body" --units dm "$gc" \
  --out x.obj --fabric tweed
expect_fail "dress: --out not an OBJ" "expected an .obj" "$bin" dress "$body" --units dm "$gc" --out x.stl
expect_fail "dress: unknown piece to leave out" "no piece 'collar'" "$bin" dress "$body" --units dm "$gc" \
  --out x.obj --without collar
expect_fail "dress: resolution out of range" "resolution" "$bin" dress "$body" --units dm "$gc" \
  --out x.obj --resolution 0.5
expect_fail "dress: bindings have no region" "piece 'aaron.armBinding' has no body region" \
  "$bin" dress "$body" --units dm "$fs" --out x.obj
if [ -f "$hoody" ]; then
  expect_fail "dress: a hood has no region" "piece 'left_hood' has no body region" \
    "$bin" dress "$body" --units dm "$hoody" --out x.obj
fi
# Trousers: the body measures titan's waistToKnee, so titan grades to it (--to-body); its front and
# back (one leg, drafted once) are paired with their mirror images, sewn at the crotch and placed
# on their legs (placement and strings only here: the drape is the benchmark's).
titan="$root/../shared/data/patterns/freesewing/titan_cisFemaleAdult36.json"
if [ -f "$titan" ]; then
  expect_ok "dress: titan graded and placed on the legs" "$bin" dress "$body" --units dm "$titan" \
    --to-body --from "$root/../shared/data/patterns/freesewing/measurement_sets.json" \
    --from-set cisFemaleAdult36 --resolution 30 --sew-seconds 0 --settle-seconds 0 --no-relax \
    --out titan.obj --report titan.json
  python3 - titan.json <<'PY' && ok "dress: titan's four legs pieces on their legs, crotch seams sewn" \
    || fail "dress: titan's report"
import json, sys
r = json.load(open(sys.argv[1]))
regions = {p["name"]: p["region"] for p in r["pieces"]}
assert regions == {"titan.front": "leg_right_front", "titan.back": "leg_right_back",
                   "titan.front (mirror)": "leg_left_front",
                   "titan.back (mirror)": "leg_left_back"}, regions
seams = {s["name"]: s for s in r["seams"]}
for name in ("crotch front", "crotch back", "inseam (mirror)", "outseam (mirror)"):
    assert seams[name]["pairs"] > 0 and seams[name]["closable"], name
assert r["placement"]["vertices_inside_body"] == 0 and r["placement"]["piece_crossings"] == 0
# four waist edges (front, back and their mirror images), each a few steps long
assert r["mesh"]["waistband_vertices"] >= 4 * 3, r["mesh"]["waistband_vertices"]
PY
  # The waist is held unless --no-waistband says otherwise (placement only, ungraded).
  expect_ok "dress: titan with --no-waistband" "$bin" dress "$body" --units dm "$titan" \
    --resolution 30 --sew-seconds 0 --settle-seconds 0 --no-relax --no-waistband \
    --out titan.obj --report titan.json
  python3 -c 'import json, sys; r = json.load(open(sys.argv[1])); assert r["mesh"]["waistband_vertices"] == 0' \
    titan.json && ok "dress: --no-waistband holds no vertex" || fail "dress: --no-waistband"
fi
expect_fail "dress: missing body" "nope.obj" "$bin" dress nope.obj --units dm "$gc" --out x.obj
expect_fail "dress: --waistband-sag 0" "waistband-sag must be a number of mm > 0" "$bin" dress "$body" \
  --units dm "$gc" --out x.obj --waistband-sag 0
expect_fail "dress: --waistband-sag nan" "waistband-sag: .nan. is not a finite number" "$bin" dress \
  "$body" --units dm "$gc" --out x.obj --waistband-sag nan
expect_fail "dress: --fold-cycles 0" "fold-cycles" "$bin" dress "$body" --units dm "$gc" --out x.obj \
  --fold-cycles 0
expect_fail "dress: --relax-settle -1" "relax-settle" "$bin" dress "$body" --units dm "$gc" --out x.obj \
  --relax-settle -1
expect_fail "dress: --relax-again-releases -1" "relax-again-releases" "$bin" dress "$body" --units dm \
  "$gc" --out x.obj --relax-again-releases -1
expect_fail "dress: --relax-again-friction -1" "relax-again-friction" "$bin" dress "$body" --units dm \
  "$gc" --out x.obj --relax-again-friction -1
expect_fail "dress: --relax-tolerance 0" "relax-tolerance must be a number of mm > 0" "$bin" dress \
  "$body" --units dm "$gc" --out x.obj --relax-tolerance 0
expect_fail "dress: --relax-tolerance inf" "relax-tolerance: .inf. is not a finite number" "$bin" \
  dress "$body" --units dm "$gc" --out x.obj --relax-tolerance inf
expect_fail "dress: --relax-settle-fraction 2" "relax-settle-fraction" "$bin" dress "$body" --units dm \
  "$gc" --out x.obj --relax-settle-fraction 2
expect_fail "dress: --fold-rounds -1" "fold-rounds" "$bin" dress "$body" --units dm "$gc" --out x.obj \
  --fold-rounds -1
expect_fail "dress: --fold-sweeps 0" "fold-sweeps" "$bin" dress "$body" --units dm "$gc" --out x.obj \
  --fold-sweeps 0
expect_fail "dress: --sdf-cell 0" "--sdf-cell must be a finite number of mm > 0" "$bin" dress "$body" \
  --units dm "$gc" --out x.obj --sdf-cell 0
if ls x.obj x.*.tmp* >/dev/null 2>&1; then fail "dress: a refusal left a file"; else ok "dress: refusals write nothing"; fi
expect_ok "dress: placement only" "$bin" dress "$body" --units dm "$gc" --resolution 30 \
  --sew-seconds 0 --settle-seconds 0 --out placed.obj --ply placed.ply --report placed.json \
  --picture placed.png --edge-edge --sdf-cell 7 --no-body-points --relax-settle 0 \
  --relax-iterations 90 --relax-again-friction 3 --relax-again-releases 12
if $py - <<'PY'
import json
r = json.load(open("placed.json"))
assert r["options"]["edge_edge_collision"] is True and r["options"]["sdf_cell_mm"] == 7, r["options"]
assert r["options"]["body_points"] is False and r["simulation"]["static_solve"]["body_point_contacts"] == 0, r
assert r["options"]["static_solve_settle"] == 0 and r["options"]["static_solve_iterations"] == 90, r["options"]
assert r["options"]["static_solve_releases"] == 45 and r["options"]["static_solve_again_releases"] == 12, r["options"]
assert r["options"]["static_solve_friction_from"] == 30 and r["options"]["static_solve_again_friction_from"] == 3, r["options"]
assert r["simulation"]["static_solve_each"] == [], r["simulation"]
# placement only: nothing sewn or draped, so nothing flattened or solved
assert r["simulation"]["fold_smoothing"] == [] and r["simulation"]["static_solves"] == 0, r["simulation"]
q = r["quality"]  # the self-intersections located and split by pieces, as many as counted
assert len(q["self_crossings_canonical_mm"]) == min(100, q["self_intersections"]), q
assert sum(q["self_crossings_by_pieces"].values()) == q["self_intersections"], q
v = sum(1 for l in open("placed.obj") if l.startswith("v "))
f = sum(1 for l in open("placed.obj") if l.startswith("f "))
assert r["placement"]["vertices_inside_body"] == 0, r["placement"]
assert v == r["mesh"]["garment_vertices"] == r["mesh"]["cloth_vertices"], (v, r["mesh"])
assert f == r["mesh"]["cloth_triangles"], (f, r["mesh"])
assert r["mesh"]["boundary_loops"] == len(r["pieces"]) == 8, r["mesh"]  # unsewn: one per piece
assert open("placed.png", "rb").read(8) == b"\x89PNG\r\n\x1a\n"
PY
then ok "dress: placement report agrees with the files"; else fail "dress: placement report"; fi
# --to-body: measure, grade, dress in one command. The bundled body's bust (845 mm) is far below
# the base set's chest (979 mm), so the graded tank top is placed narrower than the base one.
fsm="$root/data/patterns/aaron_cisFemaleAdult36_measurements.json"
expect_fail "dress: --to-body without --from" "needs what the pattern was made for" "$bin" dress "$body" --units dm "$fs" \
  --out x.obj --to-body
expect_fail "dress: --to-body with --from and --base-body" "one of them" "$bin" dress "$body" --units dm "$fs" \
  --out x.obj --to-body --from "$fsm" --base-body "$body"
expect_fail "dress: --from without --to-body" "are for --to-body" "$bin" dress "$body" --units dm "$fs" \
  --out x.obj --from "$fsm"
expect_fail "dress: --to-body with a missing base set" "nope.json" "$bin" dress "$body" --units dm "$fs" \
  --out x.obj --to-body --from nope.json
if ls x.obj x.*.tmp* >/dev/null 2>&1; then fail "dress: a --to-body refusal left a file"; else ok "dress: --to-body refusals write nothing"; fi
# A pattern without bindings (GarmentCode) dressed on a body 8 % wider than the one it was made for:
# its girths found on the base body, graded to the wider one, placed.
$py - "$body" <<'PY'
import sys
with open("wide.obj", "w") as out:
    for line in open(sys.argv[1]):
        w = line.split()
        if w and w[0] == "v":
            line = "v %.6f %s %.6f\n" % (1.08 * float(w[1]), w[2], 1.08 * float(w[3]))
        out.write(line)
PY
gcs="$root/data/patterns/shirt_mean_specification.json"
"$bin" dress wide.obj --units dm "$gcs" --to-body --base-body "$body" --base-units dm \
  --resolution 30 --sew-seconds 0 --settle-seconds 0 --out wide_shirt.obj >out.txt 2>err.txt; rc=$?
if [ $rc -eq 0 ] && [ -s wide_shirt.obj ] && grep -q "binding: bust_girth: .*ease" err.txt &&
   grep -q "grading: graded shirt_mean.* from mh_female_average to wide" err.txt
then ok "dress: --to-body --base-body grades a pattern without bindings to the body"
else fail "dress: --base-body (exit $rc): $(head -c 400 err.txt)"; fi
# The same base body lying down (Z up, front -Y; its unit inferred): the same bindings are found.
$py - "$body" <<'PY'
import sys
with open("lying.obj", "w") as out:
    for line in open(sys.argv[1]):
        w = line.split()
        if w and w[0] == "v":
            line = "v %s %.6f %s\n" % (w[1], -float(w[3]), w[2])
        out.write(line)
PY
"$bin" dress wide.obj --units dm "$gcs" --to-body --base-body lying.obj --base-up +Z \
  --base-front -Y --resolution 30 --sew-seconds 0 --settle-seconds 0 --out lying_shirt.obj \
  >out.txt 2>err_lying.txt; rc=$?
if [ $rc -eq 0 ] && [ "$(grep '^tapeline: binding:' err.txt)" = "$(grep '^tapeline: binding:' err_lying.txt)" ] &&
   [ "$(grep -c '^tapeline: binding:' err.txt)" -ge 4 ]
then ok "dress: --base-up/--base-front: a lying base body gives the same bindings"
else fail "dress: --base-up/--base-front (exit $rc): $(diff <(grep binding: err.txt) <(grep binding: err_lying.txt) | head -c 400)"; fi
expect_fail "dress: --base-up without --base-body" "describe --base-body" "$bin" dress "$body" --units dm "$gcs" \
  --base-up +Z --out x.obj
expect_fail "grade: --base-units without --base-body" "describe --base-body" "$bin" grade "$gcs" \
  --from "$fsm" --to "$fsm" --base-units dm --out x.json
place_fs() {
  "$bin" dress "$body" --units dm "$fs" --without aaron.armBinding --without aaron.neckBinding \
    --resolution 30 --sew-seconds 0 --settle-seconds 0 "$@" 2>tb_err.txt
}
if place_fs --out base.obj && place_fs --out graded.obj --to-body --from "$fsm" --seed 3 &&
   grep -q "graded .* from aaron_cisFemaleAdult36_measurements" tb_err.txt && $py - <<'PY'
def width(path):
    xs = [float(l.split()[1]) for l in open(path) if l.startswith("v ")]
    return max(xs) - min(xs)
assert width("graded.obj") < 0.95 * width("base.obj"), (width("graded.obj"), width("base.obj"))
PY
then ok "dress --to-body grades the pattern to the body first"; else fail "dress --to-body: $(tail -c 300 tb_err.txt)"; fi
# --wrinkles: a database of the dress fabric (a panel with a 40 mm wave) read before the drape,
# the wrinkles added after it; the garment without them is written with --coarse-out.
panel="$root/tests/cli/wrinkle_panel.py"
$py "$panel" wp.obj 15 20 && $py "$panel" wp_fine.obj 100 3 --wavelength 40
expect_ok "dress: a wrinkle database" "$bin" wrinkles train wp.obj wp_fine.obj --units mm --out wdb.json
expect_fail "dress: --wrinkles not a database" "placed.json: not a wrinkle database" "$bin" dress "$body" \
  --units dm "$gc" --out x.obj --wrinkles placed.json
expect_fail "dress: --wrinkles of another fabric" "a wrinkle database of fabric 'cotton_jersey', the garment is of 'denim'" \
  "$bin" dress "$body" --units dm "$gc" --out x.obj --wrinkles wdb.json --fabric denim
expect_fail "dress: --coarse-out without --wrinkles" "is for --wrinkles" "$bin" dress "$body" --units dm "$gc" \
  --out x.obj --coarse-out y.obj
if place_fs --out wr.obj --wrinkles wdb.json --coarse-out wr_coarse.obj --report wr.json &&
   grep -q "wrinkles from wdb.json" tb_err.txt && $py - <<'PY'
import json
f = lambda p: sum(1 for l in open(p) if l.startswith("f "))
assert f("wr.obj") == 16 * f("wr_coarse.obj"), (f("wr.obj"), f("wr_coarse.obj"))
w = json.load(open("wr.json"))["wrinkles"]
assert w["fine_triangles"] == f("wr.obj"), w
assert w["body_checked"] and w["new_body_contacts_left"] == 0, w
q = w["quality"]
assert q["after"]["vertices_inside_body"] <= q["before"]["vertices_inside_body"], q
PY
then ok "dress --wrinkles writes the wrinkled garment and the one without"; else fail "dress --wrinkles: $(tail -c 400 tb_err.txt)"; fi
if ls x.obj y.obj >/dev/null 2>&1; then fail "dress: a --wrinkles refusal left a file"; else ok "dress: --wrinkles refusals write nothing"; fi
fi

# --- batch ---------------------------------------------------------------------------------------
# A manifest of jobs run restartably: refusals name the file and line and write nothing; a run
# records every job in its results database and the measure step writes what `tapeline measure`
# writes; --resume skips done jobs and retries failed ones; a job whose process is killed goes back
# to the queue of the same run; a run killed mid-job (locally, or one MPI rank) and resumed gives
# the outputs of an uninterrupted run, every job done once.
if in_section batch; then
body="$root/data/bodies/mh_female_average.obj"
fsm="$root/data/patterns/aaron_cisFemaleAdult36_measurements.json"
printf '{"body": "%s", "units": "dm", "steps": ["measure"]}\n{"body": x}\n' "$body" >bad1.jsonl
expect_fail "batch: a line that is not JSON" "bad1.jsonl:2: not a JSON object" "$bin" batch bad1.jsonl --out res
printf '{"body": "%s", "unit": "dm"}\n' "$body" >bad2.jsonl
expect_fail "batch: an unknown key" "bad2.jsonl:1: unknown key 'unit'" "$bin" batch bad2.jsonl --out res
printf '{"units": "dm", "steps": ["measure"]}\n' >bad3.jsonl
expect_fail "batch: no body" "bad3.jsonl:1: missing 'body'" "$bin" batch bad3.jsonl --out res
printf '{"body": "%s", "steps": ["measure", "wash"]}\n' "$body" >bad4.jsonl
expect_fail "batch: an unknown step" "bad4.jsonl:1: unknown step \"wash\"" "$bin" batch bad4.jsonl --out res
printf '{"body": "%s", "pattern": "%s"}\n' "$body" "$fs" >bad5.jsonl
expect_fail "batch: grading without the base set" "bad5.jsonl:1: the grade step needs 'from'" "$bin" batch bad5.jsonl --out res
printf '{"body": "%s", "pattern": "%s", "steps": ["dress"], "options": {"resolution": 30}}\n' "$body" "$fs" >bad6.jsonl
expect_fail "batch: an unknown option" "bad6.jsonl:1: unknown option 'resolution'" "$bin" batch bad6.jsonl --out res
printf '{"body": "%s", "pattern": "%s", "steps": ["dress"], "options": {"threads": -2}}\n' "$body" "$fs" >bad7.jsonl
expect_fail "batch: an option of the wrong type" "bad7.jsonl:1: option 'threads' has the wrong type" "$bin" batch bad7.jsonl --out res
printf '{"bodies": "%s/nothing_*.obj", "steps": ["measure"]}\n' "$root" >bad8.jsonl
expect_fail "batch: a glob that matches nothing" "bad8.jsonl:1: 'bodies' .* matches no file" "$bin" batch bad8.jsonl --out res
printf '{"body": "%s", "pattern": "%s", "steps": ["dress"], "fabric": "tweed"}\n' "$body" "$fs" >bad9.jsonl
expect_fail "batch: an unknown fabric" "unknown fabric 'tweed'" "$bin" batch bad9.jsonl --out res
printf '{"body": "%s", "units": "furlong", "steps": ["measure"]}\n' "$body" >bad10.jsonl
expect_fail "batch: an unknown unit" "bad10.jsonl:1: units" "$bin" batch bad10.jsonl --out res
expect_fail "batch: a missing manifest" "nope.jsonl: cannot open" "$bin" batch nope.jsonl --out res
expect_fail "batch: a negative job time-out" "--job-timeout and --job-memory must be >= 0" "$bin" batch bad3.jsonl --out res --job-timeout -1
if [ -e res ]; then fail "batch: a refusal left the results folder"; else ok "batch: refusals write nothing"; fi

# Two measure jobs, one measure-grade-dress job (placement only), one job on a missing body.
cat >jobs.jsonl <<J
# the bundled body measured twice, dressed once; a body that does not exist
{"id": "m1", "body": "$body", "units": "dm", "steps": ["measure"]}
{"id": "m2", "body": "$body", "units": "dm", "steps": ["measure"]}
{"body": "$body", "units": "dm", "pattern": "$fs", "from": "$fsm", "options": {"resolution_mm": 30, "sew_seconds": 0, "settle_seconds": 0, "without": ["aaron.armBinding", "aaron.neckBinding"], "threads": 1, "population": 16, "generations": 4}}
{"id": "lost", "body": "$root/data/bodies/nobody.obj", "units": "dm", "steps": ["measure"]}
J
"$bin" batch jobs.jsonl --out res >out.txt 2>err.txt; rc=$?
if [ $rc -eq 1 ] && grep -q "3 of 4 jobs done, 1 failed (first: lost: .*nobody.obj" out.txt; then ok "batch: a failed job fails the run, others done"
else fail "batch: run (exit $rc): $(head -c 300 out.txt) $(head -c 300 err.txt)"; fi
expect_ok "measure the same body" "$bin" measure "$body" --units dm --out m.json
if $py - "$root" <<'PY'
import json, sqlite3, sys
def strip(x):
    if isinstance(x, dict):
        return {k: strip(v) for k, v in x.items() if "seconds" not in k}
    if isinstance(x, list):
        return [strip(v) for v in x]
    return x
ref = strip(json.load(open("m.json")))
for job in ["m1", "m2", "mh_female_average__aaron_cisFemaleAdult36"]:
    assert strip(json.load(open(f"res/jobs/{job}/measure.json"))) == ref, job
for f in ["graded.json", "grade.json", "dressed.obj", "dress.json"]:
    assert open(f"res/jobs/mh_female_average__aaron_cisFemaleAdult36/{f}").read(1), f
rows = sqlite3.connect("res/batch.sqlite").execute(
    "select id, status, attempts, error from jobs order by idx").fetchall()
assert [r[:3] for r in rows] == [("m1", "done", 1), ("m2", "done", 1),
                                 ("mh_female_average__aaron_cisFemaleAdult36", "done", 1),
                                 ("lost", "failed", 1)], rows
assert "nobody.obj" in rows[3][3], rows[3]
s = json.load(open("res/summary.json"))
assert s["counts"] == {"done": 3, "failed": 1}, s["counts"]
assert s["failures"][0]["jobs"] == ["lost"], s["failures"]
m = s["jobs"][0]["outcome"]["measurements"]
assert m["waist_girth"] == next(x["value_mm"] for x in ref["measurements"] if x["name"] == "waist_girth")
assert "| lost | failed |" in open("res/summary.md").read()
PY
then ok "batch: measure.json as tapeline measure, statuses, summary"; else fail "batch: outputs"; fi
expect_fail "batch: the results folder holds a batch" "holds a batch already" "$bin" batch jobs.jsonl --out res
sed 's/"m2"/"m3"/' jobs.jsonl >changed.jsonl
expect_fail "batch: --resume with another manifest" "differs from job 'm2'" "$bin" batch changed.jsonl --out res --resume
stamp=$(stat -c %Y res/jobs/m1/measure.json)
"$bin" batch jobs.jsonl --out res --resume --retries 0 >out.txt 2>err.txt; rc=$?
"$bin" batch jobs.jsonl --out res --resume >out2.txt 2>err2.txt; rc2=$?
if [ $rc -eq 1 ] && [ $rc2 -eq 1 ] && grep -q "0 jobs to run" err.txt && grep -q "1 jobs to run" err2.txt &&
   grep -q "(3 by an earlier run)" out2.txt && [ "$(stat -c %Y res/jobs/m1/measure.json)" = "$stamp" ] &&
   [ "$($py -c 'import sqlite3; print(sqlite3.connect("res/batch.sqlite").execute("select attempts from jobs where id=\"lost\"").fetchone()[0])')" = 2 ]
then ok "batch: --resume skips done jobs, retries failed ones up to --retries"
else fail "batch: resume (exit $rc $rc2): $(head -c 300 err.txt) $(head -c 300 err2.txt)"; fi

printf '{"id": "m", "body": "%s", "units": "dm", "steps": ["measure"]}\n' "$body" >one.jsonl
expect_ok "batch: --resume on a folder without a batch" "$bin" batch one.jsonl --out fresh --resume
if [ -s fresh/jobs/m/measure.json ]; then ok "batch: --resume on a new folder starts the batch"
else fail "batch: --resume on a new folder"; fi

# Six dressing jobs (a tenth of a second of sewing, no static solve, one thread each, the body's
# distance grid at 12 mm): uninterrupted, killed and resumed, over MPI.
: >six.jsonl
for k in 1 2 3 4 5 6; do
  printf '{"id": "d%s", "body": "%s", "units": "dm", "pattern": "%s", "steps": ["dress"], "options": {"resolution_mm": %s, "sew_seconds": 0.1, "settle_seconds": 0, "relax": false, "sdf_cell_mm": 12, "without": ["aaron.armBinding", "aaron.neckBinding"], "threads": 1}}\n' \
    $k "$body" "$fs" $((26 + k)) >>six.jsonl
done
same_outputs() {  # same_outputs DIR: every job's files equal those of the uninterrupted run
  $py - "$1" <<'PY'
import json, sqlite3, sys
def strip(x):
    if isinstance(x, dict):
        # wall times differ from run to run; everything else must not
        return {k: strip(v) for k, v in x.items() if "seconds" not in k and not k.startswith("ms_per")}
    if isinstance(x, list):
        return [strip(v) for v in x]
    return x
d = sys.argv[1]
for k in range(1, 7):
    assert open(f"{d}/jobs/d{k}/dressed.obj").read() == open(f"full/jobs/d{k}/dressed.obj").read(), k
    assert strip(json.load(open(f"{d}/jobs/d{k}/dress.json"))) == strip(json.load(open(f"full/jobs/d{k}/dress.json"))), k
rows = sqlite3.connect(f"{d}/batch.sqlite").execute("select status from jobs").fetchall()
assert rows == [("done",)] * 6, rows
import os
assert sorted(os.listdir(f"{d}/jobs")) == [f"d{k}" for k in range(1, 7)], os.listdir(f"{d}/jobs")
PY
}
expect_ok "batch: six dressing jobs" "$bin" batch six.jsonl --out full
if $py - <<'PY'
import json, struct
s = json.load(open("full/summary.json"))
assert s["run"]["jobs_run"] == 6 and s["run"]["ranks"] == 1, s["run"]
assert all(j["outcome"]["dress"]["garment_vertices"] > 0 for j in s["jobs"]), s["jobs"]
d1 = json.load(open("full/jobs/d1/dress.json"))  # "relax": false reached the dressing
assert d1["options"]["static_solve"] is False and not d1["simulation"]["static_solve"]["ran"], d1
assert d1["options"]["sdf_cell_mm"] == 12, d1["options"]  # and so did the grid's cell
sheet = open("full/contact_sheet.png", "rb").read()
assert sheet[:8] == bytes([0x89]) + b"PNG" + bytes([13, 10, 26, 10])
w, h = struct.unpack(">II", sheet[16:24])
sizes = [struct.unpack(">II", open(f"full/jobs/d{k}/thumb.png", "rb").read()[16:24])
         for k in range(1, 7)]
tw, th = max(x[0] for x in sizes), max(x[1] for x in sizes)
assert (w, h) == (4 * tw, 2 * th), (w, h, sizes)  # six thumbnails, four to a row
PY
then ok "batch: summary of the run and its contact sheet"; else fail "batch: contact sheet"; fi
# Killed with SIGKILL once two jobs are done (the third under way), then resumed.
"$bin" batch six.jsonl --out killed >/dev/null 2>&1 &
pid=$!
for _ in $(seq 1 600); do
  [ "$(ls killed/jobs 2>/dev/null | grep -c '^d')" -ge 2 ] && break; sleep 0.05
done
kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
before=$(ls killed/jobs | grep -c '^d')
if [ "$before" -lt 6 ] && "$bin" batch six.jsonl --out killed --resume >out.txt 2>err.txt && same_outputs killed
then ok "batch: killed after $before jobs and resumed: the outputs of an uninterrupted run"
else fail "batch: kill and resume ($before jobs before): $(head -c 300 err.txt)"; fi
# The process of the third job killed: the job goes back to the queue and is run again in the same
# run (two attempts); with --retries 0 it has failed, and --resume runs it.
job_child() {  # job_child PID: the child process running a job of batch process PID
  for _ in $(seq 1 600); do
    c=$(pgrep -P "$1" | head -1); [ -n "$c" ] && { echo "$c"; return; }; sleep 0.05
  done
}
lost_run() {  # lost_run DIR [OPTIONS]: kill the third job's process, wait for the run's end
  "$bin" batch six.jsonl --out "$@" >out.txt 2>err.txt &
  pid=$!
  for _ in $(seq 1 600); do
    [ "$(ls "$1/jobs" 2>/dev/null | grep -c '^d')" -ge 2 ] && break; sleep 0.05
  done
  c=$(job_child $pid); [ -n "$c" ] && kill -9 "$c"
  wait $pid; rc=$?
}
lost_run lost
if [ $rc -eq 0 ] && [ -n "$c" ] && grep -q "LOST d3 (attempt 1.*killed by signal" err.txt && same_outputs lost &&
   [ "$($py -c 'import sqlite3; print(sqlite3.connect("lost/batch.sqlite").execute("select group_concat(attempts) from jobs").fetchone()[0])')" = "1,1,2,1,1,1" ]
then ok "batch: a job whose process was killed runs again in the same run: the outputs of an uninterrupted run"
else fail "batch: killed job process (exit $rc, child '$c'): $(head -c 400 err.txt)"; fi
lost_run lost0 --retries 0
"$bin" batch six.jsonl --out lost0 --resume >out2.txt 2>err2.txt; rc2=$?
if [ $rc -eq 1 ] && grep -q "5 of 6 jobs done, 1 failed (first: d3: its process was killed by signal" out.txt &&
   [ $rc2 -eq 0 ] && grep -q "1 jobs to run" err2.txt && same_outputs lost0
then ok "batch: with --retries 0 a killed job has failed; --resume runs it"
else fail "batch: killed job, --retries 0 (exit $rc $rc2): $(head -c 300 out.txt) $(head -c 300 err2.txt)"; fi
"$bin" batch six.jsonl --out slow --job-timeout 0.2 >out.txt 2>err.txt; rc=$?
if [ $rc -eq 1 ] && grep -q "0 of 6 jobs done, 6 failed (first: d1: timed out: killed after 0.2" out.txt &&
   [ -z "$(ls -A slow/jobs)" ]
then ok "batch: --job-timeout stops a job, which has failed, nothing of it left"
else fail "batch: --job-timeout (exit $rc): $(head -c 300 out.txt)"; fi
mpi=$(command -v mpirun || true)
"$bin" batch bad3.jsonl --out x 2>err.txt
if [ -n "$mpi" ] && ! grep -q "built without MPI" err.txt; then
  mpirun --allow-run-as-root --oversubscribe -np 2 "$bin" batch six.jsonl --out mpi >out.txt 2>err.txt; rc=$?
  if [ $rc -eq 0 ] && grep -q "6 jobs over 2 MPI ranks" err.txt && same_outputs mpi &&
     [ "$($py -c 'import sqlite3; print(sorted({r[0] for r in sqlite3.connect("mpi/batch.sqlite").execute("select rank from jobs")}))')" = "[0, 1]" ]
  then ok "batch: mpirun -np 2: jobs on both ranks, the outputs of the local run"
  else fail "batch: mpirun (exit $rc): $(head -c 400 err.txt)"; fi
  # A worker rank killed mid-run ends the MPI run; resuming (here, without MPI) finishes it.
  mpirun --allow-run-as-root --oversubscribe -np 2 "$bin" batch six.jsonl --out mpikill >/dev/null 2>&1 &
  mpid=$!
  for _ in $(seq 1 600); do
    [ "$(ls mpikill/jobs 2>/dev/null | grep -c '^d')" -ge 2 ] && break; sleep 0.05
  done
  rank1() {  # rank1 OUT: the processes of MPI rank 1 of the batch into OUT (the rank, its job)
    pgrep -f "batch six.jsonl --out $1" | while read -r p; do
      [ "$(tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -c '^OMPI_COMM_WORLD_RANK=1$')" = 1 ] && echo "$p"; done
  }
  worker=$(rank1 mpikill | while read -r p; do
    rank1 mpikill | grep -qx "$(ps -o ppid= -p "$p" | tr -d ' ')" || echo "$p"; done | head -1)
  [ -n "$worker" ] && kill -9 "$worker"
  wait $mpid 2>/dev/null
  before=$(ls mpikill/jobs | grep -c '^d')
  if [ -n "$worker" ] && "$bin" batch six.jsonl --out mpikill --resume >out.txt 2>err.txt && same_outputs mpikill
  then ok "batch: an MPI worker killed after $before jobs, resumed: the outputs of an uninterrupted run"
  else fail "batch: MPI worker kill (worker '$worker', $before jobs): $(head -c 300 err.txt)"; fi
  # The job process of rank 1 killed: the job goes back to the queue of the same MPI run.
  mpirun --allow-run-as-root --oversubscribe -np 2 "$bin" batch six.jsonl --out mpilost >out.txt 2>err.txt &
  mpid=$!
  for _ in $(seq 1 600); do
    [ "$(ls mpilost/jobs 2>/dev/null | grep -c '^d')" -ge 1 ] && break; sleep 0.05
  done
  # A job process found may end before the kill reaches it (a job takes 1-2 s): then the next.
  job=""
  for _ in $(seq 1 600); do
    job=$(rank1 mpilost | while read -r p; do
      rank1 mpilost | grep -qx "$(ps -o ppid= -p "$p" | tr -d ' ')" && echo "$p"; done | head -1)
    [ -n "$job" ] && kill -9 "$job" 2>/dev/null && break
    job=""; sleep 0.05
  done
  wait $mpid; rc=$?
  if [ $rc -eq 0 ] && [ -n "$job" ] && grep -q "LOST d.*rank 1 .*killed by signal" err.txt && same_outputs mpilost
  then ok "batch: an MPI rank's job process killed: run again in the same run, the outputs of the local run"
  else fail "batch: MPI job process kill (exit $rc, job '$job'): $(head -c 400 err.txt)"; fi
else
  ok "batch: MPI checks skipped (no mpirun, or built without MPI)"
fi
fi

# --- fabric --------------------------------------------------------------------------------------
# The library, KES/FAST conversion checked against the published formulas (computed here, not by
# the tool), refusals that name the key and write nothing, a converted fabric used by dress, and
# the virtual tests' reports and pictures at coarse resolution.
if in_section fabric; then
expect_ok "fabric list" "$bin" fabric list
if [ "$(grep -c . out.txt)" -eq 16 ] && grep -q '^11oz-black-denim ' out.txt && grep -q '^cotton_jersey ' out.txt
then ok "fabric list: 15 fabrics and a header"; else fail "fabric list: $(head -c 300 out.txt)"; fi
expect_ok "fabric show denim" "$bin" fabric show denim
$py - <<'PY' && ok "fabric show: JSON with the bending length" || fail "fabric show: $(head -c 300 out.txt)"
import json
j = json.load(open("out.txt"))
assert j["name"] == "denim", j
c = (j["bending_un_m"] / (j["density_g_m2"] * 9.81e-6)) ** (1 / 3)
assert abs(j["derived"]["bending_length_warp_mm"] - c) < 1e-9 * c, (j["derived"], c)
PY
expect_fail "fabric show: unknown name" "unknown fabric 'tweed'" "$bin" fabric show tweed
cat >fast.json <<'J'
{"name": "wool", "W": 168, "C_warp": 15, "C_weft": 12, "E5_warp": 0.67, "E20_warp": 1.87,
 "E100_warp": 4.9, "E5_weft": 0.9, "E20_weft": 2.6, "E100_weft": 6.8, "EB5": 4.7, "T2": 0.62,
 "T100": 0.51}
J
cat >kes.json <<'J'
{"W": 16.8, "LT_warp": 0.65, "LT_weft": 0.7, "WT_warp": 6.5, "WT_weft": 10.5, "RT_warp": 65,
 "RT_weft": 60, "EMT_warp": 4.0, "EMT_weft": 6.0, "B_warp": 0.09, "B_weft": 0.07, "2HB_warp": 0.04,
 "2HB_weft": 0.03, "G_warp": 0.8, "G_weft": 0.7, "2HG_warp": 0.9, "2HG_weft": 0.8,
 "2HG5_warp": 1.9, "2HG5_weft": 1.7}
J
expect_ok "fabric convert --fast" "$bin" fabric convert --fast fast.json --out wool.json
expect_ok "fabric convert --kes" "$bin" fabric convert --kes kes.json --out kes_fabric.json --name kesfab
$py - <<'PY' && ok "fabric convert: FAST and KES formulas" || fail "fabric convert: $(head -c 400 wool.json)"
import json, math
f = json.load(open("wool.json"))
assert f["name"] == "wool"
assert abs(f["bending_un_m"] - 168 * 15**3 * 9.81e-6) < 1e-9, f["bending_un_m"]      # 5.56 µN·m
assert abs(f["bending_weft_un_m"] - 168 * 12**3 * 9.81e-6) < 1e-9
assert abs(f["shear_n_m"] - 123 / 4.7) < 1e-9
assert abs(f["stretch_warp_n_m"] - 5 * 0.980665 / 0.0067) < 1e-6
assert f["extension_warp_pct"] == [0.67, 1.87, 4.9] and f["thickness_mm"] == 0.62
k = json.load(open("kes_fabric.json"))
assert k["name"] == "kesfab"
assert abs(k["bending_un_m"] - 0.09 * 9.80665e-5 * 1e6) < 1e-9
assert abs(k["shear_n_m"] - 0.75 * 0.980665 * 180 / math.pi) < 1e-9
assert k["density_g_m2"] == 168
n = 2 / 0.65 - 1
assert abs(k["extension_warp_pct"][0] - 4.0 * (5 / 500) ** (1 / n)) < 1e-9
PY
# Refusals: one line naming the key, non-zero exit, no output file.
$py - <<'PY'
import json
r = json.load(open("fast.json"))
bad = dict(r); bad["E50_warp"] = 1; json.dump(bad, open("unknown.json", "w"))
bad = dict(r); del bad["C_weft"]; del bad["EB5"]; json.dump(bad, open("missing.json", "w"))
bad = dict(r); bad["C_warp"] = -3; json.dump(bad, open("negative.json", "w"))
open("broken.json", "w").write('{"W": 168,')
PY
expect_fail "fabric convert: unknown key" "unknown.json: unknown FAST key\(s\): E50_warp" \
  "$bin" fabric convert --fast unknown.json --out o.json
expect_fail "fabric convert: missing keys" "missing.json: missing FAST key\(s\): C_weft, EB5" \
  "$bin" fabric convert --fast missing.json --out o.json
expect_fail "fabric convert: negative value" "\"C_warp\" must be a positive finite number, got -3" \
  "$bin" fabric convert --fast negative.json --out o.json
expect_fail "fabric convert: bad JSON" "broken.json: malformed JSON at byte" \
  "$bin" fabric convert --kes broken.json --out o.json
$py -c 'open("deep.json", "w").write("{\"W\": " + "[" * 300000 + "]" * 300000 + "}")'
expect_fail "fabric convert: JSON nested too deep" "deep.json: JSON nested deeper than 256 levels" \
  "$bin" fabric convert --kes deep.json --out o.json
expect_fail "fabric show: JSON nested too deep" "deep.json: JSON nested deeper than 256 levels" \
  "$bin" fabric show deep.json
expect_fail "fabric convert: a FAST record as KES" "fast.json: unknown KES key\(s\): C_warp, C_weft" \
  "$bin" fabric convert --kes fast.json --out o.json
expect_fail "fabric convert: both records" "exactly one of --kes and --fast" \
  "$bin" fabric convert --kes kes.json --fast fast.json --out o.json
expect_fail "fabric convert: --out not JSON" "expected a .json" \
  "$bin" fabric convert --fast fast.json --out o.txt
expect_fail "fabric test: unknown fabric" "unknown fabric 'tweed'" \
  "$bin" fabric test tweed --test cantilever --report o.json
expect_fail "fabric test: unknown test" "--test 'wobble'" \
  "$bin" fabric test denim --test wobble --report o.json
expect_fail "fabric test: resolution" "resolution must be within 1 and 50 mm" \
  "$bin" fabric test denim --test cantilever --resolution 0.5 --report o.json
expect_fail "fabric test: a tensile picture" "has no picture" \
  "$bin" fabric test denim --test tensile --picture o.png
expect_fail "fabric test: a bad fabric file" "negative.json: unknown field \"C_warp\"" \
  "$bin" fabric test negative.json --test bias --report o.json
if ls o.json o.txt o.png ./*.tmp* >/dev/null 2>&1; then fail "fabric: a refusal left a file"
else ok "fabric: refusals write nothing"; fi
# The virtual tests at coarse resolution: reports name their figures; the cantilever's target is
# the fabric's own bending length, computed here.
expect_ok "fabric test cantilever" "$bin" fabric test wool.json --test cantilever --resolution 10 \
  --report cant.json --picture cant.png
expect_ok "fabric test tensile" "$bin" fabric test wool.json --test tensile --resolution 20 --report tens.json
expect_ok "fabric test bias" "$bin" fabric test wool.json --test bias --resolution 20 --report bias.json
expect_ok "fabric test cusick" "$bin" fabric test denim --test cusick --resolution 20 --repeats 2 \
  --perturbation 0.5 --report cus.json --picture cus.png
expect_ok "fabric test cusick without the static solve" "$bin" fabric test denim --test cusick \
  --resolution 20 --no-static-solve --report cus_rest.json
$py - <<'PY' && ok "fabric test: reports agree with the fabric" || fail "fabric test reports"
import json
c = json.load(open("cant.json"))
for d, cm in (("warp", 15), ("weft", 12)):
    assert abs(c["target_bending_length_%s_mm" % d] - cm) < 1e-9, c
    # 3 segments at 10 mm: the discrete elastica alone is 4.3 % short (garment/README.md).
    assert abs(c["bending_length_%s_mm" % d] - cm) < 0.10 * cm, c
t = json.load(open("tens.json"))
for load, e in ((5, 0.67), (20, 1.87), (100, 4.9)):
    assert abs(t["strain_warp_at_%d_gf_cm_pct" % load] - e) < 0.02 * e, t
b = json.load(open("bias.json"))
assert abs(b["shear_rigidity_n_m"] - 123 / 4.7) < 0.05 * 123 / 4.7, b
u = json.load(open("cus.json"))
assert 0 < u["drape_coefficient_pct"] < 100 and len(u["nodes"]) == 2, u
assert u["drape_coefficient_min_pct"] <= u["drape_coefficient_pct"] <= u["drape_coefficient_max_pct"]
assert u["static_solve"] is True and u["equilibrium"] is True, u
assert u["relax_max_residual_of_weight"] < 0.05, u
# The sub-stepped rest alone stops short of the equilibrium (denim at 20 mm: about 56 against 71).
v = json.load(open("cus_rest.json"))
assert v["static_solve"] is False and v["equilibrium"] is False, v
assert v["drape_coefficient_pct"] < u["drape_coefficient_pct"] - 5, (v, u)
for p in ("cant.png", "cus.png"):
    assert open(p, "rb").read(8) == b"\x89PNG\r\n\x1a\n"
PY
# dress takes a converted fabric file and reports it.
body="$root/data/bodies/mh_female_average.obj"
expect_ok "dress --fabric fabric.json" "$bin" dress "$body" --units dm "$gc" --resolution 30 \
  --sew-seconds 0 --settle-seconds 0 --out placed.obj --report placed.json --fabric wool.json
$py - <<'PY' && ok "dress: the report names the converted fabric" || fail "dress --fabric file"
import json
r = json.load(open("placed.json"))
assert r["fabric"]["name"] == "wool", r["fabric"]
assert abs(r["fabric"]["bending_un_m"] - 168 * 15**3 * 9.81e-6) < 1e-9
PY
fi

# --- mesh remesh / simplify ---------------------------------------------------------------------
if in_section remesh; then
expect_ok "generate icosphere:4" "$bin" mesh generate icosphere:4 --out ico4.off
expect_ok "remesh to 0.1 edges" "$bin" mesh remesh ico4.off --edge 0.1 --out r.off
expect_ok "simplify to 200 vertices" "$bin" mesh simplify ico4.off --vertices 200 --out s.ply
# Truth: the input is inscribed in the unit sphere and the remeshing projects onto it, so every
# vertex lies between the inscribed mesh's inradius and 1; a closed genus-0 triangle mesh has
# F = 2V - 4; CGAL splits edges longer than 4/3 of the target and collapses those shorter than 4/5
# of it, so every edge is below 0.1333 and the mean lies a little under the target (0.077 here):
# an equilateral triangle of side 0.077 has area sqrt(3)/4 * 0.077^2, and the sphere about 4 pi /
# that = 4,900 faces.
$py - <<'PY' && ok "remesh: on the sphere, closed, edges near 0.1" || fail "remesh output"
import math, struct
def off(path):
    t = open(path).read().split()
    assert t[0] == "OFF"
    nv, nf = int(t[1]), int(t[2])
    v = [tuple(map(float, t[4 + 3 * i: 7 + 3 * i])) for i in range(nv)]
    k, f = 4 + 3 * nv, []
    for _ in range(nf):
        n = int(t[k]); f.append(tuple(map(int, t[k + 1:k + 1 + n]))); k += 1 + n
    return v, f
v, f = off("r.off")
r = [math.sqrt(x * x + y * y + z * z) for x, y, z in v]
assert 0.98 < min(r) and max(r) < 1 + 1e-9, (min(r), max(r))
assert len(f) == 2 * len(v) - 4, (len(v), len(f))
assert 3000 < len(f) < 7000, len(f)
e = [math.dist(v[a], v[b]) for t in f for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0]))]
mean = sum(e) / len(e)
assert 0.07 < mean < 0.1 and max(e) < 0.4 / 3 and min(e) > 0.04, (mean, min(e), max(e))
PY
$py - <<'PY' && ok "simplify: 200 vertices, closed" || fail "simplify output"
import struct
data = open("s.ply", "rb").read()
head, body = data.split(b"end_header\n", 1)
nv = nf = None
for line in head.decode().splitlines():
    if line.startswith("element vertex"): nv = int(line.split()[2])
    if line.startswith("element face"): nf = int(line.split()[2])
assert abs(nv - 200) <= 5, nv
assert nf == 2 * nv - 4, (nv, nf)
PY
# An open mesh keeps its hole where it was: the cap above z = 0.9 cut out of the sphere stays out
# (every vertex below 0.9) and `mesh check` still finds one boundary loop.
$py - <<'PY'
t = open("ico4.off").read().split()
nv, nf = int(t[1]), int(t[2])
v = [tuple(map(float, t[4 + 3 * i: 7 + 3 * i])) for i in range(nv)]
k, keep = 4 + 3 * nv, []
for _ in range(nf):
    n = int(t[k]); f = t[k + 1:k + 1 + n]; k += 1 + n
    if all(v[int(i)][2] < 0.9 for i in f):
        keep.append(f)
with open("open.off", "w") as o:
    o.write("OFF\n%d %d 0\n" % (nv, len(keep)))
    o.writelines("%r %r %r\n" % p for p in v)
    o.writelines("3 %s\n" % " ".join(f) for f in keep)
PY
expect_ok "remesh an open mesh" "$bin" mesh remesh open.off --edge 0.1 --out open_r.off
expect_ok "check the re-meshed open mesh" "$bin" mesh check open_r.off
if grep -q "1 boundary loop" out.txt && $py -c "
t = open('open_r.off').read().split(); n = int(t[1])
assert max(float(t[6 + 3 * i]) for i in range(n)) < 0.9"; then ok "remesh kept the hole"
else fail "remesh of an open mesh: $(head -c 300 out.txt)"; fi
expect_fail "remesh: zero edge" "edge length must be a positive number" "$bin" mesh remesh ico4.off --edge 0 --out x.off
expect_fail "remesh: negative edge" "edge length must be a positive number" "$bin" mesh remesh ico4.off --edge -0.1 --out x.off
expect_fail "remesh: an edge for the wrong unit" "would give about .* faces, more than 20 million" "$bin" mesh remesh ico4.off --edge 0.0001 --out x.off
expect_fail "remesh: zero iterations" "at least one iteration" "$bin" mesh remesh ico4.off --edge 0.1 --iterations 0 --out x.off
expect_fail "remesh: unknown output format" "x.abc.*unknown mesh format" "$bin" mesh remesh ico4.off --edge 0.1 --out x.abc
expect_fail "remesh: missing input" "nothere.off" "$bin" mesh remesh nothere.off --edge 0.1 --out x.off
expect_fail "simplify: too few vertices" "cannot simplify 2562 vertices to 3" "$bin" mesh simplify ico4.off --vertices 3 --out x.off
expect_fail "simplify: not fewer vertices" "cannot simplify 2562 vertices to 2562" "$bin" mesh simplify ico4.off --vertices 2562 --out x.off
expect_fail "simplify: missing directory" "nodir.*does not exist" "$bin" mesh simplify ico4.off --vertices 100 --out nodir/x.off
if ls x.* nodir >/dev/null 2>&1; then fail "a refused remesh or simplify wrote: $(ls x.* nodir 2>/dev/null)"; else ok "refused remesh and simplify wrote nothing"; fi
fi

# --- wrinkles: classes of a draped garment, the buckling experiment -----------------------------
if in_section wrinkles; then
# A 10 x 10 grid of 10 mm cells wrapped on a cylinder of radius 80 mm (axis along y), written in
# dm the way `tapeline dress` writes a garment on a body in dm: shortened 5 % along the warp (y)
# everywhere, the right half also pulled 3 % around (tension), the left half not (compression).
$py - <<'PY'
import math
R = 80.0
with open("g.obj", "w") as f:
    f.write("g panel\n# grain 0 1\n")
    for j in range(11):
        for i in range(11):
            u, v = 10.0 * i, 10.0 * j
            s = u if i <= 5 else 50 + 1.03 * (u - 50)   # arc length around the cylinder
            x, z = R * math.sin(s / R), R * (1 - math.cos(s / R))
            f.write("v %.9g %.9g %.9g\n" % (x / 100, 0.95 * v / 100, z / 100))
    for j in range(11):
        for i in range(11):
            f.write("vt %g %g\n" % (10.0 * i, 10.0 * j))
    for j in range(10):
        for i in range(10):
            a, b, c, d = j * 11 + i + 1, j * 11 + i + 2, (j + 1) * 11 + i + 2, (j + 1) * 11 + i + 1
            f.write("f %d/%d %d/%d %d/%d\n" % (a, a, b, b, c, c))
            f.write("f %d/%d %d/%d %d/%d\n" % (a, a, c, c, d, d))
PY
"$bin" fabric show denim > denim.json
expect_ok "wrinkles classify" "$bin" wrinkles classify g.obj --fabric denim --report w.json --triangles t.json --picture w.png
grep -q "positions in dm" out.txt && ok "wrinkles classify: the unit found (dm)" || fail "wrinkles classify unit: $(head -c 300 out.txt)"
$py - <<'PY' && ok "wrinkles classify: classes and wavelengths" || fail "wrinkles classify: $(head -c 400 w.json)"
import json, math
r = json.load(open("w.json"))
t = json.load(open("t.json"))
c = r["report"]["classes"]
assert r["units"] == "dm" and r["fabric"] == "denim", r
assert sum(c[k]["triangles"] for k in c) == r["report"]["triangles"] == 200 == len(t["class"])
# The sheared triangles straddle the joint; away from it the halves have their classes.
cls = t["class"]
left = [cls[2 * (10 * j + i) + k] for j in range(10) for i in range(0, 4) for k in range(2)]
right = [cls[2 * (10 * j + i) + k] for j in range(10) for i in range(6, 10) for k in range(2)]
assert all(x == "compression" for x in left), left
assert all(x == "tension" for x in right), right
# Right half, away from the joint and the border: T = k_weft * 0.03 around, kappa = 1/R along the
# crests, waves along the warp: lambda = 2 pi (B_warp R^2 / T)^(1/4), A = lambda / pi sqrt(0.05).
f = json.load(open("denim.json"))
T, B, R = f["stretch_weft_n_m"] * 0.03, f["bending_un_m"] * 1e-6, 0.080
expect = 2 * math.pi * (B * R * R / T) ** 0.25 * 1e3
inner = [2 * (10 * j + i) + k for j in range(1, 9) for i in range(7, 9) for k in range(2)]
for n in inner:
    assert abs(t["wavelength_mm"][n] - expect) < 0.03 * expect, (n, t["wavelength_mm"][n], expect)
    assert abs(t["amplitude_mm"][n] - expect / math.pi * math.sqrt(0.05)) < 0.03 * expect, n
# The left half has no tension along its crests: no wavelength.
assert all(t["wavelength_mm"][n] is None for n in range(len(cls)) if cls[n] == "compression")
assert c["tension"]["median_wavelength_mm"] is not None and c["compression"]["median_wavelength_mm"] is None
PY
[ -s w.png ] && ok "wrinkles classify: picture" || fail "wrinkles classify: no picture"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > novt.obj
expect_fail "wrinkles classify: no vt" "novt.obj:4: face corner '1' has no pattern coordinate" "$bin" wrinkles classify novt.obj --report x.json
printf 'v 0 0 0\nv 3 0 0\nv 0 3 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n' > odd.obj
expect_fail "wrinkles classify: unit not found" "odd.obj: cannot tell the unit" "$bin" wrinkles classify odd.obj --report x.json
expect_ok "wrinkles classify: unit given" "$bin" wrinkles classify odd.obj --units mm
expect_fail "wrinkles classify: bad unit" "--units inch: expected auto" "$bin" wrinkles classify g.obj --units inch
expect_fail "wrinkles classify: bad threshold" "compression_threshold must lie in" "$bin" wrinkles classify g.obj --compression-threshold 0 --report x.json
expect_fail "wrinkles classify: unknown fabric" "unknown fabric 'tweed'" "$bin" wrinkles classify g.obj --fabric tweed --report x.json
expect_fail "wrinkles classify: missing file" "nothere.obj: cannot open" "$bin" wrinkles classify nothere.obj --report x.json
# compare: a flat panel (pattern 300 x 300 mm) pulled 3 % across and shortened 5 % along the
# warp, coarse at 20 mm, fine at 3 mm with a wave along the warp of 1.1 times the wavelength the
# law predicts with the tension term over 300 mm: the tool measures the ratio.
panel="$root/tests/cli/wrinkle_panel.py"
$py "$panel" coarse.obj 15 20
$py "$panel" fine.obj 100 3 --wave denim.json
expect_ok "wrinkles compare" "$bin" wrinkles compare coarse.obj fine.obj --fabric denim --tension-length 300 --report cmp.json --windows win.json --picture cmp.png
[ -s cmp.png ] && ok "wrinkles compare: picture" || fail "wrinkles compare: no picture"
$py - <<'PY' && ok "wrinkles compare: the fine wave's wavelength against the prediction" || fail "wrinkles compare: $(head -c 600 cmp.json)"
import json
c = json.load(open("cmp.json"))["comparison"]
w = json.load(open("win.json"))
assert c["windows"] == 450 == len(w), c
assert c["measured"] > 225, c
assert abs(c["median_wavelength_ratio"] - 1.1) < 0.02, c
assert abs(c["classes"]["tension"]["median_wavelength_error_percent"] - 10) < 2, c
PY
printf 'g a\ng b\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n' > twopiece.obj
expect_fail "wrinkles compare: fine mesh of other pieces" "fine triangle 0 lies on piece 1" "$bin" wrinkles compare coarse.obj twopiece.obj --units mm --report x.json
expect_fail "wrinkles buckling: one rigidity" "give two or more rigidities" "$bin" wrinkles buckling --test foundation --bending 1 --report x.json
expect_fail "wrinkles buckling: unknown test" "expected foundation or cylinder" "$bin" wrinkles buckling --test drum --bending 1,2 --report x.json
# train / apply: the compare panel's pair is the training data; a held-out panel of another size
# (240 mm, the same strains) with the same wave is the simulation the synthesis is checked against.
$py "$panel" held.obj 12 20
$py "$panel" held_fine.obj 80 3 --wave denim.json
expect_ok "wrinkles train" "$bin" wrinkles train coarse.obj fine.obj --units mm --fabric denim --out db.json
$py - <<'PY' && ok "wrinkles train: samples away from the outline, nearly all with the wave" || fail "wrinkles train: $(head -c 300 out.txt)"
import json
d = json.load(open("db.json"))
n, waves = len(d["samples"]), sum(1 for r in d["samples"] if r[-3] > 0)
assert 200 < n < 450 and waves > 0.75 * n, (n, waves)
assert d["fabric"] == "denim" and d["uses_body"] is False
PY
expect_ok "wrinkles apply" "$bin" wrinkles apply held.obj --db db.json --units mm --against held_fine.obj --out held_wr.obj --report apply.json --picture apply.png
[ -s apply.png ] && ok "wrinkles apply: picture" || fail "wrinkles apply: no picture"
$py - <<'PY' && ok "wrinkles apply: the learned wave on a held-out panel" || fail "wrinkles apply: $(head -c 900 apply.json)"
import json
r = json.load(open("apply.json"))
s, c = r["synthesis"], r["check"]["compressed"]
assert s["fine_triangles"] == 16 * 288, s
assert s["new_self_crossings_left"] == 0 and s["body_checked"] is False, s
assert c["simulation_has_wave"] > 100, c
assert c["both_have_wave"] >= 0.9 * c["simulation_has_wave"], c
assert c["median_wavelength_error_percent"] < 5, c
assert c["median_amplitude_error_percent"] < 30, c
# the written OBJ holds the fine mesh, in mm as given
v = sum(1 for line in open("held_wr.obj") if line.startswith("v "))
assert v == s["fine_vertices"], (v, s)
PY
expect_fail "wrinkles train: odd file count" "give pairs COARSE.obj FINE.obj" "$bin" wrinkles train coarse.obj fine.obj held.obj --units mm --out x.json
expect_fail "wrinkles train: bodies per pair" "--bodies names 2 bodies for 1 pairs" "$bin" wrinkles train coarse.obj fine.obj --bodies a.obj b.obj --out x.json
expect_fail "wrinkles apply: other fabric" "trained on fabric 'denim', the garment is of 'cotton_jersey'" "$bin" wrinkles apply held.obj --db db.json --fabric cotton_jersey --units mm --out x.obj
printf '{"format": "tapeline-pattern"}\n' > notdb.json
expect_fail "wrinkles apply: not a database" "notdb.json: not a wrinkle database" "$bin" wrinkles apply held.obj --db notdb.json --units mm --out x.obj
$py -c "import json; d = json.load(open('db.json')); d['samples'][3][0] = 'x'; json.dump(d, open('baddb.json', 'w'))"
expect_fail "wrinkles apply: bad sample" "baddb.json: sample 3: feature compression is not a finite number" "$bin" wrinkles apply held.obj --db baddb.json --units mm --out x.obj
expect_fail "wrinkles apply: levels" "levels must be in" "$bin" wrinkles apply held.obj --db db.json --units mm --levels 0 --out x.obj
expect_fail "wrinkles apply: output type" "--out x.ply: expected a .obj file" "$bin" wrinkles apply held.obj --db db.json --units mm --out x.ply
expect_fail "wrinkles refine: missing body" "nobody.obj" "$bin" wrinkles refine held.obj --body nobody.obj --out x.obj
expect_fail "wrinkles apply: garment not in the body's unit" "held.obj: its positions are in mm" \
  "$bin" wrinkles apply held.obj --db db.json --body "$root/data/bodies/mh_female_average.obj" --units dm --out x.obj
if ls x.* >/dev/null 2>&1; then fail "a refused wrinkles command wrote: $(ls x.*)"; else ok "refused wrinkles commands wrote nothing"; fi
fi

if [ $sections_run -eq 0 ]; then fail "no section named '$section'"; fi
[ $((passed+failed)) -gt 0 ] || fail "no check ran"
echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
