"""scipy's call forms and behaviours that ridt takes on, and the exactness of its answers where
scipy's floating point gives up: linear interpolation against a rational reference, nearest
neighbours without a triangle, pickling, incremental insertion, transforms."""

import copy
import pickle
import subprocess
import sys
import warnings
from fractions import Fraction

import numpy as np
import pytest
import scipy.interpolate
import scipy.spatial

import ridt


def rational_linear(points, values, tri, queries):
    """The piecewise-linear interpolant of ridt's own triangles at each query, in rational
    arithmetic: the exact answer the floating-point one must approach."""
    found = tri.find_simplex(queries)
    out = []
    for q, t in zip(queries, found):
        if t < 0:
            out.append(None)
            continue
        a, b, c = ([Fraction(x) for x in points[v]] for v in tri.simplices[t])
        qx, qy = Fraction(q[0]), Fraction(q[1])

        def area(u, v, w):
            return (u[0] - w[0]) * (v[1] - w[1]) - (u[1] - w[1]) * (v[0] - w[0])

        whole = area(a, b, c)
        w = [area((qx, qy), b, c) / whole, area(a, (qx, qy), c) / whole, area(a, b, (qx, qy)) / whole]
        out.append(sum(wi * Fraction(values[v]) for wi, v in zip(w, tri.simplices[t])))
    return out


def assert_matches_rational(points, values, queries, **kw):
    ip = ridt.LinearNDInterpolator(points, values, **kw)
    got = ip(queries)
    # The queries where the interpolator takes them: in the rescaled plane when it rescales.
    where = (queries - ip._offset) / ip._scale if kw.get("rescale") else queries
    want = rational_linear(ip.tri.points, values, ip.tri, where)
    scale = float(np.abs(values).max())
    for g, w in zip(got, want):
        if w is None:
            assert np.isnan(g)
        else:
            assert abs(g - float(w)) <= 1e-12 * scale, (g, float(w))
    return got


def test_the_sliver_that_rounded_to_nan():
    x = np.array([(0, 0), (-.5, -.5), (-.5, .5), (.5, .5), (.25, .3)])
    v = np.arange(5.0)
    # At the data points the data, exactly, with and without rescaling; scipy agrees.
    for rescale in (False, True):
        got = ridt.griddata(x, v, x, method="linear", rescale=rescale)
        assert (got == v).all()
        assert np.allclose(got, scipy.interpolate.griddata(x, v, x, method="linear", rescale=rescale))


def test_linear_agrees_with_a_rational_reference_on_slivers():
    rng = np.random.default_rng(5)
    # Points rounded onto a diagonal boundary: long thin triangles along it.
    t = rng.random(200)
    pts = np.round(np.stack([t, t + rng.normal(0, 1e-9, t.size)], axis=1), 10)
    pts = np.concatenate([pts, [[0, 1], [1, 0]]])
    vals = rng.normal(size=len(pts))
    tri = ridt.Delaunay(pts)
    # Queries inside: points of the triangles' sides and random convex combinations.
    corners = pts[tri.simplices]
    w = rng.dirichlet([1, 1, 1], size=len(corners))
    queries = np.concatenate([np.einsum("ij,ijk->ik", w, corners), (corners[:, 0] + corners[:, 1]) / 2, pts])
    assert_matches_rational(pts, vals, queries)


@pytest.mark.parametrize("scale", [1e-300, 1e-150, 1.0, 1e150, 1e300])
def test_linear_agrees_with_a_rational_reference_at_every_scale(scale):
    rng = np.random.default_rng(11)
    pts = rng.random((60, 2)) * scale
    vals = rng.normal(size=60) * 1e3
    tri = ridt.Delaunay(pts)
    w = rng.dirichlet([1, 1, 1], size=tri.nsimplex)
    queries = np.einsum("ij,ijk->ik", w, pts[tri.simplices])
    got = assert_matches_rational(pts, vals, np.concatenate([queries, pts]))
    assert np.isfinite(got).all()


def test_linear_agrees_with_a_rational_reference_on_a_rounded_lattice_after_rescale():
    g = np.linspace(0, 1, 9)
    pts = np.stack(np.meshgrid(g * 1e6 + 0.1, g * 1e-3), axis=-1).reshape(-1, 2)
    vals = np.sin(pts[:, 0] * 1e-6) + pts[:, 1] * 1e3
    rng = np.random.default_rng(2)
    queries = np.stack([rng.uniform(0.1, 1e6 + 0.1, 300), rng.uniform(0, 1e-3, 300)], axis=1)
    assert_matches_rational(pts, vals, queries, rescale=True)


