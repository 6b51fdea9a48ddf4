"""ridt.Voronoi, ridt.griddata and the interpolators against scipy's, where the answer is unique."""

import numpy as np
import pytest
import scipy.interpolate as si
import scipy.spatial as ss

import ridt


@pytest.fixture
def scattered():
    rng = np.random.default_rng(11)
    p = rng.random((3000, 2))
    f = np.sin(4 * p[:, 0]) * np.cos(3 * p[:, 1]) + p[:, 0]
    q = rng.random((20000, 2)) * 1.3 - 0.15
    return p, f, q


@pytest.mark.parametrize("threads", [1, 2])
def test_griddata_linear_equals_scipy(scattered, threads):
    p, f, q = scattered
    a = ridt.griddata(p, f, q, threads=threads)
    b = si.griddata(p, f, q)
    assert np.array_equal(np.isnan(a), np.isnan(b))
    ok = ~np.isnan(b)
    assert ok.sum() > 10000
    np.testing.assert_allclose(a[ok], b[ok], rtol=1e-12, atol=1e-12)


def test_linear_interpolator_shapes_fill_components_and_rescale(scattered):
    p, f, q = scattered
    values = np.stack([f, 2 * f, -f], axis=1).reshape(-1, 3, 1)
    ours = ridt.LinearNDInterpolator(p, values, fill_value=-5.0)
    theirs = si.LinearNDInterpolator(p, values, fill_value=-5.0)
    gx, gy = np.mgrid[-0.1:1.1:50j, -0.1:1.1:40j]
    a, b = ours(gx, gy), theirs(gx, gy)
    assert a.shape == b.shape == (50, 40, 3, 1)
    np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(ours((gx, gy)), b, rtol=1e-12, atol=1e-12)
    # Complex values, and a Delaunay given in place of the points.
    tri = ridt.Delaunay(p)
    c = ridt.LinearNDInterpolator(tri, f + 2j * f, fill_value=1 + 1j)(q)
    d = si.LinearNDInterpolator(p, f + 2j * f, fill_value=1 + 1j)(q)
    np.testing.assert_allclose(c, d, rtol=1e-12, atol=1e-12)
    # Rescaled: anisotropic points, the triangulation of the scaled points.
    s = p * np.array([1000.0, 0.001])
    e = ridt.LinearNDInterpolator(s, f, rescale=True)(q * np.array([1000.0, 0.001]))
    g = si.LinearNDInterpolator(s, f, rescale=True)(q * np.array([1000.0, 0.001]))
    assert np.array_equal(np.isnan(e), np.isnan(g))
    np.testing.assert_allclose(e[~np.isnan(g)], g[~np.isnan(g)], rtol=1e-9, atol=1e-9)


@pytest.mark.parametrize("method", ["linear", "natural"])
def test_grids_are_answered_as_their_nodes(scattered, method):
    # Grids given as numpy.mgrid, numpy.meshgrid (both orders), broadcast axes and decreasing,
    # uneven axes go through the grid path (each triangle takes its nodes); the answers are
    # those of the same nodes given as scattered queries, and scipy's for linear.
    p, f, _ = scattered
    x = np.linspace(-0.1, 1.1, 37)
    y = np.linspace(1.1, -0.1, 29) ** 3
    gx, gy = np.mgrid[-0.1:1.1:41j, -0.1:1.1:23j]
    forms = [(gx, gy), np.meshgrid(x, y), np.meshgrid(x, y, indexing="ij"), (x[:, None], y[None, :]),
             (x[None, :], y[:, None])]
    for form in forms:
        form = tuple(form)
        a = ridt.griddata(p, f, form, method=method, threads=2)
        bx, by = np.broadcast_arrays(*form)
        flat = np.stack([bx.ravel(), by.ravel()], axis=1)
        b = ridt.griddata(p, f, flat, method=method).reshape(bx.shape)
        assert a.shape == bx.shape
        assert np.array_equal(np.isnan(a), np.isnan(b))
        ok = ~np.isnan(a)
        assert ok.sum() > a.size / 3
        np.testing.assert_allclose(a[ok], b[ok], rtol=1e-12, atol=1e-12)
        if method == "linear":
            c = si.griddata(p, f, form)
            assert np.array_equal(np.isnan(a), np.isnan(c))
            np.testing.assert_allclose(a[ok], c[ok], rtol=1e-12, atol=1e-12)
    # Rescaled, and data on a grid of its own with nodes on its vertices and edges.
    s = p * np.array([1000.0, 0.001])
    a = ridt.griddata(s, f, (1000 * gx, 0.001 * gy), method=method, rescale=True)
    b = si.griddata(s, f, (1000 * gx, 0.001 * gy), rescale=True)
    assert np.array_equal(np.isnan(a), np.isnan(b))
    if method == "linear":
        np.testing.assert_allclose(a[~np.isnan(b)], b[~np.isnan(b)], rtol=1e-9, atol=1e-9)
    g = np.stack(np.meshgrid(np.arange(20.0), np.arange(15.0)), axis=-1).reshape(-1, 2)
    plane = 2 * g[:, 0] - g[:, 1]
    hx, hy = np.mgrid[-1:20:43j, -1:15:33j]
    a = ridt.griddata(g, plane, (hx, hy), method=method)
    inside = (hx >= 0) & (hx <= 19) & (hy >= 0) & (hy <= 14)
    assert np.array_equal(~np.isnan(a), inside)
    np.testing.assert_allclose(a[inside], (2 * hx - hy)[inside], atol=1e-12)


