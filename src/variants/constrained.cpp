// The constrained Delaunay triangulation (ridt/constrained.hpp): segments inserted one by one
// into the Delaunay triangulation. A segment a-b walks from a: where an edge at a runs along
// it, that edge is a piece of the segment and the walk goes on from its other end; else the
// triangles it crosses, up to the next vertex v on it, are taken out, and the polygons left on
// either side of a-v are triangulated again, each by the vertex c whose circle through a and v
// holds no other of the polygon's vertices, then the two smaller polygons a..c and c..v in
// turn (the circles through a and v are ordered, so one pass finds c).
#include "ridt/constrained.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "finish/finish.hpp"
#include "predicates/predicates.hpp"

namespace ridt {
namespace {

using detail::incircle;
using detail::orient2d;

std::uint64_t edge_key(VertexId a, VertexId b) { return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b); }

class Inserter {
 public:
  Inserter(std::span<const Point> pts, Triangulation& t) : pts_(pts), tris_(t.triangles), nbrs_(t.neighbors) {
    corner_.assign(pts.size(), kNone);
    for (std::size_t k = 0; k < tris_.size(); ++k) corner_[tris_[k]] = static_cast<std::uint32_t>(k);
  }

  // Segment a-b (a != b, both vertices) as edges.
  void insert(VertexId a, VertexId b, std::size_t index) {
    while (a != b) {
      const Step s = step(a, b);
      if (s.along != kNone) {
        mark(a, s.along, index);
        a = s.along;
        continue;
      }
      a = cross(a, b, s.triangle, index);
    }
  }

  std::vector<VertexId> edges() const {
    std::vector<VertexId> out;
    std::vector<std::uint64_t> keys;
    for (const auto& [key, segment] : segment_of_) keys.push_back(key);
    std::sort(keys.begin(), keys.end());
    for (const std::uint64_t k : keys)
      out.push_back(static_cast<VertexId>(k >> 32)), out.push_back(static_cast<VertexId>(k));
    return out;
  }

 private:
  static constexpr std::uint32_t kNone = 0xffffffffu;

  struct Step {
    VertexId along = kNone;  // an edge a-along runs along the segment
    std::uint32_t triangle = kNone;  // else the triangle at a through which the segment leaves a
  };

  // Position along a -> b, exactly: by x, or by y on a vertical segment.
  double key(VertexId a, VertexId b, VertexId v) const {
    const bool by_x = pts_[a].x != pts_[b].x;
    const double sign = (by_x ? pts_[b].x - pts_[a].x : pts_[b].y - pts_[a].y) > 0 ? 1 : -1;
    return sign * (by_x ? pts_[v].x : pts_[v].y);
  }

  // The triangles around vertex a: clockwise from the one corner_ names, and where that
  // meets the hull, counter-clockwise from it too.
  std::vector<std::uint32_t> around(VertexId a) const {
    std::vector<std::uint32_t> ring;
    const std::uint32_t start = corner_[a] / 3;
    for (std::uint32_t t = start;;) {
      ring.push_back(t);
      const std::int32_t n = nbrs_[3 * t + (corner_of(t, a) + 2) % 3];  // across the edge (a, next)
      if (n < 0) break;
      t = static_cast<std::uint32_t>(n);
      if (t == start) return ring;
    }
    for (std::uint32_t t = start;;) {
      const std::int32_t n = nbrs_[3 * t + (corner_of(t, a) + 1) % 3];  // across the edge (prev, a)
      if (n < 0) return ring;
      t = static_cast<std::uint32_t>(n);
      ring.push_back(t);
    }
  }

  int corner_of(std::uint32_t t, VertexId v) const { return tris_[3 * t] == v ? 0 : tris_[3 * t + 1] == v ? 1 : 2; }

  Step step(VertexId a, VertexId b) const {
    for (const std::uint32_t t : around(a)) {
      const int i = corner_of(t, a);
      const VertexId u = tris_[3 * t + (i + 1) % 3], w = tris_[3 * t + (i + 2) % 3];
      const int ou = orient2d(pts_[a], pts_[b], pts_[u]), ow = orient2d(pts_[a], pts_[b], pts_[w]);
      for (const auto& [v, o] : {std::pair{u, ou}, std::pair{w, ow}})
        if (o == 0 && key(a, b, v) > key(a, b, a) && key(a, b, v) <= key(a, b, b)) return {v, kNone};
      if (ou < 0 && ow > 0) return {kNone, t};
    }
    throw std::logic_error("ridt: a segment found no way out of its vertex");
  }

