// The serial triangulation, end to end: every result goes through the exact validator.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "helpers.hpp"
#include "order/random.hpp"
#include "output/output.hpp"
#include "ridt/generate.hpp"

namespace ridt::test {
namespace {

constexpr Distribution kDistributions[] = {Distribution::Uniform, Distribution::Normal, Distribution::Grid,
                                           Distribution::Clusters};

class EveryDistribution : public ::testing::TestWithParam<std::tuple<Distribution, int>> {};

TEST_P(EveryDistribution, PassesTheExactValidator) {
  const auto [d, n] = GetParam();
  const std::vector<Point> pts = generate(d, n, 11);
  const Triangulation t = triangulate_checked(pts);
  EXPECT_TRUE(t.warning.empty()) << t.warning;
  EXPECT_EQ(t.stats.distinct, static_cast<std::uint64_t>(n));
  // Euler for a triangulation of all points: 2n - 2 - h triangles.
  EXPECT_EQ(t.size(), 2 * static_cast<std::size_t>(n) - 2 - t.hull.size());
}

INSTANTIATE_TEST_SUITE_P(Sizes, EveryDistribution,
                         ::testing::Combine(::testing::ValuesIn(kDistributions), ::testing::Values(10, 1000, 100000)),
                         [](const auto& info) {
                           return std::string(to_string(std::get<0>(info.param))) + "_" +
                               std::to_string(std::get<1>(info.param));
                         });

TEST(Triangulate, SameTrianglesForEverySeed) {
  for (Distribution d : kDistributions) {
    const std::vector<Point> pts = generate(d, 5000, 3);
    Options o;
    o.seed = 1;
    const TriangleSet first = canonical(triangulate(pts, o).triangles);
    for (std::uint64_t seed : {2u, 3u, 12345u}) {
      o.seed = seed;
      EXPECT_EQ(canonical(triangulate(pts, o).triangles), first) << to_string(d) << " " << seed;
    }
  }
}

TEST(Triangulate, CanonicalOrderIsIdenticalForEverySeed) {
  const std::vector<Point> pts = generate(Distribution::Grid, 900, 1);
  Options o;
  o.canonical_order = true;
  const Triangulation a = triangulate(pts, o);
  o.seed = 99;
  const Triangulation b = triangulate(pts, o);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.neighbors, b.neighbors);
  EXPECT_EQ(a.hull, b.hull);
  // The order is the one promised (each triangle from its smallest vertex, the triangles
  // sorted), the neighbours follow the triangles they name, and the triangles are those of
  // the plain output.
  EXPECT_EQ(audit(pts, a), "");
  for (std::size_t t = 0; t < a.size(); ++t) {
    const VertexId* v = &a.triangles[3 * t];
    EXPECT_TRUE(v[0] < v[1] && v[0] < v[2]) << t;
    if (t > 0) {
      EXPECT_TRUE(std::lexicographical_compare(v - 3, v, v, v + 3)) << t;
    }
  }
  o.canonical_order = false;
  EXPECT_EQ(canonical(a.triangles), canonical(triangulate(pts, o).triangles));
}

// The canonical order on threads (triangles put into buckets of first vertices part by part,
// each bucket sorted on its own): the same arrays from 1, 2 and 5 threads, sorted, neighbours
// that name the right triangles.
TEST(Triangulate, CanonicalOrderIsTheSameOnAnyThreads) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 150000, 8);
  Options o;
  o.canonical_order = true;
  o.method = Method::Partition;
  o.threads = 1;
  const Triangulation one = triangulate(pts, o);
  EXPECT_EQ(audit(pts, one), "");
  for (std::size_t t = 1; t < one.size(); ++t) {
    const VertexId* v = &one.triangles[3 * t];
    ASSERT_TRUE(v[0] < v[1] && v[0] < v[2]) << t;
    ASSERT_TRUE(std::lexicographical_compare(v - 3, v, v, v + 3)) << t;
  }
  for (unsigned threads : {2u, 5u}) {
    o.threads = threads;
    const Triangulation t = triangulate(pts, o);
    EXPECT_EQ(t.triangles, one.triangles) << threads;
    EXPECT_EQ(t.neighbors, one.neighbors) << threads;
  }
}

