#!/usr/bin/env python3
"""Writes a point set that looks like an airborne LiDAR survey, as float64 x, y pairs (.bin).

What makes such sets hard for a distributed triangulation, and what this one has:
- flight strips: returns along scan lines across the flight direction, a few per metre along
  them, with the strips overlapping (twice the density where they do);
- density that changes: vegetation and buildings give more returns than open ground;
- holes: water gives no returns at all (a few lakes and a river);
- an irregular outline: the survey area's border is not a rectangle.

  bench/terrain.py -n 1000000 -o terrain.bin [--seed 1]

The same n and seed give the same file. Coordinates are metres in a square of about
sqrt(n) / 2 metres a side (some 4 points a square metre).
"""
import argparse
import sys

import numpy as np


def terrain(n, seed):
    rng = np.random.default_rng(seed)
    side = max(np.sqrt(n) / 2.0, 1.0)
    # Candidates: more than needed, thinned to n at the end.
    m = int(n * 2.2) + 16
    strips = 6
    width = side / strips * 1.3  # overlapping strips
    strip = rng.integers(0, strips, m)
    centre = (strip + 0.5) * side / strips
    across = centre + (rng.random(m) - 0.5) * width
    # Scan lines across the strip, 0.5 m apart along the flight, each a zigzag of returns.
    line = rng.integers(0, int(side / 0.5) + 1, m)
    along = line * 0.5 + rng.normal(0, 0.03, m) + 0.25 * ((across - centre) / width)
    x, y = across, along
    keep = (x >= 0) & (x < side) & (y >= 0) & (y < side)
    # Returns per square metre vary: smooth bumps (woods, towns) over the ground.
    bumps = rng.random((5, 3)) * [side, side, side / 4]
    weight = np.full(m, 0.35)
    for bx, by, r in bumps:
        weight += 0.65 * np.exp(-((x - bx) ** 2 + (y - by) ** 2) / (2 * (r + 1) ** 2))
    keep &= rng.random(m) < np.minimum(weight, 1.0)
    # Water: three lakes and a river give no returns.
    for _ in range(3):
        cx, cy, r = rng.random() * side, rng.random() * side, side * (0.04 + 0.06 * rng.random())
        keep &= (x - cx) ** 2 + (y - cy) ** 2 > r * r
    river = side * (0.3 + 0.1 * np.sin(x / side * 6.0))
    keep &= np.abs(y - river) > side * 0.015
    # The survey's border: a polygon-like cut off one corner.
    keep &= x + y > side * 0.2
    x, y = x[keep], y[keep]
    if x.size < n:
        sys.exit(f"terrain: only {x.size} candidates for {n} points; raise the oversampling")
    pick = rng.choice(x.size, n, replace=False)
    return np.column_stack([x[pick], y[pick]]).astype("<f8")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("-n", type=int, required=True)
    p.add_argument("-o", "--output", required=True)
    p.add_argument("--seed", type=int, default=1)
    a = p.parse_args()
    if a.n < 1:
        sys.exit("terrain: -n must be at least 1")
    terrain(a.n, a.seed).tofile(a.output)


if __name__ == "__main__":
    main()
