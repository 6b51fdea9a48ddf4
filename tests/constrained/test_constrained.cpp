// triangulate_constrained: every result through the exact validator of constrained
// triangulations (check_constrained); the kite, segments through collinear points, grids,
// duplicates, crossing segments refused, every method giving the same triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "helpers.hpp"
#include "order/random.hpp"
#include "predicates/predicates.hpp"
#include "ridt/check.hpp"
#include "ridt/constrained.hpp"
#include "ridt/generate.hpp"

namespace ridt::test {
namespace {

ConstrainedTriangulation checked(const std::vector<Point>& pts, const std::vector<VertexId>& segs,
                                 const Options& o = {}) {
  ConstrainedTriangulation t = triangulate_constrained(pts, segs, o);
  EXPECT_EQ(audit(pts, t, segs), "");
  return t;
}

// The constrained triangulation of pts and segs over `domain`, through check_mesh (the points
// added where segments cross after the input's).
ConstrainedTriangulation carved(const std::vector<Point>& pts, const std::vector<VertexId>& segs,
                                const Domain& domain) {
  ConstrainedTriangulation t = triangulate_constrained(pts, segs, {}, domain);
  std::vector<Point> all = pts;
  all.insert(all.end(), t.steiner.begin(), t.steiner.end());
  MeshSpec spec;
  spec.edges = t.edges, spec.segments = segs, spec.input_points = pts.size(), spec.holes = domain.holes;
  const CheckResult verdict = check_mesh(all, t.triangles, spec);
  EXPECT_TRUE(verdict.valid) << verdict.message;
  spec.edges = {};  // found along the segments, as for a mesh read from Triangle's files
  const CheckResult found = check_mesh(all, t.triangles, spec);
  EXPECT_TRUE(found.valid) << found.message;
  return t;
}

// Fuzzers' graphs beside (10, 0): a square from `first` through (10, 0), (10, above) just above
// it and (0, 10), and inside it `inner`, (6, 4), (6, 6), (4, 6); segments round the square,
// from (6, 4) and (6, 6) to (10, 0), (6, 4)-(6, 6), and (10, 0)-`inner` (kBesideTen).
std::vector<Point> beside_ten(const Point& first, double above, const Point& inner) {
  return {first, {10, 0}, {10, above}, {0, 10}, inner, {6, 4}, {6, 6}, {4, 6}};
}
const std::vector<VertexId> kBesideTen = {0, 1, 1, 2, 2, 3, 3, 0, 5, 1, 5, 6, 6, 1, 1, 4};

TEST(Constrained, TheKitesLongDiagonal) {
  const std::vector<Point> kite = {{0, 0}, {4, -1}, {8, 0}, {4, 1}};
  const ConstrainedTriangulation t = checked(kite, {0, 2});
  EXPECT_EQ(canonical(t.triangles), canonical(std::vector<VertexId>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(t.edges, (std::vector<VertexId>{0, 2}));
  EXPECT_EQ(canonical(checked(kite, {}).triangles), canonical(triangulate(kite).triangles));
}

TEST(Constrained, ASegmentThroughPointsIsSplitThere) {
  // Points along the x axis between the ends, and others above and below.
  std::vector<Point> pts = {{0, 0}, {10, 0}};
  for (int k = 1; k < 10; ++k) pts.push_back({static_cast<double>(k), 0});
  for (int k = 0; k <= 10; ++k) pts.push_back({k + 0.5, 0.3}), pts.push_back({k + 0.25, -0.2});
  const ConstrainedTriangulation t = checked(pts, {0, 1});
  EXPECT_EQ(t.edges.size(), 2 * 10u);  // ten pieces
}

TEST(Constrained, LongSegmentsInEveryDistribution) {
  for (const Distribution d :
       {Distribution::Uniform, Distribution::Normal, Distribution::Grid, Distribution::Clusters}) {
    SCOPED_TRACE(std::string(to_string(d)));
    const std::vector<Point> pts = generate(d, 3000, 11);
    // A fan of long segments from one point: they meet only there (and may pass through
    // points, on the grid, where they are split).
    std::vector<VertexId> segs;
    for (VertexId v = 1; v < 40; ++v) segs.push_back(0), segs.push_back(v * 70);
    const ConstrainedTriangulation t = checked(pts, segs);
    EXPECT_FALSE(check(pts, t.triangles).valid);
  }
}

TEST(Constrained, MemoryIsPlannedBeforeTheRun) {
  // Where the triangulation alone would fit but not the constrained steps beside it, the call is
  // refused up front with both numbers; with room for both it runs.
  const Pslg g = generate_coastline(20000, 4, 3);
  const std::size_t n = g.points.size(), segments = g.segments.size() / 2;
  Options o;
  o.threads = 1;
  const std::size_t plain = estimate_memory(n, o);
  o.memory_limit = plain;
  try {
    triangulate_constrained(g.points, g.segments, o);
    ADD_FAILURE() << "a constrained triangulation past the memory limit ran";
  } catch (const MemoryError& e) {
    EXPECT_EQ(e.available, plain);
    EXPECT_GT(e.needed, plain);
    EXPECT_NE(std::string(e.what()).find("constrained triangulation of 20000 points"), std::string::npos) << e.what();
  }
  o.memory_limit = plain + 44 * n + 8 * segments;
  EXPECT_EQ(triangulate_constrained(g.points, g.segments, o).size(),
            triangulate_constrained(g.points, g.segments).size());
}

TEST(Constrained, RefinementStopsWithinTheMemoryLimit) {
  // An area bound far below what the limit holds: refinement stops with its warning once what it
  // adds would pass Options::memory_limit (at 320 bytes a point added, 3/4 of what is left).
  const std::size_t cache = set_memory_cache_limit(0);  // nothing held from earlier calls
  const std::vector<Point> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  Options o;
  o.threads = 1;
  const std::size_t room = std::size_t{64} << 20;
  o.memory_limit = estimate_memory(square.size(), o) + room;
  Quality q;
  q.max_area = 1e-12;
  q.max_steiner = 2000000;  // were the limit not kept, the test still ends
  const std::vector<VertexId> sides = {0, 1, 1, 2, 2, 3, 3, 0};
  const ConstrainedTriangulation t = triangulate_constrained(square, sides, o, {}, q);
  set_memory_cache_limit(cache);
  EXPECT_NE(t.warning.find("the memory left holds no more"), std::string::npos) << t.warning;
  EXPECT_LE(t.steiner.size(), o.memory_limit / 320 * 3 / 4);
  EXPECT_GT(t.steiner.size(), room / 320 / 2);
}

TEST(Constrained, DuplicateEndsStandForTheirPoint) {
  std::vector<Point> pts = {{0, 0}, {4, -1}, {8, 0}, {4, 1}, {8, 0}};
  const ConstrainedTriangulation t = checked(pts, {0, 4, 2, 4});
  EXPECT_EQ(t.edges, (std::vector<VertexId>{0, 2}));
  EXPECT_EQ(t.duplicates.size(), 1u);
}

// The triangulation with the added points, as one array.
std::vector<Point> with_steiner(const std::vector<Point>& pts, const ConstrainedTriangulation& t) {
  std::vector<Point> all = pts;
  all.insert(all.end(), t.steiner.begin(), t.steiner.end());
  return all;
}

// The edges come sorted as pairs (a, b), a < b, whatever order and direction the segments had:
// around a vertex of many segments (sorted apart from the few) and across vertices.
TEST(Constrained, EdgesSortedAroundAVertexOfManySegments) {
  std::vector<Point> pts;
  std::vector<VertexId> segs;
  for (VertexId k = 0; k < 40; ++k) {  // spokes from a hub (vertex 20) to a circle, listed at random
    const double a = 2 * M_PI * k / 40;
    pts.push_back(k == 20 ? Point{0, 0} : Point{std::cos(a), std::sin(a)});
  }
  for (VertexId k = 0; k < 40; ++k)
    if (const VertexId far = (k * 17) % 40; far != 20)
      segs.push_back(k % 2 ? far : 20), segs.push_back(k % 2 ? 20 : far);
  const ConstrainedTriangulation t = checked(pts, segs);
  std::vector<VertexId> want;
  for (VertexId k = 0; k < 40; ++k)
    if (k != 20) want.push_back(std::min<VertexId>(k, 20)), want.push_back(std::max<VertexId>(k, 20));
  std::vector<std::pair<VertexId, VertexId>> pairs;
  for (std::size_t k = 0; k < want.size(); k += 2) pairs.emplace_back(want[k], want[k + 1]);
  std::sort(pairs.begin(), pairs.end());
  want.clear();
  for (const auto& [a, b] : pairs) want.push_back(a), want.push_back(b);
  EXPECT_EQ(t.edges, want);
}

TEST(Constrained, CrossingSegmentsAreSplitWhereTheyCross) {
  const std::vector<Point> kite = {{0, 0}, {4, -1}, {8, 0}, {4, 1}};
  const ConstrainedTriangulation t = triangulate_constrained(kite, std::vector<VertexId>{0, 2, 1, 3});
  ASSERT_EQ(t.crossings, 1u);
  ASSERT_EQ(t.steiner.size(), 1u);
  EXPECT_EQ(t.steiner[0].x, 4);
  EXPECT_EQ(t.steiner[0].y, 0);
  EXPECT_EQ(t.edges, (std::vector<VertexId>{0, 4, 1, 4, 2, 4, 3, 4}));
  EXPECT_TRUE(check_constrained(with_steiner(kite, t), t.triangles, t.edges).valid);
  EXPECT_THROW(triangulate_constrained(kite, std::vector<VertexId>{0, 2, 1}), InputError);
  EXPECT_THROW(triangulate_constrained(kite, std::vector<VertexId>{0, 9}), InputError);
}

TEST(Constrained, ACrossingIsTheExactOneRoundedToNearest) {
  // The segment from (0, -1) to (2/3, 2) meets y = 0 a third of the way along, at x = 2/9
  // (2/3 as a double, over 3), which no double is: the crossing's x must be the nearest.
  const std::vector<Point> pts = {{0, 0}, {1, 0}, {0, -1}, {2.0 / 3, 2}, {0.5, 5}, {0.5, -5}};
  const ConstrainedTriangulation t = triangulate_constrained(pts, std::vector<VertexId>{0, 1, 2, 3});
  ASSERT_EQ(t.crossings, 1u);
  const long double exact = static_cast<long double>(2.0 / 3) / 3;
  EXPECT_EQ(t.steiner[0].y, 0);
  EXPECT_LE(std::fabs(static_cast<long double>(t.steiner[0].x) - exact),
            std::fabs(static_cast<long double>(std::nextafter(t.steiner[0].x, 1.0)) - exact));
  EXPECT_LE(std::fabs(static_cast<long double>(t.steiner[0].x) - exact),
            std::fabs(static_cast<long double>(std::nextafter(t.steiner[0].x, 0.0)) - exact));
  EXPECT_TRUE(check_constrained(with_steiner(pts, t), t.triangles, t.edges).valid);
}

TEST(Constrained, ACrossingWhoseSegmentSpansZero) {
  // The bisection over doubles runs from -1 to 4 in y: across zero, where the integers that
  // order the doubles change sign.
  const std::vector<Point> pts = {{0, 0}, {10, 0}, {4, -1}, {6, 4}, {5, 8}};
  const ConstrainedTriangulation t = triangulate_constrained(pts, std::vector<VertexId>{0, 1, 2, 3});
  ASSERT_EQ(t.crossings, 1u);
  EXPECT_EQ(t.steiner[0].y, 0);
  EXPECT_EQ(t.steiner[0].x, 4.4);
  EXPECT_TRUE(check_constrained(with_steiner(pts, t), t.triangles, t.edges).valid);
}

TEST(Constrained, ACrossingRoundedOutsideTheHullIsMovedIntoIt) {
  // (6, 6)-(10, 0) meets (10, 1.04e-322)-(0, 10) some 2e-322 left of x = 10, at y = 3.1e-322;
  // rounded to nearest that is (10, 3.1e-322), beyond the hull's edge from (10, 1.04e-322) to
  // (6, 6). The point added is the next double to the left, inside.
  const std::vector<Point> pts = {{0, 0}, {10, 0}, {10, 1.04e-322}, {0, 10}, {6, 6}};
  const ConstrainedTriangulation t = triangulate_constrained(pts, std::vector<VertexId>{4, 1, 2, 3});
  ASSERT_EQ(t.crossings, 1u);
  EXPECT_EQ(t.steiner[0].x, std::nextafter(10.0, 0.0));
  EXPECT_GT(t.steiner[0].y, 2e-322);
  EXPECT_LT(t.steiner[0].y, 4e-322);
  EXPECT_TRUE(check_constrained(with_steiner(pts, t), t.triangles, t.edges).valid);
}

TEST(Constrained, ManyCrossingSegmentsGiveAnExactTriangulation) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 2000, 5);
  std::vector<VertexId> segs;
  for (VertexId k = 0; k + 1 < 300; k += 2) segs.push_back(k), segs.push_back(k + 1);
  const ConstrainedTriangulation t = triangulate_constrained(pts, segs);
  EXPECT_GT(t.crossings, 1000u);
  EXPECT_EQ(t.steiner.size(), t.crossings);
  const CheckResult c = check_constrained(with_steiner(pts, t), t.triangles, t.edges);
  EXPECT_TRUE(c.valid) << c.message;
}

TEST(Constrained, OverlappingAndRepeatedSegmentsMakeOneChain) {
  // Four points on a line, segments 0-2 and 1-3 overlapping on 1-2, and 0-3 over both, twice.
  const std::vector<Point> pts = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {1.5, 1}, {1.5, -1}};
  const ConstrainedTriangulation t = checked(pts, {0, 2, 1, 3, 0, 3, 3, 0});
  EXPECT_EQ(t.edges, (std::vector<VertexId>{0, 1, 1, 2, 2, 3}));
  EXPECT_EQ(t.crossings, 0u);
}

TEST(Constrained, EveryMethodGivesTheSameTriangles) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 20000, 3);
  std::vector<VertexId> segs;
  for (VertexId v = 1; v < 30; ++v) segs.push_back(7), segs.push_back(v * 601);
  Options serial;
  serial.canonical_order = true;
  const ConstrainedTriangulation first = checked(pts, segs, serial);
  for (const Method m : {Method::Partition, Method::Optimistic}) {
    Options o = serial;
    o.method = m;
    o.threads = 2;
    const ConstrainedTriangulation t = triangulate_constrained(pts, segs, o);
    EXPECT_EQ(t.triangles, first.triangles) << to_string(m);
    EXPECT_EQ(t.neighbors, first.neighbors) << to_string(m);
    EXPECT_EQ(t.edges, first.edges) << to_string(m);
  }
}