// Options::neighbors off: the same triangles (in the same order where it is fixed) and no
// neighbours; the canonical sort then works in the neighbours' memory. A fan's centre, the
// least vertex of every triangle, makes one group of them all (sorted otherwise than a few).
TEST(Triangulate, WithoutNeighboursTheSameTriangles) {
  std::vector<Point> fan = {{0, 0}};
  for (int k = 0; k < 500; ++k) fan.push_back({std::cos(k * 0.0125663706), std::sin(k * 0.0125663706)});
  for (const std::vector<Point>& pts : {generate(Distribution::Uniform, 150000, 9), fan}) {
    for (const bool canonical : {true, false})
      for (const unsigned threads : {1u, 2u, 3u}) {
        Options o;
        o.canonical_order = canonical;
        o.method = Method::Partition;
        o.threads = threads;
        const Triangulation with = triangulate(pts, o);
        o.neighbors = false;
        const Triangulation without = triangulate(pts, o);
        EXPECT_TRUE(without.neighbors.empty());
        EXPECT_EQ(without.hull, with.hull);
        if (!canonical) {  // a threaded run's order differs from run to run
          EXPECT_EQ(test::canonical(without.triangles), test::canonical(with.triangles)) << threads;
          if (threads == 1) {
            EXPECT_EQ(without.triangles, with.triangles);
          }
          continue;
        }
        EXPECT_EQ(without.triangles, with.triangles) << threads;
        EXPECT_EQ(audit(pts, with), "");
        for (std::size_t t = 1; t < without.size(); ++t) {
          const VertexId* v = &without.triangles[3 * t];
          ASSERT_TRUE(v[0] < v[1] && v[0] < v[2]) << t;
          ASSERT_TRUE(std::lexicographical_compare(v - 3, v, v, v + 3)) << t;
        }
      }
  }
}

// The canonical sort on what no triangulation holds: two triangles on one directed edge, and
// one triangle twice (each rank among its first vertex's group then not distinct). None is
// lost: the result is the triples, each turned to its least vertex, sorted; on any threads,
// with neighbours (none here) or without.
TEST(Triangulate, CanonicalSortLosesNoTriangleOnTies) {
  std::vector<VertexId> tri;
  detail::Rng rng(5);
  for (int k = 0; k < 100000; ++k) {
    const auto a = static_cast<VertexId>(rng.below(30000)), b = static_cast<VertexId>(30000 + rng.below(30000));
    tri.insert(tri.end(), {a, b, static_cast<VertexId>(60000 + rng.below(30000))});
    if (k % 7 == 0) tri.insert(tri.end(), {a, b, static_cast<VertexId>(90000 + rng.below(10))});  // a tie on a-b
    if (k % 11 == 0) tri.insert(tri.end(), {b, static_cast<VertexId>(60000 + k % 30000), a});  // turned
  }
  tri.insert(tri.end(), {tri[0], tri[1], tri[2]});  // a triangle twice
  std::vector<std::array<VertexId, 3>> expected;
  for (std::size_t t = 0; t < tri.size() / 3; ++t) {
    std::array<VertexId, 3> v = {tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]};
    std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
    expected.push_back(v);
  }
  std::sort(expected.begin(), expected.end());
  for (const bool neighbors : {true, false})
    for (const unsigned threads : {1u, 3u}) {
      Triangulation t;
      t.triangles = tri;
      t.neighbors.assign(tri.size(), -1);
      detail::canonicalize(t, threads, neighbors);
      std::vector<std::array<VertexId, 3>> got;
      for (std::size_t k = 0; k < t.size(); ++k)
        got.push_back({t.triangles[3 * k], t.triangles[3 * k + 1], t.triangles[3 * k + 2]});
      EXPECT_EQ(got, expected) << neighbors << " " << threads;
    }
}

TEST(Triangulate, ShuffledInputGivesTheSameTriangles) {
  for (Distribution d : kDistributions) {
    const std::vector<Point> pts = generate(d, 3000, 5);
    std::vector<VertexId> perm(pts.size());
    std::iota(perm.begin(), perm.end(), 0u);
    detail::Rng rng(42);
    for (std::size_t i = perm.size(); i > 1; --i) std::swap(perm[i - 1], perm[rng.below(i)]);
    std::vector<Point> shuffled(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) shuffled[i] = pts[perm[i]];
    std::vector<VertexId> back = triangulate(shuffled).triangles;
    for (VertexId& v : back) v = perm[v];
    EXPECT_EQ(canonical(back), canonical(triangulate(pts).triangles)) << to_string(d);
  }
}

