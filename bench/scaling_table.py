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
                         [--dag-max-n 1000000] [--reps 5] [--dists normal,grid,clusters]
                         [--huge 100000000] [--out docs/scaling.md]

DIR holds `ridt` and `ridt_cgal_triangulate`. The history-DAG methods (serial DAG, optimistic,
pessimistic, batch) run only up to --dag-max-n points (they need ~300 bytes a point and take
minutes a repetition at 10^7). For the partition method and the serial walk, the page also
gives each phase of the run (`--stats json`'s times) on every thread count. --dists: the
partition method on the most threads on those distributions at the largest size, beside the
same on --dist; --huge N: the partition method on the most threads on N points of --dist (no
peer: CGAL and the serial walk take minutes there). Writes the Markdown page and, beside it,
results/scaling.csv with every run of --sizes and results/scaling_more.csv with the rest.
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
              lambda f: [ridt, "triangulate", f, "--method", "serial", "--locate", "walk", "--stats", "json"])]
    if dag:
        codes.append(("ridt serial (DAG)", "serial dag", 1,
                      lambda f: [ridt, "triangulate", f, "--method", "serial", "--locate", "dag", "--stats", "json"]))
    for method in a.methods.split(","):
        if method in DAG_METHODS and not dag:
            continue
        for t in [int(s) for s in a.threads.split(",")]:
            codes.append((f"ridt {method} {t}", method, t,
                          lambda f, m=method, t=t: [ridt, "triangulate", f, "--method", m,
                                                    "--threads", str(t), "--stats", "json"]))
    return codes


PHASES = (("read", "time_read_s"), ("scan", "time_scan_s"), ("mesh", "time_mesh_s"),
          ("order", "time_order_s"), ("copy", "time_copy_s"), ("insert", "time_insert_s"),
          ("finish", "time_finish_s"))
# The partition method's insertion in parts (`--stats json`): the second passes, the points
# inserted on one thread and their time, the threads' waits summed.
PARTS = (("second", "time_second_pass_s"), ("alone_s", "time_alone_s"), ("alone", "alone"),
         ("wait", "time_wait_s"))


def measure(files, codes, reps, n, label):
    """Every code on its file, `reps` times in a new random order each time. codes: (name,
    method, threads, file key, command builder); the first code whose name is "CGAL range
    insert" or "ridt serial (walk)" on the same file gives the ratios. Returns (runs, summary)."""
    per = {name: [] for name, *_ in codes}
    for rep in range(reps):
        order = list(codes)
        random.shuffle(order)
        this = {name: run_once(cmd(files[key])) for name, _, _, key, cmd in order}
        for name, method, t, key, _ in codes:
            wall, peak, stats = this[name]
            row = {"n": n, "dist": key, "code": name, "method": method, "threads": t, "rep": rep,
                   "wall_s": wall, "peak_bytes": peak}
            for k in ("time_triangulate_s",) + tuple(f for _, f in PHASES + PARTS):
                row[k] = stats.get(k, "") if stats else ""
            for ref, col in (("CGAL range insert", "vs_cgal"), ("ridt serial (walk)", "vs_serial_walk")):
                found = [c for c in codes if c[0].startswith(ref) and c[3] == key]
                row[col] = (wall / this[found[0][0]][0] if col == "vs_cgal" else this[found[0][0]][0] / wall) \
                    if found else ""
            per[name].append(row)
        print(f"{label}: repetition {rep + 1}/{reps} done", file=sys.stderr, flush=True)
    runs, summary = [], []
    for name, method, t, key, _ in codes:
        rs = per[name]
        runs += rs
        med = lambda k: statistics.median(r[k] for r in rs) if rs[0][k] != "" else None  # noqa: E731
        s = {"n": n, "dist": key, "code": name, "method": method, "threads": t,
             "label": name if method in ("cgal", "serial walk", "serial dag") else f"ridt {method}",
             "wall_s": med("wall_s"), "min_s": min(r["wall_s"] for r in rs), "max_s": max(r["wall_s"] for r in rs),
             "vs_cgal": med("vs_cgal"), "vs_serial_walk": med("vs_serial_walk"),
             "triangulate_s": med("time_triangulate_s"), "bytes_per_point": med("peak_bytes") / n}
        for phase, field in PHASES + PARTS:
            s[phase] = med(field)
        summary.append(s)
        ratio = f"{s['vs_cgal']:.3f} of CGAL  " if s["vs_cgal"] is not None else ""
        print(f"{n:>10} {key:<9} {name:<24} {s['wall_s']:8.3f} s  {ratio}{s['bytes_per_point']:6.1f} B/pt",
              flush=True)
    return runs, summary


