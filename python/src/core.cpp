// ridt._core: the library's calls for Python. The Python layer (ridt/__init__.py) checks and
// converts the arguments; this module takes float64 arrays in C order only.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <utility>

#include "points.hpp"
#include "ridt/check.hpp"
#include "ridt/constrained.hpp"
#include "ridt/furthest.hpp"
#include "ridt/incremental.hpp"
#include "ridt/interpolate.hpp"
#include "ridt/locate.hpp"
#include "ridt/ridt.hpp"
#include "ridt/terrain.hpp"
#include "ridt/voronoi.hpp"

namespace py = pybind11;

// terrain.cpp, memory.cpp, interpolate.cpp, constrained.cpp
void bind_terrain(py::module_&m), bind_memory(py::module_&m), bind_interpolation(py::module_&m),
    bind_constrained(py::module_&m), bind_triangle(py::module_&m), bind_triangle_files(py::module_&m),
    bind_size_field(py::module_&m), bind_hull(py::module_&m), bind_sphere(py::module_&m), bind_regular(py::module_&m),
    bind_periodic(py::module_&m);

namespace {

using ridt_python::adopt;
using ridt_python::as_points;
using ridt_python::Points;

// A read-only property of Triangulation: the buffer `get` returns, viewed as rows of `cols`
// (one column: a flat array), kept alive by the Triangulation. No copy.
template <class T, class Get>
auto buffer(Get get, std::size_t cols) {
  return [get, cols](py::object self) -> py::array {
    const std::span<const T> data = get(self.cast<const ridt::Triangulation&>());
    const std::size_t rows = data.size() / cols;
    if (cols == 1) return py::array_t<T>({rows}, {sizeof(T)}, data.data(), self);
    return py::array_t<T>({rows, cols}, {cols * sizeof(T), sizeof(T)}, data.data(), self);
  };
}

// A value of Stats or ThreadStats for Python: an option's name, else the value itself.
template <class T>
py::object stat_value(const T& v) {
  if constexpr (std::is_enum_v<T>)
    return py::str(std::string(ridt::to_string(v)));
  else
    return py::cast(v);
}

py::dict stats_dict(const ridt::Stats& s) {
  py::dict d;
  ridt::for_each_stat([&](const char* name, auto member) { d[name] = stat_value(s.*member); });
  py::list per_thread;
  for (const ridt::ThreadStats& t : s.per_thread) {
    py::dict e;
    ridt::for_each_thread_stat([&](const char* name, auto member) { e[name] = stat_value(t.*member); });
    per_thread.append(e);
  }
  d["per_thread"] = per_thread;
  return d;
}

// Every option's names, as the library defines them: {"method": ("auto", "serial", ...), ...}.
template <class E>
void add_names(py::dict& d) {
  py::list names;
  for (const ridt::Named<E>& n : ridt::names<E>()) names.append(std::string(n.name));
  d[std::string(ridt::OptionNames<E>::option).c_str()] = py::tuple(names);
}

ridt::Triangulation run(const Points& points, const std::string& method, unsigned threads, const std::string& order,
                        const std::string& locate, std::uint64_t seed, const std::string& bounding, double k,
                        bool canonical, py::object progress, bool furthest_site, std::size_t memory_limit) {
  ridt::Options o;
  o.memory_limit = memory_limit;
  o.method = ridt::parse<ridt::Method>(method);
  o.order = ridt::parse<ridt::Order>(order);
  o.locate = ridt::parse<ridt::Locate>(locate);
  o.experiment.bounding = ridt::parse<ridt::Bounding>(bounding);
  o.threads = threads;
  o.seed = seed;
  o.experiment.k = k;
  o.canonical_order = canonical;
  o.experiment.time_threads = false;
  // Called on this thread every 65,536 points: the place to notice Ctrl-C (the signal handler
  // only sets a flag while the GIL is released) and to report progress. An exception thrown
  // here abandons the run and reaches Python once every worker has stopped.
  o.progress = [&progress](double share) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (!progress.is_none()) progress(share);
  };
  const std::span<const ridt::Point> pts = as_points(points, "points");
  py::gil_scoped_release nogil;
  return furthest_site ? ridt::triangulate_furthest_site(pts, o) : ridt::triangulate(pts, o);
}

