"""ridt.triangulate_out_of_core: the strips' union is the triangulation of the whole set."""

import os

import numpy as np
import pytest

import ridt
from conftest import triangle_set


def read_parts(index):
    """The triangles of every part that `index` (OUT.parts) names, as one (n, 3) array."""
    with open(index) as f:
        head = f.readline().split()
        names = [line.strip() for line in f if line.strip()]
    assert head[:2] == ["ridt", "parts"] and int(head[2]) == len(names)
    folder = os.path.dirname(index)
    parts = [np.fromfile(os.path.join(folder, name), dtype=np.uint32).reshape(-1, 3) for name in names]
    return np.concatenate(parts)


def clustered_with_ties(rng, n):
    # Gaussian clusters, an integer grid (four points on every circle through a square) and
    # repeated points: the strips must break every tie as one triangulation of the whole does.
    centres = rng.random((20, 2)) * 100
    pts = centres[rng.integers(0, 20, n // 2)] + rng.normal(0, 0.5, (n // 2, 2))
    g = np.arange(60, dtype=float)
    grid = np.stack(np.meshgrid(g, g), -1).reshape(-1, 2) + 20
    return np.concatenate([pts, grid, pts[:500]])


@pytest.mark.parametrize("threads", [1, 2])
def test_parts_are_the_triangulation_of_the_whole(tmp_path, threads):
    pts = clustered_with_ties(np.random.default_rng(3), 60_000)
    pts.tofile(tmp_path / "p.bin")
    stats = ridt.triangulate_out_of_core(tmp_path / "p.bin", tmp_path / "o.parts", threads=threads,
                                         column_points=500)
    assert stats["points"] == len(pts) and stats["strips"] > 3
    got = read_parts(tmp_path / "o.parts")
    assert stats["triangles"] == len(got)
    # Each triangle starts at its smallest index, and only one strip wrote it.
    assert (got[:, 0] < got[:, 1]).all() and (got[:, 0] < got[:, 2]).all()
    assert len(triangle_set(got)) == len(got)
    assert triangle_set(got) == triangle_set(ridt.Delaunay(pts).simplices)
    assert ridt.check(pts, got)[0]


def test_far_off_thin_sets_and_the_memory_limit(tmp_path):
    pts = np.random.default_rng(8).random((40_000, 2)) * [1e6, 1] + [5e8, -3e7]  # long, thin, far off
    pts.tofile(tmp_path / "p.bin")
    stats = ridt.triangulate_out_of_core(tmp_path / "p.bin", tmp_path / "o.parts", memory_limit=64 << 20,
                                         column_points=400)
    assert stats["strips"] > 3
    assert triangle_set(read_parts(tmp_path / "o.parts")) == triangle_set(ridt.Delaunay(pts).simplices)
    with pytest.raises(ValueError, match="memory limit of at least"):
        ridt.triangulate_out_of_core(tmp_path / "p.bin", tmp_path / "small.parts", memory_limit=1 << 20)
    assert not (tmp_path / "small.parts").exists()


def test_bad_input_raises_and_leaves_nothing(tmp_path):
    with pytest.raises(OSError, match="missing.bin"):
        ridt.triangulate_out_of_core(tmp_path / "missing.bin", tmp_path / "o.parts")
    (tmp_path / "odd.bin").write_bytes(b"\0" * 24)  # one and a half points
    with pytest.raises(ValueError, match="not a multiple of 16"):
        ridt.triangulate_out_of_core(tmp_path / "odd.bin", tmp_path / "o.parts")
    np.array([[0.0, 0.0], [np.nan, 1.0], [1.0, 1.0]]).tofile(tmp_path / "nan.bin")
    with pytest.raises(ValueError, match="point 1 has a NaN"):
        ridt.triangulate_out_of_core(tmp_path / "nan.bin", tmp_path / "o.parts")
    with pytest.raises(ValueError, match="memory_limit"):
        ridt.triangulate_out_of_core(tmp_path / "odd.bin", tmp_path / "o.parts", memory_limit=0)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["nan.bin", "odd.bin"]


def test_an_unwritable_output_raises_oserror(tmp_path):
    np.random.default_rng(2).random((1000, 2)).tofile(tmp_path / "p.bin")
    with pytest.raises(OSError):
        ridt.triangulate_out_of_core(tmp_path / "p.bin", tmp_path / "no" / "such" / "o.parts")
