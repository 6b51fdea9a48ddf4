// refine_mesh (Triangle's -r): a mesh already made, refined further. Every result through
// check_mesh with its fixed edges as the segments; per-triangle area bounds kept by every
// triangle whose centroid lies in theirs; a mesh not Delaunay made so by flips; pinched
// vertices, huge coordinates; bad meshes refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "ridt/check.hpp"
#include "ridt/constrained.hpp"
#include "ridt/generate.hpp"
#include "ridt/ridt.hpp"

namespace ridt::test {
namespace {

std::vector<Point> all_points(const std::vector<Point>& input, const ConstrainedTriangulation& t) {
  std::vector<Point> all = input;
  all.insert(all.end(), t.steiner.begin(), t.steiner.end());
  return all;
}

// check_mesh on the refined mesh: its fixed edges are its segments, with the bounds asked.
void expect_valid(const std::vector<Point>& all, const ConstrainedTriangulation& t, const std::vector<VertexId>& segs,
                  std::size_t input, double min_angle, double max_area) {
  MeshSpec spec;
  spec.edges = t.edges;
  spec.segments = segs;
  spec.input_points = input;
  spec.min_angle = min_angle;
  spec.max_area = max_area;
  const CheckResult r = check_mesh(all, t.triangles, spec);
  EXPECT_TRUE(r.valid) << r.message;
}

double twice_area(const std::vector<Point>& p, const std::vector<VertexId>& tris, std::size_t k) {
  const Point &a = p[tris[3 * k]], &b = p[tris[3 * k + 1]], &c = p[tris[3 * k + 2]];
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

double total_area(const std::vector<Point>& p, const std::vector<VertexId>& tris) {
  double sum = 0;
  for (std::size_t k = 0; k < tris.size() / 3; ++k) sum += twice_area(p, tris, k) / 2;
  return sum;
}

std::set<std::vector<VertexId>> triangle_set(const std::vector<VertexId>& tris) {
  std::set<std::vector<VertexId>> out;
  for (std::size_t k = 0; k < tris.size(); k += 3) {
    std::vector<VertexId> v(tris.begin() + static_cast<std::ptrdiff_t>(k),
                            tris.begin() + static_cast<std::ptrdiff_t>(k) + 3);
    std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
    out.insert(v);
  }
  return out;
}

// The coastline meshed coarsely, then refined to 30 degrees and an area: the same bounds as
// meshing it at once would meet, every input vertex and added one kept.
TEST(RefineMesh, ACoarseCoastlineMeshRefinedToQuality) {
  const Pslg g = generate_coastline(2000, 5, 3);
  Domain d;
  d.convex_hull = false;
  d.holes = g.holes;
  Quality coarse;
  coarse.min_angle = 20;
  const ConstrainedTriangulation first = triangulate_constrained(g.points, g.segments, {}, d, coarse);
  ASSERT_TRUE(first.warning.empty()) << first.warning;
  const std::vector<Point> pts = all_points(g.points, first);
  Quality q;
  q.min_angle = 30;
  q.max_area = total_area(pts, first.triangles) / 5000;
  const ConstrainedTriangulation second = refine_mesh(pts, first.triangles, first.edges, q);
  ASSERT_TRUE(second.warning.empty()) << second.warning;
  const std::vector<Point> all = all_points(pts, second);
  expect_valid(all, second, first.edges, pts.size(), 30, q.max_area);
  EXPECT_GT(second.size(), 5000u);
  EXPECT_NEAR(total_area(all, second.triangles), total_area(pts, first.triangles),
              1e-9 * total_area(pts, first.triangles));
  EXPECT_TRUE(second.attributes.empty());
  EXPECT_TRUE(second.hull.empty());
}

// Without bounds a constrained Delaunay mesh comes back as it was (its triangles as a set).
TEST(RefineMesh, NothingAskedChangesNothing) {
  const Pslg g = generate_coastline(500, 3, 7);
  Domain d;
  d.convex_hull = false;
  d.holes = g.holes;
  const ConstrainedTriangulation t = triangulate_constrained(g.points, g.segments, {}, d);
  const ConstrainedTriangulation again = refine_mesh(g.points, t.triangles, t.edges, {});
  EXPECT_TRUE(again.steiner.empty());
  EXPECT_EQ(triangle_set(again.triangles), triangle_set(t.triangles));
  EXPECT_EQ(again.edges, t.edges);
}

// A square split along the diagonal that is not Delaunay (the points make a kite): flipped.
TEST(RefineMesh, AMeshThatIsNotDelaunayIsFlippedToIt) {
  const std::vector<Point> kite = {{0, 0}, {4, -1}, {8, 0}, {4, 1}};
  const std::vector<VertexId> long_diagonal = {0, 1, 2, 0, 2, 3};
  const ConstrainedTriangulation t = refine_mesh(kite, long_diagonal, {}, {});
  EXPECT_EQ(triangle_set(t.triangles), triangle_set({0, 1, 3, 1, 2, 3}));
  expect_valid(kite, t, {}, kite.size(), 0, 0);
  // A segment along the long diagonal keeps it.
  const std::vector<VertexId> diagonal = {0, 2};
  const ConstrainedTriangulation kept = refine_mesh(kite, long_diagonal, diagonal, {});
  EXPECT_EQ(triangle_set(kept.triangles), triangle_set(long_diagonal));
  expect_valid(kite, kept, diagonal, kite.size(), 0, 0);
}

// Two triangles of a square, one bound tight, one none: a triangle takes the bound and the
// attribute of the given triangle that holds its centroid; the tight half is refined to it, the
// other graded out from the diagonal alone.
TEST(RefineMesh, EachTriangleToItsOwnAreaBound) {
  const std::vector<Point> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<VertexId> tris = {0, 1, 2, 0, 2, 3};  // below the diagonal y = x, then above
  const std::vector<double> bounds = {0.001, 0}, attributes = {1, 2};
  const ConstrainedTriangulation t = refine_mesh(square, tris, {}, {}, bounds, attributes);
  const std::vector<Point> all = all_points(square, t);
  expect_valid(all, t, {}, square.size(), 0, 0);
  ASSERT_EQ(t.attributes.size(), t.size());
  std::size_t below = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const Point &a = all[t.triangles[3 * k]], &b = all[t.triangles[3 * k + 1]], &c = all[t.triangles[3 * k + 2]];
    const double x = (a.x + b.x + c.x) / 3, y = (a.y + b.y + c.y) / 3;
    if (y == x) continue;  // on the diagonal: either
    EXPECT_EQ(t.attributes[k], y < x ? 1 : 2);
    if (y < x) {
      ++below;
      EXPECT_LE(twice_area(all, t.triangles, k) / 2, 0.001);
    }
  }
  EXPECT_GE(below, 500u);
  EXPECT_LT(t.size() - below, below / 2);
}

// The same with the triangles in canonical order: the attributes follow their triangles.
TEST(RefineMesh, AttributesFollowTheTrianglesInCanonicalOrder) {
  const std::vector<Point> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<VertexId> tris = {0, 1, 2, 0, 2, 3};
  Options o;
  o.canonical_order = true;
  const std::vector<double> bounds = {0.001, 0.01}, attributes = {1, 2};
  const ConstrainedTriangulation t = refine_mesh(square, tris, {}, {}, bounds, attributes, o);
  const std::vector<Point> all = all_points(square, t);
  ASSERT_EQ(t.attributes.size(), t.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    const Point &a = all[t.triangles[3 * k]], &b = all[t.triangles[3 * k + 1]], &c = all[t.triangles[3 * k + 2]];
    const double x = (a.x + b.x + c.x) / 3, y = (a.y + b.y + c.y) / 3;
    if (y != x) {
      EXPECT_EQ(t.attributes[k], y < x ? 1 : 2);
    }
    EXPECT_LE(twice_area(all, t.triangles, k) / 2, y < x ? 0.001 : 0.01);
  }
}

// A square with a triangular hole that touches its corner: the mesh's boundary passes through
// that vertex twice, and its segments there are found either way along them.
TEST(RefineMesh, AHoleTouchingTheBoundaryAtAVertex) {
  Pslg g;
  g.points = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 1}, {1, 2}};
  g.segments = {0, 1, 1, 2, 2, 3, 3, 0, 0, 4, 4, 5, 5, 0};
  Domain d;
  d.convex_hull = false;
  d.holes = {{1, 1}};
  const ConstrainedTriangulation first = triangulate_constrained(g.points, g.segments, {}, d);
  Quality q;
  q.min_angle = 25;
  q.max_area = 0.05;
  const ConstrainedTriangulation t = refine_mesh(g.points, first.triangles, first.edges, q);
  ASSERT_TRUE(t.warning.empty()) << t.warning;
  const std::vector<Point> all = all_points(g.points, t);
  expect_valid(all, t, first.edges, g.points.size(), 25, 0.05);
  EXPECT_NEAR(total_area(all, t.triangles), 16 - 1.5, 1e-12);
}

