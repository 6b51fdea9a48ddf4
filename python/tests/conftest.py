"""Shared helpers of the Python tests: scipy's answers and ridt's, compared as sets."""

import json
from pathlib import Path

import numpy as np
import pytest

import ridt

FIXTURES = Path(__file__).resolve().parents[2] / "tests" / "fixtures" / "delaunator"


def triangle_set(simplices):
    """The triangles as a set of sorted vertex triples (independent of order and rotation)."""
    return set(map(tuple, np.sort(np.asarray(simplices), axis=1).tolist()))


def matching(ours, theirs):
    """perm with ours[perm[i]] the same triangle as theirs[i] (as vertex sets)."""
    index = {t: i for i, t in enumerate(map(tuple, np.sort(ours, axis=1).tolist()))}
    return np.array([index[t] for t in map(tuple, np.sort(theirs, axis=1).tolist())], dtype=np.intp)


def assert_valid(points, tri):
    """The exact validator on a ridt.Delaunay or ridt.Triangulation."""
    simplices = tri.simplices if isinstance(tri, ridt.Delaunay) else tri.triangles
    valid, message = ridt.check(points, simplices)
    assert valid, message


def fixture(name):
    path = FIXTURES / f"{name}.json"
    if not path.exists():
        pytest.fail(f"fixture {path} is missing")
    return np.array(json.loads(path.read_text()), dtype=np.float64)
