"""ridt.triangle's calls beyond triangulate, as the `triangle` package has them: loads and load
(Triangle's files read by the tool's readers), get_data and its directory, and the drawings
plot, compare and comparev; and the package's documented scripts run with only their import
changed."""

import os
import subprocess
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.collections import LineCollection, PathCollection  # noqa: E402

from ridt import triangle as tr  # noqa: E402

# A 4 x 4 square with a square hole, numbered from 1: x, y, one attribute, a marker.
SQUARE_NODE = """# the square's corners, then the hole's
8 2 1 1
1 0 0 0.5 1
2 4 0 1.5 1
3 4 4 2.5 1   # a comment after a record
4 0 4 3.5 1
5 1.5 1.5 0 2
6 2.5 1.5 0 2
7 2.5 2.5 0 2
8 1.5 2.5 0 2
"""
SQUARE_POLY = """0 2 1 1   # the vertices are the .node's
8 1
1 1 2 5
2 2 3 5
3 3 4 5
4 4 1 5
5 5 6 0
6 6 7 0
7 7 8 0
8 8 5 0
1
1 2 2
2
1 0.5 0.5 7 0.25
2 3.5 3.5 9
"""
SQUARE = {
    "vertices": [[0, 0], [4, 0], [4, 4], [0, 4], [1.5, 1.5], [2.5, 1.5], [2.5, 2.5], [1.5, 2.5]],
    "vertex_attributes": [[0.5], [1.5], [2.5], [3.5], [0], [0], [0], [0]],
    "vertex_markers": [[1]] * 4 + [[2]] * 4,
    "segments": [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]],
    "segment_markers": [[5]] * 4 + [[0]] * 4,
    "holes": [[2, 2]],
    "regions": [[0.5, 0.5, 7, 0.25], [3.5, 3.5, 9, -1]],
}
FLOATS = {"vertices", "vertex_attributes", "holes", "regions", "triangle_attributes", "triangle_max_area",
          "ray_directions"}


def assert_dict(got, expected):
    """`got` has exactly `expected`'s keys, each array equal, float64 or intc as the package's."""
    assert set(got) == set(expected)
    for key, value in expected.items():
        dtype = np.float64 if key in FLOATS else np.intc
        assert got[key].dtype == dtype, key
        np.testing.assert_array_equal(got[key], np.asarray(value, dtype=dtype), err_msg=key)


def test_loads_a_poly_numbered_from_one_with_the_vertices_of_its_node():
    assert_dict(tr.loads(node=SQUARE_NODE, poly=SQUARE_POLY), SQUARE)
    node_only = {k: SQUARE[k] for k in ("vertices", "vertex_attributes", "vertex_markers")}
    assert_dict(tr.loads(node=SQUARE_NODE), node_only)
    assert_dict(tr.loads(node=SQUARE_NODE, ele="", area=None), node_only)  # empty text: none


def test_loads_a_poly_numbered_from_zero_that_lists_its_vertices():
    poly = """4 2 0 0
0 0 0
1 1 0
2 1 1
3 0 1
4 0
0 0 1
1 1 2
2 2 3
3 3 0
0
"""
    assert_dict(tr.loads(poly=poly), {"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]],
                                      "segments": [[0, 1], [1, 2], [2, 3], [3, 0]]})
    # Its vertices replace the .node's, with their keys.
    assert_dict(tr.loads(node=SQUARE_NODE, poly=poly), tr.loads(poly=poly))


def test_loads_ele_with_attributes_and_six_node_ele():
    ele = "2 3 2\n1 1 2 3 7 0.5\n2 1 3 4 8 -0.5\n"
    got = tr.loads(node=SQUARE_NODE, ele=ele)
    np.testing.assert_array_equal(got["triangles"], [[0, 1, 2], [0, 2, 3]])
    assert got["triangles"].dtype == np.intc
    np.testing.assert_array_equal(got["triangle_attributes"], [[7, 0.5], [8, -0.5]])
    # Numbered from 0, without a .node: the indices as they are.
    got = tr.loads(ele="1 3 0\n0 0 1 2\n")
    assert_dict(got, {"triangles": [[0, 1, 2]]})
    # Six nodes a triangle (Triangle's -o2): the corners, then the middles across from them.
    node = "6 2 0 0\n1 0 0\n2 2 0\n3 0 2\n4 1 1\n5 0 1\n6 1 0\n"
    got = tr.loads(node=node, ele="1 6 0\n1 1 2 3 4 5 6\n")
    assert_dict(got, {"vertices": [[0, 0], [2, 0], [0, 2], [1, 1], [0, 1], [1, 0]],
                      "triangles": [[0, 1, 2, 3, 4, 5]]})


