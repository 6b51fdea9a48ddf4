// The refiner of constrained/refine.cpp: its state and its small steps. Its steps near small
// input angles are in constrained/small_angles.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <new>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "constrained/buckets.hpp"
#include "constrained/cdt.hpp"
#include "constrained/refine.hpp"
#include "order/order.hpp"
#include "predicates/predicates.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"

namespace ridt::detail::refining {

inline double dot(const Point& a, const Point& b, const Point& p) {
  return (a.x - p.x) * (b.x - p.x) + (a.y - p.y) * (b.y - p.y);
}
inline double dist2(const Point& a, const Point& b) { return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y); }
// The angle from o->u to o->w, counter-clockwise positive, in (-pi, pi].
inline double turn(const Point& o, const Point& u, const Point& w) {
  const double ux = u.x - o.x, uy = u.y - o.y, wx = w.x - o.x, wy = w.y - o.y;
  return std::atan2(ux * wy - uy * wx, ux * wx + uy * wy);
}

inline constexpr double kGood = std::numeric_limits<double>::infinity();
// Two squared distances from a corner this close, relatively, are one distance (seditious edges,
// partners).
inline constexpr double kOneDistance = 1e-5;

/// A tile's refinement (constrained/tiles.cpp): the mesh is a tile's triangles and, in slots
/// [ghost_begin, ghost_end), the triangles beside them that are not the tile's (its ghosts),
/// which no step may change. A point whose cavity would reach a ghost, a subsegment with a ghost
/// beside it, and a point beyond the tile are left for the whole mesh's refinement after.
struct Fence {
  TriangleId ghost_begin = 0, ghost_end = 0;
  Extent box;  ///< the whole mesh's: the Hilbert keys and the thresholds are the whole mesh's
};

class Refiner {
 public:
  /// Refines m as r asks, from `chains` (a stage before's: constrained/tiles.cpp) where given;
  /// `fence`: m is a tile's.
  Refiner(Cdt& m, const Refinement& r, Chains chains = {}, const Fence* fence = nullptr) : m_(m), r_(r), fence_(fence) {
    const double s = std::sin(r.min_angle * 3.14159265358979323846 / 180);
    sin2_ = s * s;
    half_bound_ = r.min_angle * 3.14159265358979323846 / 360;
    // The off-centre 5 % nearer the edge than where the new triangle's angle would be the
    // bound exactly: then it is not bad again by a rounding (23 % fewer points on a coastline of 10^4 vertices).
    offset_ = r.min_angle > 0 ? 0.475 / std::tan(r.min_angle * 3.14159265358979323846 / 360) : 0;
    const double lens = std::sin(std::max(r.min_angle, 30.0) * 3.14159265358979323846 / 180);
    lens_ = 1 - 2 * lens * lens;  // the cosine of twice the lens angle (in_lens)
    box_ = fence != nullptr ? fence->box : extent_of(m.pts);
    diag2_ = dist2({box_.x0, box_.y0}, {box_.x1, box_.y1});
    tiny2_ = diag2_ * 0x1p-80;  // edges below 2^-40 of the diagonal stay
    cells_ = 65535 / std::max(box_.x1 - box_.x0, box_.y1 - box_.y0);  // infinite for one point: see curve()
    ends_ = std::move(chains.ends);
    ends_.resize(m.pts.size(), {kNoVertex, kNoVertex});
    small_ = std::move(chains.small);
  }

  /// The corners where two segments meet below 60 degrees (per corner: 1 where they do), the
  /// boundary fixed.
  std::vector<std::uint8_t> small_angles() {
    fix_boundary();
    find_small_angles();
    return small_;
  }
  std::vector<VertexId> removed() { return std::move(removed_); }  ///< those run() took out (for Cdt::compact)
  /// The chains as run() left them.
  Chains take_chains() { return {std::move(ends_), std::move(small_)}; }

