#!/usr/bin/env python3
"""ridt's Python package beside scipy.spatial.Delaunay and matplotlib.tri.Triangulation (both
Qhull) on the same points: time of the call and the memory it needed, each run in a fresh
process, the codes in a new random order every repetition.

  bench/python_table.py [--python build/venv/bin/python] [--sizes 10000,100000,1000000]
                        [--big 10000000] [--big-dists uniform] [--dists uniform,normal,grid,clusters]
                        [--reps 3]
                        [--out docs/results/python.md]

Time: the median wall seconds of the call alone (the points already in memory). Memory: the
process's peak resident size during the call above its size just before, per point. The
--big sizes run once, on --big-dists (uniform by default: scipy takes minutes there). Writes a Markdown table,
a CSV beside it and a log-log plot of time against size (python_time.png beside it).
"""
import argparse
import csv
import json
import os
import platform
import random
import statistics
import subprocess
import sys
import tempfile
import textwrap

import numpy as np

CHILD = textwrap.dedent("""
    import json, resource, sys, time
    import numpy as np
    code, path = sys.argv[1], sys.argv[2]
    pts = np.load(path)
    if code == "scipy":
        from scipy.spatial import Delaunay
        run = lambda: Delaunay(pts)
    elif code == "matplotlib":
        from matplotlib.tri import Triangulation
        run = lambda: Triangulation(pts[:, 0], pts[:, 1])
    else:
        import ridt
        ridt.set_memory_cache_limit(0)
        threads = int(code.split()[1])
        run = lambda: ridt.Delaunay(pts, threads=threads)
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

CODES = ["ridt 1", "ridt 2", "scipy", "matplotlib"]
LABEL = {"ridt 1": "ridt.Delaunay, 1 thread", "ridt 2": "ridt.Delaunay, 2 threads",
         "scipy": "scipy.spatial.Delaunay", "matplotlib": "matplotlib.tri.Triangulation"}


def points(dist, n, seed=1):
    """The paper's four distributions (the same definitions as `ridt generate`)."""
    rng = np.random.default_rng(seed)
    if dist == "uniform":
        return rng.random((n, 2))
    if dist == "normal":
        return rng.normal(size=(n, 2))
    if dist == "grid":
        s = int(np.ceil(np.sqrt(n)))
        i = np.arange(n)
        return np.stack([i % s, i // s], axis=1).astype(np.float64)
    if dist == "clusters":
        centres = rng.random((10, 2))
        return centres[rng.integers(0, 10, n)] + rng.normal(scale=0.01, size=(n, 2))
    raise ValueError(dist)


def run(python, code, path):
    out = subprocess.run([python, "-c", CHILD, code, path], capture_output=True, text=True)
    if out.returncode != 0:
        return None  # recorded as a failure of that code
    return json.loads(out.stdout.strip().splitlines()[-1])


def machine():
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "CPU")
    mem = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2**30
    return f"{cpu}, {os.cpu_count()} cores, {mem:.0f} GiB, {platform.system()} {platform.release()}"


def versions(python):
    code = "import numpy, scipy, matplotlib, ridt, sys; print(sys.version.split()[0], numpy.__version__, scipy.__version__, matplotlib.__version__, ridt.__version__)"
    v = subprocess.run([python, "-c", code], capture_output=True, text=True, check=True).stdout.split()
    return f"Python {v[0]}, numpy {v[1]}, scipy {v[2]}, matplotlib {v[3]}, ridt {v[4]}"


def write_page(args, rows):
    """The Markdown page and the CSV beside it."""
    base = os.path.splitext(args.out)[0]
    with open(base + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["n", "distribution", "code", "runs", "failed", "time_s",
                                          "extra_b_per_point", "scipy_over_code"])
        w.writeheader()
        w.writerows(rows)
    command = "bench/python_table.py " + " ".join(sys.argv[1:])
    with open(args.out, "w") as f:
        f.write("# ridt's Python package beside scipy and matplotlib\n\n")
        f.write(f"Written by `{command}`.\n\n")
        f.write(f"Machine: {machine()}. {versions(args.python)}.\n\n")
        f.write("Each code runs in a fresh process on the same points, loaded before the clock starts; the "
                "codes run in a new random order every repetition. Time: median wall seconds of the call. "
                "Memory: the peak resident size during the call above the size before it, per point (the "
                "result included, the input not). Speed-up: scipy's time over the code's.\n\n")
        f.write("| n | distribution | code | time s | speed-up over scipy | memory B/pt |\n|---:|---|---|---:|---:|---:|\n")
        for r in rows:
            if "time_s" not in r:
                f.write(f"| {r['n']:,} | {r['distribution']} | {r['code']} | failed | | |\n")
                continue
            f.write(f"| {r['n']:,} | {r['distribution']} | {r['code']} | {r['time_s']:.3f} | "
                    f"{r['scipy_over_code']:.1f} | {r['extra_b_per_point']:.0f} |\n")
        f.write("\n![time against n](python_time.png)\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--python", default="build/venv/bin/python")
    ap.add_argument("--sizes", default="10000,100000,1000000")
    ap.add_argument("--big", default="10000000")
    ap.add_argument("--dists", default="uniform,normal,grid,clusters")
    ap.add_argument("--big-dists", default="uniform", help="the distributions at the --big sizes")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--out", default="docs/results/python.md")
    args = ap.parse_args()
    cases = [(d, int(n), args.reps) for n in args.sizes.split(",") if n for d in args.dists.split(",")]
    cases += [(d, int(n), 1) for n in args.big.split(",") if n for d in args.big_dists.split(",")]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for dist, n, reps in cases:
            path = os.path.join(tmp, f"{dist}-{n}.npy")
            np.save(path, points(dist, n))
            got = {c: [] for c in CODES}
            for _ in range(reps):
                for code in random.sample(CODES, len(CODES)):
                    got[code].append(run(args.python, code, path))
            os.remove(path)
            for code in CODES:
                ok = [r for r in got[code] if r is not None]
                row = {"n": n, "distribution": dist, "code": LABEL[code], "runs": len(ok), "failed": reps - len(ok)}
                if ok:
                    row["time_s"] = statistics.median(r["time"] for r in ok)
                    row["extra_b_per_point"] = statistics.median(r["extra"] for r in ok) / n
                rows.append(row)
                print(json.dumps(row), file=sys.stderr, flush=True)
    # Speed-ups of each code against scipy within the same case.
    for r in rows:
        ref = next((s for s in rows if s["n"] == r["n"] and s["distribution"] == r["distribution"]
                    and s["code"] == LABEL["scipy"] and "time_s" in s), None)
        r["scipy_over_code"] = ref["time_s"] / r["time_s"] if ref and "time_s" in r else None

    write_page(args, rows)
    plot(rows, os.path.join(os.path.dirname(args.out), "python_time.png"))


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    dists = sorted({r["distribution"] for r in rows}, key=["uniform", "normal", "grid", "clusters"].index)
    fig, axes = plt.subplots(1, len(dists), figsize=(4 * len(dists), 3.6), sharey=True, squeeze=False)
    for ax, dist in zip(axes[0], dists):
        for code in CODES:
            pts = sorted((r["n"], r["time_s"]) for r in rows
                         if r["distribution"] == dist and r["code"] == LABEL[code] and "time_s" in r)
            if pts:
                ax.plot(*zip(*pts), marker="o", label=LABEL[code])
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(dist)
        ax.set_xlabel("points")
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel("seconds")
    axes[0][-1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    main()
