// The regular triangulation (ridt/regular.hpp): randomized incremental insertion on the one
// mutable triangulation (tds/tds.hpp), closed by a vertex at infinity.
//
// Lifted, the weighted points are points in space and the regular triangulation the lower
// hull of theirs; add a point infinitely far above and the hull is closed: the lower faces,
// and a vertical "wall" (p, q, infinity) over each edge of the convex hull. The structure holds
// exactly that closed surface, as the sphere's (sphere/sphere.cpp) holds its hull: every
// triangle has three neighbours, and a point is inserted by replacing the faces its lift sees
// (the cavity) by the fan of faces round their boundary. A finite face sees the point where the
// power test puts its lift below the face's plane (perturbed: never on it); a wall sees it
// where it lies beyond the hull edge, or on the edge's line with its lift below the edge's
// (then the wall answers as the finite face beside it, whose plane holds that edge: so no
// horizon edge has the point on its line, and no new face is flat). A point whose lift lies
// above the triangle that holds it is hidden; one whose lift hides vertices surrounds them
// with its cavity (the traversal meets a face twice): they are made hidden and their faces
// dropped (cover_cavity, tds/cover.hpp).
//
// Points are located by a visibility walk over the finite faces (which cannot cycle in a
// regular triangulation: Edelsbrunner's acyclicity theorem), stopped where it would enter a
// wall: the point lies beyond that hull edge.
#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <random>
#include <string>

#include "order/order.hpp"
#include "order/random.hpp"
#include "predicates/power.hpp"
#include "predicates/predicates.hpp"
#include "regular/settle.hpp"
#include "ridt/regular.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"
#include "tds/cover.hpp"
#include "tds/delaunay.hpp"
#include "tds/rounds.hpp"
#include "tds/tds.hpp"

namespace ridt {
namespace detail {
namespace {

void check_input(std::span<const Point> points, std::span<const double> weights) {
  if (points.size() >= kMaxSlotPoints) throw InputError("triangulate_regular: too many points");
  if (weights.size() != points.size())
    throw InputError("triangulate_regular: " + std::to_string(weights.size()) + " weights for " +
                     std::to_string(points.size()) + " points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
      throw InputError("triangulate_regular: point " + std::to_string(i) + " is not finite");
    if (!std::isfinite(weights[i]))
      throw InputError("triangulate_regular: the weight of point " + std::to_string(i) + " is not finite");
  }
}

// A thread's walks may start anew at a face found before the round every this many points, each
// found by a walk (at 10^6 points on two threads, against every 256: every 1,024 took 2.4 to 2.9
// % less time in all, every 4,096 3.8 % less, every 16,384 17 % more: walks that leave the region
// start too far away).
constexpr VertexId kEvery = 1024;

class Builder {
 public:
  Builder(std::span<const Point> points, std::span<const double> weights, unsigned threads)
      : points_(points),
        weights_(weights),
        n_(static_cast<VertexId>(points.size())),
        infinite_(n_),
        threads_(threads) {}

  // Vertex ids are places in the insertion order, so that points inserted one after another lie
  // together in memory; input_ maps them back, and the vertex at infinity is n_. The first
  // triangle's three (first_) are passed over where their places come.
  void run() {
    const std::array<VertexId, 3> first = first_triangle();
    // A biased randomized insertion order along the Hilbert curve (brio_order, the kernel's),
    // made in the memory of the structure's arrays, made first (no fresh pages for its work).
    SlotArrays arrays(n_, threads_);
    input_ = brio_order(points_.data(), n_, 0x5eed, threads_, &key_, {arrays.words(), arrays.numbers()});
    q_ = HugeArray<Weighted>(n_ + 1, threads_);
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    q_[infinite_] = {{kNaN, kNaN}, kNaN};  // (see sees)
    parallel_for(n_, threads_, 65536, [&](std::size_t from, std::size_t to) {
      constexpr std::size_t kAhead = 16;  // (read at random: the misses overlap)
      for (std::size_t v = from; v < to; ++v) {
        if (v + kAhead < to)
          __builtin_prefetch(&points_[input_[v + kAhead]]), __builtin_prefetch(&weights_[input_[v + kAhead]]);
        const VertexId i = input_[v];
        q_[v] = {points_[i], weights_[i]};
        if (i == first[0] || i == first[1] || i == first[2])  // (one v each)
          first_[i == first[0] ? 0 : i == first[1] ? 1 : 2] = static_cast<VertexId>(v);
      }
    });
    resize_present(hidden_, n_, threads_);
    cover_at_ = zeros(n_ + 1);
    start(std::move(arrays));
    // The rounds (where the keys fall back), each shared among the threads where it is large.
    for (VertexId b = 0, e; b < n_; b = e) {
      for (e = b + 1; e < n_ && key_[e] >= key_[e - 1];) ++e;
      if (shared_round(e - b, threads_)) {
        insert_round(b, e);
      } else {
        for (VertexId v = b; v < e; ++v)
          if (!is_first(v)) insert(v);
      }
    }
  }

