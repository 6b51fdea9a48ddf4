// The optimistic method: the paper's proposal (section 3, "2. Optimistic method"): no global
// lock; only the triangles an insertion changes are locked, each by its own one-word lock.
//
// Ownership (dag/kernel.hpp: try_acquire, release, owns) lives in a leaf's child word, which the
// descent reads anyway. An insertion of p, after a lock-free descent to a leaf t:
//   1. takes t; if t was split meanwhile, descends on from it;
//   2. takes the whole region the insertion will touch before changing anything: the
//      triangles whose circumcircle holds p (the cavity: exactly those that the split and the
//      flips of legalization destroy, for the flip algorithm and Bowyer-Watson build the same
//      triangulation) and the triangles across the cavity's boundary, whose neighbour links
//      change;
//   3. splits and legalizes with the serial kernel, which checks before every write that the
//      thread owns what it writes (Kernel::require_owned); its new triangles are its own from
//      birth;
//   4. releases everything.
// Every take is a try: on the first failure the insertion releases all it holds and retries
// after a randomized back-off. A thread never waits while holding a triangle, so no deadlock
// can arise and nothing needs detecting; a change is made only once all it needs is held, so
// no other thread ever sees half of one. Geogram's parallel Delaunay (Lévy) works this way.
//
// The points are shared as in the pessimistic method: the rounds of dag/rounds.hpp, located by
// all workers together, then inserted in chunks taken from a shared counter.
#include "dag/lookahead.hpp"
#include "methods/method.hpp"
#include "methods/round_driver.hpp"

namespace ridt::detail {
namespace {

using Worker = WorkerState<Scratch>;

// One worker's insertions, with what it holds in the current attempt.
class alignas(64) Inserter {  // each on its own cache lines
 public:
  Inserter(Kernel& kernel, Worker& w, std::uint64_t seed)
      : kernel_(kernel), w_(w), me_(w.scratch.owner), backoff_(seed) {}

  /// Inserts p, starting the descent at `start` (a node whose region holds p).
  template <bool kTimed>
  void insert(VertexId p, TriangleId start) {
    TriangleId t = start;
    for (;;) {
      t = kernel_.descend(t, p);
      if (!kernel_.try_acquire(t, me_)) {
        // Split since the descent (descend on from it), or owned by another thread.
        if (is_leaf(kernel_.triangles()[t].load_child())) back_off<kTimed>();
        continue;
      }
      std::uint64_t t0 = 0;
      if constexpr (kTimed) t0 = ticks();
      held_.assign(1, t);
      const Kernel::Location where = kernel_.classify(t, p);
      if (where.where == Kernel::Where::OnVertex) {
        w_.duplicates.push_back({p, kernel_.triangles()[t].v[where.i]});
        release_all();
        if constexpr (kTimed) w_.critical_ticks += ticks() - t0;
        return;
      }
      if (!acquire_region(where, p)) {
        release_all();
        if constexpr (kTimed) w_.critical_ticks += ticks() - t0;
        back_off<kTimed>();
        continue;  // t may still be the leaf: the descent then stops at once
      }
      w_.scratch.cavity = &cavity_;
      kernel_.split_at(where, p, w_.scratch);
      kernel_.legalize(p, w_.scratch);
      w_.scratch.cavity = nullptr;
      release_all();
      if constexpr (kTimed) w_.critical_ticks += ticks() - t0;
      backoff_.reset();
      return;
    }
  }

