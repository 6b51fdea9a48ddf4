// The power test of weighted points, exactly and with a symbolic perturbation: the predicate
// the regular (weighted Delaunay) triangulation is decided by (regular/regular.cpp), and its
// power centres (the power diagram's vertices).
//
// A weighted point (p, w) lifts to (p.x, p.y, |p|^2 - w); the regular triangulation is the
// lower hull of the lifted points seen from below. Point d is in conflict with the
// counter-clockwise triangle (a, b, c) where its lift lies below the plane of theirs: where
//   det [a - d, |a - d|^2 - (w_a - w_d); b - d, ...; c - d, ...] > 0,
// the in-circle determinant with each lift lowered by the weight's difference (with equal
// weights it is incircle). Evaluated in double precision with a bound on its rounding error,
// else exactly in integers (predicates/exact.cpp). Compile with -ffp-contract=off, as the others.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "predicates/predicates.hpp"
#include "ridt/ridt.hpp"

namespace ridt::detail {

/// A point and its weight.
struct Weighted {
  Point p;
  double w = 0;
  friend bool operator==(const Weighted& a, const Weighted& b) { return a.p == b.p && a.w == b.w; }
};

/// The perturbation's key: x, then y, then the weight.
inline bool weighted_less(const Weighted& a, const Weighted& b) {
  return a.p.x < b.p.x || (a.p.x == b.p.x && (a.p.y < b.p.y || (a.p.y == b.p.y && a.w < b.w)));
}

int power_exact(const Weighted& a, const Weighted& b, const Weighted& c, const Weighted& d);

/// The sign of the power determinant where double precision settles it, else 0. The bound: each
/// lift |a - d|^2 - (w_a - w_d) is within 4 kEps of the sum of its terms' magnitudes, each 2 x 2
/// minor within 3 kEps of its products' magnitudes, the three products and their sum within 3
/// more: (11 + 128 kEps) kEps times the permanent, with room to spare; where the permanent is so
/// small that a product may have underflowed, or is not finite, no answer.
[[gnu::always_inline]] inline int power_filter(const Weighted& a, const Weighted& b, const Weighted& c,
                                               const Weighted& d) {
  const double adx = a.p.x - d.p.x, ady = a.p.y - d.p.y, bdx = b.p.x - d.p.x, bdy = b.p.y - d.p.y;
  const double cdx = c.p.x - d.p.x, cdy = c.p.y - d.p.y;
  const double aw = a.w - d.w, bw = b.w - d.w, cw = c.w - d.w;
  const double asq = adx * adx + ady * ady, bsq = bdx * bdx + bdy * bdy, csq = cdx * cdx + cdy * cdy;
  const double alift = asq - aw, blift = bsq - bw, clift = csq - cw;
  const double bc = bdx * cdy - cdx * bdy, ca = cdx * ady - adx * cdy, ab = adx * bdy - bdx * ady;
  const double det = alift * bc + blift * ca + clift * ab;
  // First a cheap bound from sums the determinant needs anyway (as incircle_filter's): with A,
  // B, C the lifts' magnitudes asq + |aw|, ..., |bdx cdy| + |cdx bdy| <= sqrt(bsq csq) <=
  // (B + C) / 2 (Cauchy-Schwarz), so the permanent below is at most A B + B C + C A <= S^2 / 3,
  // S = A + B + C; 0.34 over 1/3 covers the twenty roundings of S and the products. (Trusted
  // between 2^-800, far above what an underflow loses, and 2^960, where no product overflows.)
  const double s = (asq + bsq + csq) + (std::fabs(aw) + std::fabs(bw) + std::fabs(cw));
  const double rough = (11.0 + 128.0 * kEps) * kEps * (0.34 * s * s);
  if (rough >= 0x1p-800 && rough <= 0x1p960) {
    if (det > rough) return 1;
    if (det < -rough) return -1;
  }
  const double permanent = (std::fabs(bdx * cdy) + std::fabs(cdx * bdy)) * (asq + std::fabs(aw)) +
      (std::fabs(cdx * ady) + std::fabs(adx * cdy)) * (bsq + std::fabs(bw)) +
      (std::fabs(adx * bdy) + std::fabs(bdx * ady)) * (csq + std::fabs(cw));
  const double bound = (11.0 + 128.0 * kEps) * kEps * permanent;
  if (!(permanent >= 0x1p-800 && permanent <= 0x1p1000)) return 0;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return 0;
}

/// +1 where d's lift lies below the plane of the lifts of the counter-clockwise triangle
/// (a, b, c) (d in conflict with it: its power circle reaches past their orthogonal circle),
/// -1 above, 0 on it. Exact for finite input.
[[gnu::always_inline]] inline int power(const Weighted& a, const Weighted& b, const Weighted& c, const Weighted& d) {
  const int s = power_filter(a, b, c, d);
  return s != 0 ? s : power_exact(a, b, c, d);
}

/// The power test under the perturbation, where power() is 0: each lift raised by an
/// infinitesimal that grows with the point's place in weighted_less's order, so the sign is the
/// cofactor of the greatest point whose cofactor is not 0, as incircle_tie for equal weights
/// (the same order and the same signs: with equal weights the regular triangulation is the
/// Delaunay kernel's, tie for tie). The four must differ; never 0 where (a, b, c) is a proper
/// triangle.
int power_tie(const Weighted& a, const Weighted& b, const Weighted& c, const Weighted& d);

[[gnu::always_inline]] inline int power_sos(const Weighted& a, const Weighted& b, const Weighted& c,
                                            const Weighted& d) {
  const int s = power(a, b, c, d);
  return s != 0 ? s : power_tie(a, b, c, d);
}

Point power_centre_exact(const Weighted& a, const Weighted& b, const Weighted& c);

/// The power centre of a, b and c (not collinear): the point of equal power from the three, the
/// vertex of their cells in the power diagram. Each coordinate within 2^-44 of the centre's
/// distance from a and a unit in its last place of the exact one: in double precision with bounds
/// on the rounding (as circumcentre_bounded), else exactly and rounded. NaN where the points are
/// collinear, infinite where the centre overflows.
inline Point power_centre_bounded(const Weighted& a, const Weighted& b, const Weighted& c) {
  const double bx = b.p.x - a.p.x, by = b.p.y - a.p.y, cx = c.p.x - a.p.x, cy = c.p.y - a.p.y;
  const double bw = b.w - a.w, cw = c.w - a.w;
  const double b2 = bx * bx + by * by - bw, c2 = cx * cx + cy * cy - cw;
  const double bm = bx * bx + by * by + std::fabs(bw), cm = cx * cx + cy * cy + std::fabs(cw);
  const double l = bx * cy, r = by * cx, d = l - r;
  const double nx1 = cy * b2, nx2 = by * c2, ny1 = bx * c2, ny2 = cx * b2;
  const double nx = nx1 - nx2, ny = ny1 - ny2;
  // A lift is within 4 kEps of its magnitude (bm, cm), a product of it within 6, the numerator
  // within 8 of the products' magnitudes; as circumcentre_bounded otherwise.
  constexpr double kLost = 0x1p-1068;
  const double ed = 5 * kEps * (std::fabs(l) + std::fabs(r)) + kLost;
  const double ex = 8 * kEps * (std::fabs(cy) * bm + std::fabs(by) * cm) + kLost;
  const double ey = 8 * kEps * (std::fabs(bx) * cm + std::fabs(cx) * bm) + kLost;
  const double ox = nx / (2 * d), oy = ny / (2 * d), radius = std::max(std::fabs(ox), std::fabs(oy));
  const double moved = radius * ed / std::fabs(d) + std::max(ex, ey) / (2 * std::fabs(d));
  if (std::isfinite(moved) && std::isfinite(radius) && ed <= 0x1p-46 * std::fabs(d) && moved <= 0x1p-46 * radius)
    return {a.p.x + ox, a.p.y + oy};
  return power_centre_exact(a, b, c);
}

}  // namespace ridt::detail