  void mark(VertexId a, VertexId b, std::size_t index) { segment_of_.emplace(edge_key(a, b), index); }

  void refuse_crossing(VertexId u, VertexId w, std::size_t index) const {
    const auto it = segment_of_.find(edge_key(u, w));
    throw InputError("segments " + std::to_string(it->second) + " and " + std::to_string(index) +
                     " cross at a point that is not one of the points (splitting crossing segments is not "
                     "supported yet)");
  }

  // The triangles the segment crosses from a (leaving through triangle t) up to the next
  // vertex v on it, replaced; returns v.
  VertexId cross(VertexId a, VertexId b, std::uint32_t t, std::size_t index) {
    std::vector<std::uint32_t> removed{t};
    const int i = corner_of(t, a);
    VertexId u = tris_[3 * t + (i + 1) % 3], w = tris_[3 * t + (i + 2) % 3];  // u right, w left
    std::vector<VertexId> right{a, u}, left{a, w};
    for (std::uint32_t cur = t;;) {
      if (segment_of_.count(edge_key(u, w))) refuse_crossing(u, w, index);
      const std::uint32_t next = static_cast<std::uint32_t>(nbrs_[3 * cur + opposite(cur, u, w)]);
      removed.push_back(next);
      const VertexId x = tris_[3 * next + opposite(next, u, w)];
      const int o = orient2d(pts_[a], pts_[b], pts_[x]);
      if (o == 0) {
        right.push_back(x), left.push_back(x);
        replace(removed, right, left);
        mark(a, x, index);
        return x;
      }
      (o < 0 ? right : left).push_back(x);
      (o < 0 ? u : w) = x;
      cur = next;
    }
  }

  // The corner of triangle t that is neither u nor w.
  int opposite(std::uint32_t t, VertexId u, VertexId w) const {
    for (int k = 0; k < 3; ++k)
      if (tris_[3 * t + k] != u && tris_[3 * t + k] != w) return k;
    return 0;
  }

  // The constrained Delaunay triangles of polygon `poly` (its base poly.front() - poly.back(),
  // the rest on one side: `left` of the base's direction or right), counter-clockwise.
  void fill(const std::vector<VertexId>& poly, std::size_t lo, std::size_t hi, bool left,
            std::vector<VertexId>& out) const {
    if (hi - lo < 2) return;
    const VertexId a = poly[lo], v = poly[hi];
    std::size_t c = lo + 1;
    for (std::size_t d = lo + 2; d < hi; ++d) {
      const bool inside = left ? incircle(pts_[a], pts_[v], pts_[poly[c]], pts_[poly[d]]) > 0
                               : incircle(pts_[a], pts_[poly[c]], pts_[v], pts_[poly[d]]) > 0;
      if (inside) c = d;
    }
    if (left)
      out.insert(out.end(), {a, v, poly[c]});
    else
      out.insert(out.end(), {a, poly[c], v});
    fill(poly, lo, c, left, out);
    fill(poly, c, hi, left, out);
  }

