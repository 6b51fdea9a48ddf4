"""The `triangle` package's call, on ridt: ``from ridt import triangle`` in place of ``import
triangle``.

    t = triangle.triangulate(dict(vertices=pts, segments=segs, holes=holes), "p")
    t["vertices"], t["triangles"], t["segments"]

Switches taken: ``p`` (the input is a planar straight-line graph: its segments become edges, holes
and the exterior are removed), ``q[DEG]`` (a quality mesh: no angle below DEG degrees, 20 where
no number follows), ``a[AREA]`` (no triangle larger than AREA; with no number, each region's own
bound), ``A`` (each triangle's regional attribute, as 'triangle_attributes'), ``c`` (keep the
convex hull), ``D`` (conforming Delaunay: every edge Delaunay), ``Y`` (no points added on the
boundary; ``YY``, none on the segments inside it either), ``S[N]`` (at most N
points added by refinement, then a ``ridt.RefinementWarning``; ``S0``, none), ``e`` (also return
every edge), ``n`` (also return the neighbours), ``o2`` (six-node triangles: a node at the middle
of every edge, after the vertices; each triangle its corners, then the nodes of the edges
across from them), ``O`` (the holes ignored), ``z`` (indices from 0: always so here),
``Q``/``V`` (quiet, verbose) and ``i``, ``F``, ``l``, ``X``, ``I`` (Triangle's choice of
algorithm, its exact arithmetic off, its file names: the exact result does not depend on them),
these last ignored; ``B`` (no markers in the result), ``j`` (the vertices of no triangle left out,
the rest numbered in order), ``C`` (the result checked exactly: RuntimeError where it fails),
``v`` (also return the mesh's dual, as Triangle's ``-v`` writes it: 'voronoi_vertices', row t
the circumcentre of triangle t; 'voronoi_edges', pairs of them across the mesh's inner edges;
'voronoi_ray_origins' and 'voronoi_ray_directions', a ray from a vertex across each boundary
edge, along its outward normal; with 'vertex_attributes', 'voronoi_attributes', theirs at each
centre as .v.node has them; the Voronoi diagram of the vertices where the mesh is Delaunay and
fills their hull); ``r`` refines the mesh in 'triangles' (Triangle's ``-r``: its boundary, and
with ``p`` its 'segments', kept; with ``a`` and no number each triangle to its
'triangle_max_area'; its 'triangle_attributes' carried). The others (``u``, ``s``, ``g``,
``N``, ``E``, ``P``, ...) are refused with ValueError.
Without ``p`` the result is the Delaunay triangulation of the vertices (refined where ``q`` or
``a`` ask). Every triangle is counter-clockwise; indices are 0-based; the points added follow the
input's in 'vertices'.

The package's other calls are here too: ``delaunay(pts)`` (its triangles), ``convex_hull(pts)``
(the hull's edges) and ``voronoi(pts)`` (the diagram's vertices, edges and rays).
"""

from __future__ import annotations

import re
import warnings
from typing import Any, Dict, Optional, Tuple

import numpy as np

from . import _api, _core
from ._constrained import ConstrainedDelaunay
from ._delaunay import DegenerateInputWarning, hull_edges
from ._voronoi import ray_directions

_TAKEN = set("prqaAcDYSenozOBjCvQViFlXI")
_NUMBER = re.compile(r"[0-9.]+(?:e[-+]?[0-9]+)?")


