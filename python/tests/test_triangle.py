"""ridt.triangle: the `triangle` package's call. Results checked with the exact validator, the
exterior and holes removed as the switches say, unsupported switches refused."""

import numpy as np
import pytest
import scipy.spatial

import ridt
from conftest import triangle_set
from ridt import triangle

SQUARE = [(0, 0), (10, 0), (10, 10), (0, 10)]
HOLE = [(4, 4), (6, 4), (6, 6), (4, 6)]


def loop(first, n=4):
    return [(first + k, first + (k + 1) % n) for k in range(n)]


def test_points_only_is_delaunay():
    rng = np.random.default_rng(1)
    pts = rng.random((300, 2))
    t = triangle.triangulate({"vertices": pts})
    assert triangle_set(t["triangles"]) == triangle_set(ridt.Delaunay(pts).simplices)
    assert set(t) == {"vertices", "triangles", "vertex_markers"}
    assert t["vertex_markers"].shape == (300, 1)
    assert t["vertex_markers"].sum() == len(ridt.triangulate(pts).hull)


def test_a_square_with_a_hole():
    tri = {"vertices": np.array(SQUARE + HOLE, dtype=float), "segments": np.array(loop(0) + loop(4)),
           "holes": [[5, 5]]}
    t = triangle.triangulate(tri, "p")
    assert len(t["triangles"]) == 8
    centroids = t["vertices"][t["triangles"]].mean(axis=1)
    assert (~((centroids > 4) & (centroids < 6)).all(axis=1)).all()
    assert sorted(map(tuple, t["segments"])) == sorted(tuple(sorted(s)) for s in loop(0) + loop(4))
    assert (t["segment_markers"] == 1).all() and t["holes"].tolist() == [[5.0, 5.0]]
    assert (t["vertex_markers"] == 1).all()
    t = triangle.triangulate(tri, "pen")
    assert len(t["edges"]) == 16 and t["edge_markers"].sum() == 8  # the 8 segments bound the ring
    assert t["neighbors"].shape == (8, 3) and (t["neighbors"] == -1).sum() == 8


def test_holes_ignored_and_switches_that_change_nothing():
    tri = {"vertices": np.array(SQUARE + HOLE, dtype=float), "segments": np.array(loop(0) + loop(4)),
           "holes": [[5, 5]]}
    assert len(triangle.triangulate(tri, "pO")["triangles"]) == 10  # the hole meshed too
    same = triangle.triangulate(tri, "piFlXIQ")
    np.testing.assert_array_equal(same["triangles"], triangle.triangulate(tri, "p")["triangles"])


def test_the_convex_hull_switch():
    ell = np.array([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)], dtype=float)
    tri = {"vertices": ell, "segments": loop(0, 6)}
    assert len(triangle.triangulate(tri, "p")["triangles"]) == 4
    whole = triangle.triangulate(tri, "pc")
    assert len(whole["triangles"]) == 5
    assert ridt.check(ell, whole["triangles"], segments=loop(0, 6))[0]


def smallest_angle(t) -> float:
    """The smallest angle of any triangle of a result, in degrees."""
    p = t["vertices"][t["triangles"]]
    worst = 180.0
    for i in range(3):
        u, w = p[:, (i + 1) % 3] - p[:, i], p[:, (i + 2) % 3] - p[:, i]
        cross = np.abs(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0])
        worst = min(worst, float(np.degrees(np.arctan2(cross, (u * w).sum(axis=1))).min()))
    return worst


