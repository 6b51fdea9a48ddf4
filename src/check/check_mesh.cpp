// check_mesh (ridt/check.hpp): a constrained triangulation or quality mesh validated against
// what it was asked: its segment edges, the input's segments as chains of them, holes empty,
// angles and areas.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "check/mesh_angles.hpp"
#include "check/on_segment.hpp"
#include "check/parts.hpp"
#include "predicates/predicates.hpp"
#include "ridt/check.hpp"
#include "tds/ids.hpp"

namespace ridt {
namespace {

using detail::kNoVertex;

using detail::Adjacency;
using detail::along_keys;
using detail::Edge;
using detail::OnSegment;
using detail::orient2d;
using detail::Report;
using detail::SegmentEdges;

// The convex hull of the points `of` (indices into pts), counter-clockwise, points on its sides
// kept (of equal points, the first in `of`); empty where they are fewer than three distinct or
// collinear.
std::vector<VertexId> hull_of(std::span<const Point> pts, const std::vector<VertexId>& of) {
  std::vector<Point> p(of.size());
  for (std::size_t i = 0; i < of.size(); ++i) p[i] = pts[of[i]];
  const detail::Distinct d = detail::near_the_hull(p, 0);
  if (d.degenerate) return {};
  std::vector<VertexId> hull = detail::hull_with_collinear(p, d.first);
  for (VertexId& v : hull) v = of[v];
  return hull;
}

// Boundary edges that are no segment's must lie on the convex hull of the vertices.
void check_boundary(std::span<const Point> pts, const std::vector<std::uint8_t>& used,
                    const std::vector<Edge>& boundary, const std::vector<Edge>& segment_edges, Report& report) {
  std::vector<Edge> open;
  for (const Edge& e : boundary)
    if (!std::binary_search(segment_edges.begin(), segment_edges.end(),
                            Edge{std::min(e.first, e.second), std::max(e.first, e.second)}))
      open.push_back(e);
  if (open.empty()) return;
  std::vector<VertexId> vertices;
  for (VertexId v = 0; v < pts.size(); ++v)
    if (used[v]) vertices.push_back(v);
  const std::vector<VertexId> hull = hull_of(pts, vertices);
  std::vector<Edge> on_hull;
  for (std::size_t i = 0; i < hull.size(); ++i) on_hull.emplace_back(hull[i], hull[(i + 1) % hull.size()]);
  std::sort(on_hull.begin(), on_hull.end());
  for (const Edge& e : open)
    if (!std::binary_search(on_hull.begin(), on_hull.end(), e))
      report.problem("boundary edge ", e.first, "-", e.second, " is neither a segment's nor on the convex hull");
}

// A piece of input segment `segment` from u to w that no segment edge joins: it must lie
// outside the mesh (in a hole or the exterior).
struct Gap {
  VertexId u, w;
  std::size_t segment;
};

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
// along it, the nearest to its line first; where there is none, or none leads on to b, across
// a gap to a point near the segment ahead, both on the boundary (or in no triangle), the gap
// through no triangle and no vertex. Depth first: another segment's chain may run within
// rounding of this one's (two segments at a hair's angle, or crossing near a shared end), and
// a step onto it ends where it leaves this segment, and the search goes back to take the
// other. Where no such way reaches b, the way that jumps each gap to the next point ahead (or
// to b behind) is taken: its first gap through a triangle is reported, or, where it stops, the
// segment as no chain.
class GapSearch {
 public:
  GapSearch(std::span<const Point> pts, const OnSegment& near, const Adjacency& adj,
            std::span<const std::pair<double, VertexId>> by_x, const std::vector<std::uint8_t>& on_boundary,
            TrianglesByX& triangles, std::size_t segment)
      : pts_(pts),
        a_(near.a),
        b_(near.b),
        adj_(adj),
        on_boundary_(on_boundary),
        near_(near),
        triangles_(triangles),
        segment_(segment) {
    // The points near the segment, by key: those with a segment edge within near's x range
    // [x0, x1] (by_x: every such point, by x), so that many segments in holes cost n log n.
    ahead_.push_back({key(b_), b_});
    for (auto it = std::lower_bound(by_x.begin(), by_x.end(), std::pair{near.x0, VertexId{0}});
         it != by_x.end() && it->first <= near.x1; ++it)
      if (it->second != b_ && near(it->second)) ahead_.push_back({key(it->second), it->second});
    std::sort(ahead_.begin(), ahead_.end());
  }

