"""Regular (weighted Delaunay) triangulations of weighted points in the plane and their power
diagrams (Laguerre cells), decided exactly."""

from __future__ import annotations

from typing import Any, Tuple

import numpy as np

from . import _api, _core
from ._voronoi import Voronoi


def _as_weights(weights: Any, n: int, what: str) -> np.ndarray:
    w = np.ascontiguousarray(np.asarray(weights, dtype=np.float64))
    if w.shape != (n,):
        raise ValueError(f"{what}: weights must have shape ({n},), one a point, not {w.shape}")
    if not np.isfinite(w).all():
        raise _core.InputError(f"{what}: the weight of point {int(np.flatnonzero(~np.isfinite(w))[0])} is not finite")
    return w


class RegularTriangulation(_api.PlanarPoints):
    """The regular triangulation of points with weights: the dual of their power diagram.

    Point i with weight w[i] has power |x - p[i]|^2 - w[i] at x; the triangulation is the
    projection of the lower convex hull of the points lifted to (x, y, x^2 + y^2 - w). With
    equal weights it is the Delaunay triangulation (the same triangles as :class:`ridt.Delaunay`,
    ties included); a larger weight pulls its point's triangles' circles towards it, and a point
    whose power cell is empty (its lift above the others' hull) is no vertex: it is listed in
    `hidden`. Decided by the exact power test with a symbolic perturbation, so the result is
    the same for any order of the input.

    Parameters
    ----------
    points : array_like, shape (npoints, 2)
    weights : array_like, shape (npoints,)
        Squared radii of the points' circles (any real numbers; only differences matter).
    threads : int
        Threads for the sort and the output (0 or -1: every core).

    Attributes
    ----------
    points, weights : the input, as float64 arrays
    simplices : ndarray of intc, shape (nsimplex, 3)
        Counter-clockwise triangles, as point indices.
    neighbors : ndarray of intc, shape (nsimplex, 3)
        The triangle across from each corner, -1 on the hull.
    hidden : ndarray of uint32
        The points that are no vertex because others' weights cover them, sorted.
    duplicates : ndarray of uint32, shape (ncopies, 2)
        Rows (dropped, kept): a point given again with the same weight, and the one kept.
    convex_hull : ndarray of intc, shape (nhull, 2)
        The hull's edges, counter-clockwise.

    Raises :class:`ridt.InputError` (a ValueError) where the points have no triangulation (fewer
    than three distinct, all collinear) or a coordinate or weight is not finite.
    """

    def __init__(self, points: Any, weights: Any, *, threads: int = 1) -> None:
        self._points = _api.as_points(points, "points", "ridt.RegularTriangulation")
        self._weights = _as_weights(weights, len(self._points), "ridt.RegularTriangulation")
        self._threads = _api.thread_count(threads)
        self._tri, self.hidden = _core.triangulate_regular(self._points, self._weights, self._threads)
        self.simplices = self._tri.triangles.astype(np.intc)
        self.neighbors = self._tri.neighbors.astype(np.intc)

    @property
    def weights(self) -> np.ndarray:
        return self._weights

    @property
    def duplicates(self) -> np.ndarray:
        return self._tri.duplicates

    @property
    def convex_hull(self) -> np.ndarray:
        h = self._tri.hull.astype(np.intc)
        return np.stack([h, np.roll(h, -1)], axis=1)

    @property
    def triangulation(self) -> _core.Triangulation:
        """The library's arrays (views of its buffers)."""
        return self._tri

    def power_diagram(self) -> "PowerDiagram":
        """The power diagram of the points, from this triangulation."""
        return PowerDiagram(self._points, self._weights, threads=self._threads, _regular=self)

    def check(self) -> Tuple[bool, str]:
        """The exact validator's verdict (ridt::check_regular): (valid, message)."""
        valid, message, _ = _core.check_regular(self._points, self._weights, self._tri.triangles)
        return bool(valid), message

    def __len__(self) -> int:
        return len(self.simplices)

    def __repr__(self) -> str:
        return f"<ridt.RegularTriangulation: {self.npoints} points, {len(self)} triangles, {len(self.hidden)} hidden>"


class PowerDiagram(Voronoi):
    """The power diagram (Laguerre cells) of weighted points, with scipy.spatial.Voronoi's
    attributes: cell i holds the places where point i has the least power |x - p[i]|^2 - w[i].

    Its vertices are the power centres of the regular triangulation's triangles (each
    coordinate within 2^-44 of its distance from a corner and a unit in its last place of the
    exact one), its ridges the triangulation's edges (-1 for the end of a ray, at infinity;
    `ridge_directions` gives each ray's direction), its regions the centres round each point,
    counter-clockwise. A hidden point has an empty region. With equal weights it is the Voronoi
    diagram (not merged: four cocircular points give two vertices at one place).

    Parameters
    ----------
    points : array_like, shape (npoints, 2)
    weights : array_like, shape (npoints,)
    threads : int

    Attributes
    ----------
    points, weights, vertices, ridge_points, ridge_vertices, ridge_directions, regions,
    point_region, ridge_dict : as :class:`ridt.Voronoi`
    hidden : the points with an empty cell
    triangulation : the :class:`ridt.RegularTriangulation` it is the dual of
    """

    def __init__(self, points: Any, weights: Any, *, threads: int = 1, _regular: Any = None) -> None:
        self.furthest_site = False
        self._incremental = False
        self._regular = _regular if _regular is not None else RegularTriangulation(points, weights, threads=threads)
        self._weights = self._regular.weights
        self._points, self._threads, self._at_infinity = self._regular.points, self._regular._threads, False
        self._tri = self._regular.triangulation
        self._adopt(_core.power_diagram(self._points, self._weights, self._tri, self._threads), False)

    @property
    def weights(self) -> np.ndarray:
        return self._weights

    @property
    def hidden(self) -> np.ndarray:
        return self._regular.hidden

    @property
    def triangulation(self) -> RegularTriangulation:  # type: ignore[override]
        return self._regular

    def __getstate__(self) -> dict:
        return {"points": self._points, "weights": self._weights, "threads": self._threads}

    def __setstate__(self, state: dict) -> None:
        self.__init__(state["points"], state["weights"], threads=state["threads"])  # type: ignore[misc]

    def add_points(self, points: Any, restart: bool = False) -> None:
        raise RuntimeError("ridt.PowerDiagram has no incremental mode: build one of all the points")

    def __repr__(self) -> str:
        return f"<ridt.PowerDiagram: {self.npoints} points, {len(self.vertices)} vertices, {len(self.hidden)} hidden>"