// Rows of a flat int32 array as a list of Python lists, as scipy.spatial.Voronoi's regions and
// ridge_vertices are: row r holds flat[offsets[r] .. offsets[r + 1]). The values are indices
// into `ints`, a list of the ints 0, 1, ..., whose objects the rows share; -1 stands for
// itself. Built through the C API with the cycle collector paused: the lists hold only ints,
// and millions of new containers would otherwise set off a collection every few hundred.
py::list lists(const py::array_t<std::int32_t, py::array::c_style>& flat,
               const py::array_t<std::uint32_t, py::array::c_style>& offsets, const py::list& ints) {
  if (flat.ndim() != 1 || offsets.ndim() != 1 || offsets.size() < 1)
    throw py::value_error("lists: flat and offsets must be one-dimensional, offsets not empty");
  const std::int32_t* f = flat.data();
  const std::uint32_t* o = offsets.data();
  const auto rows = static_cast<std::size_t>(offsets.size() - 1);
  const auto size = static_cast<std::int64_t>(flat.size());
  const auto known = static_cast<std::int64_t>(ints.size());
  for (std::size_t r = 0; r < rows; ++r)
    if (o[r] > o[r + 1] || o[r + 1] > size) throw py::value_error("lists: offsets out of order or past the end");
  for (std::int64_t k = 0; k < size; ++k)
    if (f[k] < -1 || f[k] >= known) throw py::value_error("lists: a value is not one of the ints");
  const py::int_ minus_one(-1);
  PyObject* const* table = reinterpret_cast<PyListObject*>(ints.ptr())->ob_item;
  const int collecting = PyGC_Disable();
  py::list out(rows);
  for (std::size_t r = 0; r < rows; ++r) {
    const std::uint32_t first = o[r], count = o[r + 1] - o[r];
    PyObject* row = PyList_New(count);
    if (row == nullptr) {
      if (collecting) PyGC_Enable();
      throw py::error_already_set();
    }
    for (std::uint32_t k = 0; k < count; ++k) {
      const std::int32_t v = f[first + k];
      PyObject* item = v >= 0 ? table[v] : minus_one.ptr();
      Py_INCREF(item);
      PyList_SET_ITEM(row, k, item);
    }
    PyList_SET_ITEM(out.ptr(), static_cast<py::ssize_t>(r), row);
  }
  if (collecting) PyGC_Enable();
  return out;
}

void bind_triangulation(py::module_& m) {
  py::class_<ridt::Triangulation>(m, "Triangulation", R"doc(
The Delaunay triangulation of a point set, as computed by ridt.triangulate().

Its arrays are views of the library's own buffers, not copies; each keeps the
Triangulation alive.
)doc")
      .def_property_readonly(
          "triangles", buffer<ridt::VertexId>([](const ridt::Triangulation& t) { return std::span(t.triangles); }, 3),
          "(ntriangles, 3) uint32: vertex indices into the points, counter-clockwise")
      .def_property_readonly(
          "neighbors", buffer<std::int32_t>([](const ridt::Triangulation& t) { return std::span(t.neighbors); }, 3),
          "(ntriangles, 3) int32: neighbors[k, i] is the triangle across from vertex i, -1 on the hull")
      .def_property_readonly("hull",
                             buffer<ridt::VertexId>([](const ridt::Triangulation& t) { return std::span(t.hull); }, 1),
                             "(nhull,) uint32: the convex hull's vertices, counter-clockwise, collinear ones included")
      .def_property_readonly("duplicates",
                             buffer<ridt::VertexId>(
                                 [](const ridt::Triangulation& t) {
                                   static_assert(sizeof(ridt::Duplicate) == 2 * sizeof(ridt::VertexId));
                                   return std::span(reinterpret_cast<const ridt::VertexId*>(t.duplicates.data()),
                                                    2 * t.duplicates.size());
                                 },
                                 2),
                             "(nduplicates, 2) uint32: rows (dropped, kept): a point left out and the equal point kept")
      .def_property_readonly(
          "warning", [](const ridt::Triangulation& t) { return t.warning; },
          "why the triangulation is empty ('' when it is not)")
      .def_property_readonly(
          "stats", [](const ridt::Triangulation& t) { return stats_dict(t.stats); }, "counters and timings of the run")
      .def("__len__", &ridt::Triangulation::size);
}

