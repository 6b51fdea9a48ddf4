// The partition method (partition.cpp: its first pass; partition_second.cpp: the second):
// threads insert into one walking kernel (tds/delaunay.hpp) without a lock and
// without a history DAG.
//
// The points come in the BRIO order, each round along a Hilbert curve, with the curve's key
// of each vertex. A large round is cut into one stretch of the curve a thread; the cut keys
// split the plane into regions, and every vertex (old or new) belongs to the thread whose
// region holds it. A thread inserts a point of its stretch only when the triangle its walk
// ends in and every triangle of its cavity have all three vertices in its region; else it
// puts the point off. Its cavity starts in that triangle and grows by triangles that share
// an edge with one already in it: only the vertex across that edge is tested. Its walk keeps
// to such triangles of its own too, and where that stops it, goes on across edges with a
// vertex in its region. Then:
//
//   - a triangle a thread changes has all its vertices in the thread's region, and the new
//     ones too (the point and the cavity's boundary edges), so no two threads write one
//     triangle, and a slot a thread writes holds its own triangles all through the pass;
//   - a triangle with a vertex in a thread's region is that thread's or holds vertices of two
//     regions: no other thread changes it during the pass, and reading it races with nothing.
//     The triangles a walk enters (across an edge with a vertex in the region), and those a
//     cavity tests (neighbours of its own, with two vertices there), are such;
//   - the links a thread rewrites are those of edges with both ends in its region, which only
//     it reads: a walk reads the link across an edge with a vertex in its region, a cavity
//     those of its own triangles' edges.
//
// On clustered points a walk between two clusters crosses the empty space between them, whose
// triangles join clusters of several regions: a walk kept to the region's own triangles
// would stop there, and put off most of the points.
//
// So the threads share the triangulation with plain loads and stores, and the passes are ordered by
// the joins between them.
//
// A thread that ends its stretch early asks the one with the most points left for some (a
// host that takes a core away for a while would otherwise leave the other idle): the asked
// thread, between two insertions, gives the far end of its stretch, about half of what it has
// left, and shrinks its region to the rest, so that its own walks never again enter the part
// it gave, and hands over with it a triangle deep in that part, found while it still held it,
// and slots for its points. A region only shrinks, and a part is given whole, so regions stay
// disjoint, and the answer (a release store the asker reads with acquire) orders what the
// giver wrote there before what the taker writes. It refuses when its next walk would start
// in the part it gives.
//
// The points put off are inserted in a second pass whose regions are made of cells of a grid
// turned against the first pass's borders, and what is left after it by one thread. Small
// rounds are inserted by one thread (cut_among_threads): their mesh is small and their
// cavities reach the bounding vertices, which belong to no thread.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <unordered_set>
#include <utility>

#include "methods/method.hpp"
#include "methods/ranges.hpp"
#include "methods/round_driver.hpp"
#include "order/order.hpp"
#include "runtime/parallel.hpp"
#include "tds/delaunay.hpp"

namespace ridt::detail {

// A round is cut among the threads when each thread gets at least this many points, and the
// round at least kMinCutRound: a smaller one meets a mesh so small that most of its points
// would be put off.
inline constexpr VertexId kMinStretch = 256;
inline constexpr VertexId kMinCutRound = 4096;

// Whether a round of `points` is cut among `threads` threads (else the calling thread inserts it).
constexpr bool cut_among_threads(std::uint64_t points, unsigned threads) {
  return points >= kMinCutRound && points >= std::uint64_t{kMinStretch} * threads;
}
// Tries to find a thread's first triangle among its first points before the pass.
inline constexpr std::size_t kStartTries = 64;
// A thread that has run out of points asks another for about half of its rest when that is
// at least twice this many.
inline constexpr VertexId kMinShare = 2048;

// kLattice: the predicates' lattice forms (Vertices::lattice()).
template <bool kLattice>
class Partition {
 public:
  Partition(DelaunayTds& tds, const std::uint32_t* key, unsigned threads, std::vector<DuplicateHit>& duplicates,
            Stats& stats, Progress& progress)
      : tds_(tds),
        key_(key),
        n_(tds.vertices().n()),
        threads_(threads),
        workers_(threads),
        duplicates_(duplicates),
        stats_(stats),
        progress_(progress) {}

