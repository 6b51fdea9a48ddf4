#!/usr/bin/env python3
"""Checks the kernel's symbolic bounding vertices against a concrete instance.

The kernel places B0 = (R, r), B1 = (-r, R^2), B2 = (-r, -R^3) with 1 << r << R and decides
every predicate that involves them by the leading term of a polynomial in R and r. Here they
are placed for real, with r = 10^6 and R = 10^40, and each decision printed by symbolic_dump
is recomputed with Python's exact integers."""
import subprocess
import sys

r, R = 10**6, 10**40
B = [(R, r), (-r, R**2), (-r, -R**3)]


def sign(v):
    return (v > 0) - (v < 0)


def orient(a, b, c):
    return sign((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))


def incircle(a, b, c, d):
    rows = [(p[0] - d[0], p[1] - d[1], (p[0] - d[0]) ** 2 + (p[1] - d[1]) ** 2) for p in (a, b, c)]
    (a1, a2, a3), (b1, b2, b3), (c1, c2, c3) = rows
    return sign(a1 * (b2 * c3 - b3 * c2) - a2 * (b1 * c3 - b3 * c1) + a3 * (b1 * c2 - b2 * c1))


def pt(x, y):
    return (int(float(x)), int(float(y)))


def bound(name):
    return B[int(name[1:])]


def main():
    out = subprocess.run([sys.argv[1]], check=True, capture_output=True, text=True).stdout
    checked = failed = 0
    for line in out.splitlines():
        f = line.split()
        if f[0] == "O":
            p, q, b = pt(f[1], f[2]), pt(f[3], f[4]), bound(f[5])
            want = [orient(p, q, b), orient(q, b, p), orient(b, p, q)]
            got = [int(v) for v in f[6:9]]
        elif f[0] == "C1":
            a, c, b, d = pt(f[1], f[2]), pt(f[3], f[4]), bound(f[5]), pt(f[6], f[7])
            want = [incircle(a, c, b, d), incircle(b, a, c, d)]
            got = [int(v) for v in f[8:10]]
        elif f[0] == "O2":
            a, bi, bj = pt(f[1], f[2]), bound(f[3]), bound(f[4])
            want = [orient(a, bi, bj), orient(a, bj, bi)]
            got = [int(v) for v in f[5:7]]
        elif f[0] == "C2":
            a, bi, bj, d = pt(f[1], f[2]), bound(f[3]), bound(f[4]), pt(f[5], f[6])
            want = [incircle(a, bi, bj, d), incircle(bj, a, bi, d)]
            got = [int(v) for v in f[7:9]]
        else:
            want = [orient(*B), orient(B[0], B[2], B[1])]
            got = [int(v) for v in f[1:3]]
        checked += 1
        if want != got or 0 in got:
            failed += 1
            if failed < 10:
                print("mismatch:", line, "want", want)
    print(f"symbolic rules: {checked - failed} passed, {failed} failed")
    return 1 if failed or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
