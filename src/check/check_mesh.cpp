// check_mesh (ridt/check.hpp): a constrained triangulation or quality mesh validated against
// what it was asked: its segment edges, the input's segments as chains of them, holes empty,
// angles and areas.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "check/parts.hpp"
#include "predicates/predicates.hpp"
#include "ridt/check.hpp"

namespace ridt {
namespace {

using detail::Edge;
using detail::orient2d;
using detail::Report;

std::uint64_t key(VertexId a, VertexId b) { return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b); }

// Boundary edges that are no segment's must lie on the convex hull of the vertices.
void check_boundary(std::span<const Point> pts, const std::vector<std::uint8_t>& used,
                    const std::vector<Edge>& boundary, const std::unordered_set<std::uint64_t>& segment,
                    Report& report) {
  std::vector<Edge> open;
  for (const Edge& e : boundary)
    if (!segment.count(key(e.first, e.second))) open.push_back(e);
  if (open.empty()) return;
  std::vector<VertexId> sorted;
  for (VertexId v = 0; v < pts.size(); ++v)
    if (used[v]) sorted.push_back(v);
  std::sort(sorted.begin(), sorted.end(), [&](VertexId a, VertexId b) { return detail::lex_less(pts[a], pts[b]); });
  const std::vector<VertexId> hull = detail::hull_with_collinear(pts, sorted);
  std::unordered_set<std::uint64_t> on_hull;
  for (std::size_t i = 0; i < hull.size(); ++i)
    on_hull.insert((std::uint64_t{hull[i]} << 32) | hull[(i + 1) % hull.size()]);
  for (const Edge& e : open)
    if (!on_hull.count((std::uint64_t{e.first} << 32) | e.second))
      report.problem("boundary edge ", e.first, "-", e.second, " is neither a segment's nor on the convex hull");
}

// The segment edges as lists of neighbours.
std::vector<std::vector<VertexId>> adjacency(std::size_t n, std::span<const VertexId> edges) {
  std::vector<std::vector<VertexId>> adj(n);
  for (std::size_t k = 0; k + 1 < edges.size(); k += 2)
    adj[edges[k]].push_back(edges[k + 1]), adj[edges[k + 1]].push_back(edges[k]);
  return adj;
}

// A piece of input segment `segment` from u to w that no segment edge joins: it must lie
// outside the mesh (in a hole or the exterior).
struct Gap {
  VertexId u, w;
  std::size_t segment;
};

// Where p lies along a -> b, exactly: its coordinate on the axis a -> b moves most along (x
// where it moves at least as much in x), signed so that it grows from a to b.
double along_key(const Point& a, const Point& b, const Point& p) {
  const bool by_x = std::fabs(b.x - a.x) >= std::fabs(b.y - a.y);
  const double from = by_x ? a.x : a.y, to = by_x ? b.x : b.y, at = by_x ? p.x : p.y;
  return to >= from ? at : -at;
}

// How far p lies off the line a-b, in units of the coordinates' magnitudes: an error of r
// times |x| in x and r times |y| in y moves p by r of this measure at most, where |x| and |y|
// are, for a point computed from the segment's ends (`computed`: split off it, on the segment
// or its pieces, from either end), the largest of a's, b's and p's; for an input point (on
// the segment exactly, or where a crossing within a few units of its own coordinates was
// merged into it), p's own or, where larger, those a and b give by interpolation at p's place
// along a-b (on a segment from near 10^19 to (10, 0), a vertex 4 units from (10, 0) is far off
// it). Each coordinate on its own scale: a point on a long segment almost along an axis may be
// off by much along the segment, but only by the other coordinate's roundings across it. No
// scale is below `least`: where the mesher worked in coordinates scaled by a power of two, its
// roundings below the least normal double there are absolute, and `least` is that double in
// these coordinates.
double off_line(const Point& a, const Point& b, const Point& p, long double least, bool computed) {
  // The cross product from the end nearer p: from the far one, its two terms could be some
  // 10^20 times it, and long double's roundings of them as large as the measure itself.
  using L = long double;
  const L ex = L{b.x} - a.x, ey = L{b.y} - a.y;
  const L e2 = ex * ex + ey * ey;
  const L t = e2 > 0 ? std::clamp((ex * (L{p.x} - a.x) + ey * (L{p.y} - a.y)) / e2, L(0), L(1)) : L(0);
  const Point& n = t < 0.5 ? a : b;
  const L cross = ex * (L{p.y} - n.y) - ey * (L{p.x} - n.x);
  auto scale = [&](double pa, double pb, double pp) {
    const L ends = computed ? std::max(std::fabs(pa), std::fabs(pb)) : (1 - t) * std::fabs(pa) + t * std::fabs(pb);
    return std::max({ends, L(std::fabs(pp)), least});
  };
  const L sx = scale(a.x, b.x, p.x), sy = scale(a.y, b.y, p.y);
  const L bound = std::fabs(L{b.x} - a.x) * sy + std::fabs(L{b.y} - a.y) * sx;
  return cross == 0 ? 0 : static_cast<double>(std::fabs(cross) / bound);
}

// Where p lies along a -> b, in order: along_key, then, where that ties, the coordinate on the
// other axis, signed the same way (a point a rounding beside an end of a steep segment lies at
// that end's along_key, yet ahead of it or behind).
std::pair<double, double> along_keys(const Point& a, const Point& b, const Point& p) {
  const bool by_x = std::fabs(b.x - a.x) >= std::fabs(b.y - a.y);
  const double from = by_x ? a.y : a.x, to = by_x ? b.y : b.x, at = by_x ? p.y : p.x;
  return {along_key(a, b, p), to >= from ? at : -at};
}

// Whether the open segment u-w passes through the inside of triangle a-b-c (counter-
// clockwise): no line of an edge of either separates them (for two convex sets in the plane,
// one of those lines does where they are apart).
bool passes_inside(const Point& u, const Point& w, const Point& a, const Point& b, const Point& c) {
  const Point* t[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i)
    if (orient2d(*t[i], *t[(i + 1) % 3], u) <= 0 && orient2d(*t[i], *t[(i + 1) % 3], w) <= 0) return false;
  const int oa = orient2d(u, w, a), ob = orient2d(u, w, b), oc = orient2d(u, w, c);
  return !((oa >= 0 && ob >= 0 && oc >= 0) || (oa <= 0 && ob <= 0 && oc <= 0));
}

// Whether p lies on the open segment u-w.
bool strictly_on(const Point& u, const Point& w, const Point& p) {
  if (orient2d(u, w, p) != 0) return false;
  const bool by_x = u.x != w.x;
  const double lo = by_x ? std::min(u.x, w.x) : std::min(u.y, w.y), hi = by_x ? std::max(u.x, w.x) : std::max(u.y, w.y);
  const double at = by_x ? p.x : p.y;
  return at > lo && at < hi;
}

// The triangles sorted by their least x, for the gaps of segments through holes: the first
// that an open segment u-w passes through (or through one of whose vertices), tested against
// those whose x range can meet its own.
class TrianglesByX {
 public:
  TrianglesByX(std::span<const Point> pts, std::span<const VertexId> tris) : pts_(pts), tris_(tris) {}