 private:
  // Takes the cavity of p and its boundary (see the top of this file), starting from the
  // held leaf holding p (and, for a point on an edge, the leaf across it). A neighbour of a
  // held triangle is a leaf: changing it would relink the held one, which needs that one.
  bool acquire_region(const Kernel::Location& where, VertexId p) {
    const TriangleStore& tris = kernel_.triangles();
    cavity_.assign(1, where.t);
    if (where.where == Kernel::Where::OnEdge) {
      const TriangleId u = tris[where.t].n[where.i];
      if (!take(u)) return false;
      cavity_.push_back(u);  // p lies on its edge, so inside its circumcircle
    }
    for (std::size_t k = 0; k < cavity_.size(); ++k) {
      const Triangle& r = tris[cavity_[k]];
      // Beyond the first ring, which the look-ahead brought in, the neighbours' records were
      // asked for when r joined (below) and have had the time to arrive: ask for their
      // vertices now, so the three incircle tests below wait for memory once, not in turn.
      if (k > 0)
        for (const TriangleId u : r.n)
          if (u != kNoTriangle) kernel_.prefetch_vertices(u);
      for (const TriangleId u : r.n) {
        // Held already? Before the split the thread owns exactly what it took in this attempt.
        if (u == kNoTriangle || kernel_.owns(u, me_)) continue;
        if (!take(u)) return false;
        const Triangle& ru = tris[u];
        // The same test as legalization, so the region is exactly what it will touch.
        if (kernel_.incircle(ru.v[0], ru.v[1], ru.v[2], p) > 0) {
          cavity_.push_back(u);
          // Its neighbours are taken and tested when its turn comes: ask for their records
          // now, for writing (a compare-and-swap on a line not held exclusive waits for it,
          // and nothing after it starts meanwhile). Without this, at 10^6 uniform points in
          // random order, the cavity walk waited on one miss after the other and one thread ran
          // at 0.89 of serial's speed; with it 0.96 (ridt_bench_threads, docs/threads_1m.txt).
          for (const TriangleId x : ru.n) tris.prefetch</*kForWrite=*/true>(x);
        }
      }
    }
    return true;
  }

  bool take(TriangleId u) {
    if (!kernel_.try_acquire(u, me_)) return false;
    held_.push_back(u);
    return true;
  }

  // Gives back what this attempt took and the triangles it made (a triangle it killed holds
  // its child link and stays as it is).
  void release_all() {
    for (const TriangleId t : held_) kernel_.release(t, me_);
    for (const TriangleId t : w_.scratch.made) kernel_.release(t, me_);
    held_.clear();
    w_.scratch.made.clear();
  }

  template <bool kTimed>
  void back_off() {
    ++w_.stats.retries;
    std::uint64_t t0 = 0;
    if constexpr (kTimed) t0 = ticks();
    backoff_.pause();
    if constexpr (kTimed) w_.wait_ticks += ticks() - t0;
  }

  Kernel& kernel_;
  Worker& w_;
  const std::uint32_t me_;
  std::vector<TriangleId> held_;  // taken in this attempt
  std::vector<TriangleId> cavity_;  // held triangles whose circumcircle holds p
  Backoff backoff_;
};

// The points [first, end), a chunk of a round; hint[v - first] holds point v, or hint is null
// and every descent starts at the root with no look-ahead (Locate::Root).
template <bool kTimed>
void insert_chunk(Kernel& kernel, VertexId first, VertexId end, const TriangleId* hint, Inserter& inserter,
                  Worker& worker) {
  if (hint == nullptr) {
    for (VertexId p = first; p < end; ++p) inserter.insert<kTimed>(p, Kernel::kRoot);
  } else {
    LookAhead ahead(kernel, first, end, /*ring=*/true, hint);
    for (VertexId i = 0; i < ahead.count(); ++i) inserter.insert<kTimed>(ahead.point(i), ahead.take(i).node);
  }
  worker.stats.points += end - first;
}

}  // namespace

void insert_optimistic(Kernel& kernel, const Insertion& run) {
  const unsigned threads = run.threads;
  const bool from_root = run.from_root, timed = run.experiment.time_threads;
  Progress& progress = run.progress;
  std::vector<Worker> workers(threads);
  std::vector<Inserter> inserters;
  inserters.reserve(threads);
  for (unsigned w = 0; w < threads; ++w) {
    workers[w].scratch.owner = w + 1;  // 0 means "free" (dag/records.hpp)
    workers[w].scratch.pooled = true;
    inserters.emplace_back(kernel, workers[w], /*seed=*/w + 1);
  }
  std::vector<Clock::duration> barrier_wait;
  const auto t_start = Clock::now();
  const TickRate rate;
  run_in_rounds(kernel, threads, from_root, barrier_wait, progress,
                [&](unsigned w, VertexId first, VertexId end, const TriangleId* hint) {
                  if (timed)
                    insert_chunk<true>(kernel, first, end, hint, inserters[w], workers[w]);
                  else
                    insert_chunk<false>(kernel, first, end, hint, inserters[w], workers[w]);
                });
  const double total = seconds(Clock::now() - t_start);
  const double tick = rate.seconds_per_tick();
  // Waiting: backing off after a failed take, and at the ends of rounds for the others.
  for (unsigned w = 0; w < threads; ++w) {
    kernel.retire_pool(workers[w].scratch);
    add_worker(workers[w], tick, timed ? seconds(barrier_wait[w]) : 0.0, total, run.duplicates, run.stats);
  }
}

}  // namespace ridt::detail
