// The pessimistic method: the paper's Fig. 10 ("Pessimistic Threaded Delaunay Triangulation
// by Randomized Incremental Insertion", section 3).
//
// The master has made the random permutation (vertex v is the v-th point of it); worker w of T
// inserts the points w, w + T, w + 2T, ... into the one shared triangulation. A worker
// descends the DAG without the lock; the rest of location, the split and the legalization
// run inside one critical section, so only one thread ever changes the mesh.
//
// Why the descent needs no lock: the records a descent reads (vertices, the split point or
// separating edge of an internal node, the child link) are all written before the child link
// that leads to them is published with a release store, and never change after it; the
// descent reads the link with an acquire load. Records are never moved (mesh.hpp).
//
// Two variants: the paper's stops the unlocked descent at the parent of a leaf and finishes
// it inside the lock (Options::paper_locking); the default goes to a leaf outside the lock
// and, inside, continues only if that leaf has been split since.
#include <chrono>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include "driver.hpp"
#include "lookahead.hpp"

namespace ridt::detail {
namespace {

// Tells the core we are spinning (frees resources for the other hardware thread).
inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

// The critical section lasts about a microsecond: a thread that finds the lock taken spins
// (reading, not writing, so the line stays shared) instead of sleeping in the kernel, which
// costs more than the wait. After a while it yields, so oversubscribed runs still progress.
class SpinLock {
 public:
  void lock() {
    for (int spins = 0;; ++spins) {
      // acquire: the holder's changes to the mesh happen before ours.
      if (!locked_.exchange(true, std::memory_order_acquire)) return;
      while (locked_.load(std::memory_order_relaxed)) {
        if (++spins < kSpinsBeforeYield) {
          cpu_relax();
        } else {
          std::this_thread::yield();
          spins = 0;
        }
      }
    }
  }
  // release: our changes to the mesh happen before the next holder's.
  void unlock() { locked_.store(false, std::memory_order_release); }

 private:
  static constexpr int kSpinsBeforeYield = 4096;  // a few microseconds of pause instructions
  alignas(64) std::atomic<bool> locked_{false};   // its own cache line
};

using Clock = std::chrono::steady_clock;

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

struct alignas(64) Worker {  // each on its own cache lines
  Scratch scratch;
  std::vector<DuplicateHit> duplicates;
  ThreadStats stats;
  std::exception_ptr error;  // what stopped it, rethrown by the master
};

template <bool kTimed>
void work(Kernel& kernel, SpinLock& lock, VertexId first, VertexId stride, bool paper,
          const std::atomic<bool>& stop, Worker& out) {
  const auto t_start = Clock::now();
  Clock::duration critical{}, waiting{};
  LookAhead ahead(kernel, first, stride, kernel.n(), /*ring=*/stride == 1);
  for (VertexId i = 0; i < ahead.count(); ++i) {
    if (stop.load(std::memory_order_relaxed)) break;  // another worker failed
    const VertexId p = ahead.point(i);
    const LookAhead::Hint hint = ahead.take(i);
    // Unlocked: down to a leaf; the paper's variant then backs up to the leaf's parent and
    // leaves the last step of location to the critical section.
    TriangleId node = hint.node, parent = hint.parent;
    for (TriangleId next; (next = kernel.step(node, p)) != node;) parent = node, node = next;
    const TriangleId start = paper ? parent : node;
    kernel.prefetch_around(node);  // its neighbours arrive while we wait for the lock
    Clock::time_point t0, t1;
    if constexpr (kTimed) t0 = Clock::now();
    {
      const std::lock_guard<SpinLock> guard(lock);  // the one critical section of Fig. 10
      if constexpr (kTimed) t1 = Clock::now();
      const TriangleId leaf = kernel.descend(start, p);
      const VertexId hit = kernel.insert_at(kernel.classify(leaf, p), p, out.scratch);
      if (hit != kNone) out.duplicates.push_back({p, hit});
      if constexpr (kTimed) critical += Clock::now() - t1;
    }
    if constexpr (kTimed) waiting += t1 - t0;
  }
  out.stats.points = ahead.count();
  out.stats.time_insert_s = seconds(Clock::now() - t_start);
  out.stats.time_critical_s = seconds(critical);
  out.stats.time_wait_s = seconds(waiting);
}

}  // namespace

void insert_pessimistic(Kernel& kernel, unsigned threads, bool paper, bool timed,
                        std::vector<DuplicateHit>& duplicates, Stats& stats) {
  SpinLock lock;
  std::atomic<bool> stop{false};
  std::vector<Worker> workers(threads);
  {
    std::vector<std::jthread> pool;
    pool.reserve(threads);
    for (unsigned w = 0; w < threads; ++w)
      pool.emplace_back([&, w] {
        try {
          if (timed)
            work<true>(kernel, lock, w, threads, paper, stop, workers[w]);
          else
            work<false>(kernel, lock, w, threads, paper, stop, workers[w]);
        } catch (...) {
          workers[w].error = std::current_exception();
          stop.store(true, std::memory_order_relaxed);
        }
      });
  }  // the master waits for every worker (Fig. 10, line 6)
  for (Worker& w : workers)
    if (w.error) std::rethrow_exception(w.error);
  for (Worker& w : workers) {
    duplicates.insert(duplicates.end(), w.duplicates.begin(), w.duplicates.end());
    stats.flips += w.scratch.flips;
    stats.edge_splits += w.scratch.edge_splits;
    stats.time_critical_s += w.stats.time_critical_s;
    stats.time_wait_s += w.stats.time_wait_s;
    stats.per_thread.push_back(w.stats);
  }
}

}  // namespace ridt::detail
