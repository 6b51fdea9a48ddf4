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
