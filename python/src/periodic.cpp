// ridt._core's periodic Delaunay triangulation, its Voronoi cells and its validator
// (ridt/periodic.hpp).
#include "ridt/periodic.hpp"

#include "points.hpp"

namespace py = pybind11;

using ridt_python::adopt;
using ridt_python::as_points;
using ridt_python::Points;

namespace {

using Indices = py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>;
using Ints = py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>;

ridt::PeriodicDomain domain_of(double x0, double y0, double width, double height) { return {{x0, y0}, width, height}; }

std::vector<ridt::Offset> as_offsets(const Ints& a, std::size_t corners, const char* name) {
  if (static_cast<std::size_t>(a.size()) != 2 * corners)
    throw py::value_error(std::string(name) + " must have shape (ntriangles, 3, 2)");
  std::vector<ridt::Offset> out(corners);
  const std::int32_t* v = a.data();
  for (std::size_t k = 0; k < corners; ++k) {
    if (std::abs(v[2 * k]) > ridt::kMaxOffset || std::abs(v[2 * k + 1]) > ridt::kMaxOffset)
      throw py::value_error(std::string(name) + ": an offset is more than " + std::to_string(ridt::kMaxOffset) +
                            " periods");
    out[k] = {static_cast<std::int16_t>(v[2 * k]), static_cast<std::int16_t>(v[2 * k + 1])};
  }
  return out;
}

py::tuple triangulate(const Points& points, double x0, double y0, double width, double height, unsigned threads) {
  const auto pts = as_points(points, "points");
  ridt::PeriodicTriangulation t;
  {
    py::gil_scoped_release nogil;
    t = ridt::triangulate_periodic(pts, domain_of(x0, y0, width, height), threads);
  }
  const auto n = static_cast<py::ssize_t>(t.size());
  std::vector<std::uint32_t> dup;
  for (const ridt::Duplicate& d : t.duplicates) dup.push_back(d.dropped), dup.push_back(d.kept);
  const auto copies = static_cast<py::ssize_t>(t.duplicates.size());
  return py::make_tuple(
      adopt(std::move(t.triangles), {n, 3}), adopt<ridt::Offset, std::int16_t>(std::move(t.offsets), {n, 3, 2}),
      adopt(std::move(t.neighbors), {n, 3}),
      adopt<ridt::Offset, std::int16_t>(std::move(t.neighbor_offsets), {n, 3, 2}), adopt(std::move(dup), {copies, 2}));
}

py::tuple voronoi(const Points& points, double x0, double y0, double width, double height, const Indices& triangles,
                  const Ints& offsets, const Ints& neighbors, const Ints& neighbor_offsets) {
  const auto pts = as_points(points, "points");
  ridt::PeriodicTriangulation t;
  t.domain = domain_of(x0, y0, width, height);
  const auto corners = static_cast<std::size_t>(triangles.size());
  if (static_cast<std::size_t>(neighbors.size()) != corners)
    throw py::value_error("neighbors must have the shape of the triangles");
  t.triangles.assign(triangles.data(), triangles.data() + corners);
  t.offsets = as_offsets(offsets, corners, "offsets");
  t.neighbor_offsets = as_offsets(neighbor_offsets, corners, "neighbor_offsets");
  t.neighbors.assign(neighbors.data(), neighbors.data() + corners);
  ridt::PeriodicVoronoi v;
  {
    py::gil_scoped_release nogil;
    v = ridt::periodic_voronoi(pts, t);
  }
  const auto size = [](const auto& x) { return static_cast<py::ssize_t>(x.size()); };
  const py::ssize_t vertices = size(v.vertices), offs = size(v.cell_offsets), cells = size(v.cell_vertices);
  return py::make_tuple(adopt<ridt::Point, double>(std::move(v.vertices), {vertices, 2}),
                        adopt(std::move(v.cell_offsets), {offs}), adopt(std::move(v.cell_vertices), {cells}),
                        adopt<ridt::Offset, std::int16_t>(std::move(v.cell_shifts), {cells, 2}));
}

py::tuple check(const Points& points, double x0, double y0, double width, double height, const Indices& triangles,
                const Ints& offsets) {
  const auto pts = as_points(points, "points");
  const auto corners = static_cast<std::size_t>(triangles.size());
  const std::span<const ridt::VertexId> tris(triangles.data(), corners);
  const std::vector<ridt::Offset> offs = as_offsets(offsets, corners, "offsets");
  ridt::CheckResult r;
  {
    py::gil_scoped_release nogil;
    r = ridt::check_periodic(pts, domain_of(x0, y0, width, height), tris, offs);
  }
  return py::make_tuple(r.valid, r.message, r.problems);
}

}  // namespace

void bind_periodic(py::module_& m) {
  m.def("triangulate_periodic", &triangulate, py::arg("points"), py::arg("x0"), py::arg("y0"), py::arg("width"),
        py::arg("height"), py::arg("threads") = 0,
        "(triangles, offsets, neighbors, neighbor_offsets, duplicates): the periodic Delaunay triangulation");
  m.def("periodic_voronoi", &voronoi, py::arg("points"), py::arg("x0"), py::arg("y0"), py::arg("width"),
        py::arg("height"), py::arg("triangles"), py::arg("offsets"), py::arg("neighbors"), py::arg("neighbor_offsets"),
        "(vertices, cell_offsets, cell_vertices, cell_shifts): the periodic Voronoi cells");
  m.def("check_periodic", &check, py::arg("points"), py::arg("x0"), py::arg("y0"), py::arg("width"), py::arg("height"),
        py::arg("triangles"), py::arg("offsets"));
}
