#!/usr/bin/python3
"""Runs every `tapeline` command over the hostile-input corpus (tests/corpus/, plus large files
generated here) under a time and memory limit, and checks each run: no crash (signal), no hang
(timeout), a refusal is a non-zero exit with exactly one line on stderr, and a refused run leaves
no file in its output directory. Named cases also check the message or the result.

    run_corpus.py TAPELINE_BINARY SOURCE_DIR WORK_DIR [--summary FILE] [--sanitized]

--sanitized: the binary is built with AddressSanitizer + UndefinedBehaviorSanitizer
(TAPELINE_SANITIZE). The memory limit is then ASan's RSS limit (an address-space limit stops
ASan's shadow memory), the time limit is doubled, and any sanitizer report counts as a crash.
LeakSanitizer's scan at exit is a third of a refusal's time there; the sweep runs it on a quarter
of its runs, a diagonal (command c, input i with (c + i) % 4 == 0: every command on a quarter of the
inputs, every input under a quarter of the commands), the named cases on all of theirs. The
distance methods other than the default (which read their input the same way) are swept over the
mesh inputs only there.
"""
import json
import math
import os
import re
import resource
import shutil
import signal
import sqlite3
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

TIME_LIMIT_S = 60
MEMORY_LIMIT = 4 << 30  # address space per run

binary, root, work = sys.argv[1], sys.argv[2], sys.argv[3]
options = sys.argv[4:]
summary_path = options[options.index("--summary") + 1] if "--summary" in options else None
sanitized = "--sanitized" in options
if sanitized:
    TIME_LIMIT_S *= 2
    os.environ["ASAN_OPTIONS"] = "hard_rss_limit_mb=%d:abort_on_error=0" % (MEMORY_LIMIT >> 20)
    os.environ["UBSAN_OPTIONS"] = "print_stacktrace=1"
SANITIZER_REPORT = re.compile(r"ERROR: (Address|Leak)Sanitizer|runtime error: |"
                              r"AddressSanitizer: hard rss limit")
corpus = os.path.join(root, "tests", "corpus")
data = os.path.join(root, "data")
spot = os.path.join(data, "spot.obj")
demo = os.path.join(data, "patterns", "aaron_cisFemaleAdult36.json")
demo_set = os.path.join(data, "patterns", "aaron_cisFemaleAdult36_measurements.json")
shutil.rmtree(work, ignore_errors=True)
gen = os.path.join(work, "generated")
os.makedirs(gen)


def write(name, text, mode="w"):
    path = os.path.join(gen, name)
    with open(path, mode) as f:
        f.write(text)
    return path


# --- inputs too large to keep in the repository ---------------------------------------------------
deep_json = write("deep_300000_levels.json", '{"chest": ' + "[" * 300000 + "]" * 300000 + "}")
deep_vit = write("deep_30000_elements.vit",
                 '<?xml version="1.0"?>\n<vit>' + "<e>" * 30000 + "</e>" * 30000 + "</vit>")
deep_pattern = write("deep_pattern.json",
                     '{"format": "tapeline-pattern", "x": ' + "{\"a\":" * 100000 + "1" +
                     "}" * 100000 + "}")
long_line = write("one_long_line.xyz", "1 " * 3000000 + "\n")
huge_pattern = write("coordinates_1e308.json", json.dumps({
    "format": "tapeline-pattern", "format_version": 1, "name": "huge", "units": "mm",
    "pieces": [{"name": "a", "outline": [
        {"type": "line", "a": [0, 0], "b": [1e308, 0]},
        {"type": "line", "a": [1e308, 0], "b": [0, 1e308]},
        {"type": "line", "a": [0, 1e308], "b": [0, 0]}]}], "seams": []}))
# 400 points on a unit sphere (golden spiral): a cloud whose extent is 2.
sphere_points = write("sphere_400.xyz", "".join(
    "%.9f %.9f %.9f\n" % (math.sqrt(1 - (1 - 2 * (i + 0.5) / 400) ** 2) * math.cos(2.399963 * i),
                         math.sqrt(1 - (1 - 2 * (i + 0.5) / 400) ** 2) * math.sin(2.399963 * i),
                         1 - 2 * (i + 0.5) / 400) for i in range(400)))
