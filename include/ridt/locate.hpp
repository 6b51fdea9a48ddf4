// Point location in a finished triangulation.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ridt/ridt.hpp"

namespace ridt {

/// For each query point, a triangle whose closure holds it, or -1 when the point lies outside
/// the convex hull or is not finite. Exact: every decision is an orientation test with exact
/// arithmetic, so a point on an edge or at a vertex gets one of the triangles that touch it.
///
/// `triangles` and `neighbors` are a result of triangulate() on `points` (#T by 3 each; the
/// neighbour i across from vertex i, -1 on the hull). The queries are taken in order along a
/// Hilbert curve, each walk starting where the last one ended, so sorted and unsorted queries
/// cost about the same; `threads` threads (0: the machine's hardware threads) take a share of
/// them each. Throws InputError when the arrays' sizes do not match.
void locate(std::span<const Point> points, std::span<const VertexId> triangles, std::span<const std::int32_t> neighbors,
            std::span<const Point> queries, std::span<std::int32_t> out, unsigned threads = 1);

/// The same for a Triangulation of `points`, returning the answers.
std::vector<std::int32_t> locate(std::span<const Point> points, const Triangulation& triangulation,
                                 std::span<const Point> queries, unsigned threads = 1);

}  // namespace ridt
