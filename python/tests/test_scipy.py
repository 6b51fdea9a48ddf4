"""ridt.Delaunay against scipy.spatial.Delaunay on points in general position, where the
Delaunay triangulation is unique: the same triangles, and every attribute with the same
shape, dtype and meaning."""

import numpy as np
import pytest
import scipy.spatial

import ridt
from conftest import assert_valid, matching, triangle_set


def general_position(kind, n, seed):
    rng = np.random.default_rng(seed)
    if kind == "uniform":
        return rng.random((n, 2))
    if kind == "normal":
        return rng.normal(size=(n, 2))
    if kind == "clusters":
        centres = rng.random((10, 2))
        return centres[rng.integers(0, 10, n)] + rng.normal(scale=0.01, size=(n, 2))
    if kind == "shifted":  # far from the origin, as map coordinates are
        return rng.random((n, 2)) * [3.0, 1.0] + [50.0, -20.0]
    raise ValueError(kind)


KINDS = ["uniform", "normal", "clusters", "shifted"]


@pytest.fixture(params=[(k, n) for k in KINDS for n in (10, 500, 5000)], ids=lambda p: f"{p[0]}-{p[1]}")
def pair(request):
    kind, n = request.param
    pts = general_position(kind, n, seed=n)
    return pts, ridt.Delaunay(pts), scipy.spatial.Delaunay(pts)


def test_same_triangles(pair):
    pts, ours, theirs = pair
    assert triangle_set(ours.simplices) == triangle_set(theirs.simplices)
    assert_valid(pts, ours)


def test_shapes_and_dtypes(pair):
    _, ours, theirs = pair
    for name in ["points", "simplices", "neighbors", "equations", "transform", "vertex_to_simplex",
                 "convex_hull", "coplanar", "min_bound", "max_bound"]:
        a, b = getattr(ours, name), getattr(theirs, name)
        assert a.dtype == b.dtype, name
        assert a.shape[1:] == b.shape[1:], name
        if name not in ("convex_hull", "coplanar"):
            assert a.shape == b.shape, name
    assert ours.convex_hull.shape == theirs.convex_hull.shape
    for name in ["npoints", "nsimplex", "ndim", "furthest_site"]:
        assert getattr(ours, name) == getattr(theirs, name), name
    for a, b in zip(ours.vertex_neighbor_vertices, theirs.vertex_neighbor_vertices):
        assert a.dtype == b.dtype and a.shape == b.shape


def test_simplices_counter_clockwise_and_points_kept(pair):
    pts, ours, _ = pair
    p = pts[ours.simplices]
    cross = (p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1]) - (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0])
    assert (cross > 0).all()
    np.testing.assert_array_equal(ours.points, pts)
    np.testing.assert_array_equal(ours.min_bound, pts.min(axis=0))
    np.testing.assert_array_equal(ours.max_bound, pts.max(axis=0))


