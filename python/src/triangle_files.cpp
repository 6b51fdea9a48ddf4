// ridt._core's reader of Triangle's files, for ridt.triangle.loads: the texts of a .node, .ele,
// .poly, .area, .edge and .neigh file, read by the tool's readers (tools/support), into the dict
// the `triangle` package's loads gives.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io.hpp"
#include "points.hpp"

namespace py = pybind11;

namespace {

using ridt_python::adopt;

// What the files give, read without Python.
struct Files {
  std::optional<ridt::io::Pslg> graph;  // the vertices (.node or .poly) and the .poly's rest
  bool poly = false;
  std::vector<ridt::VertexId> triangles, middles;  // .ele
  std::vector<double> triangle_attributes;
  std::size_t triangle_attribute_count = 0;
  bool ele = false;
  std::vector<double> max_area;  // .area
  ridt::io::EdgeText edges;  // .edge
  std::vector<std::int32_t> neighbors;  // .neigh
};

// The text of file `ext` (none where not given).
std::optional<std::string_view> text_of(const std::map<std::string, std::string>& texts, const char* ext) {
  const auto it = texts.find(ext);
  if (it == texts.end()) return std::nullopt;
  return std::string_view(it->second);
}

// Reads the files in Triangle's order: the vertices first, whose first index numbers the others.
Files read_files(const std::map<std::string, std::string>& texts, const std::map<std::string, std::string>& names) {
  const auto name = [&](const char* ext) { return names.at(ext); };
  Files f;
  const std::optional<std::string_view> node = text_of(texts, "node");
  if (node) f.graph = ridt::io::parse_node_text(*node, name("node"));
  if (const auto poly = text_of(texts, "poly")) {
    f.graph = ridt::io::parse_poly_text(*poly, name("poly"), node, node ? name("node") : std::string());
    f.poly = true;
  }
  const int first = f.graph ? f.graph->first_index : 0;
  if (const auto ele = text_of(texts, "ele")) {
    f.triangles = ridt::io::parse_elements(*ele, name("ele"), first, f.triangle_attributes, f.triangle_attribute_count,
                                           f.middles);
    f.ele = true;
  }
  if (const auto area = text_of(texts, "area")) {
    const std::optional<std::size_t> count = f.ele ? std::optional(f.triangles.size() / 3) : std::nullopt;
    f.max_area = ridt::io::parse_area_text(*area, name("area"), count, -1);
  }
  if (const auto edge = text_of(texts, "edge")) {
    const std::size_t points = f.graph ? f.graph->points.size() : std::numeric_limits<std::size_t>::max();
    f.edges = ridt::io::parse_edge_text(*edge, name("edge"), points, first);
  }
  if (const auto neigh = text_of(texts, "neigh")) {
    f.neighbors = ridt::io::parse_neighbors(*neigh, name("neigh"), f.graph ? first : -1);
    if (f.ele && f.neighbors.size() != f.triangles.size())
      throw ridt::io::IoError(name("neigh") + ": " + std::to_string(f.neighbors.size() / 3) + " triangles, but " +
                              name("ele") + " has " + std::to_string(f.triangles.size() / 3));
  }
  return f;
}

// Integers as an (n, columns) intc array (the triangle package's dtype); ValueError naming
// `what` for one out of its range.
template <class T>
py::array_t<int> intc(const std::vector<T>& v, py::ssize_t columns, const char* what) {
  py::array_t<int> out({static_cast<py::ssize_t>(v.size()) / columns, columns});
  int* to = out.mutable_data();
  for (const T x : v) {
    if (!std::in_range<int>(x))
      throw py::value_error(std::string(what) + " " + std::to_string(x) + " is outside the range of intc");
    *to++ = static_cast<int>(x);
  }
  return out;
}

// Doubles as an (n, columns) float64 array.
py::array_t<double> rows(std::vector<double> v, std::size_t columns) {
  const auto n = static_cast<py::ssize_t>(v.size() / columns);
  return adopt(std::move(v), {n, static_cast<py::ssize_t>(columns)});
}

py::array_t<double> points(std::vector<ridt::Point> p) {
  const auto n = static_cast<py::ssize_t>(p.size());
  return adopt<ridt::Point, double>(std::move(p), {n, py::ssize_t{2}});
}

// The vertices' keys, and the .poly's segments, holes and regions: each where it has a row.
void add_graph(py::dict& d, ridt::io::Pslg& g, bool poly) {
  const std::size_t n = g.points.size();
  if (n > 0) d["vertices"] = points(std::move(g.points));
  if (n > 0 && g.vertex_attributes > 0)
    d["vertex_attributes"] = rows(std::move(g.point_attributes), g.vertex_attributes);
  if (n > 0 && !g.point_markers.empty()) d["vertex_markers"] = intc(g.point_markers, 1, "vertex marker");
  if (!poly) return;
  if (!g.segments.empty()) d["segments"] = intc(g.segments, 2, "vertex index");
  if (!g.segments.empty() && !g.segment_markers.empty())
    d["segment_markers"] = intc(g.segment_markers, 1, "segment marker");
  if (!g.holes.empty()) d["holes"] = points(std::move(g.holes));
  std::vector<double> regions;
  for (const auto& r : g.regions) regions.insert(regions.end(), r.begin(), r.end());
  if (!regions.empty()) d["regions"] = rows(std::move(regions), 4);
}

// The triangles' keys: 'triangles' (each its corners, then for six-node triangles the middles
// of the edges across from them), 'triangle_attributes', 'triangle_max_area',
// 'triangle_neighbors'; each where it has a row.
void add_triangles(py::dict& d, Files& f) {
  const std::size_t m = f.triangles.size() / 3;
  if (m > 0) {
    const std::size_t nodes = f.middles.empty() ? 3 : 6;
    std::vector<ridt::VertexId> all(nodes * m);
    for (std::size_t k = 0; k < m; ++k) {
      std::copy_n(&f.triangles[3 * k], 3, &all[nodes * k]);
      if (nodes == 6) std::copy_n(&f.middles[3 * k], 3, &all[nodes * k + 3]);
    }
    d["triangles"] = intc(all, static_cast<py::ssize_t>(nodes), "vertex index");
    if (f.triangle_attribute_count > 0)
      d["triangle_attributes"] = rows(std::move(f.triangle_attributes), f.triangle_attribute_count);
  }
  if (!f.max_area.empty()) d["triangle_max_area"] = rows(std::move(f.max_area), 1);
  if (!f.neighbors.empty()) d["triangle_neighbors"] = intc(f.neighbors, 3, "neighbour");
}

// The .edge file's keys: 'edges' and 'edge_markers', 'ray_origins' and 'ray_directions'.
void add_edges(py::dict& d, ridt::io::EdgeText& e) {
  if (!e.edges.empty()) d["edges"] = intc(e.edges, 2, "vertex index");
  if (!e.edges.empty() && !e.markers.empty()) d["edge_markers"] = intc(e.markers, 1, "edge marker");
  if (!e.ray_origins.empty()) {
    d["ray_origins"] = intc(e.ray_origins, 1, "vertex index");
    d["ray_directions"] = points(std::move(e.ray_directions));
  }
}

}  // namespace

void bind_triangle_files(py::module_& m) {
  m.def(
      "triangle_files",
      [](const std::map<std::string, std::string>& texts, const std::map<std::string, std::string>& names) {
        for (const auto& [ext, text] : texts) {
          if (ext != "node" && ext != "ele" && ext != "poly" && ext != "area" && ext != "edge" && ext != "neigh")
            throw py::value_error("not one of Triangle's files: '" + ext + "'");
          if (!names.contains(ext)) throw py::value_error("no name for the " + ext + " text");
        }
        Files f;
        try {
          py::gil_scoped_release release;
          f = read_files(texts, names);
        } catch (const ridt::io::IoError& e) {
          throw py::value_error(e.what());
        }
        py::dict d;
        if (f.graph) add_graph(d, *f.graph, f.poly);
        add_triangles(d, f);
        add_edges(d, f.edges);
        return d;
      },
      py::arg("texts"), py::arg("names"),
      "Triangle's files, given as texts[ext] for ext in node, ele, poly, area, edge, neigh (names[ext]\n"
      "stands for each in messages), read into the dict ridt.triangle.loads returns; ValueError with the\n"
      "reader's message for malformed text.");
}
