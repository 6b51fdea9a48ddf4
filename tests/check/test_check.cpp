// The validator must reject what is wrong, each for the right reason.
#include <gtest/gtest.h>

#include <sys/mman.h>

#include <cmath>
#include <string>
#include <vector>

#include "predicates/predicates.hpp"
#include "ridt/check.hpp"
#include "ridt/furthest.hpp"
#include "ridt/generate.hpp"

namespace ridt {
namespace {

// A convex quadrilateral whose only Delaunay diagonal is 1-3: the square's far corner pushed
// out to (2.5, 2.5), outside the circle through the other three.
const std::vector<Point> kQuad = {{0, 0}, {2, 0}, {2.5, 2.5}, {0, 2}};

// A kite whose long diagonal 0-2 is not Delaunay (the short one 1-3 is).
const std::vector<Point> kKite = {{0, 0}, {4, -1}, {8, 0}, {4, 1}};
const std::vector<VertexId> kLongDiagonal = {0, 1, 2, 0, 2, 3};
const std::vector<VertexId> kShortDiagonal = {0, 1, 3, 1, 2, 3};

TEST(CheckConstrained, AcceptsASegmentThatIsNotDelaunay) {
  const std::vector<VertexId> segment = {0, 2};
  EXPECT_FALSE(check(kKite, kLongDiagonal).valid);
  const CheckResult r = check_constrained(kKite, kLongDiagonal, segment);
  EXPECT_TRUE(r.valid) << r.message;
  EXPECT_NE(r.message.find("constrained Delaunay with 1 segments"), std::string::npos) << r.message;
}

TEST(CheckConstrained, RejectsAMissingSegment) {
  const std::vector<VertexId> segment = {2, 0};  // either direction
  const CheckResult r = check_constrained(kKite, kShortDiagonal, segment);
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.message.find("segment 0 (2-0) is not a union of edges"), std::string::npos) << r.message;
}

TEST(CheckConstrained, OnlyTheSegmentsEdgesMayBeNonDelaunay) {
  // Segment 1-3 is the Delaunay diagonal itself; the long diagonal stays wrong.
  const std::vector<VertexId> segment = {1, 3};
  EXPECT_TRUE(check_constrained(kKite, kShortDiagonal, segment).valid);
  EXPECT_FALSE(check_constrained(kKite, kLongDiagonal, segment).valid);
  EXPECT_TRUE(check_constrained(kKite, kShortDiagonal, {}).valid);
}

TEST(CheckConstrained, ASegmentIsSplitAtThePointsOnIt) {
  // Vertex 1 lies on segment 0-2: the segment is the edges 0-1 and 1-2. Vertices 3 and 4
  // above and below: its Delaunay triangulation has those edges.
  const std::vector<Point> pts = {{0, 0}, {1, 0}, {2, 0}, {1, 1}, {1, -1}};
  const std::vector<VertexId> tris = {0, 1, 3, 1, 2, 3, 0, 4, 1, 1, 4, 2};
  ASSERT_TRUE(check(pts, tris).valid);
  const std::vector<VertexId> through = {0, 2}, vertical = {3, 4}, hull = {0, 3};
  EXPECT_TRUE(check_constrained(pts, tris, through).valid);
  EXPECT_TRUE(check_constrained(pts, tris, vertical).valid);  // 3-1 and 1-4
  EXPECT_TRUE(check_constrained(pts, tris, hull).valid);
}

TEST(CheckConstrained, EndsStandForTheirGroupOfEqualPoints) {
  std::vector<Point> pts = kKite;
  pts.push_back(pts[2]);  // point 4 equals point 2, which is the vertex
  const std::vector<VertexId> segment = {0, 4};
  EXPECT_TRUE(check_constrained(pts, kLongDiagonal, segment).valid);
  EXPECT_FALSE(check_constrained(pts, kShortDiagonal, segment).valid);
  const std::vector<VertexId> nothing = {2, 4};  // its ends coincide
  EXPECT_TRUE(check_constrained(pts, kShortDiagonal, nothing).valid);
}

TEST(CheckConstrained, RejectsBadSegmentLists) {
  const std::vector<VertexId> odd = {0, 2, 1};
  EXPECT_NE(check_constrained(kKite, kLongDiagonal, odd).message.find("not a multiple of 2"), std::string::npos);
  const std::vector<VertexId> outside = {0, 7};
  const CheckResult r = check_constrained(kKite, kLongDiagonal, outside);
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.message.find("segment 0 refers to a point that is not one of the 4"), std::string::npos) << r.message;
}