  std::string run() {
    fix_boundary();
    if (small_.empty()) find_small_angles();
    first_queues();
    const std::size_t first = m_.pts.size();
    // Stop before the memory the process has left runs out, rather than be killed for it. A
    // point added costs some 100 bytes (two triangles with their neighbours and flags, the
    // point, its corner, queue entries), twice that in arrays that grow by doubling, and the
    // result's arrays come on top: a whole run peaks at 215 to 265 bytes a point added (ridt
    // mesh and Python's ConstrainedDelaunay, 10^6 and 4 * 10^6 points), so 320 of 3/4 of it.
    const std::size_t room = (r_.memory != 0 ? r_.memory : available_memory()) / 320 * 3 / 4;
    auto out_of_memory = [&] {
      const std::size_t from = r_.added_from != 0 ? std::min(r_.added_from, first) : first;
      return "quality refinement stopped after " + std::to_string(m_.pts.size() - from) +
          " points: the memory left holds no more";
    };
    // A step's insertion allocates nothing once room_ahead() has made room (Cdt::make_room), so
    // an allocation refused within a step is the queues' or a search's, with the mesh whole.
    try {
      while (true) {
        if (r_.max_steiner > 0 && m_.pts.size() - removed_.size() - first >= r_.max_steiner)
          return "quality refinement stopped after " + std::to_string(r_.max_steiner) + " points (the limit asked)";
        if ((room > 0 && m_.pts.size() - first >= room) || !room_ahead()) return out_of_memory();
        if (!segments_.empty()) {
          const Split w = segments_.back();
          segments_.pop_back();
          const Link s = m_.find_edge(w.x, w.y);
          if (s != kNoLink && m_.fixed(s) && (w.forced || to_split(s))) split(w.clear ? clear_circle(s, w) : s);
          continue;
        }
        if (!unsized_.empty() && (bad_.empty() || unsized_.size() >= kSizeBatch)) {
          weigh_sizes();
          continue;
        }
        if (bad_.empty()) return left_bad();
        const Bad b = bad_.pop();
        prefetch_ahead();
        // A triangle still there has the vertices, so the badness, it was queued with.
        if (alive(b)) improve(b);
      }
    } catch (const std::bad_alloc&) {
      return out_of_memory();
    }
  }

 private:
  void fix_boundary() {  // (on threads for the whole mesh: a boundary edge has one side)
    parallel_for(3 * std::size_t{m_.size()}, fence_ == nullptr ? r_.threads : 1, 1 << 18,
                 [&](std::size_t from, std::size_t to) {
                   for (auto s = static_cast<Link>(from); s < static_cast<Link>(to); ++s)
                     if (m_.boundary(s) && !m_.fixed(s)) m_.constrain(s, kUnnamed);
                 });
  }

  void first_queues();

  // Room in the mesh's arrays for the next few points, grown by a quarter or more where there
  // is none (Cdt::make_room), and in the chains' ends alike; false where memory refuses it.
  // The share of memory a point is allowed above does not cover that growth, which copies
  // what the mesh holds already.
  static constexpr std::size_t kAhead = 64;
  bool room_ahead() { return m_.pts.size() + kAhead <= room_until_ || make_room(); }
  bool make_room();
  std::size_t room_until_ = 0;  // the count of points the arrays take as they are

  struct Split {
    VertexId x, y;
    bool forced;  // split though no flaw (to_split): a point to be added, or its bad triangle (split_own), asks
    bool clear = false;  // for a point refused beside it: clear_circle first
  };
  void queue_split(Link s, bool forced, bool clear = false) {
    segments_.push_back({m_.tds.tail(s), m_.tds.head(s), forced, clear});
  }

