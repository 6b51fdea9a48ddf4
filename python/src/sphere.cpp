// ridt._core's triangulation on the sphere: ridt::triangulate_sphere, its Voronoi cells and
// its validator (ridt/sphere.hpp).
#include "ridt/sphere.hpp"

#include <algorithm>
#include <cmath>

#include "points.hpp"

namespace py = pybind11;

using ridt_python::adopt;
using ridt_python::Points;

namespace {

std::span<const ridt::Point3> as_points3(const Points& a, const char* name) {
  if (a.ndim() != 2 || a.shape(1) != 3) throw py::value_error(std::string(name) + " must have shape (n, 3)");
  return {reinterpret_cast<const ridt::Point3*>(a.data()), static_cast<std::size_t>(a.shape(0))};
}

using Indices = py::array_t<std::uint32_t, py::array::c_style>;
using Links = py::array_t<std::int32_t, py::array::c_style>;

// A triangulate_sphere result given back from Python, its shapes and indices checked.
ridt::SphericalTriangulation as_triangulation(std::size_t points, const Indices& triangles, const Links& neighbors) {
  if (triangles.ndim() != 2 || triangles.shape(1) != 3 || neighbors.ndim() != 2 ||
      neighbors.shape(0) != triangles.shape(0) || neighbors.shape(1) != 3)
    throw py::value_error("triangles and neighbors must have shape (ntriangles, 3)");
  ridt::SphericalTriangulation t;
  t.triangles.assign(triangles.data(), triangles.data() + triangles.size());
  t.neighbors.assign(neighbors.data(), neighbors.data() + neighbors.size());
  for (const ridt::VertexId v : t.triangles)
    if (v >= points) throw py::value_error("a triangle's corner is not a point's index");
  for (const std::int32_t g : t.neighbors)
    if (g < 0 || static_cast<std::size_t>(g) >= t.size()) throw py::value_error("a neighbour is not a triangle");
  return t;
}

// (triangles, neighbors, duplicates, hidden), the arrays adopted.
py::tuple as_tuple(ridt::SphericalTriangulation&& t) {
  const auto size = static_cast<py::ssize_t>(t.size());
  std::vector<std::uint32_t> copies;
  for (const ridt::Duplicate& d : t.duplicates) copies.insert(copies.end(), {d.dropped, d.kept});
  const auto dups = static_cast<py::ssize_t>(t.duplicates.size()), hidden = static_cast<py::ssize_t>(t.hidden.size());
  return py::make_tuple(adopt(std::move(t.triangles), {size, 3}), adopt(std::move(t.neighbors), {size, 3}),
                        adopt(std::move(copies), {dups, 2}), adopt(std::move(t.hidden), {hidden}));
}

py::tuple triangulate(const Points& points, unsigned threads) {
  const auto pts = as_points3(points, "points");
  ridt::SphericalTriangulation t;
  {
    py::gil_scoped_release nogil;
    t = ridt::triangulate_sphere(pts, threads);
  }
  return as_tuple(std::move(t));
}

py::tuple voronoi(const Points& points, const Indices& triangles, const Links& neighbors, const Points& center,
                  double radius, bool areas, unsigned threads) {
  const auto pts = as_points3(points, "points");
  const auto c = as_points3(center, "center");
  if (c.size() != 1) throw py::value_error("center must have shape (1, 3)");
  const ridt::SphericalTriangulation t = as_triangulation(pts.size(), triangles, neighbors);
  ridt::SphericalVoronoi v;
  {
    py::gil_scoped_release nogil;
    v = ridt::spherical_voronoi(t, pts, c[0], radius, areas, threads);
  }
  const auto nv = static_cast<py::ssize_t>(v.vertices.size()), n = static_cast<py::ssize_t>(pts.size()),
             nr = static_cast<py::ssize_t>(v.regions.size()), na = static_cast<py::ssize_t>(v.areas.size());
  return py::make_tuple(adopt<ridt::Point3, double>(std::move(v.vertices), {nv, 3}),
                        adopt(std::move(v.region_start), {n + 1}), adopt(std::move(v.regions), {nr}),
                        adopt(std::move(v.areas), {na}));
}

double shortest_edge(const Points& points, const Indices& triangles, unsigned threads) {
  const auto pts = as_points3(points, "points");
  if (triangles.ndim() != 2 || triangles.shape(1) != 3)
    throw py::value_error("triangles must have shape (ntriangles, 3)");
  ridt::SphericalTriangulation t;
  t.triangles.assign(triangles.data(), triangles.data() + triangles.size());
  for (const ridt::VertexId v : t.triangles)
    if (v >= pts.size()) throw py::value_error("a triangle's corner is not a point's index");
  py::gil_scoped_release nogil;
  return ridt::shortest_edge(t, pts, threads);
}

// triangulate(), shortest_edge() and voronoi() at once: the triangulation goes to the cells as
// it is, not through Python and back.
py::tuple voronoi_of(const Points& points, const Points& center, double radius, unsigned threads) {
  const auto pts = as_points3(points, "points");
  const auto c = as_points3(center, "center");
  if (c.size() != 1) throw py::value_error("center must have shape (1, 3)");
  ridt::SphericalTriangulation t;
  ridt::SphericalVoronoi v;
  double shortest = 0;
  {
    py::gil_scoped_release nogil;
    t = ridt::triangulate_sphere(pts, threads);
    shortest = ridt::shortest_edge(t, pts, threads);
    v = ridt::spherical_voronoi(t, pts, c[0], radius, true, threads);
  }
  const py::tuple hull = as_tuple(std::move(t));
  const auto nv = static_cast<py::ssize_t>(v.vertices.size()), n = static_cast<py::ssize_t>(pts.size()),
             nr = static_cast<py::ssize_t>(v.regions.size()), na = static_cast<py::ssize_t>(v.areas.size());
  return py::make_tuple(
      hull[0], hull[1], hull[2], hull[3], shortest, adopt<ridt::Point3, double>(std::move(v.vertices), {nv, 3}),
      adopt(std::move(v.region_start), {n + 1}), adopt(std::move(v.regions), {nr}), adopt(std::move(v.areas), {na}));
}

py::tuple check(const Points& points, const Indices& triangles) {
  const auto pts = as_points3(points, "points");
  const std::span<const ridt::VertexId> tris(triangles.data(), static_cast<std::size_t>(triangles.size()));
  ridt::CheckResult r;
  {
    py::gil_scoped_release nogil;
    r = ridt::check_sphere(pts, tris);
  }
  return py::make_tuple(r.valid, r.message, r.problems);
}

py::array_t<double> interpolate(const Points& points, const Indices& triangles, const Links& neighbors,
                                const Points& values, const Points& queries, const Points& center, double fill,
                                unsigned threads, bool natural) {
  const auto pts = as_points3(points, "points");
  const auto xi = as_points3(queries, "xi");
  const auto c = as_points3(center, "center");
  if (c.size() != 1) throw py::value_error("center must have shape (1, 3)");
  if (values.ndim() != 2 || static_cast<std::size_t>(values.shape(0)) != pts.size())
    throw py::value_error("values must have shape (npoints, k)");
  const ridt::SphericalTriangulation t = as_triangulation(pts.size(), triangles, neighbors);
  const auto k = static_cast<std::size_t>(values.shape(1));
  const std::span<const double> v(values.data(), static_cast<std::size_t>(values.size()));
  std::vector<double> out;
  {
    py::gil_scoped_release nogil;
    out = natural ? ridt::interpolate_sphere_natural(t, pts, v, k, xi, c[0], fill, threads)
                  : ridt::interpolate_sphere_linear(t, pts, v, k, xi, c[0], fill, threads);
  }
  return adopt(std::move(out), {static_cast<py::ssize_t>(xi.size()), static_cast<py::ssize_t>(k)});
}

}  // namespace

