"""ridt.SphericalVoronoi: scipy's SphericalVoronoi and ConvexHull where their answer is unique,
cocircular points decided alike in every order, the exact validator on every triangulation."""

import warnings

import numpy as np
import pytest
import scipy.spatial
from hypothesis import given, settings, strategies as st

import ridt
from conftest import triangle_set


def on_sphere(n, seed, radius=1.0, center=(0.0, 0.0, 0.0)):
    p = np.random.default_rng(seed).normal(size=(n, 3))
    return radius * p / np.linalg.norm(p, axis=1, keepdims=True) + np.asarray(center)


def valid(sv):
    ok, message = ridt.check_sphere(sv.points, sv.triangles)
    assert ok, message
    return sv


def faces(points, triangles):
    """The triangles by their corners' coordinates, each from its least corner: the same whatever
    the points' numbering."""
    out = set()
    for t in triangles:
        c = [tuple(points[i]) for i in t]
        k = c.index(min(c))
        out.add(tuple(c[k:] + c[:k]))
    return out


@pytest.mark.parametrize("n", [4, 10, 1000, 50000])
def test_against_scipy(n):
    pts = on_sphere(n, n, 2.5, (1.0, -3.0, 7.0))
    sv = valid(ridt.SphericalVoronoi(pts, 2.5, (1.0, -3.0, 7.0)))
    theirs = scipy.spatial.SphericalVoronoi(pts, 2.5, (1.0, -3.0, 7.0))
    assert triangle_set(sv.triangles) == triangle_set(theirs._simplices)
    assert triangle_set(sv.triangles) == triangle_set(scipy.spatial.ConvexHull(pts).simplices)
    # The same vertices (one a triangle) and each cell the same area.
    index = {t: i for i, t in enumerate(map(tuple, np.sort(theirs._simplices, axis=1).tolist()))}
    order = [index[t] for t in map(tuple, np.sort(sv.triangles, axis=1).tolist())]
    np.testing.assert_allclose(sv.vertices, theirs.vertices[order], atol=1e-12)
    np.testing.assert_allclose(sv.calculate_areas(), theirs.calculate_areas(), rtol=1e-9)
    assert sv.calculate_areas().sum() == pytest.approx(4 * np.pi * 2.5 ** 2, rel=1e-12)
    # Cells counter-clockwise seen from outside, each the triangles round its point.
    for g in range(0, n, max(1, n // 100)):
        region = sv.regions[g]
        assert all(g in sv.triangles[k] for k in region)
        for a, b in zip(region, region[1:] + region[:1]):
            assert np.dot(np.cross(sv.vertices[a] - pts[g], sv.vertices[b] - pts[g]), pts[g] - sv.center) > 0


def test_threads_change_nothing():
    pts = on_sphere(20000, 3)
    one, two = ridt.SphericalVoronoi(pts, threads=1), ridt.SphericalVoronoi(pts, threads=2)
    assert np.array_equal(one.triangles, two.triangles)
    assert one.regions == two.regions
    assert np.array_equal(one.calculate_areas(), two.calculate_areas())


def polyhedra():
    phi = (1 + 5 ** 0.5) / 2
    cube = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)
    octahedron = np.vstack([np.eye(3), -np.eye(3)])
    icosahedron = np.array([p for a in (-1, 1) for b in (-phi, phi) for p in ([0, a, b], [a, b, 0], [b, 0, a])])
    lat, lon = np.meshgrid(np.linspace(-np.pi / 2, np.pi / 2, 13)[1:-1], np.linspace(0, 2 * np.pi, 25)[:-1])
    grid = np.vstack([np.column_stack([np.cos(lat.ravel()) * np.cos(lon.ravel()),
                                       np.cos(lat.ravel()) * np.sin(lon.ravel()), np.sin(lat.ravel())]),
                      [[0, 0, 1], [0, 0, -1]]])
    lattice = np.array([[x, y, z] for x in range(-7, 8) for y in range(-7, 8) for z in range(-7, 8)
                        if x * x + y * y + z * z == 49], dtype=float) / 7
    return {"cube": cube, "octahedron": octahedron, "icosahedron": icosahedron, "grid": grid, "lattice": lattice}


@pytest.mark.parametrize("name", sorted(polyhedra()))
def test_cocircular_points_one_answer_in_every_order(name):
    pts = polyhedra()[name]
    radius = np.linalg.norm(pts[0])
    sv = valid(ridt.SphericalVoronoi(pts, radius))
    rng = np.random.default_rng(5)
    for _ in range(3):
        shuffled = pts[rng.permutation(len(pts))]
        other = valid(ridt.SphericalVoronoi(shuffled, radius))
        assert faces(pts, sv.triangles) == faces(shuffled, other.triangles)
    assert sv.calculate_areas().sum() == pytest.approx(4 * np.pi * radius ** 2, rel=1e-12)
    if name in ("cube", "octahedron", "icosahedron"):  # regular: equal cells
        np.testing.assert_allclose(sv.calculate_areas(), 4 * np.pi * radius ** 2 / len(pts), rtol=1e-12)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.sampled_from([tuple(p) for p in polyhedra()["lattice"].tolist()]), min_size=4, max_size=60,
                unique=True))
