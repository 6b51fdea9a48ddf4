// scipy's tolerance at the hull (ridt/locate.hpp's `tolerance`): when a point outside the
// convex hull counts as in a hull triangle. Shared by location (queries/locate.cpp) and the
// interpolation of a grid's nodes (queries/field.hpp), so that both accept the same points.
#pragma once

#include <memory>
#include <mutex>
#include <span>

#include "predicates/predicates.hpp"
#include "ridt/ridt.hpp"

namespace ridt::detail {

/// q counts as in the counter-clockwise triangle (a, b, c) when each of its barycentric
/// coordinates there lies in [-tolerance, 1 + tolerance] and q lies in the points' bounding box
/// widened by `tolerance` on every side: scipy's _barycentric_inside and Qhull's test of points
/// fully outside (an absolute length there, as scipy has it). The coordinates are
/// barycentric's, exact in sign and within a few units in the last place or 2^-44 in size.
class NearHull {
 public:
  NearHull() = default;
  /// No tolerance (0 or less, or NaN) accepts nothing. The box is found the first time a point
  /// outside the hull asks (once, whichever thread asks first): a call whose queries all lie
  /// inside does not scan the points.
  NearHull(std::span<const Point> points, double tolerance)
      : tolerance_(tolerance > 0 ? tolerance : 0), lazy_(std::make_shared<Lazy>()) {
    lazy_->points = points;
  }

  bool active() const { return tolerance_ > 0; }

  /// How far outside a triangle's bounding box a point it accepts can lie, on an axis along
  /// which the triangle spans `extent`: the coordinates' sum is 1, so at most 2 tolerance
  /// extent (doubled for the rounding).
  double margin(double extent) const { return 4 * tolerance_ * extent; }

  bool operator()(const Point& a, const Point& b, const Point& c, const Point& q) const {
    if (!(tolerance_ > 0)) return false;
    const double t = tolerance_;
    std::call_once(lazy_->once, [this] { lazy_->box = extent_of(lazy_->points); });
    const Extent& box = lazy_->box;
    if (q.x < box.x0 - t || q.x > box.x1 + t || q.y < box.y0 - t || q.y > box.y1 + t) return false;
    double w[3];
    barycentric(a, b, c, q, w);
    for (const double x : w)
      if (!(x >= -t && x <= 1 + t)) return false;
    return true;
  }

 private:
  struct Lazy {
    std::span<const Point> points;
    std::once_flag once;
    Extent box;
  };
  double tolerance_ = 0;
  std::shared_ptr<Lazy> lazy_;  // shared by the copies the threads hold
};

}  // namespace ridt::detail
