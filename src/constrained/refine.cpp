// Delaunay refinement (constrained/refine.hpp), after Ruppert ("A Delaunay refinement
// algorithm for quality 2-dimensional mesh generation", 1995) and Shewchuk ("Delaunay
// refinement algorithms for triangular mesh generation", 2002): a subsegment is encroached
// when a vertex it sees lies strictly inside its diametral circle; those are split first
// (at the midpoint, or, where one end is a corner, at a power-of-two distance from it, so
// that splits near a small input angle fall on concentric shells and stop). Then each bad
// triangle (a smallest angle below the bound, or an area above it) gets a point at its
// off-centre (Üngör, "Off-centers", 2004): the circumcentre, or, where that lies far from the
// shortest edge, the point on its bisector that makes an angle a little above the bound with it.
// A point that would encroach a subsegment is not added; the subsegment is split instead.
#include "constrained/refine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "order/order.hpp"
#include "predicates/predicates.hpp"
#include "queries/circumcentre.hpp"
#include "runtime/memory.hpp"

namespace ridt::detail {
namespace {

double dot(const Point& a, const Point& b, const Point& p) {
  return (a.x - p.x) * (b.x - p.x) + (a.y - p.y) * (b.y - p.y);
}
double dist2(const Point& a, const Point& b) { return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y); }

constexpr double kGood = std::numeric_limits<double>::infinity();

// A priority queue of items with a `key` (smaller first), in buckets of a quarter octave of
// it, last in first out within one: the order refinement needs within a few per cent, without a
// heap's misses. A bucket is put in order along the Hilbert curve (by `where`, in 1024 stretches)
// when the queue comes to it and more than a few of its items came since: then one pop's triangle
// lies near the last one's in the plane, and the slots they free and take, near in memory.
template <class Item>
class Buckets {
 public:
  bool empty() const { return size_ == 0; }
  void push(const Item& item) {
    const std::size_t b = bucket(item.key);
    if (b >= lists_.size()) lists_.resize(b + 1), ordered_.resize(b + 1, 0);
    lists_[b].push_back(item);
    lowest_ = std::min(lowest_, b);
    ++size_;
  }
  Item pop() {
    while (lists_[lowest_].empty()) ++lowest_;
    if (lowest_ != current_ && lists_[lowest_].size() > ordered_[lowest_] + 64) along_curve(lowest_);
    current_ = lowest_;
    std::vector<Item>& l = lists_[lowest_];
    const Item item = l.back();
    l.pop_back();
    ordered_[lowest_] = std::min(ordered_[lowest_], l.size());
    --size_;
    return item;
  }
  // The item that would come k pops after the next, in the lowest bucket, or null.
  const Item* ahead(std::size_t k) const {
    if (size_ == 0 || lowest_ >= lists_.size()) return nullptr;
    const std::vector<Item>& l = lists_[lowest_];
    return l.size() > k ? &l[l.size() - 1 - k] : nullptr;
  }

 private:
  // Negative keys first (the most negative first), then the rest, each by quarter octaves.
  static std::size_t bucket(double key) {
    constexpr int kSpan = 4 * 2200;  // quarter octaves of every double's exponent
    int e = 0;
    const double f = std::frexp(std::fabs(key), &e);  // |key| = f 2^e, f in [0.5, 1)
    const int quarter = 4 * (e + 1100) + static_cast<int>((f - 0.5) * 8);  // f's quarters of [0.5, 1)
    const int q = std::clamp(quarter, 0, kSpan - 1);
    return static_cast<std::size_t>(key < 0 ? kSpan - 1 - q : kSpan + q);
  }

  // Bucket b's items sorted by the first bits of `where` (a counting sort: stable, linear).
  void along_curve(std::size_t b) {
    std::vector<Item>& l = lists_[b];
    constexpr int kBits = 10;
    std::vector<std::uint32_t> at((1u << kBits) + 1, 0);
    for (const Item& i : l) ++at[(i.where >> (32 - kBits)) + 1];
    std::partial_sum(at.begin(), at.end(), at.begin());
    std::vector<Item> sorted(l.size());
    for (const Item& i : l) sorted[at[i.where >> (32 - kBits)]++] = i;
    l.swap(sorted);
    ordered_[b] = l.size();
  }

