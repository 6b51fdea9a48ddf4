// Exact geometric predicates: orient2d and incircle.
//
// Each predicate first evaluates its determinant in double precision together with a bound on
// the rounding error (the forward error analysis of Shewchuk, "Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates", 1997, extended here with an
// absolute term for underflow). When the value is farther from zero than the bound the sign is
// certain; otherwise the determinant is evaluated exactly with integers (predicates/exact.cpp).
//
// These functions must be compiled with -ffp-contract=off and without -ffast-math: a fused
// multiply-add or a reassociated sum changes the rounding that the error bounds describe.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <span>

#include "ridt/ridt.hpp"

namespace ridt::detail {

// Unit roundoff of double: every +, -, * is exact up to a factor (1 + d), |d| <= kEps.
inline constexpr double kEps = 0x1p-53;
// orient2d: the computed det = l - r with l, r products of rounded differences. Each difference
// and each product adds a relative error kEps, the subtraction one more; collecting terms gives
// |det - exact| <= (3 kEps + 16 kEps^2) (|l| + |r|) (Shewchuk, section 4.3, ccwerrboundA).
inline constexpr double kOrientBound = (3.0 + 16.0 * kEps) * kEps;
// incircle: degree-4 polynomial in the differences; the same analysis gives
// (10 kEps + 96 kEps^2) times the permanent (Shewchuk, iccerrboundA).
inline constexpr double kIncircleBound = (10.0 + 96.0 * kEps) * kEps;
// A product that underflows loses up to half the smallest subnormal, 2^-1075, absolutely;
// sums of doubles never do. orient2d has two products and one subtraction: 2^-1073 covers them.
inline constexpr double kOrientUnderflow = 0x1p-1073;

int orient2d_exact(const Point& a, const Point& b, const Point& c);
/// orient2d when the filter cannot tell: rescaled when the coordinates are huge or tiny, else
/// exact (predicates/exact.cpp).
int orient2d_hard(const Point& a, const Point& b, const Point& c);

/// True when x is an integer of magnitude below 2^52: differences of such numbers are exact.
inline bool small_integer(double x) {
  return std::fabs(x) < 0x1p52 && static_cast<double>(static_cast<std::int64_t>(x)) == x;
}

/// When the filter cannot decide, integer points with small differences (grids) still have
/// an exact floating-point determinant: every difference, product and sum is an integer below
/// 2^53. `limit` bounds the differences for that: 2^25 for orient2d (|det| <= 2 * 2^50),
/// 2^12 for incircle (|det| <= 12 * 2^48).
inline bool exact_in_double(std::initializer_list<double> coords, double m, double limit) {
  if (!(m <= limit)) return false;
  for (double x : coords)
    if (!small_integer(x)) return false;
  return true;
}
int incircle_exact(const Point& a, const Point& b, const Point& c, const Point& d);

/// The sign of the orientation of (a, b, c) where double precision settles it, else 0; always
/// 0 when a coordinate is NaN (or the products overflow).
inline int orient2d_filter(const Point& a, const Point& b, const Point& c) {
  const double acx = a.x - c.x, bcx = b.x - c.x;
  const double acy = a.y - c.y, bcy = b.y - c.y;
  const double l = acx * bcy;
  const double r = acy * bcx;
  const double det = l - r;
  const double bound = kOrientBound * (std::fabs(l) + std::fabs(r)) + kOrientUnderflow;
  if (std::fabs(det) > bound) return det > 0 ? 1 : -1;
  return 0;
}

/// Sign of the orientation of (a, b, c): +1 if counter-clockwise, -1 if clockwise, 0 if
/// collinear. Exact for every finite input.
inline int orient2d(const Point& a, const Point& b, const Point& c) {
  if (const int s = orient2d_filter(a, b, c); s != 0) return s;
  // Unsure, or a NaN from an overflow: small integers compute exactly, the rest goes on.
  const double acx = a.x - c.x, bcx = b.x - c.x;
  const double acy = a.y - c.y, bcy = b.y - c.y;
  const double m = std::max({std::fabs(acx), std::fabs(bcx), std::fabs(acy), std::fabs(bcy)});
  if (exact_in_double({a.x, a.y, b.x, b.y, c.x, c.y}, m, 0x1p25)) {
    const double det = acx * bcy - acy * bcx;
    return (det > 0) - (det < 0);
  }
  return orient2d_hard(a, b, c);
}

/// The sign of the incircle determinant where double precision settles it (nearly always):
/// +1 inside, -1 outside, 0 when it cannot tell; always 0 when a coordinate is NaN (every
/// comparison with the determinant fails).
inline int incircle_filter(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double adx = a.x - d.x, ady = a.y - d.y;
  const double bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  const double bc = bdx * cdy - cdx * bdy;
  const double ca = cdx * ady - adx * cdy;
  const double ab = adx * bdy - bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det = alift * bc + blift * ca + clift * ab;
  // Underflow: a degree-2 product that underflows (absolute error <= 2^-1075) is later
  // multiplied by a degree-2 factor of size <= 2 m^2 (m the largest difference); there are at
  // most 12 such products and 3 final ones, so 2^-1075 (32 m^2 + 4) = 2^-1070 (m^2 + 1/8)
  // bounds the total. An overflow makes a lift infinite and sends us to the exact path.
  //
  // First a cheap bound, from the lifts the determinant needs anyway: five more operations,
  // where the largest difference m and the permanent take some thirty (a whole 10^6-point
  // run of the walking kernel took two thirds of its time with it). With A, B, C the exact lifts of the rounded differences,
  // |bdx cdy| + |cdx bdy| <= sqrt(B C) <= (B + C) / 2 (Cauchy-Schwarz), so the permanent
  // below is at most A B + B C + C A <= S^2 / 3, S = A + B + C; and m^2 <= S. The computed S
  // and the products round some twenty times, each by a factor 1 + 2^-53 at most: 0.34 over
  // 1/3 leaves room for all of them, and 2^-1069 s + 2^-1072 covers the underflow term even
  // when its own products underflow (2^-1075 each).
  const double s = alift + blift + clift;
  const double rough = s * (kIncircleBound * 0.34 * s + 0x1p-1069) + 0x1p-1072;
  if (std::fabs(det) > rough) return det > 0 ? 1 : -1;
  // The bound below is positive, so a determinant of 0 (a grid's cocircular squares, at every
  // other test) cannot pass it: straight to the exact path.
  if (det == 0) return 0;
  // std::max, not std::fmax: no NaN can occur (finite inputs), and it inlines to one instruction.
  const double m =
      std::max(std::max(std::max(std::fabs(adx), std::fabs(ady)), std::max(std::fabs(bdx), std::fabs(bdy))),
               std::max(std::fabs(cdx), std::fabs(cdy)));
  const double tiny = 0x1p-1070 * (m * m + 0.125);
  const double permanent = (std::fabs(bdx * cdy) + std::fabs(cdx * bdy)) * alift +
      (std::fabs(cdx * ady) + std::fabs(adx * cdy)) * blift + (std::fabs(adx * bdy) + std::fabs(bdx * ady)) * clift;
  const double bound = kIncircleBound * permanent + tiny;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return 0;
}

/// incircle when the filter cannot tell: rescaled when the coordinates are huge or tiny, else
/// exact (predicates/exact.cpp).
int incircle_hard(const Point& a, const Point& b, const Point& c, const Point& d);

/// Sign of the incircle determinant: +1 if d lies strictly inside the circle through the
/// counter-clockwise triangle (a, b, c), -1 if strictly outside, 0 if on it. Exact.
inline int incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
  const int s = incircle_filter(a, b, c, d);
  return s != 0 ? s : incircle_hard(a, b, c, d);
}

