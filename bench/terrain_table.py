#!/usr/bin/env python3
"""A DEM from LiDAR-like points: `ridt dem` beside `gdal_grid -a linear` and `-a nearest`.

For each size, bench/terrain.py writes a LAS file (ground and canopy returns); the ground
points (class 2) also go to a CSV that gdal_grid reads through a VRT (GDAL 3.6 reads no LAS).
Both make a GeoTIFF DEM of the same cells (resolution 1 m, the survey's square) from the
same ground points: ridt from the LAS with --class 2, gdal_grid from the CSV (each x, y once,
with the height of its first point, as ridt keeps it). Each run is its
own process, from start to exit with the DEM written; the codes run in a new random order every
repetition; reported are median wall times, their ratio, peak resident memory, and the largest
difference between ridt's and gdal_grid's linear DEMs where both have a value.

  bench/terrain_table.py --build build [--sizes 1000000,10000000] [--reps 3] [--threads 1]
                         [--gdal-max 10000000] [--gdal-nearest-max 1000000]
                         [--huge 100000000 --huge-threads 2]
                         [--dir /tmp/ridt-terrain] [--out docs/results/terrain.md]

gdal_grid's nearest takes minutes at 10^6 points (it searches without an index here), so it
runs once, and only up to --gdal-nearest-max. --huge N runs ridt alone on N points (gdal_grid
would take hours): the whole process, its time and its peak memory.
"""
import argparse
import os
import random
import statistics
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from process_table import machine, run_once  # noqa: E402


def las_ground_csv(las, csv):
    """The class 2 points of a LAS file of point format 0 as a CSV with a header, each x, y once:
    the first point there, whose height `ridt dem --duplicates first` (the default) keeps too.
    (Qhull keeps one of equal points as it likes; with the heights of rounded returns apart, the
    DEMs would then differ in the triangles at such points, and only there.)"""
    head = np.fromfile(las, np.uint8, 227)
    offset = int(head[96:100].view("<u4")[0])
    rec = np.dtype([("x", "<i4"), ("y", "<i4"), ("z", "<i4"), ("pad", "V3"), ("cls", "u1"), ("rest", "V4")])
    r = np.fromfile(las, rec, offset=offset)
    r = r[r["cls"] == 2]
    _, first = np.unique(np.column_stack([r["x"], r["y"]]), axis=0, return_index=True)
    r = r[np.sort(first)]
    with open(csv, "w") as f:
        f.write("x,y,z\n")
        np.savetxt(f, np.column_stack([r["x"], r["y"], r["z"]]) / 1000.0, fmt="%.3f", delimiter=",")


def prepare(n, directory, python):
    las = os.path.join(directory, f"terrain_{n}.las")
    if not os.path.exists(las):
        subprocess.check_call([python, os.path.join(HERE, "terrain.py"), "-n", str(n), "-o", las])
    return las


def gdal_inputs(las, n, directory):
    csv = os.path.join(directory, f"ground_{n}.csv")
    if not os.path.exists(csv):
        las_ground_csv(las, csv)
    vrt = os.path.join(directory, f"ground_{n}.vrt")
    with open(vrt, "w") as f:
        f.write(f'<OGRVRTDataSource><OGRVRTLayer name="ground_{n}"><SrcDataSource>{csv}</SrcDataSource>'
                '<GeometryType>wkbPoint</GeometryType><GeometryField encoding="PointFromColumns" x="x" y="y"/>'
                '</OGRVRTLayer></OGRVRTDataSource>\n')
    return vrt


def largest_difference(a_path, b_path):
    from osgeo import gdal
    a = gdal.Open(a_path).ReadAsArray()
    b = gdal.Open(b_path).ReadAsArray()
    both = np.isfinite(a) & np.isfinite(b)
    return float(np.abs(a[both] - b[both]).max()), int(both.sum()), a.size