  std::vector<std::vector<Item>> lists_;
  std::vector<std::size_t> ordered_;  // per bucket: how many of its first items are in curve order
  std::size_t lowest_ = std::numeric_limits<std::size_t>::max(), current_ = lowest_, size_ = 0;
};

class Refiner {
 public:
  Refiner(Cdt& m, const Refinement& r) : m_(m), r_(r) {
    const double s = std::sin(r.min_angle * 3.14159265358979323846 / 180);
    sin2_ = s * s;
    // The off-centre 5 % nearer the edge than where the new triangle's angle would be the
    // bound exactly: then it is not bad again by a rounding (23 % fewer points on a coastline of 10^4 vertices).
    offset_ = r.min_angle > 0 ? 0.475 / std::tan(r.min_angle * 3.14159265358979323846 / 360) : 0;
    box_ = extent_of(m.pts);
    tiny2_ = dist2({box_.x0, box_.y0}, {box_.x1, box_.y1}) * 0x1p-80;  // edges below 2^-40 of the diagonal stay
    cells_ = 65535 / std::max(box_.x1 - box_.x0, box_.y1 - box_.y0);  // infinite for one point: see curve()
    ends_.assign(m.pts.size(), {Cdt::kNone, Cdt::kNone});
  }

  std::string run() {
    for (std::uint32_t s = 0; s < m_.tris.size(); ++s)
      if (m_.nbrs[s] < 0) m_.fixed[s] = 1;
    for (std::uint32_t s = 0; s < m_.tris.size(); ++s)
      if (m_.fixed[s] && encroached(s)) queue_split(s, false);
    find_small_angles();
    for (std::uint32_t t = 0; t < m_.size(); ++t) queue_bad(t);
    const std::size_t first = m_.pts.size();
    // Each point added costs some 160 bytes (two triangles, the point, queue entries): stop
    // before the memory the system has left runs out, rather than be killed for it.
    const std::size_t room = available_memory() / 160 * 3 / 4;
    while (true) {
      if (r_.max_steiner > 0 && m_.pts.size() - first >= r_.max_steiner)
        return "quality refinement stopped after " + std::to_string(r_.max_steiner) + " points (the limit asked)";
      if (room > 0 && m_.pts.size() - first >= room)
        return "quality refinement stopped after " + std::to_string(room) + " points: the memory left holds no more";
      if (!segments_.empty()) {
        const Split w = segments_.back();
        segments_.pop_back();
        const std::uint32_t s = m_.find_edge(w.x, w.y);
        if (s != Cdt::kNone && m_.fixed[s] && (w.forced || encroached(s))) split(s);
        continue;
      }
      if (bad_.empty()) return "";
      const Bad b = bad_.pop();
      prefetch_ahead();
      // A triangle still there has the vertices, so the badness, it was queued with.
      if (alive(b)) improve(b);
    }
  }

 private:
  struct Split {
    VertexId x, y;
    bool forced;  // split even where no vertex encroaches it (a point to be added would)
  };
  void queue_split(std::uint32_t s, bool forced) {
    segments_.push_back({m_.at(s / 3, static_cast<int>(s % 3) + 1), m_.at(s / 3, static_cast<int>(s % 3) + 2), forced});
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
    if (const Bad* b = bad_.ahead(8)) __builtin_prefetch(&m_.tris[3 * std::size_t{b->t}]);
    if (const Bad* b = still_there(4)) {
      for (const VertexId v : b->v) __builtin_prefetch(&m_.pts[v]);
      __builtin_prefetch(&m_.nbrs[3 * std::size_t{b->t}]);
    }
    if (const Bad* b = still_there(2))
      for (int k = 0; k < 3; ++k)
        if (const std::int32_t n = m_.nbrs[3 * std::size_t{b->t} + k]; n >= 0)
          __builtin_prefetch(&m_.tris[3 * static_cast<std::size_t>(n)]);
  }

