// The periodic triangulation against CGAL's Periodic_2_Delaunay_triangulation_2 (exact
// predicates on the copies too): on points in general position the periodic Delaunay
// triangulation is unique, and both must give the same triangles with the same offsets.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_traits_2.h>
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include "ridt/periodic.hpp"

namespace ridt::test {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Gt = CGAL::Periodic_2_Delaunay_triangulation_traits_2<K>;
using P2dt = CGAL::Periodic_2_Delaunay_triangulation_2<Gt>;

// A triangle as (index, dx, dy) of its corners, moved so that its least index is at offset 0
// and rotated to come first (counter-clockwise order kept).
using Corner = std::tuple<VertexId, int, int>;
using Face = std::array<Corner, 3>;

Face face(std::array<Corner, 3> c) {
  while (std::get<0>(c[1]) < std::get<0>(c[0]) || std::get<0>(c[2]) < std::get<0>(c[0]))
    std::rotate(c.begin(), c.begin() + 1, c.end());
  const int dx = std::get<1>(c[0]), dy = std::get<2>(c[0]);
  for (Corner& k : c) std::get<1>(k) -= dx, std::get<2>(k) -= dy;
  return c;
}

std::set<Face> cgal(const std::vector<Point>& pts, bool& one_cover) {
  std::map<std::pair<double, double>, VertexId> index;
  for (VertexId i = 0; i < pts.size(); ++i) index[{pts[i].x, pts[i].y}] = i;
  std::vector<K::Point_2> in;
  for (const Point& p : pts) in.emplace_back(p.x, p.y);
  P2dt t(in.begin(), in.end(), P2dt::Iso_rectangle(0, 0, 1, 1));
  EXPECT_TRUE(t.is_valid());
  one_cover = t.is_1_cover();
  std::set<Face> out;
  for (auto f = t.periodic_triangles_begin(P2dt::UNIQUE); f != t.periodic_triangles_end(P2dt::UNIQUE); ++f) {
    std::array<Corner, 3> c;
    for (int i = 0; i < 3; ++i)
      c[i] = {index.at({(*f)[i].first.x(), (*f)[i].first.y()}), (*f)[i].second.x(), (*f)[i].second.y()};
    out.insert(face(c));
  }
  return out;
}

std::set<Face> ours(const std::vector<Point>& pts) {
  const PeriodicTriangulation t = triangulate_periodic(pts, {});
  const CheckResult r = check_periodic(pts, t.domain, t.triangles, t.offsets);
  EXPECT_TRUE(r.valid) << r.message;
  std::set<Face> out;
  for (std::size_t f = 0; f < t.size(); ++f) {
    std::array<Corner, 3> c;
    for (int i = 0; i < 3; ++i) c[i] = {t.triangles[3 * f + i], t.offsets[3 * f + i].dx, t.offsets[3 * f + i].dy};
    out.insert(face(c));
  }
  EXPECT_EQ(out.size(), t.size());
  return out;
}

TEST(PeriodicAgainstCgal, SameTrianglesAndOffsets) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> cluster(0, 0.02);
  int compared = 0;
  for (const std::size_t n : {60u, 1000u, 50000u}) {
    for (int kind = 0; kind < 2; ++kind) {
      std::vector<Point> pts;
      for (std::size_t i = 0; i < n; ++i) {
        Point p{u(random), u(random)};
        if (kind == 1 && i % 2 == 0) {  // clusters astride the domain's sides and corner
          p = {std::fmod(1.0 + 0.01 * double(i % 3) + cluster(random), 1.0), std::fmod(1.0 + cluster(random), 1.0)};
          if (!(p.x < 1.0)) p.x = 0;
          if (!(p.y < 1.0)) p.y = 0;
        }
        pts.push_back(p);
      }
      bool one_cover = false;
      const std::set<Face> a = cgal(pts, one_cover), b = ours(pts);
      EXPECT_EQ(b.size(), 2 * n);
      if (!one_cover) continue;  // CGAL lists its 9-sheeted cover's triangles
      EXPECT_EQ(a, b) << "n " << n << " kind " << kind;
      ++compared;
    }
  }
  EXPECT_GE(compared, 4);  // at 1,000 points and more CGAL's is one cover
}

}  // namespace
}  // namespace ridt::test
