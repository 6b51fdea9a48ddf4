#!/usr/bin/python3
"""Writes docs/performance.md from the tables that scripts/report.sh measured (docs/results/).

    bench/report.py --results docs/results --commands COMMANDS.txt --mode full|quick
                    --out docs/performance.md

COMMANDS.txt: one line a benchmark, its name and its command line separated by a tab. Every
figure on the page is read from a file under --results; the paper's own figures are quoted
from its Tables 1 and 3 and its section on Fig. 8.
"""
import argparse
import csv
import datetime
import os
import platform
import subprocess
from collections import defaultdict

# The paper's Table 1: serial seconds on a 500 MHz Pentium III, by n and distribution.
PAPER_TABLE1 = {
    100: (0.006, 0.012, 0.003, 0.010), 500: (0.031, 0.041, 0.031, 0.040),
    1000: (0.090, 0.087, 0.069, 0.088), 5000: (0.516, 0.516, 0.403, 0.522),
    10000: (1.112, 1.131, 0.891, 1.113), 50000: (6.544, 6.594, 5.403, 6.506),
    100000: (14.000, 14.122, 11.644, 13.653), 500000: (86.556, 86.000, 71.140, 77.812),
    1000000: (193.747, 193.153, 151.003, 158.790)}
DISTS = ("uniform", "normal", "grid", "clusters")
# The paper's Table 3 (two Pentium III processors, uniform points): n -> for 1 and 2 threads
# (total, insertion, critical section, waiting) in seconds.
PAPER_TABLE3 = {
    1000: ((0.076, 0.063, 0.024, 0.001), (0.058, 0.044, 0.017, 0.006)),
    10000: ((1.048, 0.898, 0.283, 0.014), (0.683, 0.533, 0.164, 0.052)),
    50000: ((6.200, 5.364, 1.389, 0.702), (3.960, 3.117, 0.819, 0.214)),
    100000: ((13.750, 11.860, 2.823, 0.142), (8.749, 6.849, 1.647, 0.409)),
    500000: ((87.000, 68.000, 14.643, 0.714), (58.276, 38.499, 8.359, 2.027)),
    1000000: ((200.400, 143.000, 29.807, 1.441), (135.400, 78.600, 16.893, 4.130))}


def rows(results, name):
    path = os.path.join(results, name)
    if not os.path.exists(path):
        raise SystemExit(f"report.py: {path} is missing: run scripts/report.sh")
    with open(path) as f:
        return list(csv.DictReader(f))


def machine():
    cpu = next((line.split(":", 1)[1].strip() for line in open("/proc/cpuinfo")
                if line.startswith("model name")), platform.processor())
    mem = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2**30
    return f"{cpu}, {os.cpu_count()} hardware threads, {mem:.0f} GiB, {platform.system()} {platform.release()}"


def compiler():
    try:
        return subprocess.run(["c++", "--version"], capture_output=True, text=True).stdout.splitlines()[0]
    except (OSError, IndexError):
        return "unknown"


def commit():
    def git(*args):
        return subprocess.run(["git", *args], capture_output=True, text=True).stdout.strip()
    head = git("rev-parse", "--short", "HEAD") or "unknown"
    dirty = git("status", "--porcelain", "--untracked-files=no", "--", "src", "include", "tools", "bench")
    return head + (" with uncommitted changes to the sources" if dirty else "")


def n_text(n):
    return f"{int(n):,}"


def table(header, body, align=None):
    align = align or ["---:"] * len(header)
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join(align) + "|"]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in body]
    return "\n".join(lines)