def test_nothing_inside_the_hull_is_nan():
    rng = np.random.default_rng(3)
    t = rng.random(500)
    pts = np.round(np.stack([t, 1 - t], axis=1), 3)  # cocircular and collinear runs
    pts = np.concatenate([pts, [[0, 0], [1, 1]]])
    tri = ridt.Delaunay(pts)
    centroids = pts[tri.simplices].mean(axis=1)
    got = ridt.LinearNDInterpolator(pts, np.arange(len(pts), dtype=float))(centroids)
    assert np.isfinite(got).all()


def test_points_as_a_tuple_of_coordinate_arrays():
    rng = np.random.default_rng(4)
    x, y = rng.random(40), rng.random(40)
    z = x + 2 * y
    q = rng.random((30, 2)) * 0.5 + 0.25
    for cls in (ridt.LinearNDInterpolator, ridt.NearestNDInterpolator):
        assert np.array_equal(cls((x, y), z)(q), cls(np.c_[x, y], z)(q))
    assert np.array_equal(ridt.griddata((x, y), z, (q[:, 0], q[:, 1])), ridt.griddata(np.c_[x, y], z, q))
    # Two points: the tuple holds coordinates, not points (scipy's reading).
    two = ridt.NearestNDInterpolator(([0.0, 1.0], [5.0, 5.0]), [1, 2])
    assert two([[0.9, 5.0]]).tolist() == [2]


@pytest.mark.parametrize("points", [
    [[0.5, 0.5]],
    [[0, 0], [1, 1]],
    [[0, 0], [1, 1], [2, 2], [3, 3], [0.5, 0.5], [1, 1]],
    [[1, 0], [3, 0], [2, 0], [0, 0], [3, 0]],
])
def test_nearest_without_a_triangle(points):
    pts = np.array(points, dtype=float)
    vals = np.arange(len(pts)) * 10
    rng = np.random.default_rng(6)
    q = rng.uniform(-1, 4, (200, 2))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no degenerate-input warning from nearest
        got = ridt.NearestNDInterpolator(pts, vals)(q)
    assert got.dtype == vals.dtype
    d = ((q[:, None, :] - pts[None, :, :]) ** 2).sum(axis=2)
    best = d.min(axis=1)
    chosen = np.array([np.flatnonzero(vals == g)[0] for g in got])
    assert (d[np.arange(len(q)), chosen] == best).all()
    assert np.array_equal(ridt.griddata(pts, vals, q, method="nearest"), got)


def test_nearest_keeps_the_dtype_and_fills_nan_for_queries_that_are_not_finite():
    pts = np.random.default_rng(7).random((20, 2))
    ip = ridt.NearestNDInterpolator(pts, np.arange(20))
    assert ip(pts).dtype == np.arange(20).dtype and (ip(pts) == np.arange(20)).all()
    out = ridt.NearestNDInterpolator(pts, np.arange(20.0))([[np.nan, 0.5]])
    assert np.isnan(out).all()


def _objects():
    rng = np.random.default_rng(8)
    pts = rng.random((300, 2))
    vals = np.sin(3 * pts[:, 0]) + 1j * pts[:, 1]
    return pts, [ridt.Delaunay(pts), ridt.Voronoi(pts), ridt.LinearNDInterpolator(pts, vals, fill_value=-1),
                 ridt.NearestNDInterpolator(pts, vals), ridt.NaturalNeighborInterpolator(pts, vals.real),
                 ridt.CloughTocher2DInterpolator(pts, vals)]


def _answers(obj, q):
    if isinstance(obj, ridt.Delaunay):
        return [obj.simplices, obj.neighbors, obj.find_simplex(q), obj.transform, obj.coplanar]
    if isinstance(obj, ridt.Voronoi):
        return [obj.vertices, obj.ridge_points, np.array(obj.ridge_vertices), obj.point_region,
                np.array([len(r) for r in obj.regions])]
    return [obj(q)]