// Coordinates near 2^500 (and their areas near 2^1000) give the same mesh, scaled: the
// predicates and the refinement work on an exactly scaled copy.
TEST(RefineMesh, HugeCoordinatesGiveTheSameMeshScaled) {
  const std::vector<Point> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<Point> huge;
  for (const Point& p : square) huge.push_back({std::ldexp(p.x, 500), std::ldexp(p.y, 500)});
  const std::vector<VertexId> tris = {0, 1, 2, 0, 2, 3};
  Quality q;
  q.min_angle = 30;
  q.max_area = 0.01;
  Quality big = q;
  big.max_area = std::ldexp(0.01, 1000);
  const ConstrainedTriangulation t = refine_mesh(square, tris, {}, q);
  const ConstrainedTriangulation u = refine_mesh(huge, tris, {}, big);
  ASSERT_EQ(t.triangles, u.triangles);
  ASSERT_EQ(t.steiner.size(), u.steiner.size());
  for (std::size_t k = 0; k < t.steiner.size(); ++k) {
    EXPECT_EQ(std::ldexp(t.steiner[k].x, 500), u.steiner[k].x);
    EXPECT_EQ(std::ldexp(t.steiner[k].y, 500), u.steiner[k].y);
  }
}

// Bad meshes: refused by name, before anything is done.
TEST(RefineMesh, BadMeshesAreRefused) {
  const std::vector<Point> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  auto message = [&](const std::vector<VertexId>& tris, const std::vector<VertexId>& segs = {},
                     const std::vector<double>& bounds = {}) {
    try {
      refine_mesh(square, tris, segs, {}, bounds);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message({0, 2, 1}).find("clockwise"), std::string::npos);
  EXPECT_NE(message({0, 1, 2, 0, 1, 3}).find("overlap"), std::string::npos);
  EXPECT_NE(message({0, 1, 7}).find("refers to point 7"), std::string::npos);
  EXPECT_NE(message({0, 1}).find("multiple of 3"), std::string::npos);
  EXPECT_NE(message({}).find("at least one triangle"), std::string::npos);
  EXPECT_NE(message({0, 1, 2}, {0, 3}).find("not an edge"), std::string::npos);
  EXPECT_NE(message({0, 1, 2}, {}, {1, 2}).find("needs as many"), std::string::npos);
  EXPECT_NE(message({0, 1, 2}, {}, {NAN}).find("not finite"), std::string::npos);
  EXPECT_NE(message({0, 1, 2}, {3, 0}).find("not an edge"), std::string::npos);  // from a point in no triangle
}

// Fans of triangles meeting at one vertex: two that close round it (each once), or two open
// ones covering some angle twice, overlap; two open ones side by side are a mesh whose domain
// touches itself there.
TEST(RefineMesh, FansThatOverlapAtAVertexAreRefused) {
  const std::vector<Point> p = {{0, 0},  {1, 0},  {0, 1}, {-1, 0}, {0, -1}, {2, 1},
                                {-2, 1}, {0, -2}, {1, 1}, {-1, 1}, {-1, -1}};
  auto refused = [&](const std::vector<VertexId>& tris) {
    try {
      refine_mesh(p, tris, {}, {});
    } catch (const InputError& e) {
      return std::string(e.what()).find("overlap") != std::string::npos;
    }
    return false;
  };
  EXPECT_TRUE(refused({0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1, 0, 5, 6, 0, 6, 7, 0, 7, 5}));  // two closed fans
  EXPECT_TRUE(refused({0, 1, 2, 0, 8, 9}));  // 0 to 90 degrees, and 45 to 135
  EXPECT_FALSE(refused({0, 1, 8, 0, 9, 10}));  // 0 to 45, and 135 to 225
  EXPECT_NO_THROW(refine_mesh(p, std::vector<VertexId>{0, 1, 8, 0, 9, 10}, std::vector<VertexId>{0, 1, 0, 9}, {}));
}

// Seven triangles round a vertex whose outer corners go twice round it: every directed edge
// once, every triangle counter-clockwise, and yet they cover the plane about it twice.
TEST(RefineMesh, TrianglesTurningTwiceRoundAVertexAreRefused) {
  std::vector<Point> p = {{0, 0}};
  for (int k = 0; k < 7; ++k) {
    const double a = 4 * 3.14159265358979323846 * k / 7;
    p.push_back({std::cos(a), std::sin(a)});
  }
  std::vector<VertexId> tris;
  for (VertexId k = 0; k < 7; ++k) tris.insert(tris.end(), {0, 1 + k, 1 + (k + 1) % 7});
  try {
    refine_mesh(p, tris, {}, {});
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("turn round it 2 times"), std::string::npos) << e.what();
  }
  // Open: five of them, from 0 to 20 pi / 7, more than a turn.
  tris.resize(15);
  EXPECT_THROW(refine_mesh(p, tris, {}, {}), InputError);
  // Three of them, 12 pi / 7 in all, less than a turn: a mesh.
  tris.resize(9);
  EXPECT_NO_THROW(refine_mesh(p, tris, {}, {}));
}

