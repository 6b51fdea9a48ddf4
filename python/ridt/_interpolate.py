"""Scattered-data interpolation with scipy.interpolate's interfaces, in the plane, on ridt's
exact triangulation: ridt.LinearNDInterpolator, ridt.NearestNDInterpolator,
ridt.CloughTocher2DInterpolator, ridt.NaturalNeighborInterpolator and ridt.griddata."""

from __future__ import annotations

import warnings
from typing import Any, Optional, Tuple

import numpy as np

from . import _api, _core
from ._delaunay import SCIPY_TOLERANCE, Delaunay, DegenerateInputWarning


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


def _is_scipy_delaunay(points: Any) -> bool:
    """Whether points is a scipy.spatial.Delaunay, without importing scipy."""
    return any(c.__name__ == "Delaunay" and c.__module__.startswith("scipy.spatial") for c in type(points).__mro__)


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


def _rescaled_axes(xs: np.ndarray, ys: np.ndarray, offset: np.ndarray,
                   scale: np.ndarray) -> Optional[Tuple[np.ndarray, np.ndarray]]:
    """A grid's axes in rescaled coordinates; None where the rounding merged nodes."""
    xs = np.ascontiguousarray((xs - offset[0]) / scale[0])
    ys = np.ascontiguousarray((ys - offset[1]) / scale[1])
    return (xs, ys) if _monotone(xs) and _monotone(ys) else None


class _TriangulationInterpolator:
    _method = "linear"
    _name = "LinearNDInterpolator"

    def __init__(self, points: Any, values: Any, fill_value: Any = np.nan, rescale: bool = False, *,
                 threads: int = 1):
        who = f"ridt.{self._name}"
        self._threads = _api.thread_count(threads)
        if isinstance(points, Delaunay) or _is_scipy_delaunay(points):
            if rescale:
                raise ValueError("Rescaling is not supported when passing a Delaunay triangulation as ``points``.")
            # A scipy.spatial.Delaunay stands for its points, triangulated here (the same
            # triangles but where Qhull broke a cocircular tie otherwise).
            self.tri = points if isinstance(points, Delaunay) else None
            pts = points.points if self.tri is not None else _coordinates(np.asarray(points.points), who)
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
        if grid is not None and self._rescaled:
            axes = _rescaled_axes(grid[0], grid[1], self._offset, self._scale)
            grid = None if axes is None else (*axes, grid[2], grid[3])
        if grid is not None:
            # The nodes of a grid: each triangle takes the nodes it holds, no walks.
            xs, ys, x_major, shape = grid
            out = _core.interpolate_grid(self.tri.points, self.tri._tri, self.values, xs, ys, x_major,
                                         float(self.fill_value), self._method, self._threads, self._gradients(),
                                         SCIPY_TOLERANCE)
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
                                     self._method, self._threads, self._gradients(), SCIPY_TOLERANCE)
        fill = complex(self.fill_value)
        out = _core.interpolate(self.tri.points, self.tri._tri, self.values, xi, fill.real, self._method,
                                self._threads, self._gradients(), SCIPY_TOLERANCE)
        outside = self.tri.find_simplex(xi) < 0
        out[outside, out.shape[1] // 2:] = fill.imag
        return out


class LinearNDInterpolator(_TriangulationInterpolator):
    """Piecewise linear interpolation in ridt's exact Delaunay triangulation, with
    scipy.interpolate.LinearNDInterpolator's interface (in the plane).

    ``LinearNDInterpolator(points, values, fill_value=nan, rescale=False)``; ``points`` may be
    a :class:`ridt.Delaunay`, or a scipy.spatial.Delaunay, whose points are then triangulated. Call it with an array of shape (..., 2) or with x and y arrays
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
    if not isinstance(tri, Delaunay):
        raise TypeError("tri must be a ridt.Delaunay")
    nthreads = tri._threads if threads is None else _api.thread_count(threads)
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


def _cubic_on_grid(points: Any, values: Any, args: Tuple[Any, ...], fill_value: Any, rescale: bool,
                   threads: int) -> Optional[np.ndarray]:
    """griddata's cubic at a grid's nodes in one call of the library (griddata_cubic: the
    points triangulated, their gradients estimated and the grid answered in one numbering), the
    same numbers as CloughTocher2DInterpolator's; None where that does not apply (complex
    values, no grid, points that are not finite)."""
    grid = _as_grid(args)
    if grid is None:
        return None
    who = "ridt.griddata"
    pts = _coordinates(points, who)
    v, trailing, complex_ = _as_values(values, pts.shape[0], who)
    if complex_:
        return None
    xs, ys, x_major, shape = grid
    pts, offset, scale = _rescaled(pts, bool(rescale))
    if rescale:
        axes = _rescaled_axes(xs, ys, offset, scale)
        if axes is None:
            return None
        xs, ys = axes
    nthreads = _api.thread_count(threads)
    if not np.isfinite(pts).all():
        return None  # Delaunay's error, as for the other methods
    # The library triangulates the points itself, in the order its sweeps and answers read them.
    out, sweeps = _core.griddata_cubic(pts, v, xs, ys, x_major, float(fill_value), 1e-6, 400, nthreads,
                                       SCIPY_TOLERANCE)
    if sweeps < 0:  # no triangle: fill_value throughout, and Delaunay's warning saying why
        Delaunay(pts, threads=nthreads)
    if sweeps == 0:
        warnings.warn("Gradient estimation did not converge, the results may be inaccurate",
                      GradientEstimationWarning, stacklevel=3)
    return out.reshape(shape + trailing)


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
    if method == "cubic":
        on_grid = _cubic_on_grid(points, values, args, fill_value, rescale, threads)
        if on_grid is not None:
            return on_grid
    cls = {"linear": LinearNDInterpolator, "cubic": CloughTocher2DInterpolator}.get(method, NaturalNeighborInterpolator)
    return cls(points, values, fill_value=fill_value, rescale=rescale, threads=threads)(*args)