  Tds& tds() { return tds_; }
  VertexId infinite() const { return infinite_; }
  /// Per vertex id: its input index (the least of its copies'), whether it is hidden.
  std::vector<VertexId>& input() { return input_; }
  const std::vector<std::uint8_t>& hidden() const { return hidden_; }
  std::span<const Weighted> weighted() const { return q_; }
  /// Copies found: (the copy's vertex id, the vertex id it coincides with).
  const std::vector<std::pair<VertexId, VertexId>>& copies() const { return copies_; }

 private:
  // Three points far from collinear: the first, the farthest from it, the farthest from their
  // line (scored in double precision on the points scaled by a power of two, confirmed exactly;
  // found by an exact search where the scores miss).
  std::array<VertexId, 3> first_triangle() const {
    if (n_ < 3) throw InputError("triangulate_regular: fewer than three distinct points");
    // Each on threads: every part's best, then the best of those (the first where they tie).
    const auto parts = static_cast<unsigned>(std::clamp<std::size_t>(n_ / 65536, 1, threads_));
    std::vector<std::pair<double, VertexId>> tops(parts);
    auto best_of = [&](auto&& score) {
      parallel_for(parts, parts, 1, [&](std::size_t from, std::size_t to) {
        for (std::size_t p = from; p < to; ++p) {
          std::pair<double, VertexId> top{-1, 0};
          for (auto v = static_cast<VertexId>(n_ * p / parts); v < n_ * (p + 1) / parts; ++v)
            if (const double s = score(v); s > top.first) top = {s, v};
          tops[p] = top;
        }
      });
      std::pair<double, VertexId> top = tops[0];
      for (const auto& t : tops)
        if (t.first > top.first) top = t;
      return top;
    };
    const double largest =
        best_of([&](VertexId v) { return std::max(std::fabs(points_[v].x), std::fabs(points_[v].y)); }).first;
    // Scaled by a power of two to at most 1: no square overflows (one that underflows scores 0).
    const double f = largest > 0 ? std::ldexp(1.0, -std::ilogb(largest) - 1) : 1.0;
    auto best = [&](auto&& score) {
      return best_of([&](VertexId v) { return score(f * points_[v].x, f * points_[v].y); }).second;
    };
    const VertexId a = 0;
    const double ax = f * points_[a].x, ay = f * points_[a].y;
    const VertexId b = best([&](double x, double y) { return (x - ax) * (x - ax) + (y - ay) * (y - ay); });
    const double bx = f * points_[b].x - ax, by = f * points_[b].y - ay;
    VertexId c = best([&](double x, double y) { return std::fabs(bx * (y - ay) - by * (x - ax)); });
    if (orient2d(points_[a], points_[b], points_[c]) == 0) {
      c = n_;
      for (VertexId v = 0; v < n_ && c == n_; ++v)
        if (orient2d(points_[a], points_[b], points_[v]) != 0) c = v;
      if (c == n_)
        throw InputError(points_[a] == points_[b] ? "triangulate_regular: fewer than three distinct points"
                                                  : "triangulate_regular: all points are collinear");
    }
    return orient2d(points_[a], points_[b], points_[c]) > 0 ? std::array{a, b, c} : std::array{a, c, b};
  }

