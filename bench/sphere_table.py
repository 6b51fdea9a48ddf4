#!/usr/bin/env python3
"""ridt.SphericalVoronoi beside scipy.spatial.SphericalVoronoi (Qhull's 3-D hull) on the same
points on the unit sphere, cells and their areas included, each run in a fresh process, the
codes in a new random order every repetition; ridt.Delaunay of as many points in the plane as
the floor.

  bench/sphere_table.py [--python build/venv/bin/python] [--sizes 10000,100000,1000000]
                        [--reps 3] [--out docs/results/sphere.md]

Time: the median wall seconds of SphericalVoronoi(points) and calculate_areas() (the points
already in memory). Writes a Markdown table and a CSV beside it.
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

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from python_table import machine  # noqa: E402

CHILD = textwrap.dedent("""
    import json, sys, time
    import numpy as np
    code, path = sys.argv[1], sys.argv[2]
    pts = np.load(path)
    if code == "scipy":
        from scipy.spatial import SphericalVoronoi
        run = lambda: SphericalVoronoi(pts, threshold=1e-9).calculate_areas()
    elif code.startswith("plane"):
        import ridt
        flat = np.ascontiguousarray(pts[:, :2])
        run = lambda: ridt.Delaunay(flat, threads=int(code.split()[1]))
    else:
        import ridt
        run = lambda: ridt.SphericalVoronoi(pts, threshold=1e-9, threads=int(code.split()[1])).calculate_areas()
    t0 = time.perf_counter()
    run()
    print(json.dumps({"time": time.perf_counter() - t0}))
""")

CODES = ["ridt 1", "ridt 2", "scipy", "plane 1", "plane 2"]
LABEL = {"ridt 1": "ridt.SphericalVoronoi, 1 thread", "ridt 2": "ridt.SphericalVoronoi, 2 threads",
         "scipy": "scipy.spatial.SphericalVoronoi", "plane 1": "floor: ridt.Delaunay in the plane, 1 thread",
         "plane 2": "floor: ridt.Delaunay in the plane, 2 threads"}


def versions(python):
    code = "import numpy, scipy, ridt, sys; print(sys.version.split()[0], numpy.__version__, scipy.__version__, ridt.__version__)"
    v = subprocess.run([python, "-c", code], capture_output=True, text=True, check=True).stdout.split()
    return f"Python {v[0]}, numpy {v[1]}, scipy {v[2]}, ridt {v[3]}"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--python", default="build/venv/bin/python")
    ap.add_argument("--sizes", default="10000,100000,1000000")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--out", default="docs/results/sphere.md")
    args = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for n in (int(s) for s in args.sizes.split(",") if s):
            p = np.random.default_rng(n).normal(size=(n, 3))
            p /= np.linalg.norm(p, axis=1, keepdims=True)
            path = os.path.join(tmp, f"{n}.npy")
            np.save(path, p)
            got = {c: [] for c in CODES}
            for _ in range(args.reps):
                for code in random.sample(CODES, len(CODES)):
                    out = subprocess.run([args.python, "-c", CHILD, code, path], capture_output=True, text=True)
                    if out.returncode != 0:
                        print(f"{code} failed on {n} points: {out.stderr.strip().splitlines()[-1:]}", file=sys.stderr)
                    got[code].append(json.loads(out.stdout.strip().splitlines()[-1])["time"]
                                     if out.returncode == 0 else None)
            for code in CODES:
                ok = [t for t in got[code] if t is not None]
                rows.append({"n": n, "code": LABEL[code], "runs": len(ok),
                             "time_s": statistics.median(ok) if ok else None})
                print(json.dumps(rows[-1]), file=sys.stderr, flush=True)
    for r in rows:
        ref = next(s for s in rows if s["n"] == r["n"] and s["code"] == LABEL["scipy"])
        r["scipy_over_code"] = ref["time_s"] / r["time_s"] if ref["time_s"] and r["time_s"] else None
    base = os.path.splitext(args.out)[0]
    with open(base + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["n", "code", "runs", "time_s", "scipy_over_code"])
        w.writeheader()
        w.writerows(rows)
    with open(args.out, "w") as f:
        f.write("# Voronoi diagrams on the sphere: ridt beside scipy\n\n")
        f.write(f"Written by `bench/sphere_table.py {' '.join(sys.argv[1:])}`.\n\n")
        f.write(f"Machine: {machine()}. {versions(args.python)}.\n\n")
        f.write("Uniform points on the unit sphere (normalized normal deviates). Each code runs in a fresh "
                "process on the same points, loaded before the clock starts, the codes in a new random order "
                f"every repetition ({args.reps}); time: the median wall seconds of `SphericalVoronoi(points)` "
                "and `calculate_areas()`. The floor: ridt.Delaunay of the same number of points in the plane "
                "(their x and y). Both SphericalVoronoi are given threshold=1e-9: among 10^6 uniform points some "
                "pairs lie closer than the default 1e-6, which both refuse as duplicates. Speed-up: scipy's time "
                "over the code's.\n\n")
        f.write("| n | code | time s | speed-up over scipy |\n|---:|---|---:|---:|\n")
        for r in rows:
            t = f"{r['time_s']:.3f}" if r["time_s"] else "failed"
            s = f"{r['scipy_over_code']:.1f}" if r["scipy_over_code"] else ""
            f.write(f"| {r['n']:,} | {r['code']} | {t} | {s} |\n")


if __name__ == "__main__":
    main()
