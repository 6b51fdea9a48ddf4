// The library's exact geometric predicates, for code outside it (tools, bindings, users): the
// signs its triangulations are built on, exact for every finite double input.
#pragma once

#include "ridt/ridt.hpp"

namespace ridt {

/// +1 when (a, b, c) turn counter-clockwise, -1 clockwise, 0 when collinear. A floating-point
/// filter with a proven error bound decides nearly always; exact integer arithmetic where it
/// cannot.
int orientation(const Point& a, const Point& b, const Point& c);

/// +1 when d lies strictly inside the circle through the counter-clockwise triangle (a, b, c),
/// -1 strictly outside, 0 on it; exact as orientation().
int in_circle(const Point& a, const Point& b, const Point& c, const Point& d);

/// +1 when d lies below the plane through (a, b, c), those seen counter-clockwise from above
/// (the side the normal (b - a) x (c - a) points to), -1 above it, 0 when the four are
/// coplanar; exact as orientation().
int orientation(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

}  // namespace ridt
