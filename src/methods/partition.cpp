// The partition method: threads insert into one walking mesh (walk/mesh.hpp) without a lock and
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
// stopped there, and such walks were nine in ten of the points put off.
//
// So the threads share the mesh with plain loads and stores, and the passes are ordered by
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
// The points put off are inserted in a second pass whose cuts lie in the middle of the first
// pass's stretches, and what is left after it by one thread. Small rounds are inserted by one
// thread: their mesh is small and their cavities reach the bounding vertices, which belong to
// no thread.
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
#include "methods/region.hpp"
#include "methods/threads.hpp"
#include "order/order.hpp"
#include "runtime/parallel.hpp"
#include "walk/mesh.hpp"

namespace ridt::detail {
namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// A round is cut among the threads when each thread gets at least this many points.
constexpr VertexId kMinStretch = 1024;
// Tries to find a thread's first triangle among its first points before the pass.
constexpr std::size_t kStartTries = 64;
// A thread that has run out of points asks another for about half of its rest when that is
// at least twice this many.
constexpr VertexId kMinShare = 2048;

// kLattice: the predicates' lattice forms (Vertices::lattice()).
template <bool kLattice>
class Partition {
 public:
  Partition(Mesh& mesh, const std::uint32_t* key, unsigned threads, std::vector<DuplicateHit>& duplicates, Stats& stats,
            Progress& progress)
      : mesh_(mesh),
        key_(key),
        n_(mesh.vertices().n()),
        threads_(threads),
        workers_(threads),
        duplicates_(duplicates),
        stats_(stats),
        progress_(progress) {}

  void run() {
    const VertexId n = mesh_.vertices().n();
    const auto t0 = Clock::now();
    for (VertexId b = 0; b < n; b = round_end(b)) {
      const VertexId e = std::min(round_end(b), n);
      if (e - b < kMinStretch * threads_) {
        std::vector<PutOff> all(e - b);
        for (VertexId p = b; p < e; ++p) all[p - b] = {p, kNoTriangle};
        insert_alone(all);
      } else {
        insert_round(b, e);
      }
    }
    const double total = seconds(Clock::now() - t0);
    for (const Worker& w : workers_) add_worker(w, 0.0, 0.0, total, duplicates_, stats_);
  }

 private:
  // Points [a, b) of a round, in curve order, that one thread inserts into its region: from
  // `from`, whose triangle `start` lies deep in the region, up to b, then from `from` down to a.
  struct Stretch {
    VertexId a = 0, b = 0, from = 0;
    Region range;
    TriangleId start = kNoTriangle;
  };
  // A point put off, and a triangle that may lie near it: the one that holds it, or where its
  // walk stopped (kNoTriangle: none). A later walk to it starts there when that looks nearer
  // than the last point inserted (nearer()): the points put off lie along the regions'
  // borders, and in curve order they jump from one stretch of a border to another, but a walk
  // that was blocked may have stopped far from its point too. A slot that once held a
  // triangle always holds one (a cavity's slots are filled again at once), so the hint stays
  // a triangle of the mesh.
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
    std::vector<std::pair<VertexId, VertexId>> held;  // the first pass's stretches it inserted
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
    Region range;
    std::vector<PutOff> todo, deferred;  // hints in todo only where the region owns them
    TriangleId start = 0;  // the triangle it starts from, in its region
    std::size_t split = 0;  // todo[split] is the first point it inserts
    SlotPool pool;
  };

  // Of triangle t and x's hint, the one whose first finite vertex lies nearer x's point: a
  // guess at where a walk to it is shorter.
  TriangleId nearer(TriangleId t, const PutOff& x) const {
    if (x.near == kNoTriangle) return t;
    const Vertices& v = mesh_.vertices();
    auto distance2 = [&](TriangleId u) {
      for (int i = 0; i < 3; ++i)
        if (const VertexId a = mesh_.vertex(u, i); !v.symbolic(a)) {
          const double dx = v[a].x - v[x.p].x, dy = v[a].y - v[x.p].y;
          return dx * dx + dy * dy;
        }
      return HUGE_VAL;
    };
    return distance2(x.near) < distance2(t) ? x.near : t;
  }

