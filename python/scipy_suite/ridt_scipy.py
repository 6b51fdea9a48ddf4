"""A pytest plugin that runs scipy's own test files against ridt.

Loaded with ``-p ridt_scipy`` (this folder on PYTHONPATH), before pytest imports any test
module, it puts ridt's classes and functions in the place of scipy's 2-D ones, in every module
the test files import them from:

- scipy.spatial: Delaunay, Voronoi, ConvexHull, tsearch (also in scipy.spatial._qhull),
  SphericalVoronoi (on a sphere and on a circle);
- scipy.interpolate: LinearNDInterpolator, NearestNDInterpolator, CloughTocher2DInterpolator,
  griddata, estimate_gradients_2d_global, GradientEstimationWarning (also in
  scipy.interpolate.interpnd, ._interpnd and ._ndgriddata).

What ridt does not claim is not run against Qhull in its place: input that is not 2-D,
HalfspaceIntersection and Qhull's own object skip the test with a reason that starts with
"outside ridt's claim"; the summary counts them. Any other skip is reported as such, and a test
that fails fails the run. Every ridt.Delaunay and ridt.ConvexHull a test builds is checked by
an exact validator as it is made, and a test listed in exceptions.txt (one that pins Qhull's
arbitrary choice among equally valid answers) must fail, strictly, with every triangulation it
built valid; one listed as "refused option:" (it passes QJ on points with copies, which ridt
refuses) must fail by ridt's ValueError.
"""

from __future__ import annotations

import os
from collections import Counter
from typing import Any, Dict, List

import numpy as np
import pytest

import ridt

HERE = os.path.dirname(os.path.abspath(__file__))
OUTSIDE = "outside ridt's claim"
REFUSED = "refused option:"  # exceptions.txt: the test passes QJ where ridt refuses it

_used: Counter = Counter()  # how often each replacement was called, over the whole session


def _dimension(points: Any) -> int:
    """The dimension of `points` as scipy reads it: an (n, d) array, a tuple of d coordinate
    arrays, or a triangulation."""
    if isinstance(points, (ridt.Delaunay, ridt.Voronoi)):
        return 2
    if isinstance(points, tuple):
        return len(points)
    if np.ma.isMaskedArray(points):
        return 2  # refused by ridt as by scipy, whatever its shape

    a = np.asarray(points)
    return a.shape[-1] if a.ndim >= 2 else 1


_current = [""]  # the test that runs now
_verdicts: Dict[str, List[str]] = {}  # the validator's words on each test's triangulations
_invalid: List[str] = []


def _validate(points: np.ndarray, triangles: np.ndarray, furthest_site: bool) -> None:
    """Every triangulation a test builds, checked exactly as it is made (a test may then change
    its arrays in place, as test_nd_simplex sorts them), whatever the test asserts. A failure
    fails the session too, so that an expected failure cannot hide it."""
    _used["validated"] += 1
    valid, message = ridt.check(points, triangles, furthest_site) if len(triangles) else (True, "empty (degenerate input)")
    _verdicts.setdefault(_current[0], []).append(message)
    if not valid:
        _invalid.append(f"{_current[0]}: {message}")
        raise AssertionError(f"ridt's triangulation of {len(points)} points is not valid: {message}")


def _validate_hull(hull: Any) -> None:
    """A hull checked exactly (ridt.check_convex_hull), of the points it was made of: with QGn
    all but point n."""
    _used["validated"] += 1
    points, corners = hull.points, hull.vertices
    if hull.good is not None:
        keep = np.ones(len(points), dtype=bool)
        keep[hull._good[0]] = False
        points, corners = points[keep], np.searchsorted(np.flatnonzero(keep), corners)
    valid, message, _ = ridt.check_convex_hull(points, corners)
    _verdicts.setdefault(_current[0], []).append(message)
    if not valid:
        _invalid.append(f"{_current[0]}: {message}")
        raise AssertionError(f"ridt's convex hull of {len(points)} points is not valid: {message}")


def _outside(what: str) -> None:
    pytest.skip(f"{OUTSIDE}: {what}")


class _Replacing(type):
    """A class whose instances are ridt's: isinstance() accepts ridt's objects."""

    def __instancecheck__(cls, obj: Any) -> bool:
        return isinstance(obj, cls._ridt)