  // Most queued triangles are gone by their turn (four in five on a coastline), and those
  // still there, with their neighbours, lie anywhere in memory: what the next pops will read is
  // asked for in stages, each reading only what the stage before asked for some pops earlier.
  // Eight pops ahead a triangle's vertices (to tell whether it is still there); four ahead,
  // where it is, its points and neighbours; two ahead its neighbours' vertices.
  void prefetch_ahead() const {
    auto still_there = [&](std::size_t ahead) {
      const Bad* b = bad_.ahead(ahead);
      return b != nullptr && alive(*b) ? b : nullptr;
    };
    const VertexId* v = m_.tds.vertex_array().data();
    const Link* link = m_.tds.link_array().data();
    if (const Bad* b = bad_.ahead(8)) __builtin_prefetch(v + 3 * std::size_t{b->t});
    if (const Bad* b = still_there(4)) {
      for (const VertexId w : b->v) __builtin_prefetch(&m_.pts[w]);
      __builtin_prefetch(link + 3 * std::size_t{b->t});
    }
    if (const Bad* b = still_there(2))
      for (int k = 0; k < 3; ++k)
        if (const Link l = link[3 * std::size_t{b->t} + k]; l != kNoLink) __builtin_prefetch(v + (l - l % 3));
  }

  struct Bad {
    double key;  // badness(t), the smaller first
    std::uint32_t t;
    VertexId v[3];
    int tries;
    std::uint32_t where;  // the Hilbert key of t's first vertex
  };

  bool corner(VertexId v) const { return v < r_.corners; }
  // Whether an edge of t is longer than r_.longer_than.
  bool longer(TriangleId t) const {
    const Point &a = m_.pts[m_.at(t, 0)], &b = m_.pts[m_.at(t, 1)], &c = m_.pts[m_.at(t, 2)];
    return std::max({dist2(a, b), dist2(b, c), dist2(c, a)}) > r_.longer_than * r_.longer_than;
  }

  // A tile's refinement (Fence): whether t is a ghost; whether edge s has one on either side
  // (then it cannot change); whether the cavity just found (Cdt::find_cavity, for p) stops at a
  // ghost whose circle holds p (the whole mesh's cavity would take it in); whether p, to be
  // added at `at`, would change a ghost so (its cavity found, for would_encroach's list).
  bool ghost(TriangleId t) const { return fence_ != nullptr && t >= fence_->ghost_begin && t < fence_->ghost_end; }
  bool frozen(Link s) const { return fence_ != nullptr && (ghost(triangle_of(s)) || ghost(m_.across(s))); }
  bool crosses_fence(const Point& p) const {
    const CavityScratch& s = m_.cavity();
    for (std::size_t i = 0; i < s.edges; ++i)
      if (const TriangleId g = m_.across(s.boundary[i].inside); g != kNoTriangle && ghost(g) &&
          incircle(m_.pts[m_.at(g, 0)], m_.pts[m_.at(g, 1)], m_.pts[m_.at(g, 2)], p) > 0)
        return true;
    return false;
  }
  bool fenced(const Point& p, const Cdt::Place& at) {
    if (fence_ == nullptr) return false;
    if (at.kind != Cdt::Place::Inside && frozen(link_to(at.t, at.k))) return true;
    m_.find_cavity(p, at);
    return crosses_fence(p);
  }
  // Whether p, put on subsegment s, would change a ghost: its cavities on both sides.
  bool fenced_split(Link s, const Point& p) {
    if (fence_ == nullptr) return false;
    if (frozen(s)) return true;
    for (const Link side : {s, m_.tds.link_at(s)}) {
      if (side == kNoLink) continue;
      m_.find_cavity(p, {Cdt::Place::Edge, triangle_of(side), edge_of(side)});
      if (crosses_fence(p)) return true;
    }
    return false;
  }
  bool boundary(Link s) const { return m_.boundary(s); }
  std::string left_bad() const;

