// The partition method: threads insert into one walking mesh (cavity.hpp) without a lock and
// without a history DAG.
//
// The points come in the BRIO order, each round along a Hilbert curve, with the curve's key
// of each vertex. A large round is cut into one stretch of the curve a thread; the cut keys
// split the plane into regions, and every vertex (old or new) belongs to the thread whose
// region holds it. A thread inserts a point of its stretch only when every triangle its walk
// enters and every triangle of its cavity has all three vertices in its region; else it puts
// the point off. Then:
//
//   - a triangle a thread changes has all its vertices in the thread's region, and the new
//     ones too (the point and the cavity's boundary edges), so no two threads write one
//     triangle, and a slot a thread writes holds its own triangles all through the pass;
//   - a neighbour of such a triangle shares two of its vertices, so it is the same thread's
//     or holds vertices of two regions: such mixed triangles no thread changes during the
//     pass, and reading them, to test them, races with nothing;
//   - the links a thread rewrites are those of edges with both ends in its region, which only
//     it reads.
//
// So the threads share the mesh with plain loads and stores, and the passes are ordered by
// the joins between them. The points put off are inserted in a second pass whose cuts lie in
// the middle of the first pass's stretches, and what is left after it by one thread. Small
// rounds are inserted by one thread: their mesh is small and their cavities reach the
// bounding vertices, which belong to no thread.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>

#include "cavity.hpp"
#include "driver.hpp"
#include "order.hpp"

namespace ridt::detail {
namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// A thread's region: the vertices whose keys lie in [lo, lo + len) round the circle of 32-bit
// keys (the regions of a pass tile the circle); the bounding vertices are in none.
struct Range {
  std::uint32_t lo = 0;
  std::uint64_t len = 0;  // up to 2^32: the whole circle
  bool holds(std::uint32_t key) const { return static_cast<std::uint32_t>(key - lo) < len; }
};
// A round is cut among the threads when each thread gets at least this many points.
constexpr VertexId kMinStretch = 1024;
// Tries to find a thread's first triangle among its first points before the pass.
constexpr std::size_t kStartTries = 64;

class Partition {
 public:
  Partition(Mesh& mesh, const std::uint32_t* key, unsigned threads, std::vector<DuplicateHit>& duplicates,
            Stats& stats, Progress& progress)
      : mesh_(mesh), key_(key), n_(mesh.vertices().n()), threads_(threads), workers_(threads),
        duplicates_(duplicates), stats_(stats), progress_(progress) {}

  void run() {
    const VertexId n = mesh_.vertices().n();
    const auto t0 = Clock::now();
    for (VertexId b = 0; b < n; b = round_end(b)) {
      const VertexId e = std::min(round_end(b), n);
      if (e - b < kMinStretch * threads_) {
        std::vector<VertexId> all(e - b);
        for (VertexId p = b; p < e; ++p) all[p - b] = p;
        insert_alone(all);
      } else {
        insert_round(b, e);
      }
    }
    const double total = seconds(Clock::now() - t0);
    for (const Worker& w : workers_) add_worker(w, 0.0, 0.0, total, duplicates_, stats_);
  }

 private:
  // A thread's state, and its stretch of the round: stats.retries counts the points it put off.
  struct Worker : WorkerState<CavityScratch> {
    std::vector<VertexId> todo, deferred;
    SlotPool pool;
    TriangleId last = 0;
    Range range;            // its region
    TriangleId start = 0;   // the triangle it starts from, in its region
    std::size_t split = 0;  // todo[split] is the first point it inserts
  };

  // Whether triangle t has all three vertices in region r (tested together, without a branch
  // between them: the answers are hard to predict).
  bool owns(const Range& r, TriangleId t) const {
    const VertexId a = mesh_.vertex(t, 0), b = mesh_.vertex(t, 1), c = mesh_.vertex(t, 2);
    return (std::max(a, std::max(b, c)) < n_) & r.holds(key_[a]) & r.holds(key_[b]) & r.holds(key_[c]);
  }

