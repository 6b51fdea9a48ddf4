#!/usr/bin/python3
"""Draws the paper's Fig. 11 (total time against threads, one line per n) and Fig. 14
(speedup of 2 threads over 1 against n) from the CSV of ridt_bench_threads.

    /usr/bin/python3 bench/plot_threads.py build/threads.csv docs/
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    rows = list(csv.DictReader(open(sys.argv[1])))
    outdir = sys.argv[2] if len(sys.argv) > 2 else "."
    os.makedirs(outdir, exist_ok=True)
    for dist in sorted({r["distribution"] for r in rows}):
        mine = [r for r in rows if r["distribution"] == dist]
        # Fig. 11: total runtime against the number of threads, ridt's locking variant.
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        for n in sorted({int(r["n"]) for r in mine}):
            pts = sorted((int(r["threads"]), float(r["total_s"])) for r in mine
                         if int(r["n"]) == n and r["variant"] == "leaf")
            if pts:
                ax.plot([t for t, _ in pts], [s for _, s in pts], marker="o", label=f"n = {n:,}")
        ax.set_xlabel("worker threads (2 cores: above 2 oversubscribed)")
        ax.set_ylabel("total time [s]")
        ax.set_yscale("log")
        ax.set_title(f"Pessimistic method, {dist} points (cf. paper Fig. 11)")
        ax.legend(fontsize=8)
        ax.grid(True, which="both", alpha=0.3)
        fig.tight_layout()
        fig.savefig(os.path.join(outdir, f"fig11_{dist}.png"), dpi=110)
        plt.close(fig)

        # Fig. 14: speedup of 2 threads over 1 thread, both locking variants.
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        for variant, label in (("leaf", "ridt: lock at the leaf"), ("paper", "paper: lock at the leaves' parent")):
            speed = []
            for n in sorted({int(r["n"]) for r in mine}):
                t = {int(r["threads"]): float(r["total_s"]) for r in mine
                     if int(r["n"]) == n and r["variant"] == variant}
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
        ax.set_title(f"Pessimistic method, {dist} points (cf. paper Fig. 14)")
        ax.legend(fontsize=8)
        ax.grid(True, which="both", alpha=0.3)
        fig.tight_layout()
        fig.savefig(os.path.join(outdir, f"fig14_{dist}.png"), dpi=110)
        plt.close(fig)
    print("wrote figures to", outdir)


if __name__ == "__main__":
    main()