  std::int64_t through(VertexId gu, VertexId gw) {
    if (by_x_.empty() && !tris_.empty()) sort();
    const Point &u = pts_[gu], &w = pts_[gw];
    auto it = std::lower_bound(by_x_.begin(), by_x_.end(), std::pair{std::min(u.x, w.x) - widest_, std::uint32_t{0}});
    for (; it != by_x_.end() && it->first <= std::max(u.x, w.x); ++it) {
      const VertexId* v = &tris_[3 * std::size_t{it->second}];
      if (passes_inside(u, w, pts_[v[0]], pts_[v[1]], pts_[v[2]]) || strictly_on(u, w, pts_[v[0]]) ||
          strictly_on(u, w, pts_[v[1]]) || strictly_on(u, w, pts_[v[2]]))
        return it->second;
    }
    return -1;
  }

 private:
  void sort() {
    by_x_.resize(tris_.size() / 3);
    for (std::size_t t = 0; t < by_x_.size(); ++t) {
      const Point &a = pts_[tris_[3 * t]], &b = pts_[tris_[3 * t + 1]], &c = pts_[tris_[3 * t + 2]];
      by_x_[t] = {std::min({a.x, b.x, c.x}), static_cast<std::uint32_t>(t)};
      widest_ = std::max(widest_, std::max({a.x, b.x, c.x}) - by_x_[t].first);
    }
    std::sort(by_x_.begin(), by_x_.end());
  }

