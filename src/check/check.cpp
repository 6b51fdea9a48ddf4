// The validator: independent of the triangulator beyond the predicates. It builds its own
// edge table and its own convex hull (Andrew's monotone chain with exact orientation), and
// for constrained triangulations follows each segment along the edges.
#include "ridt/check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "check/parts.hpp"
#include "predicates/predicates.hpp"

namespace ridt {
namespace {

using detail::check_edges;
using detail::check_hull_and_count;
using detail::check_triangles;
using detail::Distinct;
using detail::Edge;
using detail::exactly_scaled;
using detail::hull_with_collinear;
using detail::Report;

using detail::incircle;
using detail::orient2d;

Distinct group_distinct(std::span<const Point> pts) {
  const std::size_t n = pts.size();
  // The coordinates travel with the index, so the comparisons read memory in order.
  struct Entry {
    Point p;
    VertexId i;
  };
  std::vector<Entry> entries(n);
  for (std::size_t i = 0; i < n; ++i) entries[i] = {pts[i], static_cast<VertexId>(i)};
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return detail::lex_less(a.p, b.p) || (a.p == b.p && a.i < b.i); });
  std::vector<VertexId> sorted(n);
  for (std::size_t i = 0; i < n; ++i) sorted[i] = entries[i].i;
  return detail::grouped(pts, std::move(sorted));
}

// For each point, the member of its group of equal points that stands for it: the one that
// is a vertex, else the group's first.
std::vector<VertexId> standing(std::span<const Point> pts, const Distinct& d, const std::vector<std::uint8_t>& used) {
  std::vector<VertexId> stand(pts.size());
  for (std::size_t i = 0, g = 0; i < pts.size(); i = g) {
    VertexId v = d.sorted[i];
    for (g = i; g < pts.size() && pts[d.sorted[g]] == pts[d.sorted[i]]; ++g)
      if (used[d.sorted[g]]) v = d.sorted[g];
    for (std::size_t k = i; k < g; ++k) stand[d.sorted[k]] = v;
  }
  return stand;
}

// The edges that the segments cover, (lo, hi) sorted: each segment followed from end to end
// along triangle edges through the vertices that lie exactly on it. Reports a segment that is
// not a union of edges, or an index out of range.
std::vector<Edge> segment_edges(std::span<const Point> pts, std::span<const VertexId> tris,
                                std::span<const VertexId> segments, const std::vector<VertexId>& stand,
                                Report& report) {
  std::vector<std::vector<VertexId>> around(pts.size());
  for (std::size_t k = 0; k < tris.size(); ++k) {  // both ways: a hull edge is run one way only
    const VertexId a = tris[k], b = tris[k % 3 == 2 ? k - 2 : k + 1];
    around[a].push_back(b), around[b].push_back(a);
  }
  std::vector<Edge> covered;
  for (std::size_t s = 0; s + 1 < segments.size(); s += 2) {
    if (segments[s] >= pts.size() || segments[s + 1] >= pts.size()) {
      report.problem("segment ", s / 2, " refers to a point that is not one of the ", pts.size());
      continue;
    }
    const VertexId a = stand[segments[s]], b = stand[segments[s + 1]];
    if (a == b) continue;  // its ends coincide: no segment
    // Positions along a -> b, compared exactly: by x, or by y on a vertical segment.
    const bool by_x = pts[a].x != pts[b].x;
    const double sign = (by_x ? pts[b].x - pts[a].x : pts[b].y - pts[a].y) > 0 ? 1 : -1;
    auto key = [&](VertexId v) { return sign * (by_x ? pts[v].x : pts[v].y); };
    for (VertexId at = a; at != b;) {
      VertexId next = at;  // the nearest neighbour on the segment, past `at`, not past b
      for (const VertexId c : around[at])
        if (orient2d(pts[a], pts[b], pts[c]) == 0 && key(c) > key(at) && key(c) <= key(b) &&
            (next == at || key(c) < key(next)))
          next = c;
      if (next == at) {
        report.problem("segment ", s / 2, " (", segments[s], "-", segments[s + 1],
                       ") is not a union of edges: no edge ", "goes on from vertex ", at, " towards ", b);
        break;
      }
      covered.emplace_back(std::min(at, next), std::max(at, next));
      at = next;
    }
  }
  std::sort(covered.begin(), covered.end());
  covered.erase(std::unique(covered.begin(), covered.end()), covered.end());
  return covered;
}

// Every distinct point a vertex exactly once (when there are triangles). Returns the number
// of vertices.
std::size_t check_vertices(std::span<const Point> pts, const Distinct& d, const std::vector<std::uint8_t>& used,
                           bool any_triangle, Report& report) {
  const std::size_t n = pts.size();
  std::size_t vertices = 0;
  for (std::size_t i = 0, g = 0; i < n; i = g) {
    std::size_t in_use = 0;
    for (g = i; g < n && pts[d.sorted[g]] == pts[d.sorted[i]]; ++g) in_use += used[d.sorted[g]];
    vertices += in_use > 0;
    if (any_triangle && in_use == 0) report.problem("point ", d.sorted[i], " is not a vertex of any triangle");
    if (in_use > 1) report.problem("point ", d.sorted[i], " appears as ", in_use, " vertices");
  }
  return vertices;
}

}  // namespace

CheckResult check_constrained(std::span<const Point> input, std::span<const VertexId> tris,
                              std::span<const VertexId> segments) {
  // The edge table files 3 sides a triangle and names a side by 2 * triangle + direction,
  // both in 32 bits: refused before anything is counted, where either would wrap.
  if (tris.size() / 3 > kCheckMaxTriangles) {
    throw InputError(std::to_string(tris.size() / 3) +
                     " triangles are more than the validator "
                     "takes (at most " +
                     std::to_string(kCheckMaxTriangles) + ")");
  }
  const std::vector<Point> scaled = exactly_scaled(input);
  const std::span<const Point> pts = scaled.empty() ? input : std::span<const Point>(scaled);
  const std::size_t count = tris.size() / 3;
  Report report;
  if (tris.size() % 3 != 0) report.problem("the triangle list is not a multiple of 3 long");
  const Distinct distinct = group_distinct(pts);
  std::vector<std::uint8_t> used(pts.size(), 0);
  check_triangles(pts, tris, used, report);
  if (report.problems() > 0) return report.result();  // what follows needs sound triangles
  if (segments.size() % 2 != 0) report.problem("the segment list is not a multiple of 2 long");
  const std::vector<Edge> constrained = segments.empty()
      ? std::vector<Edge>{}
      : segment_edges(pts, tris, segments, standing(pts, distinct, used), report);
  std::vector<Edge> boundary = check_edges(pts, tris, constrained, report);
  const std::size_t vertices = check_vertices(pts, distinct, used, count > 0, report);
  check_hull_and_count(pts, distinct, std::move(boundary), count, vertices, report);

  std::ostringstream s;
  s << "valid: " << count << " triangles, " << vertices << " vertices of " << pts.size() << " points ("
    << distinct.first.size() << " distinct), exactly "
    << (segments.empty() ? "Delaunay"
                         : "constrained Delaunay with " + std::to_string(segments.size() / 2) + " segments");
  if (distinct.degenerate)
    s << " (no triangle: " << (distinct.first.size() < 3 ? "fewer than three distinct points" : "all points collinear")
      << ")";
  return report.result(s.str());
}

CheckResult check(std::span<const Point> points, std::span<const VertexId> triangles) {
  return check_constrained(points, triangles, {});
}

}  // namespace ridt
