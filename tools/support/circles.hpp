// Geometry that the tools' exact region exchanges share (ridt-mpi's ranks, the out-of-core
// strips): a point with its input index, circumcircles widened so that a decision made from
// them in floating point never leaves out a point the exact test would find, and exact hulls.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "io.hpp"
#include "ridt/predicates.hpp"
#include "ridt/ridt.hpp"

namespace ridt::io {

// A point and its input index.
struct Site {
  double x, y;
  std::uint64_t id;
};
static_assert(sizeof(Site) == 24);

// A disc in the plane (r infinite: the whole plane).
struct Disc {
  double x, y, r;
};

// The circumcircle of (a, b, c), widened so that it holds every point the exact in-circle
// test finds inside or on it; the whole plane when double precision cannot place it. Computed
// relative to a and scaled by the triangle's size, so that huge and tiny coordinates neither
// overflow nor underflow. Only for choosing whom to ask and where to look: which points are
// inside is decided exactly.
inline Disc circle(const Point& a, const Point& b, const Point& c) {
  constexpr Disc kEverything{0, 0, INFINITY};
  const double size =
      std::max({std::fabs(b.x - a.x), std::fabs(b.y - a.y), std::fabs(c.x - a.x), std::fabs(c.y - a.y)});
  if (!(size > 0) || !std::isfinite(size)) return kEverything;
  const double bx = (b.x - a.x) / size, by = (b.y - a.y) / size, cx = (c.x - a.x) / size, cy = (c.y - a.y) / size;
  const double d = 2 * (bx * cy - by * cx);
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const double ux = (cy * b2 - by * c2) / d, uy = (bx * c2 - cx * b2) / d;
  const double radius = std::sqrt(ux * ux + uy * uy) * size;  // ux, uy: in the triangle's size
  const Point centre{a.x + ux * size, a.y + uy * size};
  // The rounding of a flat triangle's centre grows as the triangle flattens: a generous
  // relative margin, and a little absolute one.
  const double scale = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(centre.x), std::fabs(centre.y), radius});
  const double r = radius * (1 + 1e-6) + 1e-9 * scale;
  if (!std::isfinite(centre.x) || !std::isfinite(centre.y) || !std::isfinite(r) || d == 0) return kEverything;
  return {centre.x, centre.y, r};
}

// The convex hull of points sorted by x, then y (Andrew's chain, exact orientation tests),
// counter-clockwise, collinear points left out.
inline std::vector<Site> hull_of_sorted(const std::vector<Site>& s) {
  if (s.size() < 3) return s;
  std::vector<std::uint32_t> h(2 * s.size());  // indices: a fraction of the points' size
  std::size_t k = 0;
  auto at = [&](std::size_t j) { return Point{s[h[j]].x, s[h[j]].y}; };
  auto add = [&](std::size_t i, std::size_t floor) {
    while (k >= floor && ridt::orientation(at(k - 2), at(k - 1), {s[i].x, s[i].y}) <= 0) --k;
    h[k++] = static_cast<std::uint32_t>(i);
  };
  for (std::size_t i = 0; i < s.size(); ++i) add(i, 2);  // the lower chain
  const std::size_t lower = k + 1;
  for (std::size_t i = s.size() - 1; i-- > 0;) add(i, lower);  // the upper chain, back
  std::vector<Site> hull(k - 1);  // the first point closes the upper chain
  for (std::size_t j = 0; j + 1 < k; ++j) hull[j] = s[h[j]];
  return hull;
}

}  // namespace ridt::io
