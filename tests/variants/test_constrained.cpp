// triangulate_constrained: every result through the exact validator of constrained
// triangulations (check_constrained); the kite, segments through collinear points, grids,
// duplicates, crossing segments refused, every method giving the same triangles.
#include <gtest/gtest.h>

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

TEST(Constrained, DuplicateEndsStandForTheirPoint) {
  std::vector<Point> pts = {{0, 0}, {4, -1}, {8, 0}, {4, 1}, {8, 0}};
  const ConstrainedTriangulation t = checked(pts, {0, 4, 2, 4});
  EXPECT_EQ(t.edges, (std::vector<VertexId>{0, 2}));
  EXPECT_EQ(t.duplicates.size(), 1u);
}

TEST(Constrained, CrossingSegmentsAreRefused) {
  const std::vector<Point> kite = {{0, 0}, {4, -1}, {8, 0}, {4, 1}};
  try {
    triangulate_constrained(kite, std::vector<VertexId>{0, 2, 1, 3});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("segments 0 and 1 cross"), std::string::npos) << e.what();
  }
  EXPECT_THROW(triangulate_constrained(kite, std::vector<VertexId>{0, 2, 1}), InputError);
  EXPECT_THROW(triangulate_constrained(kite, std::vector<VertexId>{0, 9}), InputError);
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

}  // namespace
}  // namespace ridt::test
