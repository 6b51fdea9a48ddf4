// The pessimistic method: the paper's Fig. 10 ("Pessimistic Threaded Delaunay Triangulation
// by Randomized Incremental Insertion", section 3).
//
// The master has made the random permutation (vertex v is the v-th point of it); the workers
// insert it into the one shared triangulation, each taking chunks of 256 consecutive points
// from a shared counter (the paper gives each thread a fixed subset; chunks taken on demand
// keep a thread on a busier core from holding the others up). A worker descends the DAG
// without the lock; the rest of location, the split and the legalization run inside one
// critical section, so only one thread ever changes the triangulation. Before each round the workers
// locate its points together (methods/round_driver.hpp, dag/rounds.hpp), so a descent during insertion starts
// from a leaf of the round's beginning.
//
// Why the descent needs no lock: the records a descent reads (vertices, the split point or
// separating edge of an internal node, the child link) are all written before the child link
// that leads to them is published with a release store, and never change after it; the
// descent reads the link with an acquire load. Records are never moved (dag/records.hpp).
//
// Two variants: the paper's stops the unlocked descent at the parent of a leaf and finishes
// it inside the lock (Experiment::paper_locking); the default goes to a leaf outside the lock
// and, inside, continues only if that leaf has been split since.
#include <mutex>

#include "dag/lookahead.hpp"
#include "methods/method.hpp"
#include "methods/round_driver.hpp"

namespace ridt::detail {
namespace {

using Worker = WorkerState<Scratch>;

// Point p, whose descent may start at node (its parent on the path given, or node itself).
template <bool kTimed>
void insert_point(Kernel& kernel, SpinLock& lock, VertexId p, TriangleId node, TriangleId parent, bool paper,
                  Worker& out) {
  // Unlocked: down to a leaf; the paper's variant then backs up to the leaf's parent and
  // leaves the last step of location to the critical section.
  for (TriangleId next; (next = kernel.step(node, p)) != node;) parent = node, node = next;
  const TriangleId start = paper ? parent : node;
  kernel.prefetch_around(node);  // its neighbours arrive while we wait for the lock
  std::uint64_t t0 = 0, t1 = 0;
  if constexpr (kTimed) t0 = ticks();
  {
    const std::lock_guard<SpinLock> guard(lock);  // the one critical section of Fig. 10
    if constexpr (kTimed) t1 = ticks();
    const TriangleId leaf = kernel.descend(start, p);
    const VertexId hit = kernel.insert_at(kernel.classify(leaf, p), p, out.scratch);
    if (hit != kNoVertex) out.duplicates.push_back({p, hit});
    if constexpr (kTimed) out.critical_ticks += ticks() - t1;
  }
  if constexpr (kTimed) out.wait_ticks += t1 - t0;
}

// The points [first, end), a chunk of a round; hint[v - first] holds point v, or hint is null
// and every descent starts at the root with no look-ahead (Locate::Root).
template <bool kTimed>
void insert_chunk(Kernel& kernel, SpinLock& lock, VertexId first, VertexId end, bool ring, const TriangleId* hint,
                  bool paper, Worker& out) {
  if (hint == nullptr) {
    for (VertexId p = first; p < end; ++p)
      insert_point<kTimed>(kernel, lock, p, Kernel::kRoot, Kernel::kRoot, paper, out);
  } else {
    LookAhead ahead(kernel, first, end, ring, hint);
    for (VertexId i = 0; i < ahead.count(); ++i) {
      const LookAhead::Hint h = ahead.take(i);
      insert_point<kTimed>(kernel, lock, ahead.point(i), h.node, h.parent, paper, out);
    }
  }
  out.stats.points += end - first;
}

}  // namespace

void insert_pessimistic(Kernel& kernel, const Insertion& run) {
  const unsigned threads = run.threads;
  const bool from_root = run.from_root, paper = run.experiment.paper_locking, timed = run.experiment.time_threads;
  Progress& progress = run.progress;
  SpinLock lock;
  std::vector<Worker> workers(threads);
  std::vector<Clock::duration> barrier_wait;
  const auto t_start = Clock::now();
  const TickRate rate;
  run_in_rounds(kernel, threads, from_root, barrier_wait, progress,
                [&](unsigned w, VertexId first, VertexId end, const TriangleId* hint) {
                  // The ring pays on one thread; with several it pulls in lines that the lock
                  // holder may be writing.
                  const bool ring = threads == 1;
                  if (timed)
                    insert_chunk<true>(kernel, lock, first, end, ring, hint, paper, workers[w]);
                  else
                    insert_chunk<false>(kernel, lock, first, end, ring, hint, paper, workers[w]);
                });
  const double total = seconds(Clock::now() - t_start);
  const double tick = rate.seconds_per_tick();
  // Waiting: for the lock, and at the ends of rounds for the others.
  for (unsigned w = 0; w < threads; ++w)
    add_worker(workers[w], tick, timed ? seconds(barrier_wait[w]) : 0.0, total, run.duplicates, run.stats);
}

}  // namespace ridt::detail
