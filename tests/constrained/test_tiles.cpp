// Quality meshes refined tile by tile on threads (constrained/tiles.cpp): the same mesh, point
// for point and triangle for triangle, on 1, 2, 3 and 8 threads, and a valid one with the
// bounds asked (check_mesh), for coastlines with lakes, small input angles, per-region areas and
// an area bound; in tiny tiles (RIDT_TILE_TRIANGLES), where most steps meet a fence, and in the
// default ones; and no larger than the mesh refined whole, but for a few per cent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "ridt/check.hpp"
#include "ridt/constrained.hpp"
#include "ridt/generate.hpp"
#include "ridt/predicates.hpp"
#include "ridt/triangle.hpp"

namespace ridt::test {
namespace {

// The tiles' size for a scope (0: tiles as large as a mesh, so none), restored after.
class TileSize {
 public:
  explicit TileSize(double triangles) {
    if (const char* v = std::getenv("RIDT_TILE_TRIANGLES")) old_ = v, had_ = true;
    setenv("RIDT_TILE_TRIANGLES", triangles > 0 ? std::to_string(triangles).c_str() : "1e300", 1);
  }
  ~TileSize() { had_ ? setenv("RIDT_TILE_TRIANGLES", old_.c_str(), 1) : unsetenv("RIDT_TILE_TRIANGLES"); }
  TileSize(const TileSize&) = delete;
  TileSize& operator=(const TileSize&) = delete;

 private:
  std::string old_;
  bool had_ = false;
};

struct Case {
  std::string name;
  Pslg g;
  Domain d;
  Quality q;
};

ConstrainedTriangulation mesh(const Case& c, unsigned threads) {
  Options o;
  o.threads = threads;
  return triangulate_constrained(c.g.points, c.g.segments, o, c.d, c.q);
}

// The mesh checked exactly, with its bounds (none where refinement warned).
void expect_valid(const Case& c, const ConstrainedTriangulation& t) {
  std::vector<Point> all = c.g.points;
  all.insert(all.end(), t.steiner.begin(), t.steiner.end());
  MeshSpec spec;
  spec.edges = t.edges;
  spec.segments = c.g.segments;
  spec.input_points = c.g.points.size();
  spec.holes = c.d.holes;
  spec.min_angle = t.warning.empty() ? c.q.min_angle : 0;
  spec.max_area = t.warning.empty() ? c.q.max_area : 0;
  const CheckResult r = check_mesh(all, t.triangles, spec);
  EXPECT_TRUE(r.valid) << r.message;
}

// Five segments from one corner at angles of 1 to 9 degrees, in a square with a lake.
Pslg small_angles() {
  Pslg g;
  g.points = {{0, 0}, {100, 0}, {100, 100}, {0, 100}, {50, 50}};
  g.segments = {0, 1, 1, 2, 2, 3, 3, 0};
  for (const double degrees : {0.0, 1.0, 3.0, 5.0, 9.0, 180.0, 182.0}) {
    const double a = degrees * 3.14159265358979323846 / 180;
    g.points.push_back({50 + 40 * std::cos(a), 50 + 40 * std::sin(a)});
    g.segments.insert(g.segments.end(), {4, static_cast<VertexId>(g.points.size() - 1)});
  }
  const auto lake = static_cast<VertexId>(g.points.size());
  g.points.insert(g.points.end(), {{20, 70}, {30, 70}, {30, 80}, {20, 80}});
  g.segments.insert(g.segments.end(), {lake, lake + 1, lake + 1, lake + 2, lake + 2, lake + 3, lake + 3, lake});
  g.holes = {{25, 75}};
  return g;
}

// Two regions, an inner square with a bound ten times smaller.
Case regions() {
  Case c{"regions", {}, {}, {}};
  c.g.points = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {3, 3}, {7, 3}, {7, 7}, {3, 7}};
  c.g.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
  c.d.regions = {{{5, 5}, 1, 2e-3}, {{1, 1}, 2, 2e-2}};
  c.q.min_angle = 25;
  return c;
}

std::vector<Case> cases() {
  std::vector<Case> out;
  Case coast{"coastline", generate_coastline(3000, 6, 11), {}, {}};
  coast.d.holes = coast.g.holes;
  coast.q.min_angle = 30;
  out.push_back(coast);
  Case area = coast;
  area.name = "coastline with an area bound";
  area.q.min_angle = 20;
  area.q.max_area = 2e-5;
  out.push_back(area);
  Case angles{"small input angles", small_angles(), {}, {}};
  angles.d.holes = angles.g.holes;
  angles.q.min_angle = 30;
  angles.q.max_area = 4;
  out.push_back(angles);
  out.push_back(regions());
  return out;
}

void expect_same(const ConstrainedTriangulation& a, const ConstrainedTriangulation& b) {
  EXPECT_EQ(a.steiner, b.steiner);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.edge_segments, b.edge_segments);
  EXPECT_EQ(a.attributes, b.attributes);
  EXPECT_EQ(a.warning, b.warning);
}

TEST(Tiles, TinyTilesGiveOneMeshOnAnyThreads) {
  const TileSize tiny(48);
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const ConstrainedTriangulation one = mesh(c, 1);
    expect_valid(c, one);
    for (const unsigned threads : {2u, 3u, 8u}) {
      SCOPED_TRACE(threads);
      expect_same(mesh(c, threads), one);
    }
  }
}

