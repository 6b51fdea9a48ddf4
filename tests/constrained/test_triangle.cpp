// ridt::triangle: Triangle's switches parsed once, and its rules (markers, attributes, every
// edge, the dual) from each piece's own segment, which the constrained triangulation knows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "ridt/check.hpp"
#include "ridt/constrained.hpp"
#include "ridt/generate.hpp"
#include "ridt/predicates.hpp"
#include "ridt/triangle.hpp"

namespace ridt::test {
namespace {

// Whether point p lies on segment a-b (exactly, or, for a point added where segments cross, within
// a rounding of it: a crossing is rounded to the nearest doubles).
bool on_segment(const Point& a, const Point& b, const Point& p) {
  const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
  const double along = ((p.x - a.x) * dx + (p.y - a.y) * dy) / length2;
  const double cross = dx * (p.y - a.y) - dy * (p.x - a.x);
  return along >= -1e-12 && along <= 1 + 1e-12 && (orientation(a, b, p) == 0 || std::fabs(cross) <= 1e-9 * length2);
}

TEST(TriangleSwitches, EachLetterAndNumber) {
  const triangle::Switches w = triangle::parse_switches("-pq28.5a0.25AcYeno2zBjCgvQViFlXI");
  EXPECT_TRUE(w.pslg && w.quality && w.attributes && w.convex_hull && w.no_boundary_steiner && w.all_edges);
  EXPECT_TRUE(w.neighbors && w.second_order && w.zero_based && w.no_markers && w.jettison && w.check && w.off);
  EXPECT_TRUE(w.voronoi);
  EXPECT_FALSE(w.no_segment_steiner || w.refine || w.region_areas || w.limit_steiner);
  EXPECT_EQ(w.min_angle, 28.5);
  EXPECT_EQ(w.max_area, 0.25);
  const Quality q = w.quality_bounds();
  EXPECT_EQ(q.min_angle, 28.5);
  EXPECT_EQ(q.max_area, 0.25);
  EXPECT_FALSE(q.split_boundary);
  EXPECT_TRUE(q.split_segments);
  // q alone is 20 degrees; "q30e" is q30 and e, not an exponent; a alone the regions' bounds.
  EXPECT_EQ(triangle::parse_switches("pq").min_angle, 20);
  const triangle::Switches e = triangle::parse_switches("pq30e");
  EXPECT_EQ(e.min_angle, 30);
  EXPECT_TRUE(e.all_edges);
  EXPECT_EQ(triangle::parse_switches("pq1e1").min_angle, 10);
  EXPECT_TRUE(triangle::parse_switches("pa").region_areas);
  // YY keeps every segment whole; S0 asks no refinement at all; rc is taken (Triangle takes it).
  const triangle::Switches yy = triangle::parse_switches("pqYY");
  EXPECT_TRUE(yy.no_boundary_steiner && yy.no_segment_steiner);
  EXPECT_FALSE(triangle::parse_switches("pq30a1S0").quality_bounds().enabled());
  EXPECT_EQ(triangle::parse_switches("pq30S17").quality_bounds().max_steiner, 17u);
  EXPECT_TRUE(triangle::parse_switches("rc").refine);
  for (const char* bad : {"pu", "ps", "po3", "pq30S", "pS1.5", "pa0", "pa-1", "pq1e999", "pqx", "pDYY"})
    EXPECT_THROW(triangle::parse_switches(bad), InputError) << bad;
}

// A square with a hole, one segment through it along the diagonal (it passes through two of the
// hole's corners), markers and attributes given.
triangle::Input holed_square() {
  triangle::Input in;
  in.vertices = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {4, 4}, {6, 4}, {6, 6}, {4, 6}, {2, 2}, {8, 8}};
  in.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4, 8, 9};
  in.segment_markers = {5, 0, 2, 0, 0, 3, 0, 0, 9};
  in.holes = {{5, 5}};
  in.attribute_count = 1;
  for (const Point& p : in.vertices) in.vertex_attributes.push_back(2 * p.x + 3 * p.y + 1);
  return in;
}

TEST(Triangle, EachPieceNamesItsOwnSegment) {
  // Two crossing segments, one overlapping another, one through a vertex; refined: every piece
  // lies on the segment it names, and every segment is covered by the pieces that name it.
  triangle::Input in;
  in.vertices = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {1, 1}, {9, 9}, {1, 9}, {9, 1}, {5, 2}, {5, 8}};
  in.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 6, 7, 8, 9, 0, 1};
  for (const char* switches : {"p", "pq30a0.5", "pcD"}) {
    const triangle::Output out = triangle::triangulate(in, switches);
    ASSERT_EQ(out.segment_of.size(), out.segments.size() / 2);
    std::vector<double> covered(in.segments.size() / 2, 0);
    for (std::size_t k = 0; k < out.segment_of.size(); ++k) {
      const std::int32_t s = out.segment_of[k];
      ASSERT_GE(s, 0) << switches << ": piece " << k;  // every fixed edge here is on a segment
      const Point &a = in.vertices[in.segments[2 * s]], &b = in.vertices[in.segments[2 * s + 1]];
      const Point &p = out.vertices[out.segments[2 * k]], &q = out.vertices[out.segments[2 * k + 1]];
      EXPECT_TRUE(on_segment(a, b, p) && on_segment(a, b, q)) << switches << ": piece " << k << " of segment " << s;
      covered[static_cast<std::size_t>(s)] += std::hypot(q.x - p.x, q.y - p.y);
    }
    for (std::size_t s = 0; s < covered.size(); ++s) {
      const Point &a = in.vertices[in.segments[2 * s]], &b = in.vertices[in.segments[2 * s + 1]];
      if (s == 0) {  // given twice: its pieces name the later one
        EXPECT_EQ(covered[s], 0) << switches;
        continue;
      }
      EXPECT_NEAR(covered[s], std::hypot(b.x - a.x, b.y - a.y), 1e-9) << switches << ": segment " << s;
    }
    EXPECT_EQ(out.crossings, 1u);  // (5, 5), where all three inner segments meet
  }
}

