// Quality meshes (triangulate_constrained with Quality): every result through check_mesh, the
// exact validator of meshes, with the bounds asked; small input angles end; regions; huge and
// tiny coordinates give the same mesh, scaled; the coastline generator's polygons are simple.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ridt/check.hpp"
#include "ridt/constrained.hpp"
#include "ridt/generate.hpp"

namespace ridt::test {
namespace {

struct Meshed {
  ConstrainedTriangulation t;
  std::vector<Point> all;  // the input's points, then those added
};

Meshed mesh(const Pslg& g, const Quality& q, bool convex_hull = false, std::vector<Region> regions = {}) {
  Domain d;
  d.convex_hull = convex_hull;
  d.holes = g.holes;
  d.regions = std::move(regions);
  Meshed m{triangulate_constrained(g.points, g.segments, {}, d, q), g.points};
  m.all.insert(m.all.end(), m.t.steiner.begin(), m.t.steiner.end());
  MeshSpec spec;
  spec.edges = m.t.edges;
  spec.segments = g.segments;
  spec.input_points = g.points.size();
  spec.holes = g.holes;
  spec.min_angle = q.min_angle;
  spec.max_area = q.max_area;
  const CheckResult r = check_mesh(m.all, m.t.triangles, spec);
  EXPECT_TRUE(r.valid) << r.message;
  return m;
}

double area(const Meshed& m, std::size_t k) {
  const Point &a = m.all[m.t.triangles[3 * k]], &b = m.all[m.t.triangles[3 * k + 1]],
              &c = m.all[m.t.triangles[3 * k + 2]];
  return ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / 2;
}

TEST(Refine, TheCoastlineToEveryAngle) {
  const Pslg g = generate_coastline(3000, 4, 7);
  for (const double angle : {20.0, 30.0, 34.0}) {
    SCOPED_TRACE(angle);
    Quality q;
    q.min_angle = angle;
    const Meshed m = mesh(g, q);
    EXPECT_GT(m.t.steiner.size(), 0u);
    EXPECT_TRUE(m.t.hull.empty());
  }
  Quality both;
  both.min_angle = 25;
  both.max_area = 1e-4;
  const Meshed m = mesh(g, both, true);  // the convex hull kept, its edges made segments
  for (std::size_t k = 0; k < m.t.size(); ++k) ASSERT_LE(area(m, k), 1e-4);
}

TEST(Refine, ASquareWithAHoleCoversItsAreaExactly) {
  Pslg g;
  g.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}};
  g.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
  g.holes = {{0.5, 0.5}};
  Quality q;
  q.min_angle = 30;
  q.max_area = 0.001;
  const Meshed m = mesh(g, q);
  double total = 0;
  for (std::size_t k = 0; k < m.t.size(); ++k) total += area(m, k);
  EXPECT_NEAR(total, 0.75, 1e-12);  // axis-parallel splits are exact: the area is the domain's
  EXPECT_GT(m.t.size(), 750u);
}

TEST(Refine, SmallInputAnglesEnd) {
  // A needle (angles of 0.6 degrees at two corners) and a fan of segments 2 degrees apart.
  Pslg needle;
  needle.points = {{0, 0}, {1, 0}, {0.5, 0.005}};
  needle.segments = {0, 1, 1, 2, 2, 0};
  Quality q;
  q.min_angle = 30;
  const Meshed m = mesh(needle, q);
  EXPECT_GT(m.t.size(), 1u);
  Pslg fan;
  fan.points = {{0, 0}};
  for (int k = 0; k <= 10; ++k) {
    const double a = k * 2 * 3.14159265358979323846 / 180;
    fan.points.push_back({std::cos(a), std::sin(a)});
    fan.segments.push_back(0), fan.segments.push_back(static_cast<VertexId>(k + 1));
    if (k > 0) fan.segments.push_back(static_cast<VertexId>(k)), fan.segments.push_back(static_cast<VertexId>(k + 1));
  }
  mesh(fan, q);
}