  std::span<const Point> pts_;
  std::span<const VertexId> tris_;
  std::vector<std::pair<double, std::uint32_t>> by_x_;
  double widest_ = 0;
};

// A segment that runs through a hole or the exterior is a chain where it lies in the mesh,
// followed from a: from each vertex by a segment edge to a point near the segment and ahead
// along it, the nearest to its line first; where there is none, across a gap to a point near
// the segment ahead, both on the boundary (or in no triangle), the gap through no triangle and
// no vertex. Depth first: another segment's chain may run within rounding of this one's (two
// segments at a hair's angle, or crossing near a shared end), and a step onto it ends where
// it leaves this segment, and the search goes back to take the other. Where no way reaches b,
// the way that jumps each gap to the next point ahead is reported: its first gap through a
// triangle, or, where it stops, the segment as no chain.
template <class Near>
void follow_across_gaps(std::span<const Point> pts, VertexId a, VertexId b,
                        const std::vector<std::vector<VertexId>>& adj,
                        std::span<const std::pair<double, VertexId>> by_x, double x0, double x1,
                        const std::vector<std::uint8_t>& on_boundary, Near near, TrianglesByX& triangles,
                        std::size_t segment, const MeshSpec& spec, Report& report) {
  constexpr VertexId kNone = std::numeric_limits<VertexId>::max();
  using Key = std::pair<double, double>;
  auto key = [&](VertexId v) { return along_keys(pts[a], pts[b], pts[v]); };
  auto off = [&](VertexId v) { return std::fabs(detail::doubled_area(pts[a], pts[b], pts[v])); };
  auto better = [&](VertexId w, VertexId than) {  // ahead sooner, then nearer the line
    return than == kNone || key(w) < key(than) || (key(w) == key(than) && off(w) < off(than));
  };
  auto nearer = [&](VertexId w, VertexId than) {
    return off(w) < off(than) || (off(w) == off(than) && better(w, than));
  };
  // The points near the segment, by key: those with a segment edge within near's x range
  // [x0, x1] (by_x: every such point, by x), so that many segments in holes cost n log n.
  std::vector<std::pair<Key, VertexId>> ahead{{key(b), b}};
  for (auto it = std::lower_bound(by_x.begin(), by_x.end(), std::pair{x0, VertexId{0}});
       it != by_x.end() && it->first <= x1; ++it)
    if (it->second != b && near(it->second)) ahead.push_back({key(it->second), it->second});
  std::sort(ahead.begin(), ahead.end());
  auto after = [&](VertexId u) {
    return std::upper_bound(ahead.begin(), ahead.end(), std::pair{key(u), std::numeric_limits<VertexId>::max()});
  };
  // `checked`: gaps only through no triangle, to any of the next few points ahead; else the
  // one way that jumps to the next, its gaps kept to report.
  auto search = [&](bool checked, std::vector<Gap>& gaps) {
    std::unordered_map<VertexId, std::pair<VertexId, bool>> from{{a, {kNone, false}}};  // from where, across a gap
    std::vector<VertexId> todo{a}, steps;
    while (!todo.empty()) {
      const VertexId u = todo.back();
      todo.pop_back();
      if (u == b) {
        for (VertexId v = b; v != a; v = from[v].first)
          if (from[v].second) gaps.push_back({from[v].first, v, segment});
        return true;
      }
      steps.clear();
      for (const VertexId w : adj[u])
        if (key(w) > key(u) && near(w) && !from.count(w)) steps.push_back(w);
      if (!steps.empty()) {  // the nearest to the line taken first: pushed last
        std::sort(steps.begin(), steps.end(), [&](VertexId w, VertexId v) { return nearer(v, w); });
        for (const VertexId w : steps) from[w] = {u, false}, todo.push_back(w);
        continue;
      }
      if (!on_boundary[u]) continue;  // (unused vertices count as on the boundary)
      if (checked) {
        for (auto it = after(u); it != ahead.end() && steps.size() < 16; ++it)
          if (on_boundary[it->second] && !from.count(it->second) && triangles.through(u, it->second) < 0)
            steps.push_back(it->second);
        for (auto w = steps.rbegin(); w != steps.rend(); ++w) from[*w] = {u, true}, todo.push_back(*w);
        continue;
      }
      VertexId next = kNone;
      const auto it = after(u);
      for (auto other = it; other != ahead.end() && other->first == it->first; ++other)
        if (better(other->second, next)) next = other->second;
      if (next == kNone) next = b;  // at b's place along the segment already (another end there)
      if (!on_boundary[next] || from.count(next)) continue;
      from[next] = {u, true};
      todo.push_back(next);
    }
    return false;
  };
  std::vector<Gap> gaps;
  if (search(true, gaps)) return;
  gaps.clear();
  if (!search(false, gaps)) {
    report.problem("segment ", segment, " (", spec.segments[2 * segment], "-", spec.segments[2 * segment + 1],
                   ") is not a chain of segment edges");
    return;
  }
  for (auto g = gaps.rbegin(); g != gaps.rend(); ++g)
    if (const std::int64_t t = triangles.through(g->u, g->w); t >= 0) {
      report.problem("segment ", segment, " (", spec.segments[2 * segment], "-", spec.segments[2 * segment + 1],
                     ") runs through triangle ", t, " between points ", g->u, " and ", g->w, " with no segment edge");
      return;
    }
  report.problem("segment ", segment, " (", spec.segments[2 * segment], "-", spec.segments[2 * segment + 1],
                 ") is not a chain of segment edges");
}

// Each input segment a-b a chain of segment edges: a search from a through points near the
// segment (between its ends along it, within its box grown by 10^-6 of its length): input
// points on its line up to a few units in the last place (a crossing rounded onto one), added
// points up to the roundings that splits of splits gather (2^-40 of the coordinates: a point
// on another segment is farther).
void check_chains(std::span<const Point> pts, std::span<const VertexId> tris, const MeshSpec& spec, long double least,
                  const std::vector<std::uint8_t>& used, const std::vector<std::uint8_t>& on_boundary, Report& report) {
  const auto adj = adjacency(pts.size(), spec.edges);
  const std::size_t input = spec.input_points == 0 ? pts.size() : spec.input_points;
  std::unordered_map<std::uint64_t, VertexId> vertex_at;  // an unused duplicate stands for the used one
  auto bits = [](const Point& p) { return std::hash<double>{}(p.x) * 31 + std::hash<double>{}(p.y); };
  for (VertexId v = 0; v < pts.size(); ++v)
    if (used[v]) vertex_at.emplace(bits(pts[v]), v);
  auto stand = [&](VertexId v) {
    const auto it = vertex_at.find(bits(pts[v]));
    return used[v] || it == vertex_at.end() || !(pts[it->second] == pts[v]) ? v : it->second;
  };
  std::vector<std::pair<double, VertexId>> by_x;  // the points with a segment edge, by x (across_gaps)
  for (VertexId v = 0; v < pts.size(); ++v)
    if (!adj[v].empty()) by_x.push_back({pts[v].x, v});
  std::sort(by_x.begin(), by_x.end());
  std::vector<std::uint32_t> seen(pts.size(), 0);
  TrianglesByX triangles(pts, tris);  // sorted when a segment first runs through a hole
  for (std::size_t s = 0; s + 1 < spec.segments.size(); s += 2) {
    if (spec.segments[s] >= input || spec.segments[s + 1] >= input) {
      report.problem("segment ", s / 2, " refers to a point that is not one of the input's ", input);
      continue;
    }
    const VertexId a = stand(spec.segments[s]), b = stand(spec.segments[s + 1]);
    if (a == b || pts[a] == pts[b]) continue;  // (two equal points, both unused)
    const double length = std::max(std::fabs(pts[a].x - pts[b].x), std::fabs(pts[a].y - pts[b].y));
    const double grow = 1e-6 * length;
    const double x0 = std::min(pts[a].x, pts[b].x) - grow, x1 = std::max(pts[a].x, pts[b].x) + grow;
    const double y0 = std::min(pts[a].y, pts[b].y) - grow, y1 = std::max(pts[a].y, pts[b].y) + grow;
    const double from = along_key(pts[a], pts[b], pts[a]), to = along_key(pts[a], pts[b], pts[b]);
    auto near = [&](VertexId v) {
      const Point& p = pts[v];
      if (v == b) return true;
      if (!(p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1)) return false;
      // Between the ends along the segment, up to 2^-40 of each end's coordinate (a crossing
      // rounded past an end): a point beside a very long segment's end, within that segment's
      // rounding of its line, is not on it.
      const double at = along_key(pts[a], pts[b], p);
      if (!(at > from - 0x1p-40 * std::fabs(from) && at < to + 0x1p-40 * std::fabs(to))) return false;
      // An added point within 2^-40 (roundings upon roundings); an input point on it exactly,
      // or where a crossing within a few units in the last place of its coordinates was merged
      // into it: within 2^-49 (the merge's 4 units, the crossing's rounding).
      return orient2d(pts[a], pts[b], p) == 0 ||
          (v >= input ? off_line(pts[a], pts[b], p, least, true) <= 0x1p-40
                      : off_line(pts[a], pts[b], p, least, false) <= 0x1p-49);
    };
    const auto stamp = static_cast<std::uint32_t>(s / 2 + 1);
    std::vector<VertexId> todo{a};
    seen[a] = stamp;
    while (!todo.empty() && seen[b] != stamp) {
      const VertexId v = todo.back();
      todo.pop_back();
      for (const VertexId w : adj[v])
        if (seen[w] != stamp && near(w)) seen[w] = stamp, todo.push_back(w);
    }
    if (seen[b] != stamp)
      follow_across_gaps(pts, a, b, adj, by_x, x0, x1, on_boundary, near, triangles, s / 2, spec, report);
  }
}

// No hole's seed inside or on any triangle: the seeds sorted by x, each triangle tested
// against those within its x range.
void check_holes(std::span<const Point> pts, std::span<const VertexId> tris, std::span<const Point> holes,
                 Report& report) {
  std::vector<Point> h(holes.begin(), holes.end());
  std::sort(h.begin(), h.end(), [](const Point& a, const Point& b) { return a.x < b.x; });
  for (std::size_t t = 0; t < tris.size() / 3; ++t) {
    const Point &a = pts[tris[3 * t]], &b = pts[tris[3 * t + 1]], &c = pts[tris[3 * t + 2]];
    const double lo = std::min({a.x, b.x, c.x}), hi = std::max({a.x, b.x, c.x});
    auto it = std::lower_bound(h.begin(), h.end(), lo, [](const Point& p, double x) { return p.x < x; });
    for (; it != h.end() && it->x <= hi; ++it)
      if (orient2d(a, b, *it) >= 0 && orient2d(b, c, *it) >= 0 && orient2d(c, a, *it) >= 0)
        report.problem("triangle ", t, " holds the hole seed (", it->x, ", ", it->y, ")");
  }
}

// The chains of segment edges between corners (input points, and added points where other
// than two segment edges meet or where the two turn, off the line between their other ends by
// more than check_chains lets a point on a segment lie: a point added where segments cross):
// each chain's two ends, and per vertex the chains it lies on.
struct Chains {
  std::vector<std::pair<VertexId, VertexId>> ends;
  std::vector<std::vector<std::uint32_t>> on;
  std::vector<std::uint8_t> small;  // per vertex: a corner where two chains meet below 60 degrees
  struct Wedge {
    VertexId corner, end1, end2;  // two chains from `corner` below 60 degrees, by their other ends
  };
  std::vector<Wedge> wedges;
};

Chains chains_of(std::span<const Point> pts, std::span<const VertexId> edges, std::size_t input, long double least) {
  const auto adj = adjacency(pts.size(), edges);
  Chains c;
  c.on.resize(pts.size());
  c.small.assign(pts.size(), 0);
  auto corner = [&](VertexId v) {
    if (v < input || adj[v].size() != 2) return true;
    return off_line(pts[adj[v][0]], pts[adj[v][1]], pts[v], least, true) > 0x1p-40;
  };
  for (VertexId z = 0; z < pts.size(); ++z) {
    if (!corner(z)) continue;
    for (const VertexId first : adj[z]) {
      VertexId prev = z, v = first;
      std::vector<VertexId> inside;
      while (!corner(v)) inside.push_back(v), std::swap(prev, v), v = adj[prev][0] == v ? adj[prev][1] : adj[prev][0];
      if (v < z || (v == z && !inside.empty() && inside.front() > inside.back())) continue;  // walked from v's side
      const auto id = static_cast<std::uint32_t>(c.ends.size());
      c.ends.emplace_back(z, v);
      c.on[z].push_back(id);
      if (v != z) c.on[v].push_back(id);
      for (const VertexId w : inside) c.on[w].push_back(id);
    }
  }
  // The angle at each corner between the straight lines to its chains' other ends.
  for (VertexId z = 0; z < pts.size(); ++z)
    for (std::size_t i = 0; i < c.on[z].size(); ++i)
      for (std::size_t j = i + 1; j < c.on[z].size(); ++j) {
        auto other = [&](std::uint32_t k) { return c.ends[k].first == z ? c.ends[k].second : c.ends[k].first; };
        const Point &o = pts[z], &u = pts[other(c.on[z][i])], &w = pts[other(c.on[z][j])];
        const double ux = u.x - o.x, uy = u.y - o.y, wx = w.x - o.x, wy = w.y - o.y;
        if (std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy) < 3.14159265358979323846 / 3) {
          c.small[z] = 1;
          c.wedges.push_back({z, other(c.on[z][i]), other(c.on[z][j])});
        }
      }
  return c;
}

