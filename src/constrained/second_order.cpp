// Six-node triangles (ridt/constrained.hpp, second_order): a node at the middle of each edge,
// shared by the two triangles of the edge through their neighbour links.
#include <limits>
#include <numeric>
#include <string>

#include "ridt/constrained.hpp"

namespace ridt {
namespace {

// The slot of triangle m whose neighbour is k, or 3 where none is.
int slot_of(std::span<const std::int32_t> neighbors, std::size_t m, std::size_t k) {
  int j = 0;
  while (j < 3 && neighbors[3 * m + j] != static_cast<std::int32_t>(k)) ++j;
  return j;
}

}  // namespace

SecondOrder second_order(std::span<const Point> vertices, const Triangulation& t) {
  const std::size_t count = t.triangles.size() / 3;
  if (t.neighbors.size() != t.triangles.size())
    throw InputError("six-node triangles need the triangulation's neighbours (Options::neighbors)");
  if (vertices.size() + t.triangles.size() > std::numeric_limits<VertexId>::max())  // a node an edge slot at most
    throw InputError("six-node triangles: " + std::to_string(vertices.size()) + " vertices and the middles of " +
                     std::to_string(count) + " triangles' edges are too many to number");
  for (const VertexId v : t.triangles)
    if (v >= vertices.size())
      throw InputError("six-node triangles: vertex " + std::to_string(v) + " is not one of the " +
                       std::to_string(vertices.size()) + " given");
  SecondOrder out;
  out.triangles.resize(6 * count);
  for (std::size_t k = 0; k < count; ++k) {
    for (int i = 0; i < 3; ++i) out.triangles[6 * k + i] = t.triangles[3 * k + i];
    for (int i = 0; i < 3; ++i) {
      const std::int32_t n = t.neighbors[3 * k + i];
      const auto m = static_cast<std::size_t>(n);
      const int j = n >= 0 && m < count && m != k ? slot_of(t.neighbors, m, k) : 3;
      if (n >= 0 && j == 3)
        throw InputError("six-node triangles: triangle " + std::to_string(k) + "'s neighbour " + std::to_string(n) +
                         " is not another of the " + std::to_string(count) + " triangles with it as a neighbour");
      const VertexId a = t.triangles[3 * k + (i + 1) % 3], b = t.triangles[3 * k + (i + 2) % 3];
      if (n >= 0 && m < k) {  // the triangle across met this edge first: its node
        if (t.triangles[3 * m + (j + 1) % 3] != b || t.triangles[3 * m + (j + 2) % 3] != a)
          throw InputError("six-node triangles: triangles " + std::to_string(m) + " and " + std::to_string(k) +
                           " are neighbours across edges that differ");
        out.triangles[6 * k + 3 + i] = out.triangles[6 * m + 3 + j];
        continue;
      }
      out.triangles[6 * k + 3 + i] = static_cast<VertexId>(vertices.size() + out.nodes.size());
      // std::midpoint: the exact mean rounded once, with no overflow near the largest doubles.
      out.nodes.push_back({std::midpoint(vertices[a].x, vertices[b].x), std::midpoint(vertices[a].y, vertices[b].y)});
      out.ends.push_back(a), out.ends.push_back(b);
    }
  }
  return out;
}

}  // namespace ridt
