// What every file of ridt._core takes and gives: float64 arrays in C order, points as rows of
// two; vectors handed to numpy without a copy.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <span>
#include <string>
#include <utility>
#include <vector>

#include "ridt/ridt.hpp"

namespace ridt_python {

using Points = pybind11::array_t<double, pybind11::array::c_style>;

/// The rows of `a` as points, or a ValueError that names the argument.
inline std::span<const ridt::Point> as_points(const Points& a, const char* name) {
  if (a.ndim() != 2 || a.shape(1) != 2) throw pybind11::value_error(std::string(name) + " must have shape (n, 2)");
  return {reinterpret_cast<const ridt::Point*>(a.data()), static_cast<std::size_t>(a.shape(0))};
}

// A vector's memory handed to numpy without a copy: the array owns the vector through a
// capsule. `shape` must cover the vector's elements (as T, or as doubles for Points).
template <class T, class Elem = T>
pybind11::array_t<Elem> adopt(std::vector<T>&& v, std::vector<pybind11::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(v));
  pybind11::capsule free_it(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return pybind11::array_t<Elem>(shape, reinterpret_cast<const Elem*>(owned->data()), free_it);
}

}  // namespace ridt_python
