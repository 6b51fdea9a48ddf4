#!/usr/bin/env python3
"""Thread scaling, whole process: every method of `ridt triangulate` on 1 to T threads beside
CGAL's range insert on one core and ridt's serial modes, on the same .bin file.

Each code runs as its own process, start to exit (reading the file included, writing nothing),
all codes in a new random order every repetition. For each code: the median wall time; the
median over repetitions of its time over CGAL's and over ridt's fastest serial mode (walking)
in the same repetition; the in-process triangulation and insertion times that `--stats json`
reports; the peak resident memory a point. Meant for a machine with many cores and nothing else
running: on 2 cores only 1 and 2 threads say anything.

  bench/scaling_table.py --build DIR [--sizes 1000000,10000000] [--dist uniform]
                         [--threads 1,2,4,8,16] [--methods partition,optimistic,pessimistic,batch]
                         [--dag-max-n 1000000] [--reps 5] [--out docs/scaling.md]

DIR holds `ridt` and `ridt_cgal_triangulate`. The history-DAG methods (serial DAG, optimistic,
pessimistic, batch) run only up to --dag-max-n points (they need ~300 bytes a point and take
minutes a repetition at 10^7). Writes the Markdown page and, beside it, results/scaling.csv with
every run.
"""
import argparse
import csv
import json
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time

from process_table import compiler, machine, tools

DAG_METHODS = {"optimistic", "pessimistic", "batch"}


