// The validator of farthest-point Delaunay triangulations (ridt/check.hpp), independent of
// src/variants/furthest.cpp: its own hull (Andrew's monotone chain on exact orientations) and edge
// table; it shares only the exact predicates.
#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include "predicates/predicates.hpp"
#include "ridt/check.hpp"

namespace ridt {
namespace {

// The convex hull's corners, counter-clockwise from the lowest-leftmost point (equal points
// once; collinear points left out).
std::vector<VertexId> hull_corners(std::span<const Point> pts) {
  std::vector<VertexId> order(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) order[i] = static_cast<VertexId>(i);
  std::sort(order.begin(), order.end(), [&](VertexId a, VertexId b) { return detail::lex_less(pts[a], pts[b]); });
  order.erase(std::unique(order.begin(), order.end(), [&](VertexId a, VertexId b) { return pts[a] == pts[b]; }),
              order.end());
  if (order.size() < 3) return {};
  std::vector<VertexId> h(2 * order.size());
  std::size_t k = 0;
  auto add = [&](VertexId p, std::size_t floor) {  // keep the chain turning left
    while (k >= floor && detail::orient2d(pts[h[k - 2]], pts[h[k - 1]], pts[p]) <= 0) --k;
    h[k++] = p;
  };
  for (const VertexId p : order) add(p, 2);  // the lower chain, left to right
  const std::size_t lower = k + 1;
  for (std::size_t n = order.size() - 1; n-- > 0;) add(order[n], lower);  // the upper, back
  --k;  // the first point closed the cycle
  h.resize(k);
  return h.size() >= 3 ? h : std::vector<VertexId>{};
}

}  // namespace

CheckResult check_furthest_site(std::span<const Point> pts, std::span<const VertexId> tris) {
  CheckResult r;
  std::string first;
  auto problem = [&](const std::string& what) {
    if (r.problems++ == 0) first = what;
  };
  if (tris.size() % 3 != 0) throw InputError("check_furthest_site: triangles must be #T by 3");
  const std::size_t count = tris.size() / 3;
  for (const VertexId v : tris)
    if (v >= pts.size()) throw InputError("check_furthest_site: a vertex is not one of the points");
  const std::vector<VertexId> corners = hull_corners(pts);
  // Directed edges (from, to, triangle, corner across), sorted to find each one's twin.
  std::vector<std::tuple<VertexId, VertexId, std::size_t, int>> edges;
  for (std::size_t t = 0; t < count; ++t) {
    const VertexId* v = &tris[3 * t];
    if (detail::orient2d(pts[v[0]], pts[v[1]], pts[v[2]]) <= 0)
      problem("triangle " + std::to_string(t) + " is not counter-clockwise or is degenerate");
    for (int i = 0; i < 3; ++i) edges.emplace_back(v[(i + 1) % 3], v[(i + 2) % 3], t, i);
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<VertexId, VertexId>> boundary;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const auto& [a, b, t, i] = edges[e];
    if (e > 0 && std::get<0>(edges[e - 1]) == a && std::get<1>(edges[e - 1]) == b)
      problem("edge " + std::to_string(a) + "-" + std::to_string(b) + " is used twice in one direction");
    const auto twin = std::lower_bound(edges.begin(), edges.end(), std::make_tuple(b, a, std::size_t{0}, 0));
    if (twin == edges.end() || std::get<0>(*twin) != b || std::get<1>(*twin) != a) {
      boundary.emplace_back(a, b);
      continue;
    }
    const VertexId* v = &tris[3 * t];
    const VertexId d = tris[3 * std::get<2>(*twin) + std::get<3>(*twin)];
    if (detail::incircle(pts[v[0]], pts[v[1]], pts[v[2]], pts[d]) < 0)
      problem("edge " + std::to_string(a) + "-" + std::to_string(b) +
              " is not locally farthest-point Delaunay (vertex " + std::to_string(d) +
              " lies outside the circle of triangle " + std::to_string(t) + ")");
  }
  // The boundary: the corners' cycle, each side once (and so no other vertex on it).
  std::vector<std::pair<VertexId, VertexId>> want;
  for (std::size_t k = 0; k < corners.size(); ++k) want.emplace_back(corners[k], corners[(k + 1) % corners.size()]);
  std::sort(boundary.begin(), boundary.end());
  std::sort(want.begin(), want.end());
  if (boundary != want) problem("the boundary is not the convex hull's corners in order");
  std::vector<VertexId> used(tris.begin(), tris.end()), hull = corners;
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::sort(hull.begin(), hull.end());
  if (used != hull) problem("the vertices are not exactly the hull's corners");
  r.valid = r.problems == 0;
  r.message = r.valid
      ? "valid: " + std::to_string(count) + " triangles of the " + std::to_string(corners.size()) +
          " hull corners, exactly farthest-point Delaunay"
      : "invalid: " + first + " (" + std::to_string(r.problems) + " problem" + (r.problems == 1 ? "" : "s") + ")";
  return r;
}

}  // namespace ridt
