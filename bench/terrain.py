#!/usr/bin/env python3
"""Writes a point set that looks like an airborne LiDAR survey, as float64 x, y pairs (.bin).

What makes such sets hard for a distributed triangulation, and what this one has:
- flight strips: returns along scan lines across the flight direction, a few per metre along
  them, with the strips overlapping (twice the density where they do);
- density that changes: vegetation and buildings give more returns than open ground;
- holes: water gives no returns at all (a few lakes and a river);
- an irregular outline: the survey area's border is not a rectangle.

  bench/terrain.py -n 1000000 -o terrain.bin [--seed 1]
  bench/terrain.py -n 1000000 -o terrain.las [--seed 1]

The same n and seed give the same file. Coordinates are metres in a square of about
sqrt(n) / 2 metres a side (some 4 points a square metre).

A .las file (LAS 1.2, point format 0, millimetre scale) adds heights and classes: ground
(class 2) on rolling hills, and in the woods some returns from the canopy (class 5, 5 to 20 m
above the ground). It is drawn in chunks of a million points with the same survey (strips,
woods, lakes, river, border), so that 10^8 points need no more memory than 10^6.
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


def ground(x, y):
    """The terrain's height in metres: rolling hills, a tilt, and small bumps."""
    return 100 + 15 * np.sin(x / 60) * np.cos(y / 45) + 0.03 * x + 3 * np.sin(x / 7 + y / 11)


def survey(rng, side):
    """What every chunk of a .las shares: the woods (bumps of density) and the lakes."""
    bumps = rng.random((5, 3)) * [side, side, side / 4]
    lakes = [(rng.random() * side, rng.random() * side, side * (0.04 + 0.06 * rng.random())) for _ in range(3)]
    return bumps, lakes


def chunk(rng, count, side, bumps, lakes):
    """`count` returns of the survey: x, y, z and class, drawn as terrain() draws them."""
    strips = 6
    width = side / strips * 1.3
    xs, ys, ws = [], [], []
    have = 0
    while have < count:
        m = int((count - have) * 2.6) + 64
        strip = rng.integers(0, strips, m)
        centre = (strip + 0.5) * side / strips
        x = centre + (rng.random(m) - 0.5) * width
        y = rng.integers(0, int(side / 0.5) + 1, m) * 0.5 + rng.normal(0, 0.03, m) + 0.25 * ((x - centre) / width)
        keep = (x >= 0) & (x < side) & (y >= 0) & (y < side)
        weight = np.full(m, 0.35)
        for bx, by, r in bumps:
            weight += 0.65 * np.exp(-((x - bx) ** 2 + (y - by) ** 2) / (2 * (r + 1) ** 2))
        keep &= rng.random(m) < np.minimum(weight, 1.0)
        for cx, cy, r in lakes:
            keep &= (x - cx) ** 2 + (y - cy) ** 2 > r * r
        keep &= np.abs(y - side * (0.3 + 0.1 * np.sin(x / side * 6.0))) > side * 0.015
        keep &= x + y > side * 0.2
        xs.append(x[keep]), ys.append(y[keep]), ws.append(weight[keep])
        have += int(keep.sum())
    x, y, w = (np.concatenate(v)[:count] for v in (xs, ys, ws))
    z = ground(x, y)
    canopy = rng.random(count) < 0.4 * np.clip(w - 0.35, 0, 1)
    z = np.where(canopy, z + 5 + 15 * rng.random(count), z)
    return x, y, z, np.where(canopy, 5, 2).astype(np.uint8)


def write_las(n, seed, path, per_chunk=1_000_000):
    """n returns as LAS 1.2, point format 0 (20 bytes a point), coordinates to the millimetre."""
    import struct
    rng = np.random.default_rng(seed)
    side = max(np.sqrt(n) / 2.0, 1.0)
    bumps, lakes = survey(rng, side)
    record = np.dtype([("x", "<i4"), ("y", "<i4"), ("z", "<i4"), ("intensity", "<u2"), ("bits", "u1"),
                       ("cls", "u1"), ("angle", "i1"), ("user", "u1"), ("source", "<u2")])
    lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
    with open(path, "wb") as f:
        f.write(bytes(227))
        done = 0
        while done < n:
            count = min(per_chunk, n - done)
            x, y, z, cls = chunk(rng, count, side, bumps, lakes)
            r = np.zeros(count, record)
            r["x"], r["y"], r["z"] = (np.round(v * 1000).astype("<i4") for v in (x, y, z))
            r["bits"], r["cls"] = 1 | (1 << 3), cls  # return 1 of 1
            r.tofile(f)
            for k, v in enumerate((x, y, z)):
                lo[k], hi[k] = min(lo[k], v.min()), max(hi[k], v.max())
            done += count
        h = bytearray(227)
        h[0:4] = b"LASF"
        h[24], h[25] = 1, 2
        h[26:26 + 12] = b"ridt bench  "
        struct.pack_into("<HIIBHI", h, 94, 227, 227, 0, 0, 20, n)
        struct.pack_into("<3d3d", h, 131, 0.001, 0.001, 0.001, 0.0, 0.0, 0.0)
        struct.pack_into("<6d", h, 179, hi[0], lo[0], hi[1], lo[1], hi[2], lo[2])
        f.seek(0)
        f.write(bytes(h))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("-n", type=int, required=True)
    p.add_argument("-o", "--output", required=True)
    p.add_argument("--seed", type=int, default=1)
    a = p.parse_args()
    if a.n < 1:
        sys.exit("terrain: -n must be at least 1")
    if a.output.endswith(".las"):
        write_las(a.n, a.seed, a.output)
    else:
        terrain(a.n, a.seed).tofile(a.output)


if __name__ == "__main__":
    main()
