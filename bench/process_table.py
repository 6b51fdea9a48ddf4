#!/usr/bin/env python3
"""Whole-process timings: `ridt triangulate` beside CGAL's range insert on the same .bin file.

Each code runs as its own process, from its start to its exit (reading the file included,
writing nothing), in a new random order every repetition, so that a drift of the machine's
speed touches every code alike. Reported: the median wall time of each code, its ratio to
CGAL's median, the median of the ratios taken repetition by repetition, and the peak resident
memory of the process per point (the input included). Writes a Markdown table (and CSV) with
the machine, the compiler and the command.

  bench/process_table.py --build build [--sizes 1000000,10000000] [--dists uniform,...]
                         [--reps 5] [--threads 2] [--out docs/results/process.md]
"""
import argparse
import csv
import os
import platform
import random
import statistics
import subprocess
import sys
import tempfile
import time


def run_once(cmd):
    """Wall seconds and peak resident bytes of one process."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    err = proc.stderr.read().decode(errors="replace")
    proc.stderr.close()
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"{' '.join(cmd)} failed: {err.strip()}")
    return wall, usage.ru_maxrss * 1024


def interleaved(commands, reps):
    """Each named command run `reps` times, the names in a new random order each repetition.
    Returns, by name, (median wall s, min, max, ratio of medians to the first name's, median of
    the paired ratios to the first name's run in the same repetition, median peak bytes)."""
    names = list(commands)
    walls = {name: [] for name in names}
    peaks = {name: [] for name in names}
    ratios = {name: [] for name in names}
    for _ in range(reps):
        order = list(names)
        random.shuffle(order)
        this = {}
        for name in order:
            this[name], peak = run_once(commands[name])
            walls[name].append(this[name])
            peaks[name].append(peak)
        for name in names:
            ratios[name].append(this[name] / this[names[0]])
    base = statistics.median(walls[names[0]])
    return {name: (statistics.median(walls[name]), min(walls[name]), max(walls[name]),
                   statistics.median(walls[name]) / base, statistics.median(ratios[name]),
                   statistics.median(peaks[name])) for name in names}


def write_csv(out, rows):
    """The rows as CSV beside the Markdown file `out`."""
    with open(os.path.splitext(out)[0] + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


def machine():
    cpu = "unknown CPU"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    mem = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2**30
    return f"{cpu}, {os.cpu_count()} cores, {mem:.0f} GiB, {platform.system()} {platform.release()}"


def tools(build):
    """The paths of `ridt` and `ridt_cgal_triangulate` in `build`; exits when one is missing."""
    ridt = os.path.join(build, "ridt")
    cgal = os.path.join(build, "ridt_cgal_triangulate")
    for tool in (ridt, cgal):
        if not os.access(tool, os.X_OK):
            sys.exit(f"{tool} is missing: build it first (cmake --build {build})")
    return ridt, cgal


def compiler(build):
    """The compiler that built the tool in `build`, as `ridt --version` says, else CMake's cache."""
    try:
        v = subprocess.run([os.path.join(build, "ridt"), "--version"], capture_output=True, text=True)
        if v.returncode == 0 and v.stdout.strip():
            return v.stdout.strip()
    except OSError:
        pass
    try:
        for line in open(os.path.join(build, "CMakeCache.txt")):
            if line.startswith("CMAKE_CXX_COMPILER:"):
                path = line.split("=", 1)[1].strip()
                return subprocess.run([path, "--version"], capture_output=True, text=True).stdout.splitlines()[0]
    except OSError:
        pass
    return "unknown compiler"


def write_page(a, rows):
    """The Markdown page and the CSV beside it."""
    write_csv(a.out, rows)
    with open(a.out, "w") as f:
        f.write("# Whole-process timings against CGAL\n\n")
        f.write(f"Written by `bench/process_table.py --build {a.build} --sizes {a.sizes} --dists {a.dists} "
                f"--reps {a.reps} --threads {a.threads}` on {time.strftime('%Y-%m-%d')}.\n\n")
        f.write(f"Machine: {machine()}. Compiler: {compiler(a.build)}.\n\n")
        f.write("Each code is one process on a `.bin` file of float64 pairs: read, triangulate, write "
                "nothing. Repetitions run the codes in a new random order each time. Time: median wall "
                "seconds (min to max). Ratio: to CGAL's median; paired: the median of the ratios "
                "within each repetition. Peak: the process's peak resident memory per point, "
                "the input's 16 bytes included.\n\n")
        f.write("| n | distribution | code | time s | min to max | ratio to CGAL | paired | peak B/pt |\n")
        f.write("|---:|---|---|---:|---:|---:|---:|---:|\n")
        for r in rows:
            f.write(f"| {r['n']:,} | {r['dist']} | {r['code']} | {r['median_s']:.3f} | "
                    f"{r['min_s']:.3f} to {r['max_s']:.3f} | {r['ratio']:.2f} | {r['paired_ratio']:.2f} | "
                    f"{r['bytes_per_point']:.0f} |\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--sizes", default="1000000")
    ap.add_argument("--dists", default="uniform,normal,grid,clusters")
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--out", default=None, help="Markdown file (a .csv beside it)")
    a = ap.parse_args()
    ridt, cgal = tools(a.build)
    t = str(a.threads)
    codes = [
        ("CGAL range insert", lambda f: [cgal, f]),
        ("ridt serial (walk)", lambda f: [ridt, "triangulate", f, "--method", "serial"]),
        (f"ridt partition {t}", lambda f: [ridt, "triangulate", f, "--method", "partition", "--threads", t]),
        (f"ridt optimistic {t} (DAG)", lambda f: [ridt, "triangulate", f, "--method", "optimistic", "--threads", t]),
    ]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for n in [int(s) for s in a.sizes.split(",")]:
            for dist in a.dists.split(","):
                points = os.path.join(tmp, f"{dist}-{n}.bin")
                subprocess.run([ridt, "generate", "--dist", dist, "-n", str(n), "-o", points], check=True)
                timed = interleaved({name: cmd(points) for name, cmd in codes}, a.reps)
                for name, _ in codes:
                    med, low, high, ratio, paired, peak = timed[name]
                    rows.append({"n": n, "dist": dist, "code": name, "median_s": med, "min_s": low, "max_s": high,
                                 "ratio": ratio, "paired_ratio": paired, "bytes_per_point": peak / n})
                    r = rows[-1]
                    print(f"{n:>9} {dist:<9} {name:<26} {med:8.3f} s  x{r['ratio']:.3f}"
                          f" (paired {r['paired_ratio']:.3f})  {r['bytes_per_point']:6.1f} B/pt", flush=True)
    if a.out:
        write_page(a, rows)

if __name__ == "__main__":
    main()