  struct Bad {
    double key;  // badness(t), the smaller first
    std::uint32_t t;
    VertexId v[3];
    int tries;
    std::uint32_t where;  // the Hilbert key of t's first vertex
  };

  bool corner(VertexId v) const { return v < r_.corners; }
  bool boundary(std::uint32_t s) const { return m_.nbrs[s] < 0; }
  bool alive(const Bad& b) const {
    return b.t < m_.size() && m_.tris[3 * b.t] == b.v[0] && m_.tris[3 * b.t + 1] == b.v[1] &&
        m_.tris[3 * b.t + 2] == b.v[2];
  }
  void queue_bad(std::uint32_t t) {
    if (const double key = badness(t); key != kGood)
      bad_.push({key, t, {m_.tris[3 * t], m_.tris[3 * t + 1], m_.tris[3 * t + 2]}, 0, curve(m_.pts[m_.tris[3 * t]])});
  }

  // The subsegment in slot s has a vertex strictly inside its diametral circle: the apex of its
  // triangle or of the one across.
  bool encroached(std::uint32_t s) const {
    const std::uint32_t t = s / 3;
    const int k = static_cast<int>(s % 3);
    const Point &a = m_.pts[m_.at(t, k + 1)], &b = m_.pts[m_.at(t, k + 2)];
    if (dot(a, b, m_.pts[m_.at(t, k)]) < 0) return true;
    const std::int32_t n = m_.nbrs[s];
    return n >= 0 &&
        dot(a, b, m_.pts[m_.at(static_cast<std::uint32_t>(n), m_.back(static_cast<std::uint32_t>(n), t))]) < 0;
  }

  // The corners at the ends of the chain of subsegments that subsegment x-y lies on.
  std::pair<VertexId, VertexId> chain(VertexId x, VertexId y) const {
    return corner(x) && corner(y) ? std::pair{x, y} : corner(x) ? ends_[y] : ends_[x];
  }

  // The corner across from triangle t's shortest edge, given its squared sides l (across from
  // corners 0, 1, 2).
  static int shortest(const double (&l)[3]) { return l[0] <= l[1] && l[0] <= l[2] ? 0 : l[1] <= l[2] ? 1 : 2; }

  // Triangle z-u-w, u and w on two chains that meet at z below 60 degrees, at one distance
  // from it: its small angle is the input's, and splitting it would only cut the shells finer.
  // (A triangle between two shells whose third vertex is not z is split as any other.)
  bool at_small_input_angle(VertexId u, VertexId w, VertexId z) const {
    if (corner(u) || corner(w) || !corner(z) || !small_[z] || ends_[u].first == Cdt::kNone ||
        ends_[w].first == Cdt::kNone)
      return false;
    auto from_z = [&](VertexId v) { return ends_[v].first == z || ends_[v].second == z; };
    const auto [u1, u2] = ends_[u];
    if (!from_z(u) || !from_z(w) || ends_[w] == std::pair{u1, u2} || ends_[w] == std::pair{u2, u1}) return false;
    const double du = dist2(m_.pts[z], m_.pts[u]), dw = dist2(m_.pts[z], m_.pts[w]);
    return std::fabs(du - dw) <= 1e-6 * std::max(du, dw);
  }

  double area_bound(std::uint32_t t) const {
    double bound = r_.max_area;
    if (!m_.region.empty() && m_.region[t] >= 0) {
      const double own = r_.region_area[static_cast<std::size_t>(m_.region[t])];
      if (own > 0) bound = bound > 0 ? std::min(bound, own) : own;
    }
    return bound;
  }