TEST(Refine, RegionsCarryAttributesAndAreaBounds) {
  Pslg g;
  g.points = {{0, 0}, {2, 0}, {2, 1}, {0, 1}, {1, 0}, {1, 1}};
  g.segments = {0, 4, 4, 1, 1, 2, 2, 5, 5, 3, 3, 0, 4, 5};
  const Meshed m = mesh(g, {}, false, {{{0.5, 0.5}, 1.5, 0.01}, {{1.5, 0.5}, -2, 0}});
  ASSERT_EQ(m.t.attributes.size(), m.t.size());
  for (std::size_t k = 0; k < m.t.size(); ++k) {
    const double x =
        (m.all[m.t.triangles[3 * k]].x + m.all[m.t.triangles[3 * k + 1]].x + m.all[m.t.triangles[3 * k + 2]].x) / 3;
    EXPECT_EQ(m.t.attributes[k], x < 1 ? 1.5 : -2);
    if (x < 1) {
      EXPECT_LE(area(m, k), 0.01);
    }
  }
}

TEST(Refine, HugeAndTinyCoordinatesGiveTheSameMesh) {
  const Pslg g = generate_coastline(500, 2, 3);
  Quality q;
  q.min_angle = 28;
  const Meshed base = mesh(g, q);
  for (const int e : {-1000, 1000}) {
    Pslg s = g;
    for (Point& p : s.points) p = {std::ldexp(p.x, e), std::ldexp(p.y, e)};
    for (Point& p : s.holes) p = {std::ldexp(p.x, e), std::ldexp(p.y, e)};
    const Meshed m = mesh(s, q);
    EXPECT_EQ(m.t.triangles, base.t.triangles) << e;
    ASSERT_EQ(m.t.steiner.size(), base.t.steiner.size());
    for (std::size_t k = 0; k < m.t.steiner.size(); ++k)
      EXPECT_EQ(m.t.steiner[k].x, std::ldexp(base.t.steiner[k].x, e));
  }
}

TEST(Refine, BadBoundsAreRefused) {
  const Pslg g = generate_coastline(100, 0, 1);
  Quality q;
  q.min_angle = 35;
  EXPECT_THROW(triangulate_constrained(g.points, g.segments, {}, {}, q), InputError);
  q.min_angle = 20;
  q.max_area = -1;
  EXPECT_THROW(triangulate_constrained(g.points, g.segments, {}, {}, q), InputError);
  Domain d;
  d.regions = {{{0, 0}, NAN, 0}};
  EXPECT_THROW(triangulate_constrained(g.points, g.segments, {}, d), InputError);
}

TEST(Refine, TheStopsAskedAreKept) {
  const Pslg g = generate_coastline(1000, 0, 2);
  Quality q;
  q.min_angle = 30;
  q.max_steiner = 50;
  Domain d;
  d.convex_hull = false;
  const ConstrainedTriangulation t = triangulate_constrained(g.points, g.segments, {}, d, q);
  EXPECT_EQ(t.steiner.size(), 50u);
  EXPECT_NE(t.warning.find("stopped after 50"), std::string::npos) << t.warning;
}

TEST(Generate, CoastlinesAreSimpleAndTheSameEveryTime) {
  const Pslg g = generate_coastline(4000, 9, 5);
  EXPECT_EQ(g.points.size(), 4000u);
  EXPECT_EQ(g.segments.size(), 2 * 4000u);
  EXPECT_EQ(g.holes.size(), 9u);
  const Pslg again = generate_coastline(4000, 9, 5);
  for (std::size_t k = 0; k < g.points.size(); ++k) ASSERT_TRUE(g.points[k] == again.points[k]);
  // Simple: the constrained triangulation adds no crossing, and every segment is one edge.
  const ConstrainedTriangulation t = triangulate_constrained(g.points, g.segments);
  EXPECT_EQ(t.crossings, 0u);
  EXPECT_EQ(t.edges.size(), g.segments.size());
  EXPECT_THROW(generate_coastline(50, 9, 1), InputError);
}

}  // namespace
}  // namespace ridt::test