def process_section(results):
    data = rows(results, "process.csv")
    codes = []
    for r in data:
        if r["code"] not in codes and not r["code"].startswith("CGAL"):
            codes.append(r["code"])
    serial = next((c for c in codes if c.startswith("ridt serial")), None)
    threaded = next((c for c in codes if c.startswith("ridt partition")), None)
    by = defaultdict(dict)
    for r in data:
        by[(int(r["n"]), r["dist"])][r["code"]] = r
    body = []
    for (n, dist), got in sorted(by.items(), key=lambda kv: (kv[0][0], DISTS.index(kv[0][1]))):
        cgal = next(v for k, v in got.items() if k.startswith("CGAL"))
        row = [n_text(n), dist, f"{float(cgal['median_s']):.3f}", f"{float(cgal['bytes_per_point']):.0f}"]
        for c in codes:
            r = got.get(c)
            row.append(f"{float(r['paired_ratio']):.2f} ({float(r['bytes_per_point']):.0f})" if r else "–")
        if serial and threaded:
            a, b = got.get(serial), got.get(threaded)
            row.append(f"{float(a['paired_ratio']) / float(b['paired_ratio']):.2f}" if a and b else "–")
        body.append(row)
    header = ["n", "distribution", "CGAL s", "CGAL B/pt"] + [f"{c}: ratio (B/pt)" for c in codes]
    speedup = ""
    if serial and threaded:
        header.append(f"{threaded[5:]} over {serial[5:]}")
        speedup = (f"The last column: how many times faster {threaded[5:]} ran than {serial[5:]}, the ratio "
                   "of their paired ratios. ")
    return (
        "## Whole process against CGAL\n\n"
        "Each code is one process on a `.bin` file of float64 pairs: read, triangulate, write nothing. "
        "CGAL is `Delaunay_triangulation_2` (Epick) with its range insert, which sorts the points "
        "along a curve. Ratio: the median over repetitions of ridt's time over CGAL's in the same "
        "repetition (below 1: ridt is faster); B/pt: the process's peak resident memory a point, the "
        "input's 16 bytes included. " + speedup + "Spread and medians: "
        "[results/process.md](results/process.md).\n\n"
        + table(header, body, ["---:", "---"] + ["---:"] * (len(header) - 2)) + "\n\n"
        "This machine's two cores are shared with others, so its 2-thread figures are noisy. "
        "[scaling.md](scaling.md), written by `scripts/scaling.sh` on a 16-core machine with nothing "
        "else running, has every method on 1 to 16 threads at 10^6 and 10^7 points, and "
        "[results/scaling_process.md](results/scaling_process.md) this table's 2-thread runs taken "
        "there.\n")


def peers_section(results):
    data = rows(results, "peers.csv")
    sizes = sorted({int(r["n"]) for r in data})
    out = ["## Against other codes\n",
           "In one process, on the same points, every code once a repetition in a new random order: "
           "ridt in each of its modes, CGAL, and Triangle, Qhull and delaunator where installed. Seconds "
           "(ratio to CGAL's median), and the memory a run adds a point, the output included. "
           "Full output: [results/peers.txt](results/peers.txt).\n"]
    for n in sizes:
        mine = [r for r in data if int(r["n"]) == n]
        codes = []
        for r in mine:
            if r["code"] not in codes:
                codes.append(r["code"])
        dists = [d for d in DISTS if any(r["distribution"] == d for r in mine)]
        body = []
        for c in codes:
            row, mem = [c], []
            for d in dists:
                r = next((r for r in mine if r["code"] == c and r["distribution"] == d), None)
                row.append(f"{float(r['median_s']):.4f} ({float(r['ratio_to_cgal']):.2f})" if r else "–")
                if r:
                    mem.append(float(r["added_bytes_per_point"]))
            row.append(f"{min(mem):.0f}–{max(mem):.0f}" if mem else "–")
            body.append(row)
        out.append(f"\n{n_text(n)} points:\n\n" + table(["code"] + dists + ["B/pt"], body,
                                                       ["---"] + ["---:"] * (len(dists) + 1)) + "\n")
    return "\n".join(out)


