// check_mesh on meshes given without their segment edges (Triangle's files, or ridt mesh's
// without OUT.edge): it finds the edges along the segments, and then passes every valid mesh,
// interior segments, hole boundaries, open polylines and crossings included, and still fails
// what is wrong.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ridt/check.hpp"
#include "ridt/constrained.hpp"

namespace ridt {
namespace {

struct Graph {
  std::vector<Point> points;
  std::vector<VertexId> segments;
  std::vector<Point> holes;
};

// The 4 x 4 square with one segment inside it, from (1, 2) to (3, 2).
const Graph kInteriorSegment = {{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 2}, {3, 2}}, {0, 1, 1, 2, 2, 3, 3, 0, 4, 5}, {}};

// The square with a triangular hole.
const Graph kRing = {
    {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 1}, {2, 3}}, {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 4}, {{2, 1.6}}};

// Two crossing diagonals, an open polyline above them and one from the boundary inwards.
const Graph kCrossingsAndPolylines = {{{0, 0},
                                       {4, 0},
                                       {4, 4},
                                       {0, 4},
                                       {0.5, 0.5},
                                       {3.5, 3.5},
                                       {0.5, 3.5},
                                       {3.5, 0.5},
                                       {1, 3.8},
                                       {2, 3.6},
                                       {3, 3.8},
                                       {4, 2},
                                       {3.2, 2}},
                                      {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 6, 7, 8, 9, 9, 10, 11, 12},
                                      {}};

struct Mesh {
  std::vector<Point> all;  // the input's points, then those added
  ConstrainedTriangulation t;
};

Mesh mesh(const Graph& g, double min_angle = 0) {
  Domain d;
  d.holes = g.holes;
  Quality q;
  q.min_angle = min_angle;
  Mesh m{g.points, triangulate_constrained(g.points, g.segments, {}, d, q)};
  m.all.insert(m.all.end(), m.t.steiner.begin(), m.t.steiner.end());
  return m;
}

CheckResult without_edges(const Graph& g, std::span<const Point> all, std::span<const VertexId> triangles,
                          double min_angle = 0) {
  MeshSpec spec;
  spec.segments = g.segments;
  spec.input_points = g.points.size();
  spec.holes = g.holes;
  spec.min_angle = min_angle;
  return check_mesh(all, triangles, spec);
}

TEST(CheckMesh, FindsTheEdgesOfAnInteriorSegment) {
  const Mesh m = mesh(kInteriorSegment);
  EXPECT_EQ(m.t.size(), 6u);
  const CheckResult r = without_edges(kInteriorSegment, m.all, m.t.triangles);
  EXPECT_TRUE(r.valid) << r.message;
  EXPECT_NE(r.message.find("5 segments as chains of 5 edges (found along them)"), std::string::npos) << r.message;
}

TEST(CheckMesh, FindsTheEdgesOfAHolesBoundary) {
  for (const double angle : {0.0, 30.0}) {
    const Mesh m = mesh(kRing, angle);
    const CheckResult r = without_edges(kRing, m.all, m.t.triangles, angle);
    EXPECT_TRUE(r.valid) << angle << ": " << r.message;
  }
}

TEST(CheckMesh, FindsTheEdgesOfCrossingsAndOpenPolylines) {
  for (const double angle : {0.0, 25.0}) {
    const Mesh m = mesh(kCrossingsAndPolylines, angle);
    EXPECT_EQ(m.t.crossings, 1u);
    const CheckResult r = without_edges(kCrossingsAndPolylines, m.all, m.t.triangles, angle);
    EXPECT_TRUE(r.valid) << angle << ": " << r.message;
  }
}

TEST(CheckMesh, ASegmentFromADuplicatePoint) {
  Graph g = kInteriorSegment;
  g.points.push_back({1, 2});  // 6, equal to 4: the mesh keeps 4, and 6 is no vertex
  g.segments[8] = 6;  // the inner segment 6-5, from the twin
  const Mesh m = mesh(g);
  const CheckResult r = without_edges(g, m.all, m.t.triangles);
  EXPECT_TRUE(r.valid) << r.message;
}

TEST(CheckMesh, StillFailsASegmentThatIsNoChain) {
  // The Delaunay triangulation of the square with (2, 1.9) and (2, 2.1) beside the segment:
  // the segment from (1, 2) to (3, 2) crosses the edge between them.
  Graph g = kInteriorSegment;
  g.points.insert(g.points.end(), {{2, 1.9}, {2, 2.1}});
  const Triangulation t = triangulate(g.points);
  const CheckResult r = without_edges(g, g.points, t.triangles);
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.message.find("segment 4 (4-5)"), std::string::npos) << r.message;
}

TEST(CheckMesh, StillFailsAFilledHole) {
  Graph filled = kRing;
  filled.holes.clear();
  const Mesh m = mesh(filled);
  const CheckResult r = without_edges(kRing, m.all, m.t.triangles);
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.message.find("holds the hole seed"), std::string::npos) << r.message;
}

TEST(CheckMesh, StillFailsAMissingPieceOfTheBoundary) {
  // The ring without its triangle at (0, 0): the boundary there is no segment's and not the hull.
  const Mesh m = mesh(kRing);
  std::vector<VertexId> cut;
  for (std::size_t k = 0; k < m.t.size(); ++k) {
    const VertexId* v = &m.t.triangles[3 * k];
    if (v[0] != 0 && v[1] != 0 && v[2] != 0) cut.insert(cut.end(), v, v + 3);
  }
  ASSERT_LT(cut.size(), m.t.triangles.size());
  const CheckResult r = without_edges(kRing, m.all, cut);
  EXPECT_FALSE(r.valid) << r.message;
}

}  // namespace
}  // namespace ridt