// Options::neighbors off leaves the result's neighbours empty (the work still has them), and
// on_sorted sees the result's own triangles, refined or not, each once.
TEST(Constrained, NeighboursOffAndOnSortedApplyToTheResult) {
  const Pslg g = generate_coastline(2000, 3, 5);
  Domain d;
  d.convex_hull = false;
  d.holes = g.holes;
  for (const double angle : {0.0, 25.0}) {
    SCOPED_TRACE(angle);
    Quality q;
    q.min_angle = angle;
    Options o;
    o.canonical_order = true;
    const ConstrainedTriangulation full = triangulate_constrained(g.points, g.segments, o, d, q);
    std::vector<VertexId> seen(full.triangles.size(), ~VertexId{0});
    o.neighbors = false;
    o.on_sorted = [&](std::size_t first, std::span<const VertexId> tris) {
      std::copy(tris.begin(), tris.end(), seen.begin() + static_cast<std::ptrdiff_t>(3 * first));
    };
    const ConstrainedTriangulation bare = triangulate_constrained(g.points, g.segments, o, d, q);
    EXPECT_TRUE(bare.neighbors.empty());
    EXPECT_EQ(bare.triangles, full.triangles);
    EXPECT_EQ(seen, full.triangles);
  }
}

// A star-shaped loop of k points round (cx, cy), radii in [r0, r1], as segments appended to
// `segs`; its points appended to `pts`.
void loop(std::vector<Point>& pts, std::vector<VertexId>& segs, double cx, double cy, double r0, double r1, int k,
          detail::Rng& rng) {
  const auto first = static_cast<VertexId>(pts.size());
  for (int i = 0; i < k; ++i) {
    const double a = 2 * 3.14159265358979 * i / k, r = r0 + (r1 - r0) * rng.uniform();
    pts.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
    segs.push_back(first + static_cast<VertexId>(i));
    segs.push_back(first + static_cast<VertexId>((i + 1) % k));
  }
}

