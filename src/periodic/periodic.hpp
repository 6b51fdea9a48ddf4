// What the periodic triangulation's parts share (src/periodic/, src/check/check_periodic.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "ridt/periodic.hpp"

namespace ridt::detail {

/// The offset (dx, dy), computed in int from offsets: in range wherever those are a periodic
/// triangulation's (sums and differences of a few of at most kMaxOffset).
inline Offset make_offset(int dx, int dy) { return {static_cast<std::int16_t>(dx), static_cast<std::int16_t>(dy)}; }

/// Each edge's twin: edge slot 3t + i (across from corner i, running corner i + 1 -> i + 2)
/// and the slot of the edge that runs back between the same copies once the two triangles are
/// placed side by side (the same two points, the offset between them negated), or -1 where
/// there is none; -2 where there are several. `points` bounds the indices.
std::vector<std::int64_t> periodic_twins(std::span<const VertexId> triangles, std::span<const Offset> offsets,
                                         std::size_t points);

/// triangulate_periodic's two ways: the points' own Delaunay triangulation and two strips across
/// the domain's sides (nothing where the points have no triangulation of their own, or the
/// strips would be a quarter of the domain wide), and the triangulation of all the points and
/// their copies near the domain (any points).
/// Without `neighbors`, the split way leaves neighbor_offsets empty (the neighbours found still).
std::optional<PeriodicTriangulation> triangulate_periodic_split(std::span<const Point> points,
                                                                const PeriodicDomain& domain, unsigned threads,
                                                                bool neighbors = true);
PeriodicTriangulation triangulate_periodic_whole(std::span<const Point> points, const PeriodicDomain& domain,
                                                 unsigned threads);

}  // namespace ridt::detail