  // Where triangle t stands in the queue of bad triangles, kGood where it is good: one too large
  // (whatever its angles) by minus its area over its bound (the largest first), one with a small
  // angle by its shortest edge's squared length (the smallest first: the sizes then grade out
  // from the boundary, with 29 % fewer points than worst shaped first on a 10^4-vertex coastline).
  double badness(std::uint32_t t) const {
    const VertexId v[3] = {m_.tris[3 * t], m_.tris[3 * t + 1], m_.tris[3 * t + 2]};
    const Point &a = m_.pts[v[0]], &b = m_.pts[v[1]], &c = m_.pts[v[2]];
    const double twice = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    // First: the terminator (improve) may leave a small angle, never an area above its bound.
    if (const double bound = area_bound(t); bound > 0 && twice > 2 * bound) return -twice / (2 * bound);
    if (sin2_ > 0) {
      const double l[3] = {dist2(b, c), dist2(c, a), dist2(a, b)};  // across from corner 0, 1, 2
      const int s = shortest(l);
      const double sine2 = twice * twice / (l[(s + 1) % 3] * l[(s + 2) % 3]);
      if (l[s] >= tiny2_ && sine2 < sin2_ && !at_small_input_angle(v[(s + 1) % 3], v[(s + 2) % 3], v[s])) return l[s];
    }
    return kGood;
  }

  // Where triangle t gets its point: the off-centre of its shortest edge.
  Point off_centre(std::uint32_t t) const {
    const Point &a = m_.pts[m_.tris[3 * t]], &b = m_.pts[m_.tris[3 * t + 1]], &c = m_.pts[m_.tris[3 * t + 2]];
    const Point cc = circumcentre(a, b, c);
    if (offset_ == 0) return cc;
    const double l[3] = {dist2(b, c), dist2(c, a), dist2(a, b)};
    const int s = shortest(l);
    const Point &p = m_.pts[m_.at(t, s + 1)], &q = m_.pts[m_.at(t, s + 2)];
    const Point mid{(p.x + q.x) / 2, (p.y + q.y) / 2};
    const double reach = offset_ * std::sqrt(l[s]), far = std::sqrt(dist2(cc, mid));
    if (!(far > reach)) return cc;
    const double f = reach / far;
    return {mid.x + (cc.x - mid.x) * f, mid.y + (cc.y - mid.y) * f};
  }

  // The fixed edges that p, added in `at`, would see strictly inside their diametral circles:
  // those bounding the triangles whose circles hold p, flooded from `at` without crossing a
  // fixed edge.
  std::vector<std::uint32_t>& would_encroach(const Point& p, const Cdt::Place& at) {
    std::vector<std::uint32_t>&todo = todo_, &seen = seen_, &out = hit_;
    todo.assign(1, at.t), seen.assign(1, at.t), out.clear();
    if (at.kind == Cdt::Place::Edge && !m_.fixed[3 * at.t + at.k] && m_.nbrs[3 * at.t + at.k] >= 0)
      todo.push_back(static_cast<std::uint32_t>(m_.nbrs[3 * at.t + at.k])), seen.push_back(todo.back());
    while (!todo.empty()) {
      const std::uint32_t t = todo.back();
      todo.pop_back();
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t s = 3 * t + k;
        if (m_.fixed[s]) {
          if (dot(m_.pts[m_.at(t, k + 1)], m_.pts[m_.at(t, k + 2)], p) < 0) out.push_back(s);
          continue;
        }
        const auto n = static_cast<std::uint32_t>(m_.nbrs[s]);
        if (std::find(seen.begin(), seen.end(), n) != seen.end()) continue;
        const VertexId* v = &m_.tris[3 * n];
        if (incircle(m_.pts[v[0]], m_.pts[v[1]], m_.pts[v[2]], p) <= 0) {
          __builtin_prefetch(&m_.nbrs[3 * std::size_t{n}]);  // on the rim: the fan links back to it
          continue;
        }
        seen.push_back(n), todo.push_back(n);
      }
    }
    return out;
  }

