// ridt._core's constrained triangulations and quality meshes (ridt/constrained.hpp) and their
// validator: ConstrainedDelaunay (ridt/_constrained.py) and ridt.triangle call these.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <utility>

#include "points.hpp"
#include "ridt/check.hpp"
#include "ridt/constrained.hpp"

namespace py = pybind11;

namespace {

using ridt_python::adopt;
using ridt_python::as_points;
using ridt_python::Points;

// `unsuitable`, where not None, is called as unsuitable((ax, ay), (bx, by), (cx, cy), area) with
// the GIL taken for the call; it stays alive with the call's arguments, so the handle kept here
// needs no reference of its own (copying it needs no GIL).
ridt::Quality quality(double min_angle, double max_area, bool split_boundary, bool conforming, std::size_t max_steiner,
                      const py::object& unsuitable, bool split_segments, const py::object& size) {
  ridt::Quality q{.min_angle = min_angle,
                  .max_area = max_area,
                  .split_boundary = split_boundary,
                  .split_segments = split_segments,
                  .max_steiner = max_steiner,
                  .conforming = conforming,
                  .unsuitable = {},
                  .size = {}};
  if (!unsuitable.is_none()) {
    if (!PyCallable_Check(unsuitable.ptr())) throw py::type_error("unsuitable must be callable or None");
    q.unsuitable = [f = py::handle(unsuitable)](const ridt::Point& a, const ridt::Point& b, const ridt::Point& c,
                                                double area) {
      py::gil_scoped_acquire gil;
      const py::object r = f(py::make_tuple(a.x, a.y), py::make_tuple(b.x, b.y), py::make_tuple(c.x, c.y), area);
      return py::bool_(r).cast<bool>();
    };
  }
  if (!size.is_none()) q.size = size.cast<ridt::SizeField>();
  return q;
}

// A constrained triangulation as Python takes it: (its triangulation, its segments' edges, the
// points it added, how many of them are crossings, each triangle's attribute).
py::tuple constrained_tuple(ridt::ConstrainedTriangulation c) {
  const auto pieces = static_cast<py::ssize_t>(c.edges.size() / 2);
  auto edges = adopt(std::move(c.edges), {pieces, py::ssize_t{2}});
  py::array_t<double> added({static_cast<py::ssize_t>(c.steiner.size()), py::ssize_t{2}});
  std::copy_n(&c.steiner.data()->x, 2 * c.steiner.size(), added.mutable_data());
  py::array_t<double> attributes(static_cast<py::ssize_t>(c.attributes.size()));
  std::copy(c.attributes.begin(), c.attributes.end(), attributes.mutable_data());
  const std::size_t crossings = c.crossings;
  return py::make_tuple(ridt::Triangulation(std::move(static_cast<ridt::Triangulation&>(c))), edges, added, crossings,
                        attributes);
}

// The constrained Delaunay triangulation or quality mesh.
void bind_triangulate_constrained(py::module_& m) {
  m.def(
      "triangulate_constrained",
      [](const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& segments, const Points& holes,
         bool convex_hull, const std::string& method, unsigned threads, std::uint64_t seed, bool canonical,
         const py::array_t<double, py::array::c_style>& regions, double min_angle, double max_area, bool split_boundary,
         bool conforming, std::size_t max_steiner, const py::object& unsuitable, bool split_segments,
         const py::object& size) {
        ridt::Options o;
        o.method = ridt::parse<ridt::Method>(method);
        o.threads = threads;
        o.seed = seed;
        o.canonical_order = canonical;
        o.experiment.time_threads = false;
        const auto pts = as_points(points, "points");
        const std::span<const ridt::VertexId> segs(segments.data(), static_cast<std::size_t>(segments.size()));
        ridt::Domain domain;
        domain.convex_hull = convex_hull;
        const auto h = as_points(holes, "holes");
        domain.holes.assign(h.begin(), h.end());
        for (py::ssize_t r = 0; r + 3 < regions.size(); r += 4) {
          const double* v = regions.data() + r;
          domain.regions.push_back({{v[0], v[1]}, v[2], v[3]});
        }
        const ridt::Quality q =
            quality(min_angle, max_area, split_boundary, conforming, max_steiner, unsuitable, split_segments, size);
        ridt::ConstrainedTriangulation c;
        {
          py::gil_scoped_release nogil;
          c = ridt::triangulate_constrained(pts, segs, o, domain, q);
        }
        return constrained_tuple(std::move(c));
      },
      py::arg("points"), py::arg("segments"), py::arg("holes"), py::arg("convex_hull"), py::arg("method"),
      py::arg("threads"), py::arg("seed"), py::arg("canonical"), py::arg("regions"), py::arg("min_angle"),
      py::arg("max_area"), py::arg("split_boundary"), py::arg("conforming"), py::arg("max_steiner"),
      py::arg("unsuitable") = py::none(), py::arg("split_segments") = true, py::arg("size") = py::none());
}

// A mesh already made, refined (ridt::refine_mesh), as triangulate_constrained's tuple.
void bind_refine_mesh(py::module_& m) {
  m.def(
      "refine_mesh",
      [](const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& triangles,
         const py::array_t<std::uint32_t, py::array::c_style>& segments,
         const py::array_t<double, py::array::c_style>& max_areas,
         const py::array_t<double, py::array::c_style>& attributes, unsigned threads, double min_angle, double max_area,
         bool split_boundary, bool conforming, std::size_t max_steiner, const py::object& unsuitable,
         bool split_segments, const py::object& size) {
        ridt::Options o;
        o.threads = threads;
        o.canonical_order = true;
        const auto pts = as_points(points, "points");
        auto span_of = [](const auto& a) { return std::span(a.data(), static_cast<std::size_t>(a.size())); };
        const ridt::Quality q =
            quality(min_angle, max_area, split_boundary, conforming, max_steiner, unsuitable, split_segments, size);
        ridt::ConstrainedTriangulation c;
        {
          py::gil_scoped_release nogil;
          c = ridt::refine_mesh(pts, span_of(triangles), span_of(segments), q, span_of(max_areas), span_of(attributes),
                                o);
        }
        return constrained_tuple(std::move(c));
      },
      py::arg("points"), py::arg("triangles"), py::arg("segments"), py::arg("max_areas"), py::arg("attributes"),
      py::arg("threads"), py::arg("min_angle"), py::arg("max_area"), py::arg("split_boundary"), py::arg("conforming"),
      py::arg("max_steiner"), py::arg("unsuitable") = py::none(), py::arg("split_segments") = true,
      py::arg("size") = py::none());
}

// The validator of constrained triangulations and meshes.
void bind_check_mesh(py::module_& m) {
  m.def(
      "check_mesh",
      [](const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& triangles,
         const py::array_t<std::uint32_t, py::array::c_style>& edges,
         const py::array_t<std::uint32_t, py::array::c_style>& segments, std::size_t input_points, const Points& holes,
         double min_angle, double max_area) {
        const auto pts = as_points(points, "points");
        const auto h = as_points(holes, "holes");
        ridt::MeshSpec spec;
        spec.edges = {edges.data(), static_cast<std::size_t>(edges.size())};
        spec.segments = {segments.data(), static_cast<std::size_t>(segments.size())};
        spec.input_points = input_points;
        spec.holes = h;
        spec.min_angle = min_angle;
        spec.max_area = max_area;
        const std::span<const ridt::VertexId> t(triangles.data(), static_cast<std::size_t>(triangles.size()));
        ridt::CheckResult r;
        {
          py::gil_scoped_release nogil;
          r = ridt::check_mesh(pts, t, spec);
        }
        return py::make_tuple(r.valid, r.message, r.problems);
      },
      py::arg("points"), py::arg("triangles"), py::arg("edges"), py::arg("segments"), py::arg("input_points"),
      py::arg("holes"), py::arg("min_angle"), py::arg("max_area"));
}

}  // namespace

void bind_constrained(py::module_& m) {
  bind_triangulate_constrained(m);
  bind_refine_mesh(m);
  bind_check_mesh(m);
}
