#!/usr/bin/env python3
"""Whole-process timings: `ridt mesh` beside Triangle's `triangle` on the same .poly file.

The graph is generate_coastline's island with lakes (written by `ridt_bench_constrained
--poly`). Each code runs as its own process, from its start to its exit, reading the .poly and
writing its files (ridt: .ele, .node, .edge; Triangle: .ele, .node, .poly), in a new random
order every repetition. Two tasks: the constrained Delaunay triangulation with the lakes and
the exterior removed (`triangle -pQ`), and a quality mesh with a minimum angle
(`triangle -pq<angle>Q`). Reported: the median wall time, its ratio to Triangle's median, the
median of the ratios taken repetition by repetition, the triangles written and the peak
resident memory. Writes a Markdown table (and CSV) with the machine and the command.

  bench/mesh_process_table.py --build build [--cdt 1000000:100] [--quality 250000:50:30]
                              [--reps 5] [--threads 2] [--out docs/results/mesh_process.md]
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from process_table import compiler, interleaved, machine, write_csv  # noqa: E402


def triangles_in(ele):
    """The triangle count in an .ele file's header."""
    with open(ele) as f:
        return int(f.readline().split()[0])


def tasks(a):
    """(name, vertices, lakes, triangle switches, ridt options) for each task asked."""
    out = []
    if a.cdt:
        n, lakes = (int(x) for x in a.cdt.split(":"))
        out.append(("CDT", n, lakes, "-pQ", []))
    if a.quality:
        n, lakes, angle = a.quality.split(":")
        out.append((f"quality {angle}°", int(n), int(lakes), f"-pq{angle}Q", ["--quality", angle]))
    return out


def measure(a, tmp, task):
    """The rows of one task: each code's medians over the repetitions."""
    name, n, lakes, switches, options = task
    poly = os.path.join(tmp, "g.poly")
    subprocess.run([os.path.join(a.build, "ridt_bench_constrained"), "--n", str(n), "--lakes", str(lakes),
                    "--poly", poly], check=True)
    ridt = os.path.join(a.build, "ridt")
    t = str(a.threads)
    codes = [
        ("Triangle", [a.triangle, switches, poly], os.path.join(tmp, "g.1.ele")),
        ("ridt mesh, 1 thread", [ridt, "mesh", poly, "-o", os.path.join(tmp, "r1.ele"), "--threads", "1"] + options,
         os.path.join(tmp, "r1.ele")),
        (f"ridt mesh, {t} threads", [ridt, "mesh", poly, "-o", os.path.join(tmp, "r2.ele"), "--threads", t] + options,
         os.path.join(tmp, "r2.ele")),
    ]
    timed = interleaved({code: cmd for code, cmd, _ in codes}, a.reps)
    rows = []
    for code, _, ele in codes:
        med, low, high, ratio, paired, peak = timed[code]
        rows.append({"task": name, "vertices": n, "lakes": lakes, "code": code, "median_s": med, "min_s": low,
                     "max_s": high, "ratio": ratio, "paired_ratio": paired, "triangles": triangles_in(ele),
                     "peak_mb": peak / 1e6})
        r = rows[-1]
        print(f"{name:<12} {n:>9} {code:<22} {med:8.3f} s  x{r['ratio']:.3f} (paired {r['paired_ratio']:.3f})"
              f"  {r['triangles']:>10} triangles  {r['peak_mb']:7.1f} MB", flush=True)
    return rows


def write_page(a, rows):
    """The Markdown page and the CSV beside it."""
    write_csv(a.out, rows)
    with open(a.out, "w") as f:
        f.write("# Whole-process meshes against Triangle\n\n")
        f.write(f"Written by `bench/mesh_process_table.py --build {a.build} --cdt {a.cdt} --quality {a.quality} "
                f"--reps {a.reps} --threads {a.threads}` on {time.strftime('%Y-%m-%d')}.\n\n")
        f.write(f"Machine: {machine()}. Compiler: {compiler(a.build)}.\n\n")
        f.write("Each code is one process on the same `.poly` file (a coastline with lakes): read, mesh "
                "with the lakes and the exterior removed, write the mesh's files. Repetitions run the "
                "codes in a new random order each time. Time: median wall seconds (min to max). Ratio: "
                "to Triangle's median (below 1: ridt is faster); paired: the median of the ratios "
                "within each repetition. Peak: the process's peak resident memory.\n\n")
        f.write("| task | vertices | lakes | code | time s | min to max | ratio to Triangle | paired | "
                "triangles | peak MB |\n")
        f.write("|---|---:|---:|---|---:|---:|---:|---:|---:|---:|\n")
        for r in rows:
            f.write(f"| {r['task']} | {r['vertices']:,} | {r['lakes']} | {r['code']} | {r['median_s']:.3f} | "
                    f"{r['min_s']:.3f} to {r['max_s']:.3f} | {r['ratio']:.2f} | {r['paired_ratio']:.2f} | "
                    f"{r['triangles']:,} | {r['peak_mb']:.0f} |\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--cdt", default="1000000:100", help="VERTICES:LAKES of the CDT's graph ('' for none)")
    ap.add_argument("--quality", default="250000:50:30", help="VERTICES:LAKES:ANGLE of the quality mesh's graph")
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--triangle", default=shutil.which("triangle") or "triangle")
    ap.add_argument("--out", default=None, help="Markdown file (a .csv beside it)")
    a = ap.parse_args()
    for tool in (os.path.join(a.build, "ridt"), os.path.join(a.build, "ridt_bench_constrained"), a.triangle):
        if not os.access(tool, os.X_OK):
            sys.exit(f"{tool} is missing: build ridt and ridt_bench_constrained, install triangle "
                     "(scripts/deps.sh bench)")
    rows = []
    for task in tasks(a):
        with tempfile.TemporaryDirectory() as tmp:
            rows += measure(a, tmp, task)
    if a.out and rows:
        write_page(a, rows)


if __name__ == "__main__":
    main()
