"""ridt.Delaunay: scipy.spatial.Delaunay's attributes and methods, on ridt's triangulation."""

from __future__ import annotations

import warnings
from functools import cached_property
from typing import Any, Optional, Tuple

import numpy as np

from . import _api, _core

# Qhull options that only make Qhull more robust or change what it reports about facets; ridt
# is exact and reports the same things whatever they say, so they are accepted and ignored.
# QJ (joggle) asks that every input point be a vertex, which Qhull gets by moving the points
# by tiny random amounts; ridt's exact triangulation of distinct points already has every point
# a vertex, so QJ is taken (with the Qbb that Qhull sets with it), and refused where the points
# hold copies, which only moving them could make vertices.
_HARMLESS_QHULL_OPTIONS = {"Qbb", "Qc", "Qz", "Qt", "Q12", "Qx", "Pp", "Qs", "Qv", "Qbk:0Bk:0"}

# scipy's tolerance of find_simplex and of its interpolators at the hull: 100 DBL_EPSILON.
SCIPY_TOLERANCE = 100 * float(np.finfo(np.float64).eps)


class DegenerateInputWarning(UserWarning):
    """The points have no triangulation (fewer than three distinct, or all collinear)."""


# Options that Qhull cannot apply to points added later; scipy refuses them with incremental.
_INCREMENTAL_BAD_OPTIONS = ("Qbb", "Qbk", "QBk", "QbB", "Qz")


def _option_tokens(options: Optional[str]) -> Optional[list]:
    if options is None:
        return None
    if isinstance(options, bytes):
        options = options.decode()
    if not isinstance(options, str):
        raise TypeError("qhull_options must be a string or None")
    return options.split()


def _check_qhull_options(options: Optional[str], incremental: bool = False) -> None:
    tokens = _option_tokens(options)
    if tokens is None:
        return
    if incremental:
        bad = [o for o in _INCREMENTAL_BAD_OPTIONS if any(o in t for t in tokens)]
        if bad:  # scipy's check and message
            raise ValueError(f"Qhull options {[o.encode() for o in bad]!r} are incompatible with incremental mode")
    accepted = f"(accepted and ignored: {' '.join(sorted(_HARMLESS_QHULL_OPTIONS))})"
    for token in tokens:
        if _is_joggle(token):
            continue
        if token not in _HARMLESS_QHULL_OPTIONS:
            raise ValueError(f"qhull_options {token!r} is not supported: ridt is not Qhull; it is exact and takes "
                             f"no tuning options {accepted}")


def _is_joggle(token: str) -> bool:
    """QJ, or QJn with Qhull's joggle factor n."""
    if not token.startswith("QJ"):
        return False
    try:
        return token == "QJ" or float(token[2:]) >= 0
    except ValueError:
        return False


def _refuse_joggled_copies(options: Optional[str], tri: _core.Triangulation, where: str) -> None:
    """With QJ every input point must be a vertex: copies of a point cannot be, unmoved."""
    tokens = _option_tokens(options) or []
    if any(_is_joggle(t) for t in tokens) and len(tri.duplicates):
        d = tri.duplicates.view(np.intc)
        raise ValueError(f"{where}: qhull_options QJ asks every input point to be a vertex, but point {d[0, 0]} "
                         f"equals point {d[0, 1]} ({len(d)} such copies); ridt does not move points apart "
                         f"as Qhull's joggle does")


def _qhull_flags(options: Optional[str], incremental: bool = False, furthest_site: bool = False) -> frozenset:
    """The options that change what ridt reports, as Qhull's do: Qbb (the paraboloid's lift
    scaled), Qc (coplanar points listed), Qz (a point at infinity). None means scipy's default:
    all three, but only Qc in incremental mode (scipy leaves out Qbb and Qz there); options given
    hold only what they say. Qhull ignores Qz for the farthest-point triangulation."""
    tokens = _option_tokens(options)
    if tokens is None:
        flags = {"Qc"} if incremental else {"Qbb", "Qc", "Qz"}
    else:
        flags = set(tokens) & {"Qbb", "Qc", "Qz"}
        if any(_is_joggle(t) for t in tokens):
            flags |= {"Qbb", "QJ"}  # Qhull sets Qbb with QJ
    if furthest_site:
        flags.discard("Qz")
    return frozenset(flags)