  bool alive(const Bad& b) const {
    return b.t < m_.size() && m_.at(b.t, 0) == b.v[0] && m_.at(b.t, 1) == b.v[1] && m_.at(b.t, 2) == b.v[2];
  }
  // A triangle queued where bad; with a size field, first put aside until the field is asked
  // for the sizes of a batch of them (weigh_sizes).
  void queue_bad(std::uint32_t t) {
    if (r_.longer_than > 0 && !longer(t)) return;
    if (r_.sizes) return unsized_.push_back({kGood, t, {m_.at(t, 0), m_.at(t, 1), m_.at(t, 2)}, 0, 0});
    push_if_bad(t, badness(t));
  }
  void push_if_bad(std::uint32_t t, double key) {
    if (key != kGood) bad_.push({key, t, {m_.at(t, 0), m_.at(t, 1), m_.at(t, 2)}, 0, curve(m_.pts[m_.at(t, 0)])});
  }
  // The sizes at the centroids of the triangles put aside and still there, in one call of the
  // field; each then queued where bad. The batches depend on the mesh alone, so the mesh does
  // not depend on how the field is given.
  void weigh_sizes() {
    std::erase_if(unsized_, [&](const Bad& b) { return !alive(b); });
    centroids_.resize(unsized_.size()), sizes_.resize(unsized_.size());
    for (std::size_t k = 0; k < unsized_.size(); ++k) {
      const Point &a = m_.pts[unsized_[k].v[0]], &b = m_.pts[unsized_[k].v[1]], &c = m_.pts[unsized_[k].v[2]];
      centroids_[k] = {a.x / 3 + b.x / 3 + c.x / 3, a.y / 3 + b.y / 3 + c.y / 3};
    }
    r_.sizes(centroids_, sizes_);
    for (std::size_t k = 0; k < unsized_.size(); ++k) push_if_bad(unsized_[k].t, badness(unsized_[k].t, sizes_[k]));
    unsized_.clear();
  }

  // Whether subsegment s is to be split before any bad triangle (refine.cpp).
  bool to_split(Link s) const;
  // Whether vertex v may encroach a subsegment (encroached says why).
  bool counts(VertexId v) const { return r_.conforming || corner(v) || ends_[v].first == kNoVertex; }
  // The subsegment in slot s has a vertex strictly inside its diametral circle: the apex of its
  // triangle or of the one across. A point added on another subsegment counts only for a
  // conforming triangulation: two segments near each other (at a small angle, or side by side)
  // would split each other down to the gap between them, where the bounds need no such thing
  // (an angle bound splits them through their triangles' off-centres where it must).
  // With `sharp_only`, only through a triangle below the angle bound that the bound exempts.
  bool encroached(Link s, bool sharp_only = false) const {
    const Point &a = m_.pts[m_.tds.tail(s)], &b = m_.pts[m_.tds.head(s)];
    auto inside = [&](VertexId v) { return counts(v) && dot(a, b, m_.pts[v]) < 0; };
    auto through = [&](Link e) { return !sharp_only || exempt_sharp(triangle_of(e)); };
    if (inside(m_.tds.vertex_at(s)) && through(s)) return true;
    const VertexId across = m_.apex_across(s);
    return across != kNoVertex && inside(across) && through(m_.tds.link_at(s));
  }
  // Whether triangle t's smallest angle is below the bound where the bound exempts it (at a
  // small input angle: badness leaves it be).
  bool exempt_sharp(TriangleId t) const {
    if (!(sin2_ > 0)) return false;
    const VertexId v[3] = {m_.at(t, 0), m_.at(t, 1), m_.at(t, 2)};
    const Point &a = m_.pts[v[0]], &b = m_.pts[v[1]], &c = m_.pts[v[2]];
    const double twice = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    const double l[3] = {dist2(b, c), dist2(c, a), dist2(a, b)};
    const int k = shortest(l);
    return twice * twice / (l[(k + 1) % 3] * l[(k + 2) % 3]) < sin2_ && at_apex(v[(k + 1) % 3], v[(k + 2) % 3], v[k]);
  }

  // The corners at the ends of the chain of subsegments that subsegment x-y lies on.
  std::pair<VertexId, VertexId> chain(VertexId x, VertexId y) const {
    return corner(x) && corner(y) ? std::pair{x, y} : corner(x) ? ends_[y] : ends_[x];
  }

  // The corner across from triangle t's shortest edge, given its squared sides l (across from
  // corners 0, 1, 2).
  static int shortest(const double (&l)[3]) { return l[0] <= l[1] && l[0] <= l[2] ? 0 : l[1] <= l[2] ? 1 : 2; }

