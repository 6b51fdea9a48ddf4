// Point location (ridt/locate.hpp) against an exact scan of every triangle.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "helpers.hpp"
#include "predicates/predicates.hpp"
#include "ridt/generate.hpp"
#include "ridt/interpolate.hpp"
#include "ridt/locate.hpp"

namespace ridt {
namespace {

// Whether the closed triangle t holds q, exactly.
bool holds(const std::vector<Point>& pts, const Triangulation& tri, std::size_t t, const Point& q) {
  const VertexId* v = &tri.triangles[3 * t];
  return detail::orient2d(pts[v[0]], pts[v[1]], q) >= 0 && detail::orient2d(pts[v[1]], pts[v[2]], q) >= 0 &&
      detail::orient2d(pts[v[2]], pts[v[0]], q) >= 0;
}

// Every answer holds its query, and -1 comes exactly when the query is outside the hull.
void expect_located(const std::vector<Point>& pts, const Triangulation& tri, const std::vector<Point>& queries,
                    const std::vector<std::int32_t>& found) {
  ASSERT_EQ(found.size(), queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    if (found[i] >= 0) {
      ASSERT_LT(static_cast<std::size_t>(found[i]), tri.size());
      EXPECT_TRUE(holds(pts, tri, found[i], queries[i])) << "query " << i;
    } else {
      // Outside the hull (counter-clockwise): strictly right of one of its edges, or not finite.
      bool outside = !std::isfinite(queries[i].x) || !std::isfinite(queries[i].y);
      for (std::size_t h = 0; h < tri.hull.size() && !outside; ++h)
        outside = detail::orient2d(pts[tri.hull[h]], pts[tri.hull[(h + 1) % tri.hull.size()]], queries[i]) < 0;
      EXPECT_TRUE(outside) << "query " << i << " is in the hull but was answered -1";
    }
  }
}

std::vector<Point> random_queries(std::size_t m, double lo, double hi, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<Point> q(m);
  for (Point& p : q) p = {u(rng), u(rng)};
  return q;
}

TEST(Locate, RandomQueriesInsideAndOutsideEveryDistribution) {
  for (const Distribution d :
       {Distribution::Uniform, Distribution::Normal, Distribution::Grid, Distribution::Clusters}) {
    const std::vector<Point> pts = generate(d, 3000, 7);
    const Triangulation tri = test::triangulate_checked(pts);
    double lo = pts[0].x, hi = lo;
    for (const Point& p : pts) lo = std::min({lo, p.x, p.y}), hi = std::max({hi, p.x, p.y});
    const double pad = (hi - lo) / 4;
    const std::vector<Point> queries = random_queries(4000, lo - pad, hi + pad, 3);
    for (const unsigned threads : {1u, 2u, 4u}) expect_located(pts, tri, queries, locate(pts, tri, queries, threads));
  }
}

TEST(Locate, VerticesEdgesAndNonFiniteQueries) {
  // A grid: many cocircular points; queries at every vertex, on every edge's midpoint (exact
  // for these integers) and beyond the hull along its lines.
  std::vector<Point> pts;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) pts.push_back({double(i), double(j)});
  const Triangulation tri = test::triangulate_checked(pts);
  std::vector<Point> queries = pts;
  for (std::size_t t = 0; t < tri.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const Point& a = pts[tri.triangles[3 * t + i]];
      const Point& b = pts[tri.triangles[3 * t + (i + 1) % 3]];
      queries.push_back({(a.x + b.x) / 2, (a.y + b.y) / 2});
    }
  queries.push_back({-1, 5});
  queries.push_back({5, 19.5});
  queries.push_back({25, 19});
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  queries.push_back({nan, 1});
  queries.push_back({1, inf});
  const std::vector<std::int32_t> found = locate(pts, tri, queries, 2);
  expect_located(pts, tri, queries, found);
  for (std::size_t i = 0; i + 5 < queries.size(); ++i) EXPECT_GE(found[i], 0) << "query " << i;
  for (std::size_t i = queries.size() - 5; i < queries.size(); ++i) EXPECT_EQ(found[i], -1);
}

TEST(Locate, ManyQueriesOnThreadsAndHugeScales) {
  for (const double scale : {1e-300, 1.0, 1e300}) {
    std::vector<Point> pts = generate(Distribution::Uniform, 2000, 11);
    for (Point& p : pts) p = {p.x * scale, p.y * scale};
    const Triangulation tri = test::triangulate_checked(pts);
    std::vector<Point> queries = random_queries(40000, -0.1, 1.1, 5);
    for (Point& p : queries) p = {p.x * scale, p.y * scale};
    expect_located(pts, tri, queries, locate(pts, tri, queries, 3));
  }
}

TEST(Locate, QueriesInOrderThenScattered) {
  // Queries row by row over a grid (walked in their own order), then scattered ones (sorted
  // along the curve once the walks grow long), then rows again, with non-finite ones mixed in.
  const std::vector<Point> pts = generate(Distribution::Normal, 20000, 9);
  const Triangulation tri = triangulate(pts);
  std::vector<Point> queries;
  for (int j = 0; j < 150; ++j)
    for (int i = 0; i < 150; ++i) queries.push_back({-4 + 8 * i / 149.0, -4 + 8 * j / 149.0});
  const std::vector<Point> scattered = random_queries(20000, -5, 5, 8);
  queries.insert(queries.end(), scattered.begin(), scattered.end());
  for (int j = 0; j < 100; ++j)
    for (int i = 0; i < 100; ++i) queries.push_back({-3 + 6 * i / 99.0, 3 - 6 * j / 99.0});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < queries.size(); k += 997) queries[k].x = nan;
  for (const unsigned threads : {1u, 2u}) expect_located(pts, tri, queries, locate(pts, tri, queries, threads));
}