TEST(Triangulate, NeighboursAndHullAreConsistent) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 2000, 9);
  const Triangulation t = triangulate(pts);
  std::size_t hull_edges = 0;
  for (std::size_t k = 0; k < t.size(); ++k)
    for (int i = 0; i < 3; ++i) {
      const std::int32_t nb = t.neighbors[3 * k + i];
      const VertexId a = t.triangles[3 * k + (i + 1) % 3], b = t.triangles[3 * k + (i + 2) % 3];
      if (nb < 0) {
        ++hull_edges;
        continue;
      }
      // The neighbour has the edge b -> a and points back to us.
      bool found = false;
      for (int j = 0; j < 3; ++j)
        if (t.triangles[3 * nb + (j + 1) % 3] == b && t.triangles[3 * nb + (j + 2) % 3] == a) {
          EXPECT_EQ(t.neighbors[3 * nb + j], static_cast<std::int32_t>(k));
          found = true;
        }
      EXPECT_TRUE(found);
    }
  EXPECT_EQ(hull_edges, t.hull.size());
  for (std::size_t i = 0; i < t.hull.size(); ++i) {
    const Point& a = pts[t.hull[i]];
    const Point& b = pts[t.hull[(i + 1) % t.hull.size()]];
    const Point& c = pts[t.hull[(i + 2) % t.hull.size()]];
    EXPECT_GE((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x), 0);
  }
}

TEST(Triangulate, FlatArrayOverload) {
  const std::vector<double> xy = {0, 0, 1, 0, 0, 1, 1, 1, 0.5, 0.25};
  const std::vector<Point> pts = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.5, 0.25}};
  const Triangulation t = triangulate(std::span<const double>(xy));
  EXPECT_EQ(audit(pts, t), "");  // x and y taken in their order, the whole result sound
  EXPECT_EQ(compare(t, triangulate(pts)), "");
  EXPECT_EQ(t.size(), 4u);
  EXPECT_THROW(triangulate(std::span<const double>(xy.data(), 3)), InputError);
}

// ---- Degenerate sets ----

// Memory is planned: the estimate grows with the points, walking needs less than the DAG, and a
// run over its limit is refused before it starts, with a message that names both numbers.
TEST(Memory, EstimateGrowsWithThePointsAndWalkingNeedsLess) {
  Options walk;
  walk.method = Method::Serial;
  Options dag = walk;
  dag.locate = Locate::Dag;
  EXPECT_LT(estimate_memory(1000000, walk), estimate_memory(1000000, dag));
  EXPECT_LT(estimate_memory(1000, walk), estimate_memory(1000000, walk));
  EXPECT_GT(estimate_memory(10000000, walk), 10000000u * 48);  // at least the result's arrays
  Options bad = walk;
  bad.method = Method::Partition;
  bad.order = Order::Random;
  EXPECT_THROW(estimate_memory(10, bad), InputError);
  EXPECT_GT(available_memory(), 0u);
}

TEST(Memory, ARunOverItsLimitIsRefusedBeforeItStarts) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 100000, 4);
  Options o;
  o.method = Method::Serial;
  o.locate = Locate::Dag;
  o.memory_limit = estimate_memory(pts.size(), o) - 1;
  try {
    triangulate(pts, o);
    FAIL() << "no MemoryError";
  } catch (const MemoryError& e) {
    EXPECT_GT(e.needed, e.available);
    const std::string what = e.what();
    EXPECT_NE(what.find("needs about"), std::string::npos) << what;
    EXPECT_NE(what.find("is available"), std::string::npos) << what;
    EXPECT_NE(what.find("the walking methods"), std::string::npos) << what;  // they would fit
  }
  o.memory_limit = estimate_memory(pts.size(), o);
  const Triangulation t = triangulate(pts, o);
  EXPECT_EQ(t.stats.memory_estimate, o.memory_limit);
  EXPECT_EQ(t.size(), triangulate(pts).size());
}

TEST(Degenerate, ZeroToThreePoints) {
  EXPECT_EQ(triangulate(std::vector<Point>{}).size(), 0u);
  const Triangulation one = triangulate(std::vector<Point>{{1, 2}});
  EXPECT_EQ(one.size(), 0u);
  EXPECT_NE(one.warning.find("fewer than three"), std::string::npos);
  EXPECT_EQ(triangulate(std::vector<Point>{{1, 2}, {3, 4}}).size(), 0u);
  const Triangulation three = triangulate_checked({{0, 0}, {1, 0}, {0, 1}});
  ASSERT_EQ(three.size(), 1u);
  EXPECT_EQ(three.hull.size(), 3u);
  const Triangulation line3 = triangulate(std::vector<Point>{{0, 0}, {1, 1}, {2, 2}});
  EXPECT_EQ(line3.size(), 0u);
  EXPECT_NE(line3.warning.find("collinear"), std::string::npos);
}

