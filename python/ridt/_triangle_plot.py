"""ridt.triangle's drawings (the `triangle` package's ``plot``, ``compare`` and ``comparev``):
the dicts that ridt.triangle's calls take and return, drawn on matplotlib's axes. matplotlib is
imported only by these calls."""

from __future__ import annotations

from typing import Any, Dict

import numpy as np


def _rows(kw: Dict[str, Any], key: str, columns: int, dtype: Any) -> np.ndarray:
    """kw[key] as rows of `columns` (none where the key is absent or None)."""
    value = kw.get(key)
    return np.zeros((0, columns), dtype=dtype) if value is None else np.asarray(value, dtype=dtype).reshape(-1, columns)


def _lines(ax: Any, ends: np.ndarray, autolim: bool = True, **style: Any) -> None:
    """Straight lines from ends[k, 0] to ends[k, 1] ((k, 2, 2) coordinates) as one collection."""
    from matplotlib.collections import LineCollection

    if len(ends):
        ax.add_collection(LineCollection(ends, **style), autolim=autolim)


def _rays(ax: Any, vertices: np.ndarray, kw: Dict[str, Any]) -> None:
    """The rays from vertices[ray_origins[k]] along ray_directions[k], each long enough to leave
    the view, which is kept as it was before them."""
    origins = _rows(kw, "ray_origins", 1, np.int64).reshape(-1)
    directions = _rows(kw, "ray_directions", 2, np.float64)
    if len(origins) != len(directions):
        raise ValueError(f"{len(origins)} ray_origins for {len(directions)} ray_directions")
    x0, x1, y0, y1 = ax.axis()
    starts = vertices[origins]
    corners = np.array([(x0, y0), (x0, y1), (x1, y0), (x1, y1)])
    # Beyond its farthest corner a ray is outside the view; the view's diagonal more is margin.
    reach = np.linalg.norm(starts[:, None, :] - corners[None, :, :], axis=2).max(axis=1) + np.hypot(x1 - x0, y1 - y0)
    norms = np.hypot(directions[:, 0], directions[:, 1])
    keep = norms > 0
    ends = starts[keep] + directions[keep] * (reach[keep] / norms[keep])[:, None]
    _lines(ax, np.stack([starts[keep], ends], axis=1), autolim=False, colors="k", linewidths=0.5)
    ax.axis((x0, x1, y0, y1))


def _texts(ax: Any, vertices: np.ndarray, kw: Dict[str, Any]) -> None:
    """Each vertex's index ('labels') and marker ('markers') as text at it."""
    if kw.get("labels"):
        for i, (x, y) in enumerate(vertices):
            ax.text(x, y, str(i))
    if kw.get("markers"):
        if kw.get("vertex_markers") is None:
            raise ValueError("markers=True draws 'vertex_markers', which the dict lacks")
        markers = np.asarray(kw["vertex_markers"]).reshape(len(vertices), -1)
        for (x, y), m in zip(vertices, markers[:, 0]):
            ax.text(x, y, str(int(m)))


def plot(ax: Any, **kw: Any) -> None:
    """Draws a dict of ridt.triangle (the package's ``plot``) on the matplotlib Axes `ax`: its
    'vertices' as black dots; 'segments' as thick red lines beneath the rest; 'triangles' with
    ``ax.triplot`` in black (of six-node triangles, their corners); 'holes' as red x markers;
    'edges' as thin black lines between vertices, and from each of 'ray_origins' a thin black
    line along its 'ray_directions' long enough to leave the view, whose limits stay as they
    were before the rays. With ``labels=True`` each vertex's index, with ``markers=True`` its
    'vertex_markers' entry, is written at it. The aspect is equal and both axes are hidden.
    Other keys are ignored."""
    if kw.get("vertices") is None:
        raise ValueError("plot needs 'vertices'")
    ax.set_aspect("equal")
    vertices = _rows(kw, "vertices", 2, np.float64)
    ax.scatter(vertices[:, 0], vertices[:, 1], color="k")
    segments = _rows(kw, "segments", 2, np.int64)
    _lines(ax, vertices[segments], colors="r", linewidths=3, zorder=0)
    if kw.get("triangles") is not None:
        triangles = np.asarray(kw["triangles"], dtype=np.int64)
        triangles = triangles.reshape(len(triangles), -1)[:, :3] if triangles.size else triangles.reshape(0, 3)
        if len(triangles):
            ax.triplot(vertices[:, 0], vertices[:, 1], triangles, "k-")
    holes = _rows(kw, "holes", 2, np.float64)
    if len(holes):
        ax.scatter(holes[:, 0], holes[:, 1], marker="x", color="r")
    _lines(ax, vertices[_rows(kw, "edges", 2, np.int64)], colors="k", linewidths=0.5)
    _texts(ax, vertices, kw)
    ax.autoscale_view()
    if kw.get("ray_origins") is not None and kw.get("ray_directions") is not None:
        _rays(ax, vertices, kw)
    ax.get_xaxis().set_visible(False)
    ax.get_yaxis().set_visible(False)


def compare(plt: Any, A: Dict[str, Any], B: Dict[str, Any], figsize: Any = (6, 3)) -> None:
    """A new figure of pyplot `plt`, `figsize` inches, of two subplots side by side that share
    both axes: ``plot`` of `A` on the left, of `B` on the right; its layout tightened."""
    fig, (ax1, ax2) = plt.subplots(1, 2, sharex=True, sharey=True, figsize=figsize)
    plot(ax1, **A)
    plot(ax2, **B)
    fig.tight_layout()


def comparev(plt: Any, A: Dict[str, Any], B: Dict[str, Any], figsize: Any = (6, 3)) -> None:
    """``compare`` for a triangulation `A` beside its Voronoi diagram `B` (a dict of 'vertices',
    'edges', 'ray_origins', 'ray_directions'): both subplots keep `A`'s view, B's vertices and
    rays clipped to it."""
    fig, (ax1, ax2) = plt.subplots(1, 2, sharex=True, sharey=True, figsize=figsize)
    plot(ax1, **A)
    view = ax1.axis()
    plot(ax2, **B)
    ax2.axis(view)
    fig.tight_layout()