  bool splittable(std::uint32_t s) const {
    if (!r_.split_boundary && boundary(s)) return false;
    const std::uint32_t t = s / 3;
    const int k = static_cast<int>(s % 3);
    return dist2(m_.pts[m_.at(t, k + 1)], m_.pts[m_.at(t, k + 2)]) >= 4 * tiny2_;
  }

  void improve(const Bad& b) {
    const Point p = off_centre(b.t);
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    const Cdt::Place at = m_.locate(b.t, p, true);
    if (at.kind == Cdt::Place::Corner) return;
    // On a subsegment that may not be split (the boundary's, asked to keep no new points): left.
    if (at.kind == Cdt::Place::Edge && m_.fixed[3 * at.t + at.k] && !splittable(3 * at.t + at.k)) return;
    const bool blocked = at.kind == Cdt::Place::Blocked || at.kind == Cdt::Place::Outside;
    if (blocked) hit_.assign(1, 3 * at.t + at.k);
    std::vector<std::uint32_t>& hit = blocked ? hit_ : would_encroach(p, at);
    std::erase_if(hit, [&](std::uint32_t s) { return !splittable(s); });
    for (const std::uint32_t s : hit)
      if (b.key >= 0 && terminated(s, b.t)) return;  // never for a triangle too large
    if (blocked || !hit.empty()) {
      if (hit.empty() || b.tries >= 64) return;
      for (const std::uint32_t s : hit) queue_split(s, true);
      bad_.push({b.key, b.t, {b.v[0], b.v[1], b.v[2]}, b.tries + 1, b.where});
      return;
    }
    // The triangles whose circles hold p are known (would_encroach's): replaced by a fan
    // about p where they make a cavity p sees whole, else p added with flips.
    const VertexId v = m_.insert_cavity(p, seen_);
    added(v != Cdt::kNone ? v : m_.insert(p, at));
  }

  // Where subsegment x-y is split: at the power of two nearest half its length from its
  // corner where one end is a corner, or, both ends corners, the one at a small angle; else
  // at its midpoint.
  Point split_point(VertexId x, VertexId y) const {
    const Point &a = m_.pts[x], &b = m_.pts[y];
    bool from_x = corner(x) && !corner(y), from_y = corner(y) && !corner(x);
    if (corner(x) && corner(y)) from_x = small_[x] && !small_[y], from_y = small_[y] && !small_[x];
    if (!from_x && !from_y) return {a.x / 2 + b.x / 2, a.y / 2 + b.y / 2};
    const Point &z = from_x ? a : b, &o = from_x ? b : a;
    const double length = std::sqrt(dist2(a, b));
    const double d = std::exp2(std::round(std::log2(length / 2)));
    const double f = d / length;
    return {z.x + (o.x - z.x) * f, z.y + (o.y - z.y) * f};
  }

  void split(std::uint32_t s);
  VertexId split_at(std::uint32_t s, const Point& given);
  void relabel(VertexId v, VertexId x, VertexId y, std::int32_t left, std::int32_t right);
  void added(VertexId v);
  void find_small_angles();
  bool terminated(std::uint32_t s, std::uint32_t t) const;

  Cdt& m_;
  const Refinement& r_;
  // Where p lies along the Hilbert curve over the points' box (a point added lies in it); a
  // box too wide or too thin for the scale (an infinite or NaN cell) puts p at an end.
  std::uint32_t curve(const Point& p) const {
    auto cell = [&](double v, double from) {
      const double c = (v - from) * cells_;
      return c >= 0 ? (c < 65535 ? static_cast<std::uint32_t>(c) : 65535u) : 0u;
    };
    return hilbert_key(cell(p.x, box_.x0), cell(p.y, box_.y0));
  }