  // Triangles `removed` replaced by the triangulations of the polygons right and left of the
  // segment's piece, in the same slots; the links inside and to the outside set anew.
  void replace(const std::vector<std::uint32_t>& removed, const std::vector<VertexId>& right,
               const std::vector<VertexId>& left) {
    // The outside: each directed edge of the region's boundary, as its outer triangle runs it.
    std::unordered_map<std::uint64_t, std::pair<std::int32_t, int>> outer;  // (x, y) -> triangle, slot
    const std::unordered_set<std::uint32_t> gone(removed.begin(), removed.end());
    for (const std::uint32_t t : removed)
      for (int k = 0; k < 3; ++k) {
        const std::int32_t n = nbrs_[3 * t + k];
        if (n >= 0 && gone.count(static_cast<std::uint32_t>(n))) continue;
        const VertexId x = tris_[3 * t + (k + 1) % 3], y = tris_[3 * t + (k + 2) % 3];
        int back = -1;
        if (n >= 0)
          for (int j = 0; j < 3; ++j)
            if (nbrs_[3 * n + j] == static_cast<std::int32_t>(t)) back = j;
        outer[(std::uint64_t{x} << 32) | y] = {n, back};
      }
    std::vector<VertexId> made;
    fill(right, 0, right.size() - 1, false, made);
    fill(left, 0, left.size() - 1, true, made);
    if (made.size() != 3 * removed.size())
      throw std::logic_error("ridt: a segment's polygons do not fill its triangles");
    std::unordered_map<std::uint64_t, std::pair<std::uint32_t, int>> inner;  // (x, y) of a new triangle
    for (std::size_t k = 0; k < removed.size(); ++k) {
      const std::uint32_t t = removed[k];
      for (int j = 0; j < 3; ++j) {
        tris_[3 * t + j] = made[3 * k + j];
        corner_[made[3 * k + j]] = 3 * t + j;
      }
      for (int j = 0; j < 3; ++j)
        inner[(std::uint64_t{tris_[3 * t + (j + 1) % 3]} << 32) | tris_[3 * t + (j + 2) % 3]] = {t, j};
    }
    for (const std::uint32_t t : removed)
      for (int j = 0; j < 3; ++j) {
        const VertexId x = tris_[3 * t + (j + 1) % 3], y = tris_[3 * t + (j + 2) % 3];
        const std::uint64_t twin = (std::uint64_t{y} << 32) | x;
        if (const auto in = inner.find(twin); in != inner.end()) {
          nbrs_[3 * t + j] = static_cast<std::int32_t>(in->second.first);
        } else {
          const auto& [n, back] = outer.at((std::uint64_t{x} << 32) | y);
          nbrs_[3 * t + j] = n;
          if (n >= 0) nbrs_[3 * n + back] = static_cast<std::int32_t>(t);
        }
      }
  }

  std::span<const Point> pts_;
  std::vector<VertexId>& tris_;
  std::vector<std::int32_t>& nbrs_;
  std::vector<std::uint32_t> corner_;  // for each vertex, a position in tris_ that holds it
  std::unordered_map<std::uint64_t, std::size_t> segment_of_;  // each segment's edge, and the segment
};

// Whether triangle t of `out` holds q (inside or on its boundary), exactly.
bool holds(const ConstrainedTriangulation& out, std::span<const Point> pts, std::size_t t, const Point& q) {
  const VertexId* v = &out.triangles[3 * t];
  return orient2d(pts[v[0]], pts[v[1]], q) >= 0 && orient2d(pts[v[1]], pts[v[2]], q) >= 0 &&
      orient2d(pts[v[2]], pts[v[0]], q) >= 0;
}

// The triangles outside `domain` removed: from the seeds (each hole's triangle; without the
// convex hull, every triangle on a hull edge that is not a segment's) across every edge that
// is not a segment's. The rest renumbered in order, their links to removed ones -1, the
// segments' edges that no kept triangle has dropped. `holes` are scaled as the points are.
void carve(ConstrainedTriangulation& out, std::span<const Point> pts, const std::vector<Point>& holes,
           bool convex_hull) {
  const std::size_t nt = out.size();
  std::unordered_set<std::uint64_t> segment;
  for (std::size_t k = 0; k < out.edges.size(); k += 2) segment.insert(edge_key(out.edges[k], out.edges[k + 1]));
  auto crossable = [&](std::size_t t, int j) {
    return !segment.count(edge_key(out.triangles[3 * t + (j + 1) % 3], out.triangles[3 * t + (j + 2) % 3]));
  };
  std::vector<std::uint8_t> gone(nt, 0);
  std::vector<std::size_t> todo;
  auto seed = [&](std::size_t t) {
    if (!gone[t]) gone[t] = 1, todo.push_back(t);
  };
  for (std::size_t t = 0; t < nt && !convex_hull; ++t)
    for (int j = 0; j < 3; ++j)
      if (out.neighbors[3 * t + j] < 0 && crossable(t, j)) seed(t);
  for (const Point& h : holes)
    for (std::size_t t = 0; t < nt && std::isfinite(h.x) && std::isfinite(h.y); ++t)
      if (holds(out, pts, t, h)) {
        seed(t);
        break;
      }
  while (!todo.empty()) {
    const std::size_t t = todo.back();
    todo.pop_back();
    for (int j = 0; j < 3; ++j)
      if (const std::int32_t n = out.neighbors[3 * t + j]; n >= 0 && crossable(t, j)) seed(static_cast<std::size_t>(n));
  }
  if (std::find(gone.begin(), gone.end(), 1) == gone.end()) return;
  std::vector<std::int32_t> id(nt, -1);
  std::size_t kept = 0;
  for (std::size_t t = 0; t < nt; ++t)
    if (!gone[t]) id[t] = static_cast<std::int32_t>(kept++);
  std::unordered_set<std::uint64_t> still;
  for (std::size_t t = 0; t < nt; ++t) {
    if (gone[t]) continue;
    const std::size_t to = static_cast<std::size_t>(id[t]);
    for (int j = 0; j < 3; ++j) {
      out.triangles[3 * to + j] = out.triangles[3 * t + j];
      const std::int32_t n = out.neighbors[3 * t + j];
      out.neighbors[3 * to + j] = n < 0 ? -1 : id[static_cast<std::size_t>(n)];
      still.insert(edge_key(out.triangles[3 * t + (j + 1) % 3], out.triangles[3 * t + (j + 2) % 3]));
    }
  }
  out.triangles.resize(3 * kept);
  out.neighbors.resize(3 * kept);
  out.hull.clear();
  std::vector<VertexId> edges;
  for (std::size_t k = 0; k < out.edges.size(); k += 2)
    if (still.count(edge_key(out.edges[k], out.edges[k + 1])))
      edges.push_back(out.edges[k]), edges.push_back(out.edges[k + 1]);
  out.edges = std::move(edges);
}

}  // namespace