def test_quality_switches():
    tri = {"vertices": np.array(SQUARE + HOLE, dtype=float), "segments": np.array(loop(0) + loop(4)),
           "holes": [[5, 5]], "regions": [[1, 1, 3.5, 0.5]]}
    t = triangle.triangulate(tri, "pq30a2A")
    n = len(t["vertices"])
    assert n > 8 and t["vertices"][:8].tolist() == tri["vertices"].tolist()  # the input's first
    assert (t["triangle_attributes"] == 3.5).all()
    p = t["vertices"][t["triangles"]]
    area = 0.5 * ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1]) - (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0]))
    assert (area > 0).all() and area.max() <= 2 and abs(area.sum() - 96) < 1e-9
    assert smallest_angle(t) >= 30 - 1e-9  # every input angle is 90 degrees: no excuse
    assert t["vertex_markers"].shape == (n, 1)
    regional = triangle.triangulate(tri, "pa")  # each region's own bound: 0.5
    assert len(regional["triangles"]) > len(t["triangles"])
    quiet = triangle.triangulate(tri, "pq")  # q alone: 20 degrees
    assert smallest_angle(quiet) >= 20 - 1e-9 and len(quiet["vertices"]) < len(t["vertices"])
    kept = triangle.triangulate(tri, "pq30Y")  # no point on the boundary
    assert len(kept["segments"]) == 8


def test_conforming_delaunay():
    rng = np.random.default_rng(3)
    pts = np.concatenate([np.array(SQUARE + HOLE, dtype=float), rng.uniform(0, 10, (200, 2))])
    tri = {"vertices": pts, "segments": np.array(loop(0) + loop(4)) }
    t = triangle.triangulate(tri, "pcD")
    assert len(t["vertices"]) > len(pts)
    assert ridt.check(t["vertices"], t["triangles"])[0]  # every edge Delaunay, segments' too
    assert not ridt.check(pts, triangle.triangulate(tri, "pc")["triangles"])[0]


def test_a_steiner_limit():
    # S10: refinement stops after 10 points, with a warning; S0: nothing refined.
    tri = {"vertices": SQUARE, "segments": np.array(loop(0))}
    with pytest.warns(ridt.RefinementWarning, match="stopped after 10 points"):
        t = triangle.triangulate(tri, "pq30a0.01S10")
    assert len(t["vertices"]) == len(SQUARE) + 10
    assert len(triangle.triangulate(tri, "pq30a0.01S0")["vertices"]) == len(SQUARE)
    assert len(triangle.triangulate(tri, "pq30a0.01S100000")["vertices"]) > len(SQUARE) + 10


def areas(t):
    p = t["vertices"][t["triangles"]]
    return 0.5 * ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1]) - (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0]))


def holder(points, triangles, queries):
    """For each query, a triangle of the mesh whose closure holds it (by signs; the meshes here
    are small), or -1."""
    p = points[triangles]
    out = np.full(len(queries), -1)
    for k in range(len(triangles)):
        a, b, c = p[k]
        sides = [(v[0] - u[0]) * (queries[:, 1] - u[1]) - (v[1] - u[1]) * (queries[:, 0] - u[0])
                 for u, v in ((a, b), (b, c), (c, a))]
        inside = (sides[0] >= 0) & (sides[1] >= 0) & (sides[2] >= 0) & (out < 0)
        out[inside] = k
    return out


def test_refining_a_mesh_each_triangle_to_its_own_bound():
    # Triangle's -r with -a and no number: the mesh's 'triangle_max_area', one a triangle. A
    # triangle of the result takes the bound of the given one that holds its centroid.
    tri = {"vertices": np.array(SQUARE + HOLE, dtype=float), "segments": np.array(loop(0) + loop(4)),
           "holes": [[5, 5]], "regions": [[1, 1, 3.5, 0]]}
    first = triangle.triangulate(tri, "pq30a4A")
    bounds = np.where(np.arange(len(first["triangles"])) % 3 == 0, 0.05, -1.0)
    first["triangle_max_area"] = bounds
    t = triangle.triangulate(first, "rpq30a")
    assert t["vertices"][:len(first["vertices"])].tolist() == first["vertices"].tolist()
    assert abs(areas(t).sum() - 96) < 1e-9 and (areas(t) > 0).all()
    assert smallest_angle(t) >= 30 - 1e-9
    assert (t["triangle_attributes"] == 3.5).all()  # carried from the mesh's, with no 'A'
    centroids = t["vertices"][t["triangles"]].mean(axis=1)
    given = holder(first["vertices"], first["triangles"], centroids)
    assert (given >= 0).all()
    tight = bounds[given] > 0
    assert tight.sum() > 100 and (areas(t)[tight] <= 0.05).all()
    assert areas(t)[~tight].max() > 0.05  # the others left coarser
    cdt = ridt.ConstrainedDelaunay.from_mesh(first["vertices"], first["triangles"], first["segments"],
                                             min_angle=30, triangle_max_area=bounds)
    assert cdt.check()[0] and triangle_set(cdt.simplices) == triangle_set(t["triangles"])
    with pytest.raises(ValueError, match="'triangle_max_area'"):
        triangle.triangulate({k: v for k, v in first.items() if k != "triangle_max_area"}, "rpa")
    with pytest.raises(ValueError, match="needs 'triangles'"):
        triangle.triangulate(tri, "rp")


