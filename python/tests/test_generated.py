"""Generated inputs (hypothesis): small sets full of ties, repeated points, collinear runs and
extreme scales. Every result passes the exact validator and is the same for every method."""

import numpy as np
from hypothesis import given, settings, strategies as st

import ridt
from conftest import triangle_set

# Coordinates from a small grid of values make ties (cocircular, collinear, equal points)
# common; a scale per set moves them across the exponent range.
small = st.integers(min_value=-4, max_value=4).map(float)
point_sets = st.lists(st.tuples(small, small), min_size=0, max_size=60)
scales = st.sampled_from([1.0, 1e-300, 1e300, 3.0e-7, 0.1])


@settings(max_examples=300, deadline=None)
@given(point_sets, scales)
def test_valid_and_unique(points, scale):
    pts = np.array(points, dtype=np.float64).reshape(-1, 2) * scale
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ridt.DegenerateInputWarning)
        serial = ridt.Delaunay(pts)
        threaded = ridt.Delaunay(pts, method="partition", threads=3)
        optimistic = ridt.Delaunay(pts, method="optimistic", threads=2, order="random")
    valid, message = ridt.check(pts, serial.simplices)
    assert valid, message
    want = triangle_set(serial.simplices)
    assert triangle_set(threaded.simplices) == want
    assert triangle_set(optimistic.simplices) == want
    if serial.nsimplex:
        assert (serial.find_simplex(pts) >= 0).all()


@settings(max_examples=100, deadline=None)
@given(st.lists(st.tuples(st.floats(-1e6, 1e6), st.floats(-1e6, 1e6)), min_size=3, max_size=40),
       st.lists(st.tuples(st.floats(-2e6, 2e6), st.floats(-2e6, 2e6)), min_size=1, max_size=20))
def test_find_simplex_is_exact(points, queries):
    pts = np.array(points)
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ridt.DegenerateInputWarning)
        tri = ridt.Delaunay(pts)
    q = np.array(queries)
    exact = tri.find_simplex(q, tol=0)
    found = tri.find_simplex(q)  # scipy's tolerance: the same, but for points just outside
    for x, s, t in zip(q, exact, found):
        inside = [k for k in range(tri.nsimplex) if holds(pts[tri.simplices[k]], x)]
        if s >= 0:
            assert s in inside and t == s
        else:
            assert not inside
            if t >= 0:  # within the tolerance of a hull triangle, and of the bounding box
                eps = 100 * np.finfo(np.float64).eps  # scipy's default
                w = barycentric(pts[tri.simplices[t]], x)
                assert all(-eps * (1 + 1e-9) <= c <= 1 + eps * (1 + 1e-9) for c in w), w
                assert (x >= pts.min(axis=0) - eps).all() and (x <= pts.max(axis=0) + eps).all()


def barycentric(tri, x):
    """x's barycentric coordinates in the triangle, in exact rational arithmetic."""
    from fractions import Fraction as F
    (ax, ay), (bx, by), (cx, cy) = [(F(p[0]), F(p[1])) for p in tri]
    px, py = F(x[0]), F(x[1])
    def area(ux, uy, vx, vy, wx, wy):
        return (vx - ux) * (wy - uy) - (vy - uy) * (wx - ux)
    whole = area(ax, ay, bx, by, cx, cy)
    return [area(px, py, bx, by, cx, cy) / whole, area(ax, ay, px, py, cx, cy) / whole,
            area(ax, ay, bx, by, px, py) / whole]


def holds(tri, x):
    """The closed triangle holds x, in exact rational arithmetic."""
    from fractions import Fraction as F
    a, b, c = [(F(p[0]), F(p[1])) for p in tri]
    px, py = F(x[0]), F(x[1])
    def side(u, v):
        return (v[0] - u[0]) * (py - u[1]) - (v[1] - u[1]) * (px - u[0])
    return side(a, b) >= 0 and side(b, c) >= 0 and side(c, a) >= 0