  // The points near the segment (those with a segment edge, and b).
  std::vector<VertexId> points() const {
    std::vector<VertexId> all;
    for (const auto& [k, v] : ahead_) all.push_back(v);
    return all;
  }

  // `checked`: gaps only through no triangle, to any of the next 16 points ahead; else the one
  // way that jumps to the next point ahead, its gaps kept to report. Whether b was reached.
  bool run(bool checked, std::vector<Gap>& gaps) {
    from_ = {{a_, {kNoVertex, false}}};  // how each point was reached: from where, across a gap
    std::vector<std::pair<VertexId, bool>> todo{{a_, false}};  // a point; true: its gaps only
    std::vector<VertexId> steps;
    while (!todo.empty()) {
      const VertexId u = todo.back().first;  // (not a structured binding: lambdas below take it)
      const bool gaps_only = todo.back().second;
      todo.pop_back();
      if (u == b_) {
        for (VertexId v = b_; v != a_; v = from_[v].first)
          if (from_[v].second) gaps.push_back({from_[v].first, v, segment_});
        return true;
      }
      steps.clear();
      if (!gaps_only)
        for (const VertexId w : adj_[u])
          if (key(w) > key(u) && near_(w) && !from_.count(w)) steps.push_back(w);
      if (!steps.empty()) {  // the nearest to the line taken first: pushed last
        // Its gaps only once every way on from its edges has failed (an edge onto another
        // segment's chain, within rounding of this one beside a hole): pushed first.
        if (checked) todo.push_back({u, true});
        std::sort(steps.begin(), steps.end(), [&](VertexId w, VertexId v) { return nearer(v, w); });
        for (const VertexId w : steps) from_[w] = {u, false}, todo.push_back({w, false});
        continue;
      }
      if (!on_boundary_[u]) continue;  // (unused vertices count as on the boundary)
      if (checked) {
        auto clear = [&](VertexId w) { return on_boundary_[w] && !from_.count(w) && triangles_.through(u, w) < 0; };
        for (auto it = after(u); it != ahead_.end() && steps.size() < 16; ++it)
          if (clear(it->second)) steps.push_back(it->second);
        if (const VertexId next = next_ahead(u); steps.empty() && next == b_ && clear(b_)) steps.push_back(b_);
      } else if (const VertexId next = next_ahead(u); on_boundary_[next] && !from_.count(next)) {
        steps.push_back(next);
      }
      for (auto w = steps.rbegin(); w != steps.rend(); ++w) from_[*w] = {u, true}, todo.push_back({*w, false});
    }
    return false;
  }

 private:
  using Key = std::pair<double, double>;

  Key key(VertexId v) const { return along_keys(pts_[a_], pts_[b_], pts_[v]); }
  double off(VertexId v) const { return std::fabs(detail::doubled_area(pts_[a_], pts_[b_], pts_[v])); }
  bool better(VertexId w, VertexId than) const {  // ahead sooner, then nearer the line
    return than == kNoVertex || key(w) < key(than) || (key(w) == key(than) && off(w) < off(than));
  }
  bool nearer(VertexId w, VertexId than) const {
    return off(w) < off(than) || (off(w) == off(than) && better(w, than));
  }
  std::vector<std::pair<Key, VertexId>>::const_iterator after(VertexId u) const {
    return std::upper_bound(ahead_.begin(), ahead_.end(), std::pair{key(u), std::numeric_limits<VertexId>::max()});
  }
  // The point ahead of u at the least key, the nearest the line there; b where none is (at b's
  // place along the segment already: another end there).
  VertexId next_ahead(VertexId u) const {
    VertexId next = kNoVertex;
    const auto it = after(u);
    for (auto other = it; other != ahead_.end() && other->first == it->first; ++other)
      if (better(other->second, next)) next = other->second;
    return next == kNoVertex ? b_ : next;
  }