  void run();

 private:
  // Points [a, b) of a round, in curve order, that one thread inserts into its region: from
  // `from`, whose triangle `start` lies deep in the region, up to b, then from `from` down to a.
  struct Stretch {
    VertexId a = 0, b = 0, from = 0;
    KeyRange range;
    TriangleId start = kNoTriangle;
  };
  // A point put off, and a triangle that may lie near it: the one that holds it, or where its
  // walk stopped (kNoTriangle: none). A later walk to it starts there when that looks nearer
  // than the last point inserted (nearer()): the points put off lie along the regions'
  // borders, and in curve order they jump from one stretch of a border to another, but a walk
  // that was blocked may have stopped far from its point too. A slot that once held a
  // triangle always holds one (a cavity's slots are filled again at once), so the hint stays
  // a triangle of the triangulation.
  struct PutOff {
    VertexId p;
    TriangleId near;
    bool operator<(const PutOff& o) const { return p < o.p; }
  };
  // A thread's answer to another that asks it for points (Worker::ask).
  enum : int { kWorking, kAsked, kGiven, kRefused, kIdle };

  // A thread's state: stats.retries counts the points it put off.
  struct Worker : WorkerState<CavityScratch> {
    std::vector<PutOff> deferred;
    SlotPool pool;
    TriangleId last = 0;
    std::vector<std::pair<TriangleId, TriangleId>> spare;  // slots its pools did not hand out
    std::vector<TriangleId> seen;  // deep_in's search
    std::uint32_t tried = 0;  // points tried since the last report
    std::uint64_t done = 0;  // inserted or found equal to a vertex, not yet counted in inserted_
    bool giving = true;  // whether it may still give points of its stretch away
    // Shared with the threads that ask it for points, on a cache line of their own: kWorking,
    // or kAsked by one of them, then kGiven (`given`, with 2 (b - a) slots from `given_slots`)
    // or kRefused until the asker has read it; kIdle between stretches.
    alignas(64) std::atomic<int> ask{kIdle};
    std::atomic<VertexId> remaining{0};  // points of its stretch it has yet to try, about
    Stretch given;
    TriangleId given_slots = 0;
  };
  // A region of the second pass and its points, in curve order.
  struct Task {
    CellRange range;
    std::vector<PutOff> todo, deferred;  // hints in todo only where the region owns them
    TriangleId start = 0;  // the triangle it starts from, in its region
    std::size_t split = 0;  // todo[split] is the first point it inserts
    SlotPool pool;
  };

  // Of triangle t and x's hint, the one whose first finite vertex lies nearer x's point: a
  // guess at where a walk to it is shorter.
  TriangleId nearer(TriangleId t, const PutOff& x) const {
    if (x.near == kNoTriangle) return t;
    const Vertices& v = tds_.vertices();
    auto distance2 = [&](TriangleId u) {
      for (int i = 0; i < 3; ++i)
        if (const VertexId a = tds_.vertex(u, i); !v.symbolic(a)) {
          const double dx = v[a].x - v[x.p].x, dy = v[a].y - v[x.p].y;
          return dx * dx + dy * dy;
        }
      return HUGE_VAL;
    };
    return distance2(x.near) < distance2(t) ? x.near : t;
  }

  // The region of keys [lo, lo + len) round the circle.
  KeyRange region(std::uint32_t lo, std::uint64_t len) const { return {key_, n_, lo, len}; }