TEST(CheckConstrained, CrossingSegmentsCannotBothBeEdges) {
  const std::vector<VertexId> both = {0, 2, 1, 3};
  EXPECT_FALSE(check_constrained(kKite, kLongDiagonal, both).valid);
  EXPECT_FALSE(check_constrained(kKite, kShortDiagonal, both).valid);
}

TEST(Check, AcceptsTheDelaunayDiagonal) {
  // (2.5, 2.5) lies outside the circle through (0,0), (2,0), (0,2): diagonal 1-3 is Delaunay.
  const CheckResult r = check(kQuad, std::vector<VertexId>{0, 1, 3, 1, 2, 3});
  EXPECT_TRUE(r.valid) << r.message;
}

TEST(Check, RejectsTheOtherDiagonal) {
  const CheckResult r = check(kQuad, std::vector<VertexId>{0, 1, 2, 0, 2, 3});
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.message.find("not locally Delaunay"), std::string::npos) << r.message;
}

TEST(Check, RejectsClockwiseTriangles) {
  const CheckResult r = check(kQuad, std::vector<VertexId>{0, 3, 1, 1, 3, 2});
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.message.find("counter-clockwise"), std::string::npos) << r.message;
}

TEST(Check, RejectsAMissingTriangle) {
  const CheckResult r = check(kQuad, std::vector<VertexId>{0, 1, 3});
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.message.find("not a vertex"), std::string::npos) << r.message;
}

TEST(Check, RejectsAMissingHullEdge) {
  // Five points; leaving out the triangle on hull edge 0-1 keeps every point a vertex.
  const std::vector<Point> pts = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 1}};
  const CheckResult full = check(pts, std::vector<VertexId>{0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4});
  ASSERT_TRUE(full.valid) << full.message;
  const CheckResult r = check(pts, std::vector<VertexId>{1, 2, 4, 2, 3, 4, 3, 0, 4});
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.message.find("hull edge"), std::string::npos) << r.message;
}

TEST(Check, RejectsAnEdgeUsedTwice) {
  const CheckResult r = check(kQuad, std::vector<VertexId>{0, 1, 3, 0, 1, 3, 1, 2, 3});
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.message.find("used by two"), std::string::npos) << r.message;
}

TEST(Check, RejectsIndicesOutOfRange) {
  // The Delaunay triangulation with one index pointing past the points.
  const CheckResult r = check(kQuad, std::vector<VertexId>{0, 1, 3, 1, 2, 7});
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.message.find("out of range"), std::string::npos) << r.message;
}

TEST(Check, RejectsADegenerateTriangle) {
  // (0, 0), (1, 0), (2, 0) on a line: a flat triangle among otherwise valid ones.
  const std::vector<Point> pts = {{0, 0}, {2, 0}, {1, 0}, {1, 1}};
  EXPECT_TRUE(check(pts, std::vector<VertexId>{0, 2, 3, 2, 1, 3}).valid);
  const CheckResult r = check(pts, std::vector<VertexId>{0, 2, 3, 2, 1, 3, 0, 2, 1});
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.message.find("degenerate"), std::string::npos) << r.message;
}

TEST(Check, EmptyIsValidOnlyForDegenerateSets) {
  EXPECT_TRUE(check(std::vector<Point>{{0, 0}, {1, 1}, {2, 2}}, {}).valid);
  EXPECT_TRUE(check(std::vector<Point>{{0, 0}, {0, 0}}, {}).valid);
  EXPECT_FALSE(check(kQuad, {}).valid);
}

TEST(Check, AcceptsEitherDiagonalOfACocircularSquare) {
  const std::vector<Point> sq = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_TRUE(check(sq, std::vector<VertexId>{0, 1, 2, 0, 2, 3}).valid);
  EXPECT_TRUE(check(sq, std::vector<VertexId>{0, 1, 3, 1, 2, 3}).valid);
}

