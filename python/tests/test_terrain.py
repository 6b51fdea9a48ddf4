"""ridt.terrain: LAS files written here byte by byte (versions 1.0 to 1.4, point formats 0, 1
and 6), damaged ones, a DEM equal to the linear interpolant at the cells' centres (and to
scipy's where both answer), duplicates merged, long edges killed, GeoTIFF read back with GDAL."""

import math
import struct

import numpy as np
import pytest
from osgeo import gdal  # a test dependency (python3-gdal): missing, the tests fail

import ridt
from ridt import terrain


def las_bytes(xyz, minor=2, fmt=0, classes=None, wkt=None, scale=0.001, offset=(0.0, 0.0, 0.0)):
    """A LAS file after the ASPRS specification: header, an optional WKT record, the points."""
    sizes = {0: 20, 1: 28, 6: 30}
    header = {0: 227, 1: 227, 2: 227, 3: 235, 4: 375}[minor]
    vlr = b""
    if wkt is not None:
        body = wkt.encode() + b"\0"
        vlr = struct.pack("<H16sHH32s", 0, b"LASF_Projection", 2112, len(body), b"") + body
    n = len(xyz)
    h = bytearray(header)
    h[0:4] = b"LASF"
    h[24], h[25] = 1, minor
    struct.pack_into("<HII", h, 94, header, header + len(vlr), 1 if vlr else 0)
    struct.pack_into("<BHI", h, 104, fmt, sizes[fmt], 0 if (minor == 4 and fmt >= 6) else n)
    struct.pack_into("<3d3d", h, 131, scale, scale, scale, *offset)
    if minor == 4:
        struct.pack_into("<Q", h, 247, n)
    out = bytes(h) + vlr
    for k, (x, y, z) in enumerate(xyz):
        ints = [round((v - o) / scale) for v, o in zip((x, y, z), offset)]
        rec = bytearray(sizes[fmt])
        struct.pack_into("<3i", rec, 0, *ints)
        cls = 2 if classes is None else classes[k]
        if fmt >= 6:
            rec[14], rec[16] = 1 | (1 << 4), cls
        else:
            rec[14], rec[15] = 1 | (1 << 3), cls
        out += bytes(rec)
    return out


def sample(n=1500, seed=4):
    rng = np.random.default_rng(seed)
    xy = np.round(rng.random((n, 2)) * 200, 3)
    z = np.round(50 + 10 * np.sin(xy[:, 0] / 13) + 0.1 * xy[:, 1], 3)
    return xy, z


@pytest.mark.parametrize("minor,fmt", [(0, 0), (2, 1), (3, 0), (4, 1), (4, 6)])
def test_las_read_back(tmp_path, minor, fmt):
    xy, z = sample(300)
    xyz = np.column_stack([xy + [500000, 4000000], z])
    p = tmp_path / "t.las"
    p.write_bytes(las_bytes(xyz, minor, fmt, wkt='PROJCS["x"]', offset=(500000.0, 4000000.0, 0.0)))
    got = terrain.read_las(p)
    np.testing.assert_allclose(got.xyz, xyz, rtol=0, atol=1e-6)
    assert got.crs == 'PROJCS["x"]'


def test_las_class_filter_and_errors(tmp_path):
    xy, z = sample(10)
    p = tmp_path / "t.las"
    p.write_bytes(las_bytes(np.column_stack([xy, z]), classes=[2, 5] * 5))
    assert len(terrain.read_las(p, classes=[2]).xyz) == 5
    assert len(terrain.read_las(p, classes=[5, 2]).xyz) == 10
    with pytest.raises(ValueError, match="returns"):
        terrain.read_las(p, returns="second")
    with pytest.raises(FileNotFoundError):
        terrain.read_las(tmp_path / "missing.las")
    cut = tmp_path / "cut.las"
    cut.write_bytes(p.read_bytes()[:-7])
    with pytest.raises(ValueError, match="truncated"):
        terrain.read_las(cut)
    laz = bytearray(p.read_bytes())
    laz[104] |= 0x80
    (tmp_path / "c.las").write_bytes(bytes(laz))
    with pytest.raises(ValueError, match="laszip"):
        terrain.read_las(tmp_path / "c.las")


