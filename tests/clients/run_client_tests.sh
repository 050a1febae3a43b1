#!/usr/bin/env bash
# Real programs open what `tapeline` writes:
#   valentina  valentina-tape (Valentina 0.7.52; Seamly2D shares its measurement schema) validates
#              the .vit of `tapeline measure` on the bundled body against its schema and its list
#              of known measurement names;
#   librecad   LibreCAD's `dxf2pdf` prints an exported DXF-AAMA pattern with its default page
#              settings; the PDF, rendered by pdftoppm, shows the pieces, not just the title.
# Each section first feeds a broken file and requires the failure, so a check that cannot fail
# is noticed.
#   run_client_tests.sh TAPELINE_BINARY SOURCE_DIR WORK_DIR SECTION
# Exit 77 (ctest SKIP_RETURN_CODE) only when the client program is not installed; 1 on failure.
set -u
bin=$1; root=$2; work=$3; section=$4
py=/usr/bin/python3
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1
passed=0; failed=0
ok()   { passed=$((passed+1)); echo "ok   - $1"; }
fail() { failed=$((failed+1)); echo "FAIL - $1"; }
need() {  # need PROGRAM PACKAGE
  command -v "$1" >/dev/null 2>&1 && return 0
  echo "SKIP: $1 is not installed (Debian package $2; scripts/tapeline-setup test installs it)"
  exit 77
}
finish() {
  echo "# $passed passed, $failed failed"
  [ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
  exit $?
}

# tape_verdict FILE: "accepted" or "refused: <reason>". valentina-tape --test exits 66 with a
# "Validation error"/"Parsing error" line when it refuses a file; a file it accepts is opened
# and the program keeps running (no window), so it is stopped after 8 s: its refusals come
# within a second. It converts the file in place to its newest format, so it gets a copy.
tape_verdict() {
  local copy="tape_$(basename "$1")"
  cp "$1" "$copy"
  QT_QPA_PLATFORM=offscreen timeout 8 valentina-tape --test "$copy" >tape.txt 2>&1
  local rc=$?
  if grep -qE "Validation error|Parsing error|CRITICAL|Exception" tape.txt || { [ $rc -ne 0 ] && [ $rc -ne 124 ]; }; then
    echo "refused (exit $rc): $(grep -E "Exception|error" tape.txt | tr '\n' ' ' | head -c 300)"
  else
    echo "accepted"
  fi
}

if [ "$section" = valentina ]; then
  need valentina-tape valentina
  if "$bin" measure "$root/data/bodies/mh_female_average.obj" --units dm --out body.json \
       --vit body.vit >measure.txt 2>&1; then ok "measure the bundled body to a .vit"
  else fail "measure: $(tail -c 300 measure.txt)"; finish; fi
  # The control: the same file without <birth-date>, as the 0.3.3 schema refuses it.
  grep -v "<birth-date>" body.vit > no_birth_date.vit
  v=$(tape_verdict no_birth_date.vit)
  case "$v" in *"Element gender is not defined"*) ok "control refused: $v" ;;
               *) fail "control: a file without <birth-date> was not refused: $v" ;; esac
  sed 's/name="bust_circ"/name="bust_circumference"/' body.vit > unknown_name.vit
  v=$(tape_verdict unknown_name.vit)
  case "$v" in *"invalid known measurement"*) ok "control refused: $v" ;;
               *) fail "control: an unknown known-name was not refused: $v" ;; esac
  v=$(tape_verdict body.vit)
  [ "$v" = accepted ] && ok "valentina-tape accepts the .vit of tapeline measure" \
                      || fail "valentina-tape: $v"
  # Valentina's own templates, as a check that the verdict is right on files it wrote itself.
  for f in /usr/share/valentina/tables/templates/*.vit; do
    [ -f "$f" ] || continue
    v=$(tape_verdict "$f")
    [ "$v" = accepted ] && ok "valentina-tape accepts its own $(basename "$f")" \
                        || fail "valentina-tape on its own $(basename "$f"): $v"
  done
  finish
fi

if [ "$section" = librecad ]; then
  need librecad librecad
  need pdftoppm poppler-utils
  if "$bin" pattern export "$root/data/patterns/shirt_mean_specification.json" --dxf shirt.dxf \
       >export.txt 2>&1; then ok "export the GarmentCode shirt to DXF-AAMA"
  else fail "export: $(tail -c 300 export.txt)"; finish; fi
  # The control: the header without the sheet ($PLIMMIN/$PLIMMAX/$PINSBASE), as LibreCAD then
  # prints on A4 at 1:1 from the origin, where only the style name lies.
  $py - <<'PY'
lines = open("shirt.dxf").read().split("\n")
out, i = [], 0
while i < len(lines):
    if lines[i].strip() == "9" and lines[i + 1] in ("$PLIMMIN", "$PLIMMAX", "$PINSBASE"):
        i += 2 + 6  # the name, then x, y, z as code/value pairs
        continue
    out.append(lines[i]); i += 1
open("no_sheet.dxf", "w").write("\n".join(out))
PY
  mkdir -p pdf
  for f in shirt no_sheet; do
    if QT_QPA_PLATFORM=offscreen timeout 60 librecad dxf2pdf -t pdf "$f.dxf" >"dxf2pdf_$f.txt" 2>&1 &&
       [ -s "pdf/$f.pdf" ] && pdftoppm -r 50 -gray "pdf/$f.pdf" "pdf/$f" && pdftoppm -r 50 -png "pdf/$f.pdf" "pdf/$f"; then
      ok "librecad dxf2pdf $f.dxf, rendered by pdftoppm"
    else fail "librecad dxf2pdf $f.dxf: $(tail -c 300 "dxf2pdf_$f.txt")"; fi
  done
  # ink.py PGM DXF: the page minus the band of the title (the topmost run of inked rows) must
  # hold ink spread over most of the page, and the page must be the DXF's extents plus 10 mm.
  cat > ink.py <<'PY'
import glob, sys
pgm = sorted(glob.glob(sys.argv[1] + "*.pgm"))[0]
data = open(pgm, "rb").read()
fields, pos = [], 0
while len(fields) < 4:  # P5 width height maxval, separated by whitespace
    while data[pos:pos + 1].isspace(): pos += 1
    start = pos
    while not data[pos:pos + 1].isspace(): pos += 1
    fields.append(data[start:pos])
w, h = int(fields[1]), int(fields[2]); pix = data[pos + 1:]
dark = lambda x, y: pix[y * w + x] < 128
rows = [sum(dark(x, y) for x in range(w)) for y in range(h)]
first = next((y for y in range(h) if rows[y]), h)
end = next((y for y in range(first, h) if not rows[y]), h)  # the title band: [first, end)
rest = [(x, y) for y in range(h) if not first <= y < end for x in range(w) if dark(x, y)]
frac = len(rest) / (w * h)
xs = [x for x, _ in rest]; ys = [y for _, y in rest]
spread = ((max(xs) - min(xs)) / w, (max(ys) - min(ys)) / h) if rest else (0, 0)
hdr = open(sys.argv[2]).read().split("\n")
val = lambda name, k: float(hdr[hdr.index(name) + 2 + 2 * k])
ext = [val("$EXTMAX", k) - val("$EXTMIN", k) for k in (0, 1)]
page_mm = (w / 50 * 25.4, h / 50 * 25.4)
print("page %.0f x %.0f mm (extents %.0f x %.0f mm), title rows %d-%d, ink outside it %.4f%%, "
      "spread %.2f x %.2f" % (page_mm + tuple(ext) + (first, end, 100 * frac) + spread))
sheet = all(abs(page_mm[k] - (ext[k] + 20)) < 2 for k in (0, 1))
sys.exit(0 if frac > 1e-3 and min(spread) > 0.8 and sheet else 1)
PY
  if r=$($py ink.py pdf/no_sheet no_sheet.dxf); then fail "control: a page without the pieces passed: $r"
  else ok "control: the default page without the sheet shows only the title: $r"; fi
  if r=$($py ink.py pdf/shirt shirt.dxf); then ok "the default page shows the pieces: $r"
  else fail "the default page does not show the pieces: $r"; fi
  finish
fi

# Assimp (Debian's assimp-utils) opens the dressed body's binary glTF: two meshes, the body's and
# the garment's, with exactly the vertex and face counts the OBJ files have. Control: a .glb cut in
# half is refused.
if [ "$section" = assimp ]; then
  need assimp assimp-utils
  body="$root/data/bodies/mh_female_average.obj"
  gc="$root/data/patterns/shirt_mean_specification.json"
  "$bin" dress "$body" --units dm "$gc" --resolution 30 --sew-seconds 0 --settle-seconds 0 \
    --out placed.obj --glb placed.glb >/dev/null 2>err.txt || fail "dress --glb: $(head -c 300 err.txt)"
  head -c "$(( $(stat -c %s placed.glb) / 2 ))" placed.glb > cut.glb
  if assimp info cut.glb >/dev/null 2>&1; then fail "control: a truncated .glb was accepted"
  else ok "control: a truncated .glb is refused"; fi
  if info=$(assimp info placed.glb 2>&1); then
    bv=$(grep -c '^v ' "$body"); bf=$(grep -c '^f ' "$body")
    gv=$(grep -c '^v ' placed.obj); gf=$(grep -c '^f ' placed.obj)
    meshes=$(echo "$info" | awk '/^Meshes:/ {print $2; exit}')
    verts=$(echo "$info" | awk '/^Vertices:/ {print $2; exit}')
    faces=$(echo "$info" | awk '/^Faces:/ {print $2; exit}')
    if [ "$meshes" = 2 ] && [ "$verts" = $((bv + gv)) ] && [ "$faces" = $((bf + gf)) ]; then
      ok "assimp reads body and garment: $meshes meshes, $verts vertices, $faces faces"
    else
      fail "assimp: $meshes meshes, $verts vertices, $faces faces; expected 2, $((bv + gv)), $((bf + gf))"
    fi
  else fail "assimp info: $(echo "$info" | tail -3)"; fi
  finish
fi

echo "unknown section '$section' (valentina, librecad, assimp)"; exit 1