def _replacement(name: str, ridt_class: Any, first_arg: str = "points", planar_only: bool = False) -> type:
    """`planar_only`: a class scipy has for the plane alone, whose refusal of other input is
    in ridt's claim too."""

    def __new__(cls, *args: Any, **kwargs: Any) -> Any:
        points = args[0] if args else kwargs.get(first_arg)
        d = _dimension(points)
        if d != 2 and not planar_only:
            _outside(f"{name} in {d}-D")
        _used[name] += 1
        obj = ridt_class(*args, **kwargs)
        owner = getattr(obj, "tri", obj)  # an interpolator's Delaunay, or the object itself
        if isinstance(owner, (ridt.Delaunay, ridt.Voronoi)):
            _validate(owner.points, owner.triangulation.triangles, owner.furthest_site)
        if isinstance(owner, ridt.ConvexHull):
            _validate_hull(owner)
        return obj

    return _Replacing(name, (), {"__new__": __new__, "_ridt": ridt_class, "__doc__": ridt_class.__doc__})


def _spherical_voronoi() -> type:
    """ridt.SphericalVoronoi on a sphere (3-D) or a circle (2-D), its triangulation validated; scipy's
    higher dimensions are outside the claim."""

    def __new__(cls, *args: Any, **kwargs: Any) -> Any:
        points = args[0] if args else kwargs.get("points")
        d = _dimension(points)
        if d not in (2, 3):
            _outside(f"SphericalVoronoi in {d}-D")
        _used["SphericalVoronoi"] += 1
        sv = ridt.SphericalVoronoi(*args, **kwargs)
        _used["validated"] += 1
        if d == 3:
            valid, message = ridt.check_sphere(sv.points, sv.triangles)
        else:
            valid, message, _ = ridt.check_convex_hull(sv.points, sv.triangles[:, 0])
        _verdicts.setdefault(_current[0], []).append(message)
        if not valid:
            _invalid.append(f"{_current[0]}: {message}")
            raise AssertionError(f"ridt's triangulation of {len(sv.points)} points on the sphere is not valid: {message}")
        return sv

    return _Replacing("SphericalVoronoi", (), {"__new__": __new__, "_ridt": ridt.SphericalVoronoi,
                                               "__doc__": ridt.SphericalVoronoi.__doc__})


def _not_claimed(name: str) -> type:
    def __new__(cls, *args: Any, **kwargs: Any) -> Any:
        _outside(name)

    return type(name, (), {"__new__": __new__})


def _griddata(points: Any, values: Any, xi: Any, *args: Any, **kwargs: Any) -> Any:
    d = _dimension(points)
    if d != 2:
        _outside(f"griddata in {d}-D")
    _used["griddata"] += 1
    return ridt.griddata(points, values, xi, *args, **kwargs)


def _tsearch(tri: Any, xi: Any) -> Any:
    _used["tsearch"] += 1
    return tri.find_simplex(xi)


def replacements() -> Dict[str, Any]:
    return {
        "Delaunay": _replacement("Delaunay", ridt.Delaunay),
        "Voronoi": _replacement("Voronoi", ridt.Voronoi),
        "LinearNDInterpolator": _replacement("LinearNDInterpolator", ridt.LinearNDInterpolator),
        "NearestNDInterpolator": _replacement("NearestNDInterpolator", ridt.NearestNDInterpolator, "x"),
        "CloughTocher2DInterpolator": _replacement("CloughTocher2DInterpolator", ridt.CloughTocher2DInterpolator,
                                                   planar_only=True),
        "griddata": _griddata,
        "tsearch": _tsearch,
        "ConvexHull": _replacement("ConvexHull", ridt.ConvexHull),
        "SphericalVoronoi": _spherical_voronoi(),
        "HalfspaceIntersection": _not_claimed("HalfspaceIntersection"),
        "_Qhull": _not_claimed("Qhull's own object (_Qhull)"),
        "estimate_gradients_2d_global": ridt.estimate_gradients_2d_global,
        "GradientEstimationWarning": ridt.GradientEstimationWarning,
    }


MODULES = ("scipy.spatial", "scipy.spatial._qhull", "scipy.spatial.qhull", "scipy.spatial._spherical_voronoi",
           "scipy.interpolate",
           "scipy.interpolate.interpnd", "scipy.interpolate._interpnd", "scipy.interpolate._ndgriddata",
           "scipy.interpolate.ndgriddata")  # where scipy's test files import them from


