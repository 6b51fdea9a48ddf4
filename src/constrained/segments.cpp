// Segments inserted into the constrained triangulation (constrained/segments.hpp). A segment
// a-b walks from a: where an edge at a runs along it, that edge is a piece of the segment and
// the walk goes on from its other end; else the triangles it crosses, up to the next vertex v
// on it, are taken out, and the polygons left on either side of a-v are triangulated again,
// each by the vertex c whose circle through a and v holds no other of the polygon's vertices,
// then the two smaller polygons a..c and c..v in turn (the circles through a and v are
// ordered, so one pass finds c). Where the walk meets a fixed edge u-w that it crosses, the
// crossing point, exact and rounded to doubles, becomes a vertex x: u-x, x-w, a-x and x-b are
// then inserted in the segments' place.
#include "constrained/segments.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <utility>
#include <vector>

#include "predicates/predicates.hpp"

namespace ridt::detail {
namespace {

std::uint64_t directed(VertexId x, VertexId y) { return (std::uint64_t{x} << 32) | y; }

class Inserter {
 public:
  explicit Inserter(Cdt& m) : m_(m) {}

  // Input segment a-b, number `segment`, its pieces fixed edges that name it.
  void insert_segment(VertexId a, VertexId b, Constraint segment) {
    first_added_ = static_cast<VertexId>(m_.pts.size());
    insert(a, b, segment);
  }

 private:
  // a-b, a piece of input segment c.
  void insert(VertexId a, VertexId b, Constraint c) {
    while (a != b) {
      const Step s = step(a, b);
      if (s.along != kNoVertex) {
        m_.constrain(link_to(s.triangle, s.slot), c);
        // The next walk (or the next segment of a chain) starts from this triangle, at hand.
        m_.corner[s.along] = 3 * s.triangle + static_cast<std::uint32_t>(m_.corner_of(s.triangle, s.along));
        a = s.along;
        continue;
      }
      a = cross(a, b, s.triangle, c);
    }
  }

  struct Step {
    VertexId along = kNoVertex;  // an edge a-along runs along the segment (edge `slot` of `triangle`)
    TriangleId triangle = kNoTriangle;  // else the triangle at a through which the segment leaves a
    int slot = 0;
  };

  // Position along a -> b, exactly: by x, or by y on a vertical segment.
  double key(VertexId a, VertexId b, VertexId v) const {
    const auto& p = m_.pts;
    const bool by_x = p[a].x != p[b].x;
    const double sign = (by_x ? p[b].x - p[a].x : p[b].y - p[a].y) > 0 ? 1 : -1;
    return sign * (by_x ? p[v].x : p[v].y);
  }

  Step step(VertexId a, VertexId b) const {
    Step s;
    // Most segments are edges already: found by the vertices alone, with no predicate.
    if (m_.around(a, [&](std::uint32_t t) {
          const int i = m_.corner_of(t, a);
          if (m_.at(t, i + 1) == b) return s = {b, t, (i + 2) % 3}, true;
          if (m_.at(t, i + 2) == b) return s = {b, t, (i + 1) % 3}, true;
          return false;
        }))
      return s;
    const auto& p = m_.pts;
    const bool found = m_.around(a, [&](std::uint32_t t) {
      const int i = m_.corner_of(t, a);
      const VertexId u = m_.at(t, i + 1), w = m_.at(t, i + 2);
      const int ou = orient2d(p[a], p[b], p[u]), ow = orient2d(p[a], p[b], p[w]);
      if (ou == 0 && key(a, b, u) > key(a, b, a) && key(a, b, u) <= key(a, b, b)) return s = {u, t, (i + 2) % 3}, true;
      if (ow == 0 && key(a, b, w) > key(a, b, a) && key(a, b, w) <= key(a, b, b)) return s = {w, t, (i + 1) % 3}, true;
      if (ou < 0 && ow > 0) return s = {kNoVertex, t, 0}, true;
      return false;
    });
    if (!found) throw std::logic_error("ridt: a segment found no way out of its vertex");
    return s;
  }

  // The corner of triangle t that is neither u nor w.
  int opposite(std::uint32_t t, VertexId u, VertexId w) const {
    for (int k = 0; k < 3; ++k)
      if (m_.at(t, k) != u && m_.at(t, k) != w) return k;
    return 0;
  }

