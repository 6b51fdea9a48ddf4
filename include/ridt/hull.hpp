// The convex hull of points in the plane, decided exactly.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ridt/ridt.hpp"

namespace ridt {

/// A convex hull (convex_hull()).
struct ConvexHull {
  /// The corners, counter-clockwise from the least point (by x, then y); of equal points the
  /// least index stands for them. A point on a side between two corners is not a corner. Empty
  /// when fewer than three distinct points are given or all are collinear.
  std::vector<VertexId> corners;
  /// With `boundary`: every other point on the boundary, in order round it, beside the side it
  /// lies on (k: corners[k] -> corners[k + 1], the last side back to corners[0]): the points on
  /// the sides between corners, and the copies of the corners and of those points.
  std::vector<VertexId> on_sides;
  std::vector<std::uint32_t> side;
  /// The polygon's area, within one unit in the last place (the shoelace formula's products
  /// and their sum exact, then rounded), and its perimeter, within a few (each side's length
  /// within one, their sum compensated). A product or sum past the largest double overflows.
  double area = 0, perimeter = 0;
};

/// The convex hull of `points` by exact orientation tests: the points are first culled by a
/// polygon of a few extreme points, on `threads` threads (0: the machine's), the rest ordered
/// and chained (Andrew's monotone chain). Throws InputError for a point that is not finite.
ConvexHull convex_hull(std::span<const Point> points, bool boundary = false, unsigned threads = 0);

}  // namespace ridt