struct Shape {
  long double smallest = 180, largest_area = 0;
  std::size_t excused = 0;
};

// The circle through a, b and c, in long double, relative to a; `flat` where it is too large
// for long double (a, b and c in a line there), and then it meets everything.
struct Circle {
  Circle(const Point& pa, const Point& b, const Point& c) : a(pa) {
    const L bx = b.x - L(a.x), by = b.y - L(a.y), cx = c.x - L(a.x), cy = c.y - L(a.y);
    const L d = 2 * (bx * cy - by * cx), b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    ox = (cy * b2 - by * c2) / d, oy = (bx * c2 - cx * b2) / d, r2 = ox * ox + oy * oy;
    flat = !std::isfinite(r2);
  }
  // Whether it meets the segment from-to.
  bool meets(const Point& from, const Point& to) const {
    if (flat) return true;
    const L px = from.x - L(a.x), py = from.y - L(a.y), qx = to.x - L(a.x), qy = to.y - L(a.y);
    const L ex = qx - px, ey = qy - py, e2 = ex * ex + ey * ey;
    const L s = e2 > 0 ? std::clamp(((ox - px) * ex + (oy - py) * ey) / e2, L(0), L(1)) : L(0);
    const L dx = px + s * ex - ox, dy = py + s * ey - oy;
    return dx * dx + dy * dy <= r2;
  }