/// What one pass over the points finds: their bounding box, the smallest and the largest
/// nonzero magnitude of a coordinate, and whether every coordinate is finite (the box and the
/// magnitudes mean nothing where one is not). Parts of the points scanned apart merge.
struct Extent {
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
  double smallest = HUGE_VAL, largest = 0;
  bool finite = true;

  void add(const Point& p) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    const double ax = std::fabs(p.x), ay = std::fabs(p.y);
    // No branch: NaN fails every comparison, so it and the infinities clear `finite`.
    finite &= (ax <= 0x1.fffffffffffffp1023) & (ay <= 0x1.fffffffffffffp1023);
    largest = std::max(largest, std::max(ax, ay));
    smallest = std::min(smallest, std::min(ax != 0 ? ax : HUGE_VAL, ay != 0 ? ay : HUGE_VAL));
  }
  void add(const Extent& e) {
    x0 = std::min(x0, e.x0), x1 = std::max(x1, e.x1), y0 = std::min(y0, e.y0), y1 = std::max(y1, e.y1);
    smallest = std::min(smallest, e.smallest), largest = std::max(largest, e.largest);
    finite = finite && e.finite;
  }
};

inline Extent extent_of(std::span<const Point> points) {
  Extent e;
  for (const Point& p : points) e.add(p);
  return e;
}