  // a-b (a piece of input segment c) meets fixed edge u-w (edge k of triangle t) inside both:
  // the rounded crossing x made a vertex, u-w replaced by u-x and x-w (pieces of u-w's own
  // segment), a-x inserted; returns x, from where a-b goes on.
  VertexId split_crossing(VertexId a, VertexId b, TriangleId t, int k, Constraint c) {
    const VertexId u = m_.at(t, k + 1), w = m_.at(t, k + 2);
    const Point x = crossing_rounded(m_.pts[a], m_.pts[b], m_.pts[u], m_.pts[w]);
    const Constraint other = m_.tds.constraint(link_to(t, k));
    m_.constrain(link_to(t, k), kFree);
    // Pieces of segments at a hair's angle, their ends rounded, can cross again at each crossing
    // added (a cascade, each piece's insertion nested in the last's, or one crossing after
    // another along the segment): past kCascade levels, or where u-w ends at a point added for
    // this input segment (which it meets again only by rounding), the crossing goes to the
    // nearest of the four ends instead, and no point is added.
    struct Level {
      int& depth;
      explicit Level(int& d) : depth(++d) {
        if (depth > 4 * kCascade) throw std::logic_error("ridt: crossings of segments at a hair's angle did not end");
      }
      ~Level() { --depth; }
    } level(depth_);
    VertexId v = 0;
    if (const VertexId end = within_ulps(x, {a, b, u, w}); end != kNoVertex) {
      v = end;  // within a few units in the last place of an end: the segments bend through it
    } else if (depth_ > kCascade || u >= first_added_ || w >= first_added_) {
      v = nearest(x, {a, b, u, w});
    } else if (const Cdt::Place at = m_.beside(t, k, x); at.kind == Cdt::Place::Corner) {
      v = m_.at(at.t, at.k);
    } else if (at.kind == Cdt::Place::Inside || at.kind == Cdt::Place::Edge) {
      v = m_.insert(x, at);
    } else if (m_.fits_on_edge(t, k, x)) {  // in neither triangle by a rounding: on the edge
      v = m_.insert_on_edge(x, t, k);
    } else if (const auto [y, far] = found_near(t, x); far.kind == Cdt::Place::Corner) {
      v = m_.at(far.t, far.k);  // beside triangles thinner than a rounding: wherever it lies
    } else if (far.kind != Cdt::Place::Outside) {
      v = m_.insert(y, far);
    } else {  // in a sliver of the hull with no double of its own near x: a corner at hand
      v = nearest(x, {a, b, u, w, m_.at(t, k)});
    }
    // u-w, no longer fixed, may be left standing where it is not locally Delaunay (x rounded
    // onto a vertex): flipped as it needs.
    if (const Link e = m_.find_edge(u, w); e != kNoLink) m_.restore({e});
    insert(u, v, other);
    insert(v, w, other);
    insert(a, v, c);
    return v;
  }

  // Where x lies in the triangulation (found from triangle t), and x itself; where x lies
  // outside it, beyond the hull by a rounding (the exact crossing lies on both segments, so
  // inside), the nearest of the doubles next to x in each coordinate that lies in it; Outside
  // where none does (the hull there thinner than a unit in the last place of x).
  std::pair<Point, Cdt::Place> found_near(TriangleId t, const Point& x) const {
    if (const Cdt::Place at = m_.find(t, x); at.kind != Cdt::Place::Outside) return {x, at};
    std::vector<Point> next;
    for (const double dx : {-1, 0, 1})
      for (const double dy : {-1, 0, 1})
        if (dx != 0 || dy != 0)
          next.push_back(
              {dx == 0 ? x.x : std::nextafter(x.x, dx * HUGE_VAL), dy == 0 ? x.y : std::nextafter(x.y, dy * HUGE_VAL)});
    auto off = [&](const Point& q) { return std::hypot(q.x - x.x, q.y - x.y); };
    std::stable_sort(next.begin(), next.end(), [&](const Point& p, const Point& q) { return off(p) < off(q); });
    for (const Point& y : next)
      if (const Cdt::Place at = m_.find(t, y); at.kind != Cdt::Place::Outside) return {y, at};
    return {x, Cdt::Place{Cdt::Place::Outside, 0, 0}};
  }