TEST(Locate, EmptyTriangulationAndBadArrays) {
  const std::vector<Point> line = {{0, 0}, {1, 1}, {2, 2}};
  const Triangulation tri = triangulate(line);
  ASSERT_EQ(tri.size(), 0u);
  const std::vector<Point> queries = {{1, 1}, {0, 5}};
  EXPECT_EQ(locate(line, tri, queries), (std::vector<std::int32_t>{-1, -1}));

  const std::vector<Point> pts = {{0, 0}, {1, 0}, {0, 1}};
  const std::vector<VertexId> bad = {0, 1, 7};
  const std::vector<std::int32_t> neighbors = {-1, -1, -1};
  std::vector<std::int32_t> out(2);
  EXPECT_THROW(locate(pts, bad, neighbors, queries, out), InputError);
  const std::vector<VertexId> good = {0, 1, 2};
  EXPECT_THROW(locate(pts, good, std::vector<std::int32_t>{-1, 3, -1}, queries, out), InputError);
  EXPECT_THROW(locate(pts, good, neighbors, queries, std::span<std::int32_t>(out.data(), 1)), InputError);
}

// scipy's find_simplex tolerance: points that rounding put an ulp or so outside a hull with
// long runs of collinear points (a grid's sides) get the hull triangle beside them, those
// farther out -1, and points inside the same answers as without it.
TEST(Locate, ScipyToleranceAcceptsPointsJustOutsideTheHull) {
  std::vector<Point> pts;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) pts.push_back({i / 20.0, j / 20.0});
  const Triangulation tri = test::triangulate_checked(pts);
  const double up = std::nextafter(1.0, 2.0), down = -std::numeric_limits<double>::denorm_min();
  std::vector<Point> near, far;
  for (int k = 0; k <= 97; ++k) {
    const double y = k / 97.0;
    near.insert(near.end(), {{up, y}, {y, up}, {down, y}, {y, down}, {std::nextafter(up, 2.0), y}});
    far.insert(far.end(), {{1 + 1e-12, y}, {y, -1e-12}, {2, y}, {y, -5}});
  }
  const std::vector<std::int32_t> found = locate(pts, tri, near, 2, kScipyTolerance);
  for (std::size_t i = 0; i < near.size(); ++i) {
    ASSERT_GE(found[i], 0) << "query " << i;
    const VertexId* v = &tri.triangles[3 * static_cast<std::size_t>(found[i])];
    for (const double w : barycentric(pts[v[0]], pts[v[1]], pts[v[2]], near[i])) {
      EXPECT_GE(w, -kScipyTolerance) << "query " << i;
      EXPECT_LE(w, 1 + kScipyTolerance) << "query " << i;
    }
  }
  EXPECT_EQ(locate(pts, tri, near, 1), std::vector<std::int32_t>(near.size(), -1));
  EXPECT_EQ(locate(pts, tri, far, 1, kScipyTolerance), std::vector<std::int32_t>(far.size(), -1));
  const std::vector<Point> inside = random_queries(2000, -0.1, 1.1, 5);
  EXPECT_EQ(locate(pts, tri, inside, 1, kScipyTolerance), locate(pts, tri, inside, 1, 0));
}

// Enough queries just outside the hull for every thread to ask for the tolerance's box at once
// (found once, by whichever asks first): the same answers as on one thread.
TEST(Locate, ScipyToleranceOnThreads) {
  const std::vector<Point> pts = generate(Distribution::Grid, 10000, 3);
  const Triangulation tri = test::triangulate_checked(pts);
  double x1 = pts[0].x;
  for (const Point& p : pts) x1 = std::max(x1, p.x);
  std::vector<Point> q;
  for (int k = 0; k < 60000; ++k) q.push_back({std::nextafter(x1, 2 * x1 + 1), pts[k % pts.size()].y});
  const std::vector<std::int32_t> one = locate(pts, tri, q, 1, kScipyTolerance);
  EXPECT_EQ(locate(pts, tri, q, 4, kScipyTolerance), one);
  EXPECT_GT(std::count_if(one.begin(), one.end(), [](std::int32_t t) { return t >= 0; }), 50000);
}

// The tolerance's bounding box is in absolute units, as scipy's: at a scale of 10^6 an ulp
// outside the box is more than 100 DBL_EPSILON outside it, and -1.
TEST(Locate, ScipyToleranceBoxIsAbsolute) {
  const std::vector<Point> pts = {{0, 0}, {1e6, 0}, {1e6, 1e6}, {0, 1e6}, {4e5, 3e5}};
  const Triangulation tri = test::triangulate_checked(pts);
  const std::vector<Point> q = {{std::nextafter(1e6, 2e6), 5e5}, {-1e-300, 5e5}};
  EXPECT_EQ(locate(pts, tri, q, 1, kScipyTolerance)[0], -1);
  EXPECT_GE(locate(pts, tri, q, 1, kScipyTolerance)[1], 0);
}

}  // namespace
}  // namespace ridt
