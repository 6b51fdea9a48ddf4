#!/usr/bin/env python3
"""ridt-mpi per rank, and a model of time, traffic and memory on a cluster drawn from it.

Runs `mpirun -np P ridt-mpi POINTS.bin -o OUT.ele --stats` for each distribution and rank
count, checks the merged result against `ridt triangulate -o` once a distribution, and writes
a Markdown page: each rank's points, the points it received, the rounds, the bytes it sent, the
share of its time spent in MPI calls and its peak memory; then the model's constants, fitted
from those figures, and what the model says for 10^9 and 10^10 points on 64 to 1,024 nodes.

  bench/mpi_table.py --build build [--n 1000000] [--ranks 1,2,4,8]
                     [--dists uniform,clusters,terrain] [--large 10000000] [--large-ranks 4]
                     [--out docs/mpi-results.md]

--large N (0: none) adds a run at N points of uniform and clusters on --large-ranks ranks: the
merged file against the single process's, `ridt check` on the parts, the rounds, and each
rank's peak memory against the single process's writing the same .ele.

On a machine with fewer cores than ranks (--oversubscribe), the time in MPI calls is mostly
waiting for ranks that share a core: the traffic, the rounds and the memory are the figures
to trust there, not the times.
"""
import argparse
import csv
import filecmp
import io
import math
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, env=ENV, **kw)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed ({r.returncode}): {r.stderr.strip()[-2000:]}")
    return r.stdout


def make_points(build, dist, n, path):
    if dist == "terrain":
        run([sys.executable, os.path.join(HERE, "terrain.py"), "-n", str(n), "-o", path])
    else:
        run([os.path.join(build, "ridt"), "generate", "--dist", dist, "-n", str(n), "--seed", "1", "-o", path])


def ranks_of(build, points, p, out):
    text = run(["mpirun", "-np", str(p), "--oversubscribe", os.path.join(build, "ridt-mpi"), points, "-o", out,
                "--stats"])
    rows = list(csv.DictReader(io.StringIO(text[text.index("rank,"):])))
    return [{k: float(v) for k, v in r.items()} for r in rows]


def single(build, points, reps=5):
    """Seconds a point and peak bytes a point of the single process (no output), medians of
    `reps` runs: one run on a shared machine can be far off."""
    import json
    runs = [json.loads(run([os.path.join(build, "ridt"), "triangulate", points, "--stats", "json"]))
            for _ in range(reps)]
    return (statistics.median(s["time_triangulate_s"] / s["points"] for s in runs),
            statistics.median(s["peak_rss_bytes"] / s["points"] for s in runs))


def single_peak(build, points, output):
    """Peak resident bytes of `ridt triangulate`, with or without writing an .ele file.

    A child's peak starts at this process's size when it was started (Linux carries the high
    mark across exec), so nothing large is ever read into this process: files are compared in
    chunks."""
    cmd = [os.path.join(build, "ridt"), "triangulate", points] + (["-o", output] if output else [])
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=ENV)
    _, status, usage = os.wait4(p.pid, 0)
    if status != 0:
        sys.exit(f"{' '.join(cmd)} failed: {p.stderr.read().decode()[-2000:]}")
    return usage.ru_maxrss * 1024


def large_rows(build, n, p, tmp, mem_fit):
    """At n points on p ranks: exactness, rounds, traffic and each rank's peak against one process.
    Each rank's (points, peak bytes) joins mem_fit[dist]."""
    rows = []
    for dist in ("uniform", "clusters"):
        pts = os.path.join(tmp, f"large-{dist}.bin")
        make_points(build, dist, n, pts)
        ref = os.path.join(tmp, "large-single.ele")
        bare, writing = single_peak(build, pts, None), single_peak(build, pts, ref)
        merged = os.path.join(tmp, "large-merged.ele")
        run(["mpirun", "-np", str(p), "--oversubscribe", os.path.join(build, "ridt-mpi"), pts, "-o", merged, "--merge"])
        if not filecmp.cmp(ref, merged, shallow=False):
            sys.exit(f"{dist} at {n} points: the merged result of {p} ranks differs from the single process's")
        os.remove(merged)
        ranks = ranks_of(build, pts, p, os.path.join(tmp, "large.ele"))
        check = run([os.path.join(build, "ridt"), "check", pts, os.path.join(tmp, "large.parts")]).strip()
        if not check.startswith("valid"):
            sys.exit(f"{dist} at {n} points: ridt check on the parts: {check}")
        peaks = [r["peak_mib"] * 2**20 for r in ranks]
        mem_fit.setdefault(dist, []).extend((r["points"], peak) for r, peak in zip(ranks, peaks))
        received = sum(r["received"] for r in ranks) / sum(r["points"] for r in ranks)
        rounds = max(r["rounds"] for r in ranks)
        rows.append(f"| {dist} | {p} | yes | {check.split(',')[0]} | {rounds:.0f} | {received:.4f} | "
                    f"{statistics.median(peaks) / 2**20:.0f} ({max(peaks) / 2**20:.0f}) | {bare / 2**20:.0f} | "
                    f"{writing / 2**20:.0f} | {max(peaks) / writing:.2f} |")
        for f in os.listdir(tmp):
            if f.startswith("large"):
                os.remove(os.path.join(tmp, f))
    return rows


