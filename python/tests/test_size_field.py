"""Size fields (ridt.SizeField, size=): the values of each kind, every triangle of a mesh within
the size at its centroid with the exact validator, the same mesh however the sizes are given and
on any number of threads, and bad fields refused."""

import numpy as np
import pytest

import ridt

SQUARE = np.array([[0, 0], [10, 0], [10, 10], [0, 10], [4, 4], [6, 4], [6, 6], [4, 6]], float)
SEGMENTS = [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]]
HOLES = [[5, 5]]


def linear(xy):
    return 0.25 + 0.1 * xy[:, 0] + 0.2 * xy[:, 1]


def centroids_and_longest(m):
    p = m.points[m.simplices]
    longest = np.max(np.linalg.norm(p - np.roll(p, 1, axis=1), axis=2), axis=1)
    return p.mean(axis=1), longest


def assert_within(m, h):
    ok, why = m.check()
    assert ok, why
    c, longest = centroids_and_longest(m)
    assert np.all(longest <= h(c) * (1 + 1e-12))


def test_grid_is_bilinear_and_clamped():
    x, y = np.linspace(0, 10, 5), np.linspace(0, 10, 3)
    gx, gy = np.meshgrid(x, y)
    values = linear(np.column_stack([gx.ravel(), gy.ravel()])).reshape(gx.shape)
    q = np.array([[0, 0], [3.3, 7.1], [10, 10], [-5, 5], [12, 20]])
    inside = np.clip(q, 0, 10)
    for f in (ridt.SizeField.grid(values, x=x, y=y), ridt.SizeField.grid(values, x=(0, 10), y=(0, 10)),
              ridt.SizeField.grid(values[::-1], x=(0, 10), y=(10, 0))):  # an image's rows, the top first
        np.testing.assert_allclose(f(q), linear(inside), rtol=1e-14)


def test_mesh_and_scattered_are_linear_and_nearest_beyond():
    pts = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    values = 1 + pts[:, 0] + 2 * pts[:, 1]
    q = np.array([[0.25, 0.25], [0.75, 0.5], [3, 0.1], [-1, 2]])
    want = [1.75, 2.75, 2, 3]
    np.testing.assert_allclose(ridt.SizeField.mesh(pts, [[0, 1, 2], [0, 3, 2]], values)(q), want, rtol=1e-14)
    np.testing.assert_allclose(ridt.SizeField.scattered(pts, values)(q), want, rtol=1e-14)


@pytest.mark.parametrize("kind", ["grid", "scattered", "mesh", "function", "pair"])
def test_every_triangle_within_its_size(kind):
    corners = SQUARE[:4]
    if kind == "grid":
        size = ridt.SizeField.grid(linear(np.array([[0, 0], [10, 0], [0, 10], [10, 10]])).reshape(2, 2),
                                   x=(0, 10), y=(0, 10))
    elif kind == "scattered":
        size = ridt.SizeField.scattered(corners, linear(corners))
    elif kind == "mesh":
        size = ridt.SizeField.mesh(corners, [[0, 1, 2], [0, 2, 3]], linear(corners))
    elif kind == "function":
        size = linear
    else:
        size = (corners, linear(corners))
    m = ridt.ConstrainedDelaunay(SQUARE, SEGMENTS, holes=HOLES, convex_hull=False, min_angle=30, size=size)
    assert m.nsimplex > 300
    assert_within(m, linear)
    c, _ = centroids_and_longest(m)
    small = np.count_nonzero((c[:, 0] < 5) & (c[:, 1] < 5))
    large = np.count_nonzero((c[:, 0] > 5) & (c[:, 1] > 5))
    assert small > 3 * large  # graded: more where the size is small


def test_same_mesh_however_given_and_on_any_threads():
    field = ridt.SizeField.scattered(SQUARE[:4], linear(SQUARE[:4]))
    one = ridt.ConstrainedDelaunay(SQUARE, SEGMENTS, holes=HOLES, min_angle=28, size=field, threads=1)
    for threads in (2, 3, 8):
        m = ridt.ConstrainedDelaunay(SQUARE, SEGMENTS, holes=HOLES, min_angle=28, size=field, threads=threads)
        np.testing.assert_array_equal(m.simplices, one.simplices)
        np.testing.assert_array_equal(m.points, one.points)
    calls = []

    def asked(xy):
        calls.append(len(xy))
        return field(xy)

    f = ridt.ConstrainedDelaunay(SQUARE, SEGMENTS, holes=HOLES, min_angle=28, size=asked)
    np.testing.assert_array_equal(f.simplices, one.simplices)
    assert len(calls) * 20 < sum(calls)  # many points a call


