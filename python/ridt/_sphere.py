"""ridt.SphericalVoronoi: scipy.spatial.SphericalVoronoi's attributes and methods, from the exact
Delaunay triangulation on the sphere (or the exact convex polygon on a circle)."""

from __future__ import annotations

import warnings
from typing import Any, List, Optional, Tuple

import numpy as np

from . import _core


def check_sphere(points: Any, triangles: Any) -> Tuple[bool, str]:
    """(valid, message): whether `triangles` (ntriangles, 3) is exactly the convex hull of `points`
    (npoints, 3), each triangle counter-clockwise seen from outside, cocircular points decided as
    ridt decides them, every point a corner, a copy of one, or inside."""
    pts = np.ascontiguousarray(points, dtype=np.float64)
    tris = np.ascontiguousarray(triangles, dtype=np.uint32)
    valid, message, _ = _core.check_sphere(pts, tris)
    return valid, message


class SphericalVoronoi:
    """The Voronoi diagram of points on a sphere, with scipy.spatial.SphericalVoronoi's interface.

    ``from ridt import SphericalVoronoi`` in place of scipy's gives the same attributes and
    methods for points on a sphere (3-D) or a circle (2-D). The diagram is the dual of the
    points' convex hull, which ridt decides exactly: four points on one circle of the sphere
    (a cube's face, a row of a longitude-latitude grid) get one answer whatever their order in
    the input, by a symbolic perturbation, and every triangle passes an exact validator.

    Parameters
    ----------
    points : array_like, shape (npoints, 3) or (npoints, 2)
        Points on the sphere (within ``threshold * radius`` of it), all finite.
    radius : float
        The sphere's radius (1 by default).
    center : array_like, optional
        The sphere's centre (the origin by default).
    threshold : float
        As scipy's: points closer than ``threshold * radius`` to each other are duplicates, and
        farther than that from the sphere, off it (ValueError for both).
    threads : int
        Threads (0: the machine's) for sorting the points, writing the triangulation, and the
        cells and their areas; the insertion itself runs on one.

    Attributes
    ----------
    points, radius, center : as given (float64)
    vertices : ndarray, shape (nvertices, ndim)
        The Voronoi vertices: on the sphere, each equally far from the three corners of one
        triangle (the triangle's circle's centre on the sphere).
    regions : list of lists of int
        For each point, its cell's vertices, counter-clockwise seen from outside (already
        sorted: sort_vertices_of_regions changes nothing).
    triangles : ndarray of int32, shape (ntriangles, ndim)
        The Delaunay triangulation on the sphere (its triangles counter-clockwise seen from
        outside; in 2-D the circle's arcs); vertex k is triangle k's centre. Also ``_simplices``,
        as scipy names it.
    neighbors : ndarray of int32, shape (ntriangles, ndim)
        The triangle across from each corner.
    hidden : ndarray of int
        Points strictly inside the hull of the others (a rounding below the sphere among close
        neighbours): they have no cell (an empty region, area 0), and a RuntimeWarning says so.
    """

    def __init__(self, points: Any, radius: Any = 1, center: Any = None, threshold: float = 1e-06,
                 threads: int = 0) -> None:
        if radius is None:
            raise ValueError("`radius` is `None`. Please provide a floating point number (i.e. `radius=1`).")
        self.radius = float(radius)
        self.points = np.array(points, dtype=np.double)
        if self.points.ndim != 2:
            raise ValueError("points must have shape (npoints, ndim)")
        self._dim = self.points.shape[1]
        if self._dim not in (2, 3):
            raise ValueError(f"ridt.SphericalVoronoi takes points on a circle (2-D) or a sphere (3-D), "
                             f"not in {self._dim}-D")
        self.center = np.zeros(self._dim) if center is None else np.array(center, dtype=float)
        if self.center.shape != (self._dim,):
            raise ValueError(f"center must have shape ({self._dim},)")
        if not np.all(np.isfinite(self.points)) or not np.all(np.isfinite(self.center)):
            raise ValueError("points and center must be finite")
        self._threads = threads
        # scipy's tests of the input, in scipy's order and words.
        if len(self.points) == 0 or self._rank(threshold) < self._dim:
            raise ValueError(f"Rank of input points must be at least {self._dim}")
        radii = np.linalg.norm(self.points - self.center, axis=1)
        if np.abs(radii - self.radius).max() >= threshold * self.radius:
            raise ValueError("Radius inconsistent with generators.")
        if self._dim == 3:
            self._on_sphere(threshold)
        else:
            self._on_circle(threshold)
        self._regions: Optional[List[List[int]]] = None
        if len(self.hidden):
            warnings.warn(f"{len(self.hidden)} of the points lie inside the hull of the others (below the "
                          f"sphere among close neighbours) and have no cell", RuntimeWarning, stacklevel=2)

    def _rank(self, threshold: float) -> int:
        """scipy's test: the rank of the points less the first, singular values up to
        threshold * radius counted out. Where the Gram matrix's eigenvalues show the smallest
        singular value far above that (a thousandth of the largest or more, at least 10^3 times
        the tolerance), the SVD of the whole array is spared."""
        a = self.points - self.points[0]
        gram = a.T @ a
        eig = np.linalg.eigvalsh(gram)
        tol = threshold * self.radius
        if eig[-1] > 0 and eig[0] >= 1e-6 * eig[-1] and eig[0] >= (1e3 * tol) ** 2:
            return self._dim
        return int(np.linalg.matrix_rank(a, tol=tol))

    def _too_close(self, shortest: float, threshold: float, duplicates: np.ndarray) -> None:
        """ValueError where two points are copies or closer than threshold * radius (the closest
        pairs are edges of the triangulation: `shortest` is its shortest edge)."""
        if len(duplicates) or shortest < threshold * self.radius:
            raise ValueError("Duplicate generators present.")

    def _hidden_apart(self, threshold: float) -> None:
        """ValueError where a point inside the hull (so on no edge) is within threshold * radius
        of another point. Such points are rare (a rounding below the sphere): each is measured
        against every point."""
        for h in self.hidden:
            d = np.linalg.norm(self.points - self.points[h], axis=1)
            d[h] = np.inf
            if d.min() < threshold * self.radius:
                raise ValueError("Duplicate generators present.")

    def _on_sphere(self, threshold: float) -> None:
        try:
            tris, nbrs, duplicates, hidden, shortest, vertices, self._start, self._flat, areas = \
                _core.spherical_voronoi_of(self.points, self.center.reshape(1, 3), self.radius, self._threads)
        except _core.InputError as e:  # coplanar beyond the rank test's tolerance
            raise ValueError(f"Rank of input points must be at least 3 ({e})") from None
        self._too_close(shortest, threshold, duplicates)
        self.hidden = hidden.astype(np.intp)
        self._hidden_apart(threshold)
        self.vertices = vertices
        self._areas = areas
        self.triangles = tris.view(np.int32)  # (fewer than 2^31 points)
        self.neighbors = nbrs

    def _on_circle(self, threshold: float) -> None:
        corners, _, _, _, _ = _core.convex_hull(np.ascontiguousarray(self.points), False, self._threads)
        corners = corners.astype(np.intp)
        h = len(corners)
        nxt = np.roll(corners, -1)
        side = self.points[nxt] - self.points[corners]
        self._too_close(float(np.sqrt(np.einsum("ij,ij->i", side, side)).min()), threshold, np.zeros(0))
        # Copies and points inside the polygon are not corners.
        rest = np.setdiff1d(np.arange(len(self.points)), corners)
        if len(rest):  # each against the two corners either side of it round the centre
            angle = np.arctan2(*(self.points[corners] - self.center).T[::-1])
            by_angle = np.argsort(angle)
            at = np.searchsorted(angle[by_angle], np.arctan2(*(self.points[rest] - self.center).T[::-1]))
            for near in (by_angle[at % h], by_angle[(at - 1) % h]):
                gap = self.points[rest] - self.points[corners[near]]
                if np.sqrt(np.einsum("ij,ij->i", gap, gap)).min() < threshold * self.radius:
                    raise ValueError("Duplicate generators present.")
        self.hidden = rest
        self._hidden_apart(threshold)
        normal = np.stack([side[:, 1], -side[:, 0]], axis=1)  # outward: the sides run counter-clockwise
        normal /= np.linalg.norm(normal, axis=1, keepdims=True)
        self.vertices = self.center + self.radius * normal
        self.triangles = np.stack([corners, nxt], axis=1).astype(np.int32)
        k = np.arange(h)
        self.neighbors = np.stack([(k + 1) % h, (k - 1) % h], axis=1).astype(np.int32)  # across from each end
        # Cell of corner k: from side k - 1's vertex to side k's, counter-clockwise.
        counts = np.zeros(len(self.points), dtype=np.int64)
        counts[corners] = 2
        self._start = np.concatenate([[0], np.cumsum(counts)]).astype(np.uint32)
        flat = np.empty(2 * h, dtype=np.uint32)
        order = np.argsort(corners)
        pairs = np.stack([(k - 1) % h, k], axis=1)[order]
        flat[:] = pairs.ravel()
        self._flat = flat
        turn = np.arctan2(normal[(k - 1) % h, 0] * normal[k, 1] - normal[(k - 1) % h, 1] * normal[k, 0],
                          np.einsum("ij,ij->i", normal[(k - 1) % h], normal[k]))
        areas = np.zeros(len(self.points))
        areas[corners] = self.radius * np.where(turn > 0, turn, turn + 2 * np.pi)
        self._areas = areas

    @property
    def _simplices(self) -> np.ndarray:
        return self.triangles

    @property
    def regions(self) -> List[List[int]]:
        if self._regions is None:
            flat = self._flat.astype(np.intp).tolist()
            start = self._start.tolist()
            self._regions = [flat[start[i]:start[i + 1]] for i in range(len(self.points))]
        return self._regions

    @regions.setter
    def regions(self, value: List[List[int]]) -> None:
        self._regions = value

    def sort_vertices_of_regions(self) -> None:
        """The regions are made counter-clockwise round their points, seen from outside: nothing
        to do. TypeError for points that are not three-dimensional, as scipy."""
        if self._dim != 3:
            raise TypeError("Only supported for three-dimensional point sets")

    def calculate_areas(self) -> np.ndarray:
        """Each cell's area (3-D: from the solid angles of the triangles it fans into, their
        triple products taken of differences) or arc length (2-D): they sum to the sphere's area
        4 pi r^2 (the circle's length 2 pi r)."""
        return self._areas.copy()