def test_loads_area_and_neigh():
    ele = "3 3 0\n1 1 2 3\n2 1 3 4\n3 1 4 2\n"
    area = "3\n1 0.5\n2 -1\n3 2.25\n"
    neigh = "3 3\n1 -1 3 2\n2 -1 1 3\n3 -1 2 1\n"
    got = tr.loads(node=SQUARE_NODE, ele=ele, area=area, neigh=neigh)
    np.testing.assert_array_equal(got["triangle_max_area"], [[0.5], [-1], [2.25]])
    assert got["triangle_max_area"].dtype == np.float64
    np.testing.assert_array_equal(got["triangle_neighbors"], [[-1, 2, 1], [-1, 0, 2], [-1, 1, 0]])
    assert got["triangle_neighbors"].dtype == np.intc
    # Without vertices, a .neigh is numbered as its records are.
    assert_dict(tr.loads(neigh=neigh), {"triangle_neighbors": [[-1, 2, 1], [-1, 0, 2], [-1, 1, 0]]})
    assert_dict(tr.loads(area="1\n0 4\n"), {"triangle_max_area": [[4]]})


def test_loads_a_voronoi_edge_file_with_rays_and_an_edge_file_with_markers():
    vnode = "3 2 0 0\n1 0.5 0.5\n2 1.5 0.5\n3 1 2\n"
    vedge = "# a Voronoi diagram's edges\n4 0\n1 1 2\n2 1 -1 -1 0\n3 2 -1 0.5 -1\n4 3 -1 0 1\n"
    assert_dict(tr.loads(node=vnode, edge=vedge), {
        "vertices": [[0.5, 0.5], [1.5, 0.5], [1, 2]], "edges": [[0, 1]], "ray_origins": [[0], [1], [2]],
        "ray_directions": [[-1, 0], [0.5, -1], [0, 1]]})
    edge = "3 1\n0 0 1 1\n1 1 2 0\n2 2 0 3\n"
    assert_dict(tr.loads(edge=edge), {"edges": [[0, 1], [1, 2], [2, 0]], "edge_markers": [[1], [0], [3]]})
    # Markers declared: a ray's is read and not kept.
    edge = "2 1\n1 1 2 4\n2 3 -1 1e-3 0 7\n"
    assert_dict(tr.loads(node=vnode, edge=edge), {
        "vertices": [[0.5, 0.5], [1.5, 0.5], [1, 2]], "edges": [[0, 1]], "edge_markers": [[4]],
        "ray_origins": [[2]], "ray_directions": [[1e-3, 0]]})


@pytest.mark.parametrize("files, message", [
    ({"node": "3 2 0 0\n1 0 0\n2 1 x\n3 0 1\n"}, 'the .node text:3: coordinate "x" is not a number'),
    ({"node": "3 2 0 0\n1 0 0\n2 1 0\n"}, "the .node text: the file ends before its 3 vertices"),
    ({"poly": SQUARE_POLY}, "the .poly text:1: the file lists no vertices and no .node text is given"),
    ({"node": SQUARE_NODE, "poly": SQUARE_POLY.replace("8 8 5 0", "8 8 9 0")}, "segment end 9 is not a vertex"),
    ({"node": SQUARE_NODE, "ele": "1 3 0\n1 0 1 2\n"}, "the .ele text:2: vertex index 0 is below the first index 1"),
    ({"ele": "1 3 0\n0 0 1 2\n", "area": "2\n0 1\n1 1\n"}, "the file bounds 2 triangles; the mesh has 1"),
    ({"ele": "1 3 0\n0 0 1 2\n", "neigh": "2 3\n0 -1 -1 1\n1 -1 -1 0\n"}, "2 triangles, but the .ele text has 1"),
    ({"area": "1\n3 1\n"}, "the .area text:2: the first triangle index must be 0 or 1, got 3"),
    ({"neigh": "1 3\n0 -1 -1 1\n"}, "neighbour 1 is neither -1 nor one of the 1 triangles numbered from 0"),
    ({"node": SQUARE_NODE, "edge": "1 0\n1 1 9\n"}, "the .edge text:2: edge end 9 is not a vertex"),
    ({"edge": "1 0\n0 1 -1 0\n"}, 'expected a ray "index a -1 dx dy [marker]"'),
])
def test_malformed_text_raises_value_error_with_the_readers_message(files, message):
    with pytest.raises(ValueError) as e:
        tr.loads(**files)
    assert message in str(e.value)


