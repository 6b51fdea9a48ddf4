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
    assert "31 segments as chains of 31 edges" in message
    assert not ridt.check(pts, c.simplices)[0]
    one = ridt.ConstrainedDelaunay(pts, segs, method="serial")
    assert np.array_equal(one.simplices, c.simplices) and np.array_equal(one.edges, c.edges)


def test_a_segment_through_points_is_split():
    pts = np.array([(0, 0), (4, 0)] + [(k, 0) for k in (1, 2, 3)] + [(k + 0.5, 0.4) for k in range(4)]
                   + [(k + 0.5, -0.3) for k in range(4)], dtype=float)
    c = ridt.ConstrainedDelaunay(pts, [(0, 1)])
    assert c.check()[0]
    assert len(c.edges) == 4


def test_crossing_segments_are_split_where_they_cross():
    c = ridt.ConstrainedDelaunay(KITE, [(0, 2), (1, 3)])
    assert c.ncrossings == 1 and c.added.tolist() == [[4.0, 0.0]]
    assert c.npoints == 5 and c.ninput == 4 and c.points[4].tolist() == [4.0, 0.0]
    assert c.edges.tolist() == [[0, 4], [1, 4], [2, 4], [3, 4]]
    assert c.check()[0]
    rng = np.random.default_rng(9)
    pts = rng.random((500, 2))
    many = ridt.ConstrainedDelaunay(pts, np.arange(200).reshape(-1, 2))
    assert many.ncrossings > 100
    valid, message = many.check()
    assert valid, message


def test_bad_segments_are_refused():
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


SQUARE_WITH_HOLE = dict(
    vertices=[(0, 0), (1, 0), (1, 1), (0, 1), (0.4, 0.4), (0.6, 0.4), (0.6, 0.6), (0.4, 0.6)],
    segments=[(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4)],
    holes=[(0.5, 0.5)])


@pytest.mark.parametrize("angle", [20, 30, 34])
def test_a_quality_mesh_keeps_its_bounds(angle):
    g = SQUARE_WITH_HOLE
    c = ridt.ConstrainedDelaunay(g["vertices"], g["segments"], holes=g["holes"], convex_hull=False,
                                 min_angle=angle, max_area=0.002)
    valid, message = c.check()
    assert valid, message
    p = c.points[c.simplices]
    a, b, d = p[:, 0], p[:, 1], p[:, 2]
    area = 0.5 * ((b[:, 0] - a[:, 0]) * (d[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (d[:, 0] - a[:, 0]))
    assert (area > 0).all() and area.max() <= 0.002
    assert abs(area.sum() - (1 - 0.04)) < 1e-12  # the square less its hole, exactly covered

    def smallest(u, v, w):
        x, y = v - u, w - u
        return np.degrees(np.arctan2(np.abs(x[:, 0] * y[:, 1] - x[:, 1] * y[:, 0]), (x * y).sum(axis=1)))
    worst = np.minimum(np.minimum(smallest(a, b, d), smallest(b, d, a)), smallest(d, a, b))
    assert worst.min() >= angle - 1e-9


def test_regions_carry_attributes_and_area_bounds():
    g = SQUARE_WITH_HOLE
    pts = np.array(g["vertices"] + [(0.5, 0), (0.5, 1)], dtype=float)
    segs = g["segments"] + [(8, 9)]  # splits the square, and the hole: a seed on either side
    c = ridt.ConstrainedDelaunay(pts, segs, holes=[(0.45, 0.5), (0.55, 0.5)], convex_hull=False,
                                 regions=[(0.1, 0.5, 1.0, 0.001), (0.9, 0.5, 2.0, 0.0)])
    assert c.ncrossings == 2
    left = c.points[c.simplices].mean(axis=1)[:, 0] < 0.5
    assert (c.attributes[left] == 1).all() and (c.attributes[~left] == 2).all()
    p = c.points[c.simplices]
    area = 0.5 * np.abs((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1])
                        - (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0]))
    assert area[left].max() <= 0.001 and area[~left].max() > 0.01
    assert c.check()[0]


def test_max_steiner_stops_refinement_with_a_warning():
    g = SQUARE_WITH_HOLE
    with pytest.warns(ridt.RefinementWarning, match="stopped after 25 points"):
        c = ridt.ConstrainedDelaunay(g["vertices"], g["segments"], holes=g["holes"], convex_hull=False,
                                     min_angle=30, max_area=0.0005, max_steiner=25)
    assert len(c.added) == 25
    valid, message = c.check()  # a sound constrained triangulation; the bounds, not met, are not tested
    assert valid, message
    with pytest.raises(ValueError, match="max_steiner"):
        ridt.ConstrainedDelaunay(KITE, [(0, 2)], min_angle=30, max_steiner=-1)