// The passes over the whole constrained triangulation that run on threads (its links made from
// the Delaunay step's neighbours, the fixed edges found, sorted and matched with their segments)
// give the same arrays on any number of threads: a coastline of 150,000 vertices and its lakes
// (some 225,000 triangles, 150,000 fixed edges), every edge listed once, sorted, each a
// segment's piece (the segment's ends on its line).
TEST(Tiles, ConstrainedArraysAreTheSameOnAnyThreads) {
  Case c{"coastline", generate_coastline(150000, 20, 3), {}, {}};
  c.d.holes = c.g.holes;
  const ConstrainedTriangulation one = mesh(c, 1);
  EXPECT_GT(one.size(), 200000u);
  expect_valid(c, one);
  ASSERT_EQ(one.edges.size(), 2 * one.edge_segments.size());
  EXPECT_GE(one.edge_segments.size(), c.g.segments.size() / 2);
  for (std::size_t k = 0; k < one.edge_segments.size(); ++k) {
    const VertexId a = one.edges[2 * k], b = one.edges[2 * k + 1];
    ASSERT_LT(a, b);
    if (k > 0) {
      ASSERT_TRUE(std::pair(one.edges[2 * k - 2], one.edges[2 * k - 1]) < std::pair(a, b)) << k;
    }
    const std::int32_t s = one.edge_segments[k];
    ASSERT_GE(s, 0);
    auto at = [&](VertexId v) { return v < c.g.points.size() ? c.g.points[v] : one.steiner[v - c.g.points.size()]; };
    const Point p = at(a), q = at(b);
    const Point &u = c.g.points[c.g.segments[2 * static_cast<std::size_t>(s)]],
                &w = c.g.points[c.g.segments[2 * static_cast<std::size_t>(s) + 1]];
    EXPECT_EQ(orientation(u, w, p), 0) << k;
    EXPECT_EQ(orientation(u, w, q), 0) << k;
  }
  for (const unsigned threads : {2u, 3u, 8u}) {
    SCOPED_TRACE(threads);
    const ConstrainedTriangulation many = mesh(c, threads);
    expect_same(many, one);
    EXPECT_EQ(many.neighbors, one.neighbors);
  }
}

// Tiles change which bad triangle is mended first, and so the mesh, but not its size by more
// than a few per cent (at the default tiles' size, a tenth of one on a coastline: in tiles of a
// thousand triangles, as here, one in a hundred; in tiny ones some more).
TEST(Tiles, NoLargerThanTheMeshRefinedWhole) {
  for (const Case& c : cases()) {
    // (Not the regions: refined whole, the inner square is halved and halved again into
    // triangles just below its bound, a lattice that tiles cut into; nor the small input angles,
    // a mesh of some thousands, tiled in tens.)
    if (c.name.rfind("coastline", 0) != 0) continue;
    SCOPED_TRACE(c.name);
    std::size_t whole = 0, tiled = 0;
    {
      const TileSize none(0);
      whole = mesh(c, 2).size();
    }
    {
      const TileSize small(1024);
      tiled = mesh(c, 2).size();
    }
    EXPECT_LE(static_cast<double>(tiled), 1.03 * static_cast<double>(whole)) << whole;
    EXPECT_GE(static_cast<double>(tiled), 0.95 * static_cast<double>(whole)) << whole;
  }
}

// A mesh large enough for the default tiles (an area bound's estimate of some 80,000, a mesh of 100,000
// triangles: a grid of 2 x 2 and more).
TEST(Tiles, DefaultTilesGiveOneMeshOnAnyThreads) {
  Case c{"coastline", generate_coastline(4000, 4, 5), {}, {}};
  c.d.holes = c.g.holes;
  c.q.min_angle = 28;
  c.q.max_area = 4e-5;
  const ConstrainedTriangulation one = mesh(c, 1);
  EXPECT_GT(one.size(), 70000u);
  expect_valid(c, one);
  {
    const TileSize none(0);  // refined whole: another mesh, so the one above was tiled
    EXPECT_NE(mesh(c, 1).triangles, one.triangles);
  }
  for (const unsigned threads : {2u, 8u}) {
    SCOPED_TRACE(threads);
    expect_same(mesh(c, threads), one);
  }
}

// Through Triangle's semantics (ridt::triangle): the same mesh and the same markers on one, two
// and eight threads, where the boundary's markers are found on threads and the whole mesh's
// pass after the tiles looks at its triangles on threads (a mesh of some 90,000 triangles).
TEST(Tiles, TrianglesMarkersAreTheSameOnAnyThreads) {
  const Pslg g = generate_coastline(4000, 4, 5);
  triangle::Input in;
  in.vertices = g.points, in.segments = g.segments, in.holes = g.holes;
  in.segment_markers.assign(g.segments.size() / 2, 0);
  for (std::size_t k = 0; k < in.segment_markers.size(); k += 7)
    in.segment_markers[k] = static_cast<std::int64_t>(k % 5);
  auto run = [&](unsigned threads) {
    Options o;
    o.threads = threads;
    return triangle::triangulate(in, "pq28a4e-5", o);
  };
  const triangle::Output one = run(1);
  EXPECT_GT(one.triangles.size() / 3, 70000u);
  EXPECT_GT(std::count(one.vertex_markers.begin(), one.vertex_markers.end(), 1), 1000);
  for (const unsigned threads : {2u, 8u}) {
    SCOPED_TRACE(threads);
    const triangle::Output many = run(threads);
    EXPECT_EQ(many.vertices, one.vertices);
    EXPECT_EQ(many.triangles, one.triangles);
    EXPECT_EQ(many.vertex_markers, one.vertex_markers);
    EXPECT_EQ(many.segments, one.segments);
    EXPECT_EQ(many.segment_markers, one.segment_markers);
  }
}

}  // namespace
}  // namespace ridt::test