  // An array of `size` zeros (HugeArray: kept for the next triangulation in the process).
  HugeArray<std::uint32_t> zeros(std::size_t size) const {
    HugeArray<std::uint32_t> a(size, threads_);
    parallel_for(size, threads_, 1 << 18, [&](std::size_t from, std::size_t to) {
      std::fill(a.data() + from, a.data() + to, std::uint32_t{0});
    });
    return a;
  }

  // The first triangle (0, 1, 2) and its three walls, linked, in arrays with room for every
  // face of n points (at most 2n - 2; a fan takes its cavity's slots and two more, freed ones
  // first).
  void start(SlotArrays arrays) {
    const VertexId a = first_[0], b = first_[1], c = first_[2], inf = infinite_;
    const VertexId faces[4][3] = {{a, b, c}, {b, a, inf}, {c, b, inf}, {a, c, inf}};
    arrays.vertices_again();  // (the order's work was done in their memory)
    for (int f = 0; f < 4; ++f)
      for (int i = 0; i < 3; ++i) arrays.v[3 * f + i] = faces[f][i];
    for (int f = 0; f < 4; ++f)
      for (int i = 0; i < 3; ++i)
        for (int g = 0; g < 4; ++g)
          for (int j = 0; j < 3; ++j)
            if (faces[g][next3(j)] == faces[f][prev3(i)] && faces[g][prev3(j)] == faces[f][next3(i)])
              arrays.link[3 * f + i] = static_cast<Link>(3 * g + j);
    tds_ = Tds(std::move(arrays.v), std::move(arrays.link), 4);
    stamp_ = zeros(2 * std::size_t{n_} + 2);
  }

  bool is_first(VertexId v) const { return v == first_[0] || v == first_[1] || v == first_[2]; }

  // The corner of face w that is the vertex at infinity, or -1.
  int infinite_corner(const VertexId* w) const {
    return w[0] == infinite_ ? 0 : w[1] == infinite_ ? 1 : w[2] == infinite_ ? 2 : -1;
  }
  bool power_sees(VertexId a, VertexId b, VertexId c, VertexId v) const {
    return power_sos(q_[a], q_[b], q_[c], q_[v]) > 0;
  }
  // Whether face w (a slot's corners) sees point v: see the file's comment. The vertex at
  // infinity's weighted point is NaN, so a wall's test fails the filter as an unsure one does,
  // and only then are the corners looked at, off the common path.
  [[gnu::always_inline]] bool sees(const VertexId* w, VertexId v) const {
    const Weighted* q = q_.data();  // (read once: a store to the cavity's bytes could change q_)
    if (const int s = power_filter(q[w[0]], q[w[1]], q[w[2]], q[v]); s != 0) return s > 0;
    return sees_unsure(w, v);
  }
  [[gnu::noinline]] bool sees_unsure(const VertexId* w, VertexId v) const {
    const int k = infinite_corner(w);
    if (k < 0) return power_sees(w[0], w[1], w[2], v);
    const VertexId p = w[next3(k)], q = w[prev3(k)];
    const int o = orient2d(q_[p].p, q_[q].p, q_[v].p);
    if (o != 0) return o > 0;
    const auto t = static_cast<TriangleId>((w - tds_.corners(0)) / 3);
    return power_sees(q, p, tds_.opposite(tds_.link(t, k)), v);
  }

  // orient2d(a, b, q) for a walk: the filter in line, the rest out of line (orient2d whole is
  // not inlined: a call at each step of a walk).
  [[gnu::always_inline]] int side(VertexId a, VertexId b, const Point& q) const {
    if (const int s = orient2d_filter(q_[a].p, q_[b].p, q); s != 0) return s;
    return side_unsure(a, b, q);
  }
  [[gnu::noinline]] int side_unsure(VertexId a, VertexId b, const Point& q) const {
    return orient2d(q_[a].p, q_[b].p, q);
  }