def test_every_object_pickles_and_deep_copies():
    pts, objects = _objects()
    q = np.random.default_rng(9).random((100, 2)) * 1.2 - 0.1
    for obj in objects:
        for twin in (pickle.loads(pickle.dumps(obj)), copy.deepcopy(obj), copy.copy(obj)):
            assert type(twin) is type(obj)
            for a, b in zip(_answers(obj, q), _answers(twin, q)):
                np.testing.assert_array_equal(a, b)


def test_a_pickled_object_answers_the_same_in_another_process(tmp_path):
    pts, objects = _objects()
    q = np.random.default_rng(10).random((100, 2))
    path = tmp_path / "objects.pickle"
    path.write_bytes(pickle.dumps((objects, q)))
    script = (
        "import pickle, sys, numpy as np\n"
        "sys.path[:0] = %r\n"
        "from test_scipy_compat import _answers\n"
        "objects, q = pickle.loads(open(sys.argv[1], 'rb').read())\n"
        "pickle.dump([_answers(o, q) for o in objects], open(sys.argv[1] + '.out', 'wb'))\n"
    ) % (sys.path,)
    subprocess.run([sys.executable, "-c", script, str(path)], check=True, cwd=str(tmp_path))
    theirs = pickle.loads((tmp_path / "objects.pickle.out").read_bytes())
    for obj, answers in zip(objects, theirs):
        for a, b in zip(_answers(obj, q), answers):
            np.testing.assert_array_equal(a, b)


def _triangle_set(simplices):
    return sorted(tuple(np.roll(t, -int(np.argmin(t)))) for t in simplices.tolist())


def test_incremental_insertion_equals_a_fresh_build():
    rng = np.random.default_rng(12)
    # Inside and far outside the first hull, equal points old and new, a grid's cocircular squares.
    chunks = [rng.random((10, 2)), np.array([[0, 0], [0, 1], [1, 0], [1, 1.0]]), rng.random((50, 2)) * 3 - 1,
              np.array([[0.5, 0.5], [0.5, 0.5], [7, 7], [0, 0]]), np.mgrid[0:4, 0:4].reshape(2, -1).T * 0.25]
    inc = ridt.Delaunay(chunks[0], incremental=True)
    vinc = ridt.Voronoi(chunks[0], incremental=True)
    for k, c in enumerate(chunks[1:], 2):
        inc.add_points(c)
        vinc.add_points(c, restart=True)
        whole = np.concatenate(chunks[:k])
        fresh = ridt.Delaunay(whole)
        assert np.array_equal(inc.points, whole)
        assert _triangle_set(inc.simplices) == _triangle_set(fresh.simplices)
        assert ridt.check(whole, inc.simplices)[0]
        assert np.array_equal(inc.convex_hull, fresh.convex_hull)
        assert np.array_equal(inc.coplanar[:, [0, 2]], fresh.coplanar[:, [0, 2]])
        # Neighbours: the triangle across from each corner shares the other two.
        for t, (tri, nb) in enumerate(zip(inc.simplices, inc.neighbors)):
            for i in range(3):
                if nb[i] >= 0:
                    assert set(tri) - {tri[i]} <= set(inc.simplices[nb[i]]) and t in inc.neighbors[nb[i]]
        fv = ridt.Voronoi(whole)
        assert sorted(map(tuple, np.round(vinc.vertices, 12))) == sorted(map(tuple, np.round(fv.vertices, 12)))
        # The fresh one has Qz's empty region at infinity (scipy's default); incremental mode
        # leaves Qz out, as in scipy.
        assert len(vinc.regions) == len(fv.regions) - 1
    inc.close()
    vinc.close()
    with pytest.raises(RuntimeError):
        inc.add_points(chunks[1])
    with pytest.raises(RuntimeError):
        vinc.add_points(chunks[1])


def test_scipy_errors_and_deprecations():
    pts = np.random.default_rng(13).random((20, 2))
    with pytest.raises(ValueError, match="masked"):
        ridt.Delaunay(np.ma.masked_array(pts))
    with pytest.raises(ValueError, match="masked"):
        ridt.Voronoi(np.ma.masked_array(pts))
    tri = ridt.Delaunay(pts)
    with pytest.warns(DeprecationWarning, match="'vertices' is deprecated"):
        assert np.array_equal(tri.vertices, tri.simplices)
    with pytest.raises(ValueError, match="Rescaling is not supported"):
        ridt.LinearNDInterpolator(tri, pts[:, 0], rescale=True)


