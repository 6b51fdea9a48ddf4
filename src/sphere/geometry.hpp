// What the sphere's queries share (sphere/voronoi.cpp, sphere/interpolate.cpp,
// sphere/natural.cpp): vectors, a triangle's unit normal within a bound, the solid angle of a
// spherical triangle, and the walk that finds the triangle whose cone from the centre holds a
// direction.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "predicates/orient3d.hpp"
#include "predicates/predicates.hpp"
#include "ridt/sphere.hpp"
#include "tds/ids.hpp"

namespace ridt::detail::sphere {

inline Point3 minus(const Point3& a, const Point3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Point3 cross(const Point3& a, const Point3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double dot(const Point3& a, const Point3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
// Coordinates whose squares and products neither overflow nor lose digits to underflow: a
// largest coordinate m in [2^-400, 2^400] (a difference of two such coordinates, if not 0, is
// at least m 2^-53, its products above 2^-906).
inline bool plain(double m) { return m >= 0x1p-400 && m <= 0x1p400; }
// a, where its largest coordinate m is not plain(), scaled by a power of two (exactly) to m in
// [1, 2).
inline Point3 scaled(const Point3& a) {
  const double m = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)});
  if (plain(m) || !(m > 0) || !std::isfinite(m)) return a;
  const int e = std::ilogb(m);
  return {std::ldexp(a.x, -e), std::ldexp(a.y, -e), std::ldexp(a.z, -e)};
}
inline Point3 unit(const Point3& given) {
  const Point3 a = scaled(given);
  const double l = std::sqrt(dot(a, a));
  return {a.x / l, a.y / l, a.z / l};
}

// The signed solid angle of the spherical triangle of unit vectors a, b, c (Van Oosterom and
// Strackee): its triple product taken of b - a and c - a, which keeps its digits where the
// three are close (a small cell's triangles).
// The angle is twice the argument of below + i triple (solid_angle_parts).
struct SolidAngleParts {
  double triple, below;
};
inline SolidAngleParts solid_angle_parts(const Point3& a, const Point3& b, const Point3& c) {
  return {dot(a, cross(minus(b, a), minus(c, a))), 1 + dot(a, b) + dot(b, c) + dot(c, a)};
}
inline double solid_angle(const Point3& a, const Point3& b, const Point3& c) {
  const SolidAngleParts s = solid_angle_parts(a, b, c);
  return 2 * std::atan2(s.triple, s.below);
}

// Whether d, a - b rounded, is a - b exactly (Knuth's two-sum: the error of the difference,
// itself exact, is 0).
inline bool exact_difference(double a, double b, double d) {
  const double back = d - a;
  return (a - (d - back)) + (-b - back) == 0;
}
// ab - cd within 2^-52 of itself (2 units of rounding): cd's rounding error, exact by a fused
// multiply-add, put back into ab - cd rounded once.
inline double product_difference(double a, double b, double c, double d) {
  const double cd = c * d;
  return std::fma(a, b, -cd) + std::fma(-c, d, cd);
}

// The unit outward normal of triangle (a, b, c), counter-clockwise seen from outside: where its
// circle on the sphere is centred. Its components, (b - a) x (c - a), are the triangle's doubled
// areas in the planes yz, zx and xy, each within 2^-50 of the exact normal's largest component
// (the orientation filter's bounds; exactly, doubled_area_exact, where a bound is larger), so
// the direction carries an error below 2^-48 however thin the triangle (two corners an ulp
// apart leave a cross product of rounded sides nothing right). A component near 0 beside a
// large one, which a bound relative to itself would send to the exact path, needs nothing more.
// Corners beyond plain() are first scaled by one power of two, so that no area overflows.
inline Point3 unit_normal(const Point3& a, const Point3& b, const Point3& c) {
  const double m = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z), std::fabs(b.x), std::fabs(b.y),
                             std::fabs(b.z), std::fabs(c.x), std::fabs(c.y), std::fabs(c.z)});
  const int e = plain(m) || !(m > 0) ? 0 : std::ilogb(m);
  auto at = [&](const Point3& p) {
    return e == 0 ? p : Point3{std::ldexp(p.x, -e), std::ldexp(p.y, -e), std::ldexp(p.z, -e)};
  };
  const Point3 u = at(a), v = at(b), w = at(c);
  // Where the sides' differences are exact (as between close coordinates of one sign), each
  // component is a difference of two exact products, which Kahan's way with a fused
  // multiply-add gives within 2^-52 of itself (Jeannerod, Louvet and Muller, 2013), so long as
  // no product underflows: a component of 2^-900 or more leaves room for what an underflow
  // loses (below 2^-1070) in every other.
  const Point3 p = minus(u, w), q = minus(v, w);
  if (exact_difference(u.x, w.x, p.x) && exact_difference(u.y, w.y, p.y) && exact_difference(u.z, w.z, p.z) &&
      exact_difference(v.x, w.x, q.x) && exact_difference(v.y, w.y, q.y) && exact_difference(v.z, w.z, q.z)) {
    const Point3 n{product_difference(p.y, q.z, p.z, q.y), product_difference(p.z, q.x, p.x, q.z),
                   product_difference(p.x, q.y, p.y, q.x)};
    if (std::max({std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)}) >= 0x1p-900) return unit(n);
  }
  const Point yz[3] = {{u.y, u.z}, {v.y, v.z}, {w.y, w.z}}, zx[3] = {{u.z, u.x}, {v.z, v.x}, {w.z, w.x}},
              xy[3] = {{u.x, u.y}, {v.x, v.y}, {w.x, w.y}};
  const BoundedArea d[3] = {bounded_area(yz[0], yz[1], yz[2]), bounded_area(zx[0], zx[1], zx[2]),
                            bounded_area(xy[0], xy[1], xy[2])};
  const double largest = std::max({std::fabs(d[0].value), std::fabs(d[1].value), std::fabs(d[2].value)});
  // (Each bound below 2^-51 of the largest approximate component: the exact largest is then
  // within 2^-51 of it, so each error is below 2^-50 of the exact one.)
  if (std::max({d[0].bound, d[1].bound, d[2].bound}) <= 0x1p-51 * largest)
    return unit({d[0].value, d[1].value, d[2].value});
  return unit(
      {doubled_area(yz[0], yz[1], yz[2]), doubled_area(zx[0], zx[1], zx[2]), doubled_area(xy[0], xy[1], xy[2])});
}