def measure(n, args, rows):
    las = prepare(n, args.dir, args.python)
    side = float(np.ceil(max(np.sqrt(n) / 2.0, 1.0)))
    cells = int(side)
    out = {k: os.path.join(args.dir, f"{k}_{n}.tif") for k in ("ridt", "ridt_nearest", "gdal", "gdal_nearest")}
    extent = f"0,0,{side:g},{side:g}"
    codes = {
        "ridt linear": [args.ridt, "dem", las, "-o", out["ridt"], "--resolution", "1", "--class", "2",
                        "--extent", extent, "--threads", str(args.threads)],
        "ridt nearest": [args.ridt, "dem", las, "-o", out["ridt_nearest"], "--resolution", "1", "--class", "2",
                         "--extent", extent, "--method", "nearest", "--threads", str(args.threads)],
    }
    if n <= args.gdal_max:
        vrt = gdal_inputs(las, n, args.dir)
        grid = ["-zfield", "z", "-txe", "0", f"{side:g}", "-tye", f"{side:g}", "0", "-outsize", str(cells), str(cells),
                "-ot", "Float64", "-l", f"ground_{n}", "-q", vrt]
        codes["gdal_grid linear"] = ["gdal_grid", "-a", "linear:radius=0:nodata=nan"] + grid + [out["gdal"]]
        if n <= args.gdal_nearest_max:
            codes["gdal_grid nearest"] = ["gdal_grid", "-a", "nearest:nodata=nan"] + grid + [out["gdal_nearest"]]
    times = {c: [] for c in codes}
    rss = {c: 0 for c in codes}
    for rep in range(args.reps if n <= args.gdal_max else 1):
        order = list(codes)
        random.shuffle(order)
        for c in order:
            if c == "gdal_grid nearest" and rep > 0:
                continue  # minutes a run: once is enough to see the ratio
            wall, peak = run_once(codes[c])
            times[c].append(wall)
            rss[c] = max(rss[c], peak)
    diff = largest_difference(out["ridt"], out["gdal"]) if "gdal_grid linear" in codes else None
    for c in codes:
        rows.append((n, c, statistics.median(times[c]), len(times[c]), rss[c]))
    return diff


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--build", default="build")
    p.add_argument("--sizes", default="1000000,10000000")
    p.add_argument("--reps", type=int, default=3)
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--gdal-max", type=int, default=10_000_000)
    p.add_argument("--gdal-nearest-max", type=int, default=1_000_000)
    p.add_argument("--huge", type=int, default=0)
    p.add_argument("--huge-threads", type=int, default=2)
    p.add_argument("--dir", default="/tmp/ridt-terrain")
    p.add_argument("--out", default="docs/results/terrain.md")
    p.add_argument("--python", default="/usr/bin/python3")
    args = p.parse_args()
    args.ridt = os.path.join(args.build, "ridt")
    os.makedirs(args.dir, exist_ok=True)
    rows, diffs = [], {}
    for n in (int(s) for s in args.sizes.split(",") if s):
        diffs[n] = measure(n, args, rows)
        print(f"n = {n}: done", flush=True)
    if args.huge:
        las = prepare(args.huge, args.dir, args.python)
        tif = os.path.join(args.dir, f"ridt_{args.huge}.tif")
        wall, peak = run_once([args.ridt, "dem", las, "-o", tif, "--resolution", "1", "--class", "2",
                               "--threads", str(args.huge_threads)])
        rows.append((args.huge, f"ridt linear, {args.huge_threads} threads", wall, 1, peak))
    write_page(args, rows, diffs)


def write_page(args, rows, diffs):
    lines = ["# A DEM from LiDAR-like points: ridt and gdal_grid", "",
             f"Machine: {machine()}. Generated by `bench/terrain_table.py --sizes {args.sizes} --reps {args.reps} "
             f"--threads {args.threads}" + (f" --huge {args.huge} --huge-threads {args.huge_threads}" if args.huge else "")
             + "`, nothing else running.", "",
             "Input: `bench/terrain.py` (LAS 1.2, ground and canopy returns); the DEM of the ground points "
             "(class 2) at 1 m over the survey's square, written as GeoTIFF (Float64). gdal_grid reads the "
             "same ground points from a CSV. Whole processes, medians of interleaved runs.", "",
             "| points | code | wall s (median) | runs | peak memory MB | vs gdal_grid |",
             "|---:|---|---:|---:|---:|---:|"]
    by = {(n, c): t for n, c, t, _, _ in rows}
    for n, c, t, k, peak in rows:
        peer = by.get((n, "gdal_grid " + c.split()[1])) if c.startswith("ridt") else None
        ratio = f"{peer / t:.1f}x faster" if peer else ""
        lines.append(f"| {n:,} | {c} | {t:.2f} | {k} | {peak / 2**20:.0f} | {ratio} |")
    lines.append("")
    for n, d in diffs.items():
        if d:
            lines.append(f"At {n:,} points the linear DEMs have {d[1]:,} of {d[2]:,} cells in common; the largest "
                         f"difference there is {d[0]:.3g} m.")
    os.makedirs(os.path.dirname(args.out) or ".", exist_ok=True)
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
