// ridt._core's regular (weighted Delaunay) triangulation, its power diagram and its validator
// (ridt/regular.hpp).
#include "ridt/regular.hpp"

#include "points.hpp"

namespace py = pybind11;

using ridt_python::adopt;
using ridt_python::as_points;
using ridt_python::Points;

namespace {

using Weights = py::array_t<double, py::array::c_style>;
using Indices = py::array_t<std::uint32_t, py::array::c_style>;

std::span<const double> as_weights(const Weights& w, std::size_t points) {
  if (w.ndim() != 1 || static_cast<std::size_t>(w.shape(0)) != points)
    throw py::value_error("weights must have shape (npoints,)");
  return {w.data(), points};
}

py::tuple triangulate(const Points& points, const Weights& weights, unsigned threads) {
  const auto pts = as_points(points, "points");
  const auto w = as_weights(weights, pts.size());
  ridt::RegularTriangulation t;
  {
    py::gil_scoped_release nogil;
    t = ridt::triangulate_regular(pts, w, threads);
  }
  const auto hidden = static_cast<py::ssize_t>(t.hidden.size());
  py::array_t<std::uint32_t> h = adopt(std::move(t.hidden), {hidden});
  return py::make_tuple(ridt::Triangulation(std::move(static_cast<ridt::Triangulation&>(t))), h);
}

py::tuple power(const Points& points, const Weights& weights, const ridt::Triangulation& t, unsigned threads) {
  const auto pts = as_points(points, "points");
  const auto w = as_weights(weights, pts.size());
  ridt::Voronoi v;
  {
    py::gil_scoped_release nogil;
    v = ridt::power_diagram(pts, w, t, threads);
  }
  const auto size = [](const auto& x) { return static_cast<py::ssize_t>(x.size()); };
  const py::ssize_t vertices = size(v.vertices), offsets = size(v.cell_offsets), cell_vertices = size(v.cell_vertices),
                    sites = size(v.point_cell), ridges = size(v.ridges);
  return py::make_tuple(adopt<ridt::Point, double>(std::move(v.vertices), {vertices, 2}),
                        adopt(std::move(v.cell_offsets), {offsets}), adopt(std::move(v.cell_vertices), {cell_vertices}),
                        adopt(std::move(v.point_cell), {sites}),
                        adopt<ridt::Ridge, std::int32_t>(std::move(v.ridges), {ridges, 4}));
}

py::tuple check(const Points& points, const Weights& weights, const Indices& triangles) {
  const auto pts = as_points(points, "points");
  const auto w = as_weights(weights, pts.size());
  const std::span<const ridt::VertexId> tris(triangles.data(), static_cast<std::size_t>(triangles.size()));
  ridt::CheckResult r;
  {
    py::gil_scoped_release nogil;
    r = ridt::check_regular(pts, w, tris);
  }
  return py::make_tuple(r.valid, r.message, r.problems);
}

}  // namespace

void bind_regular(py::module_& m) {
  m.def("triangulate_regular", &triangulate, py::arg("points"), py::arg("weights"), py::arg("threads") = 0,
        "(Triangulation, hidden): the regular triangulation of weighted points; hidden: the points whose power "
        "cell is empty");
  m.def("power_diagram", &power, py::arg("points"), py::arg("weights"), py::arg("triangulation"),
        py::arg("threads") = 1,
        "(vertices, offsets, cell_vertices, point_cell, ridges): the power diagram, as voronoi() gives the "
        "Voronoi diagram");
  m.def("check_regular", &check, py::arg("points"), py::arg("weights"), py::arg("triangles"));
}