def serial_section(results):
    data = rows(results, "serial.csv")
    by = {(r["distribution"], int(r["n"])): r for r in data}
    sizes = sorted({int(r["n"]) for r in data})
    body = []
    for n in sizes:
        row = [n_text(n)]
        for i, d in enumerate(DISTS):
            r = by.get((d, n))
            row += [f"{float(r['ridt_s']):.4f}", f"{float(r['ratio']):.2f}"] if r else ["–", "–"]
            row.append(f"{PAPER_TABLE1[n][i]:.3f}" if n in PAPER_TABLE1 else "–")
        body.append(row)
    header = ["n"]
    for d in DISTS:
        header += [f"{d} s", "÷ CGAL", "paper s"]
    fig8 = []
    for n in sizes:
        r = by.get(("uniform", n))
        if r:
            fig8.append([n_text(n)] + [f"{100 * float(r[k]):.1f} %" for k in ("locate_share", "split_share", "legalize_share")])
    return (
        "## The paper's Table 1 and Fig. 8: the serial algorithm\n\n"
        "ridt's serial method in the paper's configuration: random order, location by the history "
        "DAG (in rounds along a curve, ridt's schedule), against CGAL on the same points in the same "
        "run (÷ CGAL: ridt's time over CGAL's), beside the paper's seconds on a 500 MHz Pentium III. "
        "Medians; output: [results/serial.txt](results/serial.txt).\n\n"
        + table(header, body) + "\n\n"
        "Fig. 8, the share of the insertion time in each phase, uniform points. Profiled runs: "
        "every point descends from the DAG's root, as in the paper, and three clock reads a point "
        "add their cost to each phase. The paper measured 50 % (n = 100) to 64.5 % "
        "(n = 500,000) in location, 58.9 % on average.\n\n"
        + table(["n", "location", "split", "legalization"], fig8) + "\n")


def threads_tables(data):
    out = []
    for dist in [d for d in DISTS if any(r["distribution"] == d for r in data)]:
        body = []
        for r in data:
            if r["distribution"] != dist:
                continue
            body.append([n_text(r["n"]), r["method"], r["threads"], f"{float(r['total_s']):.4f}",
                         f"{float(r['insert_s']):.4f}", f"{float(r['critical_s']):.4f}",
                         f"{float(r['wait_s']):.4f}", f"{float(r['speedup']):.2f}"])
        out.append(f"\n{dist}:\n\n" + table(
            ["n", "method", "threads", "total s", "insertion s", "critical s", "waiting s", "speedup"], body,
            ["---:", "---"] + ["---:"] * 6))
    return "\n".join(out) + "\n"


def threads_section(results):
    data = rows(results, "threads.csv")
    dists = [d for d in DISTS if any(r["distribution"] == d for r in data)]
    figures = "\n".join(f"![speedup, {d}](results/speedup_{d}.png) ![Fig. 11, {d}](results/fig11_{d}.png) "
                        f"![Fig. 14, {d}](results/fig14_{d}.png)" for d in dists)
    return (
        "## The paper's Tables 2 and 3: the threaded methods\n\n"
        "Every threaded method at each thread count, in the paper's random order with ridt's "
        "location in rounds (docs/threads.md explains the methods). Each repetition runs serial ridt "
        "and every configuration once in a shuffled order; speedup is the median of the "
        "per-repetition ratios serial ÷ method of the whole call. Critical: time holding the lock "
        "(pessimistic; `paper` is its variant that locks from the leaf's parent) or holding "
        "triangles (optimistic); waiting: for the lock and at the ends of rounds, summed over "
        f"threads. This machine has {os.cpu_count()} hardware threads: runs with more are "
        "oversubscribed and show overhead, not scaling. Output: [results/threads.txt](results/threads.txt).\n"
        + threads_tables(data) + "\n" + figures + "\n")


