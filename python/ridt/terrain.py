"""Terrain: LiDAR points in, a DEM raster out, with the engine of ``ridt dem``.

    >>> from ridt import terrain
    >>> pts = terrain.read_las("tile.las", classes=[2])          # ground returns
    >>> dem = terrain.dem(pts.xyz, resolution=1.0, max_edge=20)    # a Raster
    >>> terrain.write_dem("dem.tif", dem, crs=pts.crs)             # GeoTIFF, through GDAL

Heights ride on the exact Delaunay triangulation of the points (``ridt.triangulate``); a cell
holds the interpolated height at its centre, ``nodata`` (NaN) outside the hull and in triangles
with a side longer than ``max_edge``. GeoTIFF is written through GDAL's Python bindings
(Debian's ``python3-gdal``) or rasterio, whichever is installed.
"""

from __future__ import annotations

import math
import os
from typing import Any, NamedTuple, Optional, Sequence

import numpy as np

from . import _core
from ._api import as_points, triangulate

METHODS = _core.NAMES["interpolation"]
DUPLICATES = _core.NAMES["duplicates"]
RETURNS = _core.NAMES["returns"]


class LasPoints(NamedTuple):
    """Points of a LAS file: ``xyz`` an (n, 3) float64 array (scale and offset applied), and
    ``crs`` the coordinate reference system as WKT or "EPSG:n" ('' when the file says none)."""

    xyz: np.ndarray
    crs: str


class Raster(NamedTuple):
    """A north-up raster: ``values`` (ny, nx) float64, row 0 the northernmost; ``transform``
    GDAL's geotransform (x0, cell, 0, y1, 0, -cell), so cell (j, i) has its centre at
    (x0 + (i + 0.5) cell, y1 - (j + 0.5) cell); ``nodata`` the value of cells without one."""

    values: np.ndarray
    transform: tuple
    nodata: float

    def centres(self):
        """The cells' centres: (x of each column, y of each row)."""
        x0, cell, _, y1, _, _ = self.transform
        ny, nx = self.values.shape
        return x0 + (np.arange(nx) + 0.5) * cell, y1 - (np.arange(ny) + 0.5) * cell


def _choice(value: str, names: Sequence[str], what: str) -> str:
    if value not in names:
        raise ValueError(f"unknown {what} {value!r} (use {', '.join(names)})")
    return value


def read_las(path: Any, classes: Optional[Sequence[int]] = None, returns: str = "all",
             withheld: bool = False) -> LasPoints:
    """The points of a LAS 1.0-1.4 file (point formats 0 to 10), read natively.

    classes : the classifications to keep (e.g. [2] for ground); all when None.
    returns : 'all', 'first', 'last' or 'single'.
    withheld : keep points flagged withheld.

    FileNotFoundError for a missing file; ValueError for a file that is not LAS, is truncated
    or inconsistent, or is compressed (LAZ: decompress it first with laszip or pdal).
    """
    path = os.fspath(path)
    if not os.path.exists(path):
        raise FileNotFoundError(path)
    cls = [] if classes is None else [int(c) for c in classes]
    if any(c < 0 or c > 255 for c in cls):
        raise ValueError("classes are integers from 0 to 255")
    xyz, crs = _core.read_las(path, cls, _choice(returns, RETURNS, "returns"), bool(withheld))
    return LasPoints(xyz, crs)


def raster_grid(extent: Sequence[float], resolution: float) -> tuple:
    """(x0, y1, nx, ny): the raster of cells ``resolution`` wide over extent (x0, y0, x1, y1),
    its edges grown out to multiples of the cell."""
    x0, y0, x1, y1 = (float(v) for v in extent)
    return _core.raster_grid(x0, y0, x1, y1, float(resolution))


