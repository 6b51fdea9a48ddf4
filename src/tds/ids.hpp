// The numbers every triangulation of the library names its parts by, defined once: the "none"
// of a vertex and of a triangle, an edge slot's link, an edge's constraint, and the branch-free
// steps round a triangle's corners.
#pragma once

#include <cstdint>
#include <limits>

#include "ridt/ridt.hpp"

namespace ridt::detail {

/// An edge slot 3t + i, as the triangle across it names it.
using Link = std::int32_t;
inline constexpr Link kNoLink = -1;
/// No vertex, no triangle: the one "none" of vertex and triangle (slot) numbers.
inline constexpr VertexId kNoVertex = 0xffffffffu;
inline constexpr TriangleId kNoTriangle = 0xffffffffu;

/// An edge's constraint: free, fixed as a piece of input segment k (k itself), or fixed with no
/// input segment.
using Constraint = std::uint32_t;
inline constexpr Constraint kFree = 0xffffffffu;
inline constexpr Constraint kUnnamed = 0xfffffffeu;

/// Links 3u + j must fit in a Link: a triangulation of n points that has 2n + 1 slots.
inline constexpr std::uint64_t kMaxSlotPoints = (std::uint64_t{std::numeric_limits<Link>::max()} - 8) / 6;

// Without branches: a branch on the edge index is taken at random, and mispredicted often.
constexpr int next3(int i) { return (1 << i) & 3; }  // 0 -> 1, 1 -> 2, 2 -> 0
constexpr int prev3(int i) { return (0x12 >> (2 * i)) & 3; }  // 0 -> 2, 1 -> 0, 2 -> 1
/// The triangle and the edge a link names (unsigned: cheaper to divide; never kNoLink).
constexpr TriangleId triangle_of(Link l) { return static_cast<std::uint32_t>(l) / 3; }
constexpr int edge_of(Link l) { return static_cast<int>(static_cast<std::uint32_t>(l) % 3); }
/// The link of triangle t's edge i.
constexpr Link link_to(TriangleId t, int i) { return static_cast<Link>(3 * t + static_cast<TriangleId>(i)); }
static_assert(next3(0) == 1 && next3(1) == 2 && next3(2) == 0 && prev3(0) == 2 && prev3(1) == 0 && prev3(2) == 1);

}  // namespace ridt::detail