def test_neighbors_meaning(pair):
    _, ours, theirs = pair
    # The k-th neighbour is across from the k-th vertex: it shares the other two, and the same
    # triangle in scipy has the same neighbour across from the same vertex.
    perm = matching(ours.simplices, theirs.simplices)
    for i in range(0, theirs.nsimplex, max(1, theirs.nsimplex // 300)):
        o = perm[i]
        for k in range(3):
            v = ours.simplices[o, k]
            kt = int(np.flatnonzero(theirs.simplices[i] == v)[0])
            nt, no = theirs.neighbors[i, kt], ours.neighbors[o, k]
            assert (nt == -1) == (no == -1)
            if no >= 0:
                assert perm[nt] == no
                assert v not in ours.simplices[no]
                assert len(set(ours.simplices[o]) & set(ours.simplices[no])) == 2


def test_hull_and_vertex_maps(pair):
    _, ours, theirs = pair
    assert {frozenset(e) for e in ours.convex_hull.tolist()} == {frozenset(e) for e in theirs.convex_hull.tolist()}
    for v, t in enumerate(ours.vertex_to_simplex):
        assert v in ours.simplices[t]
    ip, ix = ours.vertex_neighbor_vertices
    jp, jx = theirs.vertex_neighbor_vertices
    for v in range(ours.npoints):
        assert sorted(ix[ip[v]:ip[v + 1]]) == sorted(jx[jp[v]:jp[v + 1]])
    assert ours.coplanar.shape == (0, 3) == theirs.coplanar.shape


def test_lift_equations_plane_distance(pair):
    pts, ours, theirs = pair
    assert ours.paraboloid_scale == pytest.approx(theirs.paraboloid_scale, rel=1e-12)
    assert ours.paraboloid_shift == pytest.approx(theirs.paraboloid_shift, rel=1e-12, abs=1e-300)
    q = np.random.default_rng(3).random((7, 2)) * (pts.max(0) - pts.min(0)) + pts.min(0)
    np.testing.assert_allclose(ours.lift_points(q), theirs.lift_points(q), rtol=1e-12)
    perm = matching(ours.simplices, theirs.simplices)
    scale = np.abs(theirs.equations).max()
    np.testing.assert_allclose(ours.equations[perm], theirs.equations, rtol=0, atol=1e-8 * scale)
    dist = ours.plane_distance(q)
    assert dist.shape == (7, ours.nsimplex)
    np.testing.assert_allclose(dist[:, perm], theirs.plane_distance(q), rtol=0, atol=1e-8 * scale)


def test_transform_gives_barycentric_coordinates(pair):
    pts, ours, theirs = pair
    # Both maps give, for a point, the weights of the triangle's vertices that reproduce it;
    # the vertices come in another rotation in scipy, so compare the weights vertex by vertex.
    perm = matching(ours.simplices, theirs.simplices)
    rng = np.random.default_rng(5)
    for i in range(0, theirs.nsimplex, max(1, theirs.nsimplex // 200)):
        o = perm[i]
        x = pts[ours.simplices[o]].T @ rng.dirichlet([1, 1, 1])
        def weights(tri, s):
            t = tri.transform[s]
            c = t[:2] @ (x - t[2])
            return dict(zip(tri.simplices[s].tolist(), [*c, 1 - c.sum()]))
        a, b = weights(ours, o), weights(theirs, i)
        assert a.keys() == b.keys()
        for v in a:
            assert a[v] == pytest.approx(b[v], abs=1e-7)


def test_find_simplex_matches_away_from_edges(pair):
    pts, ours, theirs = pair
    rng = np.random.default_rng(9)
    lo, hi = pts.min(0), pts.max(0)
    q = lo + (rng.random((4000, 2)) * 1.4 - 0.2) * (hi - lo)
    a, b = ours.find_simplex(q), theirs.find_simplex(q)
    assert a.dtype == b.dtype and a.shape == b.shape
    # Points close to an edge may go either way in scipy, which uses a tolerance: compare where
    # scipy's barycentric coordinates are clearly inside or the point clearly outside.
    inside = b >= 0
    c = np.einsum("nij,nj->ni", theirs.transform[b[inside], :2], q[inside] - theirs.transform[b[inside], 2])
    clear = np.minimum(c.min(axis=1), 1 - c.sum(axis=1)) > 1e-9
    perm = matching(ours.simplices, theirs.simplices)
    np.testing.assert_array_equal(a[inside][clear], perm[b[inside][clear]])
    assert (a[~inside] == -1).sum() >= 0.98 * (~inside).sum()
    # ridt's answer always holds the point, exactly.
    hit = a >= 0
    p = pts[ours.simplices[a[hit]]]
    for k in range(3):
        e0, e1 = p[:, k], p[:, (k + 1) % 3]
        side = (e1[:, 0] - e0[:, 0]) * (q[hit, 1] - e0[:, 1]) - (e1[:, 1] - e0[:, 1]) * (q[hit, 0] - e0[:, 0])
        assert (side >= -1e-12 * np.abs(hi - lo).max() ** 2).all()


def test_find_simplex_shapes():
    pts = general_position("uniform", 300, 1)
    ours, theirs = ridt.Delaunay(pts), scipy.spatial.Delaunay(pts)
    for shape in [(2,), (5, 2), (3, 4, 2), (0, 2)]:
        q = np.random.default_rng(2).random(shape)
        assert ours.find_simplex(q).shape == theirs.find_simplex(q).shape
    assert ours.find_simplex(np.array([[np.nan, 0.5], [0.5, np.inf]])).tolist() == [-1, -1]
    q = np.random.default_rng(3).random((10, 2)).astype(np.float32)
    np.testing.assert_array_equal(ours.find_simplex(q), ours.find_simplex(q.astype(np.float64)))


def test_delaunator_fixtures_match_scipy_where_scipy_is_right():
    # The robustness fixtures are near-degenerate; ridt must be valid on every one, and equal
    # to scipy's answer whenever scipy's answer is a valid triangulation too.
    from conftest import fixture
    for name in ["ukraine", "robustness1", "robustness2", "robustness3", "issue13", "issue43", "issue44"]:
        pts = fixture(name)
        ours = ridt.Delaunay(pts)
        assert_valid(pts, ours)
        theirs = scipy.spatial.Delaunay(pts)
        if ridt.check(pts, theirs.simplices)[0] and len(np.unique(pts, axis=0)) == len(pts):
            assert triangle_set(ours.simplices) == triangle_set(theirs.simplices), name


def test_matplotlib_triangulation():
    pts = general_position("uniform", 400, 4)
    ours = ridt.Delaunay(pts)
    mtri = ours.to_matplotlib()
    np.testing.assert_array_equal(mtri.triangles, ours.simplices)
    # matplotlib's own neighbours of the same triangles, computed from scratch.
    import matplotlib.tri
    fresh = matplotlib.tri.Triangulation(pts[:, 0], pts[:, 1], triangles=ours.simplices)
    np.testing.assert_array_equal(mtri.neighbors, fresh.neighbors)
    assert mtri.get_trifinder()(0.5, 0.5) >= 0


def test_far_from_the_origin_ridt_stays_exact():
    # Qhull lifts x^2 + y^2 in floating point: far from the origin the lift loses the digits
    # that decide, and scipy's triangles can fail the exact check. ridt's never do.
    rng = np.random.default_rng(10)
    for n in (10, 1000):
        pts = rng.random((n, 2)) * [3.0, 1.0] + [5e5, -2e6]
        ours = ridt.Delaunay(pts)
        assert_valid(pts, ours)
        theirs = scipy.spatial.Delaunay(pts)
        if ridt.check(pts, theirs.simplices)[0]:
            assert triangle_set(ours.simplices) == triangle_set(theirs.simplices)
