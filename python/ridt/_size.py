"""Size fields for quality meshes: a target edge length over the plane (``size=``)."""

from __future__ import annotations

from typing import Any, Callable, Sequence

import numpy as np

from . import _api, _core


def _ends(axis: Any, n: int, name: str) -> tuple:
    """The first and last node's coordinate along an axis: given as (first, last), or as every
    node's coordinate, evenly spaced."""
    a = np.asarray(axis, dtype=float).reshape(-1)
    if len(a) == 2 or (n == 1 and len(a) == 1):
        return float(a[0]), float(a[-1])
    if len(a) != n:
        raise ValueError(f"{name} gives {len(a)} coordinates for {n} nodes: give (first, last) or all {n}")
    step = np.diff(a)
    if n > 2 and not np.allclose(step, step[0], rtol=1e-9, atol=0):
        raise ValueError(f"{name}'s nodes are not evenly spaced")
    return float(a[0]), float(a[-1])


class SizeField:
    """A target edge length h(x, y) for a quality mesh (``size=`` of ConstrainedDelaunay and of
    ``ridt.triangle.triangulate``): no triangle's longest edge above h at its centroid, but where
    the angle bound or the input forces one (a segment kept whole, a small input angle).

    Made from values the library interpolates (no Python in the refinement's loop), or from a
    vectorized function asked for many points at a call; either way the mesh depends only on
    the sizes, not on how they were given::

        ridt.SizeField.grid(h, x=(0, 10), y=(0, 5))        # h[j, i] at (x_i, y_j), bilinear
        ridt.SizeField.mesh(points, simplices, h)            # linear in a background mesh
        ridt.SizeField.scattered(points, h)                  # linear over their Delaunay triangulation
        ridt.SizeField.function(lambda xy: 0.01 + 0.1 * xy[:, 0])

    ``size=`` also takes a number (a uniform size), a `(points, values)` pair (scattered) or a
    function directly.
    """

    def __init__(self, field: _core.SizeField):
        self._field = field

    @classmethod
    def uniform(cls, h: float) -> "SizeField":
        """h everywhere (> 0)."""
        return cls(_core.SizeField.uniform(float(h)))

    @classmethod
    def grid(cls, values: Any, x: Sequence[float], y: Sequence[float], gradation: float = 0) -> "SizeField":
        """Values on a regular grid: ``values[j, i]`` (shape (ny, nx), as numpy.meshgrid's
        ``indexing="xy"`` gives) at ``(x_i, y_j)``; `x` and `y` each the first and last node's
        coordinate, or every node's (evenly spaced), decreasing where the rows run down (an
        image's). Bilinear within a cell; beyond the grid, the value on its edge nearest.

        `gradation` (also of `mesh` and `scattered`): above 0, the values are first lowered where
        they grow faster than that along the grid's (the mesh's) edges, each the least over
        every node of its value plus `gradation` times the path there, so that neighbouring
        triangles' sizes differ by about that fraction at most (0.2: some 20 %); no value
        rises."""
        v = np.ascontiguousarray(values, dtype=float)
        if v.ndim != 2:
            raise ValueError(f"values must be a 2-D array (ny, nx), got shape {v.shape}")
        ny, nx = v.shape
        x0, x1 = _ends(x, nx, "x")
        y0, y1 = _ends(y, ny, "y")
        return cls(_core.SizeField.grid(v.reshape(-1), nx, ny, x0, y0, x1, y1, float(gradation)))

    @classmethod
    def mesh(cls, points: Any, simplices: Any, values: Any, gradation: float = 0) -> "SizeField":
        """Values at a background mesh's vertices (`simplices`: rows of three indices into
        `points`, any mesh), linear in each triangle; beyond the mesh, the nearest vertex's."""
        pts = _api.as_points(points, "points", "ridt.SizeField.mesh")
        tris = np.asarray(simplices)
        if tris.ndim != 2 or tris.shape[1] != 3:
            raise ValueError(f"simplices must have shape (nsimplex, 3), got {tris.shape}")
        if tris.size and tris.min() < 0:
            raise ValueError("simplices refer to a negative index")
        return cls(_core.SizeField.mesh(pts, np.ascontiguousarray(tris, dtype=np.uint32).reshape(-1),
                                        np.asarray(values, dtype=float).reshape(-1), float(gradation)))

    @classmethod
    def scattered(cls, points: Any, values: Any, gradation: float = 0) -> "SizeField":
        """Values at scattered points: linear over their Delaunay triangulation, the nearest
        point's beyond its hull."""
        pts = _api.as_points(points, "points", "ridt.SizeField.scattered")
        return cls(_core.SizeField.scattered(pts, np.asarray(values, dtype=float).reshape(-1), float(gradation)))

    @classmethod
    def function(cls, f: Callable[[np.ndarray], Any]) -> "SizeField":
        """``f(xy)``, with `xy` an (n, 2) array of points, returns their n sizes; it is called with
        many points at once (the centroids of the triangles refinement made since the last
        call). What it raises comes out of the call that meshes."""
        if not callable(f):
            raise TypeError(f"a size function must be callable, got {type(f).__name__}")
        return cls(_core.SizeField.function(f))

    def __call__(self, points: Any) -> np.ndarray:
        """The sizes at `points` (shape (n, 2))."""
        return self._field.sizes(_api.as_points(points, "points", "ridt.SizeField"))


def as_size_field(size: Any) -> Any:
    """``size=``'s argument as the library's field (None: none)."""
    if size is None:
        return None
    if isinstance(size, SizeField):
        return size._field
    if isinstance(size, (int, float, np.integer, np.floating)) and not isinstance(size, bool):
        return SizeField.uniform(size)._field
    if callable(size):
        return SizeField.function(size)._field
    if isinstance(size, tuple) and len(size) == 2:
        return SizeField.scattered(*size)._field
    raise TypeError("size must be a ridt.SizeField, a number, a function of an (n, 2) array, or a "
                    f"(points, values) pair; got {type(size).__name__}")