def _switches(opts: str) -> Tuple[set, float, float, bool, int]:
    """The switches without numbers, the angle (-1: none), the area (0: none), whether the
    regions' own areas bound them, and the most points refinement may add ('S': -1 none
    given)."""
    flags, angle, area, regional, steiner, i = set(), -1.0, 0.0, False, -1, 0
    while i < len(opts):
        c = opts[i]
        if c not in _TAKEN:
            raise ValueError(f"switch '{c}' is not supported (ridt takes p, r, q, a, A, c, D, Y, YY, S, e, n, o2, O, "
                             "z, B, j, C, v, Q, V; i, F, l, X, I are ignored)")
        if c == "o" and opts[i + 1:i + 2] != "2":
            raise ValueError("switch 'o' is taken as 'o2' only (six-node triangles)")
        if c == "Y" and opts[i + 1:i + 2] == "Y":  # 'YY': no point on any segment
            flags.update(("Y", "YY"))
            i += 2
            continue
        flags.add(c)
        number = _NUMBER.match(opts, i + 1) if c in "qaS" else None
        if c == "q":
            angle = float(number.group()) if number else 20.0
        elif c == "a":
            if number:
                area = float(number.group())
            else:
                regional = True
        elif c == "S":
            if not number or float(number.group()) != int(float(number.group())):
                raise ValueError("switch 'S' needs the most points refinement may add, a whole number")
            steiner = int(float(number.group()))
        i = number.end() if number else i + 2 if c == "o" else i + 1
    return flags, angle, area, regional, steiner


def triangulate(tri: Dict[str, Any], opts: str = "") -> Dict[str, np.ndarray]:
    """Triangulates `tri` (a dict with 'vertices' and optionally 'segments', 'holes',
    'vertex_markers', 'segment_markers', 'vertex_attributes', 'regions') as Triangle's switches
    `opts` say. Returns a dict: 'vertices', 'triangles', and as the input and switches ask
    'vertex_markers', 'vertex_attributes', 'segments', 'segment_markers', 'holes',
    'triangle_attributes', 'edges', 'edge_markers', 'neighbors'.

    Markers follow Triangle's rules: a segment's pieces keep its marker where it is nonzero, and
    other segments and edges get 1 on the boundary (holes' too), 0 inside; a vertex keeps its
    input marker where nonzero, else takes that of a segment it lies on with a nonzero marker,
    else 1 on the boundary, 0 inside. 'vertex_attributes' pass through to the output's
    vertices, those of the points added (crossings, 'q', 'a') interpolated linearly over the
    Delaunay triangulation of the input's points."""
    if not isinstance(opts, str):
        raise TypeError("opts must be a string of Triangle's switches")
    flags, angle, area, regional, steiner = _switches(opts)
    if steiner == 0:  # Triangle's S0: nothing refined (the crossings, which the graph needs, stay)
        angle, area, regional = -1.0, 0.0, False
    if "vertices" not in tri:
        raise ValueError("tri needs 'vertices'")
    pts = _api.as_points(tri["vertices"], "vertices", "ridt.triangle")
    pslg = "p" in flags
    segments = np.asarray(tri.get("segments", np.zeros((0, 2), dtype=np.intc))) if pslg else np.zeros((0, 2))
    holes = tri.get("holes") if pslg and "O" not in flags and "r" not in flags else None  # 'r': the mesh's own
    if "r" in flags:
        cdt = _refined(tri, pts, segments, flags, angle, area, regional, steiner)
    else:
        cdt = ConstrainedDelaunay(pts, segments.reshape(-1, 2) if segments.size else np.zeros((0, 2), dtype=np.intc),
                                  holes=holes, convex_hull="c" in flags or not pslg, conforming="D" in flags,
                                  regions=_regions(tri, regional), min_angle=max(angle, 0.0), max_area=area,
                                  max_steiner=max(steiner, 0), split_boundary="Y" not in flags,
                                  split_segments="YY" not in flags)
    out: Dict[str, np.ndarray] = {"vertices": cdt.points.copy(), "triangles": cdt.simplices.copy()}
    if "vertex_attributes" in tri:
        out["vertex_attributes"] = _vertex_attributes(tri["vertex_attributes"], pts, cdt)
    boundary = _boundary_edges(cdt)
    given = np.asarray(tri.get("segment_markers", np.zeros(len(segments))), dtype=np.intc).reshape(-1)
    if pslg and len(given) != len(segments.reshape(-1, 2)):
        raise ValueError(f"segment_markers has {len(given)} markers for {len(segments.reshape(-1, 2))} segments")
    # Each piece's marker: its segment's where that is nonzero (Triangle's rule), else 0 here.
    owner = _piece_owners(cdt.points, segments.reshape(-1, 2), cdt.edges) if given.any() else None
    pieces = np.zeros(len(cdt.edges), dtype=np.intc)
    if owner is not None:
        pieces[owner >= 0] = given[owner[owner >= 0]]
    on_boundary = np.isin(_key(cdt.edges), _key(boundary))
    out["vertex_markers"] = _vertex_markers(tri, len(pts), cdt, boundary, pieces)
    if pslg:
        out["segments"] = cdt.edges.copy()
        out["segment_markers"] = np.where(pieces != 0, pieces, on_boundary).astype(np.intc).reshape(-1, 1)
        if holes is not None:
            out["holes"] = np.asarray(holes, dtype=float).reshape(-1, 2)
    if ("A" in flags or "r" in flags) and len(cdt.attributes):
        out["triangle_attributes"] = cdt.attributes.reshape(-1, 1).copy()
    if "e" in flags:
        out["edges"], out["edge_markers"] = _edges(cdt, boundary, pieces)
    if "n" in flags:
        out["neighbors"] = cdt.neighbors.copy()
    if "o" in flags:
        _six_nodes(out, cdt, boundary, pieces)
    return _as_asked(out, cdt, flags)