TEST(Degenerate, AllDuplicates) {
  const std::vector<Point> pts(100, Point{3.5, -2});
  const Triangulation t = triangulate(pts);
  EXPECT_EQ(t.size(), 0u);
  ASSERT_EQ(t.duplicates.size(), 99u);
  for (std::size_t i = 0; i < 99; ++i) {
    EXPECT_EQ(t.duplicates[i].dropped, i + 1);
    EXPECT_EQ(t.duplicates[i].kept, 0u);
  }
}

TEST(Degenerate, DuplicatesKeepTheSmallestIndex) {
  std::vector<Point> pts = generate(Distribution::Uniform, 500, 2);
  pts.push_back(pts[7]);
  pts.push_back(pts[7]);
  pts.insert(pts.begin(), pts[10]);  // now index 0 and 11 are equal; 8 and 501, 502 too
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    Options o;
    o.seed = seed;
    const Triangulation t = triangulate_checked(pts, o);
    ASSERT_EQ(t.duplicates.size(), 3u);
    EXPECT_EQ(t.duplicates[0].dropped, 11u);
    EXPECT_EQ(t.duplicates[0].kept, 0u);
    EXPECT_EQ(t.duplicates[1].dropped, 501u);
    EXPECT_EQ(t.duplicates[1].kept, 8u);
    EXPECT_EQ(t.duplicates[2].dropped, 502u);
    EXPECT_EQ(t.duplicates[2].kept, 8u);
    for (VertexId v : t.triangles) EXPECT_TRUE(v != 11 && v != 501 && v != 502);
  }
}

TEST(Degenerate, PointsOnOneLine) {
  std::vector<Point> pts;
  for (int i = 0; i < 1000; ++i) pts.push_back({i * 0.5, 3 - i * 0.25});
  const Triangulation t = triangulate(pts);
  EXPECT_EQ(t.size(), 0u);
  EXPECT_NE(t.warning.find("collinear"), std::string::npos);
  EXPECT_TRUE(check(pts, t.triangles).valid);
}

TEST(Degenerate, PointsOnTwoLines) {
  std::vector<Point> pts;
  for (int i = 0; i < 500; ++i) pts.push_back({double(i), 0});
  for (int i = 0; i < 500; ++i) pts.push_back({double(i) + 0.5, 7});
  const Triangulation t = triangulate_checked(pts);
  EXPECT_EQ(t.size(), 998u);  // a strip: every triangle uses both lines
  EXPECT_EQ(t.hull.size(), 1000u);
}

TEST(Degenerate, RegularPolygon) {
  std::vector<Point> pts;
  for (int i = 0; i < 1000; ++i) pts.push_back({std::cos(2 * M_PI * i / 1000), std::sin(2 * M_PI * i / 1000)});
  const Triangulation t = triangulate_checked(pts);
  EXPECT_EQ(t.size(), 998u);
}

TEST(Degenerate, ExactlyCocircularIntegerPoints) {
  // All integer points on the circle x^2 + y^2 = 5^2 * 13^2 * 17^2: heavily cocircular.
  std::vector<Point> pts;
  const long r2 = 5L * 5 * 13 * 13 * 17 * 17;
  for (long x = -1105; x <= 1105; ++x) {
    const long y2 = r2 - x * x;
    const long y = std::lround(std::sqrt(double(y2)));
    if (y * y == y2) {
      pts.push_back({double(x), double(y)});
      if (y != 0) pts.push_back({double(x), double(-y)});
    }
  }
  ASSERT_GT(pts.size(), 20u);
  const TriangleSet first = canonical(triangulate_checked(pts).triangles);
  for (std::uint64_t seed : {2u, 3u, 4u}) {
    Options o;
    o.seed = seed;
    EXPECT_EQ(canonical(triangulate_checked(pts, o).triangles), first);
  }
}

TEST(Degenerate, IntegerGrid1000x1000) {
  const std::vector<Point> pts = generate(Distribution::Grid, 1000000, 1);
  const Triangulation t = triangulate_checked(pts);
  EXPECT_EQ(t.size(), 2u * 999 * 999);
  EXPECT_EQ(t.hull.size(), 3996u);
}

TEST(Degenerate, ScaledAndShiftedGrids) {
  const std::vector<Point> base = generate(Distribution::Grid, 400, 1);
  const TriangleSet expected = canonical(triangulate_checked(base).triangles);
  for (double s : {std::ldexp(1.0, -500), 1e-9, 1e9, std::ldexp(1.0, 500)}) {
    std::vector<Point> pts = base;
    for (Point& p : pts) p = {p.x * s, p.y * s};
    EXPECT_EQ(canonical(triangulate_checked(pts).triangles), expected) << s;
  }
  std::vector<Point> shifted = base;
  for (Point& p : shifted) p = {p.x + 1e15, p.y - 1e15};
  EXPECT_EQ(canonical(triangulate_checked(shifted).triangles), expected);
}