def test_transform_is_exact_where_finite_and_nan_on_slivers():
    data = np.load("/usr/lib/python3/dist-packages/scipy/spatial/tests/data/degenerate_pointset.npz")
    pts = data["c"]
    tri = ridt.Delaunay(pts)
    T = tri.transform
    corners = pts[tri.simplices]
    finite = np.isfinite(T[:, 0, 0])
    c = np.einsum("ijk,ik->ij", T[finite, :2], corners[finite].mean(axis=1) - T[finite, 2])
    assert np.abs(c - 1 / 3).max() < 1e-9
    # The NaN ones are the slivers, whose matrix is too ill-conditioned to carry coordinates.
    m = np.stack([corners[:, 0] - corners[:, 2], corners[:, 1] - corners[:, 2]], axis=2)
    cond = np.array([np.linalg.cond(x, 1) for x in m[~finite]])
    assert (cond > 1e11).all() and (~finite).sum() < 40


def test_cubic_equals_scipys_where_the_triangulations_agree():
    rng = np.random.default_rng(14)
    pts = rng.random((3000, 2))  # general position: one Delaunay triangulation, Qhull's and ridt's
    vals = np.sin(5 * pts[:, 0]) * np.cos(3 * pts[:, 1]) + 1j * pts[:, 0] ** 2
    q = rng.random((4000, 2)) * 1.1 - 0.05
    # ridt sweeps the points in another order (colour classes, on threads): the same minimum,
    # reached within the tolerance; with a tight one both are at it.
    ours = ridt.CloughTocher2DInterpolator(pts, vals, fill_value=-1 + 2j, tol=1e-13, threads=2)
    theirs = scipy.interpolate.CloughTocher2DInterpolator(pts, vals, fill_value=-1 + 2j, tol=1e-13)
    np.testing.assert_allclose(ours.grad, theirs.grad, rtol=0, atol=1e-9)
    np.testing.assert_allclose(ours(q), theirs(q), rtol=0, atol=1e-10)
    # Given the same gradients, the same interpolant to rounding.
    ours.grad[...] = theirs.grad
    np.testing.assert_allclose(ours(q), theirs(q), rtol=0, atol=1e-13)
    g = np.linspace(0, 1, 101)
    grid = ridt.griddata(pts, vals.real, (g[:, None], g[None, :]), method="cubic", rescale=True)
    np.testing.assert_allclose(grid, scipy.interpolate.griddata(pts, vals.real, (g[:, None], g[None, :]),
                                                                 method="cubic", rescale=True), rtol=0, atol=1e-5)
    assert (ours(pts) == vals).all()  # the data at the points, exactly
    # The gradients do not depend on the threads.
    one = ridt.CloughTocher2DInterpolator(pts, vals, threads=1).grad
    assert np.array_equal(one, ridt.CloughTocher2DInterpolator(pts, vals, threads=3).grad)


def test_gradients_are_exact_for_linear_data_and_warn_when_unsettled():
    rng = np.random.default_rng(15)
    pts = rng.random((200, 2))
    tri = ridt.Delaunay(pts)
    g = ridt.estimate_gradients_2d_global(tri, np.c_[3 + 3 * pts[:, 0] + 14.15 * pts[:, 1], 1 - pts[:, 1]],
                                          tol=1e-13)
    assert g.shape == (200, 2, 2)
    np.testing.assert_allclose(g[:, 0], np.broadcast_to([3, 14.15], (200, 2)), atol=1e-10)
    np.testing.assert_allclose(g[:, 1], np.broadcast_to([0, -1], (200, 2)), atol=1e-10)
    with pytest.warns(ridt.GradientEstimationWarning):
        ridt.estimate_gradients_2d_global(tri, rng.random(200), maxiter=1)
    with pytest.raises(ValueError):
        ridt.estimate_gradients_2d_global(tri, rng.random(199))


def test_cubic_uses_the_gradients_it_is_given():
    pts = np.array([(0, 0), (1, 0), (0.5, np.sqrt(3) / 2)])
    ip = ridt.CloughTocher2DInterpolator(pts, [1.0, 0, 0])
    before = ip([[0.3, 0.2]])
    ip.grad[...] = 0
    assert ip([[0.3, 0.2]]) != before
    twin = pickle.loads(pickle.dumps(ip))
    assert twin([[0.3, 0.2]]) == ip([[0.3, 0.2]])