void bind_sphere(py::module_& m) {
  m.def("interpolate_sphere", &interpolate, py::arg("points"), py::arg("triangles"), py::arg("neighbors"),
        py::arg("values"), py::arg("xi"), py::arg("center"), py::arg("fill"), py::arg("threads") = 0,
        py::arg("natural") = false,
        "(nxi, k): linear (or natural-neighbour) interpolation on the sphere of a triangulate_sphere result");
  m.def("triangulate_sphere", &triangulate, py::arg("points"), py::arg("threads") = 0,
        "(triangles, neighbors, duplicates, hidden): the exact convex hull of points in space, each triangle "
        "counter-clockwise seen from outside; duplicates as (dropped, kept) rows; hidden: the points inside it");
  m.def("spherical_voronoi", &voronoi, py::arg("points"), py::arg("triangles"), py::arg("neighbors"), py::arg("center"),
        py::arg("radius"), py::arg("areas") = true, py::arg("threads") = 0,
        "(vertices, region_start, regions, areas): the Voronoi diagram on the sphere of a triangulate_sphere result");
  m.def("shortest_edge", &shortest_edge, py::arg("points"), py::arg("triangles"), py::arg("threads") = 0,
        "the length of the triangles' shortest edge");
  m.def("spherical_voronoi_of", &voronoi_of, py::arg("points"), py::arg("center"), py::arg("radius"),
        py::arg("threads") = 0,
        "(triangles, neighbors, duplicates, hidden, shortest edge, vertices, region_start, regions, areas): "
        "triangulate_sphere, shortest_edge and spherical_voronoi at once");
  m.def("check_sphere", &check, py::arg("points"), py::arg("triangles"));
}