directory_input = os.path.join(gen, "a_directory.obj")
os.makedirs(directory_input)
foreign_db = os.path.join(gen, "foreign.sqlite")
with sqlite3.connect(foreign_db) as c:
    c.execute("CREATE TABLE contacts(name TEXT)")
future_db = os.path.join(gen, "future.sqlite")
with sqlite3.connect(future_db) as c:
    c.execute("PRAGMA application_id=1414548558")
    c.execute("CREATE TABLE patterns(x)")
    c.execute("PRAGMA user_version=99")
truncated_db = os.path.join(gen, "truncated.sqlite")
with sqlite3.connect(truncated_db) as c:
    c.execute("CREATE TABLE t(x)")
    c.executemany("INSERT INTO t VALUES(?)", [("x" * 1000,)] * 200)
os.truncate(truncated_db, os.path.getsize(truncated_db) // 3)

inputs = {}
for sub in sorted(os.listdir(corpus)):
    d = os.path.join(corpus, sub)
    if os.path.isdir(d):
        for name in sorted(os.listdir(d)):
            inputs[sub + "/" + name] = os.path.join(d, name)
for path in [deep_json, deep_vit, deep_pattern, long_line, huge_pattern, directory_input,
             foreign_db, future_db, truncated_db]:
    inputs["generated/" + os.path.basename(path)] = path

# --- the commands; {in} is the hostile input, {out} a fresh output directory -----------------------
commands = {
    "mesh check": ["mesh", "check", "{in}"],
    "distances exact-mmp": ["geodesic", "distances", "{in}", "--source", "0", "--out", "{out}/d.txt"],
    "distances heat": ["geodesic", "distances", "{in}", "--source", "0", "--method", "heat",
                       "--out", "{out}/d.ply"],
    "distances gcf-window": ["geodesic", "distances", "{in}", "--source", "0", "--method",
                             "gcf-window", "--out", "{out}/d.txt"],
    "distances dijkstra": ["geodesic", "distances", "{in}", "--source", "1", "--method", "dijkstra",
                           "--out", "{out}/d.txt"],
    "path": ["geodesic", "path", "{in}", "--from", "0", "--to", "1", "--out", "{out}/p.json",
             "--svg", "{out}/p.svg"],
    "point cloud": ["geodesic", "distances", "{in}", "--point-cloud", "--source", "0",
                    "--out", "{out}/d.txt"],
    "pattern validate": ["pattern", "validate", "{in}"],
    "pattern show": ["pattern", "show", "{in}", "--db", "{out}/none.sqlite"],
    "pattern export": ["pattern", "export", "{in}", "--db", "{out}/none.sqlite", "--svg",
                       "{out}/a.svg", "--png", "{out}/a.png", "--json", "{out}/a.json"],
    "pattern import": ["pattern", "import", "{in}", "--db", "{out}/db.sqlite"],
    "pattern list": ["pattern", "list", "--db", "{in}"],
    "grade --to": ["grade", demo, "--from", demo_set, "--to", "{in}", "--out", "{out}/g.json",
                   "--svg", "{out}/g.svg", "--generations", "0"],
    "grade --from": ["grade", demo, "--from", "{in}", "--to", demo_set, "--out", "{out}/g.json"],
    "measure": ["measure", "{in}", "--out", "{out}/m.json", "--vit", "{out}/m.vit"],
    "dress (body)": ["dress", "{in}", demo, "--units", "dm", "--out", "{out}/d.obj",
                     "--report", "{out}/r.json"],
    "dress (pattern)": ["dress", os.path.join(data, "bodies", "mh_female_average.obj"), "{in}",
                        "--units", "dm", "--out", "{out}/d.obj"],
    "fabric show": ["fabric", "show", "{in}"],
    "fabric convert": ["fabric", "convert", "--kes", "{in}", "--out", "{out}/f.json"],
}

# Inputs a command may accept: they are hostile to other readers only.
accepted = {
    ("mesh check", "mesh/nonmanifold_edge.off"),  # repaired (split) and reported
    ("distances exact-mmp", "mesh/nonmanifold_edge.off"),
    ("distances heat", "mesh/nonmanifold_edge.off"),
    ("distances dijkstra", "mesh/nonmanifold_edge.off"),
    ("path", "mesh/nonmanifold_edge.off"),
    # `pattern show` inspects: it prints the pattern with its validation errors; `validate` and
    # every writer refuse the same files (named cases below).
    ("pattern show", "pattern/no_pieces.json"),
    ("pattern show", "generated/coordinates_1e308.json"),
}


def limits():
    if not sanitized:
        resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))