void bind_incremental(py::module_& m) {
  py::class_<ridt::IncrementalTriangulation>(m, "Incremental",
                                             "A triangulation that takes more points (ridt.Delaunay's add_points)")
      .def(py::init([](const Points& points, const ridt::Triangulation& t) {
             const auto pts = as_points(points, "points");
             py::gil_scoped_release nogil;
             return ridt::IncrementalTriangulation(pts, t);
           }),
           py::arg("points"), py::arg("triangulation"))
      .def(
          "add",
          [](ridt::IncrementalTriangulation& self, const Points& points) {
            const auto pts = as_points(points, "points");
            py::gil_scoped_release nogil;
            self.add(pts);
          },
          py::arg("points"))
      .def(
          "triangulation", [](const ridt::IncrementalTriangulation& self) { return self.triangulation(); },
          "a copy of the triangulation of every point so far");

  m.def("triangulate", &run, py::arg("points"), py::arg("method"), py::arg("threads"), py::arg("order"),
        py::arg("locate"), py::arg("seed"), py::arg("bounding"), py::arg("k"), py::arg("canonical"),
        py::arg("progress"), py::arg("furthest_site") = false, py::arg("memory_limit") = 0);
}

// Location in a finished triangulation, and the validator.
void bind_queries(py::module_& m) {
  m.def(
      "locate",
      [](const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& triangles,
         const py::array_t<std::int32_t, py::array::c_style>& neighbors, const Points& queries, unsigned threads,
         double tolerance) {
        const auto pts = as_points(points, "points");
        const auto q = as_points(queries, "queries");
        py::array_t<std::int32_t> out(static_cast<py::ssize_t>(q.size()));
        const std::span<const ridt::VertexId> t(triangles.data(), static_cast<std::size_t>(triangles.size()));
        const std::span<const std::int32_t> nb(neighbors.data(), static_cast<std::size_t>(neighbors.size()));
        const std::span<std::int32_t> o(out.mutable_data(), q.size());
        {
          py::gil_scoped_release nogil;
          ridt::locate(pts, t, nb, q, o, threads, tolerance);
        }
        return out;
      },
      py::arg("points"), py::arg("triangles"), py::arg("neighbors"), py::arg("queries"), py::arg("threads"),
      py::arg("tolerance") = 0.0);

  m.def(
      "check",
      [](const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& triangles, bool furthest_site,
         const py::array_t<std::uint32_t, py::array::c_style>& segments) {
        const auto pts = as_points(points, "points");
        const std::span<const ridt::VertexId> t(triangles.data(), static_cast<std::size_t>(triangles.size()));
        const std::span<const ridt::VertexId> s(segments.data(), static_cast<std::size_t>(segments.size()));
        ridt::CheckResult r;
        {
          py::gil_scoped_release nogil;
          r = furthest_site ? ridt::check_furthest_site(pts, t) : ridt::check_constrained(pts, t, s);
        }
        return py::make_tuple(r.valid, r.message, r.problems);
      },
      py::arg("points"), py::arg("triangles"), py::arg("furthest_site") = false,
      py::arg("segments") = py::array_t<std::uint32_t>(0));
}

// Per point and per triangle: the nearest vertex of each query, each triangle's transform.
void bind_nearest(py::module_& m) {
  m.def(
      "nearest",
      [](const Points& points, const ridt::Triangulation& t, const Points& queries, unsigned threads) {
        const auto pts = as_points(points, "points");
        const auto q = as_points(queries, "queries");
        std::vector<std::int32_t> out;
        {
          py::gil_scoped_release nogil;
          out = ridt::nearest_vertex(pts, t, q, threads);
        }
        return py::array_t<std::int32_t>(out.size(), out.data());
      },
      py::arg("points"), py::arg("triangulation"), py::arg("queries"), py::arg("threads"));

  m.def(
      "transforms",
      [](const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& triangles, unsigned threads) {
        const auto pts = as_points(points, "points");
        const std::span<const ridt::VertexId> t(triangles.data(), static_cast<std::size_t>(triangles.size()));
        py::array_t<double> out({static_cast<py::ssize_t>(t.size() / 3), py::ssize_t{3}, py::ssize_t{2}});
        const std::span<double> o(out.mutable_data(), t.size() * 2);
        {
          py::gil_scoped_release nogil;
          ridt::barycentric_transforms(pts, t, o, threads);
        }
        return out;
      },
      py::arg("points"), py::arg("triangles"), py::arg("threads"));
}

