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
///
/// `tolerance` > 0 (scipy's find_simplex `tol`; kScipyTolerance is its default) also answers
/// a point that lies outside the hull but near it, as scipy's Delaunay.find_simplex does: the
/// hull triangle that the walk towards it leaves by, when each of the point's barycentric
/// coordinates there lies in [-tolerance, 1 + tolerance] (their signs exact, their magnitudes
/// within a few units in the last place) and the point lies in the points' bounding box
/// widened by `tolerance` (an absolute length, as in scipy). A point inside the hull or on it
/// gets the exact answer above whatever the tolerance; 0 (or less) answers -1 for every point
/// outside.
void locate(std::span<const Point> points, std::span<const VertexId> triangles, std::span<const std::int32_t> neighbors,
            std::span<const Point> queries, std::span<std::int32_t> out, unsigned threads = 1, double tolerance = 0);

/// The same for a Triangulation of `points`, returning the answers.
std::vector<std::int32_t> locate(std::span<const Point> points, const Triangulation& triangulation,
                                 std::span<const Point> queries, unsigned threads = 1, double tolerance = 0);

/// scipy's default tolerance of find_simplex and of its interpolators: 100 DBL_EPSILON.
inline constexpr double kScipyTolerance = 100 * 0x1p-52;

}  // namespace ridt
