// ridt._core's memory calls: the estimate a triangulation checks before it starts, what the
// system can give, and the blocks kept between calls.
#include <pybind11/pybind11.h>

#include <memory>
#include <string>

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