  double sin2_ = 0, offset_ = 0, tiny2_ = 0, cells_ = 0;
  Extent box_;
  std::vector<std::pair<VertexId, VertexId>> ends_;  // per vertex on a chain: its corners
  std::vector<std::uint8_t> small_;  // per corner: two of its segments meet at less than 60 degrees
  std::vector<Split> segments_;  // subsegments to split, if still there (and encroached)
  Buckets<Bad> bad_;
  std::vector<std::uint32_t> todo_, seen_, hit_;  // would_encroach's
};

// Subsegment s split at its split point, or, where that cannot be placed (a vertex a rounding
// from the subsegment folds the triangles there), at a quarter or three eighths from either
// end instead; left whole where none can.
void Refiner::split(std::uint32_t s) {
  if (!splittable(s)) return;
  const std::uint32_t t = s / 3;
  const int k = static_cast<int>(s % 3);
  const VertexId x = m_.at(t, k + 1), y = m_.at(t, k + 2);
  const std::pair<VertexId, VertexId> ends = chain(x, y);
  const Point &a = m_.pts[x], &b = m_.pts[y];
  auto at = [&](double f) { return Point{a.x + (b.x - a.x) * f, a.y + (b.y - a.y) * f}; };
  const Point tries[5] = {split_point(x, y), at(0.25), at(0.75), at(0.375), at(0.625)};
  for (const Point& p : tries)
    if (const VertexId v = split_at(s, p); v != Cdt::kNone) {
      ends_.resize(m_.pts.size(), {Cdt::kNone, Cdt::kNone});
      ends_[v] = ends;
      added(v);
      return;
    }
}

// p added on subsegment s as though it lay on it (it does, up to rounding; on the boundary never
// beyond it, lest the domain grow over a hole's seed); where that folds a triangle, inside the one
// beside it that holds p (x-y freed, p added, x-p and p-y fixed, the regions kept); else kNone.
VertexId Refiner::split_at(std::uint32_t s, const Point& given) {
  const std::uint32_t t = s / 3;
  const int k = static_cast<int>(s % 3);
  const Point p = boundary(s) ? m_.not_beyond(t, k, given) : given;
  if (m_.fits_on_edge(t, k, p)) return m_.insert_on_edge(p, t, k);
  if (boundary(s)) return Cdt::kNone;
  const Cdt::Place at = m_.beside(t, static_cast<int>(k), p);
  if (at.kind != Cdt::Place::Inside) return Cdt::kNone;
  const VertexId x = m_.at(t, k + 1), y = m_.at(t, k + 2);
  // The regions of t (left of x -> y) and across, which the flips about p could mix.
  const std::int32_t across = m_.nbrs[s];
  const std::int32_t left = m_.region.empty() ? -1 : m_.region[t];
  const std::int32_t right = m_.region.empty() || across < 0 ? left : m_.region[static_cast<std::uint32_t>(across)];
  m_.set_fixed(t, k, false);
  const VertexId v = m_.insert(p, at);
  for (const VertexId e : {x, y})
    if (const std::uint32_t f = m_.find_edge(v, e); f != Cdt::kNone) m_.set_fixed(f / 3, static_cast<int>(f % 3), true);
  if (left != right) relabel(v, x, y, left, right);
  return v;
}

// The triangles about v, added beside segment x-y (now x-v-y), given the regions left and
// right of x -> v -> y: the flips made triangles about v, which v-x and v-y part into two fans.
// Triangle (v, p, q) is in the left one where v->p lies in the angle from v->y counter-clockwise
// to v->x (exact orientations; the angle is near a half-turn, either side of it).
void Refiner::relabel(VertexId v, VertexId x, VertexId y, std::int32_t left, std::int32_t right) {
  const Point &pv = m_.pts[v], &px = m_.pts[x], &py = m_.pts[y];
  const bool reflex = orient2d(pv, py, px) <= 0;  // the left angle is a half-turn or more
  m_.around(v, [&](std::uint32_t u) {
    const VertexId p = m_.at(u, m_.corner_of(u, v) + 1);
    bool in_left = p == y;
    if (p != x && p != y) {
      const bool after_y = orient2d(pv, py, m_.pts[p]) > 0, before_x = orient2d(pv, px, m_.pts[p]) < 0;
      in_left = reflex ? after_y || before_x : after_y && before_x;
    }
    m_.region[u] = in_left ? left : right;
    return false;
  });
}