def _refuse_masked(points: Any) -> None:
    if np.ma.isMaskedArray(points):
        raise ValueError("Input points cannot be a masked array")



def hull_edges(tri: _core.Triangulation) -> np.ndarray:
    """The hull's edges (a, b), counter-clockwise, as scipy's convex_hull; none without triangles."""
    h = tri.hull.view(np.intc)
    if len(tri) == 0:
        return np.empty((0, 2), dtype=np.intc)
    return np.stack([h, np.roll(h, -1)], axis=1)

class Delaunay(_api.PlanarPoints):
    """Delaunay triangulation in the plane, with scipy.spatial.Delaunay's interface.

    ``from ridt import Delaunay`` in place of ``from scipy.spatial import Delaunay`` gives the
    same attributes with the same shapes, dtypes and meaning, computed exactly: ``simplices``
    is the Delaunay triangulation of the distinct points with its whole convex hull, the same
    triangles for every method and thread count. Duplicate points are left out and listed in
    ``coplanar``; points that are all collinear, or fewer than three distinct ones, give an
    empty triangulation and a :class:`DegenerateInputWarning` (Qhull raises QhullError there).

    Parameters
    ----------
    points : array_like, shape (npoints, 2)
        Coordinates, any real dtype and layout, all finite.
    furthest_site : bool
        The farthest-point Delaunay triangulation: of the hull's corners, every circumcircle
        holding every point (exact); its triangles clockwise, as scipy's are.
    incremental : bool
        Allow add_points (scipy's incremental mode); the result always equals a fresh build.
    qhull_options : str, optional
        Accepted when it holds only options that concern Qhull's robustness or what it reports
        (Qbb, Qc, Qz, Qt, Q12, Qx, ...), and QJ (joggle: every input point a vertex, which
        ridt's exact triangulation gives unmoved; ValueError where the points hold copies, and
        Qbb set with it, as Qhull sets it); anything else raises ValueError. As in Qhull, Qbb scales the paraboloid's lift
        (paraboloid_scale, paraboloid_shift; with Qz over 1.1 times the highest lift, Qhull's
        point at infinity) and Qc lists the duplicates in coplanar. None means scipy's default,
        "Qbb Qc Qz Q12", or "Qc" with incremental=True, where Qbb and Qz raise ValueError, as in
        scipy; Qz counts for nothing with furthest_site=True, as in Qhull.
    method, threads, order, locate, seed, progress
        ridt's own, as in :func:`ridt.triangulate`. ``threads`` (0 or -1: every core) also
        serves ``find_simplex``.

    Attributes
    ----------
    points : ndarray of double, shape (npoints, 2)
    simplices : ndarray of intc, shape (nsimplex, 3)
        Vertex indices of each triangle, counter-clockwise.
    neighbors : ndarray of intc, shape (nsimplex, 3)
        The k-th neighbour lies across from the k-th vertex; -1 on the hull.
    equations : ndarray of double, shape (nsimplex, 4)
        [normal, offset] of each triangle's plane on the lifted paraboloid (see lift_points).
    paraboloid_scale, paraboloid_shift : float
        The lift: z = scale * (x^2 + y^2) + shift, as Qhull's option Qbb sets it.
    transform : ndarray of double, shape (nsimplex, 3, 2)
        Affine maps to barycentric coordinates: c = T[:2] @ (x - T[2]); the determinant exact,
        NaN for a triangle too thin for the map (see the property).
    vertex_to_simplex : ndarray of intc, shape (npoints,)
        A triangle of each point (for a duplicate left out, one of the equal point kept).
    convex_hull : ndarray of intc, shape (nhull, 2)
        The hull's edges, counter-clockwise, collinear hull points included.
    coplanar : ndarray of intc, shape (nduplicates, 3)
        Points left out as duplicates: (point, a triangle of the equal point kept, that point).
    vertex_neighbor_vertices : tuple of two ndarrays of intc, (indptr, indices)
        The neighbours of vertex k are indices[indptr[k]:indptr[k+1]].
    good : ndarray of intc, shape (nsimplex,)
        1 for every triangle, as scipy gives it (every facet of the lifted hull is good).
    npoints, nsimplex, ndim, min_bound, max_bound, furthest_site
    stats : dict
        ridt's counters and timings of the run.
    """

    def __init__(self, points: Any, furthest_site: bool = False, incremental: bool = False,
                 qhull_options: Optional[str] = None, *, method: str = "auto", threads: int = 1,
                 order: str = "brio", locate: str = "auto", seed: int = 1, progress: _api.ProgressLike = None):
        _check_qhull_options(qhull_options, bool(incremental))
        _refuse_masked(points)
        self._points = _api.as_points(points, "points", "ridt.Delaunay")
        self._threads = _api.thread_count(threads)
        self._options = dict(method=method, order=order, locate=locate, seed=seed, furthest_site=bool(furthest_site))
        self._qhull = _qhull_flags(qhull_options, bool(incremental), bool(furthest_site))
        self._incremental = bool(incremental)
        self._qhull_options = qhull_options
        self._run(progress)
        if self._tri.warning:
            warnings.warn(f"ridt: {self._tri.warning}: the triangulation is empty", DegenerateInputWarning,
                          stacklevel=2)

    def _run(self, progress: _api.ProgressLike = None) -> None:
        self._tri = _api.run(self._points, threads=self._threads, progress=progress, **self._options)
        _refuse_joggled_copies(getattr(self, "_qhull_options", None), self._tri, "ridt.Delaunay")
        self.furthest_site = self._options["furthest_site"]
        if self.furthest_site:
            # Qhull's facets of the upper hull come clockwise; the same triangles, so turned.
            self._simplices = np.ascontiguousarray(self._tri.triangles.view(np.intc)[:, [0, 2, 1]])
            self._neighbors = np.ascontiguousarray(self._tri.neighbors.view(np.intc)[:, [0, 2, 1]])
        else:
            self._simplices = self._tri.triangles.view(np.intc)
            self._neighbors = self._tri.neighbors.view(np.intc)
        self._clear()

    # --- what the library returned, as scipy's dtypes (views, no copies) ---
    @property
    def simplices(self) -> np.ndarray:
        return self._simplices

    @property
    def vertices(self) -> np.ndarray:
        """The same as simplices (scipy's older name, deprecated there as here)."""
        warnings.warn("Delaunay attribute 'vertices' is deprecated in favour of 'simplices' and will be removed "
                      "in Scipy 1.11.0.", DeprecationWarning, stacklevel=2)
        return self.simplices

    @property
    def neighbors(self) -> np.ndarray:
        return self._neighbors

    @property
    def nsimplex(self) -> int:
        return len(self._tri)

    @property
    def stats(self) -> dict:
        return self._tri.stats

    @property
    def triangulation(self) -> _core.Triangulation:
        """ridt's own result (triangles, neighbors, hull, duplicates, warning, stats)."""
        return self._tri

    @cached_property
    def good(self) -> np.ndarray:
        """Qhull's "good" flag of each simplex's facet, as scipy gives it: every triangle is a
        facet of the lifted points' lower hull (of the upper one for furthest_site), and all are
        good, so (nsimplex,) intc ones; simplices[good == 1] is every triangle."""
        return np.ones(self.nsimplex, dtype=np.intc)

    # --- derived, computed on first use ---
    @cached_property
    def convex_hull(self) -> np.ndarray:
        return hull_edges(self._tri)

    @cached_property
    def vertex_to_simplex(self) -> np.ndarray:
        v2s = np.full(self.npoints, -1, dtype=np.intc)
        v2s[self.simplices.ravel()] = np.repeat(np.arange(self.nsimplex, dtype=np.intc), 3)
        d = self._tri.duplicates.view(np.intc)
        v2s[d[:, 0]] = v2s[d[:, 1]]  # a duplicate left out: a triangle of the equal point kept
        return v2s

    @cached_property
    def coplanar(self) -> np.ndarray:
        d = self._tri.duplicates.view(np.intc)
        if "Qc" not in self._qhull:  # Qhull lists its coplanar points only when asked
            d = d[:0]
        out = np.empty((d.shape[0], 3), dtype=np.intc)
        out[:, 0] = d[:, 0]
        out[:, 1] = self.vertex_to_simplex[d[:, 0]]
        out[:, 2] = d[:, 1]
        return out

    @cached_property
    def vertex_neighbor_vertices(self) -> Tuple[np.ndarray, np.ndarray]:
        # Each interior edge is a directed edge of both its triangles; a hull edge of one only,
        # so the hull adds its edges reversed. No edge then comes twice.
        t = self._tri.triangles.view(np.intc)  # counter-clockwise, whatever simplices shows
        hull = self.convex_hull
        src = np.concatenate([t.ravel(), hull[:, 1]])
        dst = np.concatenate([t[:, [1, 2, 0]].ravel(), hull[:, 0]])
        by_src = np.argsort(src, kind="stable")
        indptr = np.zeros(self.npoints + 1, dtype=np.intc)
        np.cumsum(np.bincount(src, minlength=self.npoints), out=indptr[1:])
        return indptr, dst[by_src].astype(np.intc, copy=False)

    @cached_property
    def _lift(self) -> Tuple[float, float]:
        if self.npoints == 0 or "Qbb" not in self._qhull:
            return 1.0, 0.0
        z = np.einsum("ij,ij->i", self._points, self._points)
        low, high = float(z.min()), float(z.max())
        # Qhull's Qbb: the lifted coordinate scaled to [0, m], m the largest coordinate's size,
        # over [low, 1.1 high] with Qz (its point at infinity sits at 1.1 times the highest
        # lift; not with QJ, where Qhull scales before it adds that point), else over [low, high].
        span = (1.1 if "Qz" in self._qhull and "QJ" not in self._qhull else 1.0) * high - low
        if not span > 0:
            return 1.0, 0.0
        scale = float(np.abs(self._points).max()) / span
        return scale, -low * scale

    @property
    def paraboloid_scale(self) -> float:
        return self._lift[0]

    @property
    def paraboloid_shift(self) -> float:
        return self._lift[1]

    def lift_points(self, x: Any) -> np.ndarray:
        """Lift points (..., 2) onto the paraboloid: (..., 3) with z = scale * |x|^2 + shift."""
        x = np.asarray(x, dtype=np.float64)
        if x.shape[-1:] != (2,):
            raise ValueError(f"points must have shape (..., 2); got {x.shape}")
        z = self.paraboloid_scale * np.einsum("...i,...i->...", x, x) + self.paraboloid_shift
        return np.concatenate([x, z[..., None]], axis=-1)

    @cached_property
    def equations(self) -> np.ndarray:
        p = self.lift_points(self._points)[self.simplices]  # (nsimplex, 3 corners, 3)
        n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
        n = -n  # counter-clockwise triangles give an upward normal; the lower hull's points down
        n /= np.linalg.norm(n, axis=1)[:, None]
        offset = -np.einsum("ij,ij->i", n, p[:, 0])
        return np.concatenate([n, offset[:, None]], axis=1)

    def plane_distance(self, xi: Any) -> np.ndarray:
        """Distance of lifted points (..., 2) to every triangle's plane: (..., nsimplex)."""
        lifted = self.lift_points(xi)
        e = self.equations
        return lifted @ e[:, :3].T + e[:, 3]

    @cached_property
    def transform(self) -> np.ndarray:
        """scipy's affine maps to barycentric coordinates, (nsimplex, 3, 2): c = T[:2] @ (x - T[2])
        gives x's first two coordinates in each triangle. The determinant is exact; a triangle
        so thin that the map cannot carry its coordinates (reciprocal condition number below
        2^-40) gets NaN, as scipy gives its near-degenerate simplices. find_simplex and the
        interpolators do not use it: their weights are exact where a filter cannot vouch."""
        return _core.transforms(self._points, self.simplices.view(np.uint32), self._threads)

    def find_simplex(self, xi: Any, bruteforce: bool = False, tol: Optional[float] = None, *,
                     threads: Optional[int] = None) -> np.ndarray:
        """The triangle holding each point of `xi` (..., 2), -1 outside the hull: (...,) intc.

        Exact inside the hull and on it: every decision is an orientation test with exact
        arithmetic; a point on an edge or at a vertex gets one of the triangles that touch it.
        A point outside the hull gets the hull triangle beside it, as in scipy, when each of
        its barycentric coordinates there lies in [-tol, 1 + tol] and it lies within tol of the
        points' bounding box (scipy's rule; `tol` defaults to scipy's 100 * DBL_EPSILON, and 0
        answers -1 for every point outside): the triangle the exact walk towards it leaves the
        hull by, its coordinates' signs exact. So a point that rounding put an ulp outside the
        hull, as scipy's LinearNDInterpolator and griddata meet them, is still found; the
        interpolators use the same default. `bruteforce` is accepted for compatibility and
        changes nothing (the walk never fails). The queries are shared among `threads` threads
        (default: those the triangulation was made with; 0 or -1: every core) with the GIL
        released.
        """
        x = np.asarray(xi)
        if x.dtype.kind not in "biuf":
            raise TypeError(f"xi must hold real numbers, not {x.dtype}")
        if x.shape[-1:] != (2,):
            raise ValueError(f"xi must have shape (..., 2); got {x.shape}")
        shape = x.shape[:-1]
        q = np.ascontiguousarray(x.reshape(-1, 2), dtype=np.float64)
        nthreads = self._threads if threads is None else _api.thread_count(threads)
        eps = SCIPY_TOLERANCE if tol is None else float(tol)
        found = _core.locate(self._points, self._tri.triangles, self._tri.neighbors, q, nthreads, eps)
        return found.view(np.intc).reshape(shape)

    def __getstate__(self) -> dict:
        # The triangulation is a function of the points, so the points and options are enough
        # (an unpickled one may list its triangles in another order: a fresh build's).
        return {"points": self._points, "threads": self._threads, "options": self._options,
                "incremental": self._incremental, "qhull": self._qhull}

    def __setstate__(self, state: dict) -> None:
        self._points = state["points"]
        self._threads = state["threads"]
        self._options = state["options"]
        self._incremental = state["incremental"]
        self._qhull = state["qhull"]
        self._run()

    def _clear(self) -> None:
        """Forgets what was derived from an earlier triangulation."""
        for name in ("good", "convex_hull", "vertex_to_simplex", "coplanar", "vertex_neighbor_vertices", "_lift",
                     "equations", "transform", "min_bound", "max_bound"):
            self.__dict__.pop(name, None)

    def add_points(self, points: Any, restart: bool = False) -> None:
        """Adds points to a triangulation made with ``incremental=True``: each is inserted into
        the existing triangulation (one thread, along a Hilbert curve over the batch), and the
        result is the Delaunay triangulation of all the points, the same triangles as a fresh
        ``Delaunay(all_points)`` (perhaps in another order; the triangulation is unique, so
        ``restart`` changes nothing)."""
        if not self._incremental:
            raise RuntimeError("incremental mode not enabled or already closed")
        _refuse_masked(points)
        more = _api.as_points(points, "points", "ridt.Delaunay.add_points")
        self._points = np.ascontiguousarray(np.concatenate([self._points, more]))
        if self.furthest_site:  # the farthest-point triangulation of the hull's corners, anew
            self._run()
            return
        if getattr(self, "_inc", None) is None:
            self._inc = _core.Incremental(self._points[:len(self._points) - len(more)], self._tri)
        self._inc.add(more)
        self._tri = self._inc.triangulation()
        _refuse_joggled_copies(getattr(self, "_qhull_options", None), self._tri, "ridt.Delaunay.add_points")
        self._simplices = self._tri.triangles.view(np.intc)
        self._neighbors = self._tri.neighbors.view(np.intc)
        self._clear()

    def close(self) -> None:
        """Ends incremental mode (scipy's): add_points then raises RuntimeError."""
        self._incremental = False
        self._inc = None

    def to_matplotlib(self):
        """A matplotlib.tri.Triangulation of the same triangles, with its neighbours filled in
        (matplotlib's neighbour j lies across the edge from vertex j to vertex j + 1, i.e.
        across from vertex j + 2: ridt's and scipy's columns, rotated)."""
        import matplotlib.tri as mtri

        tri = mtri.Triangulation(self._points[:, 0], self._points[:, 1], triangles=self.simplices)
        tri._neighbors = np.ascontiguousarray(self.neighbors[:, [2, 0, 1]], dtype=np.int32)
        return tri

    def __repr__(self) -> str:
        return f"<ridt.Delaunay: {self.npoints} points, {self.nsimplex} triangles>"
