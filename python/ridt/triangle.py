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
(the hull's edges) and ``voronoi(pts)`` (the diagram's vertices, edges and rays); ``loads`` and
``load`` (Triangle's files read into such a dict), ``get_data``, ``get_data_dir`` and
``show_data`` (Triangle's sample files, from a directory the user names: ridt ships none), and
``plot``, ``compare`` and ``comparev`` (the dicts drawn with matplotlib).
"""

from __future__ import annotations

import os
import warnings
from typing import Any, Dict, Optional, Tuple

import numpy as np

from . import _api, _core
from ._constrained import RefinementWarning
from ._delaunay import DegenerateInputWarning, hull_edges
from ._triangle_plot import compare, comparev, plot
from ._voronoi import ray_directions

__all__ = ["triangulate", "delaunay", "convex_hull", "voronoi", "loads", "load", "get_data", "get_data_dir",
           "show_data", "plot", "compare", "comparev", "data_dir"]

#: The directory that ``get_data`` reads Triangle's sample files from where the environment
#: variable RIDT_TRIANGLE_DATA is not set (None: none).
data_dir: Optional[str] = None

_EXTENSIONS = ("node", "ele", "poly", "area", "edge", "neigh")


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
    vertices, _, _, _, ridges = _core.voronoi(points, tri, 1, merge)
    ridge_points, ridge_vertices = ridges[:, :2].view(np.intc), ridges[:, 2:].view(np.intc)
    ray = ridge_vertices[:, 1] < 0
    return (vertices, ridge_vertices[~ray].copy(), ridge_vertices[ray, 0].copy(),
            ray_directions(points, ridge_points[ray]))


def _text(value: Any, ext: str) -> str:
    """A file's text as loads takes it: a str, or bytes as UTF-8."""
    if isinstance(value, (bytes, bytearray)):
        return bytes(value).decode("utf-8")
    if not isinstance(value, str):
        raise TypeError(f"{ext} must be the text of a .{ext} file (str), not {type(value).__name__}")
    return value


def _read(texts: Dict[str, Any], names: Dict[str, str]) -> Dict[str, np.ndarray]:
    """The files' texts (those not empty) read by ``_core.triangle_files``."""
    given = {ext: _text(value, ext) for ext, value in texts.items() if value}
    return _core.triangle_files(given, {ext: names[ext] for ext in given})


def loads(node: Optional[str] = None, ele: Optional[str] = None, poly: Optional[str] = None,
          area: Optional[str] = None, edge: Optional[str] = None, neigh: Optional[str] = None) -> Dict[str, np.ndarray]:
    """The dict of Triangle's files given as text (the package's ``loads``): each argument the
    content of a .node, .ele, .poly, .area, .edge or .neigh file, or None (an empty text is none).
    '#' starts a comment. Malformed text raises ValueError with the reader's message.

    Keys, each where its file has at least one row: from .node (or a .poly that lists its own
    vertices, which replace the .node's) 'vertices' (float64, n x 2), 'vertex_attributes'
    (float64, n x k, where the header declares k > 0) and 'vertex_markers' (intc, n x 1, where it
    declares markers); from .poly 'segments' (intc, s x 2), 'segment_markers' (intc, s x 1, where
    declared), 'holes' (float64, h x 2) and 'regions' (float64, r x 4: x, y, attribute,
    max_area, max_area -1 where a line has none); from .ele 'triangles' (intc, m x 3, or m x 6:
    each triangle's corners, then the middles of the edges across from them) and
    'triangle_attributes' (float64, m x k); from .area 'triangle_max_area' (float64, m x 1); from
    .edge 'edges' (intc, e x 2), 'edge_markers' (intc, e x 1, where declared) and, for the rays
    of a Voronoi diagram's .v.edge (lines "i a -1 dx dy"), 'ray_origins' (intc, r x 1) and
    'ray_directions' (float64, r x 2); from .neigh 'triangle_neighbors' (intc, m x 3, -1 where
    a triangle has no neighbour).

    Indices are 0-based: the vertices' first index (0 or 1) numbers the vertices that .ele,
    .poly, .edge and .neigh refer to and the triangles that .neigh refers to (0 where neither
    .node nor .poly is given; for .neigh, then, its own first index). Each file's records are
    numbered consecutively from their first, 0 or 1. A .poly that lists no vertices takes those
    of `node`. Where .ele is given, .area and .neigh must have as many triangles."""
    texts = {"node": node, "ele": ele, "poly": poly, "area": area, "edge": edge, "neigh": neigh}
    return _read(texts, {ext: f"the .{ext} text" for ext in _EXTENSIONS})


def load(directory: Any, name: str) -> Dict[str, np.ndarray]:
    """loads of the files directory/name.node, .ele, .poly, .area, .edge and .neigh, those that
    exist (the package's ``load``); ValueError messages name the file. FileNotFoundError where
    none of them exists."""
    paths = {ext: os.path.join(os.fspath(directory), f"{name}.{ext}") for ext in _EXTENSIONS}
    texts = {}
    for ext, path in paths.items():
        if os.path.isfile(path):
            with open(path, encoding="utf-8") as f:
                texts[ext] = f.read()
    if not texts:
        raise FileNotFoundError(f"no Triangle file {name}.{{{','.join(_EXTENSIONS)}}} in {os.fspath(directory)}")
    return _read(texts, paths)


def get_data_dir() -> str:
    """The directory of Triangle's sample files that ``get_data`` reads: the environment variable
    RIDT_TRIANGLE_DATA where it is set and not empty, else ``ridt.triangle.data_dir``. ridt ships
    no sample files: FileNotFoundError where neither names a directory."""
    where = os.environ.get("RIDT_TRIANGLE_DATA") or data_dir
    if not where:
        raise FileNotFoundError("ridt ships none of Triangle's sample files: name the directory that holds them with "
                                "the environment variable RIDT_TRIANGLE_DATA or ridt.triangle.data_dir")
    return os.fspath(where)


def get_data(name: str) -> Dict[str, np.ndarray]:
    """``load(get_data_dir(), name)``: the sample `name` (Triangle's 'A', 'dots', 'face', ...)
    from the directory the user names; FileNotFoundError where none is named or none of its
    files is there."""
    return load(get_data_dir(), name)


def show_data(name: str) -> None:
    """Draws ``get_data(name)`` with ``plot`` on new axes of matplotlib's pyplot and shows it."""
    import matplotlib.pyplot as plt

    plot(plt.axes(), **get_data(name))
    plt.show()
