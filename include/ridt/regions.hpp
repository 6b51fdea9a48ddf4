// What an exact exchange between regions of the plane needs (ridt-mpi's ranks, the out-of-core
// strips: ridt/out_of_core.hpp): a point with its input index, circumcircles widened so that a
// decision made from them in floating point never leaves out a point the exact in-circle test
// would find, and exact convex hulls.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "ridt/predicates.hpp"
#include "ridt/ridt.hpp"

namespace ridt::regions {

/// An axis-parallel box [x0, x1] x [y0, y1].
struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  /// The distance from (x, y) to the box (0 inside), without overflow or underflow.
  double distance(double x, double y) const {
    const double dx = x < x0 ? x0 - x : x > x1 ? x - x1 : 0;
    const double dy = y < y0 ? y0 - y : y > y1 ? y - y1 : 0;
    return std::hypot(dx, dy);
  }
};

/// A point and its input index.
struct Site {
  double x, y;
  std::uint64_t id;
};
static_assert(sizeof(Site) == 24);

/// A disc in the plane (r infinite: the whole plane).
struct Disc {
  double x, y, r;
};

/// The circumcircle of (a, b, c), widened so that it holds every point the exact in-circle
/// test finds inside or on it; the whole plane when the working precision cannot place it.
/// Computed relative to a and scaled by the triangle's size, so that huge and tiny coordinates
/// neither overflow nor underflow. Only for choosing whom to ask and where to look: which
/// points are inside is decided exactly.
///
/// The widening bounds the centre's error. In the scaled coordinates (each within two ulps of
/// its exact value, none above 1 in size) the centre u solves a 2 x 2 system with determinant
/// D = d / 2: errors of its entries and right side move u by at most about
/// (12 + 8 |u|) eps / |D|, and the rounding of the formula (D's three operations, each
/// numerator's four) by about (16 + 6 |u|) eps / |D| more, eps the working precision's unit
/// roundoff; the bound below is four times their sum, with the rounding of the centre to
/// double. So a flat triangle's huge circle grows by its error, not by a share of its radius,
/// and does not cover rows of cells it cannot reach.
template <class F>
Disc circle_in(const Point& a, const Point& b, const Point& c, F& determinant) {
  constexpr Disc kEverything{0, 0, INFINITY};
  constexpr double kEps = 0x1p-53;
  constexpr F kEpsF = std::numeric_limits<F>::epsilon() / 2;
  const F size =
      std::max({std::fabs(F(b.x) - a.x), std::fabs(F(b.y) - a.y), std::fabs(F(c.x) - a.x), std::fabs(F(c.y) - a.y)});
  if (!(size > 0) || !std::isfinite(size)) return kEverything;
  const F bx = (F(b.x) - a.x) / size, by = (F(b.y) - a.y) / size, cx = (F(c.x) - a.x) / size,
          cy = (F(c.y) - a.y) / size;
  const F d = 2 * (bx * cy - by * cx);
  determinant = d;
  if (d == 0) return kEverything;
  const F b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const F ux = (cy * b2 - by * c2) / d, uy = (bx * c2 - cx * b2) / d;
  const F u = std::sqrt(ux * ux + uy * uy);  // in the triangle's size
  const Point centre{static_cast<double>(a.x + ux * size), static_cast<double>(a.y + uy * size)};
  const F shift = (112 + 56 * u) * kEpsF / std::fabs(d / 2) * size +
      4 * kEps * (std::fabs(F(a.x)) + std::fabs(F(a.y)) + u * size);  // and the centre's rounding to double
  const auto r = static_cast<double>((u * size * (1 + 8 * kEps) + 2 * shift) * (1 + 4 * kEps));
  if (!std::isfinite(centre.x) || !std::isfinite(centre.y) || !std::isfinite(r)) return kEverything;
  return {centre.x, centre.y, r};
}

/// In double, and again in long double (x86's 64-bit significand: an error 2048 times smaller)
/// where the triangle is flat enough for the error to matter.
inline Disc circle(const Point& a, const Point& b, const Point& c) {
  double d = 0;
  const Disc quick = circle_in<double>(a, b, c, d);
  if (!(std::fabs(d) < 1e-3) || sizeof(long double) == sizeof(double)) return quick;
  long double ld = 0;
  return circle_in<long double>(a, b, c, ld);
}

/// Whether the disc may meet the convex polygon `hull` (counter-clockwise; one or two points:
/// a point or a segment): false only when its centre, outside the polygon, is farther than its
/// radius from every edge, with a margin for rounding. Anything not finite answers true.
inline bool may_meet(const Disc& d, const std::vector<Site>& hull) {
  if (hull.empty()) return false;
  if (!std::isfinite(d.r)) return true;
  bool inside = hull.size() >= 3;
  double nearest = INFINITY;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Site& a = hull[i];
    const Site& b = hull[(i + 1) % hull.size()];
    const double ex = b.x - a.x, ey = b.y - a.y, px = d.x - a.x, py = d.y - a.y;
    const double cross = ex * py - ey * px;  // > 0: the centre is left of the edge, inward
    if (!(cross > 0)) inside = false;
    const double length = ex * ex + ey * ey;
    const double t = length > 0 ? std::clamp((px * ex + py * ey) / length, 0.0, 1.0) : 0.0;
    const double dx = px - t * ex, dy = py - t * ey;
    nearest = std::min(nearest, std::sqrt(dx * dx + dy * dy));
    if (!std::isfinite(cross) || !std::isfinite(nearest)) return true;
  }
  return inside || nearest <= d.r * (1 + 1e-9);
}

/// The order hull_of_sorted takes: by x, then y, then input index (equal points by index).
inline bool by_place(const Site& u, const Site& v) {
  return u.x != v.x ? u.x < v.x : u.y != v.y ? u.y < v.y : u.id < v.id;
}

/// The convex hull of points sorted by x, then y (Andrew's chain, exact orientation tests),
/// counter-clockwise, collinear points left out.
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

}  // namespace ridt::regions