  // The region of keys [lo, lo + len) round the circle.
  Region region(std::uint32_t lo, std::uint64_t len) const { return {key_, n_, lo, len}; }

  // Whether slot t holds a triangle (kNoTriangle: no).
  bool live(TriangleId t) const { return t < mesh_.slots() && mesh_.vertex(t, 0) != kNoVertex; }

  // Whether triangle t has all three vertices in region r (tested together, without a branch
  // between them: the answers are hard to predict).
  bool owns(const Region& r, TriangleId t) const {
    const VertexId a = mesh_.vertex(t, 0), b = mesh_.vertex(t, 1), c = mesh_.vertex(t, 2);
    return (std::max(a, std::max(b, c)) < n_) & r.holds(a) & r.holds(b) & r.holds(c);
  }

  // Whether vertex v is in region r.
  bool owns_vertex(const Region& r, VertexId v) const { return (v < n_) & r.holds(v); }
  // Whether the triangle entered by link l from one with all its vertices in region r has all
  // of them there too (Mesh::find_cavity's `owned`).
  bool enters(const Region& r, Link l) const { return owns_vertex(r, mesh_.opposite(l)); }
  // Whether a walk in region r may cross the edge a b: one of its vertices is in r.
  bool crosses(const Region& r, VertexId a, VertexId b) const { return owns_vertex(r, a) | owns_vertex(r, b); }
  // Mesh::walk's `cross` for a walk that enters only region r's own triangles (from one of
  // them), and for one that crosses the edges with a vertex in r.
  auto own_triangles(const Region& r) const {
    return [this, &r](Link l) { return enters(r, l); };
  }
  auto own_edges(const Region& r) const {
    return [this, &r](VertexId a, VertexId b) { return crosses(r, a, b); };
  }

  // Whether region r's triangles reachable from t through the region number some dozens: a
  // thread that starts in a small pocket of its region cut off by the border would put off
  // every point. Reads only triangles of r and their neighbours.
  bool deep_in(const Region& r, TriangleId t, std::vector<TriangleId>& seen) const {
    if (!owns(r, t)) return false;
    constexpr std::size_t kEnough = 48;
    seen.assign(1, t);
    for (std::size_t k = 0; k < seen.size() && seen.size() < kEnough; ++k)
      for (int i = 0; i < 3; ++i) {
        const Link l = mesh_.link(seen[k], i);
        if (l == kNoLink) continue;
        const auto u = static_cast<TriangleId>(l / 3);
        if (owns(r, u) && std::find(seen.begin(), seen.end(), u) == seen.end()) seen.push_back(u);
      }
    return seen.size() >= kEnough;
  }

  // A triangle deep in region r from which to insert points [a, b): walking from t, entering
  // only triangles that `enter` allows, to the points from the middle of [a, b) on. The point
  // it holds, or false.
  template <class Enter>
  bool find_start(Enter&& enter, const Region& r, VertexId a, VertexId b, TriangleId& t, VertexId& from,
                  std::vector<TriangleId>& seen) const {
    const VertexId size = b - a;
    for (VertexId k = 0; k < std::min<VertexId>(size, kStartTries); ++k) {
      const VertexId p = a + (size / 2 + k) % size;
      if (mesh_.walk<kLattice>(t, p, enter) && deep_in(r, t, seen)) {
        from = p;
        return true;
      }
    }
    return false;
  }