  // Whether region r's triangles reachable from t through the region number some dozens: a
  // thread that starts in a small pocket of its region cut off by the border would put off
  // every point.
  bool deep_in(const Range& r, TriangleId t) {
    if (!owns(r, t)) return false;
    constexpr std::size_t kEnough = 48;
    std::vector<TriangleId>& seen = seen_;
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

  // One round of points [b, e), in curve order: two passes on all threads, then one thread.
  void insert_round(VertexId b, VertexId e) {
    const VertexId m = e - b;
    // Pass 1: equal stretches of the round, cut where the key changes (points of one key lie
    // in one region).
    std::vector<VertexId> cut(threads_ + 1);
    cut[0] = b, cut[threads_] = e;
    for (unsigned i = 1; i < threads_; ++i) {
      VertexId c = std::max(cut[i - 1], b + static_cast<VertexId>(std::uint64_t{m} * i / threads_));
      while (c > b && c < e && key_[c] == key_[c - 1]) ++c;
      cut[i] = c;
    }
    std::vector<std::uint32_t> from(threads_);  // the smallest key of each region
    from[0] = 0;
    for (unsigned i = 1; i < threads_; ++i) from[i] = cut[i] < e ? key_[cut[i]] : 0xffffffffu;
    set_regions(from);
    for (unsigned i = 0; i < threads_; ++i) {
      Worker& w = workers_[i];
      w.todo.clear();
      for (VertexId p = cut[i]; p < cut[i + 1]; ++p) w.todo.push_back(p);
    }
    run_pass();
    // Pass 2: the points put off lie along the cuts; new cuts in the middle of the old
    // stretches put each old cut inside a region. The last region wraps round to key 0.
    std::vector<VertexId> left;
    for (Worker& w : workers_) left.insert(left.end(), w.deferred.begin(), w.deferred.end());
    if (left.size() >= 64 * threads_) {
      for (unsigned i = 0; i < threads_; ++i)  // an empty stretch at the end has its cut at e
        from[i] = key_[std::min(cut[i] + (cut[i + 1] - cut[i]) / 2, e - 1)];
      set_regions(from);
      for (Worker& w : workers_) w.todo.clear();
      for (const VertexId p : left) {
        // The last region whose first key is at most p's, or the last of all (which wraps round).
        const auto above = std::upper_bound(from.begin(), from.end(), key_[p]) - from.begin();
        workers_[above > 0 ? above - 1 : threads_ - 1].todo.push_back(p);
      }
      run_pass();
      left.clear();
      for (Worker& w : workers_) left.insert(left.end(), w.deferred.begin(), w.deferred.end());
    }
    insert_alone(left);
  }

  // Region i from key from[i] up to from[i + 1]; the last one from from[threads - 1] round the
  // circle to from[0] (the end of the keys when from[0] is 0). `from` never decreases.
  void set_regions(const std::vector<std::uint32_t>& from) {
    for (unsigned i = 0; i < threads_; ++i) {
      Range& r = workers_[i].range;
      r.lo = from[i];
      r.len = i + 1 < threads_ ? std::uint64_t{from[i + 1]} - from[i] : (std::uint64_t{1} << 32) - (from[i] - from[0]);
    }
  }

  // Each thread inserts its `todo` list into its region, putting off what it cannot.
  void run_pass() {
    // Before the threads start, with the mesh at rest: where in its list each thread starts
    // (from the middle: the ends of a stretch lie on the region's border), and from which
    // triangle; then slots enough for all its points, the free ones first.
    std::size_t taken = 0;
    for (unsigned i = 0; i < threads_; ++i) {
      Worker& w = workers_[i];
      w.deferred.clear();
      w.split = w.todo.size();  // none found: every point is put off
      for (std::size_t k = 0; k < std::min(w.todo.size(), kStartTries); ++k) {
        const std::size_t c = (w.todo.size() / 2 + k) % w.todo.size();
        last_ = mesh_.walk(last_, w.todo[c]);
        if (deep_in(w.range, last_)) {
          w.start = last_;
          w.split = c;
          break;
        }
      }
      if (w.split == w.todo.size()) {
        w.deferred = std::move(w.todo);
        w.todo.clear();
        w.split = 0;
      }
      const std::size_t need = 2 * w.todo.size();
      const std::size_t listed = std::min(need, free_.size() - taken);
      w.pool.list = free_.data() + taken;
      w.pool.listed = listed;
      taken += listed;
      w.pool.next = mesh_.grow(static_cast<TriangleId>(need - listed));
      w.pool.end = w.pool.next + static_cast<TriangleId>(need - listed);
    }
    std::atomic<bool> stop{false};
    std::atomic<std::uint64_t> inserted{0};
    std::exception_ptr failure;
    std::mutex failure_lock;
    const std::uint64_t before = done_;
    auto work = [&](unsigned i) {
      try {
        insert_owned(i, stop, inserted, before);
      } catch (...) {
        const std::lock_guard<std::mutex> guard(failure_lock);
        if (!failure) failure = std::current_exception();
        stop.store(true, std::memory_order_relaxed);
      }
    };
    {
      std::vector<std::jthread> pool;
      for (unsigned i = 1; i < threads_; ++i) pool.emplace_back(work, i);
      work(0);
    }
    if (failure) std::rethrow_exception(failure);
    const Clock::time_point end = *std::max_element(pass_end_.begin(), pass_end_.end());
    for (unsigned i = 0; i < threads_; ++i) workers_[i].stats.time_wait_s += seconds(end - pass_end_[i]);
    // What the pools did not hand out is free now; the free slots they took are used.
    std::vector<TriangleId> unused;
    for (Worker& w : workers_) {
      unused.insert(unused.end(), w.pool.list, w.pool.list + w.pool.listed);
      for (; w.pool.next < w.pool.end; ++w.pool.next) {
        mesh_.free_slot(w.pool.next);
        unused.push_back(w.pool.next);
      }
      w.pool.listed = 0;
      if (w.stats.points > 0) last_ = w.last;
    }
    unused.insert(unused.end(), free_.begin() + static_cast<std::ptrdiff_t>(taken), free_.end());
    free_ = std::move(unused);
    done_ = before + inserted.load(std::memory_order_relaxed);
  }

  void insert_owned(unsigned i, std::atomic<bool>& stop, std::atomic<std::uint64_t>& inserted,
                    std::uint64_t before) {
    Worker& w = workers_[i];
    const Range r = w.range;
    auto mine = [&](TriangleId t) { return owns(r, t); };
    std::uint64_t done = 0;  // inserted or found equal to a vertex, not yet counted in `inserted`
    // From todo[split] to the end, then from the start again back to todo[0].
    w.last = w.start;
    for (std::size_t k = 0; k < w.todo.size(); ++k) {
      if (k == w.todo.size() - w.split) w.last = w.start;
      const VertexId p = k < w.todo.size() - w.split ? w.todo[w.split + k] : w.todo[w.todo.size() - 1 - k];
      if ((k & 1023) == 1023) {
        inserted.fetch_add(std::exchange(done, 0), std::memory_order_relaxed);
        if (stop.load(std::memory_order_relaxed)) break;
        if (i == 0) progress_(before + inserted.load(std::memory_order_relaxed));
      }
      // A point put off leaves the next walk to start where this one stopped, in the region
      // and nearer the points to come than the last insertion.
      if (!r.holds(key_[p]) || !mesh_.walk(w.last, p, mine)) {
        w.deferred.push_back(p);
        ++w.stats.retries;
        continue;
      }
      const TriangleId t = w.last;
      if (const VertexId hit = mesh_.coincident(t, p); hit != kNoVertex) {
        w.duplicates.push_back({p, hit});
        ++done;
        continue;
      }
      if (!mesh_.find_cavity(t, p, w.scratch, mine)) {
        w.deferred.push_back(p);
        ++w.stats.retries;
        continue;
      }
      w.last = mesh_.fill_cavity(p, w.scratch, w.pool);
      ++w.stats.points;
      ++done;
    }
    inserted.fetch_add(done, std::memory_order_relaxed);
    pass_end_[i] = Clock::now();  // the wait for the others, from here to the last one's end
  }

  // The points of `list` by the calling thread, in order, with no regions.
  void insert_alone(const std::vector<VertexId>& list) {
    Worker& w = workers_[0];
    SlotPool pool;
    pool.list = free_.data();
    pool.listed = std::min(free_.size(), 2 * list.size());
    const std::size_t listed = pool.listed;
    const std::size_t grown = 2 * list.size() - pool.listed;
    pool.next = mesh_.grow(static_cast<TriangleId>(grown));
    pool.end = pool.next + static_cast<TriangleId>(grown);
    for (const VertexId p : list) {
      progress_(done_++);
      if (const VertexId hit = mesh_.insert(p, last_, w.scratch, pool); hit != kNoVertex)
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
  const std::uint32_t* key_;  // n + 3: the bounding vertices' are never read as keys
  VertexId n_;
  unsigned threads_;
  std::vector<Worker> workers_;
  std::vector<Clock::time_point> pass_end_ = std::vector<Clock::time_point>(threads_);
  std::vector<TriangleId> free_;  // free slots below the top
  std::vector<TriangleId> seen_;  // deep_in's search
  TriangleId last_ = 0;           // a triangle, where the next walk of the calling thread starts
  std::uint64_t done_ = 0;        // points inserted or found equal to a vertex
  std::vector<DuplicateHit>& duplicates_;
  Stats& stats_;
  Progress& progress_;
};

}  // namespace

void insert_partition(Mesh& mesh, const std::uint32_t* key, unsigned threads,
                      std::vector<DuplicateHit>& duplicates, Stats& stats, Progress& progress) {
  Partition(mesh, key, std::max(threads, 1u), duplicates, stats, progress).run();
}

}  // namespace ridt::detail
