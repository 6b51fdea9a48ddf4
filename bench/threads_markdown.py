#!/usr/bin/python3
"""Prints docs/threads.md's tables from the CSV of ridt_bench_threads: the speedup over serial for
every method and thread count, and the paper's Table 2 and 3 columns for one n.

    /usr/bin/python3 bench/threads_markdown.py docs/threads.csv [N]
"""
import csv
import sys

METHODS = ("pessimistic", "paper", "optimistic", "batch")


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: threads_markdown.py THREADS.csv [N]")
    rows = list(csv.DictReader(open(sys.argv[1])))
    detail_n = int(sys.argv[2]) if len(sys.argv) > 2 else max(int(r["n"]) for r in rows)
    threads = sorted({int(r["threads"]) for r in rows if r["method"] != "serial"})
    for dist in sorted({r["distribution"] for r in rows}):
        mine = [r for r in rows if r["distribution"] == dist]
        print(f"\nSpeedup over serial, {dist} points (serial's total time in seconds):\n")
        print("| n | serial [s] | method | " + " | ".join(f"{t} thr." for t in threads) + " |")
        print("|---:|---:|---|" + "---:|" * len(threads))
        for n in sorted({int(r["n"]) for r in mine}):
            serial = next(float(r["total_s"]) for r in mine if int(r["n"]) == n and r["method"] == "serial")
            for i, method in enumerate(METHODS):
                cells = {int(r["threads"]): float(r["speedup"]) for r in mine
                         if int(r["n"]) == n and r["method"] == method}
                if not cells:
                    continue
                first = f"{n:,} | {serial:.4f}" if i == 0 else " | "
                print(f"| {first} | {method} | " +
                      " | ".join(f"{cells[t]:.2f}" if t in cells else "" for t in threads) + " |")
        print(f"\nThe paper's columns at n = {detail_n:,}, {dist} points (seconds; critical and"
              " waiting summed over threads):\n")
        print("| method | threads | total | insertion | critical | waiting | speedup | retries |"
              " idle | stall | queue depth | stale hints |")
        print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        for r in mine:
            if int(r["n"]) != detail_n:
                continue
            if r["method"] == "serial":
                print(f"| serial | 1 | {float(r['total_s']):.3f} | {float(r['insert_s']):.3f} |"
                      " | | 1.00 | | | | | |")
                continue
            print(f"| {r['method']} | {r['threads']} | {float(r['total_s']):.3f} |"
                  f" {float(r['insert_s']):.3f} | {float(r['critical_s']):.3f} |"
                  f" {float(r['wait_s']):.3f} | {float(r['speedup']):.2f} | {r['retries']} |"
                  f" {float(r['idle_s']):.3f} | {float(r['stall_s']):.3f} |"
                  f" {float(r['queue_depth']):.0f} | {r['stale_hints']} |")


if __name__ == "__main__":
    main()
