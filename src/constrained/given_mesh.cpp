// A mesh given to be refined (constrained/given_mesh.hpp).
#include "constrained/given_mesh.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include "predicates/predicates.hpp"
#include "ridt/constrained.hpp"

namespace ridt::detail {

MeshEdges::MeshEdges(std::span<const Point> points, std::span<const VertexId> triangles)
    : tris_(triangles), start_(points.size() + 1, 0), slots_(triangles.size()) {
  const std::size_t count = triangles.size() / 3;
  for (std::size_t t = 0; t < count; ++t)
    if (orient2d(points[triangles[3 * t]], points[triangles[3 * t + 1]], points[triangles[3 * t + 2]]) <= 0)
      throw InputError("triangle " + std::to_string(t) + " (" + std::to_string(triangles[3 * t]) + ", " +
                       std::to_string(triangles[3 * t + 1]) + ", " + std::to_string(triangles[3 * t + 2]) +
                       ") is clockwise or has no area: a mesh's triangles go counter-clockwise");
  // Counted by first end, placed, then each end's sorted by second end: two slots running the
  // same way are then side by side.
  for (std::size_t s = 0; s < triangles.size(); ++s) ++start_[from(s) + 1];
  for (std::size_t v = 1; v < start_.size(); ++v) start_[v] += start_[v - 1];
  std::vector<std::uint32_t> at(start_.begin(), start_.end() - 1);
  for (std::size_t s = 0; s < triangles.size(); ++s) slots_[at[from(s)]++] = static_cast<std::uint32_t>(s);
  for (std::size_t v = 0; v + 1 < start_.size(); ++v) {
    const auto first = slots_.begin() + start_[v], last = slots_.begin() + start_[v + 1];
    std::sort(first, last, [&](std::uint32_t s, std::uint32_t u) { return to(s) < to(u); });
    if (const auto twice = std::adjacent_find(first, last, [&](auto s, auto u) { return to(s) == to(u); });
        twice != last)
      throw InputError("triangles " + std::to_string(*twice / 3) + " and " + std::to_string(twice[1] / 3) +
                       " both run from vertex " + std::to_string(v) + " to " + std::to_string(to(*twice)) +
                       ": they overlap");
  }
}

std::uint32_t MeshEdges::slot(VertexId a, VertexId b) const {
  if (a + 1 >= start_.size()) return kNoTriangle;
  const auto last = slots_.begin() + start_[a + 1];
  const auto it = std::partition_point(slots_.begin() + start_[a], last, [&](std::uint32_t s) { return to(s) < b; });
  return it != last && to(*it) == b ? *it : kNoTriangle;
}

std::vector<std::int32_t> MeshEdges::neighbours() const {
  std::vector<std::int32_t> out(tris_.size(), -1);
  for (std::size_t s = 0; s < tris_.size(); ++s)
    if (const std::uint32_t back = slot(to(s), from(s)); back != kNoTriangle)
      out[s] = static_cast<std::int32_t>(back / 3);
  return out;
}

bool GivenMesh::holds(TriangleId t, const Point& p) const {
  for (int k = 0; k < 3; ++k)
    if (orient2d(pts_[tds_.vertex(t, next3(k))], pts_[tds_.vertex(t, prev3(k))], p) < 0) return false;
  return true;
}

TriangleId GivenMesh::locate(const Point& p, TriangleId hint) const {
  TriangleId t = hint < tds_.slots() ? hint : 0;
  // The one visibility walk, never across the boundary while another edge leads on; the given
  // mesh need not be Delaunay, so a walk of more than 64 steps gives way to the search.
  int steps = 0;
  const Walked end = tds_.walk(
      t, [&](VertexId a, VertexId b) { return orient2d(pts_[a], pts_[b], p); },
      [&](Link l) {
        if (l == kNoLink) return Step::Blocked;
        return ++steps > 64 ? Step::Stop : Step::Cross;
      });
  if (end.reached) return t;
  const TriangleId found = search(p, t);
  return found != kNoTriangle ? found : hint;
}

// Breadth first from `from` across the given mesh's edges, nearest triangles first.
TriangleId GivenMesh::search(const Point& p, TriangleId from) const {
  const std::uint32_t mark = ++searches_;
  std::vector<TriangleId> queue{from};
  seen_[from] = mark;
  for (std::size_t next = 0; next < queue.size(); ++next) {
    const TriangleId t = queue[next];
    if (holds(t, p)) return t;
    for (int k = 0; k < 3; ++k)
      if (const TriangleId n = tds_.neighbour(t, k); n != kNoTriangle && seen_[n] != mark) {
        seen_[n] = mark;
        queue.push_back(n);
      }
  }
  return kNoTriangle;
}

std::int32_t GivenMesh::region_of(const Cdt& m, TriangleId t) const {
  const Point &a = m.pts[m.at(t, 0)], &b = m.pts[m.at(t, 1)], &c = m.pts[m.at(t, 2)];
  const Point centroid{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
  return static_cast<std::int32_t>(locate(centroid, static_cast<TriangleId>(std::max(m.region[t], 0))));
}

namespace {

// Whether the angle counter-clockwise from direction v -> ref to v -> u is smaller than that
// to v -> w (ref itself at angle 0, the smallest): by the half-plane left of v -> ref (with
// ref's own direction), then by orientation, exactly.
bool turns_less(const Point& v, const Point& ref, const Point& u, const Point& w) {
  auto sign = [](double a, double b) { return (a > b) - (a < b); };
  auto upper = [&](const Point& d) {
    const int o = orient2d(v, ref, d);
    return o > 0 || (o == 0 && (sign(d.x, v.x) * sign(ref.x, v.x) > 0 || sign(d.y, v.y) * sign(ref.y, v.y) > 0));
  };
  if (upper(u) != upper(w)) return upper(u);
  return orient2d(v, u, w) > 0;
}

// The same from the direction of +x.
bool before(const Point& v, const Point& u, const Point& w) {
  auto lower = [&v](const Point& p) { return !(p.y > v.y || (p.y == v.y && p.x > v.x)); };
  if (lower(u) != lower(w)) return lower(w);
  return orient2d(v, u, w) > 0;
}

// A fan of triangles about v, from direction v -> first counter-clockwise to v -> last.
struct Fan {
  VertexId v, first, last;
  bool closed;
};

// The fan about v that holds slot s (a corner of v), its corners marked seen; throws where it
// turns round v more than once. A wedge (each triangle's, from its next corner to its last)
// that ends before it starts, counted from +x, passes +x.
Fan fan_at(const Cdt& m, Link s, std::vector<std::uint8_t>& seen) {
  const VertexId v = m.tds.vertex_at(s);
  const Point& pv = m.pts[v];
  const TriangleId t0 = triangle_of(s);
  int wraps = 0;
  auto wedge = [&](TriangleId t) {
    const int i = m.corner_of(t, v);
    seen[3 * t + i] = 1;
    wraps += before(pv, m.pts[m.at(t, i + 2)], m.pts[m.at(t, i + 1)]);
    return i;
  };
  // Counter-clockwise from t0 (across the edge from its last corner to v) to the boundary or
  // round to t0; then clockwise from t0 where the fan is open.
  Fan f{v, m.at(t0, m.corner_of(t0, v) + 1), kNoVertex, false};
  for (TriangleId t = t0;;) {
    const int i = wedge(t);
    const TriangleId n = m.across(link_to(t, next3(i)));
    if (n == kNoTriangle) {
      f.last = m.at(t, i + 2);
      break;
    }
    t = n;
    if (t == t0) {
      f.closed = true;
      f.last = f.first;
      break;
    }
  }
  for (TriangleId t = t0; !f.closed;) {
    const TriangleId n = m.across(link_to(t, prev3(m.corner_of(t, v))));
    if (n == kNoTriangle) break;
    t = n;
    f.first = m.at(t, wedge(t) + 1);
  }
  const bool once = f.closed ? wraps == 1 : wraps == 0 || (wraps == 1 && before(pv, m.pts[f.last], m.pts[f.first]));
  if (!once)
    throw InputError("the triangles about vertex " + std::to_string(v) + " turn round it " +
                     (f.closed ? std::to_string(wraps) + " times" : "more than once") + ": they overlap");
  return f;
}

}  // namespace

void check_fans(const Cdt& m) {
  std::vector<std::uint8_t> seen(3 * m.size(), 0);
  std::vector<Fan> fans;
  for (Link s = 0; s < static_cast<Link>(3 * m.size()); ++s)
    if (!seen[static_cast<std::size_t>(s)]) fans.push_back(fan_at(m, s, seen));
  // Fans sharing a vertex (where the domain touches itself there), in order round it from +x:
  // none may close, and each must end before the next begins.
  std::sort(fans.begin(), fans.end(), [&](const Fan& a, const Fan& b) {
    return a.v != b.v ? a.v < b.v : before(m.pts[a.v], m.pts[a.first], m.pts[b.first]);
  });
  for (std::size_t i = 0; i < fans.size();) {
    std::size_t j = i + 1;
    while (j < fans.size() && fans[j].v == fans[i].v) ++j;
    for (std::size_t k = i; k < j && j - i > 1; ++k) {
      const Fan& f = fans[k];
      const Point& pv = m.pts[f.v];
      const VertexId next = fans[k + 1 < j ? k + 1 : i].first;
      if (f.closed || turns_less(pv, m.pts[f.first], m.pts[next], m.pts[f.last]))
        throw InputError("the triangles about vertex " + std::to_string(f.v) + " overlap: " + std::to_string(j - i) +
                         " fans of them meet there, and they cover some of one angle twice");
    }
    i = j;
  }
}

namespace {

// Pairs (a, b) of vertices below n, listed by a, each a's sorted by b (a vertex where many
// pieces of a mesh meet has many). MeshEdges lists a mesh's edge slots the same way, but asking
// it of every edge of the boundary's triangulation (a slot's end read from the triangles at
// random) took 0.15 s more of the 1.2 s that refine_mesh takes on a 10^6-vertex coastline.
class ByFirst {
 public:
  ByFirst(std::size_t n, std::span<const VertexId> pairs) : start_(n + 1, 0), to_(pairs.size() / 2) {
    for (std::size_t k = 0; k < pairs.size(); k += 2) ++start_[pairs[k] + 1];
    for (std::size_t v = 1; v <= n; ++v) start_[v] += start_[v - 1];
    std::vector<std::uint32_t> at(start_.begin(), start_.end() - 1);
    for (std::size_t k = 0; k < pairs.size(); k += 2) to_[at[pairs[k]]++] = pairs[k + 1];
    for (std::size_t v = 0; v < n; ++v)
      if (start_[v + 1] - start_[v] > 1) std::sort(to_.begin() + start_[v], to_.begin() + start_[v + 1]);
  }
  bool has(VertexId a, VertexId b) const {
    return std::binary_search(to_.begin() + start_[a], to_.begin() + start_[a + 1], b);
  }

 private:
  std::vector<std::uint32_t> start_;
  std::vector<VertexId> to_;
};

std::string at(const Point& p) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.17g, %.17g)", p.x, p.y);
  return std::string(text);
}

// How many times the mesh covers each triangle of c (the constrained triangulation of its
// boundary, `pts` its points): 0 beyond the hull, one more across a boundary edge into the side
// the mesh lies on, one less out of it. Each directed edge is a triangle's once (MeshEdges), so
// the boundary is the sum of the triangles' edges and the count is how many of them cover the
// triangle: more than once anywhere, pieces overlap (a piece inside another, or a strip that
// winds over itself).
void check_covered_once(const ConstrainedTriangulation& c, const std::vector<Point>& pts, const ByFirst& boundary) {
  constexpr std::int32_t kUnset = std::numeric_limits<std::int32_t>::min();
  std::vector<std::int32_t> cover(c.size(), kUnset);
  std::vector<std::uint32_t> queue;
  auto across = [&](std::size_t t, int j) {  // the cover's change from t's side of its edge j to the other
    const VertexId a = c.triangles[3 * t + (j + 1) % 3], b = c.triangles[3 * t + (j + 2) % 3];
    return (boundary.has(b, a) ? 1 : 0) - (boundary.has(a, b) ? 1 : 0);
  };
  for (std::size_t t = 0; t < c.size(); ++t)
    for (int j = 0; j < 3; ++j)
      if (c.neighbors[3 * t + j] < 0 && cover[t] == kUnset)
        cover[t] = -across(t, j), queue.push_back(static_cast<std::uint32_t>(t));
  for (std::size_t next = 0; next < queue.size(); ++next) {
    const std::uint32_t t = queue[next];
    if (cover[t] != 0 && cover[t] != 1) {
      const VertexId* v = &c.triangles[3 * std::size_t{t}];
      const Point middle{pts[v[0]].x / 3 + pts[v[1]].x / 3 + pts[v[2]].x / 3,
                         pts[v[0]].y / 3 + pts[v[1]].y / 3 + pts[v[2]].y / 3};
      throw InputError("pieces of the mesh overlap: it covers the area about " + at(middle) + " " +
                       std::to_string(cover[t]) + " times");
    }
    for (int j = 0; j < 3; ++j)
      if (const std::int32_t n = c.neighbors[3 * std::size_t{t} + j]; n >= 0 && cover[n] == kUnset)
        cover[n] = cover[t] + across(t, j), queue.push_back(static_cast<std::uint32_t>(n));
  }
}

// Boundary edge a-b, not whole in the constrained triangulation of the boundary (`pts`, the
// mesh's vertices `used`): a vertex lies inside it, or it crosses another where the crossing
// rounds onto an end.
[[noreturn]] void refuse_split(const std::vector<Point>& pts, const std::vector<VertexId>& used, VertexId a,
                               VertexId b) {
  const std::string edge =
      "the boundary edge from vertex " + std::to_string(used[a]) + " to " + std::to_string(used[b]);
  const Point &p = pts[a], &q = pts[b];
  for (VertexId v = 0; v < pts.size(); ++v) {
    const Point& r = pts[v];
    const bool between = (std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x)) &&
        (std::min(p.y, q.y) <= r.y && r.y <= std::max(p.y, q.y));
    if (v != a && v != b && between && orient2d(p, q, r) == 0)
      throw InputError(edge + " passes through vertex " + std::to_string(used[v]) + " at " + at(r) +
                       ": pieces of the mesh overlap, or one meets another inside an edge");
  }
  throw InputError(edge + " crosses another next to its ends: pieces of the mesh overlap");
}

}  // namespace