def test_loads_refuses_what_is_not_text():
    with pytest.raises(TypeError, match="text of a .node file"):
        tr.loads(node=3)


def write(directory, name, **texts):
    for ext, text in texts.items():
        (directory / f"{name}.{ext}").write_text(text)


def test_load_reads_the_files_of_a_name(tmp_path):
    write(tmp_path, "square", node=SQUARE_NODE, poly=SQUARE_POLY)
    write(tmp_path, "other", node="3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n")
    assert_dict(tr.load(tmp_path, "square"), SQUARE)
    assert_dict(tr.load(str(tmp_path), "other"), {"vertices": [[0, 0], [1, 0], [0, 1]]})
    write(tmp_path, "bad", node="3 2 0 0\n0 0 0\n1 1 0\n")
    with pytest.raises(ValueError, match=r"bad\.node: the file ends before its 3 vertices"):
        tr.load(tmp_path, "bad")  # the message names the file
    with pytest.raises(FileNotFoundError, match="missing"):
        tr.load(tmp_path, "missing")


def triangle_files(t, first):
    """Triangle's .node, .poly, .ele, .edge and .neigh texts of a dict triangulate returned,
    numbered from `first`, as Triangle writes them."""
    v, attrs, markers = t["vertices"], t["vertex_attributes"], t["vertex_markers"]
    node = [f"{len(v)} 2 {attrs.shape[1]} 1"]
    node += [" ".join([str(i + first), *map(repr, v[i]), *map(repr, attrs[i]), str(markers[i, 0])])
             for i in range(len(v))]
    poly = ["0 2 0 1", f"{len(t['segments'])} 1"]
    poly += [f"{i + first} {a + first} {b + first} {m}" for i, ((a, b), m) in
             enumerate(zip(t["segments"], t["segment_markers"][:, 0]))]
    poly += [f"{len(t['holes'])}"] + [f"{i + first} {x!r} {y!r}" for i, (x, y) in enumerate(t["holes"])]
    ele = [f"{len(t['triangles'])} 3 1"]
    ele += [f"{i + first} {a + first} {b + first} {c + first} {w!r}" for i, ((a, b, c), w) in
            enumerate(zip(t["triangles"], t["triangle_attributes"][:, 0]))]
    edge = [f"{len(t['edges'])} 1"] + [f"{i + first} {a + first} {b + first} {m}" for i, ((a, b), m) in
                                       enumerate(zip(t["edges"], t["edge_markers"][:, 0]))]
    neigh = [f"{len(t['neighbors'])} 3"] + [" ".join(str(n + first if n >= 0 else -1) for n in [i, *row])
                                            for i, row in enumerate(t["neighbors"])]
    return {ext: "\n".join(lines) + "\n" for ext, lines in
            (("node", node), ("poly", poly), ("ele", ele), ("edge", edge), ("neigh", neigh))}


@pytest.mark.parametrize("first", [0, 1])
def test_files_written_by_hand_from_a_mesh_read_back_as_its_dict(first):
    t = tr.triangulate(tr.loads(node=SQUARE_NODE, poly=SQUARE_POLY), "pq30a0.5Aen")
    assert len(t["triangles"]) > 20
    got = tr.loads(**triangle_files(t, first))
    keys = ["vertices", "vertex_attributes", "vertex_markers", "segments", "segment_markers", "holes", "triangles",
            "triangle_attributes", "edges", "edge_markers"]
    assert_dict(got, {**{k: t[k] for k in keys}, "triangle_neighbors": t["neighbors"]})
    for k in keys:
        assert got[k].dtype == t[k].dtype, k


def test_a_voronoi_diagram_written_by_hand_reads_back():
    pts = np.random.default_rng(5).random((40, 2))
    points, edges, origins, directions = tr.voronoi(pts)
    node = [f"{len(points)} 2 0 0"] + [f"{i + 1} {x!r} {y!r}" for i, (x, y) in enumerate(points)]
    lines = [f"{a + 1} {b + 1}" for a, b in edges] + [f"{o + 1} -1 {dx!r} {dy!r}" for o, (dx, dy) in
                                                       zip(origins, directions)]
    edge = [f"{len(lines)} 0"] + [f"{i + 1} {line}" for i, line in enumerate(lines)]
    got = tr.loads(node="\n".join(node), edge="\n".join(edge))
    assert_dict(got, {"vertices": points, "edges": edges, "ray_origins": origins.reshape(-1, 1),
                      "ray_directions": directions})