// Pieces that overlap without sharing a vertex pass every test at a vertex; they are found by
// the mesh's own constrained triangulation, and named: crossing edges, a piece inside a
// triangle, a vertex inside an edge, two vertices at one point. A point that no triangle uses
// may lie anywhere.
TEST(RefineMesh, PiecesThatOverlapWithoutSharingAVertexAreRefused) {
  auto message = [](const std::vector<Point>& p, const std::vector<VertexId>& tris) {
    try {
      refine_mesh(p, tris, {}, {});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  // Two unit squares, the second moved by (0.5, 0.5): their edges cross at (1, 0.5), (0.5, 1).
  const std::vector<Point> squares = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}};
  EXPECT_NE(message(squares, {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7}).find("cross at ("), std::string::npos);
  // A small triangle inside a large one: no edge crosses.
  const std::vector<Point> nested = {{0, 0}, {10, 0}, {0, 10}, {1, 1}, {2, 1}, {1, 2}};
  const std::string inside = message(nested, {0, 1, 2, 3, 4, 5});
  EXPECT_NE(inside.find("overlap: it covers the area about"), std::string::npos) << inside;
  EXPECT_NE(inside.find(" 2 times"), std::string::npos) << inside;
  // A vertex of one piece inside an edge of another (no overlap of area, but no mesh either).
  const std::vector<Point> hanging = {{0, 0}, {2, 0}, {1, 1}, {1, 0}, {1, -1}};
  EXPECT_NE(message(hanging, {0, 1, 2, 0, 4, 3, 3, 4, 1}).find("passes through vertex 3 at (1, 0)"), std::string::npos);
  // Two triangles touching where two of their vertices lie at one point.
  const std::vector<Point> twins = {{0, 0}, {1, 0}, {0, 1}, {0, 0}, {-1, 0}, {0, -1}};
  EXPECT_NE(message(twins, {0, 1, 2, 3, 4, 5}).find("lie at one point (0, 0)"), std::string::npos);
  // A strip that goes one and a quarter times round: every vertex's fan is sound, and it
  // covers its own first quarter again.
  std::vector<Point> spiral;
  std::vector<VertexId> strip;
  for (VertexId k = 0; k <= 11; ++k) {
    const double a = 2.5 * 3.14159265358979323846 * k / 11;
    spiral.push_back({std::cos(a), std::sin(a)}), spiral.push_back({2 * std::cos(a), 2 * std::sin(a)});
    if (k > 0) strip.insert(strip.end(), {2 * k - 2, 2 * k - 1, 2 * k + 1, 2 * k - 2, 2 * k + 1, 2 * k});
  }
  EXPECT_NE(message(spiral, strip).find("overlap"), std::string::npos);
  strip.resize(6 * 8);  // less than a turn: a mesh
  EXPECT_EQ(message(spiral, strip), "accepted");
  // The nested triangle's points unused: the large one alone is a mesh.
  EXPECT_EQ(message(nested, {0, 1, 2}), "accepted");
}

}  // namespace
}  // namespace ridt::test
