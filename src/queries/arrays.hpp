// The checks of a triangulation's arrays that the steps after it (location, Voronoi,
// interpolation) make before they read them.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "ridt/ridt.hpp"

namespace ridt::detail {

/// Throws InputError, naming `who`, unless `triangles` and `neighbors` are both #T by 3, every
/// vertex is one of `points` points and every neighbour one of the triangles or -1.
inline void check_arrays(const char* who, std::size_t points, std::span<const VertexId> triangles,
                         std::span<const std::int32_t> neighbors) {
  const std::string w = who;
  if (triangles.size() % 3 != 0 || neighbors.size() != triangles.size())
    throw InputError(w + ": triangles and neighbors must both be #T by 3 (sizes " + std::to_string(triangles.size()) +
                     " and " + std::to_string(neighbors.size()) + ")");
  const std::size_t size = triangles.size() / 3;
  if (size > 0x7fffffffu) throw InputError(w + ": more than 2^31 triangles");
  for (const VertexId v : triangles)
    if (v >= points)
      throw InputError(w + ": vertex " + std::to_string(v) + " of a triangle is not one of the " +
                       std::to_string(points) + " points");
  for (const std::int32_t u : neighbors)
    if (u < -1 || u >= static_cast<std::int64_t>(size))
      throw InputError(w + ": neighbour " + std::to_string(u) + " is not one of the " + std::to_string(size) +
                       " triangles");
}

}  // namespace ridt::detail