def spread(values, fmt):
    lo, med, hi = min(values), statistics.median(values), max(values)
    return fmt.format(med) if lo == hi else f"{fmt.format(med)} ({fmt.format(lo)}–{fmt.format(hi)})"


def measure(a, dist, ranks, tmp, lines, fit, mem_fit):
    """One distribution: the merged result checked, then each rank count's row; the model's
    constants at the most ranks."""
    pts = os.path.join(tmp, f"{dist}.bin")
    make_points(a.build, dist, a.n, pts)
    ref = os.path.join(tmp, "single.ele")
    run([os.path.join(a.build, "ridt"), "triangulate", pts, "-o", ref])
    merged = os.path.join(tmp, "merged.ele")
    run(["mpirun", "-np", str(max(ranks)), "--oversubscribe", os.path.join(a.build, "ridt-mpi"), pts, "-o",
         merged, "--merge"])
    if not filecmp.cmp(ref, merged, shallow=False):
        sys.exit(f"{dist}: the merged result of {max(ranks)} ranks differs from the single process's")
    t_single, b_single = single(a.build, pts)
    for p in ranks:
        rows = ranks_of(a.build, pts, p, os.path.join(tmp, "out.ele"))
        own = [r["points"] for r in rows]
        got = [r["received"] / max(r["points"], 1) for r in rows]
        sent = [r["bytes_sent"] / max(r["points"], 1) for r in rows]
        comm = [r["comm_s"] / max(r["total_s"], 1e-9) for r in rows]
        peak = [r["peak_mib"] for r in rows]
        rounds = max(r["rounds"] for r in rows)
        lines.append(f"| {dist} | {p} | {spread(own, '{:,.0f}')} | {spread(got, '{:.3f}')} | {rounds:.0f} | "
                     f"{spread(sent, '{:.0f}')} | {spread(comm, '{:.2f}')} | {spread(peak, '{:.0f}')} |")
        mem_fit.setdefault(dist, []).extend((r["points"], r["peak_mib"] * 2**20) for r in rows)
        if p == max(ranks):
            fit[dist] = {
                "halo": statistics.median(r["received"] / math.sqrt(max(r["points"], 1)) for r in rows),
                "bytes": statistics.median(sent),
                "rounds": rounds,
                # One core each, not oversubscribed: the single process's time a point,
                # once a round (each round triangulates again).
                "compute": rounds * t_single,
                "single_s": t_single,
                "single_b": b_single,
            }


def fit_memory(mem_fit, fit):
    for dist, pairs in mem_fit.items():  # peak = fixed + per point, least squares over every rank
        xs, ys = [x for x, _ in pairs], [y for _, y in pairs]
        mx, my = statistics.mean(xs), statistics.mean(ys)
        slope = sum((x - mx) * (y - my) for x, y in pairs) / max(sum((x - mx) ** 2 for x in xs), 1e-9)
        fit[dist]["peak"], fit[dist]["fixed"] = slope, my - slope * mx


def ranks_page(a, lines, large):
    """The page's measured part: per rank, and the large run."""
    out = []
    out.append("# ridt-mpi per rank, and a model for a cluster\n")
    out.append(f"Written by `bench/mpi_table.py --n {a.n} --ranks {a.ranks} --dists {a.dists} --large {a.large} "
               f"--large-ranks {a.large_ranks}` on "
               f"a machine of {os.cpu_count()} cores, so every run with more ranks than "
               "cores is oversubscribed and its times in MPI calls are mostly waiting for ranks that share a core. "
               "Each distribution's merged result on the most ranks was first checked equal to `ridt triangulate -o`.\n")
    out.append("Per rank, median (least–most) over the ranks: points owned; points received over points owned; "
               "request rounds (the last finds nothing new); bytes sent a point owned (the first redistribution "
               "included); share of the rank's time in MPI calls; peak resident MiB.\n")
    out.append("| distribution | ranks | points | received | rounds | bytes/pt | in MPI | peak MiB |")
    out.append("|---|---:|---:|---:|---:|---:|---:|---:|")
    out.extend(lines)
    out.append("")
    if large:
        out.append(f"## {a.large:,} points on {a.large_ranks} ranks\n")
        out.append("The merged file compared with `ridt triangulate -o`'s; `ridt check` on the parts; the request "
                   "rounds; the points received over the points owned, all ranks together; each rank's peak "
                   "resident MiB, median (most); the single process's peak without output and writing the same "
                   "`.ele`; the most a rank needs over the single process writing.\n")
        out.append("| distribution | ranks | merged = single | check on the parts | rounds | received | "
                   "rank peak MiB | single, no output | single, writing | rank / single |")
        out.append("|---|---:|---|---|---:|---:|---:|---:|---:|---:|")
        out.extend(large)
        out.append("")
    return out