run_counter = [0]


def run(argv, out, time_limit=TIME_LIMIT_S, preexec=limits, env=None):
    os.makedirs(out, exist_ok=True)
    try:
        p = subprocess.run([binary] + argv, cwd=out, stdin=subprocess.DEVNULL,
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, preexec_fn=preexec,
                           timeout=time_limit, env=env)
        return p.returncode, p.stdout.decode(errors="replace"), p.stderr.decode(errors="replace")
    except subprocess.TimeoutExpired:
        return "timeout", "", ""


results = {"runs": 0, "refused": 0, "accepted": 0, "crashes": 0, "hangs": 0, "files_left": 0,
           "failures": []}


def record_failure(name, why):
    results["failures"].append(name + ": " + why)


def check_refusal(name, argv, out, pattern=None, allow_success=False, time_limit=TIME_LIMIT_S,
                  preexec=limits, env=None):
    rc, stdout, stderr = run(argv, out, time_limit, preexec, env)
    results["runs"] += 1
    left = sorted(os.listdir(out))
    if rc == "timeout":
        results["hangs"] += 1
        record_failure(name, "no answer within %d s" % time_limit)
        return rc, stderr
    if rc < 0 or rc >= 128 or SANITIZER_REPORT.search(stderr):
        results["crashes"] += 1
        record_failure(name, "crashed (exit %s) %s" % (rc, stderr[-300:]))
        return rc, stderr
    if rc == 0:
        results["accepted"] += 1
        if not allow_success:
            record_failure(name, "accepted (exit 0): " + stdout[:200])
        return rc, stderr
    results["refused"] += 1
    # Warnings about the input may come first; the refusal itself is exactly one line.
    lines = [l for l in stderr.splitlines() if not l.startswith("tapeline: warning: ")]
    if len(lines) != 1 or not lines[0].startswith("tapeline: "):
        record_failure(name, "stderr is not one line: %r" % stderr[:400])
    elif "internal error" in lines[0]:  # an exception nobody turned into a message
        record_failure(name, "internal error: %r" % lines[0][:300])
    if pattern and not re.search(pattern, stderr):
        record_failure(name, "message %r does not match %r" % (stderr.strip(), pattern))
    if left:
        results["files_left"] += 1
        record_failure(name, "left files behind: %s" % left)
    return rc, stderr


jobs = []
no_leak_scan = None
if sanitized:
    no_leak_scan = dict(os.environ)
    no_leak_scan["ASAN_OPTIONS"] += ":detect_leaks=0"
# The commands of a family read their input with the same reader and differ only once it is
# read: under the sanitizers each family's other commands are swept over the inputs of its own
# format only, and its first command over every input (the unsanitized sweep runs every command on
# every input).
MESH_SUFFIXES = (".off", ".obj", ".ply", ".stl")
FAMILIES = [(MESH_SUFFIXES, ("distances exact-mmp", "distances heat", "distances gcf-window",
                             "distances dijkstra", "path", "measure", "dress (body)")),
            ((".json",), ("pattern show", "pattern export", "pattern import",
                          "dress (pattern)"))]
for c, (cname, template) in enumerate(commands.items()):
    for i, (iname, path) in enumerate(inputs.items()):
        if sanitized and any(cname in names and not path.lower().endswith(suffixes)
                             for suffixes, names in FAMILIES):
            continue
        argv_base = [a.replace("{in}", path) for a in template]
        env = no_leak_scan if (c + i) % 4 != 0 else None
        jobs.append((cname + " <- " + iname, argv_base, (cname, iname) in accepted, env))


