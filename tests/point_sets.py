#!/usr/bin/python3
"""The point sets that the tools' end-to-end tests of regions run on (mpi_test.sh,
out_of_core_test.sh), as .bin files in OUT: degenerate sets (duplicates, collinear, a triangle,
cocircular points), the scales 1e+-300 and the robustness fixtures of FIXTURES_DIR.

    tests/point_sets.py OUT FIXTURES_DIR
"""
import json
import math
import os
import random
import struct
import sys

out, fixtures = sys.argv[1], sys.argv[2]
def save(name, pts):
    with open(os.path.join(out, name + ".bin"), "wb") as f:
        for x, y in pts:
            f.write(struct.pack("<dd", x, y))
rng = random.Random(3)
save("duplicates", [(rng.randint(0, 40), rng.randint(0, 40)) for _ in range(5000)])
save("collinear_plus_one", [(i, 2 * i) for i in range(2000)] + [(5.0, -1.0)])
save("collinear", [(i * 0.5, i * 0.25) for i in range(500)])
save("three", [(0, 0), (1, 0), (0, 1)])
save("cocircular", [(math.cos(2 * math.pi * k / 64), math.sin(2 * math.pi * k / 64)) for k in range(64)] + [(0, 0)])
# 2916 points with integer coordinates exactly on one circle: x + iy runs over the Gaussian
# integers of norm R^2, R = 5 * 13 * 17 * 29 * 37 * 41 (each prime a sum of two squares).
ring = {(1, 0)}
for a, b in [(1, 2), (2, 3), (1, 4), (2, 5), (1, 6), (4, 5)]:
    factors = [(a * a - b * b, 2 * a * b), (a * a + b * b, 0), (a * a - b * b, -2 * a * b)]
    ring = {(x * u - y * v, x * v + y * u) for x, y in ring for u, v in factors}
ring = {p for x, y in ring for p in [(x, y), (-y, x), (-x, -y), (y, -x)]}
save("lattice_circle", sorted(ring))
u = [(rng.random(), rng.random()) for _ in range(8000)]
save("huge", [(x * 1e300, y * 1e300) for x, y in u])
save("tiny", [(x * 1e-300, y * 1e-300) for x, y in u])
for name in sorted(os.listdir(fixtures)):
    if name.endswith(".json"):
        pts = json.load(open(os.path.join(fixtures, name)))
        save("fixture_" + name[:-5], [tuple(map(float, p)) for p in pts])