def table3_section(results):
    data = rows(results, "table3.csv")
    by = {(int(r["n"]), r["method"], int(r["threads"])): r for r in data}
    body = []
    for n in sorted({int(r["n"]) for r in data}):
        one, two = by.get((n, "paper", 1)), by.get((n, "paper", 2))
        if not (one and two):
            continue
        row = [n_text(n), f"{float(one['total_s']):.4f}", f"{float(two['total_s']):.4f}",
               f"{float(one['total_s']) / float(two['total_s']):.2f}",
               f"{float(two['critical_s']) / float(two['insert_s']):.2f}"]
        p = PAPER_TABLE3.get(n)
        row += [f"{p[0][0]:.3f}", f"{p[1][0]:.3f}", f"{p[0][0] / p[1][0]:.2f}", f"{p[1][2] / p[1][1]:.2f}"] if p \
            else ["–"] * 4
        body.append(row)
    return (
        "## Table 3 in the paper's configuration\n\n"
        "The pessimistic method as the paper ran it: random order, every point descending the "
        "history DAG from its root (`--locate root`: no rounds, no look-ahead), locking from the "
        "leaf's parent (`--paper-locking`), 1 and 2 threads, uniform points, beside the paper's Table 3 "
        "(two 500 MHz Pentium III). Speedup: 1 thread's total ÷ 2 threads'; critical share: the "
        "time in the critical section over the insertion time, with 2 threads. ridt's location "
        "in rounds (the section above) makes location cheap, so there the lock's share grows and "
        "2 threads gain less. Output: [results/table3.txt](results/table3.txt).\n\n"
        + table(["n", "1 thread s", "2 threads s", "speedup", "critical share",
                 "paper 1 thread s", "paper 2 threads s", "paper speedup", "paper critical share"], body)
        + "\n\n![Fig. 14 in the paper's configuration](results/root_fig14_uniform.png) "
        "![Fig. 11 in the paper's configuration](results/root_fig11_uniform.png)\n")


def python_section(results):
    data = rows(results, "python.csv")
    body = []
    for r in data:
        if r["code"].startswith("ridt"):
            body.append([n_text(r["n"]), r["distribution"], r["code"], f"{float(r['time_s']):.3f}",
                         f"{float(r['scipy_over_code']):.1f}", f"{float(r['extra_b_per_point']):.0f}"])
    return (
        "## Python against scipy\n\n"
        "`ridt.Delaunay` against `scipy.spatial.Delaunay` and matplotlib's `Triangulation` (both "
        "Qhull), each call in a fresh process, the points already in memory; × scipy: scipy's "
        "time over ridt's. All codes and the memory: [results/python.md](results/python.md).\n\n"
        + table(["n", "distribution", "code", "s", "× scipy", "B/pt"], body,
                ["---:", "---", "---", "---:", "---:", "---:"])
        + "\n\n![time against n](results/python_time.png)\n")


def interpolate_section(results):
    data = rows(results, "interpolate.csv")
    body = [[r["task"], n_text(r["n"]), r["grid"], r["code"], f"{float(r['time_s']):.2f}",
             f"{float(r['scipy_over_code']):.1f}", f"{float(r['extra_b_per_point']):.0f}"]
            for r in data if r.get("time_s")]
    return (
        "## Interpolation, Voronoi and incremental insertion against scipy\n\n"
        "`ridt.griddata` (linear, then cubic) onto a grid, the triangulation included; `ridt.Voronoi`, "
        "the diagram and its arrays; `ridt.Voronoi` with its `regions` and `ridge_vertices` lists of "
        "lists read too (scipy builds them in its constructor, ridt when first read); and `add_points` "
        "of n/10 more points into an incremental `Delaunay` of n; against scipy's on the same uniform "
        "points, each call in a fresh process; × scipy: scipy's time over the code's. Output: "
        "[results/interpolate.md](results/interpolate.md).\n\n"
        + table(["call", "n", "grid", "code", "s", "× scipy", "B/pt"], body,
                ["---", "---:", "---:", "---", "---:", "---:", "---:"]) + "\n")


def sphere_section(results):
    data = rows(results, "sphere.csv")
    body = [[n_text(r["n"]), r["code"], f"{float(r['time_s']):.3f}", f"{float(r['scipy_over_code']):.1f}"]
            for r in data if r.get("time_s")]
    return (
        "## Voronoi diagrams on the sphere against scipy\n\n"
        "`ridt.SphericalVoronoi(points).calculate_areas()` against scipy's (Qhull's 3-D hull) on "
        "uniform points of the unit sphere, each call in a fresh process; the floor: `ridt.Delaunay` "
        "of as many points in the plane; × scipy: scipy's time over the code's. Output: "
        "[results/sphere.md](results/sphere.md).\n\n"
        + table(["n", "code", "s", "× scipy"], body, ["---:", "---", "---:", "---:"]) + "\n")


