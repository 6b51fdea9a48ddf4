// What the regular triangulation (regular/regular.cpp) settles once its points are inserted:
// the hull, the copies and hidden points grouped, and the faces written.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "ridt/regular.hpp"
#include "tds/tds.hpp"

namespace ridt::detail {

/// The hull, counter-clockwise from its lexicographically least vertex, as input indices: each
/// wall (p, q, infinity) runs p -> q, so the hull runs q -> p.
std::vector<VertexId> hull_of(const Tds& tds, VertexId infinite, std::span<const Point> points,
                              const std::vector<VertexId>& input);

/// Copies found at insertion (a point at a vertex's place with its weight) and hidden points
/// that are copies of each other (a copy of a point hidden before it came): each group of equal
/// weighted points among them, found by a hash of their values and then compared, keeps its
/// least input index, the vertex's (relabelled in `input`) or a hidden point's; the others are
/// duplicates.
struct Settled {
  std::vector<Duplicate> duplicates;
  std::vector<VertexId> hidden;
};
Settled settle(std::span<const Point> points, std::span<const double> weights,
               const std::vector<std::pair<VertexId, VertexId>>& copies, const std::vector<std::uint8_t>& is_hidden,
               std::vector<VertexId>& input, unsigned threads);

/// The finite faces (`input`: each vertex id's input index) into out.triangles and
/// out.neighbors in their slots' order, written over the structure's own arrays.
void written_in_place(Tds& tds, VertexId inf, const std::vector<VertexId>& input, RegularTriangulation& out);

}  // namespace ridt::detail