  // A triangle deep in region r, found by a breadth-first search from t through the
  // triangles of `within` (which holds r and t), or none among the first few thousand.
  TriangleId reach(const Region& within, const Region& r, TriangleId t, std::vector<TriangleId>& seen) const {
    constexpr std::size_t kMost = std::size_t{1} << 15;
    std::vector<TriangleId> queue{t};
    std::unordered_set<TriangleId> visited{t};
    for (std::size_t k = 0; k < queue.size() && k < kMost; ++k) {
      const TriangleId u = queue[k];
      if (owns(r, u) && deep_in(r, u, seen)) return u;
      for (int i = 0; i < 3; ++i) {
        const Link l = mesh_.link(u, i);
        if (l == kNoLink) continue;
        const TriangleId v = triangle_of(l);
        if (owns(within, v) && visited.insert(v).second) queue.push_back(v);
      }
    }
    return kNoTriangle;
  }

  // One round of points [b, e), in curve order: a pass on all threads, a second over the points
  // put off, then one thread for what is left.
  void insert_round(VertexId b, VertexId e) {
    const VertexId m = e - b;
    // Equal stretches of the round, cut where the key changes (points of one key lie in one
    // region); the regions' first keys, the first from 0 and the last round to the end.
    std::vector<VertexId> cut(threads_ + 1);
    cut[0] = b, cut[threads_] = e;
    for (unsigned i = 1; i < threads_; ++i) {
      VertexId c = std::max(cut[i - 1], b + static_cast<VertexId>(std::uint64_t{m} * i / threads_));
      while (c > b && c < e && key_[c] == key_[c - 1]) ++c;
      cut[i] = c;
    }
    std::vector<std::uint32_t> from(threads_);
    from[0] = 0;
    for (unsigned i = 1; i < threads_; ++i) from[i] = cut[i] < e ? key_[cut[i]] : 0xffffffffu;
    // Before the threads start, with the mesh at rest: each thread's start, and slots for all
    // its points (two a point inserted), from a range for the whole round.
    const TriangleId base = mesh_.grow(2 * m);
    const auto anywhere = Mesh::kAnywhere;
    std::vector<Stretch> stretch(threads_);
    std::vector<std::pair<VertexId, VertexId>> held;
    for (unsigned i = 0; i < threads_; ++i) {
      Worker& w = workers_[i];
      Stretch& s = stretch[i];
      s.a = cut[i], s.b = cut[i + 1];
      s.range =
          region(from[i], i + 1 < threads_ ? std::uint64_t{from[i + 1]} - from[i] : (std::uint64_t{1} << 32) - from[i]);
      w.pool = {nullptr, 0, base + 2 * (s.a - b), base + 2 * (s.b - b)};
      w.giving = true;
      if (s.a < s.b && find_start(anywhere, s.range, s.a, s.b, last_, s.from, w.seen)) {
        s.start = last_;
        w.remaining.store(s.b - s.a, std::memory_order_relaxed);
        w.ask.store(kWorking, std::memory_order_relaxed);
      } else {  // no start: every point is put off, and the thread begins by asking for some
        for (VertexId p = s.a; p < s.b; ++p) w.deferred.push_back({p, kNoTriangle});
        if (s.a < s.b) held.emplace_back(s.a, s.b);
        w.remaining.store(0, std::memory_order_relaxed);
        w.ask.store(kIdle, std::memory_order_relaxed);
      }
    }
    run_threads([&](unsigned i) { first_pass(i, stretch[i]); });
    // What no thread inserted: the points put off, and the slots the pools did not hand out.
    std::vector<PutOff> left;
    for (Worker& w : workers_) {
      left.insert(left.end(), w.deferred.begin(), w.deferred.end());
      w.deferred.clear();
      w.spare.emplace_back(w.pool.next, w.pool.end);
      w.pool = SlotPool{};
      for (const auto& [first, end] : w.spare) release(first, end);
      w.spare.clear();
      held.insert(held.end(), w.held.begin(), w.held.end());
      w.held.clear();
    }
    if (left.size() >= 64 * threads_) left = second_pass(std::move(left), std::move(held));
    std::sort(left.begin(), left.end());
    insert_alone(left);
  }

