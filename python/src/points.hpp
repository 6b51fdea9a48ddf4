// What every file of ridt._core takes: float64 arrays in C order, points as rows of two.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <span>
#include <string>

#include "ridt/ridt.hpp"

namespace ridt_python {

using Points = pybind11::array_t<double, pybind11::array::c_style>;

/// The rows of `a` as points, or a ValueError that names the argument.
inline std::span<const ridt::Point> as_points(const Points& a, const char* name) {
  if (a.ndim() != 2 || a.shape(1) != 2) throw pybind11::value_error(std::string(name) + " must have shape (n, 2)");
  return {reinterpret_cast<const ridt::Point*>(a.data()), static_cast<std::size_t>(a.shape(0))};
}

}  // namespace ridt_python
