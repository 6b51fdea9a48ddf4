"""The `triangle` package's call, on ridt: ``from ridt import triangle`` in place of ``import
triangle``.

    t = triangle.triangulate(dict(vertices=pts, segments=segs, holes=holes), "p")
    t["vertices"], t["triangles"], t["segments"]

Switches taken: ``p`` (the input is a planar straight-line graph: its segments become edges, holes
and the exterior are removed), ``q[DEG]`` (a quality mesh: no angle below DEG degrees, 20 where
no number follows), ``a[AREA]`` (no triangle larger than AREA; with no number, each region's own
bound), ``A`` (each triangle's regional attribute, as 'triangle_attributes'), ``c`` (keep the
convex hull), ``D`` (conforming Delaunay: every edge Delaunay), ``Y`` (no points added on the
boundary), ``e`` (also return every edge), ``n``
(also return the neighbours), ``z`` (indices from 0: always so here) and ``Q``/``V`` (quiet,
verbose: ignored). The others (``r``, ``S``, ``o2``, ...) are refused with ValueError.
Without ``p`` the result is the Delaunay triangulation of the vertices (refined where ``q`` or
``a`` ask). Every triangle is counter-clockwise; indices are 0-based; the points added follow the
input's in 'vertices'.
"""

from __future__ import annotations

import re
from typing import Any, Dict, Tuple

import numpy as np

from . import _api
from ._constrained import ConstrainedDelaunay

_TAKEN = set("pqaAcDYenzQV")
_NUMBER = re.compile(r"[0-9.]+(?:e[-+]?[0-9]+)?")


def _switches(opts: str) -> Tuple[set, float, float, bool]:
    """The switches without numbers, the angle (-1: none), the area (0: none) and whether the
    regions' own areas bound them."""
    flags, angle, area, regional, i = set(), -1.0, 0.0, False, 0
    while i < len(opts):
        c = opts[i]
        if c not in _TAKEN:
            raise ValueError(f"switch '{c}' is not supported (ridt takes {''.join(sorted(_TAKEN))})")
        flags.add(c)
        number = _NUMBER.match(opts, i + 1) if c in "qa" else None
        if c == "q":
            angle = float(number.group()) if number else 20.0
        elif c == "a":
            if number:
                area = float(number.group())
            else:
                regional = True
        i = number.end() if number else i + 1
    return flags, angle, area, regional


def triangulate(tri: Dict[str, Any], opts: str = "") -> Dict[str, np.ndarray]:
    """Triangulates `tri` (a dict with 'vertices' and optionally 'segments', 'holes',
    'vertex_markers', 'segment_markers', 'regions') as Triangle's switches `opts` say. Returns a dict:
    'vertices', 'triangles', and as the input and switches ask 'vertex_markers', 'segments',
    'segment_markers', 'holes', 'triangle_attributes', 'edges', 'edge_markers', 'neighbors'."""
    if not isinstance(opts, str):
        raise TypeError("opts must be a string of Triangle's switches")
    flags, angle, area, regional = _switches(opts)
    if "vertices" not in tri:
        raise ValueError("tri needs 'vertices'")
    pts = _api.as_points(tri["vertices"], "vertices", "ridt.triangle")
    pslg = "p" in flags
    segments = np.asarray(tri.get("segments", np.zeros((0, 2), dtype=np.intc))) if pslg else np.zeros((0, 2))
    holes = tri.get("holes") if pslg else None
    regions = np.asarray(tri.get("regions", np.zeros((0, 4))), dtype=float).reshape(-1, 4)
    if not regional:
        regions = np.concatenate([regions[:, :3], np.zeros((len(regions), 1))], axis=1)
    cdt = ConstrainedDelaunay(pts, segments.reshape(-1, 2) if segments.size else np.zeros((0, 2), dtype=np.intc),
                              holes=holes, convex_hull="c" in flags or not pslg, regions=regions,
                              min_angle=max(angle, 0.0), max_area=area, split_boundary="Y" not in flags,
                              conforming="D" in flags)
    out: Dict[str, np.ndarray] = {"vertices": cdt.points.copy(), "triangles": cdt.simplices.copy()}
    boundary = _boundary_edges(cdt)
    markers = np.zeros(cdt.npoints, dtype=np.intc)
    markers[boundary.ravel()] = 1
    if "vertex_markers" in tri:
        given = np.zeros(cdt.npoints, dtype=np.intc)
        given[:len(pts)] = np.asarray(tri["vertex_markers"]).reshape(-1)
        markers = np.where(given != 0, given, markers).astype(np.intc)
    out["vertex_markers"] = markers.reshape(-1, 1)
    if pslg:
        out["segments"] = cdt.edges.copy()
        out["segment_markers"] = np.ones((len(cdt.edges), 1), dtype=np.intc)
        if holes is not None:
            out["holes"] = np.asarray(holes, dtype=float).reshape(-1, 2)
    if "A" in flags and len(cdt.attributes):
        out["triangle_attributes"] = cdt.attributes.reshape(-1, 1).copy()
    if "e" in flags:
        out["edges"], out["edge_markers"] = _edges(cdt, boundary)
    if "n" in flags:
        out["neighbors"] = cdt.neighbors.copy()
    return out


def _boundary_edges(cdt: ConstrainedDelaunay) -> np.ndarray:
    """The edges with no triangle on one side, (a, b) with a < b."""
    t, n = cdt.simplices, cdt.neighbors
    rows, cols = np.nonzero(n < 0)
    a, b = t[rows, (cols + 1) % 3], t[rows, (cols + 2) % 3]
    return np.sort(np.stack([a, b], axis=1), axis=1).astype(np.intc)


def _edges(cdt: ConstrainedDelaunay, boundary: np.ndarray):
    """Every edge once, (a, b) with a < b, sorted, and 1 for those on the boundary or a segment."""
    t = cdt.simplices
    e = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    e = np.unique(np.sort(e, axis=1), axis=0).astype(np.intc)
    marked = np.concatenate([boundary, cdt.edges]) if len(cdt.edges) else boundary
    key = lambda x: x[:, 0].astype(np.int64) * (1 << 32) + x[:, 1]
    markers = np.isin(key(e), key(marked)).astype(np.intc).reshape(-1, 1)
    return e, markers
