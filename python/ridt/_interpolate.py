"""Voronoi diagrams and scattered-data interpolation with scipy's interfaces, on ridt's exact
triangulation: ridt.Voronoi (scipy.spatial.Voronoi), ridt.LinearNDInterpolator,
ridt.NearestNDInterpolator, ridt.NaturalNeighborInterpolator and ridt.griddata
(scipy.interpolate's, in the plane)."""

from __future__ import annotations

import warnings
from functools import cached_property
from typing import Any, Dict, List, Optional, Tuple

import numpy as np

from . import _api, _core
from ._delaunay import Delaunay, DegenerateInputWarning, _check_qhull_options, _refuse_masked


class Voronoi:
    """Voronoi diagram in the plane, with scipy.spatial.Voronoi's attributes.

    The diagram is the dual of ridt's exact Delaunay triangulation: vertex ``t`` is the
    circumcentre of triangle ``t``, each Delaunay edge gives a ridge, each distinct point a
    region. Where four or more points are cocircular (a grid), each triangle keeps its own
    vertex, so equal vertices and ridges of length zero appear where Qhull would merge them.
    Duplicate points share the region of the point kept. Fewer than three distinct points, or
    all collinear, raise :class:`ridt.InputError` (Qhull raises QhullError).

    Parameters
    ----------
    points : array_like, shape (npoints, 2)
    furthest_site : bool
        The farthest-point diagram: the dual of the farthest-point Delaunay triangulation; a
        point inside the hull has an empty region.
    incremental : bool
        Allow add_points (scipy's incremental mode).
    qhull_options : str, optional
        As for :class:`ridt.Delaunay`: only Qhull's robustness options, accepted and ignored.
    threads : int
        Threads for the triangulation and the diagram (0 or -1: every core).

    Attributes
    ----------
    points : ndarray of double, shape (npoints, 2)
    vertices : ndarray of double, shape (nvertices, 2)
    ridge_points : ndarray of intc, shape (nridges, 2)
        The two points each ridge lies between.
    ridge_vertices : list of list of int
        The two vertices of each ridge; -1 for the end of a ray, at infinity.
    ridge_directions : ndarray of double, shape (nridges, 2)
        ridt's own: for a ray, its direction (the outward normal of the hull edge); else 0.
    regions : list of list of int
        The vertices of each region, counter-clockwise; -1 (at infinity) in an unbounded one.
    point_region : ndarray of intp, shape (npoints,)
        The region of each point.
    ridge_dict : dict
        {(p, q): [u, v]} for every ridge.
    npoints, ndim, min_bound, max_bound, furthest_site
    """

    def __init__(self, points: Any, furthest_site: bool = False, incremental: bool = False,
                 qhull_options: Optional[str] = None, *, threads: int = 1):
        _check_qhull_options(qhull_options)
        self._incremental = bool(incremental)
        _refuse_masked(points)
        options = qhull_options.decode() if isinstance(qhull_options, bytes) else qhull_options
        # scipy's default is "Qbb Qc Qz": Qz adds a point at infinity to Qhull's input, which
        # shows as one more region, empty, that no point owns.
        at_infinity = (options is None or "Qz" in options.split()) and not furthest_site
        self.furthest_site = bool(furthest_site)
        self._build(_api.as_points(points, "points", "ridt.Voronoi"), _api.thread_count(threads), at_infinity)

    def _build(self, points: np.ndarray, threads: int, at_infinity: bool,
               tri: Optional[_core.Triangulation] = None) -> None:
        self._points, self._threads, self._at_infinity = points, threads, at_infinity
        self._tri = tri if tri is not None else _api.run(points, method="auto", threads=threads, order="brio",
                                                         locate="auto", seed=1, progress=None,
                                                         furthest_site=self.furthest_site)
        if self._tri.warning:
            raise _core.InputError(f"ridt.Voronoi: {self._tri.warning}: no Voronoi vertex")
        (self.vertices, offsets, self._cell_vertices, point_cell, ridge_points,
         self._ridge_vertices) = _core.voronoi(points, self._tri, threads)
        # The points with no region of the farthest-point diagram (those inside the hull) get an
        # empty one each, as in scipy; with Qz, region 0 is the point at infinity's, empty.
        lacking = np.flatnonzero(point_cell < 0)
        if len(lacking):
            point_cell[lacking] = len(offsets) - 1 + np.arange(len(lacking), dtype=point_cell.dtype)
            offsets = np.concatenate([offsets, np.full(len(lacking), offsets[-1], dtype=offsets.dtype)])
        if at_infinity:
            offsets = np.concatenate([offsets[:1], offsets])
            point_cell = point_cell + 1
        self._offsets = offsets
        self.ridge_points = ridge_points.view(np.intc)
        self.point_region = point_cell.astype(np.intp)

    def __getstate__(self) -> dict:
        return {"points": self._points, "threads": self._threads, "at_infinity": self._at_infinity,
                "incremental": self._incremental, "furthest_site": self.furthest_site}

    def __setstate__(self, state: dict) -> None:
        self._incremental = state["incremental"]
        self.furthest_site = state["furthest_site"]
        self._build(state["points"], state["threads"], state["at_infinity"])

    def add_points(self, points: Any, restart: bool = False) -> None:
        """Adds points to a diagram made with ``incremental=True``: they are inserted into the
        existing triangulation, and the result is the diagram of all the points, as a fresh
        ``Voronoi(all_points)`` gives it (perhaps numbered otherwise)."""
        if not self._incremental:
            raise RuntimeError("incremental mode not enabled or already closed")
        _refuse_masked(points)
        more = _api.as_points(points, "points", "ridt.Voronoi.add_points")
        for name in ("_ints", "ridge_vertices", "regions", "ridge_directions", "ridge_dict"):
            self.__dict__.pop(name, None)
        tri = None
        if not self.furthest_site:  # inserted into the existing triangulation
            if getattr(self, "_inc", None) is None:
                self._inc = _core.Incremental(self._points, self._tri)
            self._inc.add(more)
            tri = self._inc.triangulation()
        self._build(np.ascontiguousarray(np.concatenate([self._points, more])), self._threads, self._at_infinity, tri)

    def close(self) -> None:
        """Ends incremental mode (scipy's): add_points then raises RuntimeError."""
        self._incremental = False
        self._inc = None

    @property
    def points(self) -> np.ndarray:
        return self._points

    @property
    def triangulation(self) -> _core.Triangulation:
        """ridt's Delaunay triangulation of the points, whose dual the diagram is."""
        return self._tri

    @property
    def npoints(self) -> int:
        return int(self._points.shape[0])

    @property
    def ndim(self) -> int:
        return 2

    @property
    def min_bound(self) -> np.ndarray:
        return self._points.min(axis=0)

    @property
    def max_bound(self) -> np.ndarray:
        return self._points.max(axis=0)

    @cached_property
    def _ints(self) -> List[int]:
        # The ints the lists below share, one object for each vertex.
        return list(range(len(self.vertices)))

    @cached_property
    def ridge_vertices(self) -> List[List[int]]:
        pairs = np.arange(0, 2 * len(self._ridge_vertices) + 1, 2, dtype=np.uint32)
        return _core.lists(self._ridge_vertices.reshape(-1), pairs, self._ints)

    @cached_property
    def regions(self) -> List[List[int]]:
        return _core.lists(self._cell_vertices, self._offsets, self._ints)

    @cached_property
    def ridge_directions(self) -> np.ndarray:
        d = np.zeros((len(self.ridge_points), 2))
        ray = self._ridge_vertices[:, 1] < 0
        a = self._points[self.ridge_points[ray, 0]]
        b = self._points[self.ridge_points[ray, 1]]
        d[ray, 0] = b[:, 1] - a[:, 1]
        d[ray, 1] = a[:, 0] - b[:, 0]
        return d

    @cached_property
    def ridge_dict(self) -> Dict[Tuple[int, int], List[int]]:
        return {(int(a), int(b)): list(uv) for (a, b), uv in zip(self.ridge_points.tolist(), self.ridge_vertices)}


