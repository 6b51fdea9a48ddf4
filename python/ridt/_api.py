"""The plain calls: triangulate, check, locate, and the argument checks they share."""

from __future__ import annotations

import math
import numbers
import os
from typing import Any, Callable, Dict, Optional, Tuple, Union

import numpy as np

from . import _core

ProgressLike = Union[Callable[[float], Any], Any, None]

# Each option's names, as the library defines them.
METHODS = _core.NAMES["method"]
ORDERS = _core.NAMES["order"]
LOCATES = _core.NAMES["location"]
BOUNDINGS = _core.NAMES["bounding"]


def as_points(points: Any, name: str = "points", what: str = "ridt") -> np.ndarray:
    """`points` as a C-ordered float64 array of shape (n, 2), every coordinate finite.

    Any real dtype, memory order and stride is accepted (and copied when it is not float64 in C
    order); complex, string or object data raise TypeError, a wrong shape or a NaN or infinite
    coordinate ValueError.
    """
    try:
        a = np.asarray(points)
    except ValueError as e:  # ragged nested sequences
        raise ValueError(f"{name} must be an array of shape (n, 2): {e}") from None
    if a.dtype.kind == "O":
        try:
            a = a.astype(np.float64)
        except (TypeError, ValueError):
            raise TypeError(f"{name} must hold real numbers; got objects that are not") from None
    if a.dtype.kind not in "biuf":
        raise TypeError(f"{name} must hold real numbers, not {a.dtype}")
    if a.ndim != 2:
        raise ValueError(f"{name} must have shape (n, 2); got shape {a.shape}")
    if a.shape[1] != 2:
        raise ValueError(
            f"{what} works in the plane: {name} must have shape (n, 2), got {a.shape[1]} "
            "coordinates a point")
    a = np.ascontiguousarray(a, dtype=np.float64)
    if not np.isfinite(a).all():
        i = int(np.flatnonzero(~np.isfinite(a).all(axis=1))[0])
        raise ValueError(f"{name}[{i}] = {a[i].tolist()} is not finite: every coordinate must be a finite number")
    return a


def as_segments(segments: Any) -> np.ndarray:
    """`segments` as a C-ordered uint32 array of shape (nsegments, 2): TypeError unless they are
    integers, ValueError for another shape. Whether they name points is the caller's to say."""
    s = np.asarray(segments)
    if s.size == 0:
        return np.zeros((0, 2), dtype=np.uint32)
    if s.dtype.kind not in "iu":
        raise TypeError(f"segments must hold integers (point indices), not {s.dtype}")
    if s.ndim != 2 or s.shape[1] != 2:
        raise ValueError(f"segments must have shape (nsegments, 2); got shape {s.shape}")
    if s.min() < 0:
        raise ValueError("segments must hold point indices, not negative numbers")
    return np.ascontiguousarray(s, dtype=np.uint32)


def thread_count(threads: Any) -> int:
    """The library's thread count: 0 (or -1, scipy's `workers` convention) means every core."""
    if isinstance(threads, bool) or not isinstance(threads, numbers.Integral):
        raise TypeError(f"threads must be an integer, not {type(threads).__name__}")
    threads = int(threads)
    if threads == -1:
        return 0
    if threads < 0 or threads > _core.MAX_THREADS:
        raise ValueError(f"threads must be 1 to {_core.MAX_THREADS}, or 0 or -1 for every core; got {threads}")
    return threads


def _choice(value: Any, name: str, choices: Tuple[str, ...]) -> str:
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a string, one of {', '.join(choices)}")
    if value not in choices:
        raise ValueError(f"{name} must be one of {', '.join(repr(c) for c in choices)}; got {value!r}")
    return value


def progress_callback(progress: ProgressLike, n: int) -> Optional[Callable[[float], None]]:
    """A callable taking the share done from `progress`: a callable (given the share, 0 to 1)
    or a tqdm-like bar (anything with update(); its total, when unset, becomes the number of
    points, and it is advanced in points)."""
    if progress is None:
        return None
    if hasattr(progress, "update") and callable(progress.update):
        bar = progress
        if getattr(bar, "total", None) is None:
            bar.total = n
        total = bar.total
        done = [0]

        def advance(share: float) -> None:
            target = int(round(share * total))
            if target > done[0]:
                bar.update(target - done[0])
                done[0] = target

        return advance
    if callable(progress):
        return progress
    raise TypeError("progress must be a callable taking the share done (0 to 1) or a bar with update(), like tqdm's")