def test_cubic_griddata_on_a_grid_is_the_interpolators_answer(scattered):
    # griddata's cubic onto a grid runs as one call of the library (the points numbered once
    # for the gradients and the answers): the same bits as CloughTocher2DInterpolator's, with
    # several components, a fill value and rescale.
    p, f, _ = scattered
    values = np.stack([f, p[:, 0] * p[:, 1]], axis=1)
    gx, gy = np.mgrid[-0.2:1.2:61j, -0.1:1.1:47j]
    for rescale in (False, True):
        a = ridt.griddata(p * [3.0, 0.5], values, (3 * gx, 0.5 * gy), method="cubic", fill_value=-2.5,
                          rescale=rescale, threads=2)
        ip = ridt.CloughTocher2DInterpolator(p * [3.0, 0.5], values, fill_value=-2.5, rescale=rescale)
        b = ip(3 * gx, 0.5 * gy)
        assert a.shape == gx.shape + (2,)
        np.testing.assert_array_equal(a, b)
        assert (a == -2.5).any() and (a != -2.5).sum() > a.size / 2


def test_cubic_griddata_without_a_triangle_or_with_duplicates_is_the_interpolators(scattered):
    # The one call triangulates the points itself: a duplicate's first copy stands for it, as
    # in Delaunay; no triangle gives the fill value and Delaunay's warning; a point that is not
    # finite the interpolator's error.
    p, f, _ = scattered
    p2, f2 = np.vstack([p, p[5]]), np.append(f, 100.0)
    gx, gy = np.mgrid[0:1:41j, 0:1:37j]
    a = ridt.griddata(p2, f2, (gx, gy), method="cubic", threads=2)
    np.testing.assert_array_equal(a, ridt.CloughTocher2DInterpolator(p2, f2)(gx, gy))
    np.testing.assert_array_equal(a, ridt.griddata(p, f, (gx, gy), method="cubic"))
    line = np.c_[np.linspace(0, 1, 10), np.linspace(0, 1, 10)]
    for pts in (line, line[:2], line[[0, 0, 0]]):
        with pytest.warns(ridt.DegenerateInputWarning):
            b = ridt.griddata(pts, np.arange(len(pts), dtype=float), (gx, gy), method="cubic", fill_value=-1.0)
        assert b.shape == gx.shape and (b == -1).all()
    bad = line.copy()
    bad[3, 0] = np.inf
    with pytest.raises(ValueError, match="not finite"):
        ridt.griddata(bad, np.arange(10.0), (gx, gy), method="cubic")


def test_answers_are_the_same_bits_on_any_threads():
    # The triangulation's order differs between thread counts (each thread makes its own
    # region's triangles); the answers depend on the triangles alone: the same bits on 1, 2 and
    # 3 threads, on a grid and at scattered queries, for every method.
    rng = np.random.default_rng(6)
    p = rng.random((60_000, 2))
    f = np.sin(6 * p[:, 0]) * np.cos(5 * p[:, 1])
    gx, gy = np.mgrid[0:1:300j, 0:1:200j]
    q = rng.random((70_000, 2))
    orders = {ridt.Delaunay(p, threads=t).simplices.tobytes() for t in (1, 2, 3)}
    assert len(orders) > 1  # else the test would show nothing
    for method in ("linear", "cubic", "natural"):
        want_grid = ridt.griddata(p, f, (gx, gy), method=method, threads=1)
        want_q = ridt.griddata(p, f, q, method=method, threads=1)
        for t in (2, 3):
            np.testing.assert_array_equal(ridt.griddata(p, f, (gx, gy), method=method, threads=t), want_grid)
            np.testing.assert_array_equal(ridt.griddata(p, f, q, method=method, threads=t), want_q)


def test_cubic_griddata_keeps_no_block_after_it():
    # Enough points for the library's blocks to be on huge pages (the ones the cache keeps):
    # under a limit of 0 the call, which keeps blocks while it runs for its later steps to
    # reuse, keeps nothing after; the answer is the interpolator's.
    p = np.random.default_rng(4).random((400_000, 2))
    f = np.sin(6 * p[:, 0]) * np.cos(5 * p[:, 1])
    gx, gy = np.mgrid[0:1:40j, 0:1:30j]
    before = ridt.set_memory_cache_limit(0)
    try:
        a = ridt.griddata(p, f, (gx, gy), method="cubic")
        assert ridt.cached_memory() == 0
        np.testing.assert_array_equal(a, ridt.CloughTocher2DInterpolator(p, f)(gx, gy))
    finally:
        ridt.set_memory_cache_limit(before)