  std::span<const Point> pts_;
  VertexId a_, b_;
  const Adjacency& adj_;
  const std::vector<std::uint8_t>& on_boundary_;
  const OnSegment& near_;
  TrianglesByX& triangles_;
  std::size_t segment_;
  std::vector<std::pair<Key, VertexId>> ahead_;
  std::unordered_map<VertexId, std::pair<VertexId, bool>> from_;
};

// Each input segment a-b a chain of segment edges: a search from a through points on it
// (OnSegment), along segment edges or, where it runs through a hole, across gaps. And the added
// points that lie on a segment between their two segment edges' other ends (straight): no
// corner of the chains that check_shape measures angles between, however their neighbours'
// coordinates measure the turn (a point split off near the small end of a long segment
// carries the roundings of its far end).
class ChainCheck {
 public:
  ChainCheck(std::span<const Point> pts, std::span<const VertexId> tris, const MeshSpec& spec, long double least,
             const std::vector<std::uint8_t>& used, const detail::Standing& stand,
             const std::vector<std::uint8_t>& on_boundary, Report& report)
      : edges_{Adjacency::of_pairs(pts.size(), spec.edges), std::vector<std::uint8_t>(pts.size(), 0)},
        pts_(pts),
        spec_(spec),
        least_(least),
        used_(used),
        on_boundary_(on_boundary),
        report_(report),
        input_(spec.input_points == 0 ? pts.size() : spec.input_points),
        stand_(stand),
        seen_(pts.size(), 0),
        triangles_(pts, tris) {  // sorted when a segment first runs through a hole
    for (VertexId v = 0; v < pts.size(); ++v)
      if (!edges_.adj[v].empty()) by_x_.push_back({pts[v].x, v});
    std::sort(by_x_.begin(), by_x_.end());
  }

  void check(std::size_t s) {
    if (spec_.segments[2 * s] >= input_ || spec_.segments[2 * s + 1] >= input_)
      return report_.problem("segment ", s, " refers to a point that is not one of the input's ", input_);
    const VertexId a = stand_(spec_.segments[2 * s]), b = stand_(spec_.segments[2 * s + 1]);
    if (a == b || pts_[a] == pts_[b]) return;  // (two equal points, both unused)
    const OnSegment near(pts_, a, b, input_, least_);
    const auto stamp = static_cast<std::uint32_t>(s + 1);
    std::vector<VertexId> todo{a}, reached{a};
    seen_[a] = stamp;
    while (!todo.empty()) {
      const VertexId v = todo.back();
      todo.pop_back();
      for (const VertexId w : edges_.adj[v])
        if (seen_[w] != stamp && near(w)) seen_[w] = stamp, todo.push_back(w), reached.push_back(w);
    }
    if (seen_[b] != stamp) reached = across_gaps(near, s);
    mark_straight(near, reached);
  }

  // The segment edges, and the added points found on a segment between theirs.
  SegmentEdges take() { return std::move(edges_); }

 private:
  // The segment through a hole: a chain where it lies in the mesh (GapSearch), or reported.
  // Returns the points on it.
  std::vector<VertexId> across_gaps(const OnSegment& near, std::size_t s) {
    GapSearch search(pts_, near, edges_.adj, by_x_, on_boundary_, triangles_, s);
    std::vector<Gap> gaps;
    if (search.run(true, gaps)) return search.points();
    gaps.clear();
    const VertexId sa = spec_.segments[2 * s], sb = spec_.segments[2 * s + 1];
    if (!search.run(false, gaps)) {
      report_.problem("segment ", s, " (", sa, "-", sb, ") is not a chain of segment edges");
      return {};
    }
    for (auto g = gaps.rbegin(); g != gaps.rend(); ++g)
      if (const std::int64_t t = triangles_.through(g->u, g->w); t >= 0) {
        report_.problem("segment ", s, " (", sa, "-", sb, ") runs through triangle ", t, " between points ", g->u,
                        " and ", g->w, " with no segment edge");
        break;
      }
    return {};
  }

