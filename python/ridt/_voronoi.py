"""The Voronoi diagram with scipy.spatial.Voronoi's interface, the dual of ridt's exact
triangulation: cocircular points merged into one vertex, as Qhull does."""

from __future__ import annotations

from functools import cached_property
from typing import Any, Dict, List, Optional, Tuple

import numpy as np

from . import _api, _core
from ._delaunay import _check_qhull_options, _qhull_flags, _refuse_joggled_copies, _refuse_masked

def ray_directions(points: np.ndarray, hull_edges: np.ndarray) -> np.ndarray:
    """The direction of the ray that bisects each hull edge (a, b), as the diagram lists its
    points (counter-clockwise about the hull, which lies on the edge's left): the edge turned a
    quarter clockwise, outward, as long as the edge."""
    a, b = points[hull_edges[:, 0]], points[hull_edges[:, 1]]
    return np.stack([b[:, 1] - a[:, 1], a[:, 0] - b[:, 0]], axis=1)


class Voronoi(_api.PlanarPoints):
    """Voronoi diagram in the plane, with scipy.spatial.Voronoi's attributes.

    The diagram is the dual of ridt's exact Delaunay triangulation: each vertex is the
    circumcentre of its triangles, each Delaunay edge gives a ridge, each distinct point a
    region. Where four or more points are cocircular (a grid), their triangles share one
    vertex, as Qhull merges them (the exact in-circle test decides): no two vertices are equal,
    and the edges between such triangles give no ridge, so none has length zero. Duplicate
    points share the region of the point kept. Fewer than three distinct points, or
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
        As for :class:`ridt.Delaunay`: only Qhull's robustness options, accepted and ignored,
        but for Qz (scipy's default, not in incremental mode nor for the farthest-point
        diagram): region 0 is then the empty region of Qhull's point at infinity.
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
        _check_qhull_options(qhull_options, bool(incremental))
        self._incremental = bool(incremental)
        _refuse_masked(points)
        # scipy's default is "Qbb Qc Qz" ("Qc" in incremental mode): Qz adds a point at infinity
        # to Qhull's input, which shows as one more region, empty, that no point owns (not in the
        # farthest-point diagram, where Qhull ignores Qz).
        at_infinity = "Qz" in _qhull_flags(qhull_options, bool(incremental), bool(furthest_site))
        self.furthest_site = bool(furthest_site)
        self._build(_api.as_points(points, "points", "ridt.Voronoi"), _api.thread_count(threads), at_infinity)
        self._qhull_options = qhull_options
        _refuse_joggled_copies(qhull_options, self._tri, "ridt.Voronoi")

    def _build(self, points: np.ndarray, threads: int, at_infinity: bool,
               tri: Optional[_core.Triangulation] = None) -> None:
        self._points, self._threads, self._at_infinity = points, threads, at_infinity
        self._tri = tri if tri is not None else _api.run(points, method="auto", threads=threads, order="brio",
                                                         locate="auto", seed=1, progress=None,
                                                         furthest_site=self.furthest_site)
        if self._tri.warning:
            raise _core.InputError(f"ridt.Voronoi: {self._tri.warning}: no Voronoi vertex")
        self._adopt(_core.voronoi(points, self._tri, threads), at_infinity)

    def _adopt(self, diagram: tuple, at_infinity: bool) -> None:
        # _core.voronoi's (or _core.power_diagram's) arrays made scipy's attributes.
        self.vertices, offsets, self._cell_vertices, point_cell, ridges = diagram
        ridge_points, self._ridge_vertices = ridges[:, :2], ridges[:, 2:]  # views, no copy
        # The points with no region of the farthest-point diagram (those inside the hull) or of
        # the power diagram (those hidden) get an empty one each, as in scipy; with Qz, region 0 is the point at infinity's, empty.
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
        _refuse_joggled_copies(getattr(self, "_qhull_options", None), self._tri, "ridt.Voronoi.add_points")

    def close(self) -> None:
        """Ends incremental mode (scipy's): add_points then raises RuntimeError."""
        self._incremental = False
        self._inc = None

    @property
    def triangulation(self) -> _core.Triangulation:
        """ridt's Delaunay triangulation of the points, whose dual the diagram is."""
        return self._tri

    @cached_property
    def _ints(self) -> List[int]:
        # The ints the lists below share, one object for each vertex.
        return list(range(len(self.vertices)))

    @cached_property
    def ridge_vertices(self) -> List[List[int]]:
        pairs = np.arange(0, 2 * len(self._ridge_vertices) + 1, 2, dtype=np.uint32)
        return _core.lists(np.ascontiguousarray(self._ridge_vertices).reshape(-1), pairs, self._ints)

    @cached_property
    def regions(self) -> List[List[int]]:
        return _core.lists(self._cell_vertices, self._offsets, self._ints)

    @cached_property
    def ridge_directions(self) -> np.ndarray:
        d = np.zeros((len(self.ridge_points), 2))
        ray = self._ridge_vertices[:, 1] < 0
        d[ray] = ray_directions(self._points, self.ridge_points[ray])
        return d

    @cached_property
    def ridge_dict(self) -> Dict[Tuple[int, int], List[int]]:
        return {(int(a), int(b)): list(uv) for (a, b), uv in zip(self.ridge_points.tolist(), self.ridge_vertices)}