def _coordinates(points: Any, who: str) -> np.ndarray:
    """Points as scipy.interpolate takes them: an array (n, 2) or a tuple of two coordinate
    arrays (broadcast together; a tuple of one item is that item), checked by as_points."""
    if isinstance(points, tuple):
        if len(points) == 1:
            points = points[0]
        else:
            axes = np.broadcast_arrays(*[np.asarray(p) for p in points])
            points = np.stack([a.reshape(-1) for a in axes], axis=-1)
    return _api.as_points(points, "points", who)


def _rescaled(pts: np.ndarray, rescale: bool) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
    """scipy's rescale: the points centred and scaled by their extent on each axis (an axis of
    no extent left unscaled); the points, the offset and the scale."""
    if not rescale:
        return pts, np.zeros(2), np.ones(2)
    offset = pts.mean(axis=0)
    ptp = np.ptp(pts, axis=0)
    scale = np.where(ptp > 0, ptp, 1.0)
    return np.ascontiguousarray((pts - offset) / scale), offset, scale


def _as_values(values: Any, n: int, who: str) -> Tuple[np.ndarray, Tuple[int, ...], bool]:
    """values as float64 (n, k) in C order, the trailing shape, and whether they were complex."""
    v = np.asarray(values)
    if v.dtype.kind not in "biufc":
        raise TypeError(f"{who}: values must be numbers, not {v.dtype}")
    if v.ndim == 0 or v.shape[0] != n:
        raise ValueError(f"{who}: values must have {n} rows, one a point; got shape {v.shape}")
    trailing = v.shape[1:]
    complex_ = v.dtype.kind == "c"
    v = v.reshape(n, -1)
    if complex_:
        v = np.concatenate([v.real, v.imag], axis=1)
    return np.ascontiguousarray(v, dtype=np.float64), trailing, complex_