/// Huge or tiny coordinates make the products in the filters overflow or underflow, and
/// every predicate then takes the slow path. Scaling every point by one power of two 2^k
/// changes the sign of no predicate, and is exact while every coordinate stays normal. Returns
/// the k that brings half the larger side of the points' bounding box into [1/2, 1) when it
/// lies outside [low, high] and that scaling is exact, else 0 (leave the points as they are;
/// no points, or a coordinate that is not finite: 0). `e` is the points' extent.
inline int exact_scale_exponent(const Extent& e, double low = 0x1p-200, double high = 0x1p200) {
  if (!e.finite) return 0;
  const double half = std::max(e.x1 / 2 - e.x0 / 2, e.y1 / 2 - e.y0 / 2);  // halves cannot overflow
  if (!(half > 0) || (half >= low && half <= high)) return 0;
  int exponent = 0;
  std::frexp(half, &exponent);  // half in [2^(exponent-1), 2^exponent): scaled, in [1/2, 1)
  const int k = -exponent;
  const bool exact = std::ldexp(e.smallest, k) >= 0x1p-1022 && std::ldexp(e.largest, k) < 0x1p1020;
  return exact ? k : 0;
}
inline int exact_scale_exponent(std::span<const Point> points, double low = 0x1p-200, double high = 0x1p200) {
  return exact_scale_exponent(extent_of(points), low, high);
}

double doubled_area_exact(const Point& a, const Point& b, const Point& c);

/// Where segments a-b and u-w cross (at one point inside both), each coordinate the double
/// nearest the exact one (ties to even).
Point crossing_rounded(const Point& a, const Point& b, const Point& u, const Point& w);

/// Twice the signed area of (a, b, c) (the orientation determinant), within a relative 2^-50
/// of the exact value: in double precision where the filter's bound allows, else exactly and
/// rounded (infinite only where the area itself overflows).
inline double doubled_area(const Point& a, const Point& b, const Point& c) {
  const double l = (a.x - c.x) * (b.y - c.y), r = (a.y - c.y) * (b.x - c.x);
  const double det = l - r, bound = kOrientBound * (std::fabs(l) + std::fabs(r)) + kOrientUnderflow;
  if (bound <= 0x1p-50 * std::fabs(det)) return det;
  return doubled_area_exact(a, b, c);
}

void barycentric_exact(const Point& a, const Point& b, const Point& c, const Point& q, double weight[3]);

/// The barycentric coordinates of q in the counter-clockwise triangle (a, b, c), not
/// degenerate: weight[i] is the signed area of the triangle with q in place of corner i over
/// the whole triangle's. Each weight is within 2^-44 of its exact value (absolutely) and
/// within a few units in its last place where the filter decides: the four areas are computed
/// in double precision with the orientation filter's error bound, and exactly (predicates/exact.cpp)
/// where a bound is over 2^-45 of the whole area (a sliver, a query near a side of a long
/// triangle, coordinates that overflow or underflow) or where a part's sign is not certain (q
/// on or next to a side). So q at a corner gets exactly 1 there and 0 elsewhere, and q on a
/// side exactly 0 for the opposite corner.
/// The orientation determinant of (u, v, w) in double precision, and the filter's bound on its
/// error: its sign is certain where |value| > bound (as orient2d_filter decides).
struct BoundedArea {
  double value, bound;
};
inline BoundedArea bounded_area(const Point& u, const Point& v, const Point& w) {
  const double l = (u.x - w.x) * (v.y - w.y), r = (u.y - w.y) * (v.x - w.x);
  return {l - r, kOrientBound * (std::fabs(l) + std::fabs(r)) + kOrientUnderflow};
}

/// barycentric's quick path: the weights from the whole triangle's bounded area and the three
/// with q in place of a corner, (q, b, c), (a, q, c) and (a, b, q), where every bound is within
/// 2^-45 of the whole area and every sign is certain; false (weight untouched) where not.
inline bool barycentric_quick(const BoundedArea& whole, const BoundedArea part[3], double weight[3]) {
  const double room = 0x1p-45 * std::fabs(whole.value);
  auto sure = [room](const BoundedArea& x) { return x.bound <= room && std::fabs(x.value) > x.bound; };
  if (!(sure(whole) && sure(part[0]) && sure(part[1]) && sure(part[2]))) return false;
  for (int i = 0; i < 3; ++i) weight[i] = part[i].value / whole.value;
  return true;
}

inline void barycentric(const Point& a, const Point& b, const Point& c, const Point& q, double weight[3]) {
  const BoundedArea part[3] = {bounded_area(q, b, c), bounded_area(a, q, c), bounded_area(a, b, q)};
  if (!barycentric_quick(bounded_area(a, b, c), part, weight)) barycentric_exact(a, b, c, q, weight);
}

Point circumcentre_exact(const Point& a, const Point& b, const Point& c);

