"""The `triangle` package's call, on ridt: ``from ridt import triangle`` in place of ``import
triangle``.

    t = triangle.triangulate(dict(vertices=pts, segments=segs, holes=holes), "p")
    t["vertices"], t["triangles"], t["segments"]

Triangle's switches and rules are the library's (``ridt::triangle``, shared with ``ridt mesh``):
``p`` (the input is a planar straight-line graph: its segments become edges, holes and the
exterior are removed), ``q[DEG]`` (a quality mesh: no angle below DEG degrees, 20 where no
number follows), ``a[AREA]`` (no triangle larger than AREA; with no number, each region's own
bound), ``A`` (each triangle's regional attribute, as 'triangle_attributes'), ``c`` (keep the
convex hull), ``D`` (conforming Delaunay: every edge Delaunay), ``Y`` (no points added on the
boundary; ``YY``, none on the segments inside it either), ``S[N]`` (at most N points added by
refinement, then a ``ridt.RefinementWarning``; ``S0``, none), ``e`` (also return every edge),
``n`` (also return the neighbours), ``o2`` (six-node triangles: a node at the middle of every
edge, after the vertices; each triangle its corners, then the nodes of the edges across from
them), ``O`` (the holes ignored), ``B`` (no markers in the result), ``j`` (the vertices of no
triangle left out, the rest numbered in order), ``C`` (the result checked exactly:
RuntimeError where it fails), ``v`` (also return the mesh's dual, as Triangle's ``-v`` writes
it: 'voronoi_vertices', row t the circumcentre of triangle t; 'voronoi_edges', pairs of them
across the mesh's inner edges; 'voronoi_ray_origins' and 'voronoi_ray_directions', a ray from a
vertex across each boundary edge, along its outward normal; with 'vertex_attributes',
'voronoi_attributes', theirs at each centre), ``r`` (the mesh in 'triangles' refined: its
boundary, and with ``p`` its 'segments', kept; with ``a`` and no number each triangle to its
'triangle_max_area'; its 'triangle_attributes' carried; ``c`` has no effect there). ``z``,
``Q``, ``V``, ``i``, ``F``, ``l``, ``X``, ``I`` and the file switches ``N``, ``E``, ``P``, ``g``
are taken and change nothing here; ``u`` and ``s`` are refused with ValueError. Without ``p``
the result is the Delaunay triangulation of the vertices (refined where ``q`` or ``a`` ask).
Every triangle is counter-clockwise; indices are 0-based; the points added follow the input's in
'vertices'. Markers, the attributes of the points added and each piece's segment come from the
library, which knows which input segment each piece lies on.

The package's other calls are here too: ``delaunay(pts)`` (its triangles), ``convex_hull(pts)``
(the hull's edges) and ``voronoi(pts)`` (the diagram's vertices, edges and rays).
"""

from __future__ import annotations

import warnings
from typing import Any, Dict, Tuple

import numpy as np

from . import _api, _core
from ._constrained import RefinementWarning
from ._delaunay import DegenerateInputWarning, hull_edges
from ._voronoi import ray_directions


def _array(tri: Dict[str, Any], key: str, dtype: Any, columns: int = 0) -> np.ndarray:
    """tri[key] as a C-ordered array of `dtype` (empty where absent), `columns` wide where given."""
    a = np.ascontiguousarray(tri[key] if key in tri and tri[key] is not None else np.zeros(0), dtype=dtype)
    return a.reshape(-1, columns) if columns else a.reshape(-1)