TEST(Triangle, MarkersFollowEachPiecesSegment) {
  // The diagonal's stretch in the hole is gone, but its piece beyond it still carries its marker
  // (a walk along the segment from its first end stopped at the hole), and so do its ends.
  const triangle::Output out = triangle::triangulate(holed_square(), "p");
  ASSERT_EQ(out.segments.size() / 2, out.segment_markers.size());
  for (std::size_t k = 0; k < out.segment_markers.size(); ++k) {
    const std::int32_t s = out.segment_of[k];
    const std::int64_t given = s >= 0 ? holed_square().segment_markers[static_cast<std::size_t>(s)] : 0;
    EXPECT_EQ(out.segment_markers[k], given != 0 ? given : 1) << k;  // every piece here is on the boundary
  }
  EXPECT_EQ(out.vertex_markers[9], 9);  // (8, 8): the diagonal's far end
  EXPECT_EQ(out.vertex_markers[6], 9);  // (6, 6): the last marked segment it ends a piece of
  EXPECT_EQ(out.vertex_markers[0], 5);
  EXPECT_EQ(out.vertex_markers[2], 2);
  EXPECT_EQ(out.vertex_markers[7], 1);  // on the hole's boundary, no marked segment: 1
  // B: no markers; given vertex markers win.
  EXPECT_TRUE(triangle::triangulate(holed_square(), "pB").vertex_markers.empty());
  triangle::Input marked = holed_square();
  marked.vertex_markers.assign(marked.vertices.size(), 0);
  marked.vertex_markers[6] = 42;
  EXPECT_EQ(triangle::triangulate(marked, "p").vertex_markers[6], 42);
}

TEST(Triangle, AttributesEdgesMiddlesAndTheDual) {
  const triangle::Output out = triangle::triangulate(holed_square(), "pq30a1evo2");
  ASSERT_EQ(out.nodes, 6);
  ASSERT_EQ(out.vertex_attributes.size(), out.vertices.size());
  for (std::size_t v = 0; v < out.vertices.size(); ++v)  // linear attributes stay linear, to a rounding
    EXPECT_NEAR(out.vertex_attributes[v], 2 * out.vertices[v].x + 3 * out.vertices[v].y + 1, 1e-12) << v;
  // Every edge once, each middle a node; markers 1 on the boundary, 0 inside, a piece's own.
  const std::size_t triangles = out.triangles.size() / 6;
  std::set<std::pair<VertexId, VertexId>> edges;
  for (std::size_t k = 0; k < triangles; ++k)
    for (int i = 0; i < 3; ++i) {
      const VertexId a = out.triangles[6 * k + (i + 1) % 3], b = out.triangles[6 * k + (i + 2) % 3];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  EXPECT_EQ(out.edges.size() / 2, edges.size());
  EXPECT_EQ(out.voronoi_vertices.size(), triangles);
  // The dual: vertex t the circumcentre of triangle t, its attribute the triangle's linear
  // function there.
  for (std::size_t k = 0; k < triangles; ++k) {
    const Point& c = out.voronoi_vertices[k];
    EXPECT_NEAR(out.voronoi_attributes[k], 2 * c.x + 3 * c.y + 1, 1e-9) << k;
    const Point& a = out.vertices[out.triangles[6 * k]];
    const Point& b = out.vertices[out.triangles[6 * k + 1]];
    EXPECT_NEAR(std::hypot(c.x - a.x, c.y - a.y), std::hypot(c.x - b.x, c.y - b.y), 1e-9) << k;
  }
  // C checks the mesh exactly.
  const triangle::Output checked = triangle::triangulate(holed_square(), "pq30a1Cj");
  EXPECT_TRUE(checked.check.valid) << checked.check.message;
}

TEST(Triangle, RefiningAMeshKeepsItsSegmentsAndTakesC) {
  triangle::Input first = holed_square();
  const triangle::Output mesh = triangle::triangulate(first, "pq30a2");
  triangle::Input again;
  again.vertices = mesh.vertices;
  again.triangles = mesh.triangles;
  again.segments = mesh.segments;
  const triangle::Output r = triangle::triangulate(again, "rpq30a0.5C");
  EXPECT_TRUE(r.check.valid) << r.check.message;
  const triangle::Output rc = triangle::triangulate(again, "rpcq30a0.5");
  EXPECT_EQ(rc.triangles, r.triangles);  // c changes nothing where a mesh is refined
  EXPECT_THROW(triangle::triangulate(first, "r"), InputError);  // no triangles to refine
  again.triangle_max_area = {1.0};
  EXPECT_THROW(triangle::triangulate(again, "rpa"), InputError);  // one bound for many triangles
}

}  // namespace
}  // namespace ridt::test
