// The walking kernel's structure (tds/delaunay.hpp): its arrays and its bounding triangle.
#include <memory>
#include <new>
#include <stdexcept>
#include <string>

#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"
#include "tds/delaunay.hpp"

namespace ridt::detail {

SlotArrays::SlotArrays(std::uint64_t n, unsigned threads) {
  if (n > kMaxSlotPoints)
    throw InputError("too many points for the walking kernel (at most " + std::to_string(kMaxSlotPoints) + ")");
  // 2k + 1 triangles for k points, at every step.
  const std::size_t size = 3 * (2 * n + 1);
  v.reserve(size), link.reserve(size);
  make_present(v.data(), size * sizeof(VertexId), threads);
  make_present(link.data(), size * sizeof(Link), threads);
  // A vector's new elements are zeroed, on one thread: each array on its own, side by side.
  on_threads(threads >= 2 ? 2 : 1, [&](unsigned w) {
    if (w == 0) v.resize(size);
    if (w == 1 || threads < 2) link.resize(size);
  });
}

std::span<std::uint64_t> SlotArrays::words() {
  // Words begin their lifetime where the vertex numbers were (trivial types: nothing is
  // written); the kernel begins theirs again (DelaunayTds::DelaunayTds).
  const std::size_t count = v.size() * sizeof(VertexId) / sizeof(std::uint64_t);
  std::uninitialized_default_construct_n(reinterpret_cast<std::uint64_t*>(v.data()), count);
  return {std::launder(reinterpret_cast<std::uint64_t*>(v.data())), count};
}

namespace {

// The arrays begun again as vertex numbers (after words()), with the bounding triangle in slot
// 0 of n points' vertices.
std::vector<VertexId> with_root(std::vector<VertexId> v, std::uint32_t n) {
  std::uninitialized_default_construct_n(v.data(), v.size());
  v[0] = n, v[1] = n + 1, v[2] = n + 2;
  return v;
}

}  // namespace

DelaunayTds::DelaunayTds(const Vertices& vertices, SlotArrays arrays)
    : Tds(with_root(std::move(arrays.v), vertices.n()), std::move(arrays.link), 1), vertices_(vertices) {
  if (vertex_array().size() != 3 * (2 * std::size_t{vertices.n()} + 1))
    throw std::logic_error("ridt: slot arrays made for another number of points");
  set_link(0, kNoLink), set_link(1, kNoLink), set_link(2, kNoLink);
}

DelaunayTds::DelaunayTds(const Vertices& vertices) : vertices_(vertices) {
  grow(1);
  for (int i = 0; i < 3; ++i) set_vertex(0, i, vertices.n() + static_cast<VertexId>(i)), set_link(i, kNoLink);
}

}  // namespace ridt::detail
