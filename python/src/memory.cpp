// ridt._core's memory calls: the estimate a triangulation checks before it starts, what the
// system can give, the blocks kept between calls, and the out-of-core triangulation of a point
// file larger than memory.
#include <pybind11/pybind11.h>

#include <memory>
#include <string>

#include "ridt/out_of_core.hpp"
#include "ridt/ridt.hpp"

namespace py = pybind11;

void bind_memory(py::module_& m) {
  m.def(
      "estimate_memory",
      [](std::size_t n, const std::string& method, unsigned threads, const std::string& order,
         const std::string& locate) {
        ridt::Options o;
        o.method = ridt::parse<ridt::Method>(method);
        o.order = ridt::parse<ridt::Order>(order);
        o.locate = ridt::parse<ridt::Locate>(locate);
        o.threads = threads;
        return ridt::estimate_memory(n, o);
      },
      py::arg("n"), py::arg("method"), py::arg("threads"), py::arg("order"), py::arg("locate"));
  m.def("available_memory", &ridt::available_memory);
  m.def(
      "triangulate_out_of_core",
      [](const std::string& input, const std::string& output, std::size_t memory_limit, unsigned threads,
         std::uint64_t column_points) {
        ridt::OutOfCoreOptions o;
        o.input = input, o.output = output, o.memory_limit = memory_limit, o.threads = threads;
        o.column_points = column_points;
        ridt::OutOfCoreStats st;
        {
          py::gil_scoped_release release;
          st = ridt::triangulate_out_of_core(o);
        }
        py::dict d;
        d["points"] = st.points, d["triangles"] = st.triangles, d["columns"] = st.columns, d["rows"] = st.rows;
        d["strips"] = st.strips, d["loaded"] = st.loaded, d["retries"] = st.retries;
        d["time_bucket_s"] = st.time_bucket_s, d["time_triangulate_s"] = st.time_triangulate_s;
        d["time_check_s"] = st.time_check_s, d["time_write_s"] = st.time_write_s;
        return d;
      },
      py::arg("input"), py::arg("output"), py::arg("memory_limit"), py::arg("threads"), py::arg("column_points"));
  m.def("set_memory_cache_limit", &ridt::set_memory_cache_limit, py::arg("bytes"));
  m.def("cached_memory", &ridt::cached_memory);
  // ridt::MemoryReuse as a context manager: `with MemoryReuse(bytes): ...`.
  struct Reuse {
    std::size_t bytes;
    std::unique_ptr<ridt::MemoryReuse> scope;
  };
  py::class_<Reuse>(m, "MemoryReuse")
      .def(py::init([](std::size_t bytes) {
             return Reuse{bytes, nullptr};
           }),
           py::arg("bytes"))
      .def("__enter__",
           [](Reuse& r) -> Reuse& {
             r.scope = std::make_unique<ridt::MemoryReuse>(r.bytes);
             return r;
           })
      .def("__exit__", [](Reuse& r, const py::args&) {
        r.scope.reset();
        return false;
      });
}