def test_refining_a_mesh_that_is_not_delaunay_flips_it_to_delaunay():
    # Points in convex position, triangulated as a fan from one of them: flipped to Delaunay.
    rng = np.random.default_rng(5)
    angles = np.sort(rng.uniform(0, 2 * np.pi, 40))
    pts = np.c_[np.cos(angles), 0.5 * np.sin(angles)]
    fan = np.array([[0, k, k + 1] for k in range(1, 39)])
    t = triangle.triangulate({"vertices": pts, "triangles": fan}, "r")
    assert triangle_set(t["triangles"]) == triangle_set(scipy.spatial.Delaunay(pts).simplices)
    assert ridt.check(t["vertices"], t["triangles"])[0]


def test_refining_keeps_the_segments_with_p_and_takes_six_node_triangles_by_their_corners():
    # A kite split along its long diagonal, not Delaunay: with 'p' the diagonal, a segment, stays;
    # without, only the boundary does, and the diagonal is flipped away.
    kite = np.array([[0, 0], [4, -1], [8, 0], [4, 1]], dtype=float)
    tri = {"vertices": kite, "triangles": np.array([[0, 1, 2], [0, 2, 3]]), "segments": np.array([[0, 2]])}
    assert triangle_set(triangle.triangulate(tri, "rp")["triangles"]) == triangle_set(tri["triangles"])
    assert triangle_set(triangle.triangulate(tri, "r")["triangles"]) == triangle_set([[0, 1, 3], [1, 2, 3]])
    # An o2 result refined: its six-node rows read as their corners.
    six = triangle.triangulate({"vertices": SQUARE, "segments": np.array(loop(0))}, "pq30a20o2")
    corners = {"vertices": six["vertices"], "triangles": six["triangles"], "segments": six["segments"]}
    t = triangle.triangulate(corners, "rpq30a5")
    assert (areas(t) > 0).all() and abs(areas(t).sum() - 100) < 1e-9 and areas(t).max() <= 5


def test_refining_bad_meshes_is_refused():
    square = np.array(SQUARE, dtype=float)
    with pytest.raises(ValueError, match="clockwise"):
        triangle.triangulate({"vertices": square, "triangles": [[0, 2, 1]]}, "r")
    with pytest.raises(ValueError, match="overlap"):
        triangle.triangulate({"vertices": square, "triangles": [[0, 1, 2], [0, 1, 3]]}, "r")
    with pytest.raises(ValueError, match="not an edge"):
        triangle.triangulate({"vertices": square, "triangles": [[0, 1, 2]], "segments": [[0, 3]]}, "rp")
    # Triangle takes c with r, and so does ridt: the mesh refined keeps its own domain.
    assert triangle.triangulate({"vertices": square, "triangles": [[0, 1, 2]]}, "rc")["triangles"].tolist() == \
        triangle.triangulate({"vertices": square, "triangles": [[0, 1, 2]]}, "r")["triangles"].tolist()
    with pytest.raises(ValueError, match="3 values for 1 triangles"):
        ridt.ConstrainedDelaunay.from_mesh(square, [[0, 1, 2]], triangle_max_area=[1, 2, 3])
    with pytest.raises(ValueError, match="outside"):
        ridt.ConstrainedDelaunay.from_mesh(square, [[0, 1, 7]])