def run_once(cmd):
    """Wall seconds, peak resident bytes and the parsed `--stats json` (None for CGAL)."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out = proc.stdout.read()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    err = proc.stderr.read().decode(errors="replace")
    proc.stdout.close()
    proc.stderr.close()
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"{' '.join(cmd)} failed: {err.strip()}")
    stats = json.loads(out) if out.lstrip().startswith(b"{") else None
    return wall, usage.ru_maxrss * 1024, stats


def codes_for(n, a, ridt, cgal):
    """(name, method, threads, command builder) for every code at size n."""
    dag = n <= a.dag_max_n
    codes = [("CGAL range insert", "cgal", 1, lambda f: [cgal, f]),
             ("ridt serial (walk)", "serial walk", 1,
              lambda f: [ridt, "triangulate", f, "--locate", "walk", "--stats", "json"])]
    if dag:
        codes.append(("ridt serial (DAG)", "serial dag", 1,
                      lambda f: [ridt, "triangulate", f, "--locate", "dag", "--stats", "json"]))
    for method in a.methods.split(","):
        if method in DAG_METHODS and not dag:
            continue
        for t in [int(s) for s in a.threads.split(",")]:
            codes.append((f"ridt {method} {t}", method, t,
                          lambda f, m=method, t=t: [ridt, "triangulate", f, "--method", m,
                                                    "--threads", str(t), "--stats", "json"]))
    return codes


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--sizes", default="1000000,10000000")
    ap.add_argument("--dist", default="uniform")
    ap.add_argument("--threads", default="1,2,4,8,16")
    ap.add_argument("--methods", default="partition,optimistic,pessimistic,batch")
    ap.add_argument("--dag-max-n", type=int, default=1000000)
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--out", default=None, help="Markdown page; results/scaling.csv beside it")
    a = ap.parse_args()
    ridt, cgal = tools(a.build)

    runs, summary = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for n in [int(s) for s in a.sizes.split(",")]:
            points = os.path.join(tmp, f"{a.dist}-{n}.bin")
            subprocess.run([ridt, "generate", "--dist", a.dist, "-n", str(n), "-o", points], check=True)
            codes = codes_for(n, a, ridt, cgal)
            per = {name: [] for name, *_ in codes}
            for rep in range(a.reps):
                order = list(codes)
                random.shuffle(order)
                this = {}
                for name, method, t, cmd in order:
                    wall, peak, stats = run_once(cmd(points))
                    this[name] = (wall, peak, stats)
                for name, method, t, _ in codes:
                    wall, peak, stats = this[name]
                    row = {"n": n, "dist": a.dist, "code": name, "method": method, "threads": t, "rep": rep,
                           "wall_s": wall, "peak_bytes": peak,
                           "triangulate_s": stats["time_triangulate_s"] if stats else "",
                           "insert_s": stats["time_insert_s"] if stats else "",
                           "vs_cgal": wall / this["CGAL range insert"][0],
                           "vs_serial_walk": this["ridt serial (walk)"][0] / wall}
                    runs.append(row)
                    per[name].append(row)
                print(f"n={n} repetition {rep + 1}/{a.reps} done", file=sys.stderr, flush=True)
            walk_tri = statistics.median(r["triangulate_s"] for r in per["ridt serial (walk)"])
            for name, method, t, _ in codes:
                rs = per[name]
                tri = [r["triangulate_s"] for r in rs if r["triangulate_s"] != ""]
                ins = [r["insert_s"] for r in rs if r["insert_s"] != ""]
                label = name if method in ("cgal", "serial walk", "serial dag") else f"ridt {method}"
                s = {"n": n, "code": name, "label": label, "method": method, "threads": t,
                     "wall_s": statistics.median(r["wall_s"] for r in rs),
                     "min_s": min(r["wall_s"] for r in rs), "max_s": max(r["wall_s"] for r in rs),
                     "vs_cgal": statistics.median(r["vs_cgal"] for r in rs),
                     "vs_serial_walk": statistics.median(r["vs_serial_walk"] for r in rs),
                     "triangulate_s": statistics.median(tri) if tri else None,
                     "in_process_speedup": walk_tri / statistics.median(tri) if tri else None,
                     "insert_s": statistics.median(ins) if ins else None,
                     "bytes_per_point": statistics.median(r["peak_bytes"] for r in rs) / n}
                summary.append(s)
                print(f"{n:>9} {name:<24} {s['wall_s']:8.3f} s  {s['vs_cgal']:.3f} of CGAL  "
                      f"x{s['vs_serial_walk']:.2f} over serial walk  {s['bytes_per_point']:6.1f} B/pt",
                      flush=True)
    if a.out:
        write_page(a, runs, summary)


def write_page(a, runs, summary):
    results = os.path.join(os.path.dirname(a.out) or ".", "results")
    os.makedirs(results, exist_ok=True)
    with open(os.path.join(results, "scaling.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(runs[0].keys()))
        w.writeheader()
        w.writerows(runs)
    cmd = (f"bench/scaling_table.py --build {a.build} --sizes {a.sizes} --dist {a.dist} --threads {a.threads} "
           f"--methods {a.methods} --dag-max-n {a.dag_max_n} --reps {a.reps} --out {a.out}")
    with open(a.out, "w") as f:
        f.write("# Thread scaling\n\n")
        f.write(f"Written by `{cmd}` (through `scripts/scaling.sh`) on {time.strftime('%Y-%m-%d')}. "
                f"Machine: {machine()}. Compiler: {compiler(a.build)}.\n\n")
        f.write("Every code is one process on the same `.bin` file of float64 pairs, from its start to "
                "its exit: read, triangulate, write nothing. A repetition runs every code once in a new "
                "random order. Time: the median wall seconds (min to max). *of CGAL*: the median of "
                "the code's time over CGAL's in the same repetition (CGAL runs on one core: it has no "
                "threaded 2D triangulation). *× serial walk*: the median of ridt's fastest serial mode's "
                "time over the code's, in the same repetition. *in-process ×*: the same for the "
                "triangulation call alone (`--stats json`'s `time_triangulate_s`), without the "
                "process's start, the read and the exit. Insertion: the insertion phase's seconds "
                "(the rest of the call is the input's scan, the order, the points' copy and the "
                "finish). Peak: the process's peak resident memory a point, the input's 16 bytes "
                "included. Every run: [results/scaling.csv](results/scaling.csv).\n\n"
                "![Speed over ridt's serial walk against threads](results/scaling.png)\n\n")
        for n in sorted({s["n"] for s in summary}):
            f.write(f"## {n:,} {a.dist} points\n\n")
            f.write("| code | threads | time s | min to max | of CGAL | × serial walk | in-process × "
                    "| insertion s | peak B/pt |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n")
            for s in summary:
                if s["n"] != n:
                    continue
                ip = f"{s['in_process_speedup']:.2f}" if s["in_process_speedup"] else ""
                ins = f"{s['insert_s']:.3f}" if s["insert_s"] is not None else ""
                f.write(f"| {s['label']} "
                        f"| {s['threads']} | {s['wall_s']:.3f} | {s['min_s']:.3f} to {s['max_s']:.3f} "
                        f"| {s['vs_cgal']:.2f} | {s['vs_serial_walk']:.2f} | {ip} | {ins} "
                        f"| {s['bytes_per_point']:.0f} |\n")
            f.write("\n")


if __name__ == "__main__":
    main()