def test_dem_is_the_linear_interpolant_at_the_centres():
    xy, z = sample()
    r = terrain.dem(xy, z, resolution=3.0, threads=2)
    cx, cy = r.centres()
    gx, gy = np.meshgrid(cx, cy)
    q = np.column_stack([gx.ravel(), gy.ravel()])
    want = ridt.LinearNDInterpolator(xy, z)(q).reshape(r.values.shape)
    np.testing.assert_array_equal(r.values, want)  # NaN where both have none
    assert np.isnan(r.values).any() and np.isfinite(r.values).mean() > 0.9
    # scipy (Qhull, floating point) agrees where both answer, to rounding.
    from scipy.interpolate import LinearNDInterpolator
    s = LinearNDInterpolator(xy, z)(gx, gy)
    both = np.isfinite(s) & np.isfinite(r.values)
    assert both.mean() > 0.9
    assert np.abs(s[both] - r.values[both]).max() <= 1e-9 * np.abs(z).max()
    assert r.transform == (0.0, 3.0, 0.0, 201.0, 0.0, -3.0)
    # An (n, 3) array is the same call.
    np.testing.assert_array_equal(terrain.dem(np.column_stack([xy, z]), resolution=3.0).values, r.values)


def test_dem_methods_nearest_and_natural_take_data_values():
    xy, z = sample(400)
    near = terrain.dem(xy, z, resolution=5.0, method="nearest")
    inside = np.isfinite(near.values)
    assert np.isin(near.values[inside], z).all()
    nat = terrain.dem(xy, z, resolution=5.0, method="natural")
    assert (np.isfinite(nat.values) == inside).all()
    assert nat.values[inside].min() >= z.min() and nat.values[inside].max() <= z.max()
    with pytest.raises(ValueError, match="method"):
        terrain.dem(xy, z, resolution=5.0, method="cubic")


def test_duplicates_and_long_edges():
    xy = np.array([[0, 0], [10, 0], [0, 10], [10, 10], [10, 10], [10, 10]], float)
    z = np.array([0, 0, 0, 1, 4, 7], float)
    for how, want in [("first", 1), ("last", 7), ("lowest", 1), ("highest", 7), ("mean", 4)]:
        r = terrain.dem(xy, z, resolution=1.0, extent=(8, 8, 9, 9), duplicates=how, method="nearest")
        assert r.values[0, 0] == want, how
    r = terrain.dem(xy, z, resolution=1.0, max_edge=5.0, nodata=-1.0)
    assert (r.values == -1.0).all()  # every side of both triangles is 10 or more
    with pytest.raises(ValueError):
        terrain.dem(xy, z[:3], resolution=1.0)
    with pytest.raises(ValueError):
        terrain.dem(xy, z, resolution=0.0)
    with pytest.raises(ValueError, match="finite"):
        terrain.dem(xy, np.full(6, math.nan), resolution=1.0)


def test_geotiff_round_trip(tmp_path):
    xy, z = sample()
    r = terrain.dem(xy + [600000, 5000000], z, resolution=4.0)
    terrain.write_dem(tmp_path / "d.tif", r, crs="EPSG:25832")
    ds = gdal.Open(str(tmp_path / "d.tif"))
    np.testing.assert_array_equal(ds.ReadAsArray(), r.values)
    assert ds.GetGeoTransform() == r.transform
    assert "25832" in ds.GetSpatialRef().GetAuthorityCode(None)
    shade = terrain.hillshade(r)
    assert shade.dtype == np.uint8 and shade.shape == r.values.shape
    assert shade[np.isnan(r.values)].max() == 0 and shade.max() > 100