def test_a_mesh_refined_again_from_the_class():
    cdt = ridt.ConstrainedDelaunay(np.array(SQUARE + HOLE, dtype=float), np.array(loop(0) + loop(4)), holes=[[5, 5]],
                                   min_angle=30, max_area=4)
    finer = cdt.refine(min_angle=30, max_area=0.5)
    assert finer.check()[0] and finer.nsimplex > cdt.nsimplex
    assert finer.points[:cdt.npoints].tolist() == cdt.points.tolist()
    assert finer.ninput == cdt.npoints and len(finer.added) == finer.npoints - cdt.npoints


def test_switches_for_the_result():
    # B: no markers; j: the vertex in the hole left out, the rest renumbered; C: checked.
    pts = np.array(SQUARE + HOLE + [(5, 5)], dtype=float)
    tri = {"vertices": pts, "segments": np.array(loop(0) + loop(4)), "holes": [[5.5, 5.5]]}
    full = triangle.triangulate(tri, "pe")
    t = triangle.triangulate(tri, "pBjCe")
    assert not {"vertex_markers", "segment_markers", "edge_markers"} & set(t)
    assert len(full["vertices"]) == 9 and len(t["vertices"]) == 8
    assert t["vertices"].tolist() == full["vertices"][:8].tolist()  # the unused one was last
    assert triangle_set(t["triangles"]) == triangle_set(full["triangles"])
    assert sorted(map(tuple, t["edges"])) == sorted(map(tuple, full["edges"]))
    moved = triangle.triangulate({**tri, "vertices": np.concatenate([pts[8:], pts[:8]]),
                                  "segments": np.array(loop(0) + loop(4)) + 1}, "pj")
    assert moved["vertices"].tolist() == full["vertices"][:8].tolist()
    assert triangle_set(moved["triangles"]) == triangle_set(full["triangles"])
    assert sorted(map(tuple, np.sort(moved["segments"], axis=1))) == sorted(map(tuple, np.sort(full["segments"], axis=1)))
    assert moved["segments"].dtype == np.intc
    six = triangle.triangulate({**tri, "vertex_attributes": np.arange(9.0)}, "pjo2")
    assert six["triangles"].shape[1] == 6 and six["triangles"].max() == len(six["vertices"]) - 1
    assert len(six["vertex_attributes"]) == len(six["vertices"]) == len(six["vertex_markers"])


def test_refused():
    with pytest.raises(ValueError, match="'S': give the most points"):
        triangle.triangulate({"vertices": SQUARE}, "pS")
    for switch in "us":
        with pytest.raises(ValueError, match=f"switch '{switch}'"):
            triangle.triangulate({"vertices": SQUARE}, "p" + switch)
    for switch in "gNEPz":  # files' switches: nothing to change here
        assert len(triangle.triangulate({"vertices": SQUARE}, "pc" + switch)["triangles"]) == 2
    with pytest.raises(ValueError, match="needs 'vertices'"):
        triangle.triangulate({}, "")
    with pytest.raises(TypeError):
        triangle.triangulate({"vertices": SQUARE}, 3)


def on_segment(p, a, b, eps=1e-9):
    """p lies on the segment a-b (within rounding: crossings are rounded to doubles)."""
    d, e = b - a, p - a
    return abs(d[0] * e[1] - d[1] * e[0]) <= eps * (d @ d) and -eps <= (e @ d) / (d @ d) <= 1 + eps


