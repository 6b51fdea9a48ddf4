"""The constrained Delaunay triangulation: points in the plane and segments between them."""

from __future__ import annotations

from functools import cached_property
from typing import Any, Tuple

import numpy as np

from . import _api, _core
from ._delaunay import hull_edges


class ConstrainedDelaunay:
    """The constrained Delaunay triangulation of `points` with `segments`, in scipy's style.

    Every segment (a row of two point indices) is a union of triangle edges, split at the points
    that lie exactly on it; every other edge is Delaunay, so no triangle's circle holds a point
    that the triangle can see without crossing a segment. The boundary is the convex hull.
    Exact predicates throughout; with the whole convex hull kept, the result passes
    ``ridt.check(points, simplices, segments=segments)``. Duplicate points are left out (a segment's end that is one stands for
    the point kept). Two segments that cross at a point that is not one of the points raise
    ValueError (splitting them is not supported yet).

    Parameters
    ----------
    points : array_like, shape (npoints, 2)
    segments : array_like of int, shape (nsegments, 2)
    holes : array_like, shape (nholes, 2), optional
        Seeds of holes: the triangle holding each, and all reached from it without crossing a
        segment, are removed (Triangle's convention).
    convex_hull : bool
        True (the default) keeps every triangle of the convex hull; False removes those reached
        from the hull without crossing a segment, leaving what the segments enclose.
    method, threads, seed
        As for ridt.triangulate (the Delaunay triangulation the segments are inserted into).

    Attributes
    ----------
    points : ndarray of double, shape (npoints, 2)
    segments : ndarray of intc, shape (nsegments, 2)
    simplices : ndarray of intc, shape (nsimplex, 3)
        The triangles, counter-clockwise, in canonical order.
    neighbors : ndarray of intc, shape (nsimplex, 3)
        The k-th neighbour lies across from the k-th vertex; -1 on the hull.
    edges : ndarray of intc, shape (nedges, 2)
        The segments' pieces: the edges that make up the segments, (a, b) with a < b, sorted.
    convex_hull : ndarray of intc, shape (nhull, 2)
        The hull's edges; empty where triangles were removed (the boundary is then where
        neighbors is -1).
    npoints, nsimplex, ndim
    """

    def __init__(self, points: Any, segments: Any, *, holes: Any = None, convex_hull: bool = True,
                 method: str = "auto", threads: int = 1, seed: int = 1):
        self._points = _api.as_points(points, "points", "ridt.ConstrainedDelaunay")
        segs = _api.as_segments(segments)
        if segs.size and segs.max() >= self._points.shape[0]:
            bad = int(np.flatnonzero((segs >= self._points.shape[0]).any(axis=1))[0])
            raise ValueError(f"segments[{bad}] = {segs[bad].tolist()}: every end must be one of the "
                             f"{self._points.shape[0]} points")
        seeds = np.zeros((0, 2)) if holes is None or np.size(holes) == 0 else _api.as_points(holes, "holes")
        method = _api._choice(method, "method", _api.METHODS)
        tri, edges = _core.triangulate_constrained(self._points, segs, seeds, bool(convex_hull), method,
                                                   _api.thread_count(threads), int(seed), True)
        self._tri = tri
        self.segments = segs.view(np.intc)
        self.edges = edges.view(np.intc)

    @property
    def points(self) -> np.ndarray:
        return self._points

    @property
    def simplices(self) -> np.ndarray:
        return self._tri.triangles.view(np.intc)

    @property
    def neighbors(self) -> np.ndarray:
        return self._tri.neighbors.view(np.intc)

    @property
    def npoints(self) -> int:
        return int(self._points.shape[0])

    @property
    def nsimplex(self) -> int:
        return len(self._tri)

    @property
    def ndim(self) -> int:
        return 2

    @cached_property
    def convex_hull(self) -> np.ndarray:
        return hull_edges(self._tri)

    @property
    def triangulation(self) -> _core.Triangulation:
        """ridt's own result (triangles, neighbors, hull, duplicates, warning, stats)."""
        return self._tri

    def check(self) -> Tuple[bool, str]:
        """ridt.check of these triangles with these segments: (valid, message)."""
        return _api.check(self._points, self.simplices, segments=self.segments)
