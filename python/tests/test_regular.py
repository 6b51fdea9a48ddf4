"""ridt.RegularTriangulation and ridt.PowerDiagram: the lower hull of the lifted points as
scipy's (Qhull's) ConvexHull finds it where the answer is unique, ridt.Delaunay's triangles for
equal weights, ties decided alike in every order, power centres of equal and least power, the
exact validator on every triangulation."""

import pickle

import numpy as np
import pytest
import scipy.spatial
from hypothesis import given, settings, strategies as st

import ridt


def valid(rt):
    ok, message = rt.check()
    assert ok, message
    return rt


def faces(points, triangles):
    """The triangles by their corners' coordinates, each from its least corner."""
    out = set()
    for t in triangles:
        c = [tuple(points[i]) for i in t]
        k = c.index(min(c))
        out.add(tuple(c[k:] + c[:k]))
    return out


def lower_hull(points, weights):
    """The regular triangulation by Qhull: the downward facets of the lifted points' hull,
    counter-clockwise in the plane."""
    lifted = np.c_[points, (points ** 2).sum(axis=1) - weights]
    hull = scipy.spatial.ConvexHull(lifted)
    tris = hull.simplices[hull.equations[:, 2] < 0]
    a, b, c = (points[tris[:, i]] for i in range(3))
    turn = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    tris[turn < 0] = tris[turn < 0][:, ::-1]
    return tris


@pytest.mark.parametrize("n,spread", [(10, 0.1), (500, 0.002), (5000, 0.0005), (5000, 0.01)])
def test_against_qhull_lower_hull(n, spread):
    rng = np.random.default_rng(n)
    p, w = rng.random((n, 2)), rng.random(n) * spread
    rt = valid(ridt.RegularTriangulation(p, w))
    tris = lower_hull(p, w)
    assert faces(p, rt.simplices) == faces(p, tris)
    assert set(rt.hidden.tolist()) == set(range(n)) - set(tris.ravel().tolist())
    if n >= 500 and spread >= 0.01:
        assert len(rt.hidden) > n // 10


def test_equal_weights_give_delaunay():
    rng = np.random.default_rng(2)
    p = rng.random((3000, 2))
    grid = np.stack(np.meshgrid(np.arange(20.0), np.arange(20.0)), axis=-1).reshape(-1, 2)
    for pts in (p, grid):
        rt = valid(ridt.RegularTriangulation(pts, np.full(len(pts), 0.25)))
        assert len(rt.hidden) == 0
        assert faces(pts, rt.simplices) == faces(pts, ridt.Delaunay(pts).simplices)


def test_power_diagram_vertices_have_equal_and_least_power():
    rng = np.random.default_rng(3)
    p, w = rng.random((400, 2)), rng.random(400) * 0.003
    rt = valid(ridt.RegularTriangulation(p, w))
    pd = rt.power_diagram()
    power = ((pd.vertices[:, None, :] - p[None, :, :]) ** 2).sum(axis=2) - w[None, :]
    own = np.take_along_axis(power, rt.simplices.astype(np.intp), axis=1)
    scale = np.maximum(1.0, np.abs(own).max(axis=1))
    assert np.all(np.ptp(own, axis=1) <= 1e-12 * scale)
    assert np.all(power.min(axis=1) >= own.min(axis=1) - 1e-12 * scale)
    # Hidden points: an empty region; the others: the centres of their triangles.
    for i in range(len(p)):
        region = pd.regions[pd.point_region[i]]
        if i in set(rt.hidden.tolist()):
            assert region == []
        else:
            around = set(np.flatnonzero((rt.simplices == i).any(axis=1)).tolist())
            assert set(region) - {-1} == around
    assert pd.hidden is rt.hidden
    again = pickle.loads(pickle.dumps(pd))
    assert np.array_equal(again.vertices, pd.vertices)
    # Equal weights: the Voronoi diagram's vertices (before cocircular ones merge).
    z = ridt.PowerDiagram(p, np.zeros(len(p)))
    assert z.vertices.shape == (len(ridt.Delaunay(p).simplices), 2)


def test_copies_points_at_one_place_and_threads():
    rng = np.random.default_rng(4)
    p, w = rng.random((2000, 2)), rng.random(2000) * 0.001
    p = np.vstack([p, p[:5], p[5:10]])
    w = np.concatenate([w, w[:5], w[5:10] - 0.01])  # five copies, five lighter at the same places
    rt = valid(ridt.RegularTriangulation(p, w, threads=2))
    assert sorted(rt.duplicates[:, 0].tolist()) == list(range(2000, 2005))
    assert set(range(2005, 2010)) <= set(rt.hidden.tolist())
    one = ridt.RegularTriangulation(p, w, threads=1)
    assert faces(p, one.simplices) == faces(p, rt.simplices)


def test_refusals():
    with pytest.raises(ValueError):
        ridt.RegularTriangulation(np.random.random((5, 2)), np.zeros(4))
    with pytest.raises(ridt.InputError):
        ridt.RegularTriangulation(np.random.random((5, 2)), [0, 0, np.nan, 0, 0])
    with pytest.raises(ridt.InputError, match="collinear"):
        ridt.RegularTriangulation([[0, 0], [1, 1], [2, 2], [3, 3]], [0, 1, 2, 3])
    with pytest.raises(ridt.InputError):
        ridt.RegularTriangulation([[0, 0], [1, 1]], [0, 0])
    with pytest.raises(RuntimeError):
        ridt.PowerDiagram(np.random.random((5, 2)), np.zeros(5)).add_points([[0.5, 0.5]])


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 6), st.integers(0, 6), st.integers(-2, 2)), min_size=3, max_size=40,
                unique_by=lambda t: (t[0], t[1])),
       st.randoms(use_true_random=False))
def test_lattice_ties_are_decided_alike_in_any_order(rows, random):
    a = np.array(rows, dtype=float)
    p, w = a[:, :2], a[:, 2]
    if np.linalg.matrix_rank(p - p[0]) < 2:
        with pytest.raises(ridt.InputError):
            ridt.RegularTriangulation(p, w)
        return
    first = valid(ridt.RegularTriangulation(p, w))
    order = list(range(len(p)))
    random.shuffle(order)
    again = valid(ridt.RegularTriangulation(p[order], w[order]))
    assert faces(p, first.simplices) == faces(p[order], again.simplices)
    assert set(map(tuple, p[first.hidden])) == set(map(tuple, p[order][again.hidden]))
