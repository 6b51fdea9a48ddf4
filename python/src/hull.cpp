// ridt._core's convex hull: ridt::convex_hull and its validator (ridt/hull.hpp, ridt/check.hpp).
#include "ridt/hull.hpp"

#include "points.hpp"
#include "ridt/check.hpp"
#include "ridt/predicates.hpp"

namespace py = pybind11;

using ridt_python::adopt;
using ridt_python::as_points;
using ridt_python::Points;

void bind_hull(py::module_& m) {
  m.def(
      "convex_hull",
      [](const Points& points, bool boundary, unsigned threads) {
        const auto pts = as_points(points, "points");
        ridt::ConvexHull h;
        {
          py::gil_scoped_release nogil;
          h = ridt::convex_hull(pts, boundary, threads);
        }
        const auto corners = static_cast<py::ssize_t>(h.corners.size()),
                   on = static_cast<py::ssize_t>(h.on_sides.size());
        return py::make_tuple(adopt(std::move(h.corners), {corners}), adopt(std::move(h.on_sides), {on}),
                              adopt(std::move(h.side), {on}), h.area, h.perimeter);
      },
      py::arg("points"), py::arg("boundary") = false, py::arg("threads") = 0,
      "(corners, on_sides, side, area, perimeter): the exact convex hull, corners counter-clockwise");
  m.def(
      "check_convex_hull",
      [](const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& corners, unsigned threads) {
        const auto pts = as_points(points, "points");
        const std::span<const ridt::VertexId> c(corners.data(), static_cast<std::size_t>(corners.size()));
        ridt::CheckResult r;
        {
          py::gil_scoped_release nogil;
          r = ridt::check_convex_hull(pts, c, threads);
        }
        return py::make_tuple(r.valid, r.message, r.problems);
      },
      py::arg("points"), py::arg("corners"), py::arg("threads") = 0);
  m.def(
      "sees",
      [](const Points& points, const py::array_t<std::uint32_t, py::array::c_style>& sides, std::size_t from) {
        const auto pts = as_points(points, "points");
        if (sides.ndim() != 2 || sides.shape(1) != 2) throw py::value_error("sides must have shape (n, 2)");
        const std::size_t n = static_cast<std::size_t>(sides.shape(0));
        const std::uint32_t* s = sides.data();
        for (std::size_t k = 0; k < 2 * n; ++k)
          if (s[k] >= pts.size()) throw py::value_error("a side's end is not a point's index");
        if (from >= pts.size()) throw py::value_error("no such point");
        std::vector<std::uint8_t> out(n);
        for (std::size_t k = 0; k < n; ++k) out[k] = ridt::orientation(pts[s[2 * k]], pts[s[2 * k + 1]], pts[from]) < 0;
        return adopt(std::move(out), {static_cast<py::ssize_t>(n)});
      },
      py::arg("points"), py::arg("sides"), py::arg("point"),
      "per side a -> b (counter-clockwise round a convex polygon): whether the point lies strictly beyond it, exactly");
}