void check_one_layer(std::span<const Point> points, std::span<const VertexId> triangles,
                     std::span<const std::int32_t> neighbours, const Options& options) {
  // The boundary's vertices, renumbered, and its edges, each run with the mesh on its left.
  std::vector<VertexId> id(points.size(), kNoVertex), used, segments;
  for (std::size_t s = 0; s < triangles.size(); ++s) {
    if (neighbours[s] >= 0) continue;
    const VertexId ends[2] = {triangles[s - s % 3 + (s + 1) % 3], triangles[s - s % 3 + (s + 2) % 3]};
    for (const VertexId v : ends)
      if (id[v] == kNoVertex) id[v] = static_cast<VertexId>(used.size()), used.push_back(v);
    segments.push_back(id[ends[0]]), segments.push_back(id[ends[1]]);
  }
  std::vector<Point> pts(used.size());
  for (std::size_t k = 0; k < used.size(); ++k) pts[k] = points[used[k]];
  Options plain;
  plain.method = options.method, plain.threads = options.threads, plain.memory_limit = options.memory_limit;
  Domain all;
  all.convex_hull = true;
  const ConstrainedTriangulation c = triangulate_constrained(pts, segments, plain, all, {});
  if (!c.duplicates.empty())
    throw InputError("vertices " + std::to_string(used[c.duplicates[0].dropped]) + " and " +
                     std::to_string(used[c.duplicates[0].kept]) + " of the mesh's boundary lie at one point " +
                     at(pts[c.duplicates[0].kept]) + ": pieces of it overlap there");
  if (c.crossings > 0)
    throw InputError("edges of the mesh's boundary cross at " + at(c.steiner[0]) + ": pieces of it overlap");
  // Every boundary edge whole: one of c's segment edges.
  const ByFirst boundary(pts.size(), segments), fixed(pts.size(), c.edges);
  for (std::size_t k = 0; k < segments.size(); k += 2)
    if (const VertexId a = segments[k], b = segments[k + 1]; !fixed.has(std::min(a, b), std::max(a, b)))
      refuse_split(pts, used, a, b);
  check_covered_once(c, pts, boundary);
}

}  // namespace ridt::detail
