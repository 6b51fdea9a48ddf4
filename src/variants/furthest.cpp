// The farthest-point Delaunay triangulation (ridt/furthest.hpp). The hull's corners come from
// an ordinary triangulation. Every hull side is an edge of the farthest-point triangulation,
// and the triangle on an edge whose corners between its ends (going counter-clockwise) are
// all on one side is the one through the corner whose circle, among those through the edge's
// ends, bulges furthest to that side: every corner lies in it (the lifted plane through the
// three lies above every lifted corner). Splitting there leaves two such chains; a stack
// replaces the recursion.
#include "ridt/furthest.hpp"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include "predicates/predicates.hpp"

namespace ridt {

namespace {

// The hull's corners: the hull without the points inside its sides.
std::vector<VertexId> corners(std::span<const Point> points, const std::vector<VertexId>& hull) {
  std::vector<VertexId> out;
  const std::size_t h = hull.size();
  for (std::size_t k = 0; k < h; ++k)
    if (detail::orient2d(points[hull[(k + h - 1) % h]], points[hull[k]], points[hull[(k + 1) % h]]) != 0)
      out.push_back(hull[k]);
  return out;
}

// Neighbours from the triangles: the triangle across from each corner, -1 on the hull.
std::vector<std::int32_t> neighbors_of(const std::vector<VertexId>& triangles) {
  std::map<std::pair<VertexId, VertexId>, std::int32_t> side;  // directed side -> its triangle
  const std::size_t count = triangles.size() / 3;
  for (std::size_t t = 0; t < count; ++t)
    for (int i = 0; i < 3; ++i)
      side[{triangles[3 * t + (i + 1) % 3], triangles[3 * t + (i + 2) % 3]}] = static_cast<std::int32_t>(t);
  std::vector<std::int32_t> out(triangles.size(), -1);
  for (std::size_t t = 0; t < count; ++t)
    for (int i = 0; i < 3; ++i) {
      const auto it = side.find({triangles[3 * t + (i + 2) % 3], triangles[3 * t + (i + 1) % 3]});
      if (it != side.end()) out[3 * t + i] = it->second;
    }
  return out;
}

}  // namespace

Triangulation triangulate_furthest_site(std::span<const Point> points, const Options& options) {
  Triangulation near = triangulate(points, options);
  Triangulation out;
  out.duplicates = std::move(near.duplicates);
  out.stats = near.stats;
  const std::vector<VertexId> c = near.size() ? corners(points, near.hull) : std::vector<VertexId>{};
  if (c.size() < 3) {
    out.warning = near.warning.empty() ? "fewer than three hull corners" : near.warning;
    return out;
  }
  out.hull = c;
  // Chains [i, j] of corner positions to triangulate: the corners c[i+1 .. j-1] between the
  // edge's ends c[i] and c[j], counter-clockwise; first the whole hull, on its side c[h-1] c[0].
  std::vector<std::pair<std::size_t, std::size_t>> stack = {{0, c.size() - 1}};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    if (j - i < 2) continue;
    const Point &a = points[c[i]], &b = points[c[j]];
    std::size_t k = i + 1;
    for (std::size_t m = i + 2; m < j; ++m)
      if (detail::incircle(a, points[c[k]], b, points[c[m]]) < 0) k = m;  // c[m] outside: a bigger circle
    out.triangles.insert(out.triangles.end(), {c[i], c[k], c[j]});
    stack.emplace_back(i, k);
    stack.emplace_back(k, j);
  }
  out.neighbors = neighbors_of(out.triangles);
  return out;
}

}  // namespace ridt