// ---- The paper's finite bounding triangle ----

// A flat hull edge under a point close to it: the circle through them is large and swallows
// the bounding vertex (-K, -K) when K = 3 M, so the hull edge is lost (the paper's defect).
const std::vector<Point> kFlatHull = {{0, 0}, {1, 0}, {0.5, 0.03}, {0.5, 1}};

TEST(FiniteBounding, KThreeLosesAHullEdgeAndSaysSo) {
  Options o;
  o.experiment.bounding = Bounding::Finite;
  o.experiment.k = 3;
  const Triangulation t = triangulate(kFlatHull, o);
  const CheckResult r = check(kFlatHull, t.triangles);
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.message.find("convex hull edge"), std::string::npos) << r.message;
  EXPECT_NE(t.warning.find("lost convex hull edges"), std::string::npos) << t.warning;
}

TEST(FiniteBounding, KTenKeepsThisHull) {
  Options o;
  o.experiment.bounding = Bounding::Finite;
  o.experiment.k = 10;
  const Triangulation t = triangulate_checked(kFlatHull, o);
  EXPECT_TRUE(t.warning.empty());
  EXPECT_EQ(canonical(t.triangles), canonical(triangulate(kFlatHull).triangles));
}

TEST(FiniteBounding, RejectsSmallK) {
  Options o;
  o.experiment.bounding = Bounding::Finite;
  o.experiment.k = 1.5;
  EXPECT_THROW(triangulate(kFlatHull, o), InputError);
}

TEST(FiniteBounding, WarnsExactlyWhenTheResultIsWrong) {
  // Uniform points in a square have nearly collinear hull points, whose huge circles often
  // reach even K = 10 M: the paper's defect is common. The warning must match the validator.
  int lost = 0;
  for (double k : {3.0, 10.0, 100.0})
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      const std::vector<Point> pts = generate(Distribution::Uniform, 5000, seed);
      Options o;
      o.experiment.bounding = Bounding::Finite;
      o.experiment.k = k;
      const Triangulation t = triangulate(pts, o);
      const bool valid = check(pts, t.triangles).valid;
      EXPECT_EQ(valid, t.warning.empty()) << "k " << k << " seed " << seed << ": " << t.warning;
      if (valid) {
        EXPECT_EQ(canonical(t.triangles), canonical(triangulate(pts).triangles));
      }
      lost += !valid;
    }
  EXPECT_GT(lost, 0);  // the defect shows on these sets
}

// ---- Bad input ----

TEST(BadInput, NanAndInfinityAreRejected) {
  std::vector<Point> pts = {{0, 0}, {1, 0}, {0, 1}};
  pts[1].y = std::nan("");
  EXPECT_THROW(triangulate(pts), InputError);
  pts[1].y = INFINITY;
  EXPECT_THROW(triangulate(pts), InputError);
}

// The input is scanned in parts, one a thread: the message names the first bad point, wherever
// it lies, for every method and thread count.
TEST(BadInput, TheFirstBadPointIsNamed) {
  std::vector<Point> pts = generate(Distribution::Uniform, 300000, 4);
  pts[250001].x = -INFINITY;
  pts[150001].y = std::nan("");
  for (const Method m : {Method::Serial, Method::Partition, Method::Optimistic})
    for (const unsigned threads : {1u, 2u, 3u}) {
      Options o;
      o.method = m;
      o.threads = threads;
      try {
        triangulate(pts, o);
        ADD_FAILURE() << "no error";
      } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "point 150001 has a NaN coordinate");
      }
    }
  pts[150001].y = 0.5;
  try {
    triangulate(pts);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "point 250001 has an infinite coordinate");
  }
}

// ---- The robustness fixtures of delaunator ----

class Fixture : public ::testing::TestWithParam<const char*> {};

TEST_P(Fixture, EveryScaleIsExactlyDelaunay) {
  const std::vector<Point> base = read_json_points(fixture_path(GetParam()));
  ASSERT_GT(base.size(), 2u);
  for (double s : {1.0, 1e-9, 1e-2, 1e2, 1e9}) {
    std::vector<Point> pts = base;
    for (Point& p : pts) p = {p.x * s, p.y * s};
    const Triangulation t = triangulate(pts);
    const CheckResult r = check(pts, t.triangles);
    EXPECT_TRUE(r.valid) << GetParam() << " scaled by " << s << ": " << r.message;
  }
}

INSTANTIATE_TEST_SUITE_P(Delaunator, Fixture, ::testing::ValuesIn(kDelaunatorFixtures));

}  // namespace
}  // namespace ridt::test