  // The corners at the ends of the chain a vertex on one lies on, the smaller first.
  std::pair<VertexId, VertexId> chain_of(VertexId v) const { return ordered(ends_[v]); }
  static std::pair<VertexId, VertexId> ordered(std::pair<VertexId, VertexId> e) {
    return {std::min(e.first, e.second), std::max(e.first, e.second)};
  }

  // The corner below 60 degrees where the chains of u and w (two of them) meet, or kNoVertex.
  VertexId apex(VertexId u, VertexId w) const {
    if (corner(u) || corner(w) || ends_[u].first == kNoVertex || ends_[w].first == kNoVertex) return kNoVertex;
    const auto [u1, u2] = chain_of(u);
    const auto [w1, w2] = chain_of(w);
    if (u1 == w1 && u2 == w2) return kNoVertex;  // one chain
    for (const VertexId z : {u1, u2})
      if (small_[z] && (z == w1 || z == w2)) return z;
    return kNoVertex;
  }

  // apex(u, w) where the chains make an angle below half the angle bound there: a wedge so
  // thin that mending its triangles would cut the chains down to the gap between them.
  VertexId thin_apex(VertexId u, VertexId w) const {
    const VertexId z = apex(u, w);
    if (z == kNoVertex) return z;
    return std::fabs(turn(m_.pts[z], m_.pts[u], m_.pts[w])) < half_bound_ ? z : kNoVertex;
  }

  // Edge u-w is seditious (Shewchuk's word): u and w lie on two chains that meet at a corner z
  // below 60 degrees, at one distance from z. A triangle whose shortest edge it is gets its
  // small angle from the input's where it is z-u-w, or where its point would split one of the
  // two chains; splitting it would only cut the shells finer.
  bool seditious(VertexId u, VertexId w) const {
    const VertexId z = apex(u, w);
    if (z == kNoVertex) return false;
    const double du = dist2(m_.pts[z], m_.pts[u]), dw = dist2(m_.pts[z], m_.pts[w]);
    return std::fabs(du - dw) <= kOneDistance * std::max(du, dw);
  }
  bool at_apex(VertexId u, VertexId w, VertexId third) const { return third == apex(u, w) && seditious(u, w); }

  // Whether triangle t's smallest angle, at corner s (l: its squared sides, across from each
  // corner; twice: its doubled area), lies between two segments (t's two edges there are fixed):
  // an input angle, which no point added can widen (Triangle's documentation says the same of
  // its bound), with t's other angles within the bound. Refining such a triangle only repeats
  // the angle in smaller ones: leaving it took a tenth fewer triangles on random star polygons,
  // most of them in their spikes.
  bool input_angle(TriangleId t, int s, const double (&l)[3], double twice) const;

  double area_bound(std::uint32_t t) const {
    double bound = r_.max_area;
    if (r_.given != nullptr && !m_.region.empty()) m_.region[t] = r_.given->region_of(m_, t);
    if (!m_.region.empty() && m_.region[t] >= 0) {
      const double own = r_.region_area[static_cast<std::size_t>(m_.region[t])];
      if (own > 0) bound = bound > 0 ? std::min(bound, own) : own;
    }
    return bound;
  }