def _as_queries(args: Tuple[Any, ...], who: str) -> Tuple[np.ndarray, Tuple[int, ...]]:
    """Queries given as an array (..., 2) or as x and y arrays that broadcast: (m, 2) float64
    and the shape of the answer's leading part."""
    if len(args) == 1 and isinstance(args[0], tuple):
        args = args[0]
    if len(args) == 2:
        x, y = np.broadcast_arrays(np.asarray(args[0], dtype=np.float64), np.asarray(args[1], dtype=np.float64))
        shape = x.shape
        xi = np.stack([x.ravel(), y.ravel()], axis=1)
    elif len(args) == 1:
        xi = np.asarray(args[0], dtype=np.float64)
        if xi.ndim == 0 or xi.shape[-1] != 2:
            raise ValueError(f"{who}: query points must have shape (..., 2); got {xi.shape}")
        shape = xi.shape[:-1]
        xi = xi.reshape(-1, 2)
    else:
        raise TypeError(f"{who}: give the query points as one array (..., 2) or as x and y")
    # Not finite: answered with the fill value, as outside the hull.
    return np.ascontiguousarray(xi), shape


def _constant_along(a: np.ndarray, axis: int) -> bool:
    return a.shape[axis] == 1 or bool((a == a.take([0], axis=axis)).all())


def _monotone(v: np.ndarray) -> bool:
    d = np.diff(v)
    return bool(np.isfinite(v).all() and ((d > 0).all() or (d < 0).all()))


def _as_grid(args: Tuple[Any, ...]) -> Optional[Tuple[np.ndarray, np.ndarray, bool, Tuple[int, int]]]:
    """When the queries are x and y arrays that make a grid, x varying along one axis only and y
    along the other (numpy.mgrid, numpy.meshgrid, or x[:, None] and y[None, :]), each strictly
    monotone: its axes, whether x runs along the first axis, and the answer's shape; else None."""
    if len(args) == 1 and isinstance(args[0], tuple):
        args = args[0]
    if len(args) != 2:
        return None
    x, y = np.asarray(args[0]), np.asarray(args[1])
    if x.dtype.kind not in "biuf" or y.dtype.kind not in "biuf" or x.ndim > 2 or y.ndim > 2:
        return None
    try:
        shape = np.broadcast_shapes(x.shape, y.shape)
    except ValueError:
        return None
    if len(shape) != 2:
        return None
    x2, y2 = x.reshape((1,) * (2 - x.ndim) + x.shape), y.reshape((1,) * (2 - y.ndim) + y.shape)
    for along, x_major in ((0, True), (1, False)):
        other = 1 - along
        if _constant_along(x2, other) and _constant_along(y2, along):
            xs = np.broadcast_to(x2.take([0], axis=other).reshape(-1), (shape[along],))
            ys = np.broadcast_to(y2.take([0], axis=along).reshape(-1), (shape[other],))
            xs, ys = np.ascontiguousarray(xs, dtype=np.float64), np.ascontiguousarray(ys, dtype=np.float64)
            if _monotone(xs) and _monotone(ys):
                return xs, ys, x_major, shape
    return None