  // The first pass on thread i: its stretch, then points that other threads give it, until
  // none has enough left to share.
  void first_pass(unsigned i, Stretch s) {
    Worker& w = workers_[i];
    if (s.start != kNoTriangle && !insert_stretch(i, s)) return;
    for (;;) {
      go_idle(w);
      if (!take_from_another(i, s)) return;
      w.giving = true;
      w.remaining.store(s.b - s.a, std::memory_order_relaxed);
      w.ask.store(kWorking, std::memory_order_relaxed);  // only this thread leaves kIdle
      if (!insert_stretch(i, s)) return;
    }
  }

  // Stretch s on thread i, answering any thread that asks for points meanwhile. False when
  // the run stops.
  bool insert_stretch(unsigned i, Stretch& s) {
    Worker& w = workers_[i];
    w.last = s.start;
    bool up = true;
    VertexId next = s.from;  // up: the next point; down: one past it
    for (;;) {
      if (up && next >= s.b) {
        up = false;
        next = s.from;
        if (next <= s.a) break;  // it gave all its points below away
        w.last = s.start;  // a triangle of its own, or one its insertions wrote in the slot
        continue;
      }
      if (!up && next <= s.a) break;
      // acquire: whatever the asker read of a last answer was read before this question.
      if (w.ask.load(std::memory_order_acquire) == kAsked) {
        answer(w, s, up, next);
        continue;  // its stretch may have shrunk to nothing left to try
      }
      const VertexId p = up ? next++ : --next;
      if (!try_insert(i, s.range, p, w.deferred, w.pool)) return false;
      if ((p & 63) == 0)
        w.remaining.store(!w.giving ? 0 : up ? (s.b - next) + (s.from - s.a) : next - s.a, std::memory_order_relaxed);
    }
    w.held.emplace_back(s.a, s.b);
    return true;
  }

  // Another thread asks w for points while w inserts stretch s (going up or down, `next` as in
  // insert_stretch): w gives the far end of what it has left, about half, when that is enough
  // and it can hand it over safely, and shrinks its stretch and region to the rest. It still
  // holds all of its region here, so all it reads is its own or mixed.
  void answer(Worker& w, Stretch& s, bool up, VertexId next) {
    const VertexId above = up ? s.b - next : 0, below = up ? s.from - s.a : next - s.a;
    const VertexId half = (above + below) / 2;
    // What it gives: the bottom of its points below, or the top of those above, whichever's
    // border lies further from the point it is at, cut where the key changes.
    VertexId a = 0, b = 0;
    if (w.giving) {
      VertexId bottom = s.a + std::min(below, half);
      while (bottom < (up ? s.from : next) && key_[bottom] == key_[bottom - 1]) ++bottom;
      VertexId top = next + above / 2;
      while (top < s.b && key_[top] == key_[top - 1]) ++top;
      const VertexId bottom_gap = next - bottom, top_gap = up ? top - next : 0;
      if (bottom_gap >= top_gap && bottom - s.a >= kMinShare / 2)
        a = s.a, b = bottom;
      else if (top_gap > bottom_gap && s.b - top >= kMinShare / 2)
        a = top, b = s.b;
    }
    bool ok = a < b;
    Region keep = s.range, give = s.range;
    if (ok) {
      const bool bottom = a == s.a;
      const std::uint32_t at = key_[bottom ? b : a];  // the cut's key: the rest's first, or the gift's
      const std::uint64_t offset = static_cast<std::uint32_t>(at - s.range.lo);
      (bottom ? give : keep) = region(s.range.lo, offset);
      (bottom ? keep : give) = region(at, s.range.len - offset);
      // Its next walk starts at w.last, and the walk down at s.start when points below it are
      // left to it: both must stay its own.
      const bool down_left = up && (bottom ? b : s.a) < s.from;
      ok = owns(keep, w.last) && (!down_left || owns(keep, s.start));
    }
    TriangleId t = ok ? w.last : kNoTriangle;
    VertexId from = 0;
    // From where its next walk starts, along a walk to the part it gives; else, where the region's
    // shape blocks that walk, from a triangle deep in the part found by a search through its
    // region.
    const auto held = own_edges(s.range);
    if (ok && !find_start(held, give, a, b, t, from, w.seen)) {
      t = reach(s.range, give, w.last, w.seen);
      ok = t != kNoTriangle && find_start(held, give, a, b, t, from, w.seen);
    }
    if (!ok) {
      w.giving = false;  // it will not be asked again for this stretch
      w.remaining.store(0, std::memory_order_relaxed);
      w.ask.store(kRefused, std::memory_order_release);
      return;
    }
    w.given = {a, b, from, give, t};
    w.pool.end -= 2 * (b - a);  // its pool holds two slots for each point it has yet to try
    w.given_slots = w.pool.end;
    if (a == s.a)
      s.a = b;
    else
      s.b = a;
    s.range = keep;
    w.remaining.store(above + below - (b - a), std::memory_order_relaxed);
    // release: what it wrote in the part it gives, and `given`, before the answer.
    w.ask.store(kGiven, std::memory_order_release);
  }