def _dual(cdt: ConstrainedDelaunay, attributes: Optional[np.ndarray]) -> Dict[str, np.ndarray]:
    """'v': the mesh's dual, a vertex a triangle (cocircular neighbours not merged, so that
    vertex t stays triangle t's circumcentre, as in Triangle's .v.node), and with the vertices'
    `attributes` theirs at each centre, as Triangle writes them in .v.node: the triangle's
    linear function of its corners', extended beyond it where the centre lies outside."""
    keys = ("voronoi_vertices", "voronoi_edges", "voronoi_ray_origins", "voronoi_ray_directions")
    out = dict(zip(keys, _diagram(cdt.points, cdt._tri, False)))
    if attributes is not None:
        simplices = np.ascontiguousarray(cdt.simplices, dtype=np.int32)
        weights = _core.barycentric(cdt.points, simplices, out["voronoi_vertices"])
        out["voronoi_attributes"] = np.einsum("ti,tik->tk", weights, attributes[simplices])
    return out


def _as_asked(out: Dict[str, np.ndarray], cdt: ConstrainedDelaunay, flags: set) -> Dict[str, np.ndarray]:
    """'v': the mesh's dual; 'C': the exact check (RuntimeError where it fails); 'B': no markers;
    'j': the vertices of no triangle left out, the rest numbered in order (the triangles,
    segments and edges with them)."""
    if "v" in flags:
        out.update(_dual(cdt, out.get("vertex_attributes")))
    if "C" in flags:
        valid, message = cdt.check()
        if not valid:
            raise RuntimeError(f"ridt.triangle: the mesh fails its consistency check: {message}")
    if "B" in flags:
        for key in ("vertex_markers", "segment_markers", "edge_markers"):
            out.pop(key, None)
    if "j" in flags:
        used = np.zeros(len(out["vertices"]), dtype=bool)
        used[out["triangles"].ravel()] = True
        new = np.cumsum(used) - 1
        for key in ("vertices", "vertex_markers", "vertex_attributes"):
            if key in out:
                out[key] = out[key][used]
        for key in ("triangles", "segments", "edges"):
            if key in out:
                out[key] = new[out[key]].astype(np.intc)
    return out


def _regions(tri: Dict[str, Any], regional: bool) -> np.ndarray:
    """tri's 'regions' (x, y, attribute, max_area), their bounds dropped unless 'a' asks for them."""
    regions = np.asarray(tri.get("regions", np.zeros((0, 4))), dtype=float).reshape(-1, 4)
    return regions if regional else np.concatenate([regions[:, :3], np.zeros((len(regions), 1))], axis=1)