def do(job_index):
    name, argv_base, ok, env = jobs[job_index]
    out = os.path.join(work, "runs", str(job_index))
    argv = [a.replace("{out}", out) for a in argv_base]
    check_refusal(name, argv, out, allow_success=ok, env=env)


with ThreadPoolExecutor(max_workers=2) as pool:
    list(pool.map(do, range(len(jobs))))
sweep_runs = results["runs"]

# --- named cases: the message or the result ------------------------------------------------------
case_dir = os.path.join(work, "cases")


case_count = [0]


def case(name, argv, pattern, **kw):
    case_count[0] += 1
    out = os.path.join(case_dir, "%03d_%s" % (case_count[0], re.sub(r"[^a-z0-9]+", "_",
                                                                      name.lower())[:60]))
    argv = [a.replace("{out}", out) for a in argv]
    return check_refusal("case " + name, argv, out, pattern, **kw), out


case("unknown command", ["frobnicate"], r"unknown command 'frobnicate' \(expected one of: mesh")
case("unknown subcommand", ["pattern", "frobnicate"], r"unknown command 'pattern frobnicate'")
case("empty --source", ["geodesic", "distances", spot, "--source", "", "--out", "{out}/d.txt"],
     r"--source.*empty value")
case("JSON 300000 levels deep (grade --to)",
     ["grade", demo, "--from", demo_set, "--to", deep_json, "--out", "{out}/g.json"],
     r"deep_300000_levels\.json: JSON nested deeper than 256 levels at byte 265")
case("XML 30000 elements deep (grade --to)",
     ["grade", demo, "--from", demo_set, "--to", deep_vit, "--out", "{out}/g.json"],
     r"deep_30000_elements\.vit:2:.*nested deeper than 256 levels")
case("gcf-window on a tetrahedron at 1e300",
     ["geodesic", "distances", inputs["mesh/tetra_1e300.off"], "--source", "0", "--method",
      "gcf-window", "--out", "{out}/d.txt"],
     r"vertex 1 has coordinate 1e\+300, outside the supported range \|x\| <= 1e\+15")
case("exact-mmp on a tetrahedron at 1e-300",
     ["geodesic", "distances", inputs["mesh/tetra_1e-300.off"], "--source", "0",
      "--out", "{out}/d.txt"], r"span only 1\.73e-300")
case("point cloud at 1e300",
     ["geodesic", "distances", inputs["points/coordinates_1e300.xyz"], "--point-cloud",
      "--source", "0", "--out", "{out}/d.txt"], r"point 1 has coordinate 1e\+300")
case("directory as mesh", ["geodesic", "distances", directory_input, "--source", "0",
                           "--out", "{out}/d.txt"], r"a_directory\.obj: is a directory")
case("directory as pattern", ["pattern", "validate", directory_input], r"is a directory")
# Targets no body has, or no grade of the draft reaches: refused, not a pattern kilometres wide,
# a collapsed one "within tolerance", or Ceres' log.
base_set = json.load(open(demo_set))
for chest, pattern in [(1e9, r"'chest' is 1e\+09 mm, outside the range of a human body"),
                       (1e-9, r"'chest' is 1e-09 mm, outside the range of a human body"),
                       (1e308, r"'chest' is 1e\+308 mm, outside the range of a human body"),
                       (3000, r"'chest' is 3000 mm, 3\.064 times the base set .* beyond 3 times")]:
    target = os.path.join(gen, "chest_%g.json" % chest)
    json.dump(dict(base_set, chest=chest), open(target, "w"))
    case("grade to a chest of %g mm" % chest,
         ["grade", demo, "--from", demo_set, "--to", target, "--out", "{out}/g.json",
          "--generations", "0"], pattern)
case("grade output in a missing directory",
     ["grade", demo, "--from", demo_set, "--to", demo_set, "--out", "{out}/g.json",
      "--svg", "{out}/nodir/x.svg"], r"nodir/x\.svg: directory .*nodir does not exist")