def test_lattice_subsets(points):
    pts = np.array(points)
    if np.linalg.matrix_rank(pts - pts[0], tol=1e-9) < 3:
        with pytest.raises(ValueError, match="Rank"):
            ridt.SphericalVoronoi(pts)
        return
    sv = valid(ridt.SphericalVoronoi(pts))
    flipped = valid(ridt.SphericalVoronoi(pts[::-1].copy()))
    assert faces(pts, sv.triangles) == faces(pts[::-1], flipped.triangles)
    assert len(sv.vertices) == 2 * len(pts) - 4


def test_points_inside_are_hidden():
    # Three points 1e-3 apart round (1, 0, 0) and that point itself, 5e-7 below the sphere
    # (within the threshold of it): the triangle of the three passes 1.7e-7 below it, so it lies
    # inside the hull.
    pts = on_sphere(500, 8)
    pts = pts[pts[:, 0] < 0.9]
    a = np.array([0, 2 * np.pi / 3, 4 * np.pi / 3])
    ring = np.column_stack([np.ones(3), 6e-4 * np.cos(a), 6e-4 * np.sin(a)])
    ring /= np.linalg.norm(ring, axis=1, keepdims=True)
    inside = np.array([[1 - 5e-7, 0, 0]])
    with pytest.warns(RuntimeWarning, match="inside the hull"):
        sv = ridt.SphericalVoronoi(np.vstack([pts, ring, inside]))
    valid(sv)
    n = len(pts) + 3
    assert sv.hidden.tolist() == [n]
    assert sv.regions[n] == [] and sv.calculate_areas()[n] == 0
    assert sv.calculate_areas().sum() == pytest.approx(4 * np.pi)


def test_scipy_refusals():
    pts = on_sphere(50, 2)
    with pytest.raises(ValueError, match="Duplicate"):
        ridt.SphericalVoronoi(np.vstack([pts, pts[:1]]))
    with pytest.raises(ValueError, match="Duplicate"):
        ridt.SphericalVoronoi(np.vstack([pts, pts[:1] + 1e-9]))
    with pytest.raises(ValueError, match="Radius"):
        ridt.SphericalVoronoi(pts, radius=0.9)
    with pytest.raises(ValueError, match="Radius"):
        ridt.SphericalVoronoi(pts, center=[0.1, 0, 0])
    with pytest.raises(ValueError, match="Rank"):
        ridt.SphericalVoronoi(np.column_stack([pts[:, :2] / np.linalg.norm(pts[:, :2], axis=1)[:, None],
                                               np.zeros(50)]))
    with pytest.raises(ValueError, match="radius"):
        ridt.SphericalVoronoi(pts, radius=None)
    with pytest.raises(ValueError, match="finite"):
        ridt.SphericalVoronoi(np.vstack([pts, [[np.nan, 0, 0]]]))
    with pytest.raises(ValueError, match="4-D"):
        ridt.SphericalVoronoi(np.eye(4))


def test_on_a_circle():
    a = np.sort(np.random.default_rng(4).random(40) * 2 * np.pi)
    pts = 3 * np.column_stack([np.cos(a), np.sin(a)]) + [5.0, -2.0]
    sv = ridt.SphericalVoronoi(pts, 3, [5.0, -2.0])
    assert len(sv.vertices) == 40 and all(len(r) == 2 for r in sv.regions)
    assert sv.calculate_areas().sum() == pytest.approx(2 * np.pi * 3)
    # Each vertex equally far from the two points of its arc, on the circle.
    for k, (i, j) in enumerate(sv.triangles):
        v = sv.vertices[k]
        assert np.linalg.norm(v - pts[i]) == pytest.approx(np.linalg.norm(v - pts[j]))
        assert np.linalg.norm(v - sv.center) == pytest.approx(3)
    # Cell i: the arc from the middle of its arc before to the middle of its arc after.
    gap = np.diff(np.concatenate([a, a[:1] + 2 * np.pi]))
    np.testing.assert_allclose(sv.calculate_areas(), 3 * (gap + np.roll(gap, 1)) / 2, rtol=1e-11)
    with pytest.raises(TypeError, match="three-dimensional"):
        sv.sort_vertices_of_regions()