  // Whether triangle t has all three vertices in region r (tested together, without a branch
  // between them: the answers are hard to predict). R: KeyRange (the first pass) or CellRange
  // (the second), here and below.
  template <class R>
  bool owns(const R& r, TriangleId t) const {
    const VertexId a = tds_.vertex(t, 0), b = tds_.vertex(t, 1), c = tds_.vertex(t, 2);
    return (std::max(a, std::max(b, c)) < n_) & r.holds(a) & r.holds(b) & r.holds(c);
  }

  // Whether vertex v is in region r.
  template <class R>
  bool owns_vertex(const R& r, VertexId v) const {
    return (v < n_) & r.holds(v);
  }
  // Whether the triangle entered by link l from one with all its vertices in region r has all
  // of them there too (DelaunayTds::find_cavity's `owned`).
  template <class R>
  bool enters(const R& r, Link l) const {
    return owns_vertex(r, tds_.opposite(l));
  }
  // Whether a walk in region r may cross the edge a b: one of its vertices is in r.
  template <class R>
  bool crosses(const R& r, VertexId a, VertexId b) const {
    return owns_vertex(r, a) | owns_vertex(r, b);
  }
  // DelaunayTds::walk's `cross` for a walk that enters only region r's own triangles (from one of
  // them), and for one that crosses the edges with a vertex in r.
  template <class R>
  auto own_triangles(const R& r) const {
    return [this, &r](Link l) { return enters(r, l); };
  }
  template <class R>
  auto own_edges(const R& r) const {
    return [this, &r](VertexId a, VertexId b) { return crosses(r, a, b); };
  }

  // Whether region r's triangles reachable from t through the region number some dozens: a
  // thread that starts in a small pocket of its region cut off by the border would put off
  // every point. Reads only triangles of r and their neighbours.
  template <class R>
  bool deep_in(const R& r, TriangleId t, std::vector<TriangleId>& seen) const {
    if (!owns(r, t)) return false;
    constexpr std::size_t kEnough = 48;
    seen.assign(1, t);
    for (std::size_t k = 0; k < seen.size() && seen.size() < kEnough; ++k)
      for (int i = 0; i < 3; ++i) {
        const Link l = tds_.link(seen[k], i);
        if (l == kNoLink) continue;
        const auto u = static_cast<TriangleId>(l / 3);
        if (owns(r, u) && std::find(seen.begin(), seen.end(), u) == seen.end()) seen.push_back(u);
      }
    return seen.size() >= kEnough;
  }

  // A triangle deep in region r from which to insert points [a, b): walking from t, entering
  // only triangles that `enter` allows, to the points from the middle of [a, b) on. The point
  // it holds, or false.
  template <class Enter, class R>
  bool find_start(Enter&& enter, const R& r, VertexId a, VertexId b, TriangleId& t, VertexId& from,
                  std::vector<TriangleId>& seen) const {
    const VertexId size = b - a;
    for (VertexId k = 0; k < std::min<VertexId>(size, kStartTries); ++k) {
      const VertexId p = a + (size / 2 + k) % size;
      if (tds_.walk<kLattice>(t, p, enter) && deep_in(r, t, seen)) {
        from = p;
        return true;
      }
    }
    return false;
  }

  // A triangle deep in region r, found by a breadth-first search from t through the
  // triangles of `within` (which holds r and t), or none among the first few thousand.
  TriangleId reach(const KeyRange& within, const KeyRange& r, TriangleId t, std::vector<TriangleId>& seen) const {
    constexpr std::size_t kMost = std::size_t{1} << 15;
    std::vector<TriangleId> queue{t};
    std::unordered_set<TriangleId> visited{t};
    for (std::size_t k = 0; k < queue.size() && k < kMost; ++k) {
      const TriangleId u = queue[k];
      if (owns(r, u) && deep_in(r, u, seen)) return u;
      for (int i = 0; i < 3; ++i) {
        const Link l = tds_.link(u, i);
        if (l == kNoLink) continue;
        const TriangleId v = triangle_of(l);
        if (owns(within, v) && visited.insert(v).second) queue.push_back(v);
      }
    }
    return kNoTriangle;
  }