def test_with_area_bound_and_refined_mesh():
    m = ridt.ConstrainedDelaunay(SQUARE, SEGMENTS, holes=HOLES, min_angle=20, max_area=0.05, size=1.0)
    assert_within(m, lambda c: np.ones(len(c)))
    p = m.points[m.simplices]
    area = 0.5 * np.abs(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]))
    assert area.max() <= 0.05
    coarse = ridt.ConstrainedDelaunay(SQUARE, SEGMENTS, holes=HOLES, convex_hull=False)
    fine = coarse.refine(min_angle=25, size=linear)
    assert fine.nsimplex > 10 * coarse.nsimplex
    assert_within(fine, linear)


def test_gradation_limits_growth_and_the_mesh_keeps_the_graded_sizes():
    # A 5-unit-wide field of 2 with one node of 0.02: graded by 0.25, a cone about that node.
    x = np.linspace(0, 10, 51)
    values = np.full((51, 51), 2.0)
    values[25, 25] = 0.02
    f = ridt.SizeField.grid(values, x=x, y=x, gradation=0.25)
    gx, gy = np.meshgrid(x, x)
    nodes = np.column_stack([gx.ravel(), gy.ravel()])
    h = f(nodes).reshape(51, 51)
    assert h[25, 25] == 0.02 and np.all(h <= values)
    step = x[1] - x[0]
    assert np.all(np.abs(np.diff(h, axis=0)) <= 0.25 * step * (1 + 1e-12))
    assert np.all(np.abs(np.diff(h, axis=1)) <= 0.25 * step * (1 + 1e-12))
    np.testing.assert_allclose(h[25, 35], 0.02 + 0.25 * 10 * step, rtol=1e-12)
    np.testing.assert_allclose(ridt.SizeField.grid(values, x=x, y=x)(nodes), values.ravel(), rtol=1e-13)
    m = ridt.ConstrainedDelaunay(SQUARE, SEGMENTS, holes=HOLES, min_angle=25, size=f)
    assert_within(m, f)
    raw = ridt.ConstrainedDelaunay(SQUARE, SEGMENTS, holes=HOLES, min_angle=25,
                                   size=ridt.SizeField.grid(values, x=x, y=x))
    assert len(m.simplices) > len(raw.simplices)  # the cone's sizes are smaller: more triangles
    # scattered and mesh fields grade along their triangulation's edges
    pts = np.random.default_rng(2).random((500, 2)) * 10
    v = np.where(np.arange(500) == 7, 0.01, 3.0)
    hs = ridt.SizeField.scattered(pts, v, gradation=0.1)(pts)
    tri = ridt.Delaunay(pts)
    for a, b in np.vstack([tri.simplices[:, [0, 1]], tri.simplices[:, [1, 2]], tri.simplices[:, [2, 0]]]):
        assert abs(hs[a] - hs[b]) <= 0.1 * np.linalg.norm(pts[a] - pts[b]) * (1 + 1e-12) + 1e-15
    np.testing.assert_array_equal(ridt.SizeField.mesh(pts, tri.simplices, v, gradation=0.1)(pts), hs)
    for bad in (-1, float("nan"), float("inf")):
        with pytest.raises(ValueError):
            ridt.SizeField.grid(values, x=x, y=x, gradation=bad)


def test_bad_fields_are_refused():
    with pytest.raises(ValueError):
        ridt.SizeField.grid(np.ones((2, 3)), x=(0, 1, 2, 3), y=(0, 1))
    with pytest.raises(ValueError):
        ridt.SizeField.grid(np.zeros((2, 2)), x=(0, 1), y=(0, 1))
    with pytest.raises(ValueError):
        ridt.SizeField.grid(np.ones((2, 3)), x=(0, 1, 5), y=(0, 1))  # uneven nodes
    with pytest.raises(ValueError):
        ridt.SizeField.uniform(0)
    with pytest.raises(ValueError):
        ridt.SizeField.mesh(SQUARE[:3], [[0, 1, 7]], [1, 1, 1])
    with pytest.raises(ValueError):
        ridt.SizeField.scattered(SQUARE[:3], [1, np.nan, 1])
    with pytest.raises(TypeError):
        ridt.ConstrainedDelaunay(SQUARE, SEGMENTS, size="fine")
    with pytest.raises(ValueError, match="above 0"):
        ridt.ConstrainedDelaunay(SQUARE, SEGMENTS, size=lambda xy: np.zeros(len(xy)))
    with pytest.raises(ValueError, match="values for"):
        ridt.ConstrainedDelaunay(SQUARE, SEGMENTS, size=lambda xy: [1.0])
    with pytest.raises(ZeroDivisionError):
        ridt.ConstrainedDelaunay(SQUARE, SEGMENTS, size=lambda xy: 1 / 0)
