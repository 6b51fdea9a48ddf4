// A tetrahedron of points far from flat, and a point strictly inside it: where the
// triangulation on the sphere starts (sphere.cpp), and the inner point its validator measures
// from (check/check_sphere.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "predicates/orient3d.hpp"
#include "predicates/predicates.hpp"
#include "ridt/ridt.hpp"
#include "tds/ids.hpp"

namespace ridt::detail {

struct Tetrahedron {
  /// Point ids, oriented: d lies below (a, b, c), seen counter-clockwise from above. Empty
  /// (kNoVertex) where the points are all collinear or all coplanar (`flat` says which).
  std::array<VertexId, 4> v{kNoVertex, kNoVertex, kNoVertex, kNoVertex};
  const char* flat = nullptr;
  /// The centroid, rounded; `inside` where it lies strictly inside, exactly (where the
  /// tetrahedron is so thin that no rounding of it does, perhaps no double does).
  Point3 inner;
  bool inside = false;
};

/// Among points[ids[0 .. ids.size())] (distinct, at least four): the first, the farthest from
/// it, the farthest from their line, the farthest from their plane, each scored in double
/// precision on the points scaled by one power of two where their largest coordinate lies
/// beyond 2^-400 to 2^400 (so that no square overflows or underflows; within, they need none)
/// and confirmed exactly, or found by an exact search where the scores are all 0.
inline Tetrahedron fat_tetrahedron(std::span<const Point3> points, std::span<const VertexId> ids) {
  auto cross = [](const Point3& a, const Point3& b) {
    return Point3{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
  };
  auto minus = [](const Point3& a, const Point3& b) { return Point3{a.x - b.x, a.y - b.y, a.z - b.z}; };
  auto dot = [](const Point3& a, const Point3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; };
  auto collinear = [](const Point3& a, const Point3& b, const Point3& c) {
    return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == 0 && orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == 0 &&
        orient2d({a.x, a.z}, {b.x, b.z}, {c.x, c.z}) == 0;
  };
  double largest = 0;
  for (const VertexId v : ids)
    largest = std::max({largest, std::fabs(points[v].x), std::fabs(points[v].y), std::fabs(points[v].z)});
  const int e = largest > 0 && !(largest >= 0x1p-400 && largest <= 0x1p400) ? std::ilogb(largest) : 0;
  auto at = [&](VertexId v) {
    return e == 0 ? points[v]
                  : Point3{std::ldexp(points[v].x, -e), std::ldexp(points[v].y, -e), std::ldexp(points[v].z, -e)};
  };
  auto best = [&](auto&& score) {
    VertexId arg = kNoVertex;
    double top = -1;
    for (const VertexId v : ids)
      if (const double s = score(v); s > top) top = s, arg = v;
    return arg;
  };
  auto first = [&](auto&& pass) {
    for (const VertexId v : ids)
      if (pass(v)) return v;
    return kNoVertex;
  };
  Tetrahedron t;
  const VertexId a = ids[0];
  VertexId b = best([&](VertexId v) { return v == a ? -1.0 : dot(minus(at(v), at(a)), minus(at(v), at(a))); });
  VertexId c = best([&](VertexId v) {
    return dot(cross(minus(at(b), at(a)), minus(at(v), at(a))), cross(minus(at(b), at(a)), minus(at(v), at(a))));
  });
  if (collinear(points[a], points[b], points[c]))
    c = first([&](VertexId v) { return !collinear(points[a], points[b], points[v]); });
  if (c == kNoVertex) return t.flat = "collinear", t;
  const Point3 normal = cross(minus(at(b), at(a)), minus(at(c), at(a)));
  VertexId d = best([&](VertexId v) { return std::fabs(dot(normal, minus(at(v), at(a)))); });
  if (orient3d(points[a], points[b], points[c], points[d]) == 0)
    d = first([&](VertexId v) { return orient3d(points[a], points[b], points[c], points[v]) != 0; });
  if (d == kNoVertex) return t.flat = "coplanar", t;
  if (orient3d(points[a], points[b], points[c], points[d]) < 0) std::swap(b, c);
  t.v = {a, b, c, d};
  const Point3 &pa = points[a], &pb = points[b], &pc = points[c], &pd = points[d];
  // The centroid rounded three ways (the pairs summed first): in a tetrahedron a few units in
  // the last place thin, one may fall inside where another does not.
  const Point3* pairs[3][4] = {{&pa, &pb, &pc, &pd}, {&pa, &pc, &pb, &pd}, {&pa, &pd, &pb, &pc}};
  for (const auto& q : pairs) {
    t.inner = {(q[0]->x + q[1]->x) / 4 + (q[2]->x + q[3]->x) / 4, (q[0]->y + q[1]->y) / 4 + (q[2]->y + q[3]->y) / 4,
               (q[0]->z + q[1]->z) / 4 + (q[2]->z + q[3]->z) / 4};
    t.inside = orient3d(pa, pb, pc, t.inner) > 0 && orient3d(pa, pd, pb, t.inner) > 0 &&
        orient3d(pa, pc, pd, t.inner) > 0 && orient3d(pb, pd, pc, t.inner) > 0;
    if (t.inside) break;
  }
  return t;
}

}  // namespace ridt::detail