def triangulate(points: Any, *, method: str = "auto", threads: int = 1, order: str = "brio",
                locate: str = "auto", seed: int = 1, progress: ProgressLike = None,
                canonical: bool = False, bounding: str = "symbolic", k: float = 10.0,
                memory_limit: Optional[int] = None) -> _core.Triangulation:
    """The Delaunay triangulation of `points`, an (n, 2) array.

    Returns a :class:`Triangulation` whose arrays (``triangles``, ``neighbors``, ``hull``,
    ``duplicates``) are the library's own buffers, shared with numpy, not copies.

    The triangles are exactly the Delaunay triangulation of the distinct points (ties among
    cocircular points broken by a fixed symbolic perturbation), the same for every method,
    thread count, order and seed; every distinct point is a vertex and the boundary is the
    whole convex hull. Duplicates are left out and listed.

    Parameters
    ----------
    points : array_like, shape (n, 2)
        Any real dtype and memory layout; every coordinate finite.
    method : {'auto', 'serial', 'partition', 'pessimistic', 'optimistic', 'batch'}
        'auto' is 'serial' on one thread and 'partition' (threads own regions of the plane,
        no lock) on more where the order and location allow it, else 'optimistic'; the
        triangulation's ``stats['method']`` says which ran.
    threads : int
        Threads of a threaded method; 0 or -1 for every core.
    order : {'brio', 'random'}
        Insertion order: random rounds each along a Hilbert curve, or purely random (the paper's).
    locate : {'auto', 'dag', 'walk', 'root'}
        How an insertion finds its triangle: walking from the last one, or the history DAG
        (in rounds along a curve; 'root': from its root for every point, as the paper does).
    seed : int
        Seed of the random insertion order (the result does not depend on it).
    progress : callable or tqdm-like, optional
        Called with the share of points inserted (0 to 1); a bar with ``update()`` is advanced
        in points. An exception it raises abandons the run and is raised here.
    canonical : bool
        Rotate each triangle to start at its smallest vertex and sort the triangles, so the
        arrays are byte-identical for every method and seed.
    bounding, k
        'symbolic' (default) bounding vertices at infinity, or the paper's 'finite' triangle
        of size k times the points' box.
    memory_limit : int, optional
        The most bytes the call may take (default: what the system can give). A call that would
        need more (:func:`estimate_memory`) raises MemoryError before it starts, naming what it
        needs and what there is.

    The GIL is released while the library works, and Ctrl-C stops a long run with
    KeyboardInterrupt.
    """
    return run(as_points(points), method=method, threads=threads, order=order, locate=locate, seed=seed,
               progress=progress, canonical=canonical, bounding=bounding, k=k, memory_limit=memory_limit)


def run(pts: np.ndarray, *, method: str = "auto", threads: int = 1, order: str = "brio", locate: str = "auto",
        seed: int = 1, progress: ProgressLike = None, canonical: bool = False, bounding: str = "symbolic",
        k: float = 10.0, furthest_site: bool = False, memory_limit: Optional[int] = None) -> _core.Triangulation:
    """triangulate() on points that as_points() has already checked and converted."""
    method = _choice(method, "method", METHODS)
    order = _choice(order, "order", ORDERS)
    locate = _choice(locate, "locate", LOCATES)
    _choice(bounding, "bounding", BOUNDINGS)
    nthreads = thread_count(threads)
    if isinstance(seed, bool) or not isinstance(seed, numbers.Integral) or not 0 <= int(seed) < 2**64:
        raise ValueError(f"seed must be an integer from 0 to 2**64 - 1; got {seed!r}")
    if not (isinstance(k, numbers.Real) and math.isfinite(k) and k >= 2):
        raise ValueError(f"k must be a finite number of at least 2; got {k!r}")
    if pts.shape[0] >= 2**31:
        raise ValueError(f"ridt takes fewer than 2**31 points; got {pts.shape[0]}")
    limit = 0 if memory_limit is None else int(memory_limit)
    if limit < 0 or (memory_limit is not None and limit == 0):
        raise ValueError(f"memory_limit must be a positive number of bytes; got {memory_limit!r}")
    return _core.triangulate(pts, method, nthreads, order, locate,
                             int(seed), bounding, float(k), bool(canonical),
                             progress_callback(progress, pts.shape[0]), bool(furthest_site), limit)


def estimate_memory(n: int, *, method: str = "auto", threads: int = 1, order: str = "brio",
                    locate: str = "auto") -> int:
    """The most bytes :func:`triangulate` takes for `n` points with these options (its work
    space, its copy of the points and the result; not the caller's array)."""
    return _core.estimate_memory(int(n), _choice(method, "method", METHODS), thread_count(threads),
                                 _choice(order, "order", ORDERS), _choice(locate, "locate", LOCATES))


