// The exact orientation of four points in space, and its symbolic perturbation: the predicate
// the triangulation on the sphere (sphere/) is decided by.
//
// As the planar predicates (predicates/predicates.hpp), it evaluates its determinant in
// double precision with a bound on the rounding error (Shewchuk's o3derrboundA, with an
// absolute term for underflow) and goes to exact integers (predicates/exact.cpp) where the
// bound cannot vouch for the sign. Compile with -ffp-contract=off, as the others.
#pragma once

#include <algorithm>
#include <cmath>

#include "ridt/ridt.hpp"

namespace ridt::detail {

// Degree 3 in the differences: (7 kEps + 56 kEps^2) times the permanent.
inline constexpr double kOrient3dBound = (7.0 + 56.0 * 0x1p-53) * 0x1p-53;

int orient3d_exact(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

/// The sign of det[a - d; b - d; c - d] where double precision settles it, else 0 (and for a
/// NaN or an overflow).
[[gnu::always_inline]] inline int orient3d_filter(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
  const double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
  const double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
  const double bc = bdx * cdy - bdy * cdx, ca = cdx * ady - cdy * adx, ab = adx * bdy - ady * bdx;
  const double det = adz * bc + bdz * ca + cdz * ab;
  // First a cheap bound: with sa, sb, sc the rows' sums of absolute values, the permanent below
  // is at most 3 sa sb sc and the largest difference at most sa + sb + sc; 1.01 covers the
  // roundings of these few operations.
  const double sa = std::fabs(adx) + std::fabs(ady) + std::fabs(adz),
               sb = std::fabs(bdx) + std::fabs(bdy) + std::fabs(bdz),
               sc = std::fabs(cdx) + std::fabs(cdy) + std::fabs(cdz);
  const double rough = 1.01 * (3 * kOrient3dBound * (sa * sb * sc) + 0x1p-1070 * (sa + sb + sc + 1));
  if (det > rough) return 1;
  if (det < -rough) return -1;
  const double permanent = (std::fabs(bdx * cdy) + std::fabs(bdy * cdx)) * std::fabs(adz) +
      (std::fabs(cdx * ady) + std::fabs(cdy * adx)) * std::fabs(bdz) +
      (std::fabs(adx * bdy) + std::fabs(ady * bdx)) * std::fabs(cdz);
  // Underflow: six degree-2 products, each off by 2^-1075 at most, times a difference of at
  // most m, and three degree-3 products: below 2^-1072 (m + 1).
  // (a tree of maxima, not a chain: the sign waits on this bound, and a walk on the sign)
  const double m =
      std::max(std::max(std::max(std::fabs(adx), std::fabs(ady)), std::max(std::fabs(adz), std::fabs(bdx))),
               std::max(std::max(std::fabs(bdy), std::fabs(bdz)),
                        std::max(std::fabs(cdx), std::max(std::fabs(cdy), std::fabs(cdz)))));
  const double bound = kOrient3dBound * permanent + 0x1p-1070 * (m + 1);
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return 0;
}

/// +1 when d lies below the plane of (a, b, c), seen counter-clockwise from above, -1 above,
/// 0 on it. Exact for finite input.
[[gnu::always_inline]] inline int orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const int s = orient3d_filter(a, b, c, d);
  return s != 0 ? s : orient3d_exact(a, b, c, d);
}

double orient3d_value_exact(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

/// det[a - d; b - d; c - d] itself, within a relative 2^-50 of the exact value: in double
/// precision where the filter's bound allows, else exactly and rounded.
inline double orient3d_value(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
  const double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
  const double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
  const double det = adz * (bdx * cdy - bdy * cdx) + bdz * (cdx * ady - cdy * adx) + cdz * (adx * bdy - ady * bdx);
  const double permanent = (std::fabs(bdx * cdy) + std::fabs(bdy * cdx)) * std::fabs(adz) +
      (std::fabs(cdx * ady) + std::fabs(cdy * adx)) * std::fabs(bdz) +
      (std::fabs(adx * bdy) + std::fabs(ady * bdx)) * std::fabs(cdz);
  const double m = std::max({std::fabs(adx), std::fabs(ady), std::fabs(adz), std::fabs(bdx), std::fabs(bdy),
                             std::fabs(bdz), std::fabs(cdx), std::fabs(cdy), std::fabs(cdz)});
  const double bound = kOrient3dBound * permanent + 0x1p-1070 * (m + 1);
  if (bound <= 0x1p-50 * std::fabs(det)) return det;
  return orient3d_value_exact(a, b, c, d);
}

/// The sign orient3d takes where it is 0 under Simulation of Simplicity (Edelsbrunner and
/// Mücke): coordinate j of the point ranked r among the four (by `rank`, distinct) moved by
/// eps^(2^(3r + j)); never 0. The points must be distinct.
int orient3d_tie(const Point3* const p[4], const std::uint32_t rank[4]);

/// orient3d with the perturbation: never 0 for four distinct points ranked apart.
[[gnu::always_inline]] inline int orient3d_sos(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                                               std::uint32_t ra, std::uint32_t rb, std::uint32_t rc, std::uint32_t rd) {
  if (const int s = orient3d(a, b, c, d); s != 0) return s;
  const Point3* p[4] = {&a, &b, &c, &d};
  const std::uint32_t rank[4] = {ra, rb, rc, rd};
  return orient3d_tie(p, rank);
}

}  // namespace ridt::detail