  // Where v lies: a finite face whose closure holds it (outside = false), or a wall beyond whose
  // edge it lies (outside = true). A walk from face `from` (it cannot cycle in a regular
  // triangulation), and behind it, should it go on too long, a look at every face. Reads only.
  TriangleId locate(TriangleId from, VertexId v, bool& outside) const {
    TriangleId t = from;
    if (const int k = infinite_corner(tds_.corners(t)); k >= 0) t = triangle_of(tds_.link(t, k));
    const Point q = q_[v].p;
    std::size_t steps = 0;
    const std::size_t limit = walk_limit(tds_);
    bool wall = false;
    const Walked w = tds_.walk(
        t, [&](VertexId a, VertexId b) { return side(a, b, q); },
        [&](Link l) {
          wall = tds_.opposite(l) == infinite_;  // (a wall's one finite edge is the one crossed)
          return !wall && ++steps < limit ? Step::Cross : Step::Stop;
        });
    outside = !w && wall;
    if (w) return t;
    if (wall) return triangle_of(tds_.link(t, w.edge));
    for (TriangleId u = 0; u < tds_.slots(); ++u) {
      const VertexId* c = tds_.corners(u);
      if (c[0] == kNoVertex || infinite_corner(c) >= 0) continue;
      if (orient2d(q_[c[0]].p, q_[c[1]].p, q) >= 0 && orient2d(q_[c[1]].p, q_[c[2]].p, q) >= 0 &&
          orient2d(q_[c[2]].p, q_[c[0]].p, q) >= 0)
        return u;
    }
    for (TriangleId u = 0; u < tds_.slots(); ++u)
      if (const VertexId* c = tds_.corners(u); c[0] != kNoVertex && infinite_corner(c) >= 0 && sees(c, v))
        return outside = true, u;
    return from;  // unreachable: the faces cover the plane
  }

  // Inserts v, walking from `near` where it is a face, else from where the last point was.
  void insert(VertexId v, TriangleId near = kNoTriangle) {
    bool outside = false;
    const TriangleId from = tds_.live(near) ? near : last_;
    const TriangleId t = locate(from, v, outside);
    if (!outside)
      for (int i = 0; i < 3; ++i)
        if (const VertexId w = tds_.vertex(t, i); q_[w] == q_[v]) return copies_.emplace_back(v, w), void();
    if (!outside && !sees(tds_.corners(t), v)) {
      hidden_[v] = 1;
      last_ = t;  // the next point's walk starts near this one
      return;
    }
    ++epoch_;
    stamp_[t] = epoch_;
    tds_.find_cavity(
        t, scratch_, [&](const VertexId* w) { return sees(w, v); }, Tds::kAnywhere, Tds::kNoWall,
        stamped(stamp_, epoch_));
    if (scratch_.revisited)
      cover_cavity(
          tds_, scratch_, [&](TriangleId u) { return stamp_[u] == epoch_; },
          [&](VertexId u) {
            if (u < n_) hidden_[u] = 1;
          },
          free_, cover_, cover_at_);
    SlotPool pool;
    if (free_.size() >= 2) {
      pool.list = free_.data(), pool.listed = free_.size();
    } else {
      pool = tds_.fresh(2);
    }
    last_ = tds_.fill_cavity(v, scratch_, pool);
    free_.resize(pool.listed);
  }

  // The threads' share of a round, as the sphere's (sphere/sphere.cpp) and the plane's partition
  // method's: each thread takes a stretch of the round's points along the curve, whose keys make
  // its region (the vertex at infinity in none); it inserts a point only where the face its
  // walk ends in and every face of the cavity have all three corners in its region, its walk
  // crossing only edges with an end there and stopping at the walls, and puts it off else. So no
  // two threads change one face, a face a thread reads is its own or one no thread changes, and
  // the links a thread rewrites only it reads. The triangulation is unique, so the faces are
  // the same whichever thread inserted which point.
  struct alignas(64) Part {  // (a line of its own: its thread writes it at each point)
    VertexId a = 0, b = 0;  // its points
    std::uint64_t from = 0, to = 0;  // its region: the keys in [from, to)
    TriangleId start = kNoTriangle;  // where its last walk ended
    // Faces with a corner in its region found before the threads start, one every kEvery of its
    // points (kNoTriangle where none was): where a walk from the last one leaves the region (which
    // is not convex), the point is looked for again from there.
    std::vector<TriangleId> starts;
    SlotPool pool;  // two slots a point
    std::vector<std::pair<VertexId, TriangleId>> put_off;  // each with a face near it
    std::vector<std::pair<VertexId, VertexId>> copies;
    // Free slots, taken before its pool's: its share of those free before the round, then those
    // of faces dropped round covered vertices.
    std::vector<TriangleId> freed;
    CoverScratch cover;
    std::uint32_t epoch = 0;  // its stamps: each insertion's epoch its last plus the thread count
  };

