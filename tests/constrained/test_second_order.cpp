// second_order: six-node triangles. Every edge has one node, shared by its two triangles, at the
// exact middle of its ends rounded once; the corners are the triangulation's; bad input refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "ridt/check.hpp"
#include "ridt/constrained.hpp"
#include "ridt/generate.hpp"

namespace ridt::test {
namespace {

// The exact mean of a and b rounded once, without std::midpoint: a + b rounds once (or is exact,
// among the subnormals) and halving it is exact or that one rounding; where a + b overflows,
// the halves, exact at that size, are added instead.
double mean(double a, double b) {
  const double sum = a + b;
  return std::isfinite(sum) ? sum / 2 : a / 2 + b / 2;
}

// Checks `s` against `t` (of `vertices`) edge by edge; returns the number of edges.
std::size_t expect_six_nodes(const std::vector<Point>& vertices, const Triangulation& t, const SecondOrder& s) {
  const std::size_t n = vertices.size(), count = t.triangles.size() / 3;
  EXPECT_EQ(s.triangles.size(), 6 * count);
  EXPECT_EQ(s.ends.size(), 2 * s.nodes.size());
  std::map<std::pair<VertexId, VertexId>, VertexId> node_of;  // each edge's node, from either side
  std::size_t boundary = 0;
  for (std::size_t k = 0; k < count; ++k)
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(s.triangles[6 * k + i], t.triangles[3 * k + i]);
      const VertexId a = t.triangles[3 * k + (i + 1) % 3], b = t.triangles[3 * k + (i + 2) % 3];
      const VertexId node = s.triangles[6 * k + 3 + i];
      EXPECT_GE(node, n);
      const auto [it, fresh] = node_of.insert({{std::min(a, b), std::max(a, b)}, node});
      EXPECT_EQ(it->second, node) << "an edge with two nodes";
      boundary += t.neighbors[3 * k + i] < 0;
      const std::size_t q = node - n;
      EXPECT_EQ(std::minmax(s.ends[2 * q], s.ends[2 * q + 1]), std::minmax(a, b));
      EXPECT_EQ(s.nodes[q].x, mean(vertices[a].x, vertices[b].x));
      EXPECT_EQ(s.nodes[q].y, mean(vertices[a].y, vertices[b].y));
    }
  // Euler: every edge has a node, and no two edges share one.
  EXPECT_EQ(node_of.size(), (3 * count + boundary) / 2);
  EXPECT_EQ(s.nodes.size(), node_of.size());
  return node_of.size();
}

TEST(SecondOrder, TwoTrianglesShareTheNodeOfTheirDiagonal) {
  const std::vector<Point> square = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  const ConstrainedTriangulation t = triangulate_constrained(square, {});
  const SecondOrder s = second_order(square, t);
  EXPECT_EQ(expect_six_nodes(square, t, s), 5u);
  std::vector<Point> nodes = s.nodes;
  std::sort(nodes.begin(), nodes.end(),
            [](const Point& p, const Point& q) { return p.x != q.x ? p.x < q.x : p.y < q.y; });
  const std::vector<Point> want = {{0, 1}, {1, 0}, {1, 1}, {1, 2}, {2, 1}};
  for (std::size_t k = 0; k < want.size(); ++k) EXPECT_TRUE(nodes[k].x == want[k].x && nodes[k].y == want[k].y);
}

TEST(SecondOrder, EveryEdgeOfAQualityMeshWithHolesOnce) {
  const Pslg g = generate_coastline(3000, 4, 5);
  Domain d;
  d.convex_hull = false;
  d.holes = g.holes;
  Quality q;
  q.min_angle = 30;
  const ConstrainedTriangulation t = triangulate_constrained(g.points, g.segments, {}, d, q);
  std::vector<Point> all = g.points;
  all.insert(all.end(), t.steiner.begin(), t.steiner.end());
  const SecondOrder s = second_order(all, t);
  EXPECT_GT(expect_six_nodes(all, t, s), 3 * t.size() / 2);
  // Numbered as the triangles first meet their edges: the first triangle's three come first.
  EXPECT_EQ(s.triangles[3], all.size());
}

// check_second_order accepts second_order's nodes and names each way of getting them wrong.
TEST(SecondOrder, TheValidatorTakesItsNodesAndFindsWrongOnes) {
  const Pslg g = generate_coastline(400, 2, 7);
  Domain d;
  d.convex_hull = false;
  d.holes = g.holes;
  const ConstrainedTriangulation t = triangulate_constrained(g.points, g.segments, {}, d);
  std::vector<Point> all = g.points;
  all.insert(all.end(), t.steiner.begin(), t.steiner.end());
  const SecondOrder s = second_order(all, t);
  std::vector<Point> nodes = all;
  nodes.insert(nodes.end(), s.nodes.begin(), s.nodes.end());
  std::vector<VertexId> corners, middles;
  for (std::size_t k = 0; k < t.size(); ++k)
    for (int i = 0; i < 3; ++i)
      corners.push_back(s.triangles[6 * k + i]), middles.push_back(s.triangles[6 * k + 3 + i]);
  const CheckResult ok = check_second_order(nodes, corners, middles);
  EXPECT_TRUE(ok.valid) << ok.message;
  auto verdict = [&](std::vector<Point> p, std::vector<VertexId> m) {
    const CheckResult r = check_second_order(p, corners, m);
    EXPECT_FALSE(r.valid);
    return r.message;
  };
  std::vector<Point> moved = nodes;
  moved[middles[0]].x = std::nextafter(moved[middles[0]].x, 1e300);  // an ulp off the middle
  EXPECT_NE(verdict(moved, middles).find("not the middle"), std::string::npos);
  std::vector<VertexId> corner = middles;
  corner[0] = corners[0];  // a corner for a middle
  EXPECT_NE(verdict(nodes, corner).find("is a corner"), std::string::npos);
  // Two nodes for one edge: the first triangle's middle of an inner edge swapped for a fresh one.
  std::size_t slot = 0;
  while (t.neighbors[slot] < 0) ++slot;
  std::vector<Point> more = nodes;
  more.push_back(nodes[middles[slot]]);
  std::vector<VertexId> twice = middles;
  twice[slot] = static_cast<VertexId>(more.size() - 1);
  EXPECT_NE(verdict(more, twice).find("two nodes"), std::string::npos);
  std::vector<VertexId> shared = middles;  // one node for two edges of a triangle
  shared[1] = shared[0];
  EXPECT_NE(verdict(nodes, shared).find("not the middle"), std::string::npos);
  EXPECT_NE(verdict(nodes, std::vector<VertexId>(middles.begin(), middles.end() - 1)).find("3 middle nodes"),
            std::string::npos);
}

TEST(SecondOrder, MiddlesOfTheLargestAndSmallestDoublesAreExact) {
  // (a + b) / 2 overflows at the largest doubles and rounds twice among the subnormals.
  const double big = 1.7e308, tiny = 4.9e-324;
  const std::vector<Point> pts = {{-big, -big}, {big, -big}, {big, big}, {0, 3 * tiny}, {tiny, 0}, {-big, 2 * tiny}};
  const ConstrainedTriangulation t = triangulate_constrained(pts, {});
  const SecondOrder s = second_order(pts, t);
  expect_six_nodes(pts, t, s);
  for (const Point& p : s.nodes) EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
}

TEST(SecondOrder, RefusesWhatItCannotNumber) {
  const std::vector<Point> square = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  Options o;
  o.neighbors = false;
  EXPECT_THROW(second_order(square, triangulate_constrained(square, {}, o)), InputError);
  const ConstrainedTriangulation t = triangulate_constrained(square, {});
  EXPECT_THROW(second_order(std::vector<Point>(square.begin(), square.begin() + 3), t), InputError);
  const int s = t.neighbors[0] >= 0 ? 0 : t.neighbors[1] >= 0 ? 1 : 2;  // triangle 0's link to triangle 1
  Triangulation wrong = t;
  wrong.neighbors[s] = 7;  // a triangle that is not there
  EXPECT_THROW(second_order(square, wrong), InputError);
  wrong = t;
  for (int j = 3; j < 6; ++j)  // triangle 1 no longer has 0 as a neighbour: found from 0's side
    if (wrong.neighbors[j] == 0) wrong.neighbors[j] = -1;
  EXPECT_THROW(second_order(square, wrong), InputError);
  wrong = t;
  std::rotate(wrong.neighbors.begin() + 3, wrong.neighbors.begin() + 4, wrong.neighbors.begin() + 6);  // edges differ
  EXPECT_THROW(second_order(square, wrong), InputError);
}

}  // namespace
}  // namespace ridt::test