def test_segment_markers_pass_to_their_pieces_as_in_triangle():
    # The square's sides marked 2, 3, 4, 5; a diagonal inside marked 7, one unmarked (0) that
    # crosses it; refinement splits them all.
    square = np.array(SQUARE, dtype=float)
    tri = {"vertices": square, "segments": np.array(loop(0) + [(0, 2), (1, 3)]),
           "segment_markers": np.array([2, 3, 4, 5, 7, 0])}
    t = triangle.triangulate(tri, "pq30a4e")
    v, segs, marks = t["vertices"], t["segments"], t["segment_markers"].ravel()
    assert len(segs) > 6 and marks.shape == (len(segs),)
    ends = {k: square[list(s)] for k, s in enumerate(tri["segments"])}
    for (a, b), m in zip(segs, marks):
        owners = [k for k, (p, q) in ends.items() if on_segment(v[a], p, q) and on_segment(v[b], p, q)]
        assert len(owners) == 1, (a, b)
        assert m == (tri["segment_markers"][owners[0]] or 0), (a, b, m)
    # Vertices: on a marked side its marker (a corner one of its two sides'), the crossing and
    # the diagonals' inner points 7, the rest 0 inside.
    vm = t["vertex_markers"].ravel()
    for k, p in enumerate(v):
        on = [tri["segment_markers"][s] for s in range(6) if on_segment(p, *ends[s]) and tri["segment_markers"][s]]
        if on:
            assert vm[k] in on, (k, p, vm[k], on)
        else:
            assert vm[k] == 0, (k, p)
    # Every edge: a piece's marker, else 0 (none on the boundary is unmarked here).
    key = {tuple(s): m for s, m in zip(map(tuple, segs), marks)}
    for e, m in zip(map(tuple, t["edges"]), t["edge_markers"].ravel()):
        assert m == key.get(e, 0)


def test_unmarked_segments_get_one_on_the_boundary_and_zero_inside():
    tri = {"vertices": np.array(SQUARE + [(2, 2), (8, 8)], dtype=float), "segments": np.array(loop(0) + [(4, 5)])}
    t = triangle.triangulate(tri, "p")
    marks = dict(zip(map(tuple, t["segments"]), t["segment_markers"].ravel()))
    assert marks[(4, 5)] == 0 and all(m == 1 for s, m in marks.items() if s != (4, 5))
    assert t["vertex_markers"].ravel().tolist() == [1, 1, 1, 1, 0, 0]
    given = triangle.triangulate(dict(tri, vertex_markers=[0, 9, 0, 0, 6, 0]), "p")["vertex_markers"].ravel()
    assert given.tolist() == [1, 9, 1, 1, 6, 0]


def test_vertex_attributes_are_carried_and_interpolated():
    tri = {"vertices": np.array(SQUARE + [(3, 4)], dtype=float), "segments": np.array(loop(0)),
           "vertex_attributes": np.array([[1.0, 10], [2, 20], [3, 30], [4, 40], [5, 50]])}
    t = triangle.triangulate(tri, "p")
    np.testing.assert_array_equal(t["vertex_attributes"], tri["vertex_attributes"])
    flat = triangle.triangulate(dict(tri, vertex_attributes=[1.0, 2, 3, 4, 5]), "p")["vertex_attributes"]
    assert flat.shape == (5, 1)
    # The points added get the attributes interpolated linearly: exact on linear ones.
    pts = tri["vertices"]
    linear = np.stack([2 * pts[:, 0] + 3 * pts[:, 1] + 1, np.full(len(pts), 7.0)], axis=1)
    q = triangle.triangulate(dict(tri, vertex_attributes=linear), "pq30a1")
    v = q["vertices"]
    assert len(v) > len(pts)
    np.testing.assert_array_equal(q["vertex_attributes"][:len(pts)], linear)
    np.testing.assert_allclose(q["vertex_attributes"][:, 0], 2 * v[:, 0] + 3 * v[:, 1] + 1, rtol=0, atol=1e-12)
    np.testing.assert_allclose(q["vertex_attributes"][:, 1], 7, rtol=0, atol=1e-13)
    with pytest.raises(ValueError, match="rows"):
        triangle.triangulate(dict(tri, vertex_attributes=np.ones((4, 2))), "p")