void bind_voronoi(py::module_& m) {
  m.def(
      "voronoi",
      [](const Points& points, const ridt::Triangulation& t, unsigned threads, bool merge) {
        const auto pts = as_points(points, "points");
        ridt::Voronoi v;
        {
          py::gil_scoped_release nogil;
          v = ridt::voronoi(pts, t, threads, merge);
        }
        // The ridges as they are, four int32 a ridge (a, b, u, v): ridge_points and ridge_vertices
        // are views of their columns, with no copy.
        static_assert(sizeof(ridt::Ridge) == 4 * sizeof(std::int32_t));
        const auto size = [](const auto& x) { return static_cast<py::ssize_t>(x.size()); };
        const py::ssize_t vertices = size(v.vertices), offsets = size(v.cell_offsets),
                          cell_vertices = size(v.cell_vertices), sites = size(v.point_cell), ridges = size(v.ridges);
        return py::make_tuple(adopt<ridt::Point, double>(std::move(v.vertices), {vertices, 2}),
                              adopt(std::move(v.cell_offsets), {offsets}),
                              adopt(std::move(v.cell_vertices), {cell_vertices}),
                              adopt(std::move(v.point_cell), {sites}),
                              adopt<ridt::Ridge, std::int32_t>(std::move(v.ridges), {ridges, 4}));
      },
      py::arg("points"), py::arg("triangulation"), py::arg("threads"), py::arg("merge") = true);

  m.def(
      "second_order",
      [](const Points& points, const ridt::Triangulation& t) {
        const auto pts = as_points(points, "points");
        ridt::SecondOrder s;
        {
          py::gil_scoped_release nogil;
          s = ridt::second_order(pts, t);
        }
        if (pts.size() + s.nodes.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
          throw ridt::InputError("six-node triangles: " + std::to_string(pts.size() + s.nodes.size()) +
                                 " nodes are more than Python's int32 indices hold");
        const auto nodes = static_cast<py::ssize_t>(s.nodes.size());
        const auto triangles = static_cast<py::ssize_t>(s.triangles.size() / 6);
        return py::make_tuple(adopt<ridt::Point, double>(std::move(s.nodes), {nodes, 2}),
                              adopt(std::move(s.ends), {nodes, 2}), adopt(std::move(s.triangles), {triangles, 6}));
      },
      py::arg("points"), py::arg("triangulation"),
      "Six-node triangles (ridt::second_order): (nodes (k, 2), their edges' ends (k, 2), triangles (m, 6)).");

  m.def("lists", &lists, py::arg("flat"), py::arg("offsets"), py::arg("ints"),
        "Rows of `flat` as a list of lists: row r is flat[offsets[r]:offsets[r + 1]]; each value v >= 0\n"
        "is the object ints[v] (shared, not a new int), -1 is -1.");
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "ridt's C++ library (use the ridt package, which checks and converts arguments)";
  py::register_exception<ridt::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<ridt::IoError>(m, "IoError", PyExc_OSError);
  // Registered after InputError, whose kind it is, so that it is tried first.
  py::register_exception<ridt::MemoryError>(m, "RidtMemoryError", PyExc_MemoryError);
  py::dict names;
  add_names<ridt::Method>(names);
  add_names<ridt::Order>(names);
  add_names<ridt::Locate>(names);
  add_names<ridt::Bounding>(names);
  add_names<ridt::Merge>(names);
  add_names<ridt::Surface>(names);
  add_names<ridt::Returns>(names);
  m.attr("NAMES") = names;
  m.attr("MAX_THREADS") = ridt::kMaxThreads;
  bind_triangulation(m);
  bind_incremental(m);
  bind_size_field(m);
  bind_constrained(m);
  bind_triangle(m);
  bind_triangle_files(m);
  bind_terrain(m);
  bind_queries(m);
  bind_nearest(m);
  bind_voronoi(m);
  bind_hull(m);
  bind_sphere(m);
  bind_regular(m);
  bind_periodic(m);
  bind_interpolation(m);
  bind_memory(m);
}