  // Thread w has no stretch: any thread that asked it is refused, and no more will ask.
  static void go_idle(Worker& w) {
    w.remaining.store(0, std::memory_order_relaxed);
    for (unsigned spins = 0;; ++spins) {
      int state = kWorking;
      if (w.ask.compare_exchange_strong(state, kIdle, std::memory_order_acq_rel) || state == kIdle) return;
      if (state == kAsked) w.ask.store(kRefused, std::memory_order_release);
      wait_a_little(spins);  // until the asker has read the answer
    }
  }

  static void wait_a_little(unsigned spins) {
    if (spins < 4096)
      cpu_relax();
    else
      std::this_thread::yield();
  }

  // Thread i, idle, asks the thread with the most points left for some. False when none has
  // enough to share.
  bool take_from_another(unsigned i, Stretch& s) {
    Worker& me = workers_[i];
    for (unsigned spins = 0;; ++spins) {
      unsigned from = threads_;
      VertexId most = 2 * kMinShare - 1;
      for (unsigned v = 0; v < threads_; ++v) {
        const VertexId r = workers_[v].remaining.load(std::memory_order_relaxed);
        if (v != i && r > most) from = v, most = r;
      }
      if (from == threads_ || stop_.load(std::memory_order_relaxed)) return false;
      Worker& v = workers_[from];
      int state = kWorking;
      if (!v.ask.compare_exchange_strong(state, kAsked, std::memory_order_acq_rel)) {
        wait_a_little(spins);  // another asks it, or it is between stretches
        continue;
      }
      // acquire: its answer, and what it wrote in the points it gives, before we read them.
      for (unsigned wait = 0; (state = v.ask.load(std::memory_order_acquire)) == kAsked; ++wait) wait_a_little(wait);
      Stretch given;
      TriangleId slots = 0;
      if (state == kGiven) given = v.given, slots = v.given_slots;
      v.ask.store(kWorking, std::memory_order_release);  // read: it may be asked again
      if (state == kGiven) {
        s = given;
        me.spare.emplace_back(me.pool.next, me.pool.end);
        me.pool = {nullptr, 0, slots, slots + 2 * (s.b - s.a)};
        return true;
      }
    }
  }

