// ridt._core's memory calls: the estimate a triangulation checks before it starts, what the
// system can give, and the blocks kept between calls.
#include <pybind11/pybind11.h>

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
}
