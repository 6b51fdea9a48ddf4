"""ridt: exact 2D Delaunay triangulation by randomized incremental insertion, on threads.

    >>> import numpy as np, ridt
    >>> tri = ridt.Delaunay(np.random.default_rng(1).random((1000, 2)))   # scipy's interface
    >>> tri.find_simplex([[0.5, 0.5]])
    >>> t = ridt.triangulate(points, threads=2)   # the library's arrays, no copies
    >>> ridt.griddata(points, values, (gx, gy))       # scipy.interpolate's, on threads
    >>> ridt.Voronoi(points).regions                  # scipy.spatial's
    >>> ridt.ConvexHull(points).vertices              # scipy.spatial's, exact
    >>> ridt.PowerDiagram(points, weights).regions    # Laguerre cells of weighted points
    >>> ridt.terrain.dem(ridt.terrain.read_las("tile.las").xyz, resolution=1.0)   # a DEM

Every result is exactly the Delaunay triangulation of the distinct points (cocircular ties
broken by a fixed symbolic perturbation), with its whole convex hull, the same for every method
and thread count.
"""

from ._api import available_memory, check, check_convex_hull, estimate_memory, triangulate, triangulate_out_of_core
from ._core import InputError, Triangulation, cached_memory, set_memory_cache_limit
from ._constrained import ConstrainedDelaunay, RefinementWarning
from ._size import SizeField
from ._delaunay import Delaunay, DegenerateInputWarning
from ._hull import ConvexHull, DegenerateInputError
from ._sphere import SphericalLinearInterpolator, SphericalNaturalNeighborInterpolator, SphericalVoronoi, check_sphere
from ._interpolate import (CloughTocher2DInterpolator, GradientEstimationWarning, LinearNDInterpolator,
                           NaturalNeighborInterpolator, NearestNDInterpolator, estimate_gradients_2d_global, griddata)
from ._voronoi import Voronoi
from ._regular import PowerDiagram, RegularTriangulation
from ._periodic import PeriodicDelaunay, PeriodicVoronoi
from . import terrain, triangle

__version__ = "0.1.0"

__all__ = [
    "CloughTocher2DInterpolator",
    "GradientEstimationWarning",
    "estimate_gradients_2d_global",
    "ConstrainedDelaunay",
    "ConvexHull",
    "Delaunay",
    "DegenerateInputError",
    "DegenerateInputWarning",
    "InputError",
    "LinearNDInterpolator",
    "NaturalNeighborInterpolator",
    "NearestNDInterpolator",
    "PeriodicDelaunay",
    "PeriodicVoronoi",
    "PowerDiagram",
    "RefinementWarning",
    "RegularTriangulation",
    "SizeField",
    "SphericalLinearInterpolator",
    "SphericalNaturalNeighborInterpolator",
    "SphericalVoronoi",
    "Triangulation",
    "available_memory",
    "cached_memory",
    "estimate_memory",
    "triangulate_out_of_core",
    "check",
    "check_convex_hull",
    "check_sphere",
    "set_memory_cache_limit",
    "Voronoi",
    "griddata",
    "terrain",
    "triangle",
    "triangulate",
]