def dem(points: Any, z: Any = None, *, resolution: float, extent: Optional[Sequence[float]] = None,
        method: str = "linear", max_edge: Optional[float] = None, duplicates: str = "first",
        nodata: float = math.nan, threads: int = 1, triangulation: Optional[_core.Triangulation] = None) -> Raster:
    """A DEM: heights interpolated at the centres of a raster's cells.

    points : (n, 3) array of x, y, z, or (n, 2) with ``z`` given apart.
    resolution : the cell size. extent : (x0, y0, x1, y1), default the points' box; grown out to
        multiples of the cell.
    method : 'linear' (the plane of the triangle), 'natural' (Sibson) or 'nearest'.
    max_edge : cells in triangles with a side longer than this get ``nodata`` (lakes, gaps).
    duplicates : the height of points equal in x and y: 'first', 'last', 'lowest', 'highest' or
        'mean'.
    triangulation : ``ridt.triangulate`` of the points, when it is at hand.

    The raster is computed band by band on ``threads`` threads with the GIL released.
    """
    a = np.asarray(points)
    if z is None:
        if a.ndim != 2 or a.shape[1] != 3:
            raise ValueError(f"points must have shape (n, 3) when z is not given; got {a.shape}")
        xy, z = as_points(a[:, :2]), a[:, 2]
    else:
        xy = as_points(a)
    z = np.array(z, dtype=np.float64, copy=True).reshape(-1)
    if z.shape[0] != xy.shape[0]:
        raise ValueError(f"{z.shape[0]} heights for {xy.shape[0]} points")
    if not np.isfinite(z).all():
        raise ValueError("every height must be a finite number")
    _choice(method, METHODS, "method")
    if extent is None:
        if xy.shape[0] == 0:
            raise ValueError("no points, and no extent")
        extent = (xy[:, 0].min(), xy[:, 1].min(), xy[:, 0].max(), xy[:, 1].max())
    x0, y1, nx, ny = raster_grid(extent, resolution)
    t = triangulation if triangulation is not None else triangulate(xy, threads=threads)
    if len(t) == 0:
        raise ValueError(f"no triangles from {xy.shape[0]} points ({t.warning})")
    _core.merge_heights(t, z, _choice(duplicates, DUPLICATES, "duplicates"))
    edge = math.inf if max_edge is None else float(max_edge)
    values = _core.dem(xy, t, z, x0, y1, float(resolution), nx, ny, method, edge, float(nodata),
                       _threads(threads))
    return Raster(values, (x0, float(resolution), 0.0, y1, 0.0, -float(resolution)), float(nodata))


def _threads(threads: int) -> int:
    return 0 if threads in (0, -1) else int(threads)


def hillshade(raster: Raster, azimuth: float = 315.0, altitude: float = 45.0, z_factor: float = 1.0) -> np.ndarray:
    """A shaded relief of ``raster``: uint8 grey levels 1 to 255 (Horn's slopes, the sun at
    ``azimuth`` degrees clockwise from north and ``altitude`` above the horizon), 0 where a
    cell or a neighbour has no value."""
    values = np.ascontiguousarray(raster.values, dtype=np.float64)
    return _core.hillshade(values, float(raster.transform[1]), float(raster.nodata), float(azimuth),
                           float(altitude), float(z_factor))


def write_dem(path: Any, raster: Raster, crs: str = "", dtype: str = "float64") -> None:
    """Writes ``raster`` as a GeoTIFF (tiled, DEFLATE) with its transform, nodata and ``crs``
    (WKT or "EPSG:n"), through GDAL's Python bindings or else rasterio; ImportError when
    neither is installed."""
    path = os.fspath(path)
    if dtype not in ("float32", "float64"):
        raise ValueError("dtype must be 'float32' or 'float64'")
    values = np.ascontiguousarray(raster.values, dtype=dtype)
    ny, nx = values.shape
    options = ["TILED=YES", "COMPRESS=DEFLATE", "PREDICTOR=3", "BIGTIFF=IF_SAFER"]
    try:
        from osgeo import gdal, osr
    except ImportError:
        gdal = None
    if gdal is not None:
        gdal.UseExceptions()
        kind = gdal.GDT_Float32 if dtype == "float32" else gdal.GDT_Float64
        ds = gdal.GetDriverByName("GTiff").Create(path, nx, ny, 1, kind, options)
        ds.SetGeoTransform(raster.transform)
        if crs:
            srs = osr.SpatialReference()
            srs.SetFromUserInput(crs)
            ds.SetSpatialRef(srs)
        band = ds.GetRasterBand(1)
        band.SetNoDataValue(raster.nodata)
        band.WriteArray(values)
        ds = None  # closes and flushes
        return
    try:
        import rasterio
        from rasterio.transform import Affine
    except ImportError:
        raise ImportError("writing a GeoTIFF needs GDAL's Python bindings (apt-get install python3-gdal) "
                          "or rasterio") from None
    x0, cell, _, y1, _, _ = raster.transform
    with rasterio.open(path, "w", driver="GTiff", width=nx, height=ny, count=1, dtype=dtype,
                       crs=crs or None, transform=Affine(cell, 0, x0, 0, -cell, y1), nodata=raster.nodata,
                       tiled=True, compress="deflate") as out:
        out.write(values, 1)
