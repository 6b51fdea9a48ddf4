"""ridt.ConvexHull: scipy.spatial.ConvexHull's interface in the plane, against scipy where its
answer is unique, against exact rational arithmetic, and through the exact validator."""

from fractions import Fraction

import numpy as np
import pytest
import scipy.spatial
from hypothesis import given, settings, strategies as st

import ridt


def valid(hull, points=None):
    ok, message, _ = ridt.check_convex_hull(hull.points if points is None else points, hull.vertices)
    assert ok, message
    return hull


def rational_area(points, corners):
    p = [(Fraction(x), Fraction(y)) for x, y in points[corners]]
    return sum(a[0] * b[1] - a[1] * b[0] for a, b in zip(p, p[1:] + p[:1])) / 2


# Points on a circle only up to 1000: closer together than that, three in a row are collinear
# or turn the wrong way once rounded, and the exact hull leaves out some that Qhull keeps.
@pytest.mark.parametrize("shape, n", [(s, n) for s in ("uniform", "normal") for n in (3, 30, 1000, 100000)] +
                         [("disc", n) for n in (3, 30, 1000)])
def test_against_scipy(shape, n):
    rng = np.random.default_rng(n)
    if shape == "uniform":
        pts = rng.random((n, 2))
    elif shape == "normal":
        pts = rng.normal(size=(n, 2)) * 1e3 + 5e6
    else:  # many corners
        a = rng.random(n) * 2 * np.pi
        pts = np.column_stack([np.cos(a), np.sin(a)])
    h = valid(ridt.ConvexHull(pts))
    s = scipy.spatial.ConvexHull(pts)
    assert sorted(h.vertices) == sorted(s.vertices)
    assert h.vertices.dtype == s.vertices.dtype and h.simplices.dtype == s.simplices.dtype
    assert h.simplices.shape == s.simplices.shape and h.neighbors.shape == s.neighbors.shape
    assert h.equations.shape == s.equations.shape and h.coplanar.shape == s.coplanar.shape == (0, 3)
    assert {frozenset(e) for e in h.simplices.tolist()} == {frozenset(e) for e in s.simplices.tolist()}
    exact = float(rational_area(pts, h.vertices))
    assert abs(h.volume - exact) <= np.spacing(exact)  # scipy's: within 1e-12 or so
    np.testing.assert_allclose(h.volume, s.volume, rtol=1e-10)
    np.testing.assert_allclose(h.area, s.area, rtol=1e-12)
    assert h.good is None and h.ndim == 2 and h.npoints == n and h.nsimplex == len(h.vertices)
    np.testing.assert_array_equal(h.min_bound, pts.min(axis=0))
    np.testing.assert_array_equal(h.max_bound, pts.max(axis=0))


def test_vertices_counter_clockwise_from_the_least_point_and_sides_follow_them():
    pts = np.random.default_rng(5).random((500, 2))
    h = valid(ridt.ConvexHull(pts))
    v = h.vertices
    assert v[0] == np.lexsort((pts[:, 1], pts[:, 0]))[0]
    np.testing.assert_array_equal(h.simplices[:, 0], v)
    np.testing.assert_array_equal(h.simplices[:, 1], np.roll(v, -1))
    for k, (a, b) in enumerate(h.simplices):
        # the neighbour across from end a shares end b, and the other way round
        assert b in h.simplices[h.neighbors[k, 0]] and a in h.simplices[h.neighbors[k, 1]]
    # every point on the inner side of every side's equation; the corners on their sides' lines
    slack = h.equations[:, :2] @ pts.T + h.equations[:, 2:3]
    assert slack.max() <= 1e-15
    np.testing.assert_allclose(np.linalg.norm(h.equations[:, :2], axis=1), 1, rtol=1e-15)
    for k, (a, b) in enumerate(h.simplices):
        assert abs(h.equations[k, :2] @ pts[a] + h.equations[k, 2]) <= 1e-15


def test_area_exact_where_floating_point_sums_cancel():
    # A tilted thin quadrilateral far from the origin: the shoelace's products are near 10^18
    # and cancel to an area of order 1; the result is the rational area rounded once.
    o = 1e9
    pts = np.array([[o, o], [o + 3, o + 1], [o + 3.5, o + 2], [o + 0.25, o + 1.5], [o + 1, o + 1]])
    h = valid(ridt.ConvexHull(pts))
    exact = float(rational_area(pts, h.vertices))
    assert abs(h.volume - exact) <= np.spacing(exact)
    grid = np.array([[x, y] for x in range(7) for y in range(5)], dtype=float)
    h = valid(ridt.ConvexHull(grid))
    assert (h.volume, h.area) == (24.0, 20.0)
    assert len(h.vertices) == 4  # the points on the sides are not corners


def test_points_on_sides_and_copies_with_qc():
    pts = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0], [1, 1], [0.5, 0.5], [0, 0.25]])
    h = valid(ridt.ConvexHull(pts, qhull_options="Qc"))
    s = scipy.spatial.ConvexHull(pts, qhull_options="Qc")
    assert sorted(h.coplanar[:, 0]) == sorted(s.coplanar[:, 0]) == [4, 5, 7]
    for point, side, nearest in h.coplanar:
        a, b = h.simplices[side]
        assert nearest in (a, b)
        assert np.cross(pts[b] - pts[a], pts[point] - pts[a]) == 0
    assert len(ridt.ConvexHull(pts).coplanar) == 0  # without Qc none, as scipy


