// The regular triangulation against CGAL's Regular_triangulation_2 (exact predicates): on
// weighted points in general position the regular triangulation and its hidden points are
// unique, and both must be identical.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_2.h>
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <set>
#include <vector>

#include "ridt/regular.hpp"

namespace ridt::test {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Rt = CGAL::Regular_triangulation_2<K>;
using Face = std::array<double, 6>;

Face face(std::array<Point, 3> c) {
  auto less = [](const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
  while (less(c[1], c[0]) || less(c[2], c[0])) std::rotate(c.begin(), c.begin() + 1, c.end());
  return {c[0].x, c[0].y, c[1].x, c[1].y, c[2].x, c[2].y};
}

struct Result {
  std::set<Face> faces;
  std::set<std::pair<double, double>> hidden;
};

Result cgal(const std::vector<Point>& pts, const std::vector<double>& w) {
  std::vector<Rt::Weighted_point> in;
  for (std::size_t i = 0; i < pts.size(); ++i) in.emplace_back(K::Point_2(pts[i].x, pts[i].y), w[i]);
  Rt rt(in.begin(), in.end());
  EXPECT_TRUE(rt.is_valid());
  Result out;
  for (auto f = rt.finite_faces_begin(); f != rt.finite_faces_end(); ++f) {
    std::array<Point, 3> c;
    for (int i = 0; i < 3; ++i) c[i] = {f->vertex(i)->point().x(), f->vertex(i)->point().y()};
    out.faces.insert(face(c));
  }
  for (auto v = rt.hidden_vertices_begin(); v != rt.hidden_vertices_end(); ++v)
    out.hidden.insert({v->point().x(), v->point().y()});
  return out;
}

Result ours(const std::vector<Point>& pts, const std::vector<double>& w) {
  const RegularTriangulation t = triangulate_regular(pts, w);
  const CheckResult r = check_regular(pts, w, t.triangles);
  EXPECT_TRUE(r.valid) << r.message;
  Result out;
  for (std::size_t f = 0; f < t.size(); ++f)
    out.faces.insert(face({pts[t.triangles[3 * f]], pts[t.triangles[3 * f + 1]], pts[t.triangles[3 * f + 2]]}));
  for (const VertexId h : t.hidden) out.hidden.insert({pts[h].x, pts[h].y});
  return out;
}

TEST(RegularAgainstCgal, SameTrianglesAndHiddenPoints) {
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> cluster(0, 0.01);
  for (const std::size_t n : {200u, 50000u}) {
    for (int kind = 0; kind < 3; ++kind) {
      std::vector<Point> pts;
      std::vector<double> w;
      for (std::size_t i = 0; i < n; ++i) {
        if (kind == 2 && i % 2 == 0) {  // clustered about a few centres
          const double cx = 0.2 + 0.6 * double(i % 5) / 4;
          pts.push_back({cx + cluster(random), 0.5 + cluster(random)});
        } else {
          pts.push_back({u(random), u(random)});
        }
        // Weights of the order of the squared spacing (few hidden), or far larger (many).
        w.push_back(u(random) * (kind == 1 ? 50.0 : 1.0) / double(n));
      }
      const Result a = cgal(pts, w), b = ours(pts, w);
      EXPECT_EQ(a.faces, b.faces) << "n " << n << " kind " << kind;
      EXPECT_EQ(a.hidden, b.hidden) << "n " << n << " kind " << kind;
      if (kind == 1) EXPECT_GT(b.hidden.size(), n / 20);
    }
  }
}

}  // namespace
}  // namespace ridt::test