def test_yy_keeps_every_segment_whole_and_y_the_boundary_alone():
    tri = {"vertices": np.array(SQUARE + [(2, 3), (8, 6)], dtype=float), "segments": np.array(loop(0) + [(4, 5)])}
    y = triangle.triangulate(tri, "pq25a1Y")
    yy = triangle.triangulate(tri, "pq25a1YY")
    assert len(y["segments"]) > 5  # the inner segment split, the boundary whole
    assert len(yy["segments"]) == 5 and yy["segments"].max() < 6
    assert len(yy["vertices"]) > 50
    p = yy["vertices"][yy["triangles"]]
    areas = ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1]) - (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0]))
    assert areas.max() / 2 <= 1
    m = ridt.ConstrainedDelaunay(tri["vertices"], tri["segments"], min_angle=25, max_area=1, split_segments=False)
    assert np.array_equal(m.simplices, yy["triangles"]) and m.check()[0]
    with pytest.raises(ValueError, match="conforming"):
        triangle.triangulate(tri, "pq30YYD")


FIVE = [[0, 0], [0, 1], [0.5, 0.5], [1, 1], [1, 0]]  # a square and its centre


def undirected(edges):
    return set(map(tuple, np.sort(np.asarray(edges), axis=1).tolist()))


def test_delaunay_and_convex_hull_as_the_package_gives_them():
    tris = triangle.delaunay(FIVE)
    assert tris.dtype == np.intc and triangle_set(tris) == triangle_set([[1, 0, 2], [2, 4, 3], [4, 2, 0], [2, 3, 1]])
    p = np.asarray(FIVE, dtype=float)[tris]
    u, w = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    assert (u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0] > 0).all()  # counter-clockwise
    hull = triangle.convex_hull([[0, 0], [0, 1], [1, 1], [1, 0]])
    assert hull.dtype == np.intc and undirected(hull) == {(0, 3), (2, 3), (1, 2), (0, 1)}
    assert (hull[:, 1] == np.roll(hull[:, 0], -1)).all()  # one cycle, edge after edge
    # Points on the hull's edges are its corners: the square's midpoints make 8 edges.
    ring = [[0, 0], [1, 0], [2, 0], [2, 1], [2, 2], [1, 2], [0, 2], [0, 1], [1, 1]]
    assert undirected(triangle.convex_hull(ring)) == {(k, (k + 1) % 8) if k < 7 else (0, 7) for k in range(8)}


def test_delaunay_and_convex_hull_match_scipy_in_general_position():
    pts = np.random.default_rng(7).random((2000, 2))
    assert triangle_set(triangle.delaunay(pts)) == triangle_set(scipy.spatial.Delaunay(pts).simplices)
    hull = triangle.convex_hull(pts)
    assert undirected(hull) == undirected(scipy.spatial.ConvexHull(pts).simplices)
    a, b = pts[hull[:, 0]], pts[hull[:, 1]]
    for k in range(len(hull)):  # every point on the left of (or on) every edge: counter-clockwise
        d = b[k] - a[k]
        assert (d[0] * (pts[:, 1] - a[k, 1]) - d[1] * (pts[:, 0] - a[k, 0]) >= 0).all()


def test_voronoi_of_the_package_example():
    vertices, edges, origins, directions = triangle.voronoi(FIVE)
    found = {tuple(v) for v in vertices.tolist()}
    assert found == {(0.0, 0.5), (1.0, 0.5), (0.5, 0.0), (0.5, 1.0)}
    assert edges.dtype == np.intc and origins.dtype == np.intc and len(edges) == 4 and len(origins) == 4
    for o, d in zip(origins, directions):  # each ray leaves the square through the middle of a side
        side = vertices[o]
        assert np.abs(d).sum() == 1 and np.dot(side - 0.5, d) == 0.5
    assert undirected(edges) == {tuple(sorted((i, j))) for i in range(4) for j in range(i + 1, 4)
                                 if np.hypot(*(vertices[i] - vertices[j])) < 1}  # not across the square