@pytest.mark.parametrize("option", ["QG4", "QG-4", "QG0", "QG-2"])
def test_good_sides_as_scipy_marks_them(option):
    rng = np.random.default_rng(3)
    pts = rng.random((40, 2))
    pts[4], pts[0] = [1.5, 0.5], [0.5, 0.5]  # point 4 beyond the others' hull, 0 inside it
    n = int(option.strip("QG-"))
    for incremental in (False, True):
        h = ridt.ConvexHull(pts, incremental=incremental, qhull_options=option)
        keep = np.arange(len(pts)) != n
        ok, message, _ = ridt.check_convex_hull(pts[keep], np.searchsorted(np.flatnonzero(keep), h.vertices))
        assert ok, message
        s = scipy.spatial.ConvexHull(pts, incremental=incremental, qhull_options=option)
        assert n not in h.vertices and len(h.good) == len(h.simplices)

        def marked(x):
            return {frozenset(e) for e in x.simplices[x.good].tolist()}

        assert marked(h) == marked(s)


def test_incremental_equals_fresh_and_close_ends_it():
    rng = np.random.default_rng(8)
    chunks = [rng.random((10, 2)), rng.random((50, 2)) * 2 - 0.5, np.array([[3.0, 3.0], [3.0, 3.0]])]
    h = ridt.ConvexHull(chunks[0], incremental=True)
    for c in chunks[1:]:
        h.add_points(c, restart=False)
    fresh = valid(ridt.ConvexHull(np.vstack(chunks)))
    np.testing.assert_array_equal(valid(h).vertices, fresh.vertices)
    assert h.volume == fresh.volume
    h.close()
    with pytest.raises(RuntimeError):
        h.add_points([[9.0, 9.0]])
    with pytest.raises(RuntimeError):
        ridt.ConvexHull(chunks[0]).add_points([[9.0, 9.0]])
    with pytest.raises(ValueError):
        ridt.ConvexHull(chunks[0], incremental=True, qhull_options="Qbb")


def test_refusals():
    with pytest.raises(ridt.DegenerateInputError):
        ridt.ConvexHull([[0, 0], [1, 1], [2, 2], [3, 3]])
    with pytest.raises(RuntimeError):  # as scipy's QhullError
        ridt.ConvexHull([[0, 0], [0, 0], [1, 1]])
    with pytest.raises(ValueError):
        ridt.ConvexHull([[0, 0], [1, np.nan], [1, 1]])
    with pytest.raises(ValueError):
        ridt.ConvexHull(np.ma.masked_all((3, 2)))
    with pytest.raises(ValueError):
        ridt.ConvexHull(np.zeros((4, 3)))
    with pytest.raises(ValueError):
        ridt.ConvexHull([[0, 0], [1, 0], [0, 1]], qhull_options="Qx QR0")
    with pytest.raises(ValueError):
        ridt.ConvexHull([[0, 0], [1, 0], [0, 1]], qhull_options="QG7")


def test_same_on_every_thread_count():
    pts = np.random.default_rng(2).normal(size=(200000, 2))
    one = ridt.ConvexHull(pts, threads=1)
    for t in (2, 3, 0):
        h = ridt.ConvexHull(pts, threads=t)
        np.testing.assert_array_equal(h.vertices, one.vertices)
        assert (h.volume, h.area) == (one.volume, one.area)


def test_validator_refuses_wrong_hulls():
    pts = np.array([[0, 0], [2, 0], [2, 2], [0, 2], [1, 0], [1, 1]], dtype=float)
    assert ridt.check_convex_hull(pts, [0, 1, 2, 3])[0]
    for wrong in ([0, 3, 2, 1], [0, 1, 2], [0, 4, 1, 2, 3], [0, 1, 2, 3, 0, 1, 2, 3], [], [0, 1, 7]):
        assert not ridt.check_convex_hull(pts, wrong)[0], wrong


coordinate = st.integers(-6, 6).map(float) | st.floats(-1e3, 1e3, allow_nan=False, width=32).map(float)


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(coordinate, coordinate), min_size=1, max_size=40))
def test_generated_sets_full_of_ties(points):
    pts = np.array(points, dtype=float)
    d = ridt.Delaunay(pts) if len(np.unique(pts, axis=0)) >= 3 else None
    try:
        h = ridt.ConvexHull(pts)
    except ridt.DegenerateInputError:
        assert ridt.check_convex_hull(pts, [])[0]
        return
    valid(h)
    # the triangulation's boundary, where it turns, is the same polygon
    assert d is not None and d.nsimplex > 0
    ring = d.triangulation.hull.astype(np.intp)
    f = [(Fraction(x), Fraction(y)) for x, y in pts]
    turn = [(f[b][0] - f[a][0]) * (f[c][1] - f[b][1]) != (f[b][1] - f[a][1]) * (f[c][0] - f[b][0])
            for a, b, c in zip(np.roll(ring, 1), ring, np.roll(ring, -1))]
    assert {tuple(p) for p in pts[ring[turn]]} == {tuple(p) for p in pts[h.vertices]}
    exact = float(rational_area(pts, h.vertices))
    assert abs(h.volume - exact) <= np.spacing(exact)