  bool owns(const Part& p, VertexId v) const { return v != infinite_ && key_[v] >= p.from && key_[v] < p.to; }

  void insert_round(VertexId b, VertexId e) {
    std::vector<Part> parts = round_parts<Part>(tds_, key_, b, e, threads_, epoch_);
    walk_limit_ = walk_limit(tds_);
    // With the triangulation at rest (the walks only read it), each part's on a thread.
    run_parts(parts, scratches_, [&](Part& p, CavityScratch&) { find_starts(p, last_); });
    // The free slots shared among the parts, each taking its own first (then its pool's).
    for (std::size_t i = 0; i < parts.size(); ++i)
      parts[i].freed.assign(free_.begin() + static_cast<std::ptrdiff_t>(free_.size() * i / parts.size()),
                            free_.begin() + static_cast<std::ptrdiff_t>(free_.size() * (i + 1) / parts.size()));
    free_.clear();
    run_parts(parts, scratches_, [&](Part& p, CavityScratch& s) { insert_part(p, s); });
    epoch_ = round_left(tds_, parts, free_, epoch_);
    for (Part& p : parts) {  // what the parts found; then the points put off
      if (p.start != kNoTriangle) last_ = p.start;
      copies_.insert(copies_.end(), p.copies.begin(), p.copies.end());
      free_.insert(free_.end(), p.freed.begin(), p.freed.end());
    }
    for (const Part& p : parts)
      for (const auto& [v, near] : p.put_off) insert(v, near);
  }

  // The part's starts (Part::starts), by walks each from where the one before ended, the first
  // from `from`. Reads only: the parts' run side by side, before any inserts.
  void find_starts(Part& p, TriangleId from) const {
    for (VertexId a = p.a; a < p.b; a += kEvery) {
      TriangleId start = kNoTriangle;
      for (VertexId v = a; v < std::min(p.b, a + kStartTries) && start == kNoTriangle; ++v) {
        bool outside = false;
        const TriangleId t = from = locate(from, v, outside);  // (the next walk from here)
        const VertexId* c = tds_.corners(t);
        if (!outside && (owns(p, c[0]) || owns(p, c[1]) || owns(p, c[2]))) start = t;
      }
      p.starts.push_back(start);
    }
    p.start = p.starts.empty() ? kNoTriangle : p.starts[0];
  }

  void insert_part(Part& p, CavityScratch& s) {
    for (VertexId v = p.a; v < p.b; ++v)
      if (TriangleId near = kNoTriangle; !is_first(v) && !insert_in(p, s, v, near)) p.put_off.emplace_back(v, near);
  }

  // Walks to v from t within the part's region (crossing only edges with an end there, never into
  // a wall); t is left where it ended.
  bool walk_in(const Part& p, TriangleId& t, VertexId v) const {
    std::size_t steps = 0;
    const Point q = q_[v].p;
    const Walked w = tds_.walk(
        t, [&](VertexId a, VertexId b) { return side(a, b, q); },
        [&](VertexId a, VertexId b) {
          if (!(owns(p, a) || owns(p, b)) || ++steps >= walk_limit_) return Step::Stop;
          const VertexId* c = tds_.corners(t);  // (the face across shares a or b: it may be read)
          const int i = c[0] != a && c[0] != b ? 0 : c[1] != a && c[1] != b ? 1 : 2;
          return tds_.opposite(tds_.link(t, i)) == infinite_ ? Step::Stop : Step::Cross;
        });
    return static_cast<bool>(w);
  }

