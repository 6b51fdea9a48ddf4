"""What a caller can hand ridt: every real dtype and memory layout, and clear errors for the rest."""

import numpy as np
import pytest

import ridt
from conftest import triangle_set

PTS = np.random.default_rng(0).random((200, 2))


@pytest.mark.parametrize("convert", [
    lambda a: a.astype(np.float32),
    lambda a: np.asfortranarray(a),
    lambda a: np.repeat(a, 2, axis=0)[::2],           # rows not contiguous
    lambda a: np.ascontiguousarray(a.T).T,             # column-major view
    lambda a: a.tolist(),
    lambda a: [tuple(p) for p in a.tolist()],
], ids=["float32", "fortran", "strided", "transposed", "list", "tuples"])
def test_layouts_and_dtypes_give_the_same_triangles(convert):
    want = triangle_set(ridt.Delaunay(np.asarray(convert(PTS), dtype=np.float64)).simplices)
    assert triangle_set(ridt.Delaunay(convert(PTS)).simplices) == want
    assert triangle_set(ridt.triangulate(convert(PTS)).triangles) == want


def test_integer_points():
    pts = np.array([[0, 0], [4, 0], [0, 3], [5, 5], [2, 1]], dtype=np.int64)
    tri = ridt.Delaunay(pts)
    assert tri.points.dtype == np.float64
    assert ridt.check(pts, tri.simplices)[0]


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_points_raise_value_error(bad):
    pts = PTS.copy()
    pts[17, 1] = bad
    with pytest.raises(ValueError, match=r"points\[17\].*not finite"):
        ridt.Delaunay(pts)
    with pytest.raises(ValueError, match="not finite"):
        ridt.triangulate(pts)


@pytest.mark.parametrize("pts,error,match", [
    (np.zeros((5, 3)), ValueError, "plane"),
    (np.zeros(6), ValueError, "shape"),
    (np.zeros((2, 3, 2)), ValueError, "shape"),
    (np.zeros((4, 2), dtype=complex), TypeError, "real numbers"),
    (np.array([["a", "b"], ["c", "d"]]), TypeError, "real numbers"),
    ([[0, 0], [1]], ValueError, "shape"),
    (np.array([[object(), 1.0]], dtype=object), TypeError, "real numbers"),
], ids=["3d", "flat", "3-axis", "complex", "strings", "ragged", "objects"])
def test_wrong_shapes_and_types(pts, error, match):
    with pytest.raises(error, match=match):
        ridt.Delaunay(pts)


def test_unsupported_scipy_options_name_the_reason():
    with pytest.raises(RuntimeError, match="incremental mode not enabled"):
        ridt.Delaunay(PTS).add_points(PTS)
    with pytest.raises(ValueError, match="QG4"):
        ridt.Delaunay(PTS, qhull_options="Qbb QG4")
    with pytest.raises(ValueError, match="QJ"):  # joggle on copies of a point
        ridt.Delaunay(np.concatenate([PTS, PTS[:1]]), qhull_options="Qbb Qc Qz Q12 QJ")


def test_bad_options():
    with pytest.raises(ValueError, match="method"):
        ridt.triangulate(PTS, method="fast")
    with pytest.raises(ValueError, match="order"):
        ridt.triangulate(PTS, order="hilbert")
    with pytest.raises(TypeError, match="threads"):
        ridt.triangulate(PTS, threads=1.5)
    with pytest.raises(ValueError, match="threads"):
        ridt.triangulate(PTS, threads=-3)
    with pytest.raises(ValueError, match="seed"):
        ridt.triangulate(PTS, seed=-1)
    with pytest.raises(TypeError, match="progress"):
        ridt.triangulate(PTS, progress=42)
    # The library's own refusals come as ValueError (ridt.InputError) with its reason.
    with pytest.raises(ValueError, match="BRIO"):
        ridt.triangulate(PTS, method="partition", threads=2, order="random")
    with pytest.raises(ridt.InputError, match="DAG"):
        ridt.triangulate(PTS, method="partition", threads=2, locate="dag")
    with pytest.raises(TypeError):
        ridt.Delaunay(PTS).find_simplex(np.zeros((3, 2), dtype=complex))
    with pytest.raises(ValueError, match="shape"):
        ridt.Delaunay(PTS).find_simplex(np.zeros((3, 3)))


def test_triangulate_arrays_are_the_librarys_buffers():
    t = ridt.triangulate(PTS)
    a, b = t.triangles, t.triangles
    assert a.ctypes.data == b.ctypes.data  # the same memory each time: no copy
    assert a.base is not None
    assert a.dtype == np.uint32 and t.neighbors.dtype == np.int32 and a.shape == (len(t), 3)
    del t  # the arrays keep the result alive
    assert triangle_set(a) == triangle_set(ridt.Delaunay(PTS).simplices)
    d = ridt.Delaunay(PTS)
    assert d.simplices.ctypes.data == d.triangulation.triangles.ctypes.data


def test_check_with_segments():
    kite = np.array([(0, 0), (4, -1), (8, 0), (4, 1)], dtype=float)
    long_diagonal = np.array([(0, 1, 2), (0, 2, 3)])
    assert not ridt.check(kite, long_diagonal)[0]
    valid, message = ridt.check(kite, long_diagonal, segments=[(0, 2)])
    assert valid and "constrained Delaunay with 1 segments" in message
    assert not ridt.check(kite, ridt.Delaunay(kite).simplices, segments=[(2, 0)])[0]
    assert ridt.check(kite, long_diagonal, segments=[(0, 9)]) == (False, "a segment's end is not one of the 4 points")
    with pytest.raises(ValueError):
        ridt.check(kite, long_diagonal, segments=[0, 2])
    with pytest.raises(TypeError):
        ridt.check(kite, long_diagonal, segments=[(0.5, 2)])
    with pytest.raises(ValueError):
        ridt.check(kite, long_diagonal, furthest_site=True, segments=[(0, 2)])


def test_check_rejects_a_wrong_triangulation():
    tri = ridt.Delaunay(PTS)
    assert ridt.check(PTS, tri.simplices) == (True, ridt.check(PTS, tri.simplices)[1])
    flipped = tri.simplices[:, ::-1]
    valid, message = ridt.check(PTS, flipped)
    assert not valid and message
    assert not ridt.check(PTS, tri.simplices[1:])[0]
    assert not ridt.check(PTS, tri.simplices + 1000)[0]