def weighted_section(results):
    data = rows(results, "weighted.csv")
    t = [k for k in data[0] if k.startswith("regular_") and k.endswith("_s") and k != "regular_1_s"][0]
    d = [k for k in data[0] if k.startswith("delaunay_") and k.endswith("_s") and k != "delaunay_1_s"][0]
    body = [[n_text(r["n"]), r["weights"], n_text(r["hidden"]), f"{float(r['regular_1_s']):.3f}",
             f"{float(r[t]):.3f}", f"{float(r['cgal_s']):.3f}", f"{float(r['cgal_over_regular_1']):.2f}",
             f"{float(r['delaunay_1_s']):.3f}", f"{float(r['regular_1_over_delaunay_1']):.2f}"] for r in data]
    threads = t.split("_")[1]
    return (
        "## Regular (weighted Delaunay) triangulations against CGAL\n\n"
        "`ridt::triangulate_regular` against CGAL's `Regular_triangulation_2` (range insert, which sorts "
        "along a curve) on uniform points with weights uniform in [0, s/n) (light: s = 1; heavy: s = 40, "
        "most points hidden), in process, interleaved; the floor: `ridt::triangulate` of the same points "
        "without weights (`bench/weighted_table.cpp`).\n\n"
        + table(["n", "weights", "hidden", "ridt 1 thread s", f"ridt {threads} threads s", "CGAL s",
                 "CGAL / ridt", "unweighted 1 thread s", "ridt / unweighted"], body,
                ["---:", "---", "---:", "---:", "---:", "---:", "---:", "---:", "---:"]) + "\n")


def periodic_section(results):
    data = rows(results, "periodic.csv")
    t = [k for k in data[0] if k.startswith("periodic_") and k.endswith("_s") and k != "periodic_1_s"][0]
    d = [k for k in data[0] if k.startswith("delaunay_") and k.endswith("_s") and k != "delaunay_1_s"][0]
    body = [[n_text(r["n"]), f"{float(r['periodic_1_s']):.3f}", f"{float(r[t]):.3f}", f"{float(r['cgal_s']):.3f}",
             f"{float(r['cgal_over_periodic_1']):.2f}", f"{float(r['delaunay_1_s']):.3f}", f"{float(r[d]):.3f}",
             f"{float(r['periodic_1_over_delaunay_1']):.2f}", f"{float(r[t]) / float(r[d]):.2f}"] for r in data]
    threads = t.split("_")[1]
    return (
        "## Periodic (flat torus) triangulations against CGAL\n\n"
        "`ridt::triangulate_periodic` against CGAL's `Periodic_2_Delaunay_triangulation_2` (range insert) on "
        "uniform points of the unit square, the domain, in process, interleaved; the floor: "
        "`ridt::triangulate` of the same points in the plane (`bench/periodic_table.cpp`).\n\n"
        + table(["n", "ridt 1 thread s", f"ridt {threads} threads s", "CGAL s", "CGAL / ridt", "plane 1 thread s",
                 f"plane {threads} threads s", "ridt / plane, 1 thread", f"ridt / plane, {threads} threads"], body,
                ["---:"] * 9) + "\n")