case("export output in a missing directory",
     ["pattern", "export", demo, "--svg", "{out}/a.svg", "--png", "{out}/nodir/x.png"],
     r"nodir/x\.png: directory .*nodir does not exist")
case("one output given twice",
     ["pattern", "export", demo, "--svg", "{out}/a.svg", "--json", "{out}/./a.svg"],
     r"given as two different outputs")
case("pattern with no pieces", ["pattern", "validate", inputs["pattern/no_pieces.json"]],
     r"has no pieces")
case("pattern at 1e308", ["pattern", "export", huge_pattern, "--svg", "{out}/a.svg"],
     r"beyond the 10000000\.000 mm a pattern may span")
case("single-point outline", ["pattern", "validate", inputs["pattern/garmentcode_single_point.json"]],
     r".")
case("--cell larger than the cloud",
     ["geodesic", "distances", sphere_points, "--point-cloud", "--source", "0", "--cell", "100",
      "--out", "{out}/d.txt"], r"cell size 100.* more than a tenth of the extent")
case("foreign database", ["pattern", "list", "--db", foreign_db], r"not a Tapeline pattern database")
case("database from the future", ["pattern", "list", "--db", future_db], r"schema version 99")

# A 252-byte output name: the temporary name beside it stays short.
(rc, _), out = case("252-byte output name",
                    ["pattern", "export", demo, "--json", "{out}/" + "n" * 247 + ".json"], None,
                    allow_success=True)
if rc != 0 or os.listdir(out) != ["n" * 247 + ".json"]:
    record_failure("case 252-byte output name", "exit %s, files %s" % (rc, os.listdir(out)))

# Temporaries of a killed process (PID not running) are removed by the next write there.
stale_dir = os.path.join(case_dir, "stale")
os.makedirs(stale_dir)
dead = subprocess.Popen(["true"])
dead.wait()
stale = os.path.join(stale_dir, ".tapeline-tmp-%d-0.json" % dead.pid)
open(stale, "w").write("half")
(rc, _), out = case("stale temporaries", ["pattern", "export", demo, "--json",
                                          os.path.join(stale_dir, "a.json")], None,
                    allow_success=True)
if rc != 0 or sorted(os.listdir(stale_dir)) != ["a.json"]:
    record_failure("case stale temporaries", "files %s" % os.listdir(stale_dir))

# A pattern database in a directory its reader cannot write (as another user when run as root).
ro_dir = os.path.join(case_dir, "read_only_db")
os.makedirs(ro_dir)
ro_db = os.path.join(ro_dir, "patterns.sqlite")
rc, _, err = run(["pattern", "import", demo, "--db", ro_db], ro_dir)
os.chmod(ro_dir, 0o555)
for p in (gen, case_dir, work):
    os.chmod(p, 0o755)
demote = None
if os.geteuid() == 0:
    def demote():
        os.setgid(65534)
        os.setuid(65534)
        limits()
p = subprocess.run([binary, "pattern", "list", "--db", ro_db], stdout=subprocess.PIPE,
                   stderr=subprocess.PIPE, preexec_fn=demote or limits, timeout=TIME_LIMIT_S)
results["runs"] += 1
if p.returncode != 0 or b"opened immutable" not in p.stderr or b"aaron" not in p.stdout.lower():
    record_failure("case read-only database", "exit %d: %r" % (p.returncode, p.stderr[:300]))
os.chmod(ro_dir, 0o755)

# A dense sample of a closed surface: every point gets a distance. Under the sanitizers (about
# 20 times slower here) an eighth of the points runs the same code.
n_cloud = 6250 if sanitized else 50000
cloud = os.path.join(gen, "ellipsoid_%d.xyz" % n_cloud)
subprocess.run([sys.executable, os.path.join(corpus, "make_ellipsoid.py"), cloud, str(n_cloud)],
               check=True)
(rc, _), out = case("%d-point ellipsoid, default --cell and --neighbours" % n_cloud,
                    ["geodesic", "distances", cloud, "--point-cloud", "--source", "0",
                     "--out", "{out}/d.txt"], None, allow_success=True, time_limit=900)