def triangulate_out_of_core(input: str, output: str, *, memory_limit: Optional[int] = None, threads: int = 0,
                            column_points: int = 0) -> Dict[str, Any]:
    """The Delaunay triangulation of a point file larger than memory (as ``ridt triangulate
    --out-of-core``): `input` a ``.bin`` file (pairs of float64 x, y), bucketed on disk into
    columns of cells, triangulated strip by strip within `memory_limit` bytes (None: a quarter
    of what is available), each strip checked exactly against the columns it did not load, so
    that the union of the strips' triangles is the triangulation of the whole set. Writes the
    parts and their index, `output` (``OUT.parts``; each part ``OUT.k-of-S.bin``, uint32 input
    indices, three a triangle from its smallest), which ``ridt check`` and the tool's readers
    take. Returns the run's counts and times. OSError where a file cannot be read or written
    (no part is left behind), ValueError for bad input or a limit too small for a strip."""
    limit = 0 if memory_limit is None else int(memory_limit)
    if memory_limit is not None and limit <= 0:
        raise ValueError(f"memory_limit must be a positive number of bytes; got {memory_limit!r}")
    return _core.triangulate_out_of_core(os.fspath(input), os.fspath(output), limit, thread_count(threads),
                                         int(column_points))


def available_memory() -> int:
    """The bytes this process can take now: MemAvailable, or less under a cgroup's limit or the
    process's limits on address space and data (``ulimit -v``, ``-d``)."""
    return _core.available_memory()


def check(points: Any, triangles: Any, furthest_site: bool = False, segments: Any = None) -> Tuple[bool, str]:
    """Checks exactly that `triangles` ((ntriangles, 3) vertex indices into `points`) is a
    Delaunay triangulation of the distinct points: counter-clockwise, not degenerate, every
    interior edge locally Delaunay, the boundary the whole convex hull, every distinct point a
    vertex. With `furthest_site`, that it is the farthest-point Delaunay triangulation (either
    orientation: scipy's clockwise triangles are turned first): every circle holds every point,
    the hull's corners its only vertices. With `segments` ((nsegments, 2) point indices), that it
    is the constrained Delaunay triangulation: every segment a union of edges (split at the
    points on it), only the other edges need be locally Delaunay. Returns (valid, message): the
    message says what was checked or the first problem.
    """
    pts = as_points(points)
    t = np.asarray(triangles)
    if t.dtype.kind not in "iu":
        raise TypeError(f"triangles must hold integers, not {t.dtype}")
    if t.ndim != 2 or t.shape[1] != 3:
        raise ValueError(f"triangles must have shape (ntriangles, 3); got shape {t.shape}")
    if t.size and (t.min() < 0 or t.max() >= pts.shape[0]):
        return False, f"a vertex index is not one of the {pts.shape[0]} points"
    t = np.ascontiguousarray(t, dtype=np.uint32)
    if furthest_site and len(t):
        p = pts[t]
        clockwise = (p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1]) < (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0])
        if clockwise.all():
            t = np.ascontiguousarray(t[:, [0, 2, 1]])
    segs = np.zeros((0, 2), dtype=np.uint32)
    if segments is not None:
        if furthest_site:
            raise ValueError("segments constrain a Delaunay triangulation, not a farthest-point one")
        segs = as_segments(segments)
        if segs.size and segs.max() >= pts.shape[0]:
            return False, f"a segment's end is not one of the {pts.shape[0]} points"
    valid, message, _ = _core.check(pts, t, bool(furthest_site), segs)
    return bool(valid), message


def check_convex_hull(points: Any, vertices: Any) -> Tuple[bool, str, int]:
    """Checks exactly that `vertices` (point indices) is the convex hull of `points`, as
    ConvexHull.vertices gives it: at least three corners, each a strict left turn, round once
    counter-clockwise, every point inside or on it; none only where the points have fewer than
    three distinct or all are collinear. Returns (valid, message, problems)."""
    pts = as_points(points)
    v = np.asarray(vertices)
    if v.size == 0:
        v = np.zeros(0, dtype=np.uint32)
    if v.dtype.kind not in "iu" or v.ndim != 1:
        raise TypeError("vertices must be a one-dimensional array of integers")
    if v.size and (v.min() < 0 or v.max() >= pts.shape[0]):
        return False, f"a vertex index is not one of the {pts.shape[0]} points", 1
    valid, message, problems = _core.check_convex_hull(pts, np.ascontiguousarray(v, dtype=np.uint32))
    return bool(valid), message, int(problems)


class PlanarPoints:
    """scipy's attributes of the input points, shared by ridt's classes in scipy's place (each
    keeps its points in `_points`)."""

    _points: np.ndarray

    @property
    def points(self) -> np.ndarray:
        return self._points

    @property
    def npoints(self) -> int:
        return int(self._points.shape[0])

    @property
    def ndim(self) -> int:
        return 2

    @property
    def min_bound(self) -> np.ndarray:
        return self._points.min(axis=0) if len(self._points) else np.full(2, np.nan)

    @property
    def max_bound(self) -> np.ndarray:
        return self._points.max(axis=0) if len(self._points) else np.full(2, np.nan)
