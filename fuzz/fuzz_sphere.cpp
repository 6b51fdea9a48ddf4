// Fuzz target: small point sets on and near a sphere, full of cocircular points, copies and
// points a rounding inside, triangulated on the sphere (ridt/sphere.hpp).
//
// The first byte picks a transformation (scaling towards underflow or overflow, a far centre,
// a small rotation); every other byte is a point: one of the 30 integer points of the sphere of
// radius 5 (bits 0-4), as it is, a rounding below it, normalized to the unit sphere and scaled
// back, or halfway to the centre (bits 5-6). Every result must pass the exact validator and be
// the same, by coordinates, for the points in reverse order; where all lie on the sphere, the
// cells' areas must make the sphere's; a refusal must be of points that are coplanar or fewer
// than four distinct, or "too nearly coplanar" of points within a relative 2^-40 of flat.
// Anything else aborts: a finding.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "ridt/predicates.hpp"
#include "ridt/sphere.hpp"

namespace {

using namespace ridt;

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_sphere: %s\n", what.c_str());
  std::abort();
}

std::vector<Point3> lattice() {
  std::vector<Point3> out;
  for (int x = -5; x <= 5; ++x)
    for (int y = -5; y <= 5; ++y)
      for (int z = -5; z <= 5; ++z)
        if (x * x + y * y + z * z == 25) out.push_back({double(x), double(y), double(z)});
  return out;  // 30 points
}

Point3 transform(int kind, Point3 p) {
  switch (kind) {
    case 1:
      return {p.x * 1e-300, p.y * 1e-300, p.z * 1e-300};
    case 2:
      return {p.x * 1e300, p.y * 1e300, p.z * 1e300};
    case 3:
      return {p.x + 1e9, p.y - 3e9, p.z + 7};
    case 4: {
      const double c = std::cos(1e-3), s = std::sin(1e-3);
      return {c * p.x - s * p.y, s * p.x + c * p.y, p.z};
    }
    default:
      return p;
  }
}

std::vector<Point3> points_of(const std::uint8_t* bytes, std::size_t size) {
  static const std::vector<Point3> on = lattice();
  std::vector<Point3> pts;
  for (std::size_t i = 1; i < size; ++i) {
    Point3 p = on[(bytes[i] & 31) % on.size()];
    switch ((bytes[i] >> 5) & 3) {
      case 1:
        p = {p.x * (1 - 0x1p-52), p.y * (1 - 0x1p-52), p.z * (1 - 0x1p-52)};
        break;
      case 2: {
        const double l = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
        p = {p.x / l * 5, p.y / l * 5, p.z / l * 5};
        break;
      }
      case 3:
        p = {p.x / 2, p.y / 2, p.z / 2};
        break;
      default:
        break;
    }
    pts.push_back(transform(bytes[0] % 5, p));
  }
  return pts;
}

// Whether no four of the points span a tetrahedron of volume above `ratio` times their
// diameter cubed (in long double): at 2^-40, so nearly flat that no double may lie strictly
// inside it.
bool nearly_flat(const std::vector<Point3>& pts, long double ratio = 0x1p-40L) {
  long double diameter = 0, volume = 0;
  for (const Point3& a : pts)
    for (const Point3& b : pts)
      diameter = std::max(diameter, std::hypot((long double)a.x - b.x, (long double)a.y - b.y, (long double)a.z - b.z));
  for (std::size_t a = 0; a < pts.size(); ++a)
    for (std::size_t b = a + 1; b < pts.size(); ++b)
      for (std::size_t c = b + 1; c < pts.size(); ++c)
        for (std::size_t d = c + 1; d < pts.size(); ++d) {
          auto at = [&](std::size_t i, std::size_t k) {
            const Point3 &p = pts[i], &o = pts[d];
            return (long double)(k == 0 ? p.x : k == 1 ? p.y : p.z) - (k == 0 ? o.x : k == 1 ? o.y : o.z);
          };
          const long double det = at(a, 0) * (at(b, 1) * at(c, 2) - at(b, 2) * at(c, 1)) -
              at(a, 1) * (at(b, 0) * at(c, 2) - at(b, 2) * at(c, 0)) +
              at(a, 2) * (at(b, 0) * at(c, 1) - at(b, 1) * at(c, 0));
          volume = std::max(volume, std::fabs(det));
        }
  return volume <= ratio * diameter * diameter * diameter;
}

// Whether the points are fewer than four distinct or all on one plane (exactly).
bool flat(const std::vector<Point3>& pts) {
  for (std::size_t a = 0; a < pts.size(); ++a)
    for (std::size_t b = a + 1; b < pts.size(); ++b)
      for (std::size_t c = b + 1; c < pts.size(); ++c)
        for (std::size_t d = c + 1; d < pts.size(); ++d)
          if (orientation(pts[a], pts[b], pts[c], pts[d]) != 0) return false;
  return true;
}

std::set<std::array<double, 9>> faces(const std::vector<Point3>& pts, const SphericalTriangulation& t) {
  std::set<std::array<double, 9>> out;
  for (std::size_t f = 0; f < t.size(); ++f) {
    std::array<Point3, 3> c = {pts[t.triangles[3 * f]], pts[t.triangles[3 * f + 1]], pts[t.triangles[3 * f + 2]]};
    auto less = [](const Point3& a, const Point3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); };
    while (less(c[1], c[0]) || less(c[2], c[0])) std::rotate(c.begin(), c.begin() + 1, c.end());
    out.insert({c[0].x, c[0].y, c[0].z, c[1].x, c[1].y, c[1].z, c[2].x, c[2].y, c[2].z});
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  if (size == 0 || size > 65) return 0;
  const std::vector<Point3> pts = points_of(bytes, size);
  SphericalTriangulation t;
  try {
    t = triangulate_sphere(pts, 1 + size % 2);
  } catch (const InputError& e) {
    const bool thin = std::string(e.what()).find("too nearly coplanar") != std::string::npos;
    if (!(thin ? nearly_flat(pts) : flat(pts))) finding(std::string("refused points that are not flat: ") + e.what());
    return 0;
  }
  const CheckResult r = check_sphere(pts, t.triangles);
  if (!r.valid) finding(r.message);
  std::vector<Point3> reversed(pts.rbegin(), pts.rend());
  if (faces(pts, t) != faces(reversed, triangulate_sphere(reversed, 1))) finding("another order, other triangles");
  // Every point on the sphere of radius 5 about the origin (as it is, or normalized and scaled
  // back), as scipy's SphericalVoronoi takes them (no two within 1e-6 of the radius of each
  // other, not all within it of one plane): the cells' areas make the sphere's.
  bool on = bytes[0] % 5 == 0 || bytes[0] % 5 == 4;
  for (std::size_t i = 1; i < size; ++i) on = on && ((bytes[i] >> 5) & 1) == 0;
  for (std::size_t f = 0; f < t.size() && on; ++f)
    for (int i = 0; i < 3; ++i) {
      const Point3 &a = pts[t.triangles[3 * f + i]], &b = pts[t.triangles[3 * f + (i + 1) % 3]];
      on = on && std::hypot(a.x - b.x, a.y - b.y, a.z - b.z) >= 5e-6;
    }
  on = on && t.duplicates.empty() && !nearly_flat(pts, 1e-6L);
  if (on) {
    const SphericalVoronoi v = spherical_voronoi(t, pts, {}, 5, true, 2);
    double total = 0;
    for (const double a : v.areas) total += a;
    if (!(std::fabs(total - 100 * 3.14159265358979323846) < 1e-9)) finding("the cells' areas do not make the sphere");
  }
  return 0;
}