  // One round of points [b, e), in curve order: a pass on all threads, a second over the points
  // put off, then one thread for what is left.
  void insert_round(VertexId b, VertexId e);

  // The first pass on thread i: its stretch, then points that other threads give it, until
  // none has enough left to share.
  void first_pass(unsigned i, Stretch s);

  // Stretch s on thread i, answering any thread that asks for points meanwhile. False when
  // the run stops.
  bool insert_stretch(unsigned i, Stretch& s);

  // Another thread asks w for points while w inserts stretch s (going up or down, `next` as in
  // insert_stretch): w gives the far end of what it has left, about half, when that is enough
  // and it can hand it over safely, and shrinks its stretch and region to the rest. It still
  // holds all of its region here, so all it reads is its own or mixed.
  void answer(Worker& w, Stretch& s, bool up, VertexId next);

  // Thread w has no stretch: any thread that asked it is refused, and no more will ask.
  static void go_idle(Worker& w);

  static void wait_a_little(unsigned spins);

  // Thread i, idle, asks the thread with the most points left for some. False when none has
  // enough to share.
  bool take_from_another(unsigned i, Stretch& s);

  // The second pass: the points put off lie along the borders between the first pass's
  // regions, which follow the sides of the Hilbert curve's squares. The second pass's regions
  // are runs of cells of a turned grid (CellRange), in the grid's own Hilbert order, about
  // twice as many as threads with about equal numbers of these points: their borders cross the
  // first pass's at single places. Returns what is left.
  std::vector<PutOff> second_pass(std::vector<PutOff> left);

  // Task t's start, and slots for all its points, the free ones from free_[taken] on first.
  // Returns how many free slots it took.
  std::size_t prepare(Task& t, std::size_t taken);

  // Task t's points into its region on thread i, from todo[split] to the end, then from the
  // start again back to todo[0]. False when the run stops.
  bool insert_task(unsigned i, Task& t);

  // Point p into region r on thread i, from `pool`, or put off into `deferred`. False when
  // the run stops: an error, or the progress callback threw. The walk, the cavity and their
  // predicates all in line (flatten): with the class made twice (kLattice), the compiler
  // otherwise leaves the predicates out of line (2-5 % more instructions on uniform points).
  template <class R>
  [[gnu::flatten]] bool try_insert(unsigned i, const R& r, VertexId p, std::vector<PutOff>& deferred, SlotPool& pool) {
    Worker& w = workers_[i];
    if (++w.tried == 1024) {
      w.tried = 0;
      inserted_.fetch_add(std::exchange(w.done, 0), std::memory_order_relaxed);
      if (stop_.load(std::memory_order_relaxed)) return false;
      if (i == 0) progress_(before_ + inserted_.load(std::memory_order_relaxed));
    }
    // The walk keeps to the region's own triangles (one id test a step); where that stops
    // it, it goes on through triangles with a vertex in the region (two), to a triangle that
    // must be the region's. A point put off leaves the next walk to start where the first
    // walk stopped (in the region, and nearer the points to come than the last insertion),
    // and where the second got to as its hint.
    const bool in_region = r.holds(p);
    if (!in_region || !tds_.walk<kLattice>(w.last, p, own_triangles(r))) [[unlikely]] {
      TriangleId t = w.last;
      if (!in_region || !walk_on(r, t, p)) {
        deferred.push_back({p, t});
        ++w.stats.retries;
        return true;
      }
      w.last = t;
    }
    const TriangleId t = w.last;
    if (const VertexId hit = tds_.coincident(t, p); hit != kNoVertex) {
      w.duplicates.push_back({p, hit});
      ++w.done;
      return true;
    }
    if (!tds_.find_cavity<kLattice>(t, p, w.scratch, [&](Link l) { return enters(r, l); })) {
      deferred.push_back({p, t});
      ++w.stats.retries;
      return true;
    }
    if (pool.size() < 2) throw std::logic_error("ridt: a partition thread ran out of slots");
    w.last = tds_.fill_cavity(p, w.scratch, pool);
    ++w.stats.points;
    ++w.done;
    return true;
  }