  // insert() on a thread of a round, from p.start (left where the walk ended, or at the new
  // fan); false, with nothing changed, where the point is put off (`near` then where its walk
  // stopped, or kNoTriangle).
  bool insert_in(Part& p, CavityScratch& s, VertexId v, TriangleId& near) {
    TriangleId t = p.start;
    if (t == kNoTriangle || !walk_in(p, t, v)) {
      const TriangleId from = p.starts[(v - p.a) / kEvery];
      // (its slot may have been freed round a covered vertex since)
      if (!tds_.live(from)) return near = t, false;
      t = from;
      if (!walk_in(p, t, v)) return near = t, false;
    }
    p.start = t;
    const VertexId* c = tds_.corners(t);
    for (int i = 0; i < 3; ++i)
      if (q_[c[i]] == q_[v]) return p.copies.emplace_back(v, c[i]), true;
    if (!sees(c, v)) return hidden_[v] = 1, true;
    if (!owns(p, c[0]) || !owns(p, c[1]) || !owns(p, c[2]) || p.freed.size() + p.pool.size() < 2)
      return near = t, false;
    const std::uint32_t epoch = p.epoch += threads_;
    stamp_[t] = epoch;
    const bool whole = tds_.find_cavity(
        t, s, [&](const VertexId* u) { return sees(u, v); }, [&](Link l) { return owns(p, tds_.opposite(l)); },
        Tds::kNoWall, stamped(stamp_, epoch));
    if (!whole) return near = t, false;
    if (s.revisited)  // vertices covered: inside faces of the thread's own (the stamps only it writes)
      cover_cavity(
          tds_, s, [&](TriangleId u) { return stamp_[u] == epoch; },
          [&](VertexId u) {
            if (u < n_) hidden_[u] = 1;
          },
          p.freed, p.cover, cover_at_);
    p.pool.list = p.freed.data(), p.pool.listed = p.freed.size();
    p.start = tds_.fill_cavity(v, s, p.pool);
    p.freed.resize(p.pool.listed);
    p.pool.list = nullptr, p.pool.listed = 0;
    return true;
  }

  std::span<const Point> points_;
  std::span<const double> weights_;
  VertexId n_, infinite_;
  unsigned threads_;
  HugeArray<Weighted> q_;  // by vertex id, the vertex at infinity's NaN
  std::vector<VertexId> input_;
  std::array<VertexId, 3> first_{};  // the first triangle's vertices, counter-clockwise
  std::vector<std::pair<VertexId, VertexId>> copies_;
  Tds tds_;
  TriangleId last_ = 0;
  CavityScratch scratch_;
  std::vector<TriangleId> free_;
  HugeArray<std::uint32_t> stamp_;
  std::uint32_t epoch_ = 0;
  std::vector<std::uint8_t> hidden_;
  CoverScratch cover_;
  // cover_cavity's entries, by vertex id (the vertex at infinity's too): a thread writes those
  // of its cavities' vertices, which are all in its region.
  HugeArray<std::uint32_t> cover_at_;
  std::vector<std::uint32_t> key_;  // by vertex id: its point's key along the curve
  std::vector<CavityScratch> scratches_;  // a thread's each
  std::size_t walk_limit_ = 0;
};

}  // namespace
}  // namespace detail

RegularTriangulation triangulate_regular(std::span<const Point> points, std::span<const double> weights,
                                         unsigned threads) {
  using namespace detail;
  threads = thread_count(threads);
  check_input(points, weights);
  Builder builder(points, weights, threads);
  builder.run();
  Tds& tds = builder.tds();
  const VertexId inf = builder.infinite();
  std::vector<VertexId> input = std::move(builder.input());
  RegularTriangulation out;
  Settled settled = settle(points, weights, builder.weighted(), builder.copies(), builder.hidden(), input, threads);
  out.duplicates = std::move(settled.duplicates);
  out.hidden = std::move(settled.hidden);
  out.hull = hull_of(tds, inf, points, input, threads);
  finish_in_place(tds, inf, input, threads, out.triangles, out.neighbors);  // (inf: the number of points)
  out.stats.threads = threads;
  out.stats.points = points.size();
  out.stats.duplicates = out.duplicates.size();
  out.stats.distinct = points.size() - out.duplicates.size();
  return out;
}

}  // namespace ridt