  using L = long double;
  Point a;
  L ox = 0, oy = 0, r2 = 0;
  bool flat = false;
};

// Whether triangle a-b-c lies in a wedge (in the closed triangle of its corner and its chains'
// other ends) and its circle meets both chains (as the straight lines from the corner to those
// ends): the triangle is squeezed between them, and its point would split one of them.
bool squeezed(std::span<const Point> pts, const Point& a, const Point& b, const Point& c, const Chains::Wedge& w) {
  const Point &z = pts[w.corner], &e1 = pts[w.end1], &e2 = pts[w.end2];
  for (const Point* v : {&a, &b, &c}) {
    const int o1 = orient2d(z, e1, *v), o2 = orient2d(e1, e2, *v), o3 = orient2d(e2, z, *v);
    if (!((o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0))) return false;
  }
  const Circle circle(a, b, c);
  return circle.meets(z, e1) && circle.meets(z, e2);
}

// The wedges by where they lie, for squeezed(): a grid over their triangles' boxes, each wedge
// listed in the cells its box covers, or, where that is more than 64, in a list every query
// reads.
class Wedges {
 public:
  Wedges(std::span<const Point> pts, const std::vector<Chains::Wedge>& wedges) : pts_(pts), wedges_(wedges) {
    if (wedges.empty()) return;
    auto box = [&](const Chains::Wedge& w) {
      const Point &z = pts[w.corner], &p = pts[w.end1], &q = pts[w.end2];
      return std::array<double, 4>{std::min({z.x, p.x, q.x}), std::min({z.y, p.y, q.y}), std::max({z.x, p.x, q.x}),
                                   std::max({z.y, p.y, q.y})};
    };
    x0_ = y0_ = INFINITY, x1_ = y1_ = -INFINITY;
    for (const Chains::Wedge& w : wedges) {
      const auto b = box(w);
      x0_ = std::min(x0_, b[0]), y0_ = std::min(y0_, b[1]), x1_ = std::max(x1_, b[2]), y1_ = std::max(y1_, b[3]);
    }
    size_ = static_cast<int>(std::clamp(std::sqrt(static_cast<double>(wedges.size())), 1.0, 512.0));
    cells_.resize(static_cast<std::size_t>(size_) * size_);
    for (std::uint32_t k = 0; k < wedges.size(); ++k) {
      const auto b = box(wedges[k]);
      const int i0 = cell(b[0], x0_, x1_), i1 = cell(b[2], x0_, x1_), j0 = cell(b[1], y0_, y1_),
                j1 = cell(b[3], y0_, y1_);
      if ((i1 - i0 + 1) * (j1 - j0 + 1) > 64) {
        wide_.push_back(k);
        continue;
      }
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) cells_[static_cast<std::size_t>(j) * size_ + i].push_back(k);
    }
  }

  // Whether a-b-c is squeezed in any wedge.
  bool hold(const Point& a, const Point& b, const Point& c) const {
    if (wedges_.empty()) return false;
    const long double mx = (a.x + static_cast<long double>(b.x) + c.x) / 3,
                      my = (a.y + static_cast<long double>(b.y) + c.y) / 3;
    if (mx < x0_ || mx > x1_ || my < y0_ || my > y1_) return false;  // in no wedge's box
    auto any = [&](const std::vector<std::uint32_t>& list) {
      return std::any_of(list.begin(), list.end(),
                         [&](std::uint32_t k) { return squeezed(pts_, a, b, c, wedges_[k]); });
    };
    const std::size_t at = static_cast<std::size_t>(cell(my, y0_, y1_)) * size_ + cell(mx, x0_, x1_);
    return any(cells_[at]) || any(wide_);
  }

 private:
  int cell(long double v, long double lo, long double hi) const {
    const long double f = hi > lo ? (v - lo) / (hi - lo) : 0;
    return static_cast<int>(std::clamp<long double>(std::floor(f * size_), 0, size_ - 1));
  }

  std::span<const Point> pts_;
  const std::vector<Chains::Wedge>& wedges_;
  double x0_ = 0, y0_ = 0, x1_ = 0, y1_ = 0;
  int size_ = 1;
  std::vector<std::vector<std::uint32_t>> cells_;
  std::vector<std::uint32_t> wide_;
};