class _TriangulationInterpolator:
    _method = "linear"
    _name = "LinearNDInterpolator"

    def __init__(self, points: Any, values: Any, fill_value: Any = np.nan, rescale: bool = False, *,
                 threads: int = 1):
        who = f"ridt.{self._name}"
        self._threads = _api.thread_count(threads)
        if isinstance(points, Delaunay):
            if rescale:
                raise ValueError("Rescaling is not supported when passing a Delaunay triangulation as ``points``.")
            self.tri = points
            pts = points.points
        else:
            pts = _coordinates(points, who)
            self.tri = None
        self._rescaled = bool(rescale)
        pts, self._offset, self._scale = _rescaled(pts, self._rescaled)
        if self.tri is None:
            self.tri = Delaunay(pts, threads=self._threads)
        self.points = pts
        self.values, self._trailing, self._complex = _as_values(values, pts.shape[0], who)
        self.fill_value = fill_value
        self._who = who

    def __call__(self, *args: Any) -> np.ndarray:
        grid = None if self._complex else _as_grid(args)
        if grid is not None:
            # The nodes of a grid: each triangle takes the nodes it holds, no walks.
            xs, ys, x_major, shape = grid
            if self._rescaled:
                xs = np.ascontiguousarray((xs - self._offset[0]) / self._scale[0])
                ys = np.ascontiguousarray((ys - self._offset[1]) / self._scale[1])
                if not (_monotone(xs) and _monotone(ys)):  # nodes merged by the rounding
                    grid = None
        if grid is not None:
            out = _core.interpolate_grid(self.tri.points, self.tri._tri, self.values, xs, ys, x_major,
                                         float(self.fill_value), self._method, self._threads, self._gradients())
            return out.reshape(shape + self._trailing)
        xi, shape = _as_queries(args, self._who)
        if self._rescaled:
            xi = np.ascontiguousarray((xi - self._offset) / self._scale)
        out = self._evaluate(xi)
        if self._complex:
            half = out.shape[1] // 2
            out = out[:, :half] + 1j * out[:, half:]
        return out.reshape(shape + self._trailing)

    def _gradients(self) -> Optional[np.ndarray]:
        return None

    def _evaluate(self, xi: np.ndarray) -> np.ndarray:
        if not self._complex:
            return _core.interpolate(self.tri.points, self.tri._tri, self.values, xi, float(self.fill_value),
                                     self._method, self._threads, self._gradients())
        fill = complex(self.fill_value)
        out = _core.interpolate(self.tri.points, self.tri._tri, self.values, xi, fill.real, self._method,
                                self._threads, self._gradients())
        outside = self.tri.find_simplex(xi) < 0
        out[outside, out.shape[1] // 2:] = fill.imag
        return out


class LinearNDInterpolator(_TriangulationInterpolator):
    """Piecewise linear interpolation in ridt's exact Delaunay triangulation, with
    scipy.interpolate.LinearNDInterpolator's interface (in the plane).

    ``LinearNDInterpolator(points, values, fill_value=nan, rescale=False)``; ``points`` may be
    a :class:`ridt.Delaunay`. Call it with an array of shape (..., 2) or with x and y arrays
    that broadcast. Outside the convex hull the answer is ``fill_value``. ``threads`` (ridt's
    own; 0 or -1: every core) serves the triangulation and every call.
    """


class NaturalNeighborInterpolator(_TriangulationInterpolator):
    """Sibson's natural-neighbour interpolation: smooth where linear interpolation has kinks,
    exact on linear functions, equal to the data at the points; the same arguments as
    :class:`ridt.LinearNDInterpolator`. On the hull's edges it is linear along the edge."""

    _method = "natural"
    _name = "NaturalNeighborInterpolator"


class GradientEstimationWarning(Warning):
    """The gradients' sweeps stopped at maxiter before they settled (scipy's warning)."""


def estimate_gradients_2d_global(tri: Delaunay, y: Any, maxiter: int = 400, tol: float = 1e-6, *,
                                 threads: Optional[int] = None) -> np.ndarray:
    """scipy.interpolate's estimate_gradients_2d_global on a :class:`ridt.Delaunay`: the
    gradients at the points that minimise the squared second derivative along the Delaunay
    edges of the cubics the data define on them (Nielson's minimum-norm network), by
    Gauss-Seidel sweeps until a sweep changes no gradient by more than `tol` (relative, where
    the gradient exceeds 1), at most `maxiter`. Returns an array of y's shape plus a last axis
    of 2 (d/dx, d/dy); warns with :class:`GradientEstimationWarning` when the sweeps did not
    settle. Exact for linear data. ``threads`` (ridt's own; default: the triangulation's)
    share each sweep; the result does not depend on them."""
    nthreads = tri._threads if threads is None else _api.thread_count(threads)
    if not isinstance(tri, Delaunay):
        raise TypeError("tri must be a ridt.Delaunay")
    y = np.asanyarray(y)
    if y.ndim == 0 or y.shape[0] != tri.npoints:
        raise ValueError("'y' has a wrong number of items")
    if np.iscomplexobj(y):
        with warnings.catch_warnings():
            warnings.simplefilter("error", GradientEstimationWarning)
            try:
                re = estimate_gradients_2d_global(tri, y.real, maxiter=maxiter, tol=tol, threads=nthreads)
                im = estimate_gradients_2d_global(tri, y.imag, maxiter=maxiter, tol=tol, threads=nthreads)
                return re + 1j * im
            except GradientEstimationWarning:
                pass
        warnings.warn("Gradient estimation did not converge, the results may be inaccurate",
                      GradientEstimationWarning, stacklevel=2)
        return (estimate_gradients_2d_global(tri, y.real, maxiter=maxiter, tol=tol, threads=nthreads)
                + 1j * estimate_gradients_2d_global(tri, y.imag, maxiter=maxiter, tol=tol, threads=nthreads))
    if int(maxiter) < 1 or not float(tol) > 0:
        raise ValueError(f"maxiter must be at least 1 and tol positive; got {maxiter} and {tol}")
    v = np.ascontiguousarray(y.reshape(tri.npoints, -1), dtype=np.float64)
    g, sweeps = _core.estimate_gradients(tri.points, tri.triangulation, v, float(tol), int(maxiter), nthreads)
    if sweeps == 0:
        warnings.warn("Gradient estimation did not converge, the results may be inaccurate",
                      GradientEstimationWarning, stacklevel=2)
    return g.reshape(y.shape + (2,))


class CloughTocher2DInterpolator(_TriangulationInterpolator):
    """Piecewise cubic, C1 interpolation with scipy.interpolate.CloughTocher2DInterpolator's
    interface: ``CloughTocher2DInterpolator(points, values, fill_value=nan, tol=1e-6,
    maxiter=400, rescale=False)``. Each triangle of ridt's exact triangulation is split at its
    centroid into three cubic pieces that take the values and the gradients ``grad`` (estimated
    as :func:`estimate_gradients_2d_global` does; set it to use others) at its corners; the
    derivative across each side is linear, along the line between the two triangles'
    centroids, as scipy does. Computed in C++ on ``threads`` threads; at a data point its
    value exactly."""

    _method = "cubic"
    _name = "CloughTocher2DInterpolator"

    def __init__(self, points: Any, values: Any, fill_value: Any = np.nan, tol: float = 1e-6, maxiter: int = 400,
                 rescale: bool = False, *, threads: int = 1):
        super().__init__(points, values, fill_value=fill_value, rescale=rescale, threads=threads)
        k = self.values.shape[1] // (2 if self._complex else 1)
        data = self.values[:, :k] + 1j * self.values[:, k:] if self._complex else self.values
        self.grad = estimate_gradients_2d_global(self.tri, data, maxiter=maxiter, tol=tol, threads=self._threads)

    def _gradients(self) -> np.ndarray:
        g = np.asarray(self.grad)
        g = np.concatenate([g.real, g.imag], axis=1) if self._complex else g
        return np.ascontiguousarray(g, dtype=np.float64).reshape(len(self.values), -1)


class NearestNDInterpolator:
    """Nearest-neighbour interpolation with scipy.interpolate.NearestNDInterpolator's interface
    (in the plane): the value of a nearest point, found by a walk on the Delaunay graph, or,
    where the points have no triangle (fewer than three distinct, or all on a line), by their
    order along the line. The values keep their dtype, as scipy's do."""

    def __init__(self, x: Any, y: Any, rescale: bool = False, tree_options: Any = None, *, threads: int = 1):
        who = "ridt.NearestNDInterpolator"
        pts = x.points if isinstance(x, Delaunay) else _coordinates(x, who)
        self.values = np.asarray(y)
        if self.values.ndim == 0 or self.values.shape[0] != pts.shape[0]:
            raise ValueError(f"{who}: values must have {pts.shape[0]} rows, one a point; got shape {self.values.shape}")
        self._threads = _api.thread_count(threads)
        self._rescaled = bool(rescale)
        pts, self._offset, self._scale = _rescaled(pts, self._rescaled)
        self.points = pts
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", DegenerateInputWarning)
            self.tri = Delaunay(pts, threads=self._threads)
        self._line = None if self.tri.nsimplex else _Line(pts, self.tri.triangulation.duplicates)

    def __call__(self, *args: Any) -> np.ndarray:
        xi, shape = _as_queries(args, "ridt.NearestNDInterpolator")
        if self._rescaled:
            xi = np.ascontiguousarray((xi - self._offset) / self._scale)
        if self._line is None:
            which = _core.nearest(self.points, self.tri.triangulation, xi, self._threads)
        else:
            which = self._line.nearest(xi)
        lost = which < 0  # a query that is not finite
        out = self.values[np.where(lost, 0, which)]
        if lost.any():
            if out.dtype.kind not in "fc":
                out = out.astype(np.float64)
            out[lost] = np.nan
        return out.reshape(shape + self.values.shape[1:])


class _Line:
    """Points with no triangle: one distinct point, or all on a line. A query's nearest point is
    the one nearest its projection on the line, found by bisection in their order along it."""

    def __init__(self, points: np.ndarray, duplicates: np.ndarray):
        keep = np.ones(len(points), dtype=bool)
        keep[duplicates[:, 0]] = False
        self.index = np.flatnonzero(keep)
        distinct = points[self.index]
        order = np.lexsort((distinct[:, 1], distinct[:, 0]))  # along the line, for collinear points
        self.index, self.points = self.index[order], distinct[order]
        self.origin = self.points[0]
        self.direction = self.points[-1] - self.origin
        self.t = (self.points - self.origin) @ self.direction

    def nearest(self, xi: np.ndarray) -> np.ndarray:
        out = np.full(len(xi), -1, dtype=np.intp)
        finite = np.isfinite(xi).all(axis=1)
        if len(self.index) == 0:
            return out
        q = xi[finite]
        k = np.searchsorted(self.t, (q - self.origin) @ self.direction)
        # The neighbours of the bisection's place, wide enough for the rounding of t.
        candidates = np.clip(k[:, None] + np.arange(-2, 2)[None, :], 0, len(self.t) - 1)
        d2 = ((self.points[candidates] - q[:, None, :]) ** 2).sum(axis=2)
        out[finite] = self.index[candidates[np.arange(len(q)), d2.argmin(axis=1)]]
        return out


def griddata(points: Any, values: Any, xi: Any, method: str = "linear", fill_value: Any = np.nan,
             rescale: bool = False, *, threads: int = 1) -> np.ndarray:
    """Interpolate scattered data, with scipy.interpolate.griddata's arguments (in the plane).

    ``method`` is scipy's 'linear', 'nearest' or 'cubic' (Clough-Tocher), or 'natural'
    (Sibson's natural neighbours). ``xi`` is an array (..., 2) or a tuple (x, y) of
    arrays that broadcast (e.g. from numpy.mgrid). ``threads`` is ridt's own (0 or -1: every
    core).
    """
    if method not in ("linear", "nearest", "natural", "cubic"):
        raise ValueError(f"method must be 'linear', 'cubic', 'nearest' or 'natural'; got {method!r}")
    args = xi if isinstance(xi, tuple) else (xi,)
    if method == "nearest":
        return NearestNDInterpolator(points, values, rescale=rescale, threads=threads)(*args)
    cls = {"linear": LinearNDInterpolator, "cubic": CloughTocher2DInterpolator}.get(method, NaturalNeighborInterpolator)
    return cls(points, values, fill_value=fill_value, rescale=rescale, threads=threads)(*args)