def test_get_data_reads_the_directory_the_user_names(tmp_path, monkeypatch):
    write(tmp_path, "square", node=SQUARE_NODE, poly=SQUARE_POLY)
    monkeypatch.delenv("RIDT_TRIANGLE_DATA", raising=False)
    monkeypatch.setattr(tr, "data_dir", None)
    with pytest.raises(FileNotFoundError) as e:
        tr.get_data("square")
    assert "RIDT_TRIANGLE_DATA" in str(e.value) and "ridt.triangle.data_dir" in str(e.value)
    monkeypatch.setattr(tr, "data_dir", str(tmp_path))
    assert tr.get_data_dir() == str(tmp_path)
    assert_dict(tr.get_data("square"), SQUARE)
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    write(elsewhere, "square", node="3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n")
    monkeypatch.setenv("RIDT_TRIANGLE_DATA", str(elsewhere))  # the variable before data_dir
    assert tr.get_data_dir() == str(elsewhere)
    assert_dict(tr.get_data("square"), {"vertices": [[0, 0], [1, 0], [0, 1]]})
    with pytest.raises(FileNotFoundError, match="A"):
        tr.get_data("A")


def test_show_data_plots_and_shows(tmp_path, monkeypatch):
    write(tmp_path, "square", node=SQUARE_NODE, poly=SQUARE_POLY)
    monkeypatch.setenv("RIDT_TRIANGLE_DATA", str(tmp_path))
    shown = []
    monkeypatch.setattr(plt, "show", lambda *a, **k: shown.append(plt.gcf()))
    plt.close("all")
    tr.show_data("square")
    assert len(shown) == 1
    ax = shown[0].axes[0]
    assert len(ax.collections) == 3  # vertices, segments, holes
    plt.close("all")


def kinds(ax):
    """The Axes' collections by kind: scatters (PathCollection) and LineCollections."""
    return ([c for c in ax.collections if isinstance(c, PathCollection)],
            [c for c in ax.collections if isinstance(c, LineCollection)])


def test_plot_draws_a_mesh_from_triangulate():
    t = tr.triangulate(tr.loads(node=SQUARE_NODE, poly=SQUARE_POLY), "pq30a0.5")
    fig, ax = plt.subplots()
    tr.plot(ax, labels=True, markers=True, **t)
    scatters, lines = kinds(ax)
    assert len(scatters) == 2 and len(lines) == 1  # vertices and holes; segments
    vertices, holes = scatters
    assert len(vertices.get_offsets()) == len(t["vertices"]) and holes.get_offsets().tolist() == [[2.0, 2.0]]
    assert holes.get_facecolor()[0].tolist() == [1, 0, 0, 1]
    segments = lines[0]
    assert len(segments.get_segments()) == len(t["segments"]) and segments.get_linewidth()[0] == 3
    assert segments.get_color()[0].tolist() == [1, 0, 0, 1] and segments.get_zorder() < vertices.get_zorder()
    assert len(ax.lines) == 2  # triplot's edges and nodes
    edges = {tuple(sorted(e)) for tri in t["triangles"] for e in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0]))}
    assert np.isfinite(ax.lines[0].get_xydata()).all(axis=1).sum() == 2 * len(edges)
    assert len(ax.texts) == 2 * len(t["vertices"])  # the indices and the markers
    assert [x.get_text() for x in ax.texts[:3]] == ["0", "1", "2"]
    assert ax.texts[len(t["vertices"])].get_text() == str(t["vertex_markers"][0, 0])
    assert not ax.get_xaxis().get_visible() and not ax.get_yaxis().get_visible() and ax.get_aspect() == 1
    plt.close(fig)


