"""The constrained Delaunay triangulation: points in the plane and segments between them."""

from __future__ import annotations

import warnings
from functools import cached_property
from typing import Any, Callable, Optional, Tuple

import numpy as np

from . import _api, _core
from ._delaunay import DegenerateInputWarning, hull_edges
from ._size import as_size_field


class RefinementWarning(RuntimeWarning):
    """Quality refinement stopped before the bounds were met (``max_steiner``, or the memory left):
    the mesh is a valid constrained triangulation, and ``check()`` then tests no bounds."""


def _callable(unsuitable: Any) -> Any:
    if unsuitable is not None and not callable(unsuitable):
        raise TypeError(f"unsuitable must be callable or None, got {type(unsuitable).__name__}")
    return unsuitable


def _check_steiner(max_steiner: Any) -> None:
    if isinstance(max_steiner, bool) or int(max_steiner) != max_steiner or max_steiner < 0:
        raise ValueError(f"max_steiner must be a whole number >= 0 (0: no limit), got {max_steiner!r}")


class ConstrainedDelaunay:
    """The constrained Delaunay triangulation of `points` with `segments`, or a quality mesh of
    it, in scipy's style.

    Every segment (a row of two point indices) is a union of triangle edges, split at the points
    that lie exactly on it; every other edge is Delaunay, so no triangle's circle holds a point
    that the triangle can see without crossing a segment. Two segments that cross are split where
    they cross: the exact crossing, rounded to the nearest doubles, is added as a point (the
    first ``ncrossings`` rows of ``added``). With `min_angle` or `max_area` (or a region's area
    bound) the triangulation is refined (Delaunay refinement with off-centres, as Triangle's
    ``-q`` and ``-a``): points are added until no triangle has an angle below `min_angle`
    degrees (at most 34) or an area above its bound, except beside input angles below 60 degrees
    between segments, which no point can mend. Exact predicates throughout; ``check()`` validates
    the result exactly. Duplicate points are left out (a segment's end that is one stands for the
    point kept).

    Parameters
    ----------
    points : array_like, shape (npoints, 2)
    segments : array_like of int, shape (nsegments, 2)
    holes : array_like, shape (nholes, 2), optional
        Seeds of holes: the triangles holding each (inside or on their boundary: a seed on a
        segment empties both sides), and all reached from them without crossing a segment, are
        removed (Triangle's convention).
    convex_hull : bool
        True (the default) keeps every triangle of the convex hull; False removes those reached
        from the hull without crossing a segment, leaving what the segments enclose.
    regions : array_like, shape (nregions, 4), optional
        Rows (x, y, attribute, max_area): every triangle reached from (x, y) without crossing a
        segment gets the attribute (``attributes``), and is refined to an area of at most
        max_area where that is > 0.
    min_angle, max_area : float
        Quality bounds (0: none).
    split_boundary : bool
        False adds no point on the boundary's segments (Triangle's ``-Y``): a triangle with an
        angle below `min_angle` may then stay where its point would fall on the boundary, and
        ``check()`` tests the area bound alone.
    split_segments : bool
        False adds no point on any segment, those inside the domain too, nor on the boundary
        (Triangle's ``-YY``): the segments stay whole (but where they cross), with the same
        consequence for the angle; not with `conforming`.
    conforming : bool
        Split segments until every edge, theirs too, is Delaunay (Triangle's ``-D``).
    unsuitable : callable, optional
        A test of your own (Triangle's ``-u``): ``unsuitable(a, b, c, area)``, with a triangle's
        corners as (x, y) tuples, counter-clockwise, and its area, returns True for a triangle to
        refine (at its off-centre, as one above `max_area` is); for a size that depends on the
        position, ``lambda a, b, c, area: area > size((a[0] + b[0] + c[0]) / 3, (a[1] + b[1] +
        c[1]) / 3)``. Called once for each triangle refinement makes or first sees; what it
        raises comes out of the call. It must hold for no triangle small enough, else refinement
        goes on until `max_steiner` (or the memory left) stops it.
    size : ridt.SizeField, number, callable or (points, values), optional
        A target edge length over the plane: no triangle's longest edge above it at its
        centroid, but where the angle bound or the input forces one. A ridt.SizeField (a grid, a
        background mesh, scattered points), a number (uniform), a vectorized function of an
        (n, 2) array of points returning n sizes (called with many points at once), or a
        `(points, values)` pair (scattered). Refines even without `min_angle`.
    method, threads, seed
        As for ridt.triangulate (the Delaunay triangulation the segments are inserted into).
        A large mesh is refined on `threads` too, tile by tile: the mesh is the same on any
        number of them (but with `unsuitable`, `size` or `max_steiner`: serially).

    Attributes
    ----------
    points : ndarray of double, shape (npoints, 2)
        Every vertex: the input's, then ``added``.
    added : ndarray of double, shape (nadded, 2)
        The points added: crossings first (``ncrossings`` of them), then refinement's.
    ninput : int
        How many of ``points`` are the input's.
    segments : ndarray of intc, shape (nsegments, 2)
    simplices : ndarray of intc, shape (nsimplex, 3)
        The triangles, counter-clockwise, in canonical order.
    neighbors : ndarray of intc, shape (nsimplex, 3)
        The k-th neighbour lies across from the k-th vertex; -1 on the boundary.
    edges : ndarray of intc, shape (nedges, 2)
        The segments' pieces (and, after refinement, the boundary's edges), (a, b) with a < b,
        sorted.
    attributes : ndarray of double, shape (nsimplex,)
        Each triangle's regional attribute; empty without regions.
    convex_hull : ndarray of intc, shape (nhull, 2)
        The hull's edges; empty where triangles were removed or refined (the boundary is then
        where neighbors is -1).
    npoints, nsimplex, ndim
    """

    def __init__(self, points: Any, segments: Any, *, holes: Any = None, convex_hull: bool = True,
                 regions: Any = None, min_angle: float = 0.0, max_area: float = 0.0,
                 split_boundary: bool = True, split_segments: bool = True, conforming: bool = False,
                 max_steiner: int = 0, unsuitable: Optional[Callable[..., Any]] = None, size: Any = None,
                 method: str = "auto", threads: int = 1, seed: int = 1):
        pts = _api.as_points(points, "points", "ridt.ConstrainedDelaunay")
        segs = _api.as_segments(segments)
        if segs.size and segs.max() >= pts.shape[0]:
            bad = int(np.flatnonzero((segs >= pts.shape[0]).any(axis=1))[0])
            raise ValueError(f"segments[{bad}] = {segs[bad].tolist()}: every end must be one of the "
                             f"{pts.shape[0]} points")
        seeds = np.zeros((0, 2)) if holes is None or np.size(holes) == 0 else _api.as_points(holes, "holes")
        zones = np.zeros((0, 4)) if regions is None or np.size(regions) == 0 else np.asarray(regions, dtype=float)
        if zones.ndim != 2 or zones.shape[1] != 4:
            raise ValueError(f"regions must have shape (nregions, 4): x, y, attribute, max_area; got {zones.shape}")
        _check_steiner(max_steiner)
        method = _api._choice(method, "method", _api.METHODS)
        result = _core.triangulate_constrained(
            pts, segs, seeds, bool(convex_hull), method, _api.thread_count(threads), int(seed), True,
            np.ascontiguousarray(zones), float(min_angle), float(max_area), bool(split_boundary),
            bool(conforming), int(max_steiner), _callable(unsuitable), bool(split_segments), as_size_field(size))
        self._take(pts, segs, seeds, result, min_angle if split_boundary and split_segments else 0.0, max_area)

    @classmethod
    def from_mesh(cls, points: Any, simplices: Any, segments: Any = None, *, min_angle: float = 0.0,
                  max_area: float = 0.0, triangle_max_area: Any = None, triangle_attributes: Any = None,
                  split_boundary: bool = True, split_segments: bool = True, conforming: bool = False,
                  max_steiner: int = 0, unsuitable: Optional[Callable[..., Any]] = None, size: Any = None,
                  threads: int = 1) -> "ConstrainedDelaunay":
        """A mesh already made, refined (Triangle's ``-r``; ridt.refine_mesh): `simplices`
        (counter-clockwise rows of three point indices) cover the domain, whose boundary and
        `segments` (each an edge of the mesh) stay fixed. The mesh is first made constrained
        Delaunay by edge flips (one that is, as this class and Triangle make, has none to make),
        then refined to `min_angle` and `max_area` and, where `triangle_max_area` is given (one
        a triangle, <= 0 none; Triangle's ``.area``), each triangle to the bound of the given
        triangle that holds its centroid; ``attributes`` are `triangle_attributes` (one a given
        triangle) by the same rule. Every point keeps its index; ``added`` are the points
        refinement added. ValueError for a triangle clockwise or without area, triangles that
        overlap about a vertex or along an edge (pieces that overlap without sharing a vertex
        are not found), a segment that is no edge, or per-triangle values not one a triangle.
        Six-column simplices are not taken: pass an ``o2`` mesh's first three columns.
        `unsuitable` and `size`: as for the class."""
        pts = _api.as_points(points, "points", "ridt.ConstrainedDelaunay.from_mesh")
        tris = np.asarray(simplices)
        if tris.ndim != 2 or tris.shape[1] != 3 or (tris.size and not np.issubdtype(tris.dtype, np.integer)):
            raise ValueError(f"simplices must be an (nsimplex, 3) array of point indices, got shape {tris.shape}")
        if tris.size and (tris.min() < 0 or tris.max() >= len(pts)):
            raise ValueError(f"simplices refer to points outside 0..{len(pts) - 1}")
        segs = _api.as_segments(np.zeros((0, 2), dtype=np.intc) if segments is None else segments)
        if segs.size and segs.max() >= len(pts):
            raise ValueError(f"segments refer to points outside 0..{len(pts) - 1}")
        _check_steiner(max_steiner)

        def per_triangle(values: Any, what: str) -> np.ndarray:
            if values is None:
                return np.zeros(0)
            v = np.asarray(values, dtype=float).reshape(-1)
            if len(v) != len(tris):
                raise ValueError(f"{what} has {len(v)} values for {len(tris)} triangles")
            return np.ascontiguousarray(v)

        result = _core.refine_mesh(
            pts, np.ascontiguousarray(tris, dtype=np.uint32), segs,
            per_triangle(triangle_max_area, "triangle_max_area"), per_triangle(triangle_attributes,
                                                                               "triangle_attributes"),
            _api.thread_count(threads), float(min_angle), float(max_area), bool(split_boundary), bool(conforming),
            int(max_steiner), _callable(unsuitable), bool(split_segments), as_size_field(size))
        self = cls.__new__(cls)
        self._take(pts, segs, np.zeros((0, 2)), result, min_angle if split_boundary and split_segments else 0.0,
                   max_area)
        return self

    def refine(self, *, min_angle: float = 0.0, max_area: float = 0.0, triangle_max_area: Any = None,
               split_boundary: bool = True, split_segments: bool = True, conforming: bool = False,
               max_steiner: int = 0, unsuitable: Optional[Callable[..., Any]] = None, size: Any = None,
               threads: int = 1) -> "ConstrainedDelaunay":
        """This mesh refined further (``from_mesh`` on its points, simplices and edges; its
        attributes carried): a new ConstrainedDelaunay. `triangle_max_area`: one bound a triangle
        of this mesh, for adaptive refinement."""
        return ConstrainedDelaunay.from_mesh(
            self._points, self.simplices, self.edges, min_angle=min_angle, max_area=max_area,
            triangle_max_area=triangle_max_area, triangle_attributes=self.attributes if len(self.attributes) else None,
            split_boundary=split_boundary, split_segments=split_segments, conforming=conforming,
            max_steiner=max_steiner, unsuitable=unsuitable, size=size, threads=threads)

    def _take(self, pts: np.ndarray, segs: np.ndarray, seeds: np.ndarray, result: tuple, min_angle: float,
              max_area: float) -> None:
        """The fields from the library's result; its warning as a Python warning."""
        tri, edges, added, crossings, attributes = result
        self._tri = tri
        if tri.warning and len(tri.triangles) == 0:  # too few distinct points, or all collinear
            warnings.warn(f"ridt: {tri.warning}: the triangulation is empty", DegenerateInputWarning, stacklevel=3)
        elif tri.warning:  # refinement stopped early (max_steiner, or the memory left): the bounds are not kept
            warnings.warn(f"ridt: {tri.warning}", RefinementWarning, stacklevel=3)
            min_angle, max_area = 0.0, 0.0
        self.ninput = int(pts.shape[0])
        self._points = np.concatenate([pts, added]) if len(added) else pts
        self.added = added
        self.ncrossings = int(crossings)
        self.attributes = attributes
        self.segments = segs.view(np.intc)
        self.edges = edges.view(np.intc)
        self._holes = seeds
        self._bounds = (float(min_angle), float(max_area))

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

    def second_order(self) -> Tuple[np.ndarray, np.ndarray]:
        """Six-node triangles for quadratic elements (Triangle's -o2): ``(points, simplices)``,
        ``points`` this triangulation's then a node at the middle of every edge (the exact mean
        of its ends, rounded once), ``simplices`` (nsimplex, 6) intc: each triangle's corners as
        in ``simplices``, then the nodes of the edges across from corners 0, 1 and 2."""
        nodes, _, six = _core.second_order(self._points, self._tri)
        return np.concatenate([self._points, nodes]), six.view(np.intc)

    def check(self) -> Tuple[bool, str]:
        """The exact validator of constrained triangulations and meshes (ridt.check_mesh): every
        edge but the segments' locally Delaunay, every segment a chain of ``edges``, the holes
        empty, the angle and area bounds kept: (valid, message)."""
        valid, message, _ = _core.check_mesh(
            self._points, np.ascontiguousarray(self.simplices, dtype=np.uint32),
            np.ascontiguousarray(self.edges, dtype=np.uint32), np.ascontiguousarray(self.segments, dtype=np.uint32),
            self.ninput, np.ascontiguousarray(self._holes, dtype=float), *self._bounds)
        return bool(valid), message