// Angles and areas: a triangle below the angle is excused where one of its vertices lies on a
// chain of segment edges that ends at an input angle below 60 degrees (refinement stops short
// of those, as its concentric shells reach them), where its circle meets both chains of such an
// angle (it lies in a wedge thinner than the bound can fill: the area bound or the wedge's far
// end put points there, and splitting it would cut the chains down to the gap between them),
// or where its shortest edge is below 2^-39 of the points' extent (refinement splits no
// subsegment that short).
Shape check_shape(std::span<const Point> pts, std::span<const Point> scaled, std::span<const VertexId> tris,
                  const MeshSpec& spec, const Chains& chains, Report& report) {
  Shape shape;
  const Wedges wedges(scaled, chains.wedges);  // in the predicates' coordinates
  const long double pi = 3.14159265358979323846264338327950288L;
  // A vertex on a chain that ends at a corner with a small angle: refinement stops there.
  auto beside_small_angle = [&](VertexId v) {
    for (const std::uint32_t k : chains.on[v])
      if (chains.small[chains.ends[k].first] || chains.small[chains.ends[k].second]) return true;
    return false;
  };
  const detail::Extent box = detail::extent_of(pts);
  const long double w = box.x1 - (long double)box.x0, h = box.y1 - (long double)box.y0;
  const long double tiny2 = (w * w + h * h) * 0x1p-78L;
  // The segment edges refinement never splits (below 2^-39 of the extent, with a margin).
  std::vector<Edge> short_edges;
  for (std::size_t k = 0; k + 1 < spec.edges.size(); k += 2) {
    const Point &p = pts[spec.edges[k]], &q = pts[spec.edges[k + 1]];
    const long double dx = p.x - (long double)q.x, dy = p.y - (long double)q.y;
    if (dx * dx + dy * dy < 2 * tiny2) short_edges.emplace_back(spec.edges[k], spec.edges[k + 1]);
  }
  auto length2 = [&](VertexId a, VertexId b) {
    const long double dx = pts[a].x - (long double)pts[b].x, dy = pts[a].y - (long double)pts[b].y;
    return dx * dx + dy * dy;
  };
  for (std::size_t t = 0; t < tris.size() / 3; ++t) {
    const VertexId* v = &tris[3 * t];
    long double worst = 180;
    for (int i = 0; i < 3; ++i) {
      const Point &o = pts[v[i]], &u = pts[v[(i + 1) % 3]], &w = pts[v[(i + 2) % 3]];
      const long double ux = u.x - (long double)o.x, uy = u.y - (long double)o.y;
      const long double wx = w.x - (long double)o.x, wy = w.y - (long double)o.y;
      worst = std::min(worst, std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180 / pi);
    }
    const Point &a = pts[v[0]], &b = pts[v[1]], &c = pts[v[2]];
    const long double area = std::fabs((b.x - (long double)a.x) * (c.y - (long double)a.y) -
                                       (b.y - (long double)a.y) * (c.x - (long double)a.x)) /
        2;
    shape.smallest = std::min(shape.smallest, worst);
    shape.largest_area = std::max(shape.largest_area, area);
    if (spec.max_area > 0 && area > spec.max_area * (1 + 1e-9L))
      report.problem("triangle ", t, " has area ", static_cast<double>(area), ", above ", spec.max_area);
    if (spec.min_angle > 0 && worst < spec.min_angle * (1 - 1e-9L)) {
      const long double shortest = std::min({length2(v[0], v[1]), length2(v[1], v[2]), length2(v[2], v[0])});
      auto at_a_short_one = [&] {  // its circle meets a segment edge too short to split
        if (short_edges.empty()) return false;
        const Circle circle(scaled[v[0]], scaled[v[1]], scaled[v[2]]);
        return std::any_of(short_edges.begin(), short_edges.end(),
                           [&](const Edge& e) { return circle.meets(scaled[e.first], scaled[e.second]); });
      };
      if (beside_small_angle(v[0]) || beside_small_angle(v[1]) || beside_small_angle(v[2]) || shortest < tiny2 ||
          wedges.hold(scaled[v[0]], scaled[v[1]], scaled[v[2]]) || at_a_short_one())
        ++shape.excused;
      else
        report.problem("triangle ", t, " has an angle of ", static_cast<double>(worst), " degrees, below ",
                       spec.min_angle, ", and no small input angle beside it");
    }
  }
  return shape;
}

}  // namespace

