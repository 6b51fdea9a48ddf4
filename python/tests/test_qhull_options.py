"""Qhull's options as scipy passes them: its defaults in each mode (incremental, farthest
site), what they change in the attributes, and the options refused. Compared with the scipy
installed on the machine, on attributes that do not depend on Qhull's arbitrary choices: the
lift's scale and shift, each triangle's equation matched by its vertex set, the regions as sets."""

import numpy as np
import pytest
import scipy.spatial as ss

import ridt

PTS = np.random.default_rng(1).random((40, 2)) * [3, 1] + [1, 2]
QUERIES = np.random.default_rng(2).random((7, 2)) * 4

MODES = [dict(), dict(incremental=True), dict(furthest_site=True), dict(furthest_site=True, incremental=True),
         dict(qhull_options="Qbb Qc"), dict(qhull_options="Qz"), dict(qhull_options="Qc", incremental=True),
         dict(furthest_site=True, qhull_options="Qbb Qc Qz"), dict(furthest_site=True, qhull_options="Qz")]


def by_vertices(tri, rows):
    """rows (one a triangle) keyed by the triangle's vertex set."""
    return {tuple(sorted(s)): r for s, r in zip(tri.simplices.tolist(), rows)}


@pytest.mark.parametrize("mode", MODES, ids=str)
def test_the_lift_and_equations_are_scipys(mode):
    ours, theirs = ridt.Delaunay(PTS, **mode), ss.Delaunay(PTS, **mode)
    assert ours.paraboloid_scale == pytest.approx(theirs.paraboloid_scale, rel=1e-12)
    assert ours.paraboloid_shift == pytest.approx(theirs.paraboloid_shift, rel=1e-12, abs=1e-15)
    np.testing.assert_allclose(ours.lift_points(QUERIES), theirs.lift_points(QUERIES), rtol=1e-12, atol=1e-14)
    a, b = by_vertices(ours, ours.equations), by_vertices(theirs, theirs.equations)
    assert a.keys() == b.keys()
    for key in b:
        np.testing.assert_allclose(a[key], b[key], rtol=1e-11, atol=1e-12)
    a = by_vertices(ours, ours.plane_distance(QUERIES).T)
    b = by_vertices(theirs, theirs.plane_distance(QUERIES).T)
    for key in b:
        np.testing.assert_allclose(a[key], b[key], rtol=1e-11, atol=1e-12)


@pytest.mark.parametrize("mode", [m for m in MODES], ids=str)
def test_voronoi_regions_are_scipys(mode):
    ours, theirs = ridt.Voronoi(PTS, **mode), ss.Voronoi(PTS, **mode)
    assert len(ours.regions) == len(theirs.regions)

    def cells(v):  # each point's region as a set of rounded vertex coordinates
        out = []
        for p in range(len(PTS)):
            r = v.regions[v.point_region[p]]
            out.append(frozenset(tuple(np.round(v.vertices[i], 9)) if i >= 0 else None for i in r))
        return out

    assert cells(ours) == cells(theirs)

    def unowned(v):  # Qz's empty region at infinity, that no point owns (where Qhull put it)
        return sum(1 for k, r in enumerate(v.regions) if not r and k not in set(v.point_region))

    assert unowned(ours) == unowned(theirs)


def test_incremental_voronoi_has_no_region_at_infinity():
    v = ridt.Voronoi(PTS[:20], incremental=True)
    assert len(v.regions) == 20 and all(v.regions[k] for k in v.point_region)
    v.add_points(PTS[20:])
    assert len(v.regions) == len(ss.Voronoi(PTS, incremental=True).regions) == 40
    d = ridt.Delaunay(PTS[:20], incremental=True)
    d.add_points(PTS[20:])
    assert (d.paraboloid_scale, d.paraboloid_shift) == (1.0, 0.0)


@pytest.mark.parametrize("options", ["Qbb", "Qz", "Qbb Qc", "Qc Qz Q12", "Qbk:0Bk:0"])
@pytest.mark.parametrize("cls", [ridt.Delaunay, ridt.Voronoi])
def test_incremental_refuses_what_scipy_refuses(cls, options):
    scipy_cls = ss.Delaunay if cls is ridt.Delaunay else ss.Voronoi
    with pytest.raises(ValueError, match="incompatible with incremental mode"):
        scipy_cls(PTS, incremental=True, qhull_options=options)
    with pytest.raises(ValueError, match="incompatible with incremental mode"):
        cls(PTS, incremental=True, qhull_options=options)
    cls(PTS, qhull_options=options)  # without incremental: accepted


@pytest.mark.parametrize("options", ["QJ", "Qbb Qc Qz Q12 QJ", "QJ Pp", "QJ0.001"])
@pytest.mark.parametrize("cls", [ridt.Delaunay, ridt.Voronoi])
def test_joggle_makes_every_point_a_vertex_or_is_refused(cls, options):
    # Distinct points: every one a vertex, unmoved, as joggling is meant to give.
    got = cls(PTS, qhull_options=options)
    tri = got if cls is ridt.Delaunay else ridt.Delaunay(PTS, qhull_options=options)
    assert np.array_equal(np.unique(tri.simplices), np.arange(len(PTS)))
    if cls is ridt.Delaunay:  # Qhull sets Qbb with QJ: the same lift as scipy's
        ref = ss.Delaunay(PTS, qhull_options=options)
        # (Qhull's from the joggled points: off by the joggle's size, some 1e-10 by default)
        off = 1e-2 if "QJ0" in options else 1e-8
        assert got.paraboloid_scale == pytest.approx(ref.paraboloid_scale, rel=off)
        assert got.paraboloid_shift == pytest.approx(ref.paraboloid_shift, rel=off)
    # Copies of a point cannot all be vertices without moving them: refused by name.
    with pytest.raises(ValueError, match="QJ.*copies"):
        cls(np.concatenate([PTS, PTS[:2]]), qhull_options=options)