/// The circumcentre of a, b and c (not collinear), each coordinate within 2^-44 of the
/// circumradius of the exact one and within a unit in its last place beside that: computed
/// relative to a in double precision, with bounds on the rounding of the orientation
/// determinant and of the two numerators, and exactly (predicates/exact.cpp, the two roundings
/// of a quotient of exact integers) where a bound is over 2^-46 of what it bounds or a value
/// overflows (points far from the origin, slivers, huge or tiny coordinates). Infinite or NaN
/// only where the circumcentre itself overflows or the points are collinear.
inline Point circumcentre_bounded(const Point& a, const Point& b, const Point& c) {
  const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const double l = bx * cy, r = by * cx, d = l - r;
  const double nx1 = cy * b2, nx2 = by * c2, ny1 = bx * c2, ny2 = cx * b2;
  const double nx = nx1 - nx2, ny = ny1 - ny2;
  // Each difference is off by a relative kEps, each square sum by 4 kEps, each product of them
  // by 6 and each result by one more: the bounds, with room for the terms of second order, and
  // for the absolute 2^-1075 a step can lose where it underflows.
  constexpr double kLost = 0x1p-1068;
  const double ed = 5 * kEps * (std::fabs(l) + std::fabs(r)) + kLost;
  const double ex = 8 * kEps * (std::fabs(nx1) + std::fabs(nx2)) + kLost;
  const double ey = 8 * kEps * (std::fabs(ny1) + std::fabs(ny2)) + kLost;
  const double ox = nx / (2 * d), oy = ny / (2 * d), radius = std::max(std::fabs(ox), std::fabs(oy));
  // An error in d moves the offset by its relative size; one in a numerator by itself over 2 d.
  const double moved = radius * ed / std::fabs(d) + std::max(ex, ey) / (2 * std::fabs(d));
  if (std::isfinite(moved) && std::isfinite(radius) && ed <= 0x1p-46 * std::fabs(d) && moved <= 0x1p-46 * radius)
    return {a.x + ox, a.y + oy};
  return circumcentre_exact(a, b, c);
}

/// Lexicographic order (x, then y): the fixed key of the symbolic perturbation.
inline bool lex_less(const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

/// The incircle determinant in plain double arithmetic, the differences taken from d: exact
/// where every step is an exact integer (small integer coordinates), else only an estimate.
inline double incircle_determinant(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double adx = a.x - d.x, ady = a.y - d.y;
  const double bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  return (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
      (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
}

/// Whether every coordinate of the n points is an integer (of magnitude below 2^52) and their
/// bounding box is at most 2^12 wide and high, as a grid's often is. Then every difference of
/// coordinates, product and sum in orient2d_lattice and incircle_sos_lattice is an integer
/// below 2^53, computed exactly: no filter and no error bound is needed. Stops at the first
/// point that is not such, so other inputs pay one test.
bool on_small_lattice(const Point* points, std::uint32_t n);

/// orient2d for points on a small lattice (on_small_lattice): the determinant is exact.
inline int orient2d_lattice(const Point& a, const Point& b, const Point& c) {
  const double det = (a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x);
  return (det > 0) - (det < 0);
}

/// The perturbed incircle's sign when the exact determinant is 0 (a, b, c, d cocircular): the
/// rule described at incircle_sos below.
int incircle_tie(const Point& a, const Point& b, const Point& c, const Point& d);

/// incircle with Simulation of Simplicity: never 0 when (a, b, c) is a proper
/// counter-clockwise triangle and d differs from a, b and c.
///
/// Each point p is lifted to z = x^2 + y^2 + eps_p, where the lexicographically larger point
/// gets the infinitely larger eps (Edelsbrunner and Muecke; Devillers and Teillaud for
/// Delaunay). The incircle value is the 4x4 determinant with rows (x, y, z, 1); perturbing z_p
/// adds eps_p times its cofactor, so when the exact value is 0 the sign is that of the
/// cofactor of the largest point whose cofactor is not 0. The cofactor of d, -orient(a, b, c),
/// is never 0, so the answer is always decided.
int incircle_sos_hard(const Point& a, const Point& b, const Point& c, const Point& d);
inline int incircle_sos(const Point& a, const Point& b, const Point& c, const Point& d) {
  const int s = incircle_filter(a, b, c, d);
  return s != 0 ? s : incircle_sos_hard(a, b, c, d);
}

/// incircle_sos for points on a small lattice (on_small_lattice): the determinant is exact, so
/// its sign answers, and the perturbation only where it is 0. A grid's cocircular squares make
/// that every other test; through the filter each cost a failed bound and an exactness check.
inline int incircle_sos_lattice(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double det = incircle_determinant(a, b, c, d);
  if (det != 0) return det > 0 ? 1 : -1;
  return incircle_tie(a, b, c, d);
}

}  // namespace ridt::detail