  // Added points with two segment edges, to points on the segment either side of them along it.
  void mark_straight(const OnSegment& near, const std::vector<VertexId>& reached) {
    const Point &a = pts_[near.a], &b = pts_[near.b];
    for (const VertexId v : reached) {
      const std::span<const VertexId> n = edges_.adj[v];
      if (v < input_ || n.size() != 2 || !near(n[0]) || !near(n[1])) continue;
      const auto kp = along_keys(a, b, pts_[n[0]]), kv = along_keys(a, b, pts_[v]), kq = along_keys(a, b, pts_[n[1]]);
      if ((kp < kv && kv < kq) || (kq < kv && kv < kp)) edges_.straight[v] = 1;
    }
  }

  SegmentEdges edges_;
  std::span<const Point> pts_;
  const MeshSpec& spec_;
  long double least_;
  const std::vector<std::uint8_t>& used_;
  const std::vector<std::uint8_t>& on_boundary_;
  Report& report_;
  std::size_t input_;
  const detail::Standing& stand_;
  std::vector<std::pair<double, VertexId>> by_x_;  // the points with a segment edge, by x (GapSearch)
  std::vector<std::uint32_t> seen_;
  TrianglesByX triangles_;
};

// The input's segments checked as chains; returns the segment edges (ChainCheck).
SegmentEdges check_chains(std::span<const Point> pts, std::span<const VertexId> tris, const MeshSpec& spec,
                          long double least, const std::vector<std::uint8_t>& used, const detail::Standing& stand,
                          const std::vector<std::uint8_t>& on_boundary, Report& report) {
  ChainCheck chains(pts, tris, spec, least, used, stand, on_boundary, report);
  for (std::size_t s = 0; s + 1 < spec.segments.size(); s += 2) chains.check(s / 2);
  return chains.take();
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

// The edges of a mesh given without its segment edges: those along the segments, and along the
// input's convex hull (a mesh of the hull has its edges as segments: Triangle's -c).
std::vector<VertexId> edges_found(std::span<const Point> pts, const Adjacency& sides,
                                  std::span<const VertexId> segments, std::size_t input_points,
                                  const std::vector<std::uint8_t>& used, const detail::Standing& stand,
                                  long double least) {
  std::vector<VertexId> follow(segments.begin(), segments.end());
  std::vector<VertexId> input(input_points);
  for (VertexId v = 0; v < input_points; ++v) input[v] = v;
  const std::vector<VertexId> hull = hull_of(pts, input);
  for (std::size_t i = 0; i < hull.size(); ++i)
    follow.push_back(hull[i]), follow.push_back(hull[(i + 1) % hull.size()]);
  return detail::edges_along_segments(pts, sides, follow, segments.size() / 2, input_points, used, stand, least, 0);
}

// What check_mesh says of a valid mesh.
std::string valid_message(std::size_t triangles, std::size_t added, const MeshSpec& spec, std::size_t segment_edges,
                          bool found, const detail::MeshShape& shape) {
  std::ostringstream s;
  s << "valid: " << triangles << " triangles, " << added << " points added, " << spec.segments.size() / 2
    << " segments as chains of " << segment_edges << (found ? " edges (found along them)" : " edges")
    << ", every other edge locally Delaunay; smallest angle " << static_cast<double>(shape.smallest) << " degrees";
  if (shape.excused > 0)
    s << " (" << shape.excused << " triangles below " << spec.min_angle
      << " beside small input angles, in their wedges or with an edge below 2^-39 of the extent)";
  s << ", largest area " << static_cast<double>(shape.largest_area);
  return s.str();
}

}  // namespace

CheckResult check_mesh(std::span<const Point> input, std::span<const VertexId> tris, const MeshSpec& given) {
  if (tris.size() / 3 > kCheckMaxTriangles)
    throw InputError(std::to_string(tris.size() / 3) + " triangles are more than the validator takes");
  const std::vector<Point> scaled = detail::exactly_scaled(input);
  const std::span<const Point> pts = scaled.empty() ? input : std::span<const Point>(scaled);
  Report report;
  if (tris.size() % 3 != 0 || given.edges.size() % 2 != 0 || given.segments.size() % 2 != 0)
    report.problem("a triangle, edge or segment list has a length that does not divide");
  std::vector<std::uint8_t> used(pts.size(), 0);
  detail::check_triangles(pts, tris, used, report);
  for (const VertexId e : given.edges)
    if (e >= pts.size()) report.problem("an edge refers to point ", e, " of ", pts.size());
  if (report.problems() > 0) return report.result();
  // The least normal double in the coordinates the mesher worked in (the input points scaled
  // by a power of two where they are huge or tiny), in these coordinates (scaled or not).
  const std::size_t input_points = given.input_points == 0 ? pts.size() : std::min(given.input_points, pts.size());
  const int here = scaled.empty() ? 0 : detail::exact_scale_exponent(input);
  // No finer either than the roundings of the output's doubles, 2^-1074 apart below the least
  // normal (points computed in scaled coordinates and scaled back), 2^-40 of the scale.
  const long double least =
      std::max(std::ldexp(0x1p-1022L, here - detail::exact_scale_exponent(input.first(input_points))),
               std::ldexp(0x1p-1034L, here));
  // A mesh given without its segment edges: those along the segments, and along the input's
  // convex hull (a mesh of the hull has its edges as segments: Triangle's -c).
  MeshSpec spec = given;
  std::vector<VertexId> found;
  const bool find = given.edges.empty() && !given.segments.empty();
  const Adjacency sides = Adjacency::of_triangles(pts.size(), tris);
  const detail::Standing stand(pts, used, input_points);
  if (find) spec.edges = found = edges_found(pts, sides, given.segments, input_points, used, stand, least);
  std::vector<Edge> segment_edges;
  for (std::size_t k = 0; k + 1 < spec.edges.size(); k += 2)
    segment_edges.emplace_back(std::min(spec.edges[k], spec.edges[k + 1]), std::max(spec.edges[k], spec.edges[k + 1]));
  std::sort(segment_edges.begin(), segment_edges.end());
  const std::vector<Edge> boundary = detail::check_edges(pts, tris, segment_edges, report);
  for (const auto& [u, w] : segment_edges)
    if (const auto n = sides[u]; std::find(n.begin(), n.end(), w) == n.end())
      report.problem("segment edge ", u, "-", w, " is no edge");
  check_boundary(pts, used, boundary, segment_edges, report);
  std::vector<std::uint8_t> on_boundary(pts.size(), 0);
  for (const Edge& e : boundary) on_boundary[e.first] = on_boundary[e.second] = 1;
  for (VertexId v = 0; v < pts.size(); ++v) on_boundary[v] |= !used[v];
  const detail::SegmentEdges edges = check_chains(pts, tris, spec, least, used, stand, on_boundary, report);
  std::vector<Point> holes(spec.holes.begin(), spec.holes.end());
  if (here != 0)
    for (Point& h : holes) h = {std::ldexp(h.x, here), std::ldexp(h.y, here)};
  check_holes(pts, tris, holes, report);
  const detail::MeshShape shape = detail::check_mesh_shape(input, pts, tris, spec, input_points, least, edges, report);
  return report.result(
      valid_message(tris.size() / 3, pts.size() - input_points, spec, segment_edges.size(), find, shape));
}

}  // namespace ridt