def constrained_section(results):
    """ridt_bench_constrained's rows (constrained.csv) and the whole-process page beside them."""
    data = rows(results, "constrained.csv")
    body = []
    for r in data:
        graph = f"{n_text(r['n'])} vertices, {r['lakes']} lakes"
        if int(r["extra"]) > 0:
            graph += f", {n_text(r['extra'])} more points"
        task = "CDT" if r["task"] == "cdt" else f"quality {float(r['angle']):g}°"
        angle = f"{float(r['min_angle']):.2f}" if r["task"] == "quality" else ""
        body.append([task, graph, r["code"], f"{float(r['seconds']):.3f}", f"{float(r['ratio']):.2f}",
                     n_text(r["triangles"]), angle, f"{float(r['mb_added']):.0f}"])
    process = included(results, "mesh_process.md", "Whole processes: ridt mesh against triangle",
                       "The graph: `ridt_bench_constrained --poly`.", "Machine:")
    large = included(results, "mesh_process_large.md", "The 10^7-triangle quality mesh on 1 and 2 threads",
                     "Refinement on threads, the same mesh on any number of them: "
                     "[constrained.md](constrained.md#refinement-on-threads-the-same-mesh-on-any-number-of-them).",
                     "Machine:")
    return (
        "## Constrained triangulations and quality meshes against Triangle and CGAL\n\n"
        "`ridt_bench_constrained`: generate_coastline's island with lakes (and, where said, uniform points "
        "around it), the same graph to each code, each run a process of its own (forked, the graph "
        "already in memory), the codes in a new random order each repetition. ridt and Triangle remove "
        "the lakes and the exterior; CGAL's `Constrained_Delaunay_triangulation_2` keeps them (hence its "
        "triangle count), its `Delaunay_mesher_2` meshes inside the coastline. Ratio: the median of each "
        "repetition's time over ridt's one-thread time in it (above 1: slower than ridt); MB: the memory "
        "the run added to its process. How the mesher works: [constrained.md](constrained.md).\n\n"
        + table(["task", "graph", "code", "s", "ratio", "triangles", "min angle", "MB"], body,
                ["---", "---", "---", "---:", "---:", "---:", "---:", "---:"])
        + "\n\n" + process.replace("## ", "### ", 1) + ("\n" + large.replace("## ", "### ", 1) if large else ""))


def included(results, name, heading, footer, skip):
    """The page a benchmark wrote (results/NAME) under this page's HEADING, without its title
    and the lines that start with SKIP (its machine: the head of this page has it)."""
    path = os.path.join(results, name)
    if not os.path.exists(path):
        return ""
    lines = open(path).read().splitlines()
    body = "\n".join(line for line in lines[1:] if not line.startswith(skip)).strip()
    while "\n\n\n" in body:  # the skipped lines' blank neighbours
        body = body.replace("\n\n\n", "\n\n")
    return f"## {heading}\n\n{body}\n\n{footer} Output: [results/{name}](results/{name}).\n"


def terrain_section(results):
    return included(results, "terrain.md", "A DEM from LiDAR-like points against gdal_grid",
                    "How the DEM is made: [terrain.md](terrain.md).", "Machine:")


def out_of_core_section(results):
    return included(results, "out_of_core.md", "Out of core", "How: [out-of-core.md](out-of-core.md).",
                    "Written by")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--results", default="docs/results")
    ap.add_argument("--commands", required=True)
    ap.add_argument("--mode", choices=("full", "quick", "large"), required=True)
    ap.add_argument("--out", default="docs/performance.md")
    args = ap.parse_args()
    commands = [line.rstrip("\n").split("\t", 1) for line in open(args.commands) if "\t" in line]
    head = (
        "# Performance\n\n"
        f"Written by `scripts/report.sh{'' if args.mode == 'full' else ' --' + args.mode}` on "
        f"{datetime.date.today().isoformat()}, commit {commit()}, in one run: every table and "
        "figure below, and every file in [results/](results/), comes from it. Machine: "
        f"{machine()}. Compiler: {compiler()}, Release (-O3). "
        + ("A quick run: sizes up to 10^5 and few repetitions, to try the pipeline; "
           "`scripts/report.sh` without `--quick` measures the paper's sizes. " if args.mode == "quick" else "")
        + "Times are medians of interleaved repetitions; on a shared machine compare ratios "
        "taken in the same run, not seconds across runs.\n")
    parts = [head, process_section(args.results), peers_section(args.results), serial_section(args.results),
             threads_section(args.results), table3_section(args.results), python_section(args.results),
             interpolate_section(args.results), sphere_section(args.results), weighted_section(args.results),
             periodic_section(args.results), constrained_section(args.results),
             terrain_section(args.results),
             out_of_core_section(args.results)]
    parts.append("## Commands\n\nWhat the report ran, in this order:\n\n```\n"
                 + "\n".join(cmd for _, cmd in commands) + "\n```\n")
    with open(args.out, "w") as f:
        f.write("\n".join(parts))
    print("wrote", args.out)


if __name__ == "__main__":
    main()