def test_queries_that_are_no_grid_take_the_general_path(scattered):
    p, f, q = scattered
    x = q[:400, 0].reshape(20, 20)
    y = q[:400, 1].reshape(20, 20)
    np.testing.assert_array_equal(ridt.griddata(p, f, (x, y)), ridt.griddata(p, f, q[:400]).reshape(20, 20))


def test_nearest_is_as_near_as_scipys(scattered):
    p, f, q = scattered
    a = ridt.griddata(p, np.arange(len(p)), q, method="nearest")
    b = si.griddata(p, np.arange(len(p)), q, method="nearest")
    da = np.hypot(*(p[a.astype(int)] - q).T)
    db = np.hypot(*(p[b.astype(int)] - q).T)
    np.testing.assert_array_equal(da, db)


def test_natural_neighbour_is_exact_on_planes_and_a_convex_combination(scattered):
    p, f, q = scattered
    plane = 3 * p[:, 0] - 2 * p[:, 1] + 0.5
    a = ridt.griddata(p, plane, q, method="natural")
    inside = ~np.isnan(si.griddata(p, plane, q))
    assert np.array_equal(~np.isnan(a), inside)
    np.testing.assert_allclose(a[inside], 3 * q[inside, 0] - 2 * q[inside, 1] + 0.5, atol=1e-12)
    # Sibson's coordinates are positive: the answer lies between the data's bounds, and at the
    # points it is the data.
    n = ridt.NaturalNeighborInterpolator(p, f)
    b = n(q)
    assert np.nanmin(b) >= f.min() - 1e-12 and np.nanmax(b) <= f.max() + 1e-12
    np.testing.assert_allclose(n(p), f, atol=1e-12)


def test_griddata_refuses_what_it_cannot_do(scattered):
    p, f, q = scattered
    with pytest.raises(ValueError):
        ridt.griddata(p, f, q, method="quadratic")
    with pytest.raises(ValueError):
        ridt.griddata(p, f[:-1], q)
    with pytest.raises(ValueError):
        ridt.LinearNDInterpolator(p, f)(np.zeros((4, 3)))


def _sorted_pairs(a):
    return {tuple(sorted(r)) for r in np.asarray(a).tolist()}


def test_voronoi_equals_scipy():
    rng = np.random.default_rng(5)
    p = rng.random((2000, 2))
    ours, theirs = ridt.Voronoi(p, threads=2), ss.Voronoi(p)
    assert len(ours.vertices) == len(theirs.vertices)
    assert _sorted_pairs(ours.ridge_points) == _sorted_pairs(theirs.ridge_points)

    def ends(vd, i):  # a ridge's ends as coordinates, None for infinity, in a set
        return {None if v < 0 else tuple(np.round(vd.vertices[v], 9)) for v in vd.ridge_vertices[i]}

    ridges = {tuple(sorted(r)): ends(theirs, i) for i, r in enumerate(theirs.ridge_points.tolist())}
    for i, r in enumerate(ours.ridge_points.tolist()):
        assert ends(ours, i) == ridges[tuple(sorted(r))]
    for k in range(len(p)):
        a = ours.regions[ours.point_region[k]]
        b = theirs.regions[theirs.point_region[k]]
        coords = lambda vd, reg: {None if v < 0 else tuple(np.round(vd.vertices[v], 9)) for v in reg}
        assert coords(ours, a) == coords(theirs, b)
    assert set(ours.ridge_dict) == set(map(tuple, ours.ridge_points.tolist()))
    assert ours.npoints == 2000 and ours.ndim == 2


def test_voronoi_regions_are_counter_clockwise_and_hold_their_sites():
    rng = np.random.default_rng(6)
    p = rng.normal(size=(1000, 2))
    vd = ridt.Voronoi(p)
    for k in range(len(p)):
        reg = vd.regions[vd.point_region[k]]
        if -1 in reg:
            assert reg[-1] == -1 and reg.count(-1) == 1
            continue
        c = vd.vertices[reg]
        e = np.roll(c, -1, axis=0) - c
        side = e[:, 0] * (p[k, 1] - c[:, 1]) - e[:, 1] * (p[k, 0] - c[:, 0])
        assert (side > -1e-12).all()


def test_voronoi_duplicates_and_degenerate_input():
    p = np.array([[0, 0], [1, 0], [0, 1], [1, 1], [0.4, 0.6], [1, 0]], dtype=float)
    vd = ridt.Voronoi(p)
    assert vd.point_region[5] == vd.point_region[1]
    # scipy's default options hold Qz: one more region, empty, owned by no point.
    assert len(vd.regions) == 6 and vd.regions[0] == [] and 0 not in vd.point_region
    assert len(ridt.Voronoi(p, qhull_options="Qbb Qc").regions) == 5
    with pytest.raises(ridt.InputError):
        ridt.Voronoi([[0, 0], [1, 1], [2, 2]])
