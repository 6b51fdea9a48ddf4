// ridt._core.SizeField (ridt/size_field.hpp): a target edge length for quality meshes, from a
// grid, a background mesh, scattered points or a vectorized Python function.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <span>
#include <string>

#include "points.hpp"
#include "ridt/size_field.hpp"

namespace py = pybind11;

namespace {

using ridt_python::as_points;
using ridt_python::Points;
using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::span<const double> span_of(const Doubles& a) { return {a.data(), static_cast<std::size_t>(a.size())}; }

// A Python function of an (n, 2) array of points, returning n sizes, as a SizeField. Refinement
// runs without the GIL: each call takes it; the function is held by a reference that is given
// back with the GIL too, so copies of the field need no GIL.
ridt::SizeField of_function(const py::function& f) {
  std::shared_ptr<py::object> held(new py::object(f), [](py::object* o) {
    py::gil_scoped_acquire gil;
    delete o;
  });
  return ridt::SizeField::of([held](std::span<const ridt::Point> at, std::span<double> out) {
    py::gil_scoped_acquire gil;
    py::array_t<double> xy({static_cast<py::ssize_t>(at.size()), py::ssize_t{2}});
    std::copy_n(&at.data()->x, 2 * at.size(), xy.mutable_data());
    const Doubles h = Doubles::ensure((*held)(xy));
    if (!h || static_cast<std::size_t>(h.size()) != at.size())
      throw ridt::InputError("the size function gave " + (h ? std::to_string(h.size()) : std::string("no array of")) +
                             " values for " + std::to_string(at.size()) + " points");
    std::copy_n(h.data(), at.size(), out.data());
  });
}

}  // namespace

void bind_size_field(py::module_& m) {
  py::class_<ridt::SizeField>(m, "SizeField")
      .def_static("uniform", &ridt::SizeField::uniform, py::arg("h"))
      .def_static(
          "grid",
          [](const Doubles& values, std::size_t nx, std::size_t ny, double x0, double y0, double x1, double y1,
             double gradation) { return ridt::SizeField::on_grid(span_of(values), nx, ny, x0, y0, x1, y1, gradation); },
          py::arg("values"), py::arg("nx"), py::arg("ny"), py::arg("x0"), py::arg("y0"), py::arg("x1"), py::arg("y1"),
          py::arg("gradation") = 0.0)
      .def_static(
          "mesh",
          [](const Points& points, const py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>& t,
             const Doubles& values, double gradation) {
            return ridt::SizeField::on_mesh(as_points(points, "points"), {t.data(), static_cast<std::size_t>(t.size())},
                                            span_of(values), gradation);
          },
          py::arg("points"), py::arg("triangles"), py::arg("values"), py::arg("gradation") = 0.0)
      .def_static(
          "scattered",
          [](const Points& points, const Doubles& values, double gradation) {
            return ridt::SizeField::on_points(as_points(points, "points"), span_of(values), gradation);
          },
          py::arg("points"), py::arg("values"), py::arg("gradation") = 0.0)
      .def_static("function", &of_function, py::arg("f"))
      .def(
          "sizes",
          [](const ridt::SizeField& f, const Points& points) {
            const auto p = as_points(points, "points");
            py::array_t<double> out(static_cast<py::ssize_t>(p.size()));
            f.sizes(p, {out.mutable_data(), p.size()});
            return out;
          },
          py::arg("points"));
}
