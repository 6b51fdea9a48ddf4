// ridt._core's interpolation calls (ridt/interpolate.hpp): linear, natural-neighbour and cubic
// answers at queries or at a grid's nodes, the cubic's gradients, and scipy's cubic griddata
// onto a grid in one call. Float64 arrays in C order; ridt/_interpolate.py checks the rest.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

#include "points.hpp"
#include "ridt/interpolate.hpp"

namespace py = pybind11;

namespace {

using ridt_python::as_points;
using ridt_python::Points;

// The interpolant of `values` (n by k) at `where`: queries, or a grid's nodes, `rows` answers
// in a new (rows, k) array, computed without the GIL.
template <class Where>
py::array_t<double> interpolate_at(const Points& points, const ridt::Triangulation& t, const Points& values,
                                   const Where& where, std::size_t rows, double fill, const std::string& method,
                                   unsigned threads, const std::optional<Points>& gradients, double hull_tolerance) {
  const auto pts = as_points(points, "points");
  if (values.ndim() != 2) throw py::value_error("values must have shape (n, k)");
  const auto k = static_cast<std::size_t>(values.shape(1));
  const ridt::Values v{std::span<const double>(values.data(), static_cast<std::size_t>(values.size())), k};
  py::array_t<double> a({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(k)});
  const std::span<double> out(a.mutable_data(), rows * k);
  {
    py::gil_scoped_release nogil;
    if (method == "cubic") {
      if (!gradients) throw std::invalid_argument("the cubic needs gradients");
      const std::span<const double> g(gradients->data(), static_cast<std::size_t>(gradients->size()));
      ridt::interpolate_clough_tocher(pts, t, v, g, where, out, fill, threads, hull_tolerance);
    } else if (method == "natural")
      ridt::interpolate_natural_neighbor(pts, t, v, where, out, fill, threads, hull_tolerance);
    else
      ridt::interpolate_linear(pts, t, v, where, out, fill, threads, hull_tolerance);
  }
  return a;
}

// griddata's cubic onto a grid: (values at the nodes, sweeps).
py::tuple cubic_on_grid(const Points& points, const Points& values, const Points& x, const Points& y, bool x_major,
                        double fill, double tol, int maxiter, unsigned threads, double hull_tolerance) {
  const auto pts = as_points(points, "points");
  if (values.ndim() != 2) throw py::value_error("values must have shape (n, k)");
  if (x.ndim() != 1 || y.ndim() != 1) throw py::value_error("the grid's axes must be one-dimensional");
  const ridt::Grid g{
      {x.data(), static_cast<std::size_t>(x.size())}, {y.data(), static_cast<std::size_t>(y.size())}, x_major};
  const auto k = static_cast<std::size_t>(values.shape(1));
  const ridt::Values v{std::span<const double>(values.data(), static_cast<std::size_t>(values.size())), k};
  py::array_t<double> a({static_cast<py::ssize_t>(g.size()), static_cast<py::ssize_t>(k)});
  const std::span<double> out(a.mutable_data(), g.size() * k);
  int sweeps = 0;
  {
    py::gil_scoped_release nogil;
    sweeps = ridt::griddata_cubic(pts, v, g, out, fill, tol, maxiter, threads, hull_tolerance);
  }
  return py::make_tuple(a, sweeps);
}

// The cubic's gradients, and griddata's cubic onto a grid in one call.
void bind_cubic(py::module_& m) {
  m.def(
      "estimate_gradients",
      [](const Points& points, const ridt::Triangulation& t, const Points& values, double tol, int maxiter,
         unsigned threads) {
        const auto pts = as_points(points, "points");
        if (values.ndim() != 2) throw py::value_error("values must have shape (n, k)");
        const auto k = static_cast<std::size_t>(values.shape(1));
        const ridt::Values v{std::span<const double>(values.data(), static_cast<std::size_t>(values.size())), k};
        py::array_t<double> g({static_cast<py::ssize_t>(pts.size()), static_cast<py::ssize_t>(k), py::ssize_t{2}});
        int sweeps = 0;
        {
          py::gil_scoped_release nogil;
          sweeps = ridt::estimate_gradients(pts, t, v, std::span<double>(g.mutable_data(), pts.size() * k * 2), tol,
                                            maxiter, threads);
        }
        return py::make_tuple(g, sweeps);
      },
      py::arg("points"), py::arg("triangulation"), py::arg("values"), py::arg("tol"), py::arg("maxiter"),
      py::arg("threads") = 1u);

  // Of the points' own triangulation, made in the call: sweeps -1 where there is none.
  m.def(
      "griddata_cubic",
      [](const Points& points, const Points& values, const Points& x, const Points& y, bool x_major, double fill,
         double tol, int maxiter, unsigned threads, double hull_tolerance) {
        return cubic_on_grid(points, values, x, y, x_major, fill, tol, maxiter, threads, hull_tolerance);
      },
      py::arg("points"), py::arg("values"), py::arg("x"), py::arg("y"), py::arg("x_major"), py::arg("fill"),
      py::arg("tol"), py::arg("maxiter"), py::arg("threads"), py::arg("hull_tolerance") = 0.0);
}

}  // namespace