def test_voronoi_matches_scipy():
    rng = np.random.default_rng(3)
    for pts in (rng.random((500, 2)), np.array([(x, y) for x in range(6) for y in range(5)], dtype=float)):
        vertices, edges, origins, directions = triangle.voronoi(pts)
        theirs = scipy.spatial.Voronoi(pts)
        np.testing.assert_allclose(np.sort(vertices.view("f8,f8"), axis=0).view(float),
                                   np.sort(theirs.vertices.view("f8,f8"), axis=0).view(float), rtol=0, atol=1e-12)
        ridges = np.array(theirs.ridge_vertices)
        assert len(edges) == (ridges >= 0).all(axis=1).sum() and len(origins) == (ridges < 0).any(axis=1).sum()
        assert len(origins) == len(triangle.convex_hull(pts))
        for o, d in zip(origins, directions):
            # The ray bisects a hull edge: of the points farthest along d (a side of the hull),
            # the two nearest its origin are equally near it, and no point is nearer.
            along = pts @ d
            side = np.flatnonzero(along >= along.max() - 1e-12)
            near = np.sort(np.hypot(*(pts[side] - vertices[o]).T))
            assert len(side) >= 2 and near[0] == pytest.approx(near[1], abs=1e-12)
            assert near[0] <= np.hypot(*(pts - vertices[o]).T).min() + 1e-12


def test_the_dual_with_v_is_scipys_voronoi_diagram_of_random_points():
    pts = np.random.default_rng(5).random((400, 2))
    t = triangle.triangulate({"vertices": pts}, "v")
    theirs = scipy.spatial.Voronoi(pts)
    vertices, edges = t["voronoi_vertices"], t["voronoi_edges"]
    assert len(vertices) == len(t["triangles"])  # one a triangle, in its order
    np.testing.assert_allclose(np.sort(vertices.view("f8,f8"), axis=0).view(float),
                               np.sort(theirs.vertices.view("f8,f8"), axis=0).view(float), rtol=0, atol=1e-12)
    # The same edges, by their ends' coordinates; a ray for each of scipy's ridges to infinity.
    ours = {tuple(sorted(map(tuple, np.round(vertices[e], 9).tolist()))) for e in edges}
    ridges = np.array(theirs.ridge_vertices)
    finite = ridges[(ridges >= 0).all(axis=1)]
    assert ours == {tuple(sorted(map(tuple, np.round(theirs.vertices[e], 9).tolist()))) for e in finite}
    assert len(t["voronoi_ray_origins"]) == (ridges < 0).any(axis=1).sum() == len(triangle.convex_hull(pts))


def test_the_dual_of_a_mesh_with_a_hole():
    holed = {"vertices": SQUARE + HOLE, "segments": loop(0) + loop(4), "holes": [(5, 5)]}
    t = triangle.triangulate(holed, "pq30a4v")
    pts, tris = t["vertices"], t["triangles"]
    centres = t["voronoi_vertices"]
    assert centres.shape == (len(tris), 2)
    for tri, c in zip(tris, centres):  # each the circumcentre of its triangle
        r = np.hypot(*(pts[tri] - c).T)
        assert np.ptp(r) <= 1e-12 * r.max()
    # An edge between two triangles for each side they share, a ray for each side of one alone
    # (the outer boundary and the hole's), along the side's outward normal.
    sides = {}
    for k, tri in enumerate(tris):
        for i in range(3):  # side a -> b, counter-clockwise: the triangle on its left
            a, b = tri[i], tri[(i + 1) % 3]
            sides.setdefault(tuple(sorted((a, b))), []).append((k, a, b))
    shared = {tuple(sorted(s[0] for s in ks)) for ks in sides.values() if len(ks) == 2}
    assert {tuple(sorted(e)) for e in t["voronoi_edges"].tolist()} == shared
    # Each boundary side (a, b) of triangle k: a ray from k along the side turned a quarter
    # clockwise, (b.y - a.y, a.x - b.x), outward and as long as the side.
    alone = sorted((k, pts[b][1] - pts[a][1], pts[a][0] - pts[b][0]) for ks in sides.values() if len(ks) == 1
                   for k, a, b in ks)
    rays = sorted(zip(t["voronoi_ray_origins"].tolist(), *t["voronoi_ray_directions"].T.tolist()))
    assert len(alone) >= 8 and rays == alone


