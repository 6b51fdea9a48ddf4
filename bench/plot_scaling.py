#!/usr/bin/python3
"""Draws scaling.png from the CSV of bench/scaling_table.py: for each n, the whole process's
speed over ridt's fastest serial mode (walking) against threads, one line per method, with
CGAL's range insert on one core as a horizontal line. Each point is the median over
repetitions of the ratio taken within a repetition.

    /usr/bin/python3 bench/plot_scaling.py docs/results/scaling.csv docs/results/scaling.png
"""
import csv
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

METHODS = (("partition", "partition (walking, regions)"),
           ("optimistic", "optimistic (DAG, try-locks)"),
           ("batch", "batch (DAG, one modifier)"),
           ("pessimistic", "pessimistic (DAG, one lock)"))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.strip().splitlines()[-1].strip())
    rows = list(csv.DictReader(open(sys.argv[1])))
    sizes = sorted({int(r["n"]) for r in rows})
    fig, axes = plt.subplots(1, len(sizes), figsize=(4.6 * len(sizes), 4.0), sharey=True)
    if len(sizes) == 1:
        axes = [axes]
    for ax, n in zip(axes, sizes):
        at_n = [r for r in rows if int(r["n"]) == n]
        for method, label in METHODS:
            threads = sorted({int(r["threads"]) for r in at_n if r["method"] == method})
            if not threads:
                continue
            speed = [statistics.median(float(r["vs_serial_walk"]) for r in at_n
                                       if r["method"] == method and int(r["threads"]) == t) for t in threads]
            ax.plot(threads, speed, marker="o", label=label)
        cgal = statistics.median(float(r["vs_serial_walk"]) for r in at_n if r["method"] == "cgal")
        ax.axhline(1.0, color="black", linewidth=0.9, label="ridt serial (walking)")
        ax.axhline(cgal, color="grey", linestyle="--", linewidth=0.9, label="CGAL, one core")
        ax.set_xscale("log", base=2)
        ax.set_xticks(sorted({int(r["threads"]) for r in at_n}))
        ax.get_xaxis().set_major_formatter(matplotlib.ticker.ScalarFormatter())
        ax.set_title(f"n = {n:,}")
        ax.set_xlabel("threads")
        ax.grid(True, alpha=0.3)
    axes[0].set_ylabel("speed over ridt serial (whole process)")
    axes[0].legend(fontsize=7)
    fig.suptitle("Thread scaling, uniform points, one process each")
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=110)


if __name__ == "__main__":
    main()