def test_plot_draws_the_corners_of_six_node_triangles():
    t = tr.triangulate({"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]]}, "o2")
    assert t["triangles"].shape == (2, 6)
    fig, ax = plt.subplots()
    tr.plot(ax, **t)
    xy = ax.lines[0].get_xydata()
    assert len(xy[np.isfinite(xy).all(axis=1)]) == 2 * 5  # the 5 edges of the corners
    assert len(kinds(ax)[0][0].get_offsets()) == 9  # every node a dot
    plt.close(fig)


def test_plot_draws_a_voronoi_diagram_with_rays_that_leave_the_view():
    pts = np.random.default_rng(2).random((25, 2))
    points, edges, origins, directions = tr.voronoi(pts)
    fig, ax = plt.subplots()
    tr.plot(ax, vertices=pts)
    tr.plot(ax, vertices=points, edges=edges)
    view = ax.axis()
    tr.plot(ax, vertices=points, edges=edges, ray_origins=origins, ray_directions=directions)
    assert ax.axis() == pytest.approx(view)
    scatters, lines = kinds(ax)
    assert len(scatters) == 3 and len(lines) == 3  # each call's edges; the rays
    rays = np.array(lines[2].get_segments())
    assert len(rays) == len(origins) and len(lines[1].get_segments()) == len(edges)
    np.testing.assert_allclose(rays[:, 0], points[origins])
    x0, x1, y0, y1 = view
    ends = rays[:, 1]
    assert ((ends[:, 0] < x0) | (ends[:, 0] > x1) | (ends[:, 1] < y0) | (ends[:, 1] > y1)).all()
    plt.close(fig)


def test_compare_and_comparev():
    A = tr.loads(node=SQUARE_NODE, poly=SQUARE_POLY)
    B = tr.triangulate(A, "pq30a0.5")
    plt.close("all")
    tr.compare(plt, A, B, figsize=(5, 2))
    fig = plt.gcf()
    ax1, ax2 = fig.axes
    assert fig.get_size_inches().tolist() == [5, 2]
    assert ax1.get_shared_x_axes().joined(ax1, ax2) and ax1.get_shared_y_axes().joined(ax1, ax2)
    assert len(ax1.lines) == 0 and len(ax2.lines) == 2 and len(ax1.collections) == len(ax2.collections) == 3
    pts = np.random.default_rng(4).random((30, 2)) * 4
    A = tr.triangulate({"vertices": pts})
    points, edges, origins, directions = tr.voronoi(pts)
    tr.comparev(plt, A, dict(vertices=points, edges=edges, ray_origins=origins, ray_directions=directions))
    fig = plt.gcf()
    ax1, ax2 = fig.axes
    assert fig.get_size_inches().tolist() == [6, 3]
    assert ax1.axis() == ax2.axis()
    x0, x1, y0, y1 = ax1.axis()
    assert x0 <= pts[:, 0].min() and x1 >= pts[:, 0].max() and x1 - x0 < 4.5  # A's view
    assert len(kinds(ax2)[1]) == 2 and len(kinds(ax2)[1][1].get_segments()) == len(origins)
    plt.close("all")


DOTS = "\n".join(["20 2 0 0"] + [f"{i} {x!r} {y!r}" for i, (x, y) in
                                 enumerate(np.random.default_rng(9).random((20, 2)).tolist())]) + "\n"

SCRIPTS = {
    "quality": """
        A = tr.get_data('square')
        B = tr.triangulate(A, 'pq30a0.1')
        tr.compare(plt, A, B)
        plt.savefig(OUT)
        print(len(A['vertices']), len(B['triangles']), B['triangles'].max() < len(B['vertices']))
    """,
    "voronoi": """
        pts = tr.get_data('dots')['vertices']
        A = dict(vertices=pts)
        points, edges, ray_origin, ray_direct = tr.voronoi(pts)
        B = dict(vertices=points, edges=edges, ray_origins=ray_origin, ray_directions=ray_direct)
        tr.comparev(plt, A, B)
        plt.savefig(OUT)
        print(len(pts), len(edges) + len(ray_origin), 1)
    """,
    "refine": """
        A = tr.get_data('square')
        B = tr.triangulate(A, 'p')
        C = tr.triangulate(B, 'rpa0.2')
        tr.compare(plt, B, C)
        plt.savefig(OUT)
        print(len(B['triangles']), len(C['triangles']), (C['vertices'][:len(B['vertices'])] == B['vertices']).all())
    """,
}


@pytest.mark.parametrize("name", sorted(SCRIPTS))
def test_the_packages_documented_scripts_run_with_only_the_import_changed(tmp_path, name):
    write(tmp_path, "square", node=SQUARE_NODE, poly=SQUARE_POLY)
    write(tmp_path, "dots", node=DOTS)
    out = tmp_path / f"{name}.png"
    script = "import matplotlib.pyplot as plt\nimport ridt.triangle as tr\n\n"
    script += f"OUT = {str(out)!r}\n" + textwrap.dedent(SCRIPTS[name])
    env = dict(os.environ, RIDT_TRIANGLE_DATA=str(tmp_path), MPLBACKEND="Agg")
    run = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    first, second, third = run.stdout.split()
    assert out.stat().st_size > 1000 and out.read_bytes()[:4] == b"\x89PNG"
    if name == "quality":
        assert first == "8" and int(second) > 100 and third == "True"  # 12 square units, 0.1 at most each
    elif name == "voronoi":
        assert first == "20" and int(second) >= 20  # at least one Voronoi edge per point
    else:
        assert int(second) > int(first) and third == "True"  # refined: more triangles, the vertices kept


def _circle(n, radius):
    i = np.arange(n)
    theta = i * 2 * np.pi / n
    return np.stack([np.cos(theta), np.sin(theta)], axis=1) * radius, np.stack([i, i + 1], axis=1) % n


def _boxes():
    vertices, segments, regions = [], [], []
    for x, y, w, h, attribute in [(0, 0, 5, 5, 1), (1, 1, 3, 1, 2), (1, 3, 1, 1, 3), (3, 3, 1, 1, 4)]:
        i = len(vertices)
        vertices += [[x, y], [x + w, y], [x + w, y + h], [x, y + h]]
        segments += [(i, i + 1), (i + 1, i + 2), (i + 2, i + 3), (i + 3, i)]
        regions.append([x + 0.5 * w, y + 0.5 * h, attribute, 0])
    return dict(vertices=vertices, segments=segments, regions=regions)


def _annulus():
    outer, outer_segments = _circle(30, 1.4)
    inner, inner_segments = _circle(16, 0.6)
    return dict(vertices=np.vstack([outer, inner]), segments=np.vstack([outer_segments, inner_segments + 30]),
                holes=[[0, 0]])


UNIT_SQUARE = dict(vertices=np.array(((0, 0), (1, 0), (1, 1), (0, 1)), dtype=float))
THIRTY_TWO_GON = dict(vertices=np.vstack((np.cos(np.linspace(0, 2 * np.pi, 33)[:-1]),
                                          np.sin(np.linspace(0, 2 * np.pi, 33)[:-1]))).T)
# The package's documented examples with their data in the script (its simple examples: a square,
# a 32-gon's points, an annulus with a hole, boxes with regional attributes), each with the
# smallest angle and the largest area its switches ask, and Triangle's triangle count for the
# same input and switches (`triangle -Q...` of it written as .node or .poly).
DOCUMENTED = [
    ("square q", UNIT_SQUARE, "q", 20, 0, 2),
    ("square qa0.1", UNIT_SQUARE, "qa0.1", 20, 0.1, 16),
    ("square qa0.01", UNIT_SQUARE, "qa0.01", 20, 0.01, 150),
    ("32-gon q", THIRTY_TWO_GON, "q", 20, 0, 56),
    ("32-gon qa0.05", THIRTY_TWO_GON, "qa0.05", 20, 0.05, 102),
    ("annulus qpa0.05", _annulus(), "qpa0.05", 20, 0.05, 170),
    ("boxes pA", _boxes(), "pA", 0, 0, 26),
]


@pytest.mark.parametrize("name, data, switches, angle, area, theirs", DOCUMENTED, ids=[d[0] for d in DOCUMENTED])
def test_the_packages_documented_examples_take_no_more_triangles_than_triangle(name, data, switches, angle, area,
                                                                             theirs):
    t = tr.triangulate(data, switches)
    p = t["vertices"][t["triangles"]]
    u, w = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    doubled = u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0]
    assert (doubled > 0).all()
    if area:
        assert doubled.max() / 2 <= area
    smallest = 180.0
    for i in range(3):
        u, w = p[:, (i + 1) % 3] - p[:, i], p[:, (i + 2) % 3] - p[:, i]
        smallest = min(smallest, float(np.degrees(np.arctan2(np.abs(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0]),
                                                                (u * w).sum(axis=1))).min()))
    assert smallest >= angle - 1e-9  # no input angle below the bound in these
    assert len(t["triangles"]) <= 1.03 * theirs, (len(t["triangles"]), theirs)