def test_collinear_points_warn_as_delaunay_does():
    with pytest.warns(ridt.DegenerateInputWarning, match="collinear"):
        c = ridt.ConstrainedDelaunay([(0, 0), (1, 1), (2, 2)], [(0, 2)], min_angle=30)
    assert c.nsimplex == 0


def test_quality_bounds_are_checked():
    with pytest.raises(ValueError, match="34"):
        ridt.ConstrainedDelaunay(KITE, [(0, 2)], min_angle=40)
    with pytest.raises(ValueError):
        ridt.ConstrainedDelaunay(KITE, [(0, 2)], max_area=-1)
    with pytest.raises(ValueError, match="regions"):
        ridt.ConstrainedDelaunay(KITE, [(0, 2)], regions=[(1, 2)])


def _centroid_size(a, b, c, area):
    """Unsuitable above an area that grows with the centroid's distance from the origin."""
    x, y = (a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3
    return area > 0.0005 + 0.02 * (x * x + y * y)


def _areas(m):
    p = m.points[m.simplices]
    return ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1])
            - (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0])) / 2


def test_a_test_of_ones_own_grades_the_mesh():
    square = [(0, 0), (1, 0), (1, 1), (0, 1), (0.4, 0.4), (0.6, 0.4), (0.6, 0.6), (0.4, 0.6)]
    loops = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4)]
    seen = []

    def size(a, b, c, area):
        seen.append(area)
        return np.bool_(_centroid_size(a, b, c, area))  # numpy's bool is taken as Python's

    m = ridt.ConstrainedDelaunay(square, loops, holes=[(0.5, 0.5)], convex_hull=False, min_angle=25,
                                 unsuitable=size)
    assert m.check()[0], m.check()[1]
    assert len(seen) >= len(m.simplices)
    p = m.points[m.simplices]
    for tri, area in zip(p, _areas(m)):
        assert not _centroid_size(*tri, area)
    centroids = p.mean(axis=1)
    near = ((centroids[:, 0] < 0.5) & (centroids[:, 1] < 0.5)).sum()
    far = ((centroids[:, 0] > 0.5) & (centroids[:, 1] > 0.5)).sum()
    assert near > 3 * far
    finer = m.refine(unsuitable=lambda a, b, c, area: area > 0.001)
    assert len(finer.simplices) > len(m.simplices) and _areas(finer).max() <= 0.001
    again = ridt.ConstrainedDelaunay.from_mesh(m.points, m.simplices, m.edges, unsuitable=_centroid_size)
    assert len(again.added) == 0  # every triangle already suitable


def test_what_ones_test_raises_comes_out_and_a_bad_test_is_refused():
    square, loop = [(0, 0), (1, 0), (1, 1), (0, 1)], [(0, 1), (1, 2), (2, 3), (3, 0)]

    def broken(a, b, c, area):
        raise KeyError("the caller's own")

    with pytest.raises(KeyError, match="the caller's own"):
        ridt.ConstrainedDelaunay(square, loop, unsuitable=broken)
    with pytest.raises(TypeError, match="callable"):
        ridt.ConstrainedDelaunay(square, loop, unsuitable=0.01)
    with pytest.warns(ridt.RefinementWarning, match="stopped after 300"):
        m = ridt.ConstrainedDelaunay(square, loop, unsuitable=lambda a, b, c, area: True, max_steiner=300)
    assert len(m.added) == 300


def test_a_mesh_whose_pieces_overlap_is_refused():
    # No vertex shared: a small triangle inside a large one, and two squares whose edges cross.
    nested = np.array([[0, 0], [10, 0], [0, 10], [1, 1], [2, 1], [1, 2]], float)
    with pytest.raises(ValueError, match="covers the area about .* 2 times"):
        ridt.ConstrainedDelaunay.from_mesh(nested, [[0, 1, 2], [3, 4, 5]])
    squares = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [.5, .5], [1.5, .5], [1.5, 1.5], [.5, 1.5]])
    with pytest.raises(ValueError, match=r"cross at \(1, 0.5\)"):
        ridt.ConstrainedDelaunay.from_mesh(squares, [[0, 1, 2], [0, 2, 3], [4, 5, 6], [4, 6, 7]])
    # The large triangle alone, the others' points unused: a mesh.
    assert len(ridt.ConstrainedDelaunay.from_mesh(nested, [[0, 1, 2]]).simplices) == 1