if rc == 0:
    values = open(os.path.join(out, "d.txt")).read().split()
    unreached = sum(1 for v in values if v == "inf")
    if len(values) != n_cloud or unreached:
        record_failure("case ellipsoid %d" % n_cloud, "%d values, %d inf" % (len(values),
                                                                              unreached))
else:
    record_failure("case ellipsoid %d" % n_cloud, "exit %s" % rc)

# --- command-line values: negative, non-numeric, huge, non-finite, empty, unicode digits ----------
# Each must be refused in one line naming the option (or, where listed, accepted for what it is).
bad_values = ["-1", "abc", "1e999", "99999999999999999999999", "nan", "inf", "", "\u0663",
              "\uff11", "1;2"]
value_slots = {
    "--source": ["geodesic", "distances", spot, "--source", "{v}", "--out", "{out}/d.txt"],
    "--window": ["geodesic", "distances", spot, "--source", "0", "--method", "gcf-window",
                 "--window", "{v}", "--out", "{out}/d.txt"],
    "--from": ["geodesic", "path", spot, "--from", "{v}", "--to", "1", "--out", "{out}/p.json"],
    "--cell": ["geodesic", "distances", sphere_points, "--point-cloud", "--source", "0",
               "--cell", "{v}", "--out", "{out}/d.txt"],
    "--generations": ["grade", demo, "--from", demo_set, "--to", demo_set, "--out",
                      "{out}/g.json", "--generations", "{v}"],
    "--max-target-ratio": ["grade", demo, "--from", demo_set, "--to", demo_set, "--out",
                           "{out}/g.json", "--generations", "0", "--max-target-ratio", "{v}"],
    "--units": ["measure", os.path.join(data, "bodies", "mh_female_average.obj"), "--units",
                "{v}", "--out", "{out}/m.json"],
}
value_accepted = set()
for slot, template in value_slots.items():
    for v in bad_values:
        argv = [a.replace("{v}", v) for a in template]
        case("%s %r" % (slot, v), argv, None, allow_success=(slot, v) in value_accepted)

# --- paths and names in other scripts are ordinary names --------------------------------------------
uni_dir = os.path.join(case_dir, "unicode")
os.makedirs(uni_dir)
uni_mesh = os.path.join(uni_dir, "\u00fcber \u540d\u524d \U0001F9F5.obj")
shutil.copy(spot, uni_mesh)
(rc, _), out = case("unicode input and output names",
                    ["geodesic", "distances", uni_mesh, "--source", "0",
                     "--out", "{out}/\u8ddd\u96e2 \u00e9.txt"], None, allow_success=True)
if rc != 0 or os.listdir(out) != ["\u8ddd\u96e2 \u00e9.txt"]:
    record_failure("case unicode names", "exit %s, files %s" % (rc, os.listdir(out)))

# --- a full disk: writes fail (file size limit, SIGXFSZ ignored so write() returns EFBIG) ---------


def small_disk():
    limits()
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))


full_disk = [("distances", ["geodesic", "distances", spot, "--source", "0",
                             "--out", "{out}/d.txt"]),
             ("pattern export", ["pattern", "export", demo, "--svg", "{out}/a.svg",
                                 "--json", "{out}/a.json"])]
if not sanitized:  # the same atomic writer as the two above; the body alone takes 40 s at -O0
    full_disk.append(("measure", ["measure", os.path.join(data, "bodies", "mh_female_average.obj"),
                                  "--units", "dm", "--out", "{out}/m.json", "--vit",
                                  "{out}/m.vit"]))
for name, argv in full_disk:
    case("full disk (%s)" % name, argv, r"tapeline: error: .*(write|space|large)",
         preexec=small_disk)

# --- a database another process holds locked: the writer waits, then says so -------------------
locked_db = os.path.join(case_dir, "locked.sqlite")
rc, _, err = run(["pattern", "import", demo, "--db", locked_db], case_dir)
holder = sqlite3.connect(locked_db, timeout=0, isolation_level=None)
holder.execute("BEGIN EXCLUSIVE")
(rc, err), out = case("database locked by another process",
                      ["pattern", "import", os.path.join(data, "patterns",
                                                         "aaron_cisFemaleAdult36.json"),
                       "--db", locked_db, "--replace"], r"locked|busy")
