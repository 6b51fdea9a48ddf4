#!/usr/bin/python3
"""Draws, from the CSV of ridt_bench_threads:
- speedup_<dist>.png: speedup over serial against threads, one line per method, a panel per n;
- fig11_<dist>.png: the pessimistic method's total time against threads (the paper's Fig. 11);
- fig14_<dist>.png: speedup of 2 threads over 1 against n for both pessimistic locking
  variants, beside the paper's Table 3 (its Fig. 14).

    /usr/bin/python3 bench/plot_threads.py THREADS.csv OUTDIR [PREFIX]

PREFIX goes before each file's name (for a second configuration beside the first).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

METHODS = (("pessimistic", "pessimistic (lock at the leaf)"),
           ("optimistic", "optimistic (per-triangle try-locks)"),
           ("batch", "batch (locators + one modifier)"))
CORES_NOTE = "threads (2 cores: above 2 oversubscribed)"


def speedup_figure(rows, dist, outdir, prefix=""):
    sizes = sorted({int(r["n"]) for r in rows})
    fig, axes = plt.subplots(1, len(sizes), figsize=(3.2 * len(sizes), 3.6), sharey=True)
    if len(sizes) == 1:
        axes = [axes]
    for ax, n in zip(axes, sizes):
        for method, label in METHODS:
            pts = sorted((int(r["threads"]), float(r["speedup"])) for r in rows
                         if int(r["n"]) == n and r["method"] == method)
            if pts:
                ax.plot([t for t, _ in pts], [s for _, s in pts], marker="o", label=label)
        ax.axhline(1.0, color="grey", linewidth=0.8)
        ax.set_title(f"n = {n:,}")
        ax.set_xlabel(CORES_NOTE, fontsize=8)
        ax.grid(True, alpha=0.3)
    axes[0].set_ylabel("speedup over serial")
    axes[0].legend(fontsize=7)
    fig.suptitle(f"Threaded methods against serial ridt, {dist} points")
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, f"{prefix}speedup_{dist}.png"), dpi=110)
    plt.close(fig)


def fig11(rows, dist, outdir, prefix="", note=""):
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for n in sorted({int(r["n"]) for r in rows}):
        pts = sorted((int(r["threads"]), float(r["total_s"])) for r in rows
                     if int(r["n"]) == n and r["method"] == "pessimistic")
        if pts:
            ax.plot([t for t, _ in pts], [s for _, s in pts], marker="o", label=f"n = {n:,}")
    ax.set_xlabel(CORES_NOTE)
    ax.set_ylabel("total time [s]")
    ax.set_yscale("log")
    ax.set_title(f"Pessimistic method, {dist} points{note} (cf. paper Fig. 11)", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, f"{prefix}fig11_{dist}.png"), dpi=110)
    plt.close(fig)


def fig14(rows, dist, outdir, prefix="", note=""):
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for method, label in (("pessimistic", "ridt: lock at the leaf"),
                          ("paper", "ridt: lock at the leaves' parent (paper)")):
        speed = []
        for n in sorted({int(r["n"]) for r in rows}):
            t = {int(r["threads"]): float(r["total_s"]) for r in rows
                 if int(r["n"]) == n and r["method"] == method}
            if 1 in t and 2 in t:
                speed.append((n, t[1] / t[2]))
        if speed:
            ax.plot([n for n, _ in speed], [s for _, s in speed], marker="o", label=label)
    paper = [(1000, 0.076 / 0.058), (10000, 1.048 / 0.683), (50000, 6.200 / 3.960),
             (100000, 13.750 / 8.749), (500000, 87.0 / 58.276), (1000000, 200.4 / 135.4)]
    ax.plot([n for n, _ in paper], [s for _, s in paper], marker="s", linestyle="--",
            label="paper, Table 3 (2 x Pentium III)")
    ax.set_xscale("log")
    ax.set_xlabel("points")
    ax.set_ylabel("speedup, 1 thread / 2 threads")
    ax.axhline(1.0, color="grey", linewidth=0.8)
    ax.set_title(f"Pessimistic method, {dist} points{note} (cf. paper Fig. 14)", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, f"{prefix}fig14_{dist}.png"), dpi=110)
    plt.close(fig)


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: plot_threads.py THREADS.csv [OUTDIR [PREFIX]]")
    rows = list(csv.DictReader(open(sys.argv[1])))
    outdir = sys.argv[2] if len(sys.argv) > 2 else "."
    prefix = sys.argv[3] if len(sys.argv) > 3 else ""
    note = ", paper's location" if prefix else ""
    os.makedirs(outdir, exist_ok=True)
    for dist in sorted({r["distribution"] for r in rows}):
        mine = [r for r in rows if r["distribution"] == dist]
        speedup_figure(mine, dist, outdir, prefix)
        fig11(mine, dist, outdir, prefix, note)
        fig14(mine, dist, outdir, prefix, note)
    print("wrote figures to", outdir)


if __name__ == "__main__":
    main()