def _refined(tri: Dict[str, Any], pts: np.ndarray, segments: np.ndarray, flags: set, angle: float, area: float,
             regional: bool, steiner: int) -> ConstrainedDelaunay:
    """'r': the mesh in tri's 'triangles' refined (ConstrainedDelaunay.from_mesh), its boundary
    and, with 'p', tri's 'segments' kept; with 'a' and no number, each triangle to its
    'triangle_max_area'; its 'triangle_attributes' (the first column) carried."""
    if "triangles" not in tri:
        raise ValueError("switch 'r' refines a mesh: tri needs 'triangles'")
    if "c" in flags:
        raise ValueError("switch 'c' does not apply with 'r': a mesh refined keeps its own triangles' domain")
    bounds = None
    if regional:
        if "triangle_max_area" not in tri:
            raise ValueError("switches 'r' and 'a' with no number bound each triangle: tri needs 'triangle_max_area'")
        bounds = np.asarray(tri["triangle_max_area"], dtype=float).reshape(-1)
    attributes = tri.get("triangle_attributes")
    if attributes is not None:
        attributes = np.asarray(attributes, dtype=float)
        attributes = attributes.reshape(len(attributes), -1)[:, 0] if attributes.size else None
    triangles = np.asarray(tri["triangles"])
    if triangles.ndim == 2 and triangles.shape[1] == 6:  # six-node triangles ('o2'): their corners
        triangles = triangles[:, :3]
    return ConstrainedDelaunay.from_mesh(
        pts, triangles.reshape(-1, 3), segments.reshape(-1, 2) if segments.size else None,
        min_angle=max(angle, 0.0), max_area=area, triangle_max_area=bounds, triangle_attributes=attributes,
        split_boundary="Y" not in flags, split_segments="YY" not in flags, conforming="D" in flags,
        max_steiner=max(steiner, 0))


def _six_nodes(out: Dict[str, np.ndarray], cdt: ConstrainedDelaunay, boundary: np.ndarray, pieces: np.ndarray) -> None:
    """'o2': a node at the middle of every edge, after the vertices (ridt.second_order: the exact
    mean of the ends, rounded once), and each triangle's six nodes: its corners, then the nodes
    of the edges across from them. A node's marker by the vertices' rule (its segment edge's
    marker where nonzero, else 1 on the boundary, 0 inside); its attributes the mean of its
    ends', as linear interpolation along the edge gives them."""
    nodes, ends, six = _core.second_order(cdt.points, cdt.triangulation)
    keys = _key(np.sort(ends, axis=1))
    markers = np.isin(keys, _key(boundary)).astype(np.intc)
    if len(cdt.edges):  # a segment edge's node: its marker where nonzero (cdt.edges are sorted)
        at = np.minimum(np.searchsorted(_key(cdt.edges), keys), len(cdt.edges) - 1)
        given = np.where(_key(cdt.edges)[at] == keys, pieces[at], 0)
        markers = np.where(given != 0, given, markers).astype(np.intc)
    out["vertices"] = np.concatenate([out["vertices"], nodes])
    out["triangles"] = six.astype(np.intc)
    out["vertex_markers"] = np.concatenate([out["vertex_markers"], markers.reshape(-1, 1)])
    if "vertex_attributes" in out:
        a = out["vertex_attributes"]
        u, w = a[ends[:, 0]], a[ends[:, 1]]
        with np.errstate(over="ignore"):
            mean = (u + w) / 2
        mean = np.where(np.isfinite(mean), mean, u / 2 + w / 2)
        out["vertex_attributes"] = np.concatenate([a, mean])


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


def _key(e: np.ndarray) -> np.ndarray:
    """Edges (a, b) with a < b as one integer each."""
    return np.asarray(e, dtype=np.int64).reshape(-1, 2) @ np.array([1 << 32, 1], dtype=np.int64)


def _vertex_attributes(given: Any, pts: np.ndarray, cdt: ConstrainedDelaunay) -> np.ndarray:
    """The input's vertex attributes, carried to the output's vertices; those of the points
    added (crossings, 'q', 'a') interpolated linearly over the Delaunay triangulation of the
    input's points, as `ridt mesh` does (exact where the attributes are linear in the position;
    Triangle interpolates in the mesh of the moment each point is inserted, so the two differ
    where they are not), the nearest input point's a rounding outside their hull."""
    from ._interpolate import LinearNDInterpolator, NearestNDInterpolator

    a = np.asarray(given, dtype=np.float64)
    a = a.reshape(-1, 1) if a.ndim == 1 else a.reshape(len(a), -1)
    if len(a) != len(pts):
        raise ValueError(f"vertex_attributes has {len(a)} rows for {len(pts)} vertices")
    added = cdt.points[len(pts):]
    if len(added) == 0:
        return a.copy()
    at = LinearNDInterpolator(pts, a)(added).reshape(len(added), a.shape[1])
    outside = np.isnan(at).any(axis=1)
    if outside.any():
        at[outside] = NearestNDInterpolator(pts, a)(added[outside]).reshape(-1, a.shape[1])
    return np.concatenate([a, at])