  // The one of `ends` nearest x.
  VertexId nearest(const Point& x, std::initializer_list<VertexId> ends) const {
    auto d2 = [&](VertexId e) {
      const long double dx = m_.pts[e].x - static_cast<long double>(x.x),
                        dy = m_.pts[e].y - static_cast<long double>(x.y);
      return dx * dx + dy * dy;
    };
    return *std::min_element(ends.begin(), ends.end(), [&](VertexId p, VertexId q) { return d2(p) < d2(q); });
  }

  // The first of `ends` within 4 units in the last place of x in each coordinate, or kNoVertex:
  // nearly collinear segments would otherwise cross again and again at the points added.
  VertexId within_ulps(const Point& x, std::initializer_list<VertexId> ends) const {
    auto close = [](double p, double q) {
      const double ulp = std::max(std::fabs(p), std::fabs(q)) * 0x1p-52;
      return std::fabs(p - q) <= 4 * ulp;
    };
    for (const VertexId e : ends)
      if (close(m_.pts[e].x, x.x) && close(m_.pts[e].y, x.y)) return e;
    return kNoVertex;
  }

  // The triangles the segment (a piece of input segment c) crosses from a (leaving through
  // triangle t) up to the next vertex v on it, replaced; returns v. (removed_, right_ and left_
  // are this call's: where it meets a fixed edge, the inserts that follow use them again, and
  // it returns what they return.)
  VertexId cross(VertexId a, VertexId b, TriangleId t, Constraint c) {
    const auto& p = m_.pts;
    removed_.assign({t});
    const int i = m_.corner_of(t, a);
    VertexId u = m_.at(t, i + 1), w = m_.at(t, i + 2);  // u right, w left
    right_.assign({a, u}), left_.assign({a, w});
    for (TriangleId cur = t;;) {
      const int k = opposite(cur, u, w);
      if (m_.fixed(link_to(cur, k))) return split_crossing(a, b, cur, k, c);
      const TriangleId next = m_.across(link_to(cur, k));
      removed_.push_back(next);
      const VertexId x = m_.at(next, opposite(next, u, w));
      const int o = orient2d(p[a], p[b], p[x]);
      if (o == 0) {
        right_.push_back(x), left_.push_back(x);
        if (removed_.size() == 2)
          m_.flip(link_to(t, m_.corner_of(t, a)));  // one edge crossed: t becomes (a, u, x), the other (a, x, w)
        else
          replace();
        m_.constrain(m_.find_edge(a, x), c);
        return x;
      }
      (o < 0 ? right_ : left_).push_back(x);
      (o < 0 ? u : w) = x;
      cur = next;
    }
  }

  // The constrained Delaunay triangles of polygon `poly` (its base poly.front() - poly.back(),
  // the rest on one side: `left` of the base's direction or right), counter-clockwise.
  void fill(const std::vector<VertexId>& poly, std::size_t lo, std::size_t hi, bool left,
            std::vector<VertexId>& out) const {
    if (hi - lo < 2) return;
    const auto& p = m_.pts;
    const VertexId a = poly[lo], v = poly[hi];
    std::size_t c = lo + 1;
    for (std::size_t d = lo + 2; d < hi; ++d) {
      const bool inside =
          left ? incircle(p[a], p[v], p[poly[c]], p[poly[d]]) > 0 : incircle(p[a], p[poly[c]], p[v], p[poly[d]]) > 0;
      if (inside) c = d;
    }
    if (left)
      out.insert(out.end(), {a, v, poly[c]});
    else
      out.insert(out.end(), {a, poly[c], v});
    fill(poly, lo, c, left, out);
    fill(poly, c, hi, left, out);
  }

  // A boundary edge of the triangles a piece replaces, as its outer triangle runs it: the link
  // across (kNoLink on the boundary) and its constraint.
  struct Outer {
    Link outside;
    Constraint c;
  };
  using Keyed = std::pair<std::uint64_t, Outer>;