// Each corner's sectors: the angles the domain's triangles make at it between two fixed
// edges; a corner with one below 60 degrees is the apex of a cluster of segments.
void Refiner::find_small_angles() {
  small_.assign(r_.corners, 0);
  auto angle = [&](std::uint32_t t, int i) {
    const Point &o = m_.pts[m_.at(t, i)], &u = m_.pts[m_.at(t, i + 1)], &w = m_.pts[m_.at(t, i + 2)];
    const double ux = u.x - o.x, uy = u.y - o.y, wx = w.x - o.x, wy = w.y - o.y;
    return std::atan2(ux * wy - uy * wx, ux * wx + uy * wy);
  };
  for (VertexId z = 0; z < r_.corners; ++z) {
    if (m_.corner[z] == Cdt::kNone) continue;
    // From each triangle whose edge (z, u) is fixed, counter-clockwise across the edges (w, z)
    // that are not, to the next fixed one.
    m_.around(z, [&](std::uint32_t first) {
      if (!m_.fixed[3 * first + (m_.corner_of(first, z) + 2) % 3]) return false;
      double sector = 0;
      for (std::uint32_t t = first;;) {
        const int i = m_.corner_of(t, z);
        sector += angle(t, i);
        if (m_.fixed[3 * t + (i + 1) % 3]) break;
        t = static_cast<std::uint32_t>(m_.nbrs[3 * t + (i + 1) % 3]);
      }
      if (sector < 3.14159265358979323846 / 3) small_[z] = 1;
      return small_[z] != 0;
    });
  }
}

// Shewchuk's terminator, simplified: triangle t, with a vertex on a chain that ends at a
// small angle, is left as it is where its point would have subsegment s, there, split closer
// to one of its ends than t's shortest edge is long (t's small angle then comes from the
// input's, and splitting on would only cut the shells finer).
bool Refiner::terminated(std::uint32_t s, std::uint32_t t) const {
  const VertexId x = m_.at(s / 3, static_cast<int>(s % 3) + 1), y = m_.at(s / 3, static_cast<int>(s % 3) + 2);
  const auto [z1, z2] = chain(x, y);
  if (z1 == Cdt::kNone || !(small_[z1] || small_[z2])) return false;
  auto beside = [&](VertexId v) {
    if (corner(v)) return small_[v] != 0;
    return ends_[v].first != Cdt::kNone && (small_[ends_[v].first] || small_[ends_[v].second]);
  };
  if (!beside(m_.tris[3 * t]) && !beside(m_.tris[3 * t + 1]) && !beside(m_.tris[3 * t + 2])) return false;
  const Point p = split_point(x, y);
  const double radius = std::min(dist2(p, m_.pts[x]), dist2(p, m_.pts[y]));
  const Point &a = m_.pts[m_.tris[3 * t]], &b = m_.pts[m_.tris[3 * t + 1]], &c = m_.pts[m_.tris[3 * t + 2]];
  return radius < std::min({dist2(a, b), dist2(b, c), dist2(c, a)});
}

// After v is added: its triangles queued where bad, its fixed edges where encroached.
void Refiner::added(VertexId v) {
  ends_.resize(m_.pts.size(), {Cdt::kNone, Cdt::kNone});
  m_.around(v, [&](std::uint32_t t) {
    queue_bad(t);
    for (int k = 0; k < 3; ++k)
      if (m_.fixed[3 * t + k] && encroached(3 * t + k)) queue_split(3 * t + k, false);
    return false;
  });
}

}  // namespace

std::string refine(Cdt& m, const Refinement& r) { return Refiner(m, r).run(); }

}  // namespace ridt::detail
