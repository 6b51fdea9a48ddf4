// What the regular triangulation (regular/regular.cpp) settles once its points are inserted:
// the hull, and the copies and hidden points grouped.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "predicates/power.hpp"
#include "ridt/regular.hpp"
#include "tds/tds.hpp"

namespace ridt::detail {

/// The hull, counter-clockwise from its lexicographically least vertex, as input indices: each
/// wall (p, q, infinity) runs p -> q, so the hull runs q -> p. The walls found on `threads`.
std::vector<VertexId> hull_of(const Tds& tds, VertexId infinite, std::span<const Point> points,
                              const std::vector<VertexId>& input, unsigned threads);

/// Copies found at insertion (a point at a vertex's place with its weight) and hidden points
/// that are copies of each other (a copy of a point hidden before it came): each group of equal
/// weighted points among them, found by a hash of their values and then compared, keeps its
/// least input index, the vertex's (relabelled in `input`) or a hidden point's; the others are
/// duplicates. `q`: the weighted points by vertex id (hashed in that order, not read at random).
struct Settled {
  std::vector<Duplicate> duplicates;
  std::vector<VertexId> hidden;
};
Settled settle(std::span<const Point> points, std::span<const double> weights, std::span<const Weighted> q,
               const std::vector<std::pair<VertexId, VertexId>>& copies, const std::vector<std::uint8_t>& is_hidden,
               std::vector<VertexId>& input, unsigned threads);

}  // namespace ridt::detail
