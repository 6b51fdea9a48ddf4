// ridt._core's Triangle run (ridt/triangle.hpp), for ridt.triangle: the `triangle` package's
// dict in, the dict it returns out, with the keys it gives for the switches asked.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <utility>

#include "points.hpp"
#include "ridt/triangle.hpp"

namespace py = pybind11;

namespace {

using ridt_python::adopt;
using ridt_python::as_points;
using ridt_python::Points;
using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Indices = py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>;
using Markers = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

template <class T, class A>
std::vector<T> copy_of(const A& a) {
  return std::vector<T>(a.data(), a.data() + a.size());
}

// Points as an (n, 2) float64 array.
py::array_t<double> points_array(std::vector<ridt::Point> p) {
  const auto n = static_cast<py::ssize_t>(p.size());
  return adopt<ridt::Point, double>(std::move(p), {n, py::ssize_t{2}});
}

// Integers as an intc array of `columns` columns (the triangle package's dtype).
template <class T>
py::array_t<int> intc(const std::vector<T>& v, py::ssize_t columns) {
  py::array_t<int> out({static_cast<py::ssize_t>(v.size()) / columns, columns});
  std::transform(v.begin(), v.end(), out.mutable_data(), [](T x) { return static_cast<int>(x); });
  return out;
}

// Doubles as an array of `columns` columns.
py::array_t<double> rows(std::vector<double> v, std::size_t columns) {
  const auto n = static_cast<py::ssize_t>(columns == 0 ? 0 : v.size() / columns);
  return adopt(std::move(v), {n, static_cast<py::ssize_t>(columns)});
}

// The dual's keys, as the package's voronoi() gives them: edges between two vertices, and rays
// (an origin and a direction) across the boundary.
void add_dual(py::dict& out, const ridt::triangle::Output& m) {
  std::vector<int> edges, origins;
  std::vector<ridt::Point> directions;
  for (std::size_t k = 0; k < m.voronoi_edges.size() / 2; ++k) {
    const std::int32_t u = m.voronoi_edges[2 * k], w = m.voronoi_edges[2 * k + 1];
    if (w >= 0)
      edges.push_back(u), edges.push_back(w);
    else
      origins.push_back(u), directions.push_back(m.voronoi_directions[k]);
  }
  out["voronoi_vertices"] = points_array(m.voronoi_vertices);
  out["voronoi_edges"] = intc(edges, 2);
  py::array_t<int> o(static_cast<py::ssize_t>(origins.size()));
  std::copy(origins.begin(), origins.end(), o.mutable_data());
  out["voronoi_ray_origins"] = o;
  out["voronoi_ray_directions"] = points_array(directions);
  if (m.attribute_count > 0) out["voronoi_attributes"] = rows(m.voronoi_attributes, m.attribute_count);
}

// The dict the package returns for `w`.
py::dict as_dict(ridt::triangle::Output m, const ridt::triangle::Switches& w, bool holes_given) {
  py::dict out;
  const bool markers = !w.no_markers;
  out["vertices"] = points_array(m.vertices);
  out["triangles"] = intc(m.triangles, m.nodes);
  if (m.attribute_count > 0) out["vertex_attributes"] = rows(m.vertex_attributes, m.attribute_count);
  if (markers) out["vertex_markers"] = intc(m.vertex_markers, 1);
  if (w.pslg) {
    out["segments"] = intc(m.segments, 2);
    if (markers) out["segment_markers"] = intc(m.segment_markers, 1);
    if (holes_given && !w.no_holes && !w.refine) out["holes"] = points_array(m.holes);
  }
  if (!m.triangle_attributes.empty()) out["triangle_attributes"] = rows(m.triangle_attributes, 1);
  if (w.all_edges) {
    out["edges"] = intc(m.edges, 2);
    if (markers) out["edge_markers"] = intc(m.edge_markers, 1);
  }
  if (w.neighbors) out["neighbors"] = intc(m.neighbors, 3);
  if (w.voronoi) add_dual(out, m);
  out["_warning"] = m.warning;  // ridt.triangle warns with it
  return out;
}

}  // namespace

void bind_triangle(py::module_& m) {
  m.def(
      "triangle_triangulate",
      [](const Points& vertices, const Markers& vertex_markers, const Doubles& vertex_attributes,
         const Indices& segments, const Markers& segment_markers, const Points& holes, const Doubles& regions,
         const Indices& triangles, const Doubles& triangle_attributes, const Doubles& triangle_max_area,
         const std::string& switches, unsigned threads, bool holes_given) {
        const ridt::triangle::Switches w = ridt::triangle::parse_switches(switches);
        if (w.refine && triangles.size() == 0)
          throw py::value_error("switch 'r' refines a mesh: tri needs 'triangles'");
        if (w.refine && w.region_areas && triangle_max_area.size() == 0)
          throw py::value_error(
              "switches 'r' and 'a' with no number bound each triangle: tri needs 'triangle_max_area'");
        ridt::triangle::Input in;
        const auto pts = as_points(vertices, "vertices");
        in.vertices.assign(pts.begin(), pts.end());
        in.vertex_markers = copy_of<std::int64_t>(vertex_markers);
        in.attribute_count = in.vertices.empty() ? 0 : static_cast<std::size_t>(vertex_attributes.size()) / pts.size();
        in.vertex_attributes = copy_of<double>(vertex_attributes);
        in.segments = copy_of<ridt::VertexId>(segments);
        in.segment_markers = copy_of<std::int64_t>(segment_markers);
        const auto h = as_points(holes, "holes");
        in.holes.assign(h.begin(), h.end());
        for (py::ssize_t k = 0; k + 3 < regions.size(); k += 4) {
          const double* r = regions.data() + k;
          in.regions.push_back({{r[0], r[1]}, r[2], r[3]});
        }
        in.triangles = copy_of<ridt::VertexId>(triangles);
        in.triangle_attributes = copy_of<double>(triangle_attributes);
        in.triangle_max_area = copy_of<double>(triangle_max_area);
        ridt::Options o;
        o.threads = threads;
        o.experiment.time_threads = false;
        ridt::triangle::Output out;
        {
          py::gil_scoped_release release;
          out = ridt::triangle::triangulate(in, w, o);
        }
        if (w.check && !out.check.valid)
          throw std::runtime_error("ridt.triangle: the mesh fails its consistency check: " + out.check.message);
        return as_dict(std::move(out), w, holes_given);
      },
      py::arg("vertices"), py::arg("vertex_markers"), py::arg("vertex_attributes"), py::arg("segments"),
      py::arg("segment_markers"), py::arg("holes"), py::arg("regions"), py::arg("triangles"),
      py::arg("triangle_attributes"), py::arg("triangle_max_area"), py::arg("switches"), py::arg("threads"),
      py::arg("holes_given"));
}