  // The second pass: the points put off lie along the borders between the first pass's
  // stretches; regions cut in the middle of each stretch put each such border inside one. The
  // last region wraps round to key 0. Returns what is left.
  std::vector<PutOff> second_pass(std::vector<PutOff> left, std::vector<std::pair<VertexId, VertexId>> held) {
    std::vector<std::uint32_t> from;  // the smallest key of each region
    for (const auto& [a, b] : held)
      if (a < b) from.push_back(key_[a + (b - a) / 2]);
    std::sort(from.begin(), from.end());
    from.erase(std::unique(from.begin(), from.end()), from.end());
    if (from.empty()) return left;
    std::sort(left.begin(), left.end());  // curve order: the round is sorted by key
    tasks_.assign(from.size(), Task{});
    for (std::size_t j = 0; j < from.size(); ++j)
      tasks_[j].range = region(
          from[j],
          j + 1 < from.size() ? std::uint64_t{from[j + 1]} - from[j] : (std::uint64_t{1} << 32) - (from[j] - from[0]));
    for (PutOff x : left) {
      // The last region whose first key is at most p's, or the last of all (which wraps round).
      const auto above = std::upper_bound(from.begin(), from.end(), key_[x.p]) - from.begin();
      Task& t = tasks_[above > 0 ? static_cast<std::size_t>(above - 1) : from.size() - 1];
      // A hint the region does not own may change under another thread: read it now or never.
      if (!live(x.near) || !owns(t.range, x.near)) x.near = kNoTriangle;
      t.todo.push_back(x);
    }
    // Before the threads start: each region's start, and slots for all its points, the free
    // ones first.
    std::size_t taken = 0;
    for (Task& t : tasks_) {
      t.split = t.todo.size();  // none found: every point is put off
      for (std::size_t k = 0; k < std::min(t.todo.size(), kStartTries); ++k) {
        const std::size_t c = (t.todo.size() / 2 + k) % t.todo.size();
        last_ = mesh_.walk(t.todo[c].near != kNoTriangle ? t.todo[c].near : last_, t.todo[c].p);
        if (deep_in(t.range, last_, workers_[0].seen)) {
          t.start = last_;
          t.split = c;
          break;
        }
      }
      if (t.split == t.todo.size()) {
        t.deferred = std::move(t.todo);
        t.todo.clear();
        t.split = 0;
      }
      const std::size_t need = 2 * t.todo.size();
      const std::size_t listed = std::min(need, free_.size() - taken);
      t.pool.list = free_.data() + taken;
      t.pool.listed = listed;
      taken += listed;
      t.pool.next = mesh_.grow(static_cast<TriangleId>(need - listed));
      t.pool.end = t.pool.next + static_cast<TriangleId>(need - listed);
    }
    std::atomic<std::size_t> next{0};
    run_threads([&](unsigned i) {
      // relaxed: the counter only hands out each region once; the joins order the rest.
      for (std::size_t j; (j = next.fetch_add(1, std::memory_order_relaxed)) < tasks_.size();)
        if (!insert_task(i, tasks_[j])) return;
    });
    // What the pools did not hand out is free now; the free slots they took are used.
    std::vector<TriangleId> unused;
    left.clear();
    for (Task& t : tasks_) {
      unused.insert(unused.end(), t.pool.list, t.pool.list + t.pool.listed);
      for (; t.pool.next < t.pool.end; ++t.pool.next) {
        mesh_.free_slot(t.pool.next);
        unused.push_back(t.pool.next);
      }
      left.insert(left.end(), t.deferred.begin(), t.deferred.end());
    }
    unused.insert(unused.end(), free_.begin() + static_cast<std::ptrdiff_t>(taken), free_.end());
    free_ = std::move(unused);
    tasks_.clear();
    return left;
  }

  // Task t's points into its region on thread i, from todo[split] to the end, then from the
  // start again back to todo[0]. False when the run stops.
  bool insert_task(unsigned i, Task& t) {
    Worker& w = workers_[i];
    auto insert = [&](const PutOff& x) {
      w.last = nearer(w.last, x);  // the hint is its region's, and so still (PutOff)
      return try_insert(i, t.range, x.p, t.deferred, t.pool);
    };
    w.last = t.start;
    for (std::size_t k = t.split; k < t.todo.size(); ++k)
      if (!insert(t.todo[k])) return false;
    w.last = t.start;
    for (std::size_t k = t.split; k-- > 0;)
      if (!insert(t.todo[k])) return false;
    return true;
  }

