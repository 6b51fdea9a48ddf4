// The Voronoi diagram (ridt/voronoi.hpp): its structure against the triangulation, convex
// cells around their sites, and the cells clipped to a box tiling the box.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "helpers.hpp"
#include "io.hpp"
#include "ridt/generate.hpp"
#include "ridt/voronoi.hpp"

namespace ridt {
namespace {

double cross(const Point& o, const Point& a, const Point& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

double area(const std::vector<Point>& poly) {
  double s = 0;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Point& a = poly[k];
    const Point& b = poly[(k + 1) % poly.size()];
    s += a.x * b.y - a.y * b.x;
  }
  return s / 2;
}

class VoronoiOf : public ::testing::TestWithParam<Distribution> {};

TEST_P(VoronoiOf, CellsAreConvexHoldTheirSitesAndTileABox) {
  const std::vector<Point> pts = generate(GetParam(), 3000, 7);
  const Triangulation t = triangulate(pts);
  const Voronoi vd = voronoi(pts, t, 2);
  ASSERT_EQ(vd.vertices.size(), t.size());
  ASSERT_EQ(vd.point_cell.size(), pts.size());
  // Each vertex is equidistant from its triangle's three sites.
  for (std::size_t k = 0; k < t.size(); ++k) {
    const Point& c = vd.vertices[k];
    double d[3];
    for (int i = 0; i < 3; ++i)
      d[i] = std::hypot(pts[t.triangles[3 * k + i]].x - c.x, pts[t.triangles[3 * k + i]].y - c.y);
    EXPECT_NEAR(d[0], d[1], 1e-9 * d[0]);
    EXPECT_NEAR(d[0], d[2], 1e-9 * d[0]);
  }
  // A ridge for each edge: (3T + H) / 2, each between two sites of its triangles.
  EXPECT_EQ(vd.ridges.size(), (3 * t.size() + t.hull.size()) / 2);
  for (const Ridge& r : vd.ridges) {
    const VertexId* w = &t.triangles[3 * std::size_t(r.u)];
    EXPECT_TRUE(std::count(w, w + 3, r.a) == 1 && std::count(w, w + 3, r.b) == 1);
    const Point d = ray_direction(pts, r);
    EXPECT_EQ(r.v < 0, d.x != 0 || d.y != 0);
    if (r.v < 0) {  // the ray leaves the hull: away from the triangle's third vertex
      const Point& c = pts[w[0] != r.a && w[0] != r.b ? w[0] : w[1] != r.a && w[1] != r.b ? w[1] : w[2]];
      EXPECT_GT(d.x * ((pts[r.a].x + pts[r.b].x) / 2 - c.x) + d.y * ((pts[r.a].y + pts[r.b].y) / 2 - c.y), 0);
    }
  }
  // Every site has a cell; cells of the distinct points, bounded ones convex around their site.
  double x0 = pts[0].x, x1 = x0, y0 = pts[0].y, y1 = y0;
  for (const Point& p : pts)
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  EXPECT_EQ(vd.cells(), pts.size() - t.duplicates.size());
  double tiled = 0;
  const double box = (x1 - x0) * (y1 - y0);
  for (std::size_t c = 0; c < vd.cells(); ++c) {
    EXPECT_EQ(vd.point_cell[vd.cell_site[c]], static_cast<std::int32_t>(c));
    const Point& s = pts[vd.cell_site[c]];
    if (vd.cell(c).back() != -1) {
      std::vector<Point> poly;
      for (const std::int32_t v : vd.cell(c)) poly.push_back(vd.vertices[v]);
      for (std::size_t k = 0; k < poly.size(); ++k) {
        const Point& a = poly[k];
        const Point& b = poly[(k + 1) % poly.size()];
        // Convex and counter-clockwise around the site (a cell side may be very short).
        if (std::hypot(b.x - a.x, b.y - a.y) > 1e-9 * std::max(x1 - x0, y1 - y0)) {
          EXPECT_GT(cross(a, b, s), 0);
        }
      }
    }
    const double a = area(io::clipped_cell(pts, t, vd, c, {x0, y0, x1, y1}));
    EXPECT_GE(a, -1e-12 * box);
    tiled += a;
  }
  EXPECT_NEAR(tiled, box, 1e-9 * box);
}

INSTANTIATE_TEST_SUITE_P(Distributions, VoronoiOf, test::every_distribution(), test::distribution_name);

// The vertices at any scale: points scaled by a power of two, where the plain circumcentre's
// products overflow or underflow, give the vertices scaled, within the circumcentre's bound.
TEST(Voronoi, VerticesAtEveryScale) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 3000, 21);
  const Triangulation t = triangulate(pts);
  const Voronoi plain = voronoi(pts, t);
  for (const int e : {-990, -600, 400, 900}) {  // the points stay normal doubles: scaled exactly
    SCOPED_TRACE(e);
    std::vector<Point> sp = pts;
    for (Point& p : sp) p = {std::ldexp(p.x, e), std::ldexp(p.y, e)};
    const Voronoi big = voronoi(sp, triangulate(sp));
    ASSERT_EQ(big.vertices.size(), plain.vertices.size());
    for (std::size_t k = 0; k < big.vertices.size(); ++k) {
      const Point& a = pts[t.triangles[3 * k]];
      const Point& v = plain.vertices[k];
      const double radius = std::max(std::fabs(v.x - a.x), std::fabs(v.y - a.y));
      ASSERT_NEAR(std::ldexp(big.vertices[k].x, -e), v.x, 0x1p-43 * radius + 4e-16 * std::fabs(v.x)) << k;
      ASSERT_NEAR(std::ldexp(big.vertices[k].y, -e), v.y, 0x1p-43 * radius + 4e-16 * std::fabs(v.y)) << k;
    }
  }
}

