"""scipy's tolerance at the hull: find_simplex(tol) and the interpolators answer a point that
rounding put just outside the convex hull from the hull triangle beside it, as scipy does, and
keep the exact answer everywhere inside."""

import numpy as np
import pytest
import scipy.interpolate as si
import scipy.spatial as ss

import ridt

EPS = 100 * np.finfo(np.float64).eps  # scipy's default tol
UP = np.nextafter(1.0, 2.0)


@pytest.fixture
def square():
    """A grid filling the unit square: every side a run of collinear hull points, and a plane's
    values (every interpolant gives the plane, whichever diagonals the cocircular cells take)."""
    g = np.linspace(0, 1, 11)
    pts = np.array([(x, y) for x in g for y in g])
    return pts, pts[:, 0] + 2 * pts[:, 1] - 0.3


def rim(n=37):
    """Points an ulp or two outside each side of the unit square, and at its corners."""
    y = np.linspace(0, 1, n)
    down = -np.finfo(np.float64).smallest_subnormal
    sides = [np.stack(c, axis=1) for c in ((np.full(n, UP), y), (y, np.full(n, UP)), (np.full(n, down), y),
                                             (y, np.full(n, down)), (np.full(n, np.nextafter(UP, 2)), y))]
    return np.concatenate(sides + [np.array([[UP, UP], [down, down], [UP, down]])])


def test_find_simplex_takes_points_an_ulp_outside_as_scipy_does(square):
    pts, _ = square
    tri, theirs = ridt.Delaunay(pts), ss.Delaunay(pts)
    q = rim()
    found = tri.find_simplex(q)
    assert (found >= 0).all()
    assert (theirs.find_simplex(q) >= 0).all()
    for x, t in zip(q, found):  # within tol of the triangle found, exactly by scipy's measure
        a, b, c = pts[tri.simplices[t]]
        w = np.linalg.solve(np.array([[a[0], b[0], c[0]], [a[1], b[1], c[1]], [1, 1, 1]]), [x[0], x[1], 1])
        assert (w >= -EPS - 1e-15).all() and (w <= 1 + EPS + 1e-15).all()
    assert (tri.find_simplex(q, tol=0) == -1).all()
    assert (theirs.find_simplex(q, tol=0) == -1).all()
    assert (tri.find_simplex(q, bruteforce=True) == found).all()


def test_find_simplex_refuses_points_beyond_the_tolerance(square):
    pts, _ = square
    tri, theirs = ridt.Delaunay(pts), ss.Delaunay(pts)
    y = np.linspace(0, 1, 23)
    q = np.concatenate([np.stack([np.full(23, 1 + 1e-12), y], axis=1), np.stack([y, np.full(23, -1e-12)], axis=1),
                        [[3.0, 0.5], [-1, -1]]])
    assert (tri.find_simplex(q) == -1).all()
    assert (theirs.find_simplex(q) == -1).all()
    # A larger tol takes them, as scipy's does.
    assert (tri.find_simplex(q[:46], tol=1e-9) >= 0).all()
    assert (theirs.find_simplex(q[:46], tol=1e-9) >= 0).all()


def test_inside_the_hull_the_answer_stays_exact(square):
    pts, _ = square
    tri = ridt.Delaunay(pts)
    q = np.random.default_rng(3).uniform(-0.2, 1.2, (3000, 2))
    q = np.concatenate([q, pts, (pts[:-1] + pts[1:]) / 2])
    exact = tri.find_simplex(q, tol=0)
    found = tri.find_simplex(q)
    inside = exact >= 0
    assert (found[inside] == exact[inside]).all()
    assert (found[~inside] == -1).all()  # these are all far outside


def test_the_tolerance_box_is_absolute_as_scipys():
    """At a scale of 10^6 an ulp beyond the points' bounding box exceeds 100 DBL_EPSILON: -1
    in scipy and here, though the barycentric coordinates would allow it."""
    pts = np.array([[0, 0], [1e6, 0], [1e6, 1e6], [0, 1e6], [4e5, 3e5]])
    q = [[np.nextafter(1e6, 2e6), 5e5], [-1e-300, 5e5]]
    assert ridt.Delaunay(pts).find_simplex(q).tolist()[0] == -1
    assert ss.Delaunay(pts).find_simplex(q).tolist()[0] == -1
    assert ridt.Delaunay(pts).find_simplex(q)[1] >= 0


@pytest.mark.parametrize("method", ["linear", "cubic"])
def test_griddata_has_no_nan_rim_where_scipy_has_none(square, method):
    pts, v = square
    q = rim()
    ours = ridt.griddata(pts, v, q, method=method)
    theirs = si.griddata(pts, v, q, method=method)
    assert np.isfinite(theirs).all()
    np.testing.assert_allclose(ours, theirs, rtol=1e-6, atol=1e-9)
    assert ridt.griddata(pts, v, [[np.nextafter(1, 2), .5]], method=method)[0] == pytest.approx(
        si.griddata(pts, v, [[np.nextafter(1, 2), .5]], method=method)[0])


@pytest.mark.parametrize("method", ["linear", "cubic", "natural"])
def test_grid_nodes_just_outside_are_answered_as_the_queries(square, method):
    pts, v = square
    xs = np.array([np.nextafter(0.0, -1), 0.25, 0.5, UP, 1 + 1e-12])
    ys = np.linspace(0, 1, 9)
    X, Y = np.meshgrid(xs, ys)
    on_grid = ridt.griddata(pts, v, (X, Y), method=method)
    one_by_one = ridt.griddata(pts, v, np.stack([X, Y], axis=-1), method=method)
    np.testing.assert_allclose(on_grid, one_by_one, rtol=1e-12, atol=1e-12)
    assert np.isfinite(on_grid[:, :4]).all()
    assert np.isnan(on_grid[:, 4]).all()
    if method != "natural":
        np.testing.assert_allclose(on_grid[:, :4], si.griddata(pts, v, (X, Y), method=method)[:, :4], rtol=1e-6)


def test_rescaled_rims_are_answered(square):
    """rescale=True moves the points and the queries by rounding: the hull's own points, given
    as queries, must be answered, as in scipy."""
    pts, v = square
    pts = pts * [3.7, 0.013] + [0.1, 1e3]
    q = pts[np.isclose(pts[:, 0], pts[:, 0].max()) | np.isclose(pts[:, 1], pts[:, 1].min())]
    for interp in (ridt.LinearNDInterpolator, ridt.CloughTocher2DInterpolator, ridt.NaturalNeighborInterpolator):
        assert np.isfinite(interp(pts, v, rescale=True)(q)).all()


def test_natural_neighbour_just_outside_is_linear_along_the_hull_edge(square):
    pts, v = square
    q = np.array([[UP, 0.33], [0.71, UP]])
    on_edge = np.array([[1.0, 0.33], [0.71, 1.0]])
    np.testing.assert_allclose(ridt.griddata(pts, v, q, method="natural"),
                               ridt.griddata(pts, v, on_edge, method="linear"), rtol=1e-13)


def test_complex_values_outside_get_the_whole_fill(square):
    pts, v = square
    f = ridt.LinearNDInterpolator(pts, v + 1j * v, fill_value=complex(-1, -2))
    out = f([[UP, 0.5], [2.0, 0.5]])
    assert out[0] == pytest.approx(f([[1.0, 0.5]])[0])
    assert out[1] == complex(-1, -2)