  // Triangles removed_ replaced by the triangulations of the polygons right_ and left_ of the
  // segment's piece, in the same slots; the links inside and to the outside set anew. Edges
  // are looked up in sorted lists: a piece crosses a few triangles, or very many.
  void replace() {
    gone_.assign(removed_.begin(), removed_.end());
    std::sort(gone_.begin(), gone_.end());
    outer_.clear();  // each directed boundary edge, as its outer triangle runs it
    for (const TriangleId t : removed_)
      for (int k = 0; k < 3; ++k) {
        const Link e = link_to(t, k);
        const TriangleId n = m_.across(e);
        if (n != kNoTriangle && std::binary_search(gone_.begin(), gone_.end(), n)) continue;
        outer_.push_back({directed(m_.at(t, k + 1), m_.at(t, k + 2)), {m_.tds.link_at(e), m_.tds.constraint(e)}});
      }
    std::sort(outer_.begin(), outer_.end(), [](const Keyed& x, const Keyed& y) { return x.first < y.first; });
    made_.clear();
    fill(right_, 0, right_.size() - 1, false, made_);
    fill(left_, 0, left_.size() - 1, true, made_);
    if (made_.size() != 3 * removed_.size())
      throw std::logic_error("ridt: a segment's polygons do not fill its triangles");
    inner_.clear();  // (x, y) of a new triangle's edge, and its link
    for (std::size_t k = 0; k < removed_.size(); ++k) {
      const TriangleId t = removed_[k];
      for (int j = 0; j < 3; ++j) {
        m_.tds.set_vertex(t, j, made_[3 * k + j]);
        m_.corner[made_[3 * k + j]] = 3 * t + static_cast<TriangleId>(j);
      }
      for (int j = 0; j < 3; ++j) inner_.push_back({directed(m_.at(t, j + 1), m_.at(t, j + 2)), link_to(t, j)});
    }
    std::sort(inner_.begin(), inner_.end());
    for (const TriangleId t : removed_)
      for (int j = 0; j < 3; ++j) {
        const VertexId x = m_.at(t, j + 1), y = m_.at(t, j + 2);
        const Link e = link_to(t, j);
        const auto in = std::lower_bound(inner_.begin(), inner_.end(), std::pair{directed(y, x), Link{0}});
        if (in != inner_.end() && in->first == directed(y, x)) {
          m_.tds.set_link(e, in->second);
          m_.tds.set_constraint(e, kFree);
          continue;
        }
        const auto out = std::lower_bound(outer_.begin(), outer_.end(), directed(x, y),
                                          [](const Keyed& o, std::uint64_t key) { return o.first < key; });
        if (out == outer_.end() || out->first != directed(x, y))
          throw std::logic_error("ridt: a segment's new triangle has an edge that was not there");
        const Outer& o = out->second;
        m_.tds.glue(e, o.outside);
        m_.tds.set_constraint(e, o.c);
      }
  }

  static constexpr int kCascade = 32;
  Cdt& m_;
  int depth_ = 0;  // split_crossing's calls nested
  VertexId first_added_ = 0;  // the first point added for the input segment being inserted
  // Scratch, kept between segments.
  std::vector<TriangleId> removed_, gone_;
  std::vector<VertexId> right_, left_, made_;
  std::vector<Keyed> outer_;
  std::vector<std::pair<std::uint64_t, Link>> inner_;
};

}  // namespace

void insert_segments(Cdt& m, std::span<const VertexId> segments, std::span<const VertexId> kept) {
  Inserter inserter(m);
  // A segment's walk begins at the triangles about its first vertex, which lie wherever the
  // Delaunay triangulation put them: those of the segments some way on are asked for ahead, in
  // two stages, the triangle at the vertex and then, once it is at hand, its neighbours.
  constexpr std::size_t kFar = 16, kNear = 8;
  const std::size_t count = segments.size() / 2;
  const VertexId* v = m.tds.vertex_array().data();
  const Link* link = m.tds.link_array().data();
  auto slot_of = [&](std::size_t s) { return s < count ? m.corner[kept[segments[2 * s]]] : kNoTriangle; };
  for (std::size_t s = 0; s < count; ++s) {
    if (const std::uint32_t c = slot_of(s + kFar); c != kNoTriangle) {
      __builtin_prefetch(v + (c - c % 3));
      __builtin_prefetch(link + (c - c % 3));
    }
    if (const std::uint32_t c = slot_of(s + kNear); c != kNoTriangle)
      for (std::uint32_t j = c - c % 3; j < c - c % 3 + 3; ++j)
        if (const Link l = link[j]; l != kNoLink) {
          __builtin_prefetch(v + (l - l % 3));
          __builtin_prefetch(link + (l - l % 3));
        }
    const VertexId a = kept[segments[2 * s]], b = kept[segments[2 * s + 1]];
    if (a != b) inserter.insert_segment(a, b, static_cast<Constraint>(s));
    v = m.tds.vertex_array().data(), link = m.tds.link_array().data();  // the arrays may have grown
  }
}

}  // namespace ridt::detail
