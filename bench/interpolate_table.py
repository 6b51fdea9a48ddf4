#!/usr/bin/env python3
"""Interpolation onto a grid, Voronoi diagrams and incremental insertion: ridt's Python package
beside scipy's on the same points, each call in a fresh process, the codes in a new random order
every repetition.

  bench/interpolate_table.py [--python /usr/bin/python3] [--n 1000000] [--grid 2000] [--reps 3]
                             [--add-points-reps 1] [--out docs/results/interpolate.md]

griddata: `griddata(points, values, (gx, gy))`, linear, and again cubic (Clough-Tocher, its
gradients estimated), of n uniform points onto a grid of grid x grid nodes over the unit
square, the triangulation included. add_points: `add_points(more)` of n / 10 more uniform
points into `Delaunay(points, incremental=True)` (made before the clock starts); scipy's
(Qhull's incremental mode) takes minutes at 10^6, so it runs --add-points-reps times. Voronoi: `Voronoi(points)`,
the diagram with its arrays (vertices, ridge_points, point_region); and again with its
`regions` and `ridge_vertices` lists of lists read too (scipy builds them in the constructor,
ridt when first read). Time: the median wall seconds of the call; × scipy: the median of each
repetition's ratio of scipy's time to the code's (the two runs of a repetition are next to each
other in time); memory: the process's peak resident size during the call above its size just
before, per point. Writes a Markdown table and a CSV.
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
import textwrap

import numpy as np

from python_table import machine

CHILD = textwrap.dedent("""
    import json, resource, sys, time
    import numpy as np
    task, code, path, grid = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
    pts = np.load(path)
    values = np.sin(6 * pts[:, 0]) * np.cos(5 * pts[:, 1])
    if code == "scipy":
        import scipy.interpolate as si, scipy.spatial as ss
        griddata, Voronoi, Delaunay, kw = si.griddata, ss.Voronoi, ss.Delaunay, {}
    else:
        import ridt
        ridt.set_memory_cache_limit(0)
        griddata, Voronoi, Delaunay = ridt.griddata, ridt.Voronoi, ridt.Delaunay
        kw = {"threads": int(code.split()[1])}
    if task in ("griddata", "griddata_cubic"):
        gx, gy = np.mgrid[0:1:grid * 1j, 0:1:grid * 1j]
        method = "cubic" if task == "griddata_cubic" else "linear"
        run = lambda: griddata(pts, values, (gx, gy), method=method, **kw)
    elif task == "add_points":
        more = np.random.default_rng(2).random((len(pts) // 10, 2))
        tri = Delaunay(pts, incremental=True, **kw)
        run = lambda: tri.add_points(more)
    elif task == "voronoi":
        run = lambda: Voronoi(pts, **kw)
    else:
        def run():
            v = Voronoi(pts, **kw)
            return v, v.regions, v.ridge_vertices
    def rss():
        for line in open("/proc/self/status"):
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) * 1024
    before = rss()
    t0 = time.perf_counter()
    result = run()
    wall = time.perf_counter() - t0
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    print(json.dumps({"time": wall, "extra": max(0, peak - before)}))
""")

CODES = ["ridt 1", "ridt 2", "scipy"]
LABEL = {"ridt 1": "ridt, 1 thread", "ridt 2": "ridt, 2 threads", "scipy": "scipy"}
CALL = {"griddata": "griddata, linear", "griddata_cubic": "griddata, cubic", "voronoi": "Voronoi",
        "voronoi_lists": "Voronoi, with its lists", "add_points": "add_points of n/10"}


def run(python, task, code, path, grid):
    out = subprocess.run([python, "-c", CHILD, task, code, path, str(grid)], capture_output=True, text=True)
    if out.returncode != 0:
        print(out.stderr, file=sys.stderr)
        return None
    return json.loads(out.stdout.strip().splitlines()[-1])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--python", default="/usr/bin/python3")
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--grid", type=int, default=2000)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--add-points-reps", type=int, default=1)
    ap.add_argument("--tasks", default=",".join(CALL), help="which calls, comma-separated: " + ", ".join(CALL))
    ap.add_argument("--out", default="docs/results/interpolate.md")
    args = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "points.npy")
        np.save(path, np.random.default_rng(1).random((args.n, 2)))
        for task in args.tasks.split(","):
            got = {c: [] for c in CODES}
            reps = args.add_points_reps if task == "add_points" else args.reps
            for _ in range(reps):
                for code in random.sample(CODES, len(CODES)):
                    got[code].append(run(args.python, task, code, path, args.grid))
            for code in CODES:
                ok = [r for r in got[code] if r is not None]
                row = {"task": CALL[task], "n": args.n, "grid": args.grid if task.startswith("griddata") else "",
                       "code": LABEL[code], "runs": len(ok), "failed": reps - len(ok)}
                if ok:
                    row["time_s"] = statistics.median(r["time"] for r in ok)
                    row["extra_b_per_point"] = statistics.median(r["extra"] for r in ok) / args.n
                # Each repetition's scipy time over this code's, the two runs next to each other
                # in time, so that a drift of the machine's speed cancels: their median.
                pairs = [s["time"] / c["time"] for s, c in zip(got["scipy"], got[code]) if s and c]
                if pairs:
                    row["scipy_over_code"] = statistics.median(pairs)
                rows.append(row)
                print(json.dumps(row), file=sys.stderr, flush=True)
    base = os.path.splitext(args.out)[0]
    fields = ["task", "n", "grid", "code", "runs", "failed", "time_s", "extra_b_per_point", "scipy_over_code"]
    with open(base + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)
    with open(args.out, "w") as f:
        f.write(f"Machine: {machine()}. {args.n:,} uniform points; griddata onto a {args.grid} x {args.grid} "
                f"grid; add_points of {args.n // 10:,} more; medians of {args.reps} interleaved runs "
                f"({args.add_points_reps} for add_points), each in a fresh process; × scipy: the median of "
                f"each repetition's ratio.\n\n")
        f.write("| call | code | s | × scipy | peak B/pt |\n|---|---|---:|---:|---:|\n")
        for r in rows:
            if "time_s" not in r:
                f.write(f"| {r['task']} | {r['code']} | failed | | |\n")
                continue
            ratio = f"{r['scipy_over_code']:.1f}" if r.get("scipy_over_code") else ""
            f.write(f"| {r['task']} | {r['code']} | {r['time_s']:.2f} | {ratio} | {r['extra_b_per_point']:.0f} |\n")
    print("wrote", args.out)


if __name__ == "__main__":
    main()