def generate(ridt, tmp, dist, n):
    path = os.path.join(tmp, f"{dist}-{n}.bin")
    subprocess.run([ridt, "generate", "--dist", dist, "-n", str(n), "-o", path], check=True)
    return path


def partition_code(ridt, t, key):
    return (f"ridt partition {t} ({key})", "partition", t, key,
            lambda f: [ridt, "triangulate", f, "--method", "partition", "--threads", str(t), "--stats", "json"])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--sizes", default="1000000,10000000")
    ap.add_argument("--dist", default="uniform")
    ap.add_argument("--threads", default="1,2,4,8,16")
    ap.add_argument("--methods", default="partition,optimistic,pessimistic,batch")
    ap.add_argument("--dag-max-n", type=int, default=1000000)
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--dists", default="", help="other distributions, at the largest size")
    ap.add_argument("--huge", type=int, default=0, help="points for the partition method alone")
    ap.add_argument("--out", default=None, help="Markdown page; results/scaling.csv beside it")
    a = ap.parse_args()
    ridt, cgal = tools(a.build)
    most = max(int(t) for t in a.threads.split(","))
    runs, summary, more_runs, more = [], [], [], []
    with tempfile.TemporaryDirectory() as tmp:
        for n in [int(s) for s in a.sizes.split(",")]:
            files = {a.dist: generate(ridt, tmp, a.dist, n)}
            codes = [(name, method, t, a.dist, cmd) for name, method, t, cmd in codes_for(n, a, ridt, cgal)]
            r, s = measure(files, codes, a.reps, n, f"n={n}")
            runs += r
            summary += s
            os.remove(files[a.dist])
        if a.dists:
            n = max(int(s) for s in a.sizes.split(","))
            dists = [a.dist] + a.dists.split(",")
            files = {d: generate(ridt, tmp, d, n) for d in dists}
            codes = [partition_code(ridt, most, d) for d in dists]
            r, s = measure(files, codes, a.reps, n, f"distributions at n={n}")
            more_runs += r
            more += s
            for f in files.values():
                os.remove(f)
        if a.huge:
            files = {a.dist: generate(ridt, tmp, a.dist, a.huge)}
            r, s = measure(files, [partition_code(ridt, most, a.dist)], max(3, a.reps // 2), a.huge, f"n={a.huge}")
            more_runs += r
            more += s
    if a.out:
        write_page(a, runs, summary, more_runs, more)


def write_csv(path, runs):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(runs[0].keys()))
        w.writeheader()
        w.writerows(runs)


def phase_table(f, rows):
    """Each phase's median seconds for the rows given (one code a row), and the speed-up of
    each phase from the partition method's one thread (else the first row) to the last row."""
    f.write("| code | threads | " + " | ".join(p for p, _ in PHASES) + " | rest | whole process |\n")
    f.write("|---|---:|" + "---:|" * (len(PHASES) + 2) + "\n")

    def rest(s):
        return s["wall_s"] - s["triangulate_s"] - s["read"]
    for s in rows:
        f.write(f"| {s['label']} | {s['threads']} | " + " | ".join(f"{s[p]:.3f}" for p, _ in PHASES) +
                f" | {rest(s):.3f} | {s['wall_s']:.3f} |\n")
    ones = [s for s in rows if s["method"] == "partition" and s["threads"] == 1]
    first, last = (ones or rows)[0], rows[-1]
    ratio = [f"{first[p] / last[p]:.1f}" if last[p] else "" for p, _ in PHASES]
    f.write(f"| speed-up, {first['label']} {first['threads']} to {last['threads']} threads | | " + " | ".join(ratio) +
            f" | {rest(first) / rest(last):.1f} | {first['wall_s'] / last['wall_s']:.1f} |\n\n")


def write_page(a, runs, summary, more_runs, more):
    results = os.path.join(os.path.dirname(a.out) or ".", "results")
    os.makedirs(results, exist_ok=True)
    write_csv(os.path.join(results, "scaling.csv"), runs)
    if more_runs:
        write_csv(os.path.join(results, "scaling_more.csv"), more_runs)
    cmd = (f"bench/scaling_table.py --build {a.build} --sizes {a.sizes} --dist {a.dist} --threads {a.threads} "
           f"--methods {a.methods} --dag-max-n {a.dag_max_n} --reps {a.reps}"
           + (f" --dists {a.dists}" if a.dists else "") + (f" --huge {a.huge}" if a.huge else "") + f" --out {a.out}")
    with open(a.out, "w") as f:
        f.write("# Thread scaling\n\n")
        f.write(f"Written by `{cmd}` (through `scripts/scaling.sh`) on {time.strftime('%Y-%m-%d')}. "
                f"Machine: {machine()}. Compiler: {compiler(a.build)}.\n\n")
        f.write("Every code is one process on the same `.bin` file of float64 pairs, from its start to "
                "its exit: read, triangulate, write nothing. A repetition runs every code once in a new "
                "random order. Time: the median wall seconds (min to max). *of CGAL*: the median of "
                "the code's time over CGAL's in the same repetition (CGAL runs on one core: it has no "
                "threaded 2D triangulation). *× serial walk*: the median of ridt's fastest serial mode's "
                "(`--method serial`, walking) time over the code's, in the same repetition. "
                "*in-process ×*: the same for the triangulation call alone (`--stats json`'s "
                "`time_triangulate_s`), without the process's start, the read and the exit. Insertion: "
                "the insertion phase's seconds; the phase tables give the rest. Peak: the process's peak "
                "resident memory a point, the input's 16 bytes included. Every run: "
                "[results/scaling.csv](results/scaling.csv)"
                + (" and [results/scaling_more.csv](results/scaling_more.csv)" if more_runs else "") + ".\n\n"
                "![Speed over ridt's serial walk against threads](results/scaling.png)\n\n")
        for n in sorted({s["n"] for s in summary}):
            at_n = [s for s in summary if s["n"] == n]
            walk_tri = next(s["triangulate_s"] for s in at_n if s["method"] == "serial walk")
            f.write(f"## {n:,} {a.dist} points\n\n")
            f.write("| code | threads | time s | min to max | of CGAL | × serial walk | in-process × "
                    "| insertion s | peak B/pt |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n")
            for s in at_n:
                ip = f"{walk_tri / s['triangulate_s']:.2f}" if s["triangulate_s"] else ""
                ins = f"{s['insert']:.3f}" if s["insert"] is not None else ""
                f.write(f"| {s['label']} "
                        f"| {s['threads']} | {s['wall_s']:.3f} | {s['min_s']:.3f} to {s['max_s']:.3f} "
                        f"| {s['vs_cgal']:.2f} | {s['vs_serial_walk']:.2f} | {ip} | {ins} "
                        f"| {s['bytes_per_point']:.0f} |\n")
            f.write(f"\n### Phases at {n:,} points\n\n"
                    "Median seconds of each phase (`--stats json`): the file read, the points' extent, "
                    "the walking kernel's memory made present, the insertion order (BRIO), the points "
                    "copied in that order, the insertion, the finish (the mesh into the result's "
                    "arrays); *rest*: the whole process less the read and the call (the process's start "
                    "and exit, memory given back).\n\n")
            phase_table(f, [s for s in at_n if s["method"] in ("serial walk", "partition")])
            parts_table(f, [s for s in at_n if s["method"] == "partition"])
        if more:
            write_more(f, a, more)


def parts_table(f, rows, key="threads"):
    """The partition method's insertion in parts, one row a code."""
    rows = [s for s in rows if s.get("second") is not None]
    if not rows:
        return
    f.write("The partition method's insertion in parts (`--stats json`, medians): the first passes "
            "(the rest of the insertion), the second passes (`time_second_pass_s`), the points "
            "left to one thread and its seconds (`alone`, `time_alone_s`: the small rounds and "
            "what both passes put off), and the threads' waits for the slowest at the passes' ends "
            "(`time_wait_s`, summed over threads, and a thread's mean).\n\n"
            f"| {key} | insert | first passes | second passes | one thread | points alone "
            "| waits summed | a thread's wait |\n|---|---:|---:|---:|---:|---:|---:|---:|\n")
    for s in rows:
        first = s["insert"] - s["second"] - s["alone_s"]
        f.write(f"| {s[key]} | {s['insert']:.3f} | {first:.3f} | {s['second']:.3f} | {s['alone_s']:.3f} "
                f"| {s['alone']:,.0f} | {s['wait']:.3f} | {s['wait'] / s['threads']:.3f} |\n")
    f.write("\n")


def write_more(f, a, more):
    dists = [s for s in more if s["n"] != a.huge]
    if dists:
        n = dists[0]["n"]
        base = next(s for s in dists if s["dist"] == a.dist)
        f.write(f"## Distributions at {n:,} points, {base['threads']} threads\n\n"
                f"The partition method on each distribution (`ridt generate --dist`), all in one "
                f"interleaved series; *of {a.dist}*: the median time over {a.dist}'s.\n\n"
                "| distribution | time s | min to max | of " + a.dist + " | peak B/pt |\n|---|---:|---:|---:|---:|\n")
        for s in dists:
            f.write(f"| {s['dist']} | {s['wall_s']:.3f} | {s['min_s']:.3f} to {s['max_s']:.3f} | "
                    f"{s['wall_s'] / base['wall_s']:.2f} | {s['bytes_per_point']:.0f} |\n")
        f.write("\n")
        phase_rows = [dict(s, label=s["dist"]) for s in dists]
        f.write("| distribution | threads | " + " | ".join(p for p, _ in PHASES) + " | rest | whole process |\n")
        f.write("|---|---:|" + "---:|" * (len(PHASES) + 2) + "\n")
        for s in phase_rows:
            f.write(f"| {s['label']} | {s['threads']} | " + " | ".join(f"{s[p]:.3f}" for p, _ in PHASES) +
                    f" | {s['wall_s'] - s['triangulate_s'] - s['read']:.3f} | {s['wall_s']:.3f} |\n")
        f.write("\n")
        parts_table(f, dists, key="dist")
    huge = [s for s in more if s["n"] == a.huge]
    if huge:
        s = huge[0]
        f.write(f"## {a.huge:,} {a.dist} points\n\n"
                f"The partition method on {s['threads']} threads alone (CGAL and the serial walk take "
                f"a minute and more here): {s['wall_s']:.3f} s whole process ({s['min_s']:.3f} to "
                f"{s['max_s']:.3f}), {s['bytes_per_point']:.0f} bytes a point at the peak.\n\n")
        f.write("| code | threads | " + " | ".join(p for p, _ in PHASES) + " | rest | whole process |\n")
        f.write("|---|---:|" + "---:|" * (len(PHASES) + 2) + "\n")
        f.write(f"| {s['label']} | {s['threads']} | " + " | ".join(f"{s[p]:.3f}" for p, _ in PHASES) +
                f" | {s['wall_s'] - s['triangulate_s'] - s['read']:.3f} | {s['wall_s']:.3f} |\n\n")
        parts_table(f, huge)


if __name__ == "__main__":
    main()
