#!/usr/bin/python3
"""Runs `tapeline batch` on one manifest (population bodies x 2 designs) in several
configurations, one after the other on this machine, and writes a Markdown report: wall time,
throughput and speed-up against one rank, the distribution of the time per job, the
coordinator's bookkeeping per job, and a projection of a cluster run from the measured costs.

    batch_bench.py TAPELINE ROOT DATA WORK OUT.md [--resolution MM] [--bodies N]
"""
import argparse
import json
import os
import shutil
import socket
import sqlite3
import statistics
import subprocess
import sys
import time


def run(cmd, env=None):
    t0 = time.perf_counter()
    done = subprocess.run(cmd, capture_output=True, text=True, env=env)
    wall = time.perf_counter() - t0
    if done.returncode not in (0, 1):  # 1: some job failed, recorded in the database
        sys.exit(f"batch_bench.py: {' '.join(cmd)} exited {done.returncode}: {done.stderr[-500:]}")
    return wall, done


def percentile(xs, q):
    xs = sorted(xs)
    k = (len(xs) - 1) * q
    lo, hi = int(k), min(int(k) + 1, len(xs) - 1)
    return xs[lo] + (xs[hi] - xs[lo]) * (k - lo)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tapeline")
    ap.add_argument("root")
    ap.add_argument("data")
    ap.add_argument("work")
    ap.add_argument("out")
    ap.add_argument("--resolution", type=float, default=30)
    ap.add_argument("--bodies", type=int, default=40)
    a = ap.parse_args()
    pop = os.path.join(a.data, "bodies", "population")
    bodies = sorted(f for f in os.listdir(pop) if f.endswith(".ply"))[: a.bodies]
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    manifest = os.path.join(a.work, "jobs.jsonl")
    shirt = os.path.join(a.root, "data", "patterns", "shirt_mean_specification.json")
    aaron = os.path.join(a.root, "data", "patterns", "aaron_cisFemaleAdult36.json")
    base = os.path.join(a.root, "data", "patterns", "aaron_cisFemaleAdult36_measurements.json")
    with open(manifest, "w") as f:
        for b in bodies:
            body = os.path.join(pop, b)
            f.write(json.dumps({"body": body, "units": "dm", "pattern": shirt,
                                "steps": ["measure", "dress"],
                                "options": {"resolution_mm": a.resolution, "threads": "T"}}) + "\n")
            f.write(json.dumps({"body": body, "units": "dm", "pattern": aaron, "from": base,
                                "options": {"resolution_mm": a.resolution, "threads": "T",
                                            "without": ["aaron.armBinding",
                                                        "aaron.neckBinding"]}}) + "\n")
    text = open(manifest).read()
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    configs = [("1 rank, 1 thread per job", 1, 1), ("2 ranks, 1 thread per job", 2, 1),
               ("4 ranks on 2 cores (oversubscribed), 1 thread per job", 4, 1),
               ("1 rank, 2 TBB threads per job", 1, 2)]
    results = []
    for label, ranks, threads in configs:
        m = os.path.join(a.work, f"jobs_t{threads}.jsonl")
        open(m, "w").write(text.replace('"T"', str(threads)))
        out = os.path.join(a.work, f"np{ranks}_t{threads}")
        cmd = [a.tapeline, "batch", m, "--out", out]
        if ranks > 1:
            cmd = ["mpirun", "--oversubscribe", "-np", str(ranks)] + cmd
        print(f"{label}: {len(bodies) * 2} jobs", file=sys.stderr, flush=True)
        wall, done = run(cmd, env)
        rows = sqlite3.connect(os.path.join(out, "batch.sqlite")).execute(
            "select id, status, seconds, rank from jobs").fetchall()
        summary = json.load(open(os.path.join(out, "summary.json")))
        results.append({"label": label, "ranks": ranks, "threads": threads, "wall": wall,
                        "rows": rows, "run": summary["run"], "out": out})
        print(f"  {wall:.1f} s", file=sys.stderr, flush=True)

    w1 = results[0]["wall"]
    n = len(results[0]["rows"])
    lines = [f"# The crowd batch on this machine",
             "",
             f"`benchmarks/run_batch.sh build/apps/tapeline {a.resolution:g}`: {len(bodies)} "
             f"population bodies (MakeHuman, CC0) x 2 designs = {n} jobs, one run per row, one "
             f"after the other on {os.cpu_count()} cores ({socket.gethostname()}). Designs: the "
             "GarmentCode shirt as drafted (measure, dress) and the FreeSewing tank top graded to "
             "each body (measure, grade, dress; bindings left out). Drape at "
             f"{a.resolution:g} mm, the other options `dress`'s defaults.",
             "",
             "| run | wall s | jobs done | jobs failed | jobs per minute | speed-up vs 1 rank | "
             "coordinator ms per job |",
             "|---|---:|---:|---:|---:|---:|---:|"]
    for r in results:
        done = sum(1 for x in r["rows"] if x[1] == "done")
        failed = sum(1 for x in r["rows"] if x[1] == "failed")
        lines.append(f"| {r['label']} | {r['wall']:.1f} | {done} | {failed} | "
                     f"{60 * n / r['wall']:.2f} | {w1 / r['wall']:.2f} | "
                     f"{r['run']['coordinator_ms_per_job']:.3f} |")
    lines += ["", "Time per job (s), 1 rank and 1 thread (the job's own cost):", "",
              "| design | jobs | min | p10 | median | p90 | max | max / min |",
              "|---|---:|---:|---:|---:|---:|---:|---:|"]
    base_rows = results[0]["rows"]
    per_design = {}
    for jid, status, seconds, _ in base_rows:
        if status == "done":
            per_design.setdefault(jid.split("__")[-1], []).append(seconds)
    for design, xs in per_design.items():
        lines.append(f"| {design} | {len(xs)} | {min(xs):.1f} | {percentile(xs, 0.1):.1f} | "
                     f"{statistics.median(xs):.1f} | {percentile(xs, 0.9):.1f} | {max(xs):.1f} | "
                     f"{max(xs) / min(xs):.1f} |")
    # Determinism: every run's garments against the first run's, byte for byte.
    compared = differ = 0
    for r in results[1:]:
        for jid, status, _, _ in r["rows"]:
            mine = os.path.join(r["out"], "jobs", jid, "dressed.obj")
            first = os.path.join(results[0]["out"], "jobs", jid, "dressed.obj")
            if os.path.exists(mine) and os.path.exists(first):
                compared += 1
                differ += open(mine, "rb").read() != open(first, "rb").read()
    lines += ["", f"The garments of the other runs against the first, byte for byte: {compared} "
              f"compared, {differ} differ."]
    failure_lines = []
    for r in results:
        db = sqlite3.connect(os.path.join(r["out"], "batch.sqlite"))
        for jid, err in db.execute("select id, error from jobs where status = 'failed'"):
            failure_lines.append(f"- {r['label']}: `{jid}`: {err}")
    if failure_lines:
        lines += ["", "Failed jobs (the job's error line, per run):", ""] + failure_lines
    everyone = [s for xs in per_design.values() for s in xs]
    mean = statistics.mean(everyone)
    coord = max(r["run"]["coordinator_ms_per_job"] for r in results) / 1000
    # A cluster on paper: 10,000 characters x 5 garments on 100 nodes of 32 cores, one
    # single-threaded rank per core, the jobs' costs those measured here.
    jobs, ranks = 10000 * 5, 100 * 32
    compute = jobs * mean / ranks
    tail = max(everyone)
    serial = jobs * coord
    lines += ["",
              "## A cluster on paper",
              "",
              f"10,000 characters x 5 garments = {jobs:,} jobs on 100 nodes x 32 cores, one "
              f"single-threaded rank per core ({ranks:,} ranks), each job costing what it cost "
              f"here (mean {mean:.1f} s at {a.resolution:g} mm; a 10 mm drape costs about 10x "
              "more, see docs/garment.md):",
              "",
              "| part | figure |",
              "|---|---:|",
              f"| compute: jobs x mean cost / ranks | {compute:.0f} s ({compute / 3600:.2f} h) |",
              f"| dynamic dispatch tail: the longest job | {tail:.0f} s |",
              f"| rank 0 bookkeeping, serial: jobs x {1000 * coord:.3f} ms | {serial:.0f} s |",
              f"| rank 0 load: {ranks:,} ranks each asking every {mean:.1f} s | "
              f"{ranks / mean:.0f} requests/s, {100 * ranks / mean * coord:.1f} % of rank 0 |",
              f"| projected wall | {compute + tail:.0f} s ({(compute + tail) / 3600:.2f} h) |",
              "",
              "What would limit it: rank 0 answers one request at a time, so it saturates at "
              f"about {1 / coord:,.0f} requests per second (its bookkeeping is a SQLite update "
              "per job start and per result, in WAL mode) - far above the load here; at "
              "10 mm and more garments per character the load falls further. The file system: "
              "every job writes its folder (the dressed OBJ is 0.1-1 MB at this resolution, "
              "several MB at 10 mm) and renames it into place; 50,000 renames on a shared file "
              "system are cheap, the bytes are the cost. The results database stays on rank 0's "
              "node; only rank 0 opens it.",
              ""]
    open(a.out, "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
