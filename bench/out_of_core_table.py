#!/usr/bin/env python3
"""Out-of-core triangulation: `ridt triangulate --out-of-core` on uniform point sets, its time,
its peak memory and its phases, beside the in-memory run where that fits, and `ridt check` of
its parts (read in passes), its time and peak.

Each size is one .bin file written by `ridt generate` to --dir (a disk, not memory: the point
is that the set need not fit). Every code is one process, timed whole, its peak resident
memory from the kernel; the out-of-core run with --memory-limit.

  bench/out_of_core_table.py --build DIR [--sizes 10000000,100000000,500000000]
                             [--limits 500M,2G,4G] [--threads 2] [--in-memory-max 100000000]
                             [--check-max 100000000] [--dir /tmp] [--out docs/results/out_of_core.md]

--limits: the --memory-limit of each size's run (one for all, or one a size).
"""
import argparse
import json
import os
import subprocess
import sys
import time

from process_table import compiler, machine
from scaling_table import run_once


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--sizes", default="10000000,100000000,500000000")
    ap.add_argument("--limits", default="500M,2G,4G")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--in-memory-max", type=int, default=100000000)
    ap.add_argument("--check-max", type=int, default=100000000)
    ap.add_argument("--dir", default="/tmp")
    ap.add_argument("--out", default=None)
    a = ap.parse_args()
    ridt = os.path.join(a.build, "ridt")
    rows = []
    sizes = [int(s) for s in a.sizes.split(",")]
    limits = a.limits.split(",")
    if len(limits) not in (1, len(sizes)):
        sys.exit("--limits: one for all sizes, or one a size")
    for n, limit in zip(sizes, limits * len(sizes) if len(limits) == 1 else limits):
        points = os.path.join(a.dir, f"ooc-uniform-{n}.bin")
        parts = os.path.join(a.dir, f"ooc-{n}.parts")
        subprocess.run([ridt, "generate", "--dist", "uniform", "-n", str(n), "-o", points], check=True)
        row = {"n": n, "limit": limit}
        if n <= a.in_memory_max:
            row["in_memory_s"], row["in_memory_peak"], _ = run_once(
                [ridt, "triangulate", points, "--threads", str(a.threads)])
        wall, peak, stats = run_once([ridt, "triangulate", points, "-o", parts, "--out-of-core", "--memory-limit",
                                      limit, "--threads", str(a.threads), "--stats"])
        row.update(wall_s=wall, peak=peak, stats=stats)
        if n <= a.check_max:
            row["check_s"], row["check_peak"], row["check"] = check_once([ridt, "check", points, parts])
        with open(parts) as index:
            names = index.read().split()[3:]
        for name in names:
            os.remove(os.path.join(os.path.dirname(parts), name))
        os.remove(parts)
        os.remove(points)
        rows.append(row)
        print(json.dumps(row), flush=True)
    if a.out:
        write_page(a, rows)


def check_once(cmd):
    """Wall seconds, peak resident bytes and the verdict's first word (or the error) of a check."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out = proc.stdout.read().decode(errors="replace")
    _, _, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    err = proc.stderr.read().decode(errors="replace")
    proc.stdout.close()
    proc.stderr.close()
    return wall, usage.ru_maxrss * 1024, out.strip().split(":")[0] or err.strip()


def write_page(a, rows):
    cmd = (f"bench/out_of_core_table.py --build {a.build} --sizes {a.sizes} --limits {a.limits} --threads {a.threads} "
           f"--in-memory-max {a.in_memory_max} --check-max {a.check_max} --dir {a.dir} --out {a.out}")
    with open(a.out, "w") as f:
        f.write("# Out-of-core triangulation\n\n")
        f.write(f"Written by `{cmd}` on {time.strftime('%Y-%m-%d')}. Machine: {machine()}. "
                f"Compiler: {compiler(a.build)}.\n\n")
        f.write(f"Uniform points in a `.bin` file on disk; `ridt triangulate --out-of-core --memory-limit LIMIT "
                f"--threads {a.threads}`, one run each, the whole process: bucketing the points into cells on disk, "
                "triangulating the strips, checking them against the points not loaded, writing the parts. Peak: "
                "the process's peak resident memory. *In memory*: `ridt triangulate` of the same file on the same "
                "threads, writing nothing. *Check*: `ridt check POINTS OUT.parts`, exact, the parts read in passes "
                "(the points mapped, the sides of a range of vertices at a time), its time and peak. "
                "*Loaded*: the points triangulated over all strips, over n.\n\n")
        f.write("| n | limit | out of core s | peak GB | in memory s | in memory peak GB | strips | loaded | retries "
                "| bucketing s | triangulating s | checking s | writing s | check | check s | check peak GB |\n")
        f.write("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|\n")
        for r in rows:
            s = r["stats"]
            mem = f"{r['in_memory_s']:.1f} | {r['in_memory_peak'] / 1e9:.2f}" if "in_memory_s" in r else "— | —"
            f.write(f"| {r['n']:,} | {r['limit']} | {r['wall_s']:.1f} | {r['peak'] / 1e9:.2f} | {mem} | {s['strips']} | "
                    f"{s['loaded'] / s['points']:.2f} | {s['retries']} | {s['time_bucket_s']:.1f} | "
                    f"{s['time_triangulate_s']:.1f} | {s['time_check_s']:.1f} | {s['time_write_s']:.1f} | "
                    f"{r.get('check', 'not run')} | " +
                    (f"{r['check_s']:.1f} | {r['check_peak'] / 1e9:.2f} |\n" if "check_s" in r else "— | — |\n"))
        f.write("\n")


if __name__ == "__main__":
    main()