  // The walk from t to p across edges with a vertex in region r, to a triangle of r: whether
  // it got there (out of line: the common path has no use for it).
  template <class R>
  [[gnu::noinline]] bool walk_on(const R& r, TriangleId& t, VertexId p) const {
    return tds_.walk<kLattice>(t, p, own_edges(r)) && owns(r, t);
  }

  // body(i) on each thread i, the calling one taking 0; rethrows the first failure once all
  // ended, and counts what they inserted and how long each waited for the last.
  template <class Body>
  void run_threads(Body&& body) {
    stop_.store(false, std::memory_order_relaxed);
    inserted_.store(0, std::memory_order_relaxed);
    before_ = done_;
    std::exception_ptr failure;
    std::mutex failure_lock;
    auto work = [&](unsigned i) {
      try {
        body(i);
      } catch (...) {
        const std::lock_guard<std::mutex> guard(failure_lock);
        if (!failure) failure = std::current_exception();
        stop_.store(true, std::memory_order_relaxed);
      }
      go_idle(workers_[i]);  // a thread that asked it, on an error, is answered
      pass_end_[i] = Clock::now();  // the wait for the others, from here to the last one's end
    };
    on_threads(threads_, work);
    if (failure) std::rethrow_exception(failure);
    const Clock::time_point end = *std::max_element(pass_end_.begin(), pass_end_.end());
    std::uint64_t inserted = 0;
    for (unsigned i = 0; i < threads_; ++i) {
      Worker& w = workers_[i];
      w.stats.time_wait_s += seconds(end - pass_end_[i]);
      inserted += std::exchange(w.done, 0);
      w.tried = 0;
      if (w.stats.points > 0) last_ = w.last;
    }
    done_ = before_ + inserted_.load(std::memory_order_relaxed) + inserted;
  }

  // Slots [first, end) that no insertion took: free, and listed for the next ones.
  void release(TriangleId first, TriangleId end);

  // The points of `list` by the calling thread, in order, with no regions.
  void insert_alone(const std::vector<PutOff>& list);

  DelaunayTds& tds_;
  const std::uint32_t* key_;  // n: the bounding vertices have none
  VertexId n_;
  unsigned threads_;
  std::vector<Worker> workers_;
  std::vector<Clock::time_point> pass_end_ = std::vector<Clock::time_point>(threads_);
  std::vector<Task> tasks_;  // the second pass's regions
  std::vector<std::uint16_t> owner_;  // the second pass's region of each cell (CellRange)
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> inserted_{0};  // counted by the threads as they go
  std::uint64_t before_ = 0;  // done_ when the pass began
  std::vector<TriangleId> free_;  // free slots below the top
  TriangleId last_ = 0;  // a triangle, where the next walk of the calling thread starts
  std::uint64_t done_ = 0;  // points inserted or found equal to a vertex
  std::vector<DuplicateHit>& duplicates_;
  Stats& stats_;
  Progress& progress_;
};

// Used by run_threads in both passes: made where they are used.
template <bool kLattice>
void Partition<kLattice>::go_idle(Worker& w) {
  w.remaining.store(0, std::memory_order_relaxed);
  for (unsigned spins = 0;; ++spins) {
    int state = kWorking;
    if (w.ask.compare_exchange_strong(state, kIdle, std::memory_order_acq_rel) || state == kIdle) return;
    if (state == kAsked) w.ask.store(kRefused, std::memory_order_release);
    wait_a_little(spins);  // until the asker has read the answer
  }
}

template <bool kLattice>
void Partition<kLattice>::wait_a_little(unsigned spins) {
  if (spins < 4096)
    cpu_relax();
  else
    std::this_thread::yield();
}

}  // namespace ridt::detail