ConstrainedTriangulation triangulate_constrained(std::span<const Point> points, std::span<const VertexId> segments,
                                                 const Options& options, const Domain& domain) {
  for (const Point& h : domain.holes)
    if (!std::isfinite(h.x) || !std::isfinite(h.y)) throw InputError("a hole's coordinate is not finite");
  if (segments.size() % 2 != 0)
    throw InputError("a segment list needs an even size (got " + std::to_string(segments.size()) + ")");
  for (std::size_t k = 0; k < segments.size(); ++k)
    if (segments[k] >= points.size())
      throw InputError("segment " + std::to_string(k / 2) + " refers to point " + std::to_string(segments[k]) + " of " +
                       std::to_string(points.size()));
  Options plain = options;
  plain.canonical_order = false;
  ConstrainedTriangulation out;
  static_cast<Triangulation&>(out) = triangulate(points, plain);
  std::vector<VertexId> kept(points.size());
  for (VertexId v = 0; v < kept.size(); ++v) kept[v] = v;
  for (const Duplicate& d : out.duplicates) kept[d.dropped] = d.kept;
  // The predicates on an exactly scaled copy where the coordinates are huge or tiny.
  std::vector<Point> scaled;
  const int scale = detail::exact_scale_exponent(points);
  if (scale != 0)
    for (const Point& p : points) scaled.push_back({std::ldexp(p.x, scale), std::ldexp(p.y, scale)});
  const std::span<const Point> pts = scaled.empty() ? points : std::span<const Point>(scaled);
  if (out.size() > 0) {
    Inserter inserter(pts, out);
    for (std::size_t s = 0; s + 1 < segments.size(); s += 2)
      if (kept[segments[s]] != kept[segments[s + 1]]) inserter.insert(kept[segments[s]], kept[segments[s + 1]], s / 2);
    out.edges = inserter.edges();
    std::vector<Point> holes = domain.holes;
    if (!scaled.empty())
      for (Point& h : holes) h = {std::ldexp(h.x, scale), std::ldexp(h.y, scale)};
    carve(out, pts, holes, domain.convex_hull);
  }
  if (options.canonical_order) detail::canonicalize(out, options.threads);
  return out;
}

}  // namespace ridt
