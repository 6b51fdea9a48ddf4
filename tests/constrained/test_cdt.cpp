// Taking free vertices out of the constrained triangulation (Cdt::remove_free, Cdt::compact), as
// quality refinement's clearing does: what is left is the (constrained) Delaunay triangulation of
// the other points, and the arrays hold no trace of what was taken out.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <vector>

#include "constrained/cdt.hpp"
#include "ridt/ridt.hpp"

namespace ridt::test {
namespace {

std::vector<Point> random_points(std::size_t n, std::uint64_t seed) {
  std::uint64_t x = seed;
  auto unit = [&] {
    return static_cast<double>((x = x * 6364136223846793005u + 1442695040888963407u) >> 11) * 0x1p-53;
  };
  std::vector<Point> p(n);
  for (Point& q : p) q.x = unit(), q.y = unit();
  return p;
}

using Corners = std::array<std::pair<double, double>, 3>;

// The triangles as sets of their corners' coordinates (so that renumbered points compare).
std::set<Corners> corner_set(const std::vector<Point>& pts, const std::vector<VertexId>& triangles) {
  std::set<Corners> out;
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
    Corners c;
    for (int k = 0; k < 3; ++k) c[k] = {pts[triangles[t + k]].x, pts[triangles[t + k]].y};
    std::sort(c.begin(), c.end());
    out.insert(c);
  }
  return out;
}

std::vector<VertexId> live_triangles(const detail::Cdt& m) {
  std::vector<VertexId> out;
  for (TriangleId t = 0; t < m.size(); ++t)
    if (m.at(t, 0) != detail::kNoVertex)
      for (int k = 0; k < 3; ++k) out.push_back(m.at(t, k));
  return out;
}

TEST(Cdt, RemovingFreeVerticesLeavesTheDelaunayTriangulationOfTheRest) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const std::vector<Point> pts = random_points(400, seed);
    Triangulation t = triangulate(pts);
    std::vector<bool> on_hull(pts.size(), false);
    for (const VertexId v : t.hull) on_hull[v] = true;
    detail::Cdt m(pts, t);
    std::vector<VertexId> dead;
    std::vector<Point> rest;
    for (VertexId v = 0; v < pts.size(); ++v)
      if (!on_hull[v] && v % 3 == 1) {
        ASSERT_TRUE(m.remove_free(v)) << v;
        dead.push_back(v);
      } else {
        rest.push_back(pts[v]);
      }
    EXPECT_EQ(corner_set(m.pts, live_triangles(m)), corner_set(rest, triangulate(rest).triangles));
    EXPECT_EQ(m.freed.size(), 2 * dead.size());
    const std::size_t slots = m.size();
    m.compact(dead);
    // the others: those before the first taken out in their places, the last ones moved into gaps
    ASSERT_EQ(m.pts.size(), rest.size());
    EXPECT_TRUE(std::equal(rest.begin(), rest.begin() + dead[0], m.pts.begin()));
    auto by_xy = [](const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
    std::vector<Point> sorted = m.pts, expected = rest;
    std::sort(sorted.begin(), sorted.end(), by_xy), std::sort(expected.begin(), expected.end(), by_xy);
    EXPECT_EQ(sorted, expected);
    EXPECT_EQ(m.size(), slots - 2 * dead.size());
    EXPECT_TRUE(m.freed.empty());
    const std::vector<VertexId> after = live_triangles(m);
    EXPECT_EQ(after.size(), 3 * std::size_t{m.size()});  // no free slot left
    EXPECT_EQ(corner_set(m.pts, after), corner_set(rest, triangulate(rest).triangles));
    for (TriangleId u = 0; u < m.size(); ++u)
      for (int k = 0; k < 3; ++k) {  // links that lead back, corners that hold their vertex
        const detail::Link l = m.tds.link(u, k);
        if (l != detail::kNoLink) {
          EXPECT_EQ(m.tds.link_at(l), detail::link_to(u, k));
        }
        EXPECT_EQ(m.at(m.corner[m.at(u, k)] / 3, m.corner[m.at(u, k)] % 3), m.at(u, k));
      }
  }
}

// A vertex with a fixed edge is no free vertex: refused, nothing changed. One whose ring has a
// fixed edge is taken out, and the edge stays fixed, with its constraint.
TEST(Cdt, FixedEdgesStayAndTheirVerticesAreNotFree) {
  const std::vector<Point> pts = random_points(200, 7);
  Triangulation t = triangulate(pts);
  std::vector<bool> on_hull(pts.size(), false);
  for (const VertexId v : t.hull) on_hull[v] = true;
  detail::Cdt m(pts, t);
  VertexId v = 0;
  while (on_hull[v]) ++v;
  const TriangleId t0 = m.corner[v] / 3;
  const int i = m.corner_of(t0, v);
  const VertexId a = m.at(t0, i + 1), b = m.at(t0, i + 2);
  m.constrain(detail::link_to(t0, i), 5);  // a-b, across from v
  m.constrain(m.find_edge(v, a), 6);
  const std::vector<VertexId> before = live_triangles(m);
  EXPECT_FALSE(m.remove_free(v));
  EXPECT_EQ(live_triangles(m), before);
  m.constrain(m.find_edge(v, a), detail::kFree);
  EXPECT_TRUE(m.remove_free(v));
  const detail::Link ab = m.find_edge(a, b);
  ASSERT_NE(ab, detail::kNoLink);
  EXPECT_EQ(m.tds.constraint(ab), 5);
  EXPECT_EQ(m.tds.constraint(m.tds.link_at(ab)), 5);
}

}  // namespace
}  // namespace ridt::test