def _install() -> None:
    import importlib
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        modules = []
        for name in MODULES:  # the private names differ between scipy's versions
            try:
                modules.append(importlib.import_module(name))
            except ModuleNotFoundError:
                pass
    for name, value in replacements().items():
        for module in modules:
            if name in vars(module):
                setattr(module, name, value)


def _exceptions() -> Dict[str, str]:
    """exceptions.txt: `test id  why` lines; '#' starts a comment."""
    out = {}
    with open(os.path.join(HERE, "exceptions.txt"), encoding="utf-8") as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                test, _, why = line.partition(" ")
                out[test] = why.strip()
    return out


def pytest_configure(config: pytest.Config) -> None:
    _install()
    config._ridt_exceptions = _exceptions()  # type: ignore[attr-defined]
    config._ridt_seen = set()  # type: ignore[attr-defined]


def _short_id(item: pytest.Item) -> str:
    return "::".join([os.path.basename(item.location[0])] + item.nodeid.split("::")[1:])


def pytest_collection_modifyitems(config: pytest.Config, items: List[pytest.Item]) -> None:
    exceptions = config._ridt_exceptions  # type: ignore[attr-defined]
    for item in items:
        key = _short_id(item)
        if key in exceptions:
            config._ridt_seen.add(key)  # type: ignore[attr-defined]
            why = exceptions[key]
            if why.startswith(REFUSED):  # must fail by ridt's ValueError, nothing else
                item.add_marker(pytest.mark.xfail(reason=why, strict=True, raises=ValueError))
            else:
                item.add_marker(pytest.mark.xfail(reason=f"pins Qhull's choice: {why}", strict=True))


def pytest_runtest_setup(item: pytest.Item) -> None:
    _current[0] = _short_id(item)


def pytest_terminal_summary(terminalreporter: Any, exitstatus: int, config: pytest.Config) -> None:
    stats = terminalreporter.stats
    reasons: Counter = Counter()
    for report in stats.get("skipped", []):
        reason = str(report.longrepr[2]) if isinstance(report.longrepr, tuple) else str(report.longrepr)
        reasons[OUTSIDE if OUTSIDE in reason else "other: " + reason] += 1
    tw = terminalreporter
    tw.section("scipy's tests against ridt")
    tw.line(f"passed against ridt: {len(stats.get('passed', []))}")
    tw.line(f"failed: {len(stats.get('failed', []))}")
    refused = sum(1 for why in config._ridt_exceptions.values() if why.startswith(REFUSED))  # type: ignore
    tw.line(f"listed exceptions: {len(stats.get('xfailed', []))} ({refused} pass an option ridt refuses with "
            f"ValueError; the others pin Qhull's choice, ridt's output validated)")
    for reason, count in sorted(reasons.items()):
        tw.line(f"skipped, {reason}: {count}")
    tw.line("replacements called: " + ", ".join(f"{k} {v}" for k, v in sorted(_used.items())))
    for test in sorted(config._ridt_seen):  # type: ignore[attr-defined]
        verdicts = Counter(v.split(":")[0] for v in _verdicts.get(test, []))
        tw.line(f"  exception {test}: validator on its {sum(verdicts.values())} triangulations: "
                + ", ".join(f"{k} {n}" for k, n in sorted(verdicts.items())))
    for problem in _problems(config):
        tw.line(problem)


def _problems(config: pytest.Config) -> List[str]:
    out = []
    # Exceptions of files not run this session are not looked for.
    files = {os.path.basename(str(a)).split("::")[0] for a in config.args}
    unseen = {t for t in set(config._ridt_exceptions) - config._ridt_seen  # type: ignore[attr-defined]
              if t.split("::")[0] in files}
    if unseen:
        out.append(f"exceptions.txt names tests that were not collected: {sorted(unseen)}")
    out += [f"not a valid triangulation: {x}" for x in _invalid]
    called = {"test_qhull.py": "Delaunay", "test_interpnd.py": "LinearNDInterpolator",
              "test_ndgriddata.py": "griddata", "test_spherical_voronoi.py": "SphericalVoronoi"}
    for f in files:
        if f in called and not _used[called[f]]:
            out.append(f"ridt's {called[f]} was never called in {f}: the replacement did not take")
    return out


def pytest_sessionfinish(session: pytest.Session, exitstatus: int) -> None:
    if _problems(session.config) and session.exitstatus == 0:
        session.exitstatus = 1