def test_check_sphere_refuses_a_wrong_hull():
    pts = on_sphere(100, 1)
    sv = ridt.SphericalVoronoi(pts)
    ok, _ = ridt.check_sphere(pts, sv.triangles[:, ::-1])
    assert not ok
    ok, message = ridt.check_sphere(pts, sv.triangles[1:])
    assert not ok and "other side" in message
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ridt.SphericalVoronoi(pts)  # no warning without hidden points


def test_linear_interpolation_on_the_sphere():
    pts = on_sphere(3000, 21, 2.0, (1.0, 0.0, -1.0))
    values = np.column_stack([np.sin(3 * pts[:, 0]), pts[:, 2]])
    f = ridt.SphericalLinearInterpolator(pts, values, center=(1.0, 0.0, -1.0), threads=2)
    xi = on_sphere(400, 22, 0.5, (1.0, 0.0, -1.0))
    got = f(xi)
    assert got.shape == (400, 2)
    # Against the same interpolant found by brute force: the triangle whose cone from the centre
    # holds the query, the barycentric coordinates of the query's projection onto its plane.
    o = np.array([1.0, 0.0, -1.0])
    a, b, c = (pts[f.triangles[:, i]] - o for i in range(3))
    for q, g in zip(xi - o, got):
        w = np.stack([np.einsum("ij,ij->i", np.broadcast_to(q, a.shape), np.cross(b, c)),
                      np.einsum("ij,ij->i", a, np.cross(np.broadcast_to(q, a.shape), c)),
                      np.einsum("ij,ij->i", a, np.cross(b, np.broadcast_to(q, a.shape)))], axis=1)
        k = np.flatnonzero((w >= 0).all(axis=1))[0]
        expected = (w[k] / w[k].sum()) @ values[f.triangles[k]]
        np.testing.assert_allclose(g, expected, rtol=1e-12, atol=1e-14)
    # The data at the points; a constant kept; the fill beyond points in one hemisphere.
    np.testing.assert_allclose(f(pts[:50] * 3 - 2 * o), values[:50], atol=1e-13)
    assert np.allclose(ridt.SphericalLinearInterpolator(pts, np.full(3000, 4.5), center=o)(xi), 4.5, rtol=1e-14)
    half = on_sphere(500, 23)
    half[:, 0] = np.abs(half[:, 0])
    h = ridt.SphericalLinearInterpolator(half, np.ones(500), fill_value=-7.0)
    assert h([[1.0, 0.1, 0.2]])[0] == pytest.approx(1.0) and h([[-1.0, 0.1, 0.2]])[0] == -7.0
    with pytest.raises(ValueError):
        ridt.SphericalLinearInterpolator(pts, values[:10])


def test_natural_neighbour_interpolation_against_scipys_cells():
    # Sibson's weights by their definition, from scipy's own SphericalVoronoi: what each cell
    # loses when the query is inserted, over the query's new cell.
    pts = on_sphere(300, 31)
    values = np.sin(3 * pts[:, 0]) + pts[:, 2]
    f = ridt.SphericalNaturalNeighborInterpolator(pts, values, threads=2)
    before = scipy.spatial.SphericalVoronoi(pts).calculate_areas()
    for q in on_sphere(25, 32):
        after = scipy.spatial.SphericalVoronoi(np.vstack([pts, q])).calculate_areas()
        weights = (before - after[:-1]) / after[-1]
        assert weights.min() > -1e-9 and abs(weights.sum() - 1) < 1e-9
        assert f(q[None, :])[0] == pytest.approx(weights @ values, abs=1e-9)
    np.testing.assert_allclose(f(pts[:50] * 4.0), values[:50], atol=1e-12)
    assert np.allclose(ridt.SphericalNaturalNeighborInterpolator(pts, np.full(300, -2.5))(pts * 0.3 + 0.01), -2.5,
                       rtol=1e-13)
    half = on_sphere(500, 33)
    half[:, 0] = np.abs(half[:, 0])
    h = ridt.SphericalNaturalNeighborInterpolator(half, np.ones(500), fill_value=-7.0)
    assert h([[1.0, 0.1, 0.2]])[0] == pytest.approx(1.0) and h([[-1.0, 0.1, 0.2]])[0] == -7.0