  // Point p into region r on thread i, from `pool`, or put off into `deferred`. False when
  // the run stops: an error, or the progress callback threw. The walk, the cavity and their
  // predicates all in line (flatten): with the class made twice (kLattice), the compiler
  // otherwise left the predicates out of line, 2-5 % more instructions on uniform points.
  [[gnu::flatten]] bool try_insert(unsigned i, const Region& r, VertexId p, std::vector<PutOff>& deferred,
                                   SlotPool& pool) {
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
    if (!in_region || !mesh_.walk<kLattice>(w.last, p, own_triangles(r))) [[unlikely]] {
      TriangleId t = w.last;
      if (!in_region || !walk_on(r, t, p)) {
        deferred.push_back({p, t});
        ++w.stats.retries;
        return true;
      }
      w.last = t;
    }
    const TriangleId t = w.last;
    if (const VertexId hit = mesh_.coincident(t, p); hit != kNoVertex) {
      w.duplicates.push_back({p, hit});
      ++w.done;
      return true;
    }
    if (!mesh_.find_cavity<kLattice>(t, p, w.scratch, [&](Link l) { return enters(r, l); })) {
      deferred.push_back({p, t});
      ++w.stats.retries;
      return true;
    }
    if (pool.size() < 2) throw std::logic_error("ridt: a partition thread ran out of slots");
    w.last = mesh_.fill_cavity(p, w.scratch, pool);
    ++w.stats.points;
    ++w.done;
    return true;
  }

  // The walk from t to p across edges with a vertex in region r, to a triangle of r: whether
  // it got there (out of line: the common path has no use for it).
  [[gnu::noinline]] bool walk_on(const Region& r, TriangleId& t, VertexId p) const {
    return mesh_.walk<kLattice>(t, p, own_edges(r)) && owns(r, t);
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
  void release(TriangleId first, TriangleId end) {
    for (TriangleId t = first; t < end; ++t) {
      mesh_.free_slot(t);
      free_.push_back(t);
    }
  }

  // The points of `list` by the calling thread, in order, with no regions.
  void insert_alone(const std::vector<PutOff>& list) {
    Worker& w = workers_[0];
    SlotPool pool;
    pool.list = free_.data();
    pool.listed = std::min(free_.size(), 2 * list.size());
    const std::size_t listed = pool.listed;
    const std::size_t grown = 2 * list.size() - pool.listed;
    pool.next = mesh_.grow(static_cast<TriangleId>(grown));
    pool.end = pool.next + static_cast<TriangleId>(grown);
    for (const auto [p, near] : list) {
      progress_(done_++);
      last_ = nearer(last_, {p, live(near) ? near : kNoTriangle});
      if (const VertexId hit = mesh_.insert<kLattice>(p, last_, w.scratch, pool); hit != kNoVertex)
        w.duplicates.push_back({p, hit});
      else
        ++w.stats.points;
    }
    // The pool takes its listed slots from the back: those it left, at the front of its part
    // of the list, stay free, and its range is given back.
    free_.erase(free_.begin() + static_cast<std::ptrdiff_t>(pool.listed),
                free_.begin() + static_cast<std::ptrdiff_t>(listed));
    pool.listed = 0;
    mesh_.give_back(pool);
  }

  Mesh& mesh_;
  const std::uint32_t* key_;  // n: the bounding vertices have none
  VertexId n_;
  unsigned threads_;
  std::vector<Worker> workers_;
  std::vector<Clock::time_point> pass_end_ = std::vector<Clock::time_point>(threads_);
  std::vector<Task> tasks_;  // the second pass's regions
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

}  // namespace

void insert_partition(Mesh& mesh, const Insertion& run) {
  const std::uint32_t* key = run.keys;
  const unsigned threads = run.threads;
  std::vector<DuplicateHit>& duplicates = run.duplicates;
  Stats& stats = run.stats;
  Progress& progress = run.progress;
  if (mesh.vertices().lattice())
    Partition<true>(mesh, key, std::max(threads, 1u), duplicates, stats, progress).run();
  else
    Partition<false>(mesh, key, std::max(threads, 1u), duplicates, stats, progress).run();
}

}  // namespace ridt::detail