def test_furthest_site_equals_scipys_in_general_position():
    rng = np.random.default_rng(16)
    pts = rng.normal(size=(500, 2))
    ours = ridt.Delaunay(pts, furthest_site=True)
    theirs = scipy.spatial.Delaunay(pts, furthest_site=True)
    assert ours.furthest_site and ridt.check(pts, ours.simplices, furthest_site=True)[0]
    rot = lambda t: tuple(np.roll(t, -int(np.argmin(t))))  # noqa: E731  (each triangle from its least corner)
    assert sorted(map(rot, ours.simplices)) == sorted(map(rot, theirs.simplices))  # clockwise both
    q = rng.normal(size=(200, 2))
    assert ((ours.find_simplex(q) >= 0) == (theirs.find_simplex(q) >= 0)).all()
    vo, vt = ridt.Voronoi(pts, furthest_site=True), scipy.spatial.Voronoi(pts, furthest_site=True)
    key = lambda v: sorted(map(tuple, np.round(v, 9)))  # noqa: E731
    assert key(vo.vertices) == key(vt.vertices)
    assert len(vo.regions) == len(vt.regions) and sorted(map(len, vo.regions)) == sorted(map(len, vt.regions))
    inside = np.setdiff1d(np.arange(len(pts)), ours.convex_hull.ravel())
    assert all(vo.regions[vo.point_region[i]] == [] for i in inside)


@pytest.mark.parametrize("options", [None, "Qbb", "Qc", "Qbb Qc Qz", "Qt", "Qz Qc"])
def test_qhull_options_that_change_what_is_reported(options):
    rng = np.random.default_rng(17)
    pts = rng.random((40, 2))
    pts = np.r_[pts, pts[:4]]
    ours, theirs = ridt.Delaunay(pts, qhull_options=options), scipy.spatial.Delaunay(pts, qhull_options=options)
    assert ours.coplanar.shape == theirs.coplanar.shape  # Qc lists the duplicates
    np.testing.assert_allclose([ours.paraboloid_scale, ours.paraboloid_shift],
                               [theirs.paraboloid_scale, theirs.paraboloid_shift], rtol=1e-12)  # Qbb, Qz
    v = ridt.Voronoi(pts[:40], qhull_options=options)
    assert len(v.regions) == len(scipy.spatial.Voronoi(pts[:40], qhull_options=options).regions)  # Qz


def test_estimate_gradients_refuses_what_is_not_a_triangulation():
    with pytest.raises(TypeError, match="ridt.Delaunay"):
        ridt.estimate_gradients_2d_global(np.zeros((4, 2)), np.zeros(4))
    pts = np.random.default_rng(4).random((20, 2))
    with pytest.raises(TypeError, match="ridt.Delaunay"):
        ridt.estimate_gradients_2d_global(scipy.spatial.Delaunay(pts), np.zeros(20))


@pytest.mark.parametrize("cls", [ridt.LinearNDInterpolator, ridt.CloughTocher2DInterpolator])
def test_interpolators_take_a_scipy_delaunay_as_scipys_do(cls):
    pts = np.random.default_rng(5).random((40, 2))
    values = np.sin(3 * pts[:, 0]) + pts[:, 1] ** 2
    theirs = scipy.spatial.Delaunay(pts)
    q = np.random.default_rng(6).uniform(-0.1, 1.1, (50, 2))
    f = cls(theirs, values)
    np.testing.assert_array_equal(f(q), cls(pts, values)(q))
    assert isinstance(f.tri, ridt.Delaunay) and np.array_equal(f.tri.points, pts)
    with pytest.raises(ValueError, match="Rescaling"):
        cls(theirs, values, rescale=True)


@pytest.mark.parametrize("mode", [dict(), dict(furthest_site=True), dict(incremental=True)], ids=str)
def test_good_is_scipys(mode):
    pts = np.random.default_rng(7).random((30, 2))
    ours, theirs = ridt.Delaunay(pts, **mode), scipy.spatial.Delaunay(pts, **mode)
    assert ours.good.dtype == theirs.good.dtype and ours.good.shape == (ours.nsimplex,)
    np.testing.assert_array_equal(ours.good, theirs.good)
    if mode.get("incremental"):
        ours.add_points(pts[:5] * 0.5 + 0.2)
        theirs.add_points(pts[:5] * 0.5 + 0.2)
        np.testing.assert_array_equal(ours.good, theirs.good)