class SphericalLinearInterpolator:
    """Piecewise-linear interpolation on the sphere, over the exact Delaunay triangulation on the
    sphere of the points (as ``SphericalVoronoi`` makes it), in the manner of scipy's
    LinearNDInterpolator.

    Parameters
    ----------
    points : array_like, shape (npoints, 3)
        The data points (on a sphere about `center`; as given, not projected).
    values : array_like, shape (npoints,) or (npoints, ...)
        The data at the points.
    center : array_like, optional
        The sphere's centre (the origin by default): queries are directions from it.
    fill_value : float
        The value where no triangle covers a query's direction (the points in one hemisphere,
        the query beyond them); NaN by default.
    threads : int
        Threads for the queries (0: the machine's).

    Calling it with ``xi`` of shape (..., 3) gives, for each query, the combination of the
    values at the corners of the triangle its direction from the centre meets, weighted by the
    barycentric coordinates of its central projection onto the triangle's plane (each within a
    relative 2^-50 of the exact ones).
    """

    def __init__(self, points: Any, values: Any, center: Any = None, fill_value: float = np.nan,
                 threads: int = 0) -> None:
        self.points = np.ascontiguousarray(points, dtype=np.float64)
        if self.points.ndim != 2 or self.points.shape[1] != 3:
            raise ValueError("points must have shape (npoints, 3)")
        values = np.asarray(values)
        if values.shape[:1] != (len(self.points),):
            raise ValueError("values must have one row a point")
        self._shape = values.shape[1:]
        self.values = np.ascontiguousarray(values.reshape(len(self.points), -1), dtype=np.float64)
        self.center = np.zeros(3) if center is None else np.asarray(center, dtype=np.float64).reshape(3)
        self.fill_value = float(fill_value)
        self._threads = threads
        if not np.all(np.isfinite(self.points)) or not np.all(np.isfinite(self.center)):
            raise ValueError("points and center must be finite")
        try:
            self.triangles, self.neighbors, _, self.hidden = _core.triangulate_sphere(self.points, threads)
        except _core.InputError as e:
            raise ValueError(str(e)) from None

    def __call__(self, xi: Any) -> np.ndarray:
        xi = np.asarray(xi, dtype=np.float64)
        if xi.shape[-1:] != (3,):
            raise ValueError("xi must have shape (..., 3): directions from the centre")
        flat = np.ascontiguousarray(xi.reshape(-1, 3))
        out = _core.interpolate_sphere(self.points, self.triangles, self.neighbors, self.values, flat,
                                       self.center.reshape(1, 3), self.fill_value, self._threads, self._natural)
        return out.reshape(xi.shape[:-1] + self._shape)

    _natural = False


class SphericalNaturalNeighborInterpolator(SphericalLinearInterpolator):
    """Natural-neighbour (Sibson) interpolation on the sphere, over the same triangulation as
    :class:`SphericalLinearInterpolator`, with the same parameters.

    Each query's weights are the areas its Voronoi cell on the sphere would take from its
    neighbours' cells were it inserted (spherical areas, the cells' vertices within a bound
    however thin their triangles): positive, summing to 1, the data at the points, continuous,
    and in a small cap the plane's Sibson coordinates. Where the query lies within rounding of a
    data point's direction, that point's value; `fill_value` beyond the points of one
    hemisphere.
    """

    _natural = True