  // Where triangle t stands in the queue of bad triangles, kGood where it is good: one with a
  // small angle by its shortest edge's squared length (the smallest first: the sizes then grade
  // out from the boundary, with 29 % fewer points than worst shaped first on a 10^4-vertex
  // coastline); after all of those (the queue takes negative keys last) one too large (whatever
  // its angles) by minus its area over its bound, or its longest edge's squared length over the
  // squared `size` (the largest first: -1 or below), then one the caller's test finds unsuitable,
  // refined as one too large is (the largest first, from -1/3 to 0).
  double badness(std::uint32_t t, double size = kGood) const {
    const VertexId v[3] = {m_.at(t, 0), m_.at(t, 1), m_.at(t, 2)};
    const Point &a = m_.pts[v[0]], &b = m_.pts[v[1]], &c = m_.pts[v[2]];
    const double twice = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    // First: the terminator (improve) may leave a small angle, never an area above its bound.
    double large = 0;
    if (const double bound = area_bound(t); bound > 0 && twice > 2 * bound) large = twice / (2 * bound);
    if (size != kGood) {
      const double longest = std::max({dist2(b, c), dist2(c, a), dist2(a, b)}), h2 = size * size;
      // (kept finite where h2 underflows: the queue's buckets take finite keys)
      if (longest > h2) large = std::max(large, std::min(longest / h2, 0x1p1000));
    }
    if (large > 0) return -large;
    // Within the box a triangle's doubled area is at most diag2_ / 2, so this is in [-1/3, 0)
    // (divided first: diag2_ may be near the largest double).
    if (r_.unsuitable && r_.unsuitable(a, b, c, twice)) {
      const double r = twice / diag2_;
      return std::min(-r / (1 + r), -0x1p-1000);
    }
    if (sin2_ > 0) {
      const double l[3] = {dist2(b, c), dist2(c, a), dist2(a, b)};  // across from corner 0, 1, 2
      const int s = shortest(l);
      const double sine2 = twice * twice / (l[(s + 1) % 3] * l[(s + 2) % 3]);
      if (l[s] >= tiny2_ && sine2 < sin2_ && !input_angle(t, s, l, twice) &&
          !at_apex(v[(s + 1) % 3], v[(s + 2) % 3], v[s]))
        return l[s];
    }
    return kGood;
  }

  // Where triangle t gets its point: the off-centre of its shortest edge. The circumcentre is
  // computed within its bound (circumcentre_bounded: exactly where the filter cannot vouch for
  // it), so that a sliver's point lies where it is meant to, and not where rounding or an
  // overflow in its distance would put it (on the edge itself, whose pieces then shrank without
  // end).
  Point off_centre(TriangleId t) const {
    const Point &a = m_.pts[m_.at(t, 0)], &b = m_.pts[m_.at(t, 1)], &c = m_.pts[m_.at(t, 2)];
    const Point cc = circumcentre_bounded(a, b, c);
    if (offset_ == 0) return cc;
    const double l[3] = {dist2(b, c), dist2(c, a), dist2(a, b)};
    const int s = shortest(l);
    const Point &p = m_.pts[m_.at(t, s + 1)], &q = m_.pts[m_.at(t, s + 2)];
    const Point mid{(p.x + q.x) / 2, (p.y + q.y) / 2};
    const double reach = offset_ * std::sqrt(l[s]), far = std::sqrt(dist2(cc, mid));
    if (!(far > reach)) return cc;  // (NaN where the corners are collinear)
    if (std::isfinite(far)) {
      const double f = reach / far;
      return {mid.x + (cc.x - mid.x) * f, mid.y + (cc.y - mid.y) * f};
    }
    // The centre so far that its squared distance overflows, or beyond the doubles (a sliver):
    // its direction from the middle of the edge p -> q is the edge's left normal, toward t.
    const double ex = q.x - p.x, ey = q.y - p.y, length = std::hypot(ex, ey);
    return {mid.x - ey / length * reach, mid.y + ex / length * reach};
  }

  // The fixed edges that p, added in `at`, would encroach (refine.cpp).
  std::vector<Link>& would_encroach(const Point& p, const Cdt::Place& at);
  bool in_lens(const Point& a, const Point& b, const Point& p) const;

  bool splittable(Link s) const {
    if (!r_.split_segments || (!r_.split_boundary && boundary(s))) return false;
    return dist2(m_.pts[m_.tds.tail(s)], m_.pts[m_.tds.head(s)]) >= 4 * tiny2_;
  }

  void improve(const Bad& b);

  void split_own(TriangleId t);

  void leave(const Bad& b);

  void centroid(const Bad& b);

