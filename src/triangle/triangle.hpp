// Triangle's run's steps after the mesh (triangle/triangle.cpp, triangle/extras.cpp).
#pragma once

#include <algorithm>
#include <span>
#include <utility>

#include "ridt/constrained.hpp"
#include "ridt/triangle.hpp"

namespace ridt::triangle {

/// Edges (pairs (a, b) with a < b, sorted: ConstrainedTriangulation::edges) found by their ends.
class EdgeIndex {
 public:
  explicit EdgeIndex(std::span<const VertexId> edges) : edges_(edges) {}
  /// The index of edge a-b (either way), or the number of edges where it is none.
  std::size_t find(VertexId a, VertexId b) const {
    const std::pair<VertexId, VertexId> key{std::min(a, b), std::max(a, b)};
    std::size_t lo = 0, hi = edges_.size() / 2;
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (std::pair{edges_[2 * mid], edges_[2 * mid + 1]} < key)
        lo = mid + 1;
      else
        hi = mid;
    }
    return lo < edges_.size() / 2 && edges_[2 * lo] == key.first && edges_[2 * lo + 1] == key.second
        ? lo
        : edges_.size() / 2;
  }

 private:
  std::span<const VertexId> edges_;
};

/// e: every edge of t once, (a, b) with a < b, sorted, into out.edges, and its marker: a piece's
/// (out.segment_markers) where not 0, else 1 on the boundary, 0 inside.
void every_edge(const ConstrainedTriangulation& t, Output& out);
/// v: the mesh's dual, with the vertices' attributes at its vertices.
void add_dual(const ConstrainedTriangulation& t, unsigned threads, Output& out);
/// o2: a node at the middle of every edge, after the vertices, with its marker and attributes;
/// the triangles become six-node ones. `neighbors` are those of out.triangles, `pieces` the
/// fixed edges (ConstrainedTriangulation::edges).
void add_middles(const std::vector<std::int32_t>& neighbors, const std::vector<VertexId>& pieces, Output& out);
/// j: the vertices of no triangle left out, the rest numbered in order.
void jettison(Output& out);

}  // namespace ridt::triangle
