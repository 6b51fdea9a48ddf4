"""ridt.PeriodicDelaunay and PeriodicVoronoi: against scipy's (Qhull's) Delaunay triangulation of
the copies laid out explicitly where they are exact doubles and the answer is unique, the exact
validator, the cells tiling the domain, duplicates and bad input."""

import numpy as np
import pytest
import scipy.spatial

from hypothesis import given, settings, strategies as st

import ridt


def _faces(simplices, offsets):
    """Each triangle as ((index, dx, dy) x 3), its least corner first at offset 0."""
    out = set()
    for tri, off in zip(simplices, offsets):
        c = [(int(tri[i]), int(off[i][0]), int(off[i][1])) for i in range(3)]
        k = c.index(min(c))
        c = c[k:] + c[:k]
        dx, dy = c[0][1], c[0][2]
        out.add(tuple((i, x - dx, y - dy) for i, x, y in c))
    return out


def _by_copies(points, periods, k=1):
    """The periodic triangles from scipy's triangulation of the copies in a (2k+1)^2 block:
    those whose least corner is a point as given and whose circle stays within the block."""
    n = len(points)
    shifts = [(dx, dy) for dy in range(-k, k + 1) for dx in range(-k, k + 1)]
    copies = np.concatenate([points + np.array(s) * periods for s in shifts])
    corner = [(i, s[0], s[1]) for s in shifts for i in range(n)]
    tri = scipy.spatial.Delaunay(copies)
    out = []
    offs = []
    for simplex in tri.simplices:
        a, b, c = copies[simplex]
        if (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) < 0:
            simplex = simplex[[0, 2, 1]]
            a, b, c = copies[simplex]
        corners = [corner[v] for v in simplex]
        low = min(corners)
        if low[1:] != (0, 0):
            continue
        d = 2 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
        b2, c2 = np.sum((b - a) ** 2), np.sum((c - a) ** 2)
        o = a + np.array([(c[1] - a[1]) * b2 - (b[1] - a[1]) * c2, (b[0] - a[0]) * c2 - (c[0] - a[0]) * b2]) / d
        r = np.hypot(*(a - o))
        reach = (k - 1) * np.min(periods) + 0.0
        if np.any(o - r < -reach) or np.any(o + r > periods + reach):
            continue
        out.append([v[0] for v in corners])
        offs.append([v[1:] for v in corners])
    return _faces(np.array(out), np.array(offs))


def test_equal_to_qhull_on_the_copies():
    rng = np.random.default_rng(4)
    # Coordinates on a grid of 2^-20 in a unit domain: every copy is exact.
    for n in (50, 2000):
        points = np.unique(np.floor(rng.random((n, 2)) * 2**20) / 2**20, axis=0)
        t = ridt.PeriodicDelaunay(points)
        valid, message = t.check()
        assert valid, message
        assert len(t) == 2 * len(points)
        assert _faces(t.simplices, t.offsets) == _by_copies(points, np.array([1.0, 1.0]), k=2)


def test_rectangular_domain_far_from_the_origin_and_cells():
    rng = np.random.default_rng(9)
    origin, periods = np.array([1e5, -3.0]), np.array([2.5, 0.75])
    points = origin + rng.random((3000, 2)) * periods
    points = np.minimum(points, np.nextafter(origin + periods, -np.inf))
    t = ridt.PeriodicDelaunay(points, periods=periods, origin=origin, threads=2)
    valid, message = t.check()
    assert valid, message
    assert t.simplices.shape == (6000, 3) and t.offsets.shape == (6000, 3, 2)
    assert (t.offsets[:, 0] == 0).all()
    corners = t.triangle_points() - origin
    a, b, c = corners[:, 0], corners[:, 1], corners[:, 2]
    assert ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]) > 0).all()
    # Each neighbour, moved by its offset, shares the edge.
    for k in range(0, len(t), 97):
        for i in range(3):
            u, s = t.neighbors[k, i], t.neighbor_offsets[k, i]
            edge = {(int(t.simplices[k, j]), *map(int, t.offsets[k, j])) for j in range(3) if j != i}
            theirs = {(int(t.simplices[u, j]), *map(int, t.offsets[u, j] + s)) for j in range(3)}
            assert edge <= theirs
    v = t.voronoi()
    areas = v.areas()
    assert (areas > 0).all()
    assert abs(areas.sum() - periods.prod()) < 1e-9 * periods.prod()
    # Each cell's vertices are as near to its point as to the other corners of their triangles.
    cell = v.cell(17) - points[17]
    for m, t_id in enumerate(v.regions[17]):
        r = np.hypot(*(t.triangle_points()[t_id] - v.vertices[t_id]).T)
        assert np.ptp(r) < 1e-9
        assert abs(np.hypot(*(cell[m])) - r[0]) < 1e-9


def test_lattice_ties_and_duplicates():
    x, y = np.meshgrid(np.arange(8.0), np.arange(8.0))
    points = np.column_stack([x.ravel(), y.ravel()])
    points = np.vstack([points, points[:3]])
    t = ridt.PeriodicDelaunay(points, periods=(8, 8))
    assert t.check()[0]
    assert len(t) == 128
    assert t.duplicates.tolist() == [[64, 0], [65, 1], [66, 2]]
    shuffled = np.random.default_rng(1).permutation(64)
    u = ridt.PeriodicDelaunay(points[shuffled], periods=(8, 8))
    back = _faces(shuffled[u.simplices], u.offsets)
    assert back == _faces(t.simplices, t.offsets)
    assert abs(t.voronoi().areas().sum() - 64) < 1e-12


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 5), st.integers(0, 3)), min_size=1, max_size=30))
def test_small_grids_cover_the_torus(cells):
    # Few points on a coarse grid: copies of one point in a triangle, collinear and cocircular
    # sets everywhere, duplicates.
    points = np.array(cells, dtype=np.float64) / [6, 4]
    t = ridt.PeriodicDelaunay(points)
    valid, message = t.check()
    assert valid, message
    assert len(t) == 2 * len(np.unique(points, axis=0))
    assert abs(t.voronoi().areas().sum() - 1) < 1e-12


@pytest.mark.parametrize("points,kwargs", [
    (np.zeros((0, 2)), {}),
    ([[1.0, 0.5]], {}),
    ([[0.5, np.nan]], {}),
    ([[0.5, 0.5]], {"periods": (0, 1)}),
    ([[0.5, 0.5]], {"periods": (1, np.inf)}),
])
def test_bad_input(points, kwargs):
    with pytest.raises(ValueError):
        ridt.PeriodicDelaunay(points, **kwargs)


def test_offsets_out_of_range_are_refused():
    t = ridt.PeriodicDelaunay(np.random.default_rng(3).random((50, 2)))
    assert t.check()[0]
    t.offsets[0, 0, 0] = 40000  # beyond what an offset may be: refused, not wrapped round
    with pytest.raises(ValueError, match="more than 1000 periods"):
        t.check()
    with pytest.raises(ValueError, match="more than 1000 periods"):
        t.voronoi()
