#!/usr/bin/env python3
"""Whole-process timings: `ridt mesh` beside Triangle's `triangle` on the same .poly file.

The graph is generate_coastline's island with lakes (written by `ridt_bench_constrained
--poly`). Each code runs as its own process, from its start to its exit, reading the .poly and
writing its files (ridt: .ele, .node, .edge; Triangle: .ele, .node, .poly), in a new random
order every repetition. Two tasks: the constrained Delaunay triangulation with the lakes and
the exterior removed (`triangle -pQ`), and a quality mesh with a minimum angle
(`triangle -pq<angle>Q`), and, with --size, a quality mesh to a size field (an ESRI ASCII grid
over the graph's box, the size growing from its centre out to four times as large) beside the
uniform area bound that gives a mesh of the same size (Triangle's and ridt's). Reported: the median wall time, its ratio to Triangle's median, the
median of the ratios taken repetition by repetition, the triangles written and the peak
resident memory. Writes a Markdown table (and CSV) with the machine and the command.

  bench/mesh_process_table.py --build build [--cdt 1000000:100] [--quality 250000:50:30]
                              [--size 250000:50:30] [--reps 5] [--threads 2]
                              [--out docs/results/mesh_process.md]
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


def mesh_area(node, ele):
    """The area a mesh's files cover."""
    with open(node) as f:
        f.readline()
        p = {r[0]: (float(r[1]), float(r[2])) for r in (line.split() for line in f) if r and r[0][0] != "#"}
    total = 0.0
    with open(ele) as f:
        f.readline()
        for r in (line.split() for line in f):
            if r and r[0][0] != "#":
                (ax, ay), (bx, by), (cx, cy) = p[r[1]], p[r[2]], p[r[3]]
                total += abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)) / 2
    return total


def write_size_grid(poly, n, path):
    """An ESRI ASCII grid of 101 by 101 sizes over the .poly's box: h0 at its centre, growing
    linearly to 4 h0 at its corners, h0 the spacing of n points over the box."""
    with open(poly) as f:
        count = int(f.readline().split()[0])
        xy = [tuple(map(float, f.readline().split()[1:3])) for _ in range(count)]
    x0, x1 = min(p[0] for p in xy), max(p[0] for p in xy)
    y0, y1 = min(p[1] for p in xy), max(p[1] for p in xy)
    side = max(x1 - x0, y1 - y0) * 1.01
    cx, cy, half = (x0 + x1) / 2, (y0 + y1) / 2, side / 2
    h0 = side / n ** 0.5
    k = 101
    with open(path, "w") as f:
        f.write(f"ncols {k}\nnrows {k}\nxllcenter {cx - half!r}\nyllcenter {cy - half!r}\n"
                f"cellsize {side / (k - 1)!r}\n")
        for j in range(k - 1, -1, -1):  # the top row first
            y = cy - half + side * j / (k - 1)
            f.write(" ".join(repr(h0 * (1 + 3 * ((cx - half + side * i / (k - 1) - cx) ** 2 + (y - cy) ** 2) ** 0.5
                                         / (half * 2 ** 0.5))) for i in range(k)) + "\n")


def tasks(a):
    """(name, vertices, lakes, triangle switches, ridt options) for each task asked."""
    out = []
    if a.cdt:
        n, lakes = (int(x) for x in a.cdt.split(":"))
        out.append(("CDT", n, lakes, "-pQ", []))
    if a.quality:
        n, lakes, angle = a.quality.split(":")
        out.append((f"quality {angle}°", int(n), int(lakes), f"-pq{angle}Q", ["--quality", angle]))
    if a.size:
        n, lakes, angle = a.size.split(":")
        out.append((f"size field, {angle}°", int(n), int(lakes), angle, None))
    return out


def size_codes(a, tmp, n, angle, poly):
    """The size field's codes: ridt to the grid on 1 and a.threads threads, and ridt and Triangle
    to the uniform area bound with which ridt makes as many triangles."""
    ridt, t = os.path.join(a.build, "ridt"), str(a.threads)
    grid = os.path.join(tmp, "h.asc")
    write_size_grid(poly, n, grid)
    probe = os.path.join(tmp, "probe.ele")
    subprocess.run([ridt, "mesh", poly, "-o", probe, "--quality", angle, "--size", grid], check=True)
    # Without an exponent: Triangle reads a switch's number as digits and a point.
    want = triangles_in(probe)
    area = 2 * mesh_area(os.path.join(tmp, "probe.node"), probe) / want  # a first guess
    for _ in range(8):  # the bound that makes as many triangles, within 1 %: each count ~ 1 / bound
        bound = f"{float(f'{area:.4g}'):.15f}".rstrip("0")  # no exponent: Triangle reads digits and a point
        subprocess.run([ridt, "mesh", poly, "-o", probe, "--quality", angle, "--max-area", bound], check=True)
        got = triangles_in(probe)
        if abs(got / want - 1) < 0.01:
            break
        area *= got / want
    return [
        (f"Triangle, -a{bound}", [a.triangle, f"-pq{angle}a{bound}Q", poly], os.path.join(tmp, "g.1.ele")),
        (f"ridt mesh, --max-area {bound}, 1 thread",
         [ridt, "mesh", poly, "-o", os.path.join(tmp, "a1.ele"), "--threads", "1", "--quality", angle, "--max-area",
          bound], os.path.join(tmp, "a1.ele")),
        ("ridt mesh, --size, 1 thread",
         [ridt, "mesh", poly, "-o", os.path.join(tmp, "s1.ele"), "--threads", "1", "--quality", angle, "--size", grid],
         os.path.join(tmp, "s1.ele")),
        (f"ridt mesh, --size, {t} threads",
         [ridt, "mesh", poly, "-o", os.path.join(tmp, "s2.ele"), "--threads", t, "--quality", angle, "--size", grid],
         os.path.join(tmp, "s2.ele")),
    ]


def measure(a, tmp, task):
    """The rows of one task: each code's medians over the repetitions."""
    name, n, lakes, switches, options = task
    poly = os.path.join(tmp, "g.poly")
    subprocess.run([os.path.join(a.build, "ridt_bench_constrained"), "--n", str(n), "--lakes", str(lakes),
                    "--poly", poly], check=True)
    ridt = os.path.join(a.build, "ridt")
    t = str(a.threads)
    codes = size_codes(a, tmp, n, switches, poly) if options is None else [
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
        print(f"{name:<16} {n:>9} {code:<36} {med:8.3f} s  x{r['ratio']:.3f} (paired {r['paired_ratio']:.3f})"
              f"  {r['triangles']:>10} triangles  {r['peak_mb']:7.1f} MB", flush=True)
    return rows


def write_page(a, rows):
    """The Markdown page and the CSV beside it."""
    write_csv(a.out, rows)
    with open(a.out, "w") as f:
        f.write("# Whole-process meshes against Triangle\n\n")
        f.write(f"Written by `bench/mesh_process_table.py --build {a.build} --cdt {a.cdt} --quality {a.quality} "
                f"{'--size ' + a.size + ' ' if a.size else ''}--reps {a.reps} --threads {a.threads}` on {time.strftime('%Y-%m-%d')}.\n\n")
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
    ap.add_argument("--size", default="", help="VERTICES:LAKES:ANGLE of the size field's graph ('' for none)")
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