TEST(Voronoi, ThreadsGiveTheSameDiagram) {
  // Enough triangles for each thread to take a stretch of them.
  const std::vector<Point> pts = generate(Distribution::Clusters, 80000, 3);
  const Triangulation t = triangulate(pts);
  const Voronoi one = voronoi(pts, t, 1), two = voronoi(pts, t, 2);
  EXPECT_EQ(one.cell_offsets, two.cell_offsets);
  EXPECT_EQ(one.cell_vertices, two.cell_vertices);
  EXPECT_EQ(one.cell_site, two.cell_site);
  EXPECT_EQ(one.point_cell, two.point_cell);
  ASSERT_EQ(one.ridges.size(), two.ridges.size());
  for (std::size_t k = 0; k < one.ridges.size(); ++k) {
    const Ridge &a = one.ridges[k], &b = two.ridges[k];
    EXPECT_TRUE(a.a == b.a && a.b == b.b && a.u == b.u && a.v == b.v) << k;
  }
  // Every corner of every triangle is in exactly its vertex's cell.
  std::vector<int> seen(t.size(), 0);
  for (std::size_t c = 0; c < one.cells(); ++c)
    for (const std::int32_t v : one.cell(c))
      if (v >= 0) {
        const VertexId* w = &t.triangles[3 * std::size_t(v)];
        EXPECT_TRUE(w[0] == one.cell_site[c] || w[1] == one.cell_site[c] || w[2] == one.cell_site[c]);
        ++seen[static_cast<std::size_t>(v)];
      }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 3), static_cast<std::ptrdiff_t>(t.size()));
}

TEST(Voronoi, DuplicatesShareTheirKeptPointsCell) {
  const std::vector<Point> pts = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {1, 0}, {0.5, 0.4}, {0, 0}};
  const Triangulation t = triangulate(pts);
  const Voronoi vd = voronoi(pts, t);
  EXPECT_EQ(vd.cells(), 5u);
  EXPECT_EQ(vd.point_cell[4], vd.point_cell[1]);
  EXPECT_EQ(vd.point_cell[6], vd.point_cell[0]);
  // The inner point's cell is bounded; the corners' are not.
  EXPECT_NE(vd.cell(vd.point_cell[5]).back(), -1);
  EXPECT_EQ(vd.cell(vd.point_cell[0]).back(), -1);
}

