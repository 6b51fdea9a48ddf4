"""ridt.ConstrainedDelaunay: every result through the exact validator with its segments; the
kite's long diagonal, segments split at points, every method alike, bad input refused."""

import numpy as np
import pytest

import ridt
from conftest import triangle_set

KITE = np.array([(0, 0), (4, -1), (8, 0), (4, 1)], dtype=float)


def test_the_kites_long_diagonal():
    c = ridt.ConstrainedDelaunay(KITE, [(0, 2)])
    assert triangle_set(c.simplices) == triangle_set(np.array([(0, 1, 2), (0, 2, 3)]))
    assert c.check()[0]
    assert c.edges.tolist() == [[0, 2]]
    assert c.simplices.dtype == np.intc and c.neighbors.shape == (2, 3)
    assert not ridt.check(KITE, c.simplices)[0]  # not Delaunay without the segment
    assert triangle_set(ridt.ConstrainedDelaunay(KITE, []).simplices) == triangle_set(ridt.Delaunay(KITE).simplices)


def test_random_segments_everywhere():
    rng = np.random.default_rng(4)
    pts = rng.random((3000, 2))
    segs = np.array([(0, v) for v in range(1, 3000, 97)])  # a fan: segments meet only at point 0
    c = ridt.ConstrainedDelaunay(pts, segs, threads=2)
    valid, message = c.check()
    assert valid, message
    assert "constrained Delaunay with" in message
    assert not ridt.check(pts, c.simplices)[0]
    one = ridt.ConstrainedDelaunay(pts, segs, method="serial")
    assert np.array_equal(one.simplices, c.simplices) and np.array_equal(one.edges, c.edges)


def test_a_segment_through_points_is_split():
    pts = np.array([(0, 0), (4, 0)] + [(k, 0) for k in (1, 2, 3)] + [(k + 0.5, 0.4) for k in range(4)]
                   + [(k + 0.5, -0.3) for k in range(4)], dtype=float)
    c = ridt.ConstrainedDelaunay(pts, [(0, 1)])
    assert c.check()[0]
    assert len(c.edges) == 4


def test_bad_segments_are_refused():
    with pytest.raises(ValueError, match="crossed|cross"):
        ridt.ConstrainedDelaunay(KITE, [(0, 2), (1, 3)])
    with pytest.raises(ValueError, match="one of the 4 points"):
        ridt.ConstrainedDelaunay(KITE, [(0, 4)])
    with pytest.raises(ValueError, match="shape"):
        ridt.ConstrainedDelaunay(KITE, [0, 2])
    with pytest.raises(TypeError):
        ridt.ConstrainedDelaunay(KITE, [(0.0, 2.5)])
    with pytest.raises(ValueError):
        ridt.ConstrainedDelaunay(KITE, [(0, 2)], method="magic")


def test_holes_and_the_exterior():
    square = [(0, 0), (10, 0), (10, 10), (0, 10)]
    hole = [(4, 4), (6, 4), (6, 6), (4, 6)]
    rng = np.random.default_rng(2)
    pts = np.array(square + hole + [(-5, -5), (15, 15)] + rng.uniform(-4, 14, (400, 2)).tolist())
    loop = lambda first: [(first + k, first + (k + 1) % 4) for k in range(4)]
    segs = loop(0) + loop(4)
    whole = ridt.ConstrainedDelaunay(pts, segs)
    assert whole.check()[0]
    inner = ridt.ConstrainedDelaunay(pts, segs, holes=[(5, 5)], convex_hull=False)
    centroids = pts[inner.simplices].mean(axis=1)
    inside_square = (centroids > 0).all(axis=1) & (centroids < 10).all(axis=1)
    inside_hole = (centroids > 4).all(axis=1) & (centroids < 6).all(axis=1)
    assert (inside_square & ~inside_hole).all()
    all_centroids = pts[whole.simplices].mean(axis=1)
    wanted = (((all_centroids > 0) & (all_centroids < 10)).all(axis=1)
              & ~((all_centroids > 4) & (all_centroids < 6)).all(axis=1))
    assert inner.nsimplex == wanted.sum()
    assert len(inner.convex_hull) == 0 and len(whole.convex_hull) > 0
    with pytest.raises(ValueError):
        ridt.ConstrainedDelaunay(pts, segs, holes=[(np.nan, 1)])
