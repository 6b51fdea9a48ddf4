// check_sphere (ridt/sphere.hpp): a triangulation on the sphere checked to be the convex hull
// of its points, by other means than triangulate_sphere finds it. A closed surface (each
// directed edge once, its reverse once, one piece, Euler's V - E + F = 2) whose triangles all
// face away from an inner point and wrap round it once (their solid angles from it sum to
// 4 pi) projects onto the directions from that point one to one: it is star-shaped. Star-shaped
// with every edge convex, it is convex, so it is the hull of its corners; every other point
// then lies below the triangle whose cone holds it.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "check/parts.hpp"
#include "predicates/orient3d.hpp"
#include "ridt/sphere.hpp"
#include "tds/ids.hpp"

namespace ridt {

namespace {

using detail::kNoVertex;
using detail::next3;
using detail::orient3d;
using detail::prev3;

bool lex_less3(const Point3& a, const Point3& b) {
  return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
}

}  // namespace

CheckResult check_sphere(std::span<const Point3> pts, std::span<const VertexId> tris) {
  detail::Report report;
  const std::size_t n = pts.size(), m = tris.size() / 3;
  if (tris.size() % 3 != 0) {
    report.problem("the triangles' array holds ", tris.size(), " numbers, not a multiple of three");
    return report.result();
  }
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(pts[i].x) || !std::isfinite(pts[i].y) || !std::isfinite(pts[i].z)) {
      report.problem("point ", i, " is not finite");
      return report.result();
    }
  for (const VertexId v : tris)
    if (v >= n) {
      report.problem("corner ", v, " is not a point's index (", n, " points)");
      return report.result();
    }
  if (m < 4) {
    report.problem(m, " triangles: a closed surface has at least four");
    return report.result();
  }
  // Ranks: the points' lexicographic order, equal points one rank (the perturbation's key).
  std::vector<VertexId> order(n);
  std::iota(order.begin(), order.end(), VertexId{0});
  std::sort(order.begin(), order.end(), [&](VertexId a, VertexId b) { return lex_less3(pts[a], pts[b]); });
  std::vector<std::uint32_t> rank(n);
  for (std::size_t k = 0, r = 0; k < n; ++k) {
    if (k > 0 && !(pts[order[k - 1]] == pts[order[k]])) ++r;
    rank[order[k]] = static_cast<std::uint32_t>(r);
  }
  // Corners: distinct points, each used by one index.
  std::vector<std::uint8_t> corner(n, 0);
  for (const VertexId v : tris) corner[v] = 1;
  std::vector<VertexId> owner(n, kNoVertex);  // by rank: the corner that stands for it
  std::size_t corners = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (!corner[v]) continue;
    ++corners;
    if (owner[rank[v]] != kNoVertex) {
      report.problem("corners ", owner[rank[v]], " and ", v, " are the same point");
      return report.result();
    }
    owner[rank[v]] = static_cast<VertexId>(v);
  }
  // Every directed edge once, its reverse once: the triangle across each edge.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> edges(3 * m);  // (tail, head), slot 3f + i
  for (std::size_t f = 0; f < m; ++f)
    for (int i = 0; i < 3; ++i) {
      const std::uint64_t a = tris[3 * f + next3(i)], b = tris[3 * f + prev3(i)];
      if (a == b || tris[3 * f + i] == a) {
        report.problem("triangle ", f, " repeats a corner");
        return report.result();
      }
      edges[3 * f + i] = {a << 32 | b, static_cast<std::uint32_t>(3 * f + i)};
    }
  std::sort(edges.begin(), edges.end());
  for (std::size_t k = 1; k < edges.size(); ++k)
    if (edges[k].first == edges[k - 1].first) {
      report.problem("edge ", edges[k].first >> 32, "-", edges[k].first & 0xffffffffu, " is used twice the same way");
      return report.result();
    }
  std::vector<std::uint32_t> across(3 * m);
  for (const auto& [key, slot] : edges) {
    const std::uint64_t reverse = (key & 0xffffffffu) << 32 | key >> 32;
    const auto at = std::lower_bound(edges.begin(), edges.end(), std::pair{reverse, std::uint32_t{0}});
    if (at == edges.end() || at->first != reverse) {
      report.problem("edge ", key >> 32, "-", key & 0xffffffffu, " has no triangle on its other side");
      return report.result();
    }
    across[slot] = at->second;
  }
  // One piece, and a sphere: V - E + F = 2.
  std::vector<std::uint8_t> reached(m, 0);
  std::vector<std::uint32_t> todo{0};
  reached[0] = 1;
  std::size_t pieces = 1;
  while (!todo.empty()) {
    const std::uint32_t f = todo.back();
    todo.pop_back();
    for (int i = 0; i < 3; ++i)
      if (const std::uint32_t g = across[3 * f + i] / 3; !reached[g]) reached[g] = 1, todo.push_back(g);
  }
  if (std::count(reached.begin(), reached.end(), 1) != static_cast<std::ptrdiff_t>(m)) ++pieces;
  if (pieces != 1 || corners + m != 3 * m / 2 + 2) {
    report.problem(pieces != 1 ? "the triangles make more than one surface" : "the surface is not a sphere (",
                   pieces != 1 ? "" : std::to_string(corners) + " corners, " + std::to_string(m) + " triangles)");
    return report.result();
  }
  // Every edge convex: the apex across below the triangle's plane (perturbed as the
  // triangulation is).
  auto p = [&](VertexId v) -> const Point3& { return pts[v]; };
  for (std::size_t f = 0; f < m && report.problems() < 100; ++f)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t l = across[3 * f + i];
      if (l < 3 * f) continue;  // each edge once
      const VertexId a = tris[3 * f], b = tris[3 * f + 1], c = tris[3 * f + 2], d = tris[l];
      if (detail::orient3d_sos(p(a), p(b), p(c), p(d), rank[a], rank[b], rank[c], rank[d]) <= 0)
        report.problem("edge ", tris[3 * f + next3(i)], "-", tris[3 * f + prev3(i)], " is not convex");
    }
  if (report.problems() > 0) return report.result();
  // An inner point: the corners' centroid; every triangle faces away from it, and their solid
  // angles from it make one turn of the sphere.
  long double sx = 0, sy = 0, sz = 0;
  for (std::size_t v = 0; v < n; ++v)
    if (corner[v]) sx += pts[v].x, sy += pts[v].y, sz += pts[v].z;
  const Point3 o{static_cast<double>(sx / corners), static_cast<double>(sy / corners),
                 static_cast<double>(sz / corners)};
  double total = 0;
  for (std::size_t f = 0; f < m; ++f) {
    const Point3 &a = pts[tris[3 * f]], &b = pts[tris[3 * f + 1]], &c = pts[tris[3 * f + 2]];
    if (orient3d(a, b, c, o) <= 0) {
      report.problem("triangle ", f, " does not face away from the corners' centroid");
      return report.result();
    }
    const Point3 u{a.x - o.x, a.y - o.y, a.z - o.z}, v{b.x - o.x, b.y - o.y, b.z - o.z},
        w{c.x - o.x, c.y - o.y, c.z - o.z};
    auto dot = [](const Point3& x, const Point3& y) { return x.x * y.x + x.y * y.y + x.z * y.z; };
    const double lu = std::sqrt(dot(u, u)), lv = std::sqrt(dot(v, v)), lw = std::sqrt(dot(w, w));
    const double triple = u.x * (v.y * w.z - v.z * w.y) + u.y * (v.z * w.x - v.x * w.z) + u.z * (v.x * w.y - v.y * w.x);
    total += 2 * std::atan2(triple, lu * lv * lw + dot(u, v) * lw + dot(u, w) * lv + dot(v, w) * lu);
  }
  const double turns = total / (4 * 3.14159265358979323846);
  if (!(std::fabs(turns - 1) < 0.5)) {
    report.problem("the triangles wrap round the inner point ", std::lround(turns), " times, not once");
    return report.result();
  }
  // Every point not a corner: a copy of one, or below the triangle whose cone from o holds it
  // (and below every triangle whose closed cone does). The cones are found by walking.
  auto side = [&](VertexId a, VertexId b, const Point3& q) { return -orient3d(o, pts[a], pts[b], q); };
  auto holds = [&](std::size_t f, const Point3& q) {
    const VertexId* t = tris.data() + 3 * f;
    return side(t[0], t[1], q) >= 0 && side(t[1], t[2], q) >= 0 && side(t[2], t[0], q) >= 0;
  };
  std::size_t last = 0, hidden = 0;
  std::vector<std::uint32_t> stamp(m, 0);
  std::uint32_t epoch = 0;
  for (std::size_t q = 0; q < n && report.problems() < 100; ++q) {
    if (corner[q]) continue;
    if (owner[rank[q]] != kNoVertex) continue;  // a copy of a corner
    ++hidden;
    const Point3& x = pts[q];
    std::size_t f = last, steps = 0;
    for (bool moved = true; moved && steps < 4 * m;) {
      moved = false;
      for (int i = 0; i < 3 && !moved; ++i)
        if (side(tris[3 * f + next3(i)], tris[3 * f + prev3(i)], x) < 0) f = across[3 * f + i] / 3, moved = true;
      ++steps;
    }
    if (!holds(f, x)) {
      f = 0;
      while (f < m && !holds(f, x)) ++f;
    }
    last = f;
    ++epoch;
    todo.assign(1, static_cast<std::uint32_t>(f));
    stamp[f] = epoch;
    while (!todo.empty()) {
      const std::uint32_t g = todo.back();
      todo.pop_back();
      const VertexId a = tris[3 * g], b = tris[3 * g + 1], c = tris[3 * g + 2];
      if (detail::orient3d_sos(p(a), p(b), p(c), x, rank[a], rank[b], rank[c], rank[q]) < 0) {
        report.problem("point ", q, " is outside the hull (above triangle ", g, ")");
        break;
      }
      for (int i = 0; i < 3; ++i)
        if (const std::uint32_t h = across[3 * g + i] / 3; stamp[h] != epoch && holds(h, x))
          stamp[h] = epoch, todo.push_back(h);
    }
  }
  return report.result("valid: the convex hull of " + std::to_string(corners) + " points, " + std::to_string(m) +
                       " triangles" + (hidden > 0 ? ", " + std::to_string(hidden) + " inside it" : ""));
}

}  // namespace ridt