TEST(Voronoi, CollinearPointsHaveNoCells) {
  const std::vector<Point> pts = {{0, 0}, {1, 1}, {2, 2}};
  const Voronoi vd = voronoi(pts, triangulate(pts));
  EXPECT_EQ(vd.cells(), 0u);
  EXPECT_TRUE(vd.vertices.empty());
  EXPECT_EQ(vd.point_cell, std::vector<std::int32_t>(3, -1));
}

TEST(Voronoi, RefusesATriangulationOfOtherPoints) {
  const std::vector<Point> pts = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  const Triangulation t = triangulate(pts);
  EXPECT_THROW(voronoi(std::span(pts).first(2), t), InputError);
}

TEST(Voronoi, CocircularNeighboursShareOneVertex) {
  // A 3 x 3 grid: four squares, each two triangles on one circle; the diagram has a vertex a
  // square and a ridge for each of the grid's 12 sides, none for the diagonals.
  std::vector<Point> pts;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) pts.push_back({double(i), double(j)});
  const Triangulation t = triangulate(pts);
  Voronoi vd = voronoi(pts, t);
  const std::vector<std::int32_t> vertex = merge_cocircular(pts, t, vd);
  ASSERT_EQ(vd.vertices.size(), 4u);
  EXPECT_EQ(vd.ridges.size(), 12u);
  for (const Ridge& r : vd.ridges) {
    EXPECT_NE(r.u, r.v);
    EXPECT_EQ(std::fabs(pts[r.a].x - pts[r.b].x) + std::fabs(pts[r.a].y - pts[r.b].y), 1.0);
  }
  for (std::size_t k = 0; k < t.size(); ++k) {
    const Point& c = vd.vertices[static_cast<std::size_t>(vertex[k])];
    for (int i = 0; i < 3; ++i)  // the vertex is its triangles' circumcentre
      EXPECT_DOUBLE_EQ(std::hypot(pts[t.triangles[3 * k + i]].x - c.x, pts[t.triangles[3 * k + i]].y - c.y),
                       std::sqrt(0.5));
  }
  // The centre's cell is the square of the four vertices; each vertex once in every cell.
  const auto centre = vd.cell(static_cast<std::size_t>(vd.point_cell[4]));
  EXPECT_EQ(centre.size(), 4u);
  for (std::size_t c = 0; c < vd.cells(); ++c) {
    std::vector<std::int32_t> seen(vd.cell(c).begin(), vd.cell(c).end());
    std::sort(seen.begin(), seen.end());
    EXPECT_EQ(std::adjacent_find(seen.begin(), seen.end()), seen.end());
  }
}

TEST(Voronoi, MergingChangesNothingInGeneralPosition) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 5000, 4);
  const Triangulation t = triangulate(pts);
  const Voronoi before = voronoi(pts, t, 2);
  Voronoi after = before;
  merge_cocircular(pts, t, after, 2);
  EXPECT_EQ(before.vertices.size(), after.vertices.size());
  EXPECT_EQ(before.cell_vertices, after.cell_vertices);
  EXPECT_EQ(before.ridges.size(), after.ridges.size());
  EXPECT_THROW(merge_cocircular(std::span(pts).first(10), t, after), InputError);
}

TEST(Voronoi, MergedInOnePassEqualsMergedAfter) {
  for (const Distribution d : {Distribution::Grid, Distribution::Clusters}) {
    const std::vector<Point> pts = generate(d, 20000, 6);
    const Triangulation t = triangulate(pts);
    Voronoi after = voronoi(pts, t, 2);
    merge_cocircular(pts, t, after, 2);
    const Voronoi once = voronoi(pts, t, 2, true);
    EXPECT_EQ(once.vertices.size(), after.vertices.size());
    EXPECT_EQ(once.cell_offsets, after.cell_offsets);
    EXPECT_EQ(once.cell_vertices, after.cell_vertices);
    ASSERT_EQ(once.ridges.size(), after.ridges.size());
    for (std::size_t k = 0; k < once.ridges.size(); ++k)
      EXPECT_TRUE(once.ridges[k].u == after.ridges[k].u && once.ridges[k].v == after.ridges[k].v);
    if (d == Distribution::Grid) {
      EXPECT_LT(once.vertices.size(), t.size());  // a grid's squares merged
    }
  }
}

}  // namespace
}  // namespace ridt