def _vertex_markers(tri: Dict[str, Any], ninput: int, cdt: ConstrainedDelaunay, boundary: np.ndarray,
                    pieces: np.ndarray) -> np.ndarray:
    """Triangle's rule: the input's marker where nonzero; else that of a segment with a nonzero
    marker the vertex lies on (the last one here); else 1 on the boundary; else 0."""
    markers = np.zeros(cdt.npoints, dtype=np.intc)
    markers[boundary.ravel()] = 1
    marked = pieces != 0
    for column in (0, 1):
        markers[cdt.edges[marked, column]] = pieces[marked]
    if "vertex_markers" in tri:
        given = np.zeros(cdt.npoints, dtype=np.intc)
        given[:ninput] = np.asarray(tri["vertex_markers"]).reshape(-1)
        markers = np.where(given != 0, given, markers).astype(np.intc)
    return markers.reshape(-1, 1)


def _piece_owners(points: np.ndarray, segments: np.ndarray, pieces: np.ndarray) -> np.ndarray:
    """For each piece (a row of `pieces`, the output's segment edges), the input segment it is a
    part of, or -1 (an edge refinement keeps on the hull). Each segment's chain of pieces is
    walked from its first end: at each vertex, on along the piece that heads most nearly
    towards the other end (the points added on a segment lie on it, crossings within
    rounding). A piece of segments that overlap goes to the first."""
    owner = np.full(len(pieces), -1, dtype=np.intp)
    around: Dict[int, list] = {}
    for k, (a, b) in enumerate(pieces.tolist()):
        around.setdefault(a, []).append((b, k))
        around.setdefault(b, []).append((a, k))
    for s, (u, w) in enumerate(segments.tolist()):
        if u == w:
            continue
        direction = points[w] - points[u]
        length = float(np.hypot(*direction))
        v, reach = u, 0.0
        for _ in range(len(pieces)):
            if v == w:
                break
            best, best_cos = None, 1 - 1e-9
            for x, k in around.get(v, ()):
                step = points[x] - points[v]
                size = float(np.hypot(*step))
                cos = float(step @ direction) / (size * length) if size > 0 else -1.0
                if cos > best_cos and float((points[x] - points[u]) @ direction) / length > reach:
                    best, best_cos = (x, k), cos
            if best is None:
                break
            v, k = best
            reach = float((points[v] - points[u]) @ direction) / length
            if owner[k] < 0:
                owner[k] = s
    return owner


def _boundary_edges(cdt: ConstrainedDelaunay) -> np.ndarray:
    """The edges with no triangle on one side, (a, b) with a < b."""
    t, n = cdt.simplices, cdt.neighbors
    rows, cols = np.nonzero(n < 0)
    a, b = t[rows, (cols + 1) % 3], t[rows, (cols + 2) % 3]
    return np.sort(np.stack([a, b], axis=1), axis=1).astype(np.intc)


def _edges(cdt: ConstrainedDelaunay, boundary: np.ndarray, pieces: np.ndarray):
    """Every edge once, (a, b) with a < b, sorted, and its marker by Triangle's rule: a segment
    piece's segment's marker where nonzero; else 1 on the boundary; else 0."""
    t = cdt.simplices
    e = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    e = np.unique(np.sort(e, axis=1), axis=0).astype(np.intc)
    markers = np.isin(_key(e), _key(boundary)).astype(np.intc)
    if len(cdt.edges):
        where = np.searchsorted(_key(e), _key(cdt.edges))  # every piece is an edge
        markers[where] = np.where(pieces != 0, pieces, markers[where])
    return e, markers.reshape(-1, 1)