TEST(Check, DuplicatesMayBeUnusedButNotBothUsed) {
  const std::vector<Point> pts = {{0, 0}, {1, 0}, {0, 1}, {1, 0}};
  EXPECT_TRUE(check(pts, std::vector<VertexId>{0, 1, 2}).valid);
  EXPECT_TRUE(check(pts, std::vector<VertexId>{0, 3, 2}).valid);
  // A square around its centre, given twice (4 and 5): each copy a vertex of two of the four
  // triangles, which otherwise fit edge to edge.
  const std::vector<Point> square = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}, {1, 1}};
  EXPECT_TRUE(check(square, std::vector<VertexId>{0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4}).valid);
  const CheckResult r = check(square, std::vector<VertexId>{0, 1, 4, 1, 2, 4, 2, 3, 5, 3, 0, 5});
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.message.find("appears as 2 vertices"), std::string::npos) << r.message;
}

TEST(Check, CollinearHullPointsMustBeVertices) {
  const std::vector<Point> pts = {{0, 0}, {1, 0}, {2, 0}, {1, 1}};
  EXPECT_TRUE(check(pts, std::vector<VertexId>{0, 1, 3, 1, 2, 3}).valid);
  EXPECT_FALSE(check(pts, std::vector<VertexId>{0, 2, 3}).valid);
}

// More triangles than the edge table's 32-bit counters hold: refused before any is read. The
// list is a reserved, never touched range of address space (some 17 GB), so no memory is used.
TEST(Check, RefusesMoreTrianglesThanItsCountersHold) {
  const std::size_t ids = 3 * (kCheckMaxTriangles + 1);
  void* range = ::mmap(nullptr, ids * sizeof(VertexId), PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  ASSERT_NE(range, MAP_FAILED);
  const std::span<const VertexId> tris(static_cast<const VertexId*>(range), ids);
  try {
    check(kQuad, tris);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "1431655766 triangles are more than the validator takes (at most 1431655765)");
  }
  ::munmap(range, ids * sizeof(VertexId));
}

}  // namespace
}  // namespace ridt