/// The linear weights of direction q (from `centre`) in triangle (a, b, c): the barycentric
/// coordinates of its central projection onto the triangle's plane, the volumes
/// det[q, b, c] : det[a, q, c] : det[a, b, q] about the centre (each within a relative 2^-50 of
/// the exact one), summing to 1; false where their sum is 0 or not finite.
inline bool linear_weights(const Point3& a, const Point3& b, const Point3& c, const Point3& q, const Point3& centre,
                           double w[3]) {
  // det[x - o, y - o, z - o] is orient3d(x, y, z, o) up to its sign convention: the same for
  // all three, so the ratios stand.
  w[0] = orient3d_value(q, b, c, centre), w[1] = orient3d_value(a, q, c, centre),
  w[2] = orient3d_value(a, b, q, centre);
  const double sum = w[0] + w[1] + w[2];
  if (!(sum != 0) || !std::isfinite(sum)) return false;
  for (int i = 0; i < 3; ++i) w[i] /= sum;
  return true;
}

/// Finds, for a direction from the centre, the triangle whose cone from the centre holds it,
/// among the triangles that face away from the centre (all where the centre is inside the
/// hull): a walk from the last triangle found, or, where it cycles or leaves them, a scan.
class ConeWalk {
 public:
  ConeWalk(const SphericalTriangulation& t, std::span<const Point3> points, const Point3& centre)
      : t_(t), points_(points), centre_(centre), away_(t.size()) {
    for (std::size_t f = 0; f < t.size(); ++f) {
      const VertexId* c = &t.triangles[3 * f];
      away_[f] = orient3d(points[c[0]], points[c[1]], points[c[2]], centre) > 0;
    }
  }

  /// Whether triangle f faces away from the centre.
  bool away(std::size_t f) const { return away_[f] != 0; }

  /// The triangle whose cone holds q, from f (kept for the next query); false where none does
  /// (the points in one hemisphere, q beyond them).
  bool locate(const Point3& q, std::size_t& f) const {
    const std::size_t m = t_.size();
    bool moved = true;
    for (std::size_t steps = 0; moved && steps < 4 * m + 8; ++steps) {
      moved = false;
      for (int j = 0; j < 3 && !moved; ++j)
        if (side(t_.triangles[3 * f + next3(j)], t_.triangles[3 * f + prev3(j)], q) < 0 && away_[f])
          f = static_cast<std::size_t>(t_.neighbors[3 * f + j]), moved = true;
    }
    if (holds(f, q) && away_[f]) return true;
    for (std::size_t g = 0; g < m; ++g)  // a walk that cycled, or left the triangles facing away
      if (away_[g] && holds(g, q)) return f = g, true;
    return false;
  }

 private:
  // q's side of the plane through the centre, a and b: +1 on the side of the triangle left of a -> b.
  int side(VertexId a, VertexId b, const Point3& q) const { return -orient3d(centre_, points_[a], points_[b], q); }
  bool holds(std::size_t f, const Point3& q) const {
    const VertexId* c = &t_.triangles[3 * f];
    return side(c[0], c[1], q) >= 0 && side(c[1], c[2], q) >= 0 && side(c[2], c[0], q) >= 0;
  }

  const SphericalTriangulation& t_;
  std::span<const Point3> points_;
  Point3 centre_;
  std::vector<std::uint8_t> away_;
};

}  // namespace ridt::detail::sphere
