// The circumcentre of three points in floating point (not exact), for the Voronoi diagram and
// natural-neighbour interpolation.
#pragma once

#include "ridt/ridt.hpp"

namespace ridt::detail {

/// The circumcentre of a, b and c, computed relative to a, which keeps it accurate for a small
/// triangle far from the origin. Infinite or NaN for collinear points.
inline Point circumcentre(const Point& a, const Point& b, const Point& c) {
  const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const double d = 2 * (bx * cy - by * cx);
  return {a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d};
}

}  // namespace ridt::detail
