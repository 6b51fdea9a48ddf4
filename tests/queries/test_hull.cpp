// The convex hull (ridt/hull.hpp) against the Delaunay triangulation's boundary, and its
// validator (check_convex_hull) against hulls made wrong on purpose.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "helpers.hpp"
#include "predicates/predicates.hpp"
#include "ridt/check.hpp"
#include "ridt/generate.hpp"
#include "ridt/hull.hpp"

namespace ridt {
namespace {

void expect_hull(const std::vector<Point>& pts, unsigned threads = 1) {
  const ConvexHull h = convex_hull(pts, false, threads);
  const CheckResult r = check_convex_hull(pts, h.corners);
  EXPECT_TRUE(r.valid) << r.message;
  // Equal points: the triangulation keeps one of them (not always the least index).
  std::vector<Point> mine;
  for (const VertexId v : h.corners) mine.push_back(pts[v]);
  EXPECT_EQ(mine, test::hull_turns(pts, triangulate(pts)));
  for (const VertexId v : h.corners)
    for (VertexId u = 0; u < v; ++u) ASSERT_FALSE(pts[u] == pts[v]) << "corner " << v << " is not the least copy";
}

class HullOf : public ::testing::TestWithParam<Distribution> {};

TEST_P(HullOf, EqualsTheTriangulationsBoundaryAndIsValid) {
  for (const std::size_t n : {3u, 10u, 1000u, 50000u}) {
    const std::vector<Point> pts = generate(GetParam(), n, 7);
    if (n < 10 && GetParam() == Distribution::Grid) continue;  // a few grid points may be collinear
    expect_hull(pts, 2);
  }
}
INSTANTIATE_TEST_SUITE_P(Distributions, HullOf, test::every_distribution(), test::distribution_name);

TEST(Hull, DelaunatorFixtures) {
  for (const char* name : test::kDelaunatorFixtures) {
    SCOPED_TRACE(name);
    expect_hull(test::read_json_points(test::fixture_path(name)));
  }
}

TEST(Hull, PointsOnTheSidesAndCopiesAreNotCorners) {
  // A 5 x 5 grid, each point twice, shuffled: four corners; with `boundary`, the 12 other points
  // on the sides and the 20 copies of boundary points, each beside its side.
  std::vector<Point> pts;
  for (int x = 0; x < 5; ++x)
    for (int y = 0; y < 5; ++y) pts.push_back({double(x), double(y)}), pts.push_back({double(x), double(y)});
  std::shuffle(pts.begin(), pts.end(), std::mt19937(3));
  const ConvexHull h = convex_hull(pts, true);
  ASSERT_EQ(h.corners.size(), 4u);
  EXPECT_EQ(pts[h.corners[0]], (Point{0, 0}));
  EXPECT_EQ(pts[h.corners[1]], (Point{4, 0}));
  EXPECT_EQ(pts[h.corners[2]], (Point{4, 4}));
  EXPECT_EQ(h.on_sides.size(), 12u + 16u);  // 12 on the sides, a copy of each of the 16 boundary points
  for (std::size_t k = 0; k < h.on_sides.size(); ++k) {
    const Point &a = pts[h.corners[h.side[k]]], &b = pts[h.corners[(h.side[k] + 1) % 4]], &p = pts[h.on_sides[k]];
    EXPECT_EQ(detail::orient2d(a, b, p), 0);
    EXPECT_TRUE(std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
                p.y <= std::max(a.y, b.y));
  }
  EXPECT_EQ(h.area, 16);
  EXPECT_EQ(h.perimeter, 16);
  EXPECT_TRUE(check_convex_hull(pts, h.corners).valid);
}

TEST(Hull, AreaAndPerimeterFarFromTheOrigin) {
  // A unit square at 10^9: the shoelace's products are near 10^18, its area 1; exact products
  // and a double-double sum give it to the last place.
  const double o = 1e9;
  const std::vector<Point> pts = {{o, o}, {o + 1, o}, {o + 1, o + 1}, {o, o + 1}, {o + 0.5, o + 0.5}};
  const ConvexHull h = convex_hull(pts);
  EXPECT_EQ(h.area, 1);
  EXPECT_EQ(h.perimeter, 4);
  // A thin triangle: area 2^-30 beside sides of length 1.
  const std::vector<Point> thin = {{0, 0}, {1, 0}, {0.5, 0x1p-29}};
  EXPECT_EQ(convex_hull(thin).area, 0x1p-30);
}

TEST(Hull, HugeAndTinyCoordinates) {
  for (const double scale : {1e300, 1e-300, 0x1p-1070}) {
    SCOPED_TRACE(scale);
    std::vector<Point> pts = generate(Distribution::Uniform, 2000, 5);
    for (Point& p : pts) p = {p.x * scale, p.y * scale};
    const ConvexHull h = convex_hull(pts);
    EXPECT_TRUE(check_convex_hull(pts, h.corners).valid);
    EXPECT_GE(h.corners.size(), 3u);
  }
}

TEST(Hull, DegenerateAndBadInput) {
  EXPECT_TRUE(convex_hull(std::vector<Point>{}).corners.empty());
  EXPECT_TRUE(convex_hull(std::vector<Point>{{1, 1}, {1, 1}, {2, 2}}).corners.empty());
  std::vector<Point> line;
  for (int i = 0; i < 100; ++i) line.push_back({0.1 * i, 0.3 * i});  // rounded: maybe not collinear
  const ConvexHull l = convex_hull(line);
  EXPECT_TRUE(check_convex_hull(line, l.corners).valid);
  std::vector<Point> exact_line;
  for (int i = 0; i < 100; ++i) exact_line.push_back({double(i), double(3 * i)});
  EXPECT_TRUE(convex_hull(exact_line).corners.empty());
  EXPECT_TRUE(check_convex_hull(exact_line, {}).valid);
  EXPECT_THROW(convex_hull(std::vector<Point>{{0, 0}, {1, NAN}, {1, 1}}), InputError);
  EXPECT_THROW(convex_hull(std::vector<Point>{{0, 0}, {INFINITY, 0}, {1, 1}}), InputError);
}

TEST(Hull, ValidatorRefusesWrongHulls) {
  const std::vector<Point> pts = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 0}, {1, 1}, {0, 0}};
  auto valid = [&](std::vector<VertexId> c) { return check_convex_hull(pts, c).valid; };
  EXPECT_TRUE(valid({0, 1, 2, 3}));
  EXPECT_TRUE(valid({1, 2, 3, 0}));  // any start
  EXPECT_FALSE(valid({0, 3, 2, 1}));  // clockwise
  EXPECT_FALSE(valid({0, 1, 2}));  // point 3 outside
  EXPECT_FALSE(valid({0, 4, 1, 2, 3}));  // a point on a side as a corner
  EXPECT_FALSE(valid({0, 1, 2, 3, 6}));  // a copy as a corner
  EXPECT_FALSE(valid({0, 1, 2, 3, 0, 1, 2, 3}));  // round twice
  EXPECT_FALSE(valid({0, 1, 9}));  // not a point
  EXPECT_FALSE(valid({}));  // the points are not collinear
  EXPECT_FALSE(valid({0, 1}));
}

TEST(Hull, SameOnEveryThreadCount) {
  const std::vector<Point> pts = generate(Distribution::Normal, 300000, 11);
  const ConvexHull one = convex_hull(pts, true, 1);
  for (const unsigned t : {2u, 3u, 8u}) {
    const ConvexHull h = convex_hull(pts, true, t);
    EXPECT_EQ(h.corners, one.corners);
    EXPECT_EQ(h.on_sides, one.on_sides);
    EXPECT_EQ(h.area, one.area);
    EXPECT_TRUE(check_convex_hull(pts, h.corners, t).valid);
  }
}

}  // namespace
}  // namespace ridt