// Whether q is inside the loops of `segs`: the parity of their crossings with the ray to +x.
bool inside(const std::vector<Point>& pts, const std::vector<VertexId>& segs, const Point& q) {
  bool in = false;
  for (std::size_t s = 0; s < segs.size(); s += 2) {
    const Point &a = pts[segs[s]], &b = pts[segs[s + 1]];
    if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
  }
  return in;
}

TEST(Constrained, TheExteriorAndHolesAreRemoved) {
  detail::Rng rng(21, 3);
  std::vector<Point> pts;
  std::vector<VertexId> segs;
  loop(pts, segs, 0, 0, 6, 9, 60, rng);  // the outer boundary
  loop(pts, segs, 0.5, 0.2, 1.5, 2.5, 25, rng);  // a hole round (0.5, 0.2)
  loop(pts, segs, -3, 3, 0.5, 1, 12, rng);  // a second hole
  for (int i = 0; i < 3000; ++i) pts.push_back({24 * rng.uniform() - 12, 24 * rng.uniform() - 12});
  const ConstrainedTriangulation whole = checked(pts, segs);
  Domain domain;
  domain.convex_hull = false;
  domain.holes = {{0.5, 0.2}, {-3, 3}, {100, 100}};  // the last one outside: it removes nothing
  const ConstrainedTriangulation t = triangulate_constrained(pts, segs, {}, domain);
  // Exactly the triangles of the whole whose centroid the loops enclose (an odd number of them).
  std::vector<VertexId> expected;
  for (std::size_t k = 0; k < whole.size(); ++k) {
    const Point &a = pts[whole.triangles[3 * k]], &b = pts[whole.triangles[3 * k + 1]],
                &c = pts[whole.triangles[3 * k + 2]];
    if (inside(pts, segs, {(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3}))
      expected.insert(expected.end(), &whole.triangles[3 * k], &whole.triangles[3 * k] + 3);
  }
  ASSERT_GT(expected.size(), 3000u);
  EXPECT_EQ(canonical(t.triangles), canonical(expected));
  EXPECT_TRUE(t.hull.empty());
  // The links: every edge's two triangles name each other, -1 exactly on the domain's boundary,
  // which is made of segments only.
  std::set<std::pair<VertexId, VertexId>> pieces;
  for (std::size_t k = 0; k < t.edges.size(); k += 2) pieces.insert({t.edges[k], t.edges[k + 1]});
  EXPECT_EQ(pieces.size(), segs.size() / 2);  // every segment borders the domain
  for (std::size_t k = 0; k < t.size(); ++k)
    for (int j = 0; j < 3; ++j) {
      const VertexId a = t.triangles[3 * k + (j + 1) % 3], b = t.triangles[3 * k + (j + 2) % 3];
      const std::int32_t n = t.neighbors[3 * k + j];
      if (n < 0) {
        EXPECT_TRUE(pieces.count({std::min(a, b), std::max(a, b)})) << a << "-" << b;
        continue;
      }
      bool back = false;
      for (int i = 0; i < 3; ++i) back |= t.neighbors[3 * std::size_t(n) + i] == static_cast<std::int32_t>(k);
      EXPECT_TRUE(back) << k;
    }
  // The convex hull kept, holes only.
  domain.convex_hull = true;
  const ConstrainedTriangulation holed = triangulate_constrained(pts, segs, {}, domain);
  EXPECT_LT(holed.size(), whole.size());
  EXPECT_GT(holed.size(), t.size());
  EXPECT_EQ(triangulate_constrained(pts, segs, {}, Domain{}).triangles, whole.triangles);
  domain.holes = {{std::nan(""), 0}};
  EXPECT_THROW(triangulate_constrained(pts, segs, {}, domain), InputError);
}

// A seed on a segment or at a vertex empties the triangles on every side of it, whatever the
// walk to it found first: no triangle holds a seed inside or on its boundary (check_mesh). The
// first case is the fuzzer's: a triangle whose long side, the diagonal (0, 0)-(10, 10), runs
// through two corners of a square (4, 4)-(6, 6) and through the hole seed (5, 5).
TEST(Constrained, HoleSeedsOnAnEdgeOrAVertexEmptyEverySide) {
  const std::vector<Point> pts = {{0, 0}, {10, 0}, {10, 10}, {4, 4}, {6, 4}, {6, 6}, {4, 6}};
  const std::vector<VertexId> segs = {0, 1, 1, 2, 2, 0, 3, 4, 4, 5, 5, 6, 6, 3};
  auto holed = [&](bool hull, std::vector<Point> holes) {
    Domain domain;
    domain.convex_hull = hull;
    domain.holes = holes;
    return carved(pts, segs, domain).size();
  };
  const std::size_t all = holed(true, {}), outline = holed(false, {});
  ASSERT_LT(outline, all);
  // (5, 5) on the diagonal: the half square below it goes, the half above was outside already.
  EXPECT_LT(holed(false, {{5, 5}}), outline);
  // With the convex hull kept, both halves go; and a seed at the corner (6, 6) or (4, 4) takes
  // every triangle about it, on both sides of the diagonal and of the square's sides.
  EXPECT_LT(holed(true, {{5, 5}}), holed(true, {{5.5, 4.5}}));
  EXPECT_LT(holed(true, {{6, 6}}), holed(true, {{5, 5}}));
  EXPECT_EQ(holed(true, {{4, 4}}), holed(true, {{6, 6}}));
  // The outline's corner (0, 0) takes the triangles on both sides of the diagonal there, more
  // than a seed beside it does. With (5, 5) too, one triangle is left, (4, 6)-(6, 6)-(10, 10),
  // closed off above the square by segments and the hull; (6, 7) lies in it.
  EXPECT_LT(holed(true, {{0, 0}}), holed(true, {{1, 0.5}}));
  EXPECT_EQ(holed(true, {{0, 0}, {5, 5}}), 1u);
  EXPECT_EQ(holed(true, {{0, 0}, {5, 5}, {6, 7}}), 0u);
}

// A segment 1.9e20 long whose end (10, 10) lies beside a square (4, 4)-(6, 6), a few units off
// its line and beyond that end: check_mesh does not take the square's corners for points on it.
// The hole takes all but the square, and the long segment runs through it whole.
TEST(Constrained, ASquareBesideTheEndOfAVeryLongSegment) {
  const std::vector<Point> pts = {{0, 0}, {1.9e20, 0}, {10, 10}, {4, 4}, {6, 4}, {6, 6}, {4, 6}};
  const std::vector<VertexId> segs = {0, 1, 1, 2, 2, 0, 3, 4, 4, 5, 5, 6, 6, 3};
  Domain domain;
  domain.convex_hull = false;
  domain.holes = {{5, 2}};
  EXPECT_EQ(carved(pts, segs, domain).size(), 2u);  // the square's halves
}

// A fuzzer's graph: the segment from (9.2e18, 9.2e18) to (10, 0) runs outside the domain (its
// outline is open there), past the vertices (0, 10), (6, 6) and the crossing (4, 10), which lie
// 4 to 14 units off its line: within 2^-50 of its far end's coordinates, but points on it there
// are computed to the roundings of coordinates near 10, so check_mesh takes none of them for a
// point on it, and finds the segment a gap through no triangle.
TEST(Constrained, PointsBesideTheSmallEndOfAHugeSegmentAreNotOnIt) {
  const std::vector<Point> pts = {{9223372036427387904.0, 9223372036747855872.0},
                                  {10, 0},
                                  {10, 10},
                                  {0, 10},
                                  {4, 4},
                                  {6, 4},
                                  {6, 6},
                                  {5, 79223372036854775807.0}};
  const std::vector<VertexId> segs = {0, 1, 3, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
  Domain domain;
  domain.convex_hull = false;
  domain.holes = {{0, 5}};
  EXPECT_EQ(carved(pts, segs, domain).crossings, 4u);
}

// A fuzzer's graph: (10, 10^-322) just above (10, 0), and three segments that end at (10, 0)
// cross the one from (10, 10^-322) within 10^-14 of it, at points rounded into the hull; then a
// hole takes most of the square. Near (10, 0) the chains of four segments lie within rounding
// of one another: check_mesh finds the one from (10, 0) to (4, 4) by going back from steps onto
// the others' chains and from gaps that pass through triangles.
TEST(Constrained, ChainsWithinRoundingOfOneAnotherBesideAnEndIntoAHole) {
  const std::vector<Point> pts = beside_ten({0, 0}, 104.9e-324, {4, 4});
  for (const bool hull : {true, false}) {
    SCOPED_TRACE(hull);
    Domain domain;
    domain.convex_hull = hull;
    domain.holes = {{5, 5}};
    EXPECT_EQ(carved(pts, kBesideTen, domain).crossings, 4u);
  }
}

// The same square with (3, 4) in place of (4, 4): the pieces of the segments from (10, 0) and
// (10, 10^-322) or (10, 10^-160), their ends rounded, cross again at each crossing added, each
// nearer the last: nested, a cascade that ran the stack out; along one segment, points added
// without end on the column of doubles left of x = 10. A crossing with a piece that ends at a
// point added for the segment being inserted (which it meets only by rounding) goes to the
// nearest end of the two pieces instead, and the result is a valid constrained triangulation
// of the graph so bent.
TEST(Constrained, CrossingsThatCascadeEnd) {
  for (const double above : {104.9e-324, 104.9e-162})
    for (const bool forward : {true, false})
      for (const bool hull : {true, false}) {
        SCOPED_TRACE(testing::Message() << above << (forward ? " forward" : " backward") << (hull ? " hull" : ""));
        const std::vector<Point> pts = beside_ten({0, 0}, above, {3, 4});
        std::vector<VertexId> segs = kBesideTen;
        if (!forward) std::swap(segs[14], segs[15]);
        Domain domain;
        domain.convex_hull = hull;
        domain.holes = {{5, 5}};
        EXPECT_LT(carved(pts, segs, domain).crossings, 10u);
      }
}

TEST(Constrained, ACrossingInASliverOfTheHullGoesToACornerAtHand) {
  // (6, 6)-(10, 0) crosses (10, 1e-322)-(0, 10) 2e-322 left of x = 10, where the hull is
  // 1e-322 wide: the crossing and the doubles next to it lie outside, so it goes to the
  // nearest corner, (10, 1e-322). Without the hull only the sliver between (6, 4)-(10, 0) and
  // the segment above it and the triangle that (6, 4)-(6, 6) closes beyond it are left.
  const std::vector<Point> pts = beside_ten({0, 1}, 104.9e-324, {3, 4});
  Domain domain;
  domain.holes = {{5, 5}};
  const ConstrainedTriangulation t = carved(pts, kBesideTen, domain);
  EXPECT_TRUE(t.steiner.empty());
  EXPECT_EQ(canonical(t.triangles), canonical(std::vector<VertexId>{1, 2, 5, 2, 6, 5}));
  domain.convex_hull = true;
  EXPECT_TRUE(carved(pts, kBesideTen, domain).steiner.empty());
}

}  // namespace
}  // namespace ridt::test