holder.execute("ROLLBACK")
holder.close()

# --- whole bodies measured: the measuring code end to end (under the sanitizers, the stage's
# check of it: landmarks, sections, tapes, self-checks, hole filling) -----------------------------


def holed_body(src, dst, low=0.002, high=0.005):
    """Writes the OBJ body SRC without its faces in the lowest LOW and the highest HIGH of its
    height (soles and crown cut open, as scans have them); returns the number of faces cut."""
    points, faces = [], []
    for line in open(src):
        t = line.split()
        if t and t[0] == "v":
            points.append([float(x) for x in t[1:4]])
        elif t and t[0] == "f":
            faces.append([int(x.split("/")[0]) for x in t[1:]])
    ys = [p[1] for p in points]
    y0, y1 = min(ys), max(ys)
    lo, hi = y0 + low * (y1 - y0), y1 - high * (y1 - y0)
    kept = [f for f in faces if not all(points[i - 1][1] < lo or points[i - 1][1] > hi
                                        for i in f)]
    with open(dst, "w") as out:
        out.writelines("v %.9g %.9g %.9g\n" % tuple(p) for p in points)
        out.writelines("f %s\n" % " ".join(map(str, f)) for f in kept)
    return len(faces) - len(kept)


bundled_body = os.path.join(data, "bodies", "mh_female_average.obj")
holed = os.path.join(gen, "mh_female_average_holes.obj")
faces_cut = holed_body(bundled_body, holed)
body_runs = [("OBJ body", bundled_body, 0), ("PLY body, flat chest",
                                             os.path.join(data, "bodies", "mh_thin_flat_chest.ply"),
                                             0), ("body with holes at soles and crown", holed, 3)]


measured = {}


def measure_body(run_index):
    name, path, least_holes = body_runs[run_index]
    (rc, err), out = case("measure " + name, ["measure", path, "--units", "dm", "--out",
                                              "{out}/m.json"], None, allow_success=True)
    if rc != 0:
        record_failure("case measure " + name, "exit %s: %s" % (rc, err.strip()[-300:]))
        return
    m = json.load(open(os.path.join(out, "m.json")))
    holes = m["report"]["holes"]
    if len(m["measurements"]) < 50 or m["missing"] or m["report"]["landmarks_missing"] or \
            len(holes) < least_holes:
        record_failure("case measure " + name,
                       "%d measurements, missing %s, %d landmarks missing, %d holes filled"
                       % (len(m["measurements"]), m["missing"],
                          m["report"]["landmarks_missing"], len(holes)))
    measured[path] = {x["name"]: x["value_mm"] for x in m["measurements"]}


if faces_cut < 20:
    record_failure("case body with holes", "only %d faces cut" % faces_cut)
with ThreadPoolExecutor(max_workers=2) as pool:
    list(pool.map(measure_body, range(len(body_runs))))
# The holes lie far from the torso's tapes: its girths are the closed body's.
if bundled_body in measured and holed in measured:
    for girth in ("bust_girth", "waist_girth", "hip_girth"):
        a, b = measured[bundled_body].get(girth), measured[holed].get(girth)
        if a is None or b is None or abs(a - b) > 1:
            record_failure("case body with holes", "%s %s mm closed, %s mm with holes"
                           % (girth, a, b))

# --- summary -------------------------------------------------------------------------------------
results["corpus_files"] = len(inputs)
results["commands"] = len(commands)
results["sweep_runs"] = sweep_runs
for f in results["failures"]:
    print("FAIL - " + f)
print("corpus: %d inputs x %d commands: %d runs, %d named-case runs; refused %d, accepted %d, "
      "crashes %d, hangs %d, runs leaving files %d; %d failures"
      % (len(inputs), len(commands), sweep_runs, results["runs"] - sweep_runs, results["refused"],
         results["accepted"], results["crashes"], results["hangs"], results["files_left"],
         len(results["failures"])))
if summary_path:
    json.dump(results, open(summary_path, "w"), indent=1)
sys.exit(1 if results["failures"] else 0)
