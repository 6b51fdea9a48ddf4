// The triangulation on the sphere against CGAL's convex_hull_3 (exact predicates): on points
// in general position the hull is unique, and the triangle sets must be identical.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "ridt/sphere.hpp"

namespace ridt::test {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Face = std::array<double, 9>;

Face face(std::array<Point3, 3> c) {
  auto less = [](const Point3& a, const Point3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); };
  while (less(c[1], c[0]) || less(c[2], c[0])) std::rotate(c.begin(), c.begin() + 1, c.end());
  return {c[0].x, c[0].y, c[0].z, c[1].x, c[1].y, c[1].z, c[2].x, c[2].y, c[2].z};
}

std::set<Face> cgal_hull(const std::vector<Point3>& pts) {
  std::vector<K::Point_3> in;
  for (const Point3& p : pts) in.emplace_back(p.x, p.y, p.z);
  CGAL::Surface_mesh<K::Point_3> mesh;
  CGAL::convex_hull_3(in.begin(), in.end(), mesh);
  std::set<Face> out;
  for (const auto f : mesh.faces()) {
    std::array<Point3, 3> c;
    int k = 0;
    for (const auto v : mesh.vertices_around_face(mesh.halfedge(f))) {
      const K::Point_3& p = mesh.point(v);
      c[k++] = {p.x(), p.y(), p.z()};
    }
    out.insert(face(c));
  }
  return out;
}

std::set<Face> ridt_hull(const std::vector<Point3>& pts) {
  const SphericalTriangulation t = triangulate_sphere(pts);
  EXPECT_TRUE(check_sphere(pts, t.triangles).valid);
  std::set<Face> out;
  for (std::size_t f = 0; f < t.size(); ++f)
    out.insert(face({pts[t.triangles[3 * f]], pts[t.triangles[3 * f + 1]], pts[t.triangles[3 * f + 2]]}));
  return out;
}

TEST(SphereAgainstCgal, SameHullOnPointsInGeneralPosition) {
  std::mt19937_64 random(42);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> inside(-0.57, 0.57);
  for (const std::size_t n : {100u, 20000u}) {
    std::vector<Point3> pts;
    for (std::size_t i = 0; i < n; ++i) {
      const double x = normal(random), y = normal(random), z = normal(random), l = std::hypot(x, y, z);
      pts.push_back({x / l + 7, y / l - 3, z / l});  // off the origin
      if (i % 4 == 0) pts.push_back({inside(random) + 7, inside(random) - 3, inside(random)});  // hidden
    }
    EXPECT_EQ(ridt_hull(pts), cgal_hull(pts)) << n << " points";
  }
}

}  // namespace
}  // namespace ridt::test