  // Where subsegment x-y is split: at the power of two nearest the midpoint's distance from its
  // end at a small angle where exactly one end is such, or, neither end such, from the end of
  // its chain (the segment's subsegments) at a small angle where exactly one is (Shewchuk's
  // concentric shells: the two chains of a small angle are cut at the same distances, so their
  // pieces never grow shorter than the gap across), where that falls well inside; else at the
  // midpoint. Shells about corners with no small angle cut the segments unevenly for nothing
  // (docs/constrained.md: spiky star polygons took a sixth more triangles with them).
  Point split_point(VertexId x, VertexId y) const;
  bool matched(VertexId z, VertexId y, Point& at) const;

  void split(Link s);
  VertexId split_at(Link s, const Point& given);
  void relabel(VertexId v, VertexId x, VertexId y, std::int32_t left, std::int32_t right);
  void added(VertexId v);
  Link clear_circle(Link s, const Split& w);
  std::vector<VertexId> removed_;  // free vertices taken out (clear_circle)
  void find_small_angles();
  void find_small_angle(VertexId z);
  bool wedged(TriangleId t, const std::vector<Link>& hit);
  bool partnered(std::uint32_t t);
  bool partner(VertexId x, VertexId y, VertexId z);
  bool terminated(Link s, TriangleId t) const;

  Cdt& m_;
  const Refinement& r_;
  const Fence* fence_ = nullptr;
  bool deferred_ = false;  // split_at left a split to the whole mesh (a tile's fence)
  // Where p lies along the Hilbert curve over the points' box (a point added lies in it); a
  // box too wide or too thin for the scale (an infinite or NaN cell) puts p at an end.
  std::uint32_t curve(const Point& p) const {
    auto cell = [&](double v, double from) {
      const double c = (v - from) * cells_;
      return c >= 0 ? (c < 65535 ? static_cast<std::uint32_t>(c) : 65535u) : 0u;
    };
    return hilbert_key(cell(p.x, box_.x0), cell(p.y, box_.y0));
  }

  double sin2_ = 0, half_bound_ = 0, lens_ = 0, offset_ = 0, diag2_ = 0, tiny2_ = 0, cells_ = 0;
  Extent box_;
  std::vector<std::pair<VertexId, VertexId>> ends_;  // per vertex on a chain: its corners
  std::vector<std::uint8_t> small_;  // per corner: two of its segments meet at less than 60 degrees
  std::vector<Split> segments_;  // subsegments to split, if still there (and encroached)
  std::vector<Bad> given_up_;  // triangles left bad: for their shape after 64 tries, too large with no point inside
  Buckets<Bad> bad_;
  // With a size field: the triangles made since the field was last asked, and its answers.
  static constexpr std::size_t kSizeBatch = 4096;
  std::vector<Bad> unsized_;
  std::vector<Point> centroids_;
  std::vector<double> sizes_;
  std::vector<Link> hit_;  // would_encroach's
  // Subsegments split could not split, each by its ends and the apexes on either side (kNoVertex
  // beyond the boundary): the outcome depends on those four alone, so a subsegment asked again
  // with the same neighbours is not tried again (where coordinates span the doubles' range, a
  // wedge's bad triangles asked for the same unsplittable subsegments 600,000 times, each try
  // exact at some thousand bits).
  struct Unsplit {
    VertexId v[4];
    bool operator==(const Unsplit& o) const { return std::equal(v, v + 4, o.v); }
  };
  struct UnsplitHash {
    std::size_t operator()(const Unsplit& u) const {
      std::uint64_t h = 0;
      for (const VertexId v : u.v) h = (h ^ v) * 0x9e3779b97f4a7c15u;
      return static_cast<std::size_t>(h ^ (h >> 29));
    }
  };
  std::unordered_set<Unsplit, UnsplitHash> unsplit_;
  Unsplit unsplit_key(Link s) const {
    return {{m_.tds.tail(s), m_.tds.head(s), m_.tds.vertex_at(s), m_.apex_across(s)}};
  }
};

}  // namespace ridt::detail::refining