def test_the_package_calls_on_degenerate_input_warn_and_return_nothing():
    line = [[0, 0], [1, 1], [2, 2], [3, 3]]
    with pytest.warns(ridt.DegenerateInputWarning, match="delaunay"):
        assert triangle.delaunay(line).shape == (0, 3)
    with pytest.warns(ridt.DegenerateInputWarning):
        assert triangle.convex_hull(line).shape == (0, 2)
    with pytest.warns(ridt.DegenerateInputWarning):
        assert [a.shape for a in triangle.voronoi(line)] == [(0, 2), (0, 2), (0,), (0, 2)]
    with pytest.raises(ValueError):
        triangle.delaunay([[0, 0], [1, np.nan], [2, 0]])


def test_six_node_triangles():
    tri = {"vertices": np.array(SQUARE + HOLE, dtype=float), "segments": np.array(loop(0) + loop(4)),
           "holes": [[5, 5]], "segment_markers": [5, 0, 0, 0, 0, 0, 0, 0]}
    pts = tri["vertices"]
    tri["vertex_attributes"] = np.stack([2 * pts[:, 0] + 3 * pts[:, 1] + 1, np.full(len(pts), 7.0)], axis=1)
    three, six = triangle.triangulate(tri, "pq30a4"), triangle.triangulate(tri, "pq30a4o2")
    t, v = six["triangles"], six["vertices"]
    assert t.dtype == np.intc and t.shape == (len(three["triangles"]), 6)
    np.testing.assert_array_equal(t[:, :3], three["triangles"])  # the same corners
    first = len(three["vertices"])
    np.testing.assert_array_equal(v[:first], three["vertices"])
    middle = {}
    for row in t.tolist():
        for k in range(3):
            a, b, m = row[(k + 1) % 3], row[(k + 2) % 3], row[3 + k]
            assert middle.setdefault(frozenset((a, b)), m) == m  # one node an edge, shared
            assert tuple(v[m]) == ((v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2)
    assert sorted(middle.values()) == list(range(first, len(v)))
    # Markers by the vertices' rule: 5 along y = 0 (the marked segment), 1 elsewhere on the
    # boundary (the hole's too), 0 inside; attributes linear, so the means are exact.
    x, y = v[first:, 0], v[first:, 1]
    boundary = (x == 0) | (x == 10) | (y == 10) | (((x == 4) | (x == 6)) & (y >= 4) & (y <= 6)) | \
               (((y == 4) | (y == 6)) & (x >= 4) & (x <= 6))
    want = np.where(y == 0, 5, boundary.astype(int))
    np.testing.assert_array_equal(six["vertex_markers"][first:, 0], want)
    np.testing.assert_allclose(six["vertex_attributes"][:, 0], 2 * v[:, 0] + 3 * v[:, 1] + 1, rtol=0, atol=1e-12)
    # The class gives the same.
    cdt = ridt.ConstrainedDelaunay(pts, tri["segments"], holes=[[5, 5]], convex_hull=False, min_angle=30,
                                   max_area=4)
    points, simplices = cdt.second_order()
    np.testing.assert_array_equal(points, v)
    np.testing.assert_array_equal(simplices, t)
    with pytest.raises(ValueError, match="o2 only"):
        triangle.triangulate(tri, "po3")


def test_the_dual_carries_the_vertices_attributes_at_the_centres():
    # Attributes linear in the position come out so at every centre, those outside their
    # triangle (a mesh without quality: thin triangles) too; without attributes, no key.
    pts = np.array([[0, 0], [4, 0], [4, 1], [0, 1], [2, 0.1], [1, 0.95]])
    linear = np.column_stack([2 * pts[:, 0] + 3 * pts[:, 1] + 1, -pts[:, 0]])
    t = triangle.triangulate({"vertices": pts, "vertex_attributes": linear}, "v")
    c = t["voronoi_vertices"]
    expected = np.column_stack([2 * c[:, 0] + 3 * c[:, 1] + 1, -c[:, 0]])
    np.testing.assert_allclose(t["voronoi_attributes"], expected, rtol=1e-12, atol=1e-12)
    assert ((c[:, 1] < 0) | (c[:, 1] > 1)).any()  # some centres outside the points' box
    assert "voronoi_attributes" not in triangle.triangulate({"vertices": pts}, "v")
