// ridt._core's terrain calls: LAS in (the tool's reader, tools/support/io_las.cpp), heights of
// duplicates merged, a DEM raster and its hillshade (ridt/terrain.hpp). ridt/terrain.py checks
// the arguments and writes GeoTIFF through GDAL's Python bindings or rasterio.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <string>
#include <vector>

#include "points.hpp"
#include "ridt/terrain.hpp"
#include "terrain_io.hpp"

namespace py = pybind11;

namespace {

using Doubles = ridt_python::Points;

std::span<const ridt::Point> as_points(const Doubles& a) { return ridt_python::as_points(a, "points"); }

py::tuple read_las(const std::string& path, const std::vector<int>& classes, const std::string& returns,
                   bool withheld) {
  ridt::io::PointFilter filter;
  filter.classes = classes;
  filter.returns = ridt::parse<ridt::Returns>(returns);
  filter.withheld = withheld;
  ridt::io::Terrain t;
  {
    py::gil_scoped_release nogil;
    t = ridt::io::read_las(path, filter);
  }
  Doubles xyz({static_cast<py::ssize_t>(t.points.size()), py::ssize_t{3}});
  double* out = xyz.mutable_data();
  for (std::size_t i = 0; i < t.points.size(); ++i)
    out[3 * i] = t.points[i].x, out[3 * i + 1] = t.points[i].y, out[3 * i + 2] = t.z[i];
  return py::make_tuple(xyz, t.crs);
}

Doubles dem(const Doubles& points, const ridt::Triangulation& t, const Doubles& z, double x0, double y1, double cell,
            std::size_t nx, std::size_t ny, const std::string& method, double max_edge, double nodata,
            unsigned threads) {
  const auto pts = as_points(points);
  const std::span<const double> heights(z.data(), static_cast<std::size_t>(z.size()));
  ridt::DemOptions o;
  o.method = ridt::parse<ridt::Surface>(method);
  o.max_edge = max_edge;
  o.nodata = nodata;
  o.threads = threads;
  Doubles out({static_cast<py::ssize_t>(ny), static_cast<py::ssize_t>(nx)});
  const std::span<double> cells(out.mutable_data(), nx * ny);
  {
    py::gil_scoped_release nogil;
    ridt::Dem(pts, t, heights, ridt::RasterGrid{x0, y1, cell, nx, ny}, o).all(cells);
  }
  return out;
}

}  // namespace

void bind_terrain(py::module_& m) {
  // Registered after the library's IoError (an OSError), whose kind it is, so that it is tried
  // first: a malformed file is a ValueError.
  py::register_exception<ridt::io::IoError>(m, "FileError", PyExc_ValueError);
  m.def("read_las", &read_las, py::arg("path"), py::arg("classes"), py::arg("returns"), py::arg("withheld"));
  m.def("dem", &dem, py::arg("points"), py::arg("triangulation"), py::arg("z"), py::arg("x0"), py::arg("y1"),
        py::arg("cell"), py::arg("nx"), py::arg("ny"), py::arg("method"), py::arg("max_edge"), py::arg("nodata"),
        py::arg("threads"));
  m.def(
      "raster_grid",
      [](double x0, double y0, double x1, double y1, double cell) {
        const ridt::RasterGrid g = ridt::RasterGrid::around(x0, y0, x1, y1, cell);
        return py::make_tuple(g.x0, g.y1, g.nx, g.ny);
      },
      py::arg("x0"), py::arg("y0"), py::arg("x1"), py::arg("y1"), py::arg("cell"));
  m.def(
      "merge_heights",
      [](const ridt::Triangulation& t, py::array_t<double, py::array::c_style> z, const std::string& how) {
        ridt::merge_heights(t, std::span<double>(z.mutable_data(), static_cast<std::size_t>(z.size())),
                            ridt::parse<ridt::Merge>(how));
      },
      py::arg("triangulation"), py::arg("z"), py::arg("how"));
  m.def(
      "hillshade",
      [](const Doubles& dem, double cell, double nodata, double azimuth, double altitude, double z_factor) {
        if (dem.ndim() != 2) throw py::value_error("the DEM must be a 2-D array");
        const auto ny = static_cast<std::size_t>(dem.shape(0)), nx = static_cast<std::size_t>(dem.shape(1));
        const std::vector<std::uint8_t> s =
            ridt::hillshade({dem.data(), nx * ny}, nx, ny, cell, nodata, azimuth, altitude, z_factor);
        py::array_t<std::uint8_t> out({static_cast<py::ssize_t>(ny), static_cast<py::ssize_t>(nx)});
        std::memcpy(out.mutable_data(), s.data(), s.size());
        return out;
      },
      py::arg("dem"), py::arg("cell"), py::arg("nodata"), py::arg("azimuth"), py::arg("altitude"), py::arg("z_factor"));
}
