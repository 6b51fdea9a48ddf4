"""ridt.ConvexHull: scipy.spatial.ConvexHull's attributes and methods in the plane, exactly."""

from __future__ import annotations

import re
from typing import Any, Optional, Tuple

import numpy as np

from . import _api, _core
from ._delaunay import _HARMLESS_QHULL_OPTIONS, _INCREMENTAL_BAD_OPTIONS, _option_tokens, _refuse_masked


class DegenerateInputError(RuntimeError):
    """The points have no convex hull in the plane: fewer than three distinct, or all collinear
    (a RuntimeError, as scipy's QhullError is)."""


_GOOD = re.compile(r"^QG(-?)(\d+)$")


def _options(options: Optional[str], incremental: bool) -> Tuple[bool, Optional[Tuple[int, bool]]]:
    """(Qc given, (n, visible) for QGn / QG-n or None); ValueError for any other option that is
    not one of those ridt accepts and ignores."""
    tokens = _option_tokens(options) or []
    if incremental:
        bad = [o for o in _INCREMENTAL_BAD_OPTIONS if any(o in t for t in tokens)]
        if bad:
            raise ValueError(f"Qhull options {[o.encode() for o in bad]!r} are incompatible with incremental mode")
    good = None
    for token in tokens:
        m = _GOOD.match(token)
        if m:
            good = (int(m.group(2)), m.group(1) != "-")
        elif token not in _HARMLESS_QHULL_OPTIONS:
            raise ValueError(f"qhull_options {token!r} is not supported: ridt is not Qhull; it is exact and takes "
                             f"no tuning options (accepted: QGn, QG-n, {' '.join(sorted(_HARMLESS_QHULL_OPTIONS))})")
    return "Qc" in tokens, good


class ConvexHull(_api.PlanarPoints):
    """The convex hull of points in the plane, with scipy.spatial.ConvexHull's interface.

    ``from ridt import ConvexHull`` in place of ``from scipy.spatial import ConvexHull`` gives
    the same attributes with the same shapes and dtypes, for points in two dimensions; every
    decision is an exact orientation test, so a point on a side is never a corner and copies of
    a point count once (its least index stands for them).

    Parameters
    ----------
    points : array_like, shape (npoints, 2)
        Coordinates, any real dtype and layout, all finite.
    incremental : bool
        Allow add_points; the hull always equals a fresh one of all the points.
    qhull_options : str, optional
        ``QGn`` / ``QG-n``: the hull of every point but point n, and ``good`` marks the sides
        point n sees (strictly beyond them) or does not see. ``Qc``: ``coplanar`` lists the
        points on the boundary that are not corners. Qhull's options of robustness (Qbb, Qt,
        Qz, ...) are accepted and change nothing; any other raises ValueError.
    threads : int
        Threads for the cull of the points inside (0 or -1: every core).

    Attributes
    ----------
    points : (npoints, 2) float64
    vertices : (nvertices,) intc, the corners counter-clockwise, from the least point (by x,
        then y)
    simplices : (nfacet, 2) intc, the sides, each (corner k, corner k + 1): counter-clockwise
    neighbors : (nfacet, 2) intc, the side across from each end: [k + 1, k - 1]
    equations : (nfacet, 3) float64, each side's outward unit normal and offset: a point x lies
        inside where normal . x + offset <= 0 (within rounding; the corners are exact)
    coplanar : (ncoplanar, 3) intc, with Qc: each point on the boundary that is not a corner,
        the side it lies on and the nearer end of that side; else empty
    good : (nfacet,) bool or None, with QGn / QG-n
    area : float, the perimeter; volume : float, the area enclosed (both within a few units in
        the last place)
    min_bound, max_bound : (2,) float64, the points' bounding box

    Raises DegenerateInputError (a RuntimeError) where the points have fewer than three
    distinct, or all lie on a line, as scipy raises QhullError.
    """

    def __init__(self, points: Any, incremental: bool = False, qhull_options: Optional[str] = None,
                 threads: int = 0) -> None:
        _refuse_masked(points)
        self._coplanar_wanted, self._good = _options(qhull_options, bool(incremental))
        self._points = _api.as_points(points, "points", "ridt.ConvexHull")
        self._threads = _api.thread_count(threads)
        self._incremental = bool(incremental)
        self._run()

    def _run(self) -> None:
        pts = self._points
        if self._good is not None:  # the hull of every point but n
            n = self._good[0]
            if n >= len(pts):
                raise ValueError(f"qhull_options QG{n}: there is no point {n} ({len(pts)} points)")
            index = np.flatnonzero(np.arange(len(pts)) != n)
            pts = np.ascontiguousarray(pts[index])
        corners, on, side, volume, area = _core.convex_hull(pts, self._coplanar_wanted, self._threads)
        if len(corners) == 0:
            raise DegenerateInputError(f"ridt.ConvexHull: the {len(pts)} points have no convex hull in the plane "
                                       "(fewer than three distinct, or all collinear)")
        corners = corners.astype(np.intc)
        on = on.astype(np.intc)
        side = side.astype(np.intc)
        if self._good is not None:  # back to the indices of all the points
            corners, on = index[corners].astype(np.intc), index[on].astype(np.intc)
        h = len(corners)
        self.vertices = corners
        self.simplices = np.stack([corners, np.roll(corners, -1)], axis=1).astype(np.intc)
        k = np.arange(h, dtype=np.intc)
        self.neighbors = np.stack([(k + 1) % h, (k - 1) % h], axis=1).astype(np.intc)
        a, b = self._points[self.simplices[:, 0]], self._points[self.simplices[:, 1]]
        d = b - a
        length = np.hypot(d[:, 0], d[:, 1])
        normal = np.stack([d[:, 1] / length, -d[:, 0] / length], axis=1)
        offset = -(normal[:, 0] * a[:, 0] + normal[:, 1] * a[:, 1])
        self.equations = np.column_stack([normal, offset])
        if self._coplanar_wanted:
            ends = self.simplices[side]
            p = self._points[on]
            da = ((self._points[ends[:, 0]] - p) ** 2).sum(axis=1)
            db = ((self._points[ends[:, 1]] - p) ** 2).sum(axis=1)
            nearest = np.where(db < da, ends[:, 1], ends[:, 0])
            self.coplanar = np.column_stack([on, side, nearest]).astype(np.intc)
        else:
            self.coplanar = np.empty((0, 3), dtype=np.intc)
        self.good = None
        if self._good is not None:
            visible = np.asarray(_core.sees(self._points, self.simplices.astype(np.uint32), n), dtype=bool)
            self.good = visible if self._good[1] else ~visible
        self.area = float(area)
        self.volume = float(volume)

    @property
    def nsimplex(self) -> int:
        return int(self.simplices.shape[0])

    def add_points(self, points: Any, restart: bool = False) -> None:
        """Adds points to a hull made with ``incremental=True``; the hull is then that of all
        the points (``restart`` changes nothing: the hull is unique)."""
        if not self._incremental:
            raise RuntimeError("incremental mode not enabled or already closed")
        _refuse_masked(points)
        more = _api.as_points(points, "points", "ridt.ConvexHull.add_points")
        self._points = np.ascontiguousarray(np.concatenate([self._points, more]))
        self._run()

    def close(self) -> None:
        """Ends incremental mode: add_points then raises RuntimeError."""
        self._incremental = False

    def __repr__(self) -> str:
        return f"<ridt.ConvexHull: {self.npoints} points, {len(self.vertices)} corners>"