namespace ridt {
namespace {

TEST(FurthestSite, ValidOnEveryDistributionAndOnACircle) {
  for (const Distribution d :
       {Distribution::Uniform, Distribution::Normal, Distribution::Grid, Distribution::Clusters}) {
    const std::vector<Point> pts = generate(d, 3000, 5);
    const Triangulation f = triangulate_furthest_site(pts);
    const CheckResult r = check_furthest_site(pts, f.triangles);
    EXPECT_TRUE(r.valid) << r.message;
    EXPECT_EQ(f.size(), f.hull.size() - 2);
    // Every circle holds every point, checked here point by point.
    for (std::size_t t = 0; t < f.size(); ++t)
      for (const Point& p : pts)
        ASSERT_GE(
            detail::incircle(pts[f.triangles[3 * t]], pts[f.triangles[3 * t + 1]], pts[f.triangles[3 * t + 2]], p), 0);
  }
  // Cocircular corners (a regular polygon, rounded): any triangulation of them qualifies.
  std::vector<Point> circle;
  for (int k = 0; k < 64; ++k) circle.push_back({std::cos(k * 0.0981747704), std::sin(k * 0.0981747704)});
  circle.push_back({0.1, 0.2});
  const Triangulation f = triangulate_furthest_site(circle);
  EXPECT_TRUE(check_furthest_site(circle, f.triangles).valid) << check_furthest_site(circle, f.triangles).message;
}

TEST(FurthestSite, DegenerateInputAndTheValidatorsRefusals) {
  const std::vector<Point> line = {{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  const Triangulation empty = triangulate_furthest_site(line);
  EXPECT_EQ(empty.size(), 0u);
  EXPECT_FALSE(empty.warning.empty());
  EXPECT_TRUE(check_furthest_site(line, empty.triangles).valid);
  const std::vector<Point> pts = {{0, 0}, {0, 1}, {1, 0}, {0.5, 0.5}, {1.1, 1.1}, {1, 0}};
  const Triangulation f = triangulate_furthest_site(pts);
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f.duplicates.size(), 1u);
  EXPECT_TRUE(check_furthest_site(pts, f.triangles).valid);
  // The nearest-site triangulation, the other diagonal, a missing triangle: each refused.
  EXPECT_FALSE(check_furthest_site(pts, triangulate(pts).triangles).valid);
  const std::vector<VertexId> other = {0, 2, 1, 2, 4, 1};
  EXPECT_FALSE(check_furthest_site(pts, other).valid);
  EXPECT_FALSE(check_furthest_site(pts, std::span(f.triangles).first(3)).valid);
  EXPECT_FALSE(check(pts, f.triangles).valid);
}

}  // namespace
}  // namespace ridt

namespace ridt {
namespace {

// check_in_passes over the triangles in chunks of `chunk` triangles, with room for `budget`
// bytes of sides a pass.
CheckResult in_passes(std::span<const Point> pts, std::span<const VertexId> tris, std::size_t chunk, std::size_t budget,
                      unsigned threads) {
  std::size_t calls = 0;
  const TriangleFeed feed = [&](const TriangleSink& sink) {
    ++calls;
    for (std::size_t k = 0; k < tris.size(); k += 3 * chunk)
      sink(tris.subspan(k, std::min(3 * chunk, tris.size() - k)));
  };
  const CheckResult r = check_in_passes(pts, feed, budget, threads);
  // A pass a vertex at most, where there is room for one file only.
  EXPECT_LE(calls, pts.size() + 1);
  return r;
}

// The verdict in passes is check()'s, whatever the chunks, the room and the threads; where
// valid, the same words. Returns check()'s.
CheckResult same_verdict(std::span<const Point> pts, std::span<const VertexId> tris) {
  const CheckResult whole = check(pts, tris);
  struct Way {
    std::size_t chunk, budget;
    unsigned threads;
  };
  for (const Way w : {Way{1, 5000, 3}, Way{7, 1, 1}, Way{7, 5000, 1}, Way{1 << 20, 1 << 30, 3}}) {
    const CheckResult r = in_passes(pts, tris, w.chunk, w.budget, w.threads);
    EXPECT_EQ(r.valid, whole.valid) << "chunk " << w.chunk << ", room " << w.budget << ": " << r.message << " / "
                                    << whole.message;
    if (whole.valid) {
      EXPECT_EQ(r.message, whole.message);
    }
  }
  return whole;
}

TEST(CheckInPasses, TheVerdictsOfTheSmallCases) {
  EXPECT_TRUE(same_verdict(kQuad, std::vector<VertexId>{0, 1, 3, 1, 2, 3}).valid);
  EXPECT_FALSE(same_verdict(kQuad, std::vector<VertexId>{0, 1, 2, 0, 2, 3}).valid);  // the other diagonal
  EXPECT_FALSE(same_verdict(kQuad, std::vector<VertexId>{0, 3, 1, 1, 3, 2}).valid);  // clockwise
  EXPECT_FALSE(same_verdict(kQuad, std::vector<VertexId>{0, 1, 3}).valid);  // a point left out
  EXPECT_FALSE(same_verdict(kQuad, std::vector<VertexId>{0, 1, 3, 0, 1, 3, 1, 2, 3}).valid);  // an edge twice
  EXPECT_FALSE(same_verdict(kQuad, std::vector<VertexId>{0, 1, 3, 1, 2, 7}).valid);  // out of range
  EXPECT_FALSE(same_verdict(kQuad, std::vector<VertexId>{0, 1, 3, 1, 2}).valid);  // not whole triangles
  EXPECT_FALSE(same_verdict(kQuad, {}).valid);
  const std::vector<Point> five = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 1}};
  EXPECT_TRUE(same_verdict(five, std::vector<VertexId>{0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4}).valid);
  EXPECT_FALSE(same_verdict(five, std::vector<VertexId>{1, 2, 4, 2, 3, 4, 3, 0, 4}).valid);  // a hull edge missing
  EXPECT_FALSE(same_verdict(five, std::vector<VertexId>{0, 1, 2, 0, 2, 3}).valid);  // an inner point left out
  const std::vector<Point> flat = {{0, 0}, {2, 0}, {1, 0}, {1, 1}};
  EXPECT_TRUE(same_verdict(flat, std::vector<VertexId>{0, 2, 3, 2, 1, 3}).valid);
  EXPECT_FALSE(same_verdict(flat, std::vector<VertexId>{0, 2, 3, 2, 1, 3, 0, 2, 1}).valid);  // a flat triangle
  EXPECT_FALSE(same_verdict(flat, std::vector<VertexId>{0, 1, 3}).valid);  // a point on the hull left out
  EXPECT_TRUE(same_verdict(std::vector<Point>{{0, 0}, {1, 1}, {2, 2}}, {}).valid);
  EXPECT_FALSE(same_verdict(std::vector<Point>{{0, 0}, {1, 1}, {2, 2}}, std::vector<VertexId>{0, 1, 2}).valid);
  const std::vector<Point> sq = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_TRUE(same_verdict(sq, std::vector<VertexId>{0, 1, 2, 0, 2, 3}).valid);
  EXPECT_TRUE(same_verdict(sq, std::vector<VertexId>{0, 1, 3, 1, 2, 3}).valid);
  const std::vector<Point> twice = {{0, 0}, {1, 0}, {0, 1}, {1, 0}};
  EXPECT_TRUE(same_verdict(twice, std::vector<VertexId>{0, 1, 2}).valid);
  EXPECT_TRUE(same_verdict(twice, std::vector<VertexId>{0, 3, 2}).valid);
  // A centre given twice, each copy the corner of two of the four triangles; and a point given
  // twice and also left out, on the hull and inside.
  const std::vector<Point> square = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}, {1, 1}};
  EXPECT_TRUE(same_verdict(square, std::vector<VertexId>{0, 1, 5, 1, 2, 5, 2, 3, 5, 3, 0, 5}).valid);
  EXPECT_FALSE(same_verdict(square, std::vector<VertexId>{0, 1, 4, 1, 2, 4, 2, 3, 5, 3, 0, 5}).valid);
  EXPECT_FALSE(same_verdict(square, std::vector<VertexId>{0, 1, 2, 0, 2, 3}).valid);
}