def model_page(fit):
    """The model for a cluster, from the fitted constants."""
    out = []
    out.append("## The model\n")
    out.append("A node holds n = N / P points. Its time is read + redistribute + compute + exchange:\n")
    out.append("- read: 16 n bytes from a parallel file system whose bandwidth B_fs is shared by the P nodes "
               "(16 N / B_fs);")
    out.append("- redistribute: nearly all of a node's points move once (24 bytes each with its index), over a "
               "link of B_net a node;")
    out.append("- compute: n times the single process's seconds a point on one core, once a round (ridt-mpi "
               "triangulates again each round; oversubscribed ranks' own times say nothing of a core's speed);")
    out.append("- exchange: the points received, h sqrt(n) (a region's border grows as the square root of its "
               "points; h fitted below), 24 bytes each, in the measured number of rounds, each round costing "
               "a few collectives (latency L log2 P).\n")
    out.append("Memory: a fixed part and bytes a point owned, fitted by least squares to every rank's peak "
               "above, the large run's included (the fixed part is mostly Open MPI's own).\n")
    out.append("Constants fitted at the most ranks above, per distribution:\n")
    out.append("| distribution | h | bytes/pt sent | rounds | compute s/pt | single process s/pt | "
               "rank peak: B/pt + fixed MiB | single process peak B/pt |")
    out.append("|---|---:|---:|---:|---:|---:|---:|---:|")
    for dist, f in fit.items():
        out.append(f"| {dist} | {f['halo']:.2f} | {f['bytes']:.0f} | {f['rounds']:.0f} | {f['compute'] * 1e6:.2f} µs | "
                   f"{f['single_s'] * 1e6:.2f} µs | {f['peak']:.0f} + {f['fixed'] / 2**20:.0f} | {f['single_b']:.0f} |")
    out.append("")
    b_fs, b_net, lat = 50e9, 10e9, 5e-6
    out.append(f"Assumed cluster: B_fs = {b_fs / 1e9:.0f} GB/s in all, B_net = {b_net / 1e9:.0f} GB/s a node, "
               f"L = {lat * 1e6:.0f} µs, one rank a node on one core (threads on the node would divide the "
               "compute term by their speed-up).\n")
    out.append("| distribution | N | nodes | points a node | read s | redistribute s | compute s | exchange s | "
               "total s | memory a node | traffic a node |")
    out.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for dist, f in fit.items():
        for big in (1e9, 1e10):
            for p in (64, 256, 1024):
                n = big / p
                t_read = 16 * big / b_fs
                t_red = 24 * n / b_net
                t_comp = n * f["compute"]
                halo = f["halo"] * math.sqrt(n)
                t_ex = 24 * halo / b_net + f["rounds"] * 4 * lat * math.log2(p)
                mem = f["peak"] * n + f["fixed"]
                traffic = 24 * n + 24 * halo
                out.append(f"| {dist} | 10^{round(math.log10(big))} | {p:,} | {n:,.0f} | {t_read:.1f} | {t_red:.2f} | "
                           f"{t_comp:.1f} | {t_ex:.3f} | {t_read + t_red + t_comp + t_ex:.1f} | "
                           f"{mem / 2**30:.1f} GiB | {traffic / 2**30:.2f} GiB |")
    out.append("")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--n", type=int, default=1000000)
    ap.add_argument("--ranks", default="1,2,4,8")
    ap.add_argument("--dists", default="uniform,clusters,terrain")
    ap.add_argument("--large", type=int, default=10000000)
    ap.add_argument("--large-ranks", type=int, default=4)
    ap.add_argument("--out", default="docs/mpi-results.md")
    a = ap.parse_args()
    ranks = [int(x) for x in a.ranks.split(",")]
    lines = []
    fit = {}  # per distribution at the most ranks: the model's constants
    mem_fit = {}  # per distribution: (points owned, peak bytes) of every rank of every run
    large = []
    with tempfile.TemporaryDirectory() as tmp:
        if a.large:
            large = large_rows(a.build, a.large, a.large_ranks, tmp, mem_fit)
        for dist in a.dists.split(","):
            measure(a, dist, ranks, tmp, lines, fit, mem_fit)
    fit_memory(mem_fit, fit)
    out = ranks_page(a, lines, large) + model_page(fit)
    os.makedirs(os.path.dirname(a.out) or ".", exist_ok=True)
    with open(a.out, "w") as f:
        f.write("\n".join(out))
    print("\n".join(out))


if __name__ == "__main__":
    main()