void bind_interpolation(py::module_& m) {
  m.def(
      "interpolate",
      [](const Points& points, const ridt::Triangulation& t, const Points& values, const Points& queries, double fill,
         const std::string& method, unsigned threads, const std::optional<Points>& gradients, double hull_tolerance) {
        const auto q = as_points(queries, "queries");
        return interpolate_at(points, t, values, q, q.size(), fill, method, threads, gradients, hull_tolerance);
      },
      py::arg("points"), py::arg("triangulation"), py::arg("values"), py::arg("queries"), py::arg("fill"),
      py::arg("method"), py::arg("threads"), py::arg("gradients") = py::none(), py::arg("hull_tolerance") = 0.0);

  m.def(
      "interpolate_grid",
      [](const Points& points, const ridt::Triangulation& t, const Points& values, const Points& x, const Points& y,
         bool x_major, double fill, const std::string& method, unsigned threads, const std::optional<Points>& gradients,
         double hull_tolerance) {
        if (x.ndim() != 1 || y.ndim() != 1) throw py::value_error("the grid's axes must be one-dimensional");
        const ridt::Grid g{
            {x.data(), static_cast<std::size_t>(x.size())}, {y.data(), static_cast<std::size_t>(y.size())}, x_major};
        return interpolate_at(points, t, values, g, g.size(), fill, method, threads, gradients, hull_tolerance);
      },
      py::arg("points"), py::arg("triangulation"), py::arg("values"), py::arg("x"), py::arg("y"), py::arg("x_major"),
      py::arg("fill"), py::arg("method"), py::arg("threads"), py::arg("gradients") = py::none(),
      py::arg("hull_tolerance") = 0.0);
  bind_cubic(m);

  // Row k: the barycentric coordinates of queries[k] in triangle triangles[k] (ridt::barycentric:
  // within 2^-44 of the exact ones, exact where a side passes through the query); NaN where the
  // query is not finite.
  m.def(
      "barycentric",
      [](const Points& points, const py::array_t<std::int32_t, py::array::c_style>& triangles, const Points& queries) {
        const auto pts = as_points(points, "points");
        const auto q = as_points(queries, "queries");
        if (triangles.ndim() != 2 || triangles.shape(1) != 3 ||
            static_cast<std::size_t>(triangles.shape(0)) != q.size())
          throw py::value_error("triangles must have shape (m, 3), a row a query");
        py::array_t<double> w({static_cast<py::ssize_t>(q.size()), py::ssize_t{3}});
        double* out = w.mutable_data();
        const std::int32_t* tri = triangles.data();
        for (std::size_t k = 0; k < q.size(); ++k) {
          for (int i = 0; i < 3; ++i)
            if (tri[3 * k + i] < 0 || static_cast<std::size_t>(tri[3 * k + i]) >= pts.size())
              throw py::index_error("a triangle refers to a point out of range");
          if (!std::isfinite(q[k].x) || !std::isfinite(q[k].y)) {
            out[3 * k] = out[3 * k + 1] = out[3 * k + 2] = std::numeric_limits<double>::quiet_NaN();
            continue;
          }
          const std::array<double, 3> b =
              ridt::barycentric(pts[tri[3 * k]], pts[tri[3 * k + 1]], pts[tri[3 * k + 2]], q[k]);
          std::copy(b.begin(), b.end(), out + 3 * k);
        }
        return w;
      },
      py::arg("points"), py::arg("triangles"), py::arg("queries"));
}