// Every distribution, with duplicates and at tiny and huge scales: valid, and each kind of
// damage found.
TEST(CheckInPasses, TheVerdictsOnTriangulationsAndTheirDamage) {
  for (const Distribution d :
       {Distribution::Uniform, Distribution::Normal, Distribution::Grid, Distribution::Clusters}) {
    for (const double scale : {1.0, 0x1p-900, 0x1p+900}) {
      std::vector<Point> pts = generate(d, 2000, 3);
      for (std::size_t i = 0; i < 100; ++i) pts.push_back(pts[i * 7]);  // duplicates
      for (Point& p : pts) p = {p.x * scale, p.y * scale};
      const Triangulation t = triangulate(pts);
      ASSERT_TRUE(same_verdict(pts, t.triangles).valid);
      // An interior edge flipped (its quadrilateral convex): valid only where cocircular.
      bool flipped = false;
      for (std::size_t k = 0; k < t.size() && !flipped; ++k)
        for (int i = 0; i < 3 && !flipped; ++i) {
          const std::int32_t u = t.neighbors[3 * k + i];
          if (u < 0) continue;
          const VertexId a = t.triangles[3 * k + i], b = t.triangles[3 * k + (i + 1) % 3],
                         c = t.triangles[3 * k + (i + 2) % 3];
          VertexId e = 0;
          for (int j = 0; j < 3; ++j)
            if (const VertexId w = t.triangles[3 * static_cast<std::size_t>(u) + j]; w != b && w != c) e = w;
          if (detail::orient2d(pts[a], pts[b], pts[e]) <= 0 || detail::orient2d(pts[a], pts[e], pts[c]) <= 0) continue;
          std::vector<VertexId> other = t.triangles;
          const VertexId first[3] = {a, b, e}, second[3] = {a, e, c};
          std::copy_n(first, 3, &other[3 * k]);
          std::copy_n(second, 3, &other[3 * static_cast<std::size_t>(u)]);
          EXPECT_EQ(same_verdict(pts, other).valid, detail::incircle_exact(pts[a], pts[b], pts[c], pts[e]) == 0);
          flipped = true;
        }
      EXPECT_TRUE(flipped);
      std::vector<VertexId> fewer(t.triangles.begin() + 3, t.triangles.end());
      EXPECT_FALSE(same_verdict(pts, fewer).valid);
      std::vector<VertexId> more = t.triangles;
      more.insert(more.end(), t.triangles.end() - 3, t.triangles.end());
      EXPECT_FALSE(same_verdict(pts, more).valid);
    }
  }
}

}  // namespace
}  // namespace ridt