def triangulate(tri: Dict[str, Any], opts: str = "") -> Dict[str, np.ndarray]:
    """Triangulates `tri` (a dict with 'vertices' and optionally 'segments', 'holes',
    'vertex_markers', 'segment_markers', 'vertex_attributes', 'regions', and with ``r``
    'triangles', 'triangle_attributes', 'triangle_max_area') as Triangle's switches `opts` say.
    Returns a dict: 'vertices', 'triangles', and as the input and switches ask 'vertex_markers',
    'vertex_attributes', 'segments', 'segment_markers', 'holes', 'triangle_attributes', 'edges',
    'edge_markers', 'neighbors' and the dual's keys (``v``).

    Markers follow Triangle's rules: a segment's pieces keep its marker where it is nonzero, and
    other segments and edges get 1 on the boundary (holes' too), 0 inside; a vertex keeps its
    input marker where nonzero, else takes that of the last marked segment it ends a piece of,
    else 1 on the boundary, 0 inside. 'vertex_attributes' pass through to the output's vertices,
    those of the points added (crossings, 'q', 'a') interpolated linearly over the Delaunay
    triangulation of the input's points."""
    if not isinstance(opts, str):
        raise TypeError("opts must be a string of Triangle's switches")
    if "vertices" not in tri:
        raise ValueError("tri needs 'vertices'")
    pts = _api.as_points(tri["vertices"], "vertices", "ridt.triangle")
    attributes = np.asarray(tri.get("vertex_attributes", np.zeros((len(pts), 0))), dtype=np.float64)
    attributes = attributes.reshape(-1, 1) if attributes.ndim == 1 else attributes.reshape(len(attributes), -1)
    if len(attributes) != len(pts):
        raise ValueError(f"vertex_attributes has {len(attributes)} rows for {len(pts)} vertices")
    triangles = _array(tri, "triangles", np.int64)
    if triangles.size and np.asarray(tri["triangles"]).ndim == 2 and np.asarray(tri["triangles"]).shape[1] == 6:
        triangles = np.asarray(tri["triangles"])[:, :3].reshape(-1)  # six-node triangles ('o2'): their corners
    if triangles.size and (triangles.min() < 0 or triangles.max() >= len(pts)):
        raise ValueError(f"triangles refer to vertices outside 0 .. {len(pts) - 1}")
    segments = _array(tri, "segments", np.int64)
    if segments.size and (segments.min() < 0 or segments.max() >= len(pts)):
        raise ValueError(f"segments refer to vertices outside 0 .. {len(pts) - 1}")
    given = _array(tri, "triangle_attributes", np.float64)
    first = given.reshape(len(triangles) // 3, -1)[:, 0] if given.size and len(triangles) else given
    out = _core.triangle_triangulate(
        pts, _array(tri, "vertex_markers", np.int64), np.ascontiguousarray(attributes).reshape(-1),
        segments.astype(np.uint32),
        _array(tri, "segment_markers", np.int64), _array(tri, "holes", np.float64, 2),
        _array(tri, "regions", np.float64, 4), triangles.astype(np.uint32), np.ascontiguousarray(first),
        _array(tri, "triangle_max_area", np.float64), opts, 1, tri.get("holes") is not None)
    warning = out.pop("_warning")
    if warning:
        warnings.warn(f"ridt: {warning}", RefinementWarning, stacklevel=2)
    if "vertex_attributes" in out and np.ndim(tri.get("vertex_attributes")) == 1:
        out["vertex_attributes"] = out["vertex_attributes"].reshape(-1, 1)
    return out


def _plain(pts: Any, what: str) -> Tuple[np.ndarray, _core.Triangulation]:
    """The points checked and their Delaunay triangulation; a DegenerateInputWarning where it is
    empty."""
    points = _api.as_points(pts, "pts", what)
    tri = _api.run(points)
    if tri.warning:
        warnings.warn(f"{what}: {tri.warning}: the triangulation is empty", DegenerateInputWarning, stacklevel=3)
    return points, tri


def delaunay(pts: Any) -> np.ndarray:
    """The Delaunay triangulation of `pts` (the package's ``delaunay``: Triangle's ``Qz``), an
    (M, 3) intc array of vertex indices, each triangle counter-clockwise. Exact: ties among
    cocircular points are broken by a fixed symbolic perturbation. Of equal points the first
    stands for them; the others are in no triangle. Fewer than three distinct points, or all on
    a line: no triangle, with a ``ridt.DegenerateInputWarning``."""
    _, tri = _plain(pts, "ridt.triangle.delaunay")
    return tri.triangles.view(np.intc).reshape(-1, 3).copy()


def convex_hull(pts: Any) -> np.ndarray:
    """The convex hull's edges (the package's ``convex_hull``: the segments Triangle's ``Qzc``
    gives), an (K, 2) intc array, each edge (a, b) with the hull on its left, in order
    counter-clockwise; points on an edge of the hull are corners of it. Degenerate input (as
    for ``delaunay``): no edge, with the warning."""
    _, tri = _plain(pts, "ridt.triangle.convex_hull")
    return hull_edges(tri).astype(np.intc)


def voronoi(pts: Any) -> Tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The Voronoi diagram of `pts` (the package's ``voronoi``): ``(points, edges, ray_origins,
    ray_directions)``. ``points`` are the diagram's vertices, the circumcentres of the Delaunay
    triangles, where cocircular points' triangles share one (as ``ridt.Voronoi`` merges them: no
    edge has length zero); ``edges`` (intc pairs) join two vertices; each ray starts at the vertex
    ``ray_origins[k]`` and runs to infinity along ``ray_directions[k]``, the outward normal of
    the hull edge it bisects, as long as that edge. Degenerate input (as for ``delaunay``):
    every array empty, with the warning."""
    points, tri = _plain(pts, "ridt.triangle.voronoi")
    return _diagram(points, tri, True)


def _diagram(points: np.ndarray, tri: Any, merge: bool) -> Tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The dual of triangulation `tri` of `points` as ``voronoi`` returns it: vertices (with
    `merge`, cocircular triangles' one), edges, ray origins and ray directions."""
    if len(tri.triangles) == 0:
        return (np.empty((0, 2)), np.empty((0, 2), dtype=np.intc), np.empty(0, dtype=np.intc), np.empty((0, 2)))
    vertices, _, _, _, ridge_points, ridge_vertices = _core.voronoi(points, tri, 1, merge)
    ridge_points, ridge_vertices = ridge_points.view(np.intc), ridge_vertices.view(np.intc)
    ray = ridge_vertices[:, 1] < 0
    return (vertices, ridge_vertices[~ray].copy(), ridge_vertices[ray, 0].copy(),
            ray_directions(points, ridge_points[ray]))