CheckResult check_mesh(std::span<const Point> input, std::span<const VertexId> tris, const MeshSpec& spec) {
  if (tris.size() / 3 > kCheckMaxTriangles)
    throw InputError(std::to_string(tris.size() / 3) + " triangles are more than the validator takes");
  const std::vector<Point> scaled = detail::exactly_scaled(input);
  const std::span<const Point> pts = scaled.empty() ? input : std::span<const Point>(scaled);
  Report report;
  if (tris.size() % 3 != 0 || spec.edges.size() % 2 != 0 || spec.segments.size() % 2 != 0)
    report.problem("a triangle, edge or segment list has a length that does not divide");
  std::vector<std::uint8_t> used(pts.size(), 0);
  detail::check_triangles(pts, tris, used, report);
  for (const VertexId e : spec.edges)
    if (e >= pts.size()) report.problem("an edge refers to point ", e, " of ", pts.size());
  if (report.problems() > 0) return report.result();
  std::vector<Edge> segment_edges;
  std::unordered_set<std::uint64_t> segment;
  for (std::size_t k = 0; k + 1 < spec.edges.size(); k += 2) {
    segment_edges.emplace_back(std::min(spec.edges[k], spec.edges[k + 1]), std::max(spec.edges[k], spec.edges[k + 1]));
    segment.insert(key(spec.edges[k], spec.edges[k + 1]));
  }
  std::sort(segment_edges.begin(), segment_edges.end());
  const std::vector<Edge> boundary = detail::check_edges(pts, tris, segment_edges, report);
  std::unordered_set<std::uint64_t> sides;
  for (std::size_t k = 0; k < tris.size(); ++k) sides.insert(key(tris[k], tris[k % 3 == 2 ? k - 2 : k + 1]));
  for (const Edge& e : segment_edges)
    if (!sides.count(key(e.first, e.second))) report.problem("segment edge ", e.first, "-", e.second, " is no edge");
  check_boundary(pts, used, boundary, segment, report);
  std::vector<std::uint8_t> on_boundary(pts.size(), 0);
  for (const Edge& e : boundary) on_boundary[e.first] = on_boundary[e.second] = 1;
  for (VertexId v = 0; v < pts.size(); ++v) on_boundary[v] |= !used[v];
  // The least normal double in the coordinates the mesher worked in (the input points scaled
  // by a power of two where they are huge or tiny), in these coordinates (scaled or not).
  const std::size_t input_points = spec.input_points == 0 ? pts.size() : std::min(spec.input_points, pts.size());
  const int here = scaled.empty() ? 0 : detail::exact_scale_exponent(input);
  // No finer either than the roundings of the output's doubles, 2^-1074 apart below the least
  // normal (points computed in scaled coordinates and scaled back), 2^-40 of the scale.
  const long double least =
      std::max(std::ldexp(0x1p-1022L, here - detail::exact_scale_exponent(input.first(input_points))),
               std::ldexp(0x1p-1034L, here));
  check_chains(pts, tris, spec, least, used, on_boundary, report);
  std::vector<Point> holes(spec.holes.begin(), spec.holes.end());
  if (here != 0)
    for (Point& h : holes) h = {std::ldexp(h.x, here), std::ldexp(h.y, here)};
  check_holes(pts, tris, holes, report);
  const Shape shape = check_shape(input, pts, tris, spec, chains_of(pts, spec.edges, input_points, least), report);
  std::ostringstream s;
  s << "valid: " << tris.size() / 3 << " triangles, " << pts.size() - input_points << " points added, "
    << spec.segments.size() / 2 << " segments as chains of " << segment_edges.size()
    << " edges, every other edge locally Delaunay; smallest angle " << static_cast<double>(shape.smallest)
    << " degrees";
  if (shape.excused > 0)
    s << " (" << shape.excused << " triangles below " << spec.min_angle
      << " beside small input angles, in their wedges or with an edge below 2^-39 of the extent)";
  s << ", largest area " << static_cast<double>(shape.largest_area);
  return report.result(s.str());
}

}  // namespace ridt
