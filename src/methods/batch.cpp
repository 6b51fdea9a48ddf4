// The batch method: the paper's third way (section 3, "3. Batch method"). L locator threads
// only locate: they descend the DAG and queue (point, node reached). One modifier thread takes
// the queue in order, finishes each location from its node (the node may have been split
// since: a stale hint), splits and legalizes. Only the modifier changes the triangulation, so nothing
// is locked; the locators read only what was published (dag/records.hpp), as the pessimistic workers
// do outside their lock.
//
// The queue is a ring of kCapacity slots indexed by position in the random order, so the
// modifier inserts in the paper's order. Locators claim blocks of kBlock positions and start
// a block only when all of it fits in the ring (else they stall: the queue is full). The
// locator that holds the modifier's next position can then always go on: no deadlock. Within
// a block a locator descends along the Hilbert curve (dag/rounds.hpp), so consecutive descents
// share the upper part of their paths.
//
// One thread has no locator: it locates and modifies, the serial method.
#include <algorithm>
#include <memory>
#include <numeric>

#include "dag/rounds.hpp"
#include "methods/method.hpp"
#include "methods/round_driver.hpp"
#include "order/order.hpp"

namespace ridt::detail {
namespace {

constexpr VertexId kCapacity = VertexId{1} << 16;  // queue slots: 512 KiB, in L2 with room
constexpr VertexId kBlock = VertexId{1} << 12;  // positions a locator claims at a time
static_assert(kBlock <= kCapacity / 4, "blocks must fit the ring several times over");

struct Slot {
  std::atomic<VertexId> filled{0};  // position + 1 once `node` holds its hint
  TriangleId node = 0;
};

struct Queue {
  std::unique_ptr<Slot[]> slots{new Slot[kCapacity]};
  alignas(64) std::atomic<VertexId> consumed{0};  // the modifier's next position
  alignas(64) std::atomic<VertexId> claimed{0};  // the next block to claim
  alignas(64) std::atomic<std::uint64_t> published{0};  // hints queued so far
  alignas(64) std::atomic<bool> stop{false};  // a thread failed
};

struct alignas(64) Locator {
  ThreadStats stats;
  Clock::duration stalled{};
  std::exception_ptr error;
};

// Spins, then yields: on an oversubscribed machine the thread waited for needs the core.
template <class Ready>
void wait_until(Ready&& ready, const std::atomic<bool>& stop) {
  for (int spins = 0; !ready(); ++spins) {
    if (stop.load(std::memory_order_relaxed)) return;
    if (spins < 256) {
      cpu_relax();
    } else {
      std::this_thread::yield();
    }
  }
}

// `key` empty: each point descends from the root on its own, in the random order (the paper's
// location, Locate::Root).
void locate(const Kernel& kernel, const std::vector<std::uint32_t>& key, Queue& q, Locator& me) {
  const VertexId n = kernel.n();
  std::vector<VertexId> along;
  const auto t_start = Clock::now();
  for (;;) {
    const VertexId begin = q.claimed.fetch_add(kBlock, std::memory_order_relaxed);
    if (begin >= n || q.stop.load(std::memory_order_relaxed)) break;
    const VertexId end = std::min<std::uint64_t>(n, std::uint64_t{begin} + kBlock);
    // acquire: pairs with the modifier's release, so its last reads of the slots we are about
    // to reuse happen before our writes.
    auto fits = [&] { return end - q.consumed.load(std::memory_order_acquire) <= kCapacity; };
    if (!fits()) {
      const auto t0 = Clock::now();
      wait_until(fits, q.stop);
      me.stalled += Clock::now() - t0;
    }
    auto publish = [&](VertexId v, TriangleId leaf) {
      Slot& slot = q.slots[v % kCapacity];
      slot.node = leaf;
      slot.filled.store(v + 1, std::memory_order_release);  // release: `node` is written first
    };
    if (key.empty()) {
      for (VertexId v = begin; v < end; ++v) publish(v, kernel.descend(Kernel::kRoot, v));
    } else {
      along.resize(end - begin);
      std::iota(along.begin(), along.end(), begin);
      hilbert_sort(&kernel.point(0), key.data(), along.data(), end - begin);
      descend_along(kernel, along.data(), end - begin, publish);
    }
    q.published.fetch_add(end - begin, std::memory_order_relaxed);
    me.stats.points += end - begin;
  }
  me.stats.time_insert_s = seconds(Clock::now() - t_start);
  me.stats.time_wait_s = seconds(me.stalled);
}

// What the modifier counts: its waits for hints, the hints queued ahead of it, the stale ones.
struct Tally {
  Clock::duration idle{};
  std::uint64_t depth_sum = 0, stale = 0;
};

// The modifier: takes the queue's hints in order, finishes each location from its hint and
// inserts, prefetching what the coming insertions read. Stops early when a locator failed.
void modify(Kernel& kernel, Queue& q, const Insertion& run, WorkerState<Scratch>& modifier, Tally& tally) {
  const VertexId n = kernel.n();
  // Prefetch distances, in positions: a hint's record, then what the insertion into it reads
  // (its neighbours and vertices), then the ring beyond (as LookAhead does).
  constexpr VertexId kRecord = 12, kAround = 8, kRing = 4;
  auto ready = [&](VertexId p) -> const Slot* {
    if (p >= n) return nullptr;
    const Slot& s = q.slots[p % kCapacity];
    return s.filled.load(std::memory_order_acquire) == p + 1 ? &s : nullptr;
  };
  for (VertexId p = 0; p < n; ++p) {
    run.progress(p);
    const Slot* s = ready(p);
    if (s == nullptr) {
      const auto t0 = Clock::now();
      wait_until([&] { return (s = ready(p)) != nullptr; }, q.stop);
      tally.idle += Clock::now() - t0;
      if (s == nullptr) return;  // a locator failed
    }
    const TriangleId hint = s->node;
    // release: our read of the slot happens before a locator refills it.
    q.consumed.store(p + 1, std::memory_order_release);
    // Hints queued beyond this one (counted per finished block, so at times behind).
    const std::uint64_t queued = q.published.load(std::memory_order_relaxed);
    tally.depth_sum += queued > p + 1 ? queued - p - 1 : 0;
    if (const Slot* a = ready(p + kRecord)) kernel.prefetch(a->node);
    if (const Slot* a = ready(p + kAround)) kernel.prefetch_around(a->node);
    if (const Slot* a = ready(p + kRing)) kernel.prefetch_ring(a->node);
    tally.stale += !is_leaf(kernel.triangles()[hint].load_child());
    const TriangleId leaf = kernel.descend(hint, p);
    const VertexId hit = kernel.insert_at(kernel.classify(leaf, p), p, modifier.scratch);
    if (hit != kNoVertex) modifier.duplicates.push_back({p, hit});
    ++modifier.stats.points;
  }
}

// The run's batch statistics: the modifier waits for hints (idle), the locators for room in
// the queue (stalls).
void add_stats(WorkerState<Scratch>& modifier, std::vector<Locator>& locators, const Tally& tally, double total,
               VertexId n, const Insertion& run) {
  Stats& stats = run.stats;
  modifier.stats.time_wait_s = stats.time_idle_s = seconds(tally.idle);
  add_worker(modifier, 0.0, 0.0, total, run.duplicates, stats);
  stats.stale_hints = tally.stale;
  stats.queue_depth_mean = n > 0 ? static_cast<double>(tally.depth_sum) / n : 0.0;
  for (Locator& l : locators) {
    l.stats.role = "locator";
    stats.time_stall_s += l.stats.time_wait_s;
    stats.time_wait_s += l.stats.time_wait_s;
    stats.per_thread.push_back(l.stats);
  }
}

}  // namespace

void insert_batch(Kernel& kernel, const Insertion& run) {
  if (run.threads == 1) {
    const auto t_start = Clock::now();
    insert_serial(kernel, run);
    run.stats.per_thread.push_back({"modifier", kernel.n(), seconds(Clock::now() - t_start), 0, 0, 0});
    return;
  }
  const VertexId n = kernel.n();
  const std::vector<std::uint32_t> key =
      run.from_root ? std::vector<std::uint32_t>{} : hilbert_keys(&kernel.point(0), n);
  Queue q;
  std::vector<Locator> locators(run.threads - 1);
  WorkerState<Scratch> modifier;
  modifier.stats.role = "modifier";
  Tally tally;
  const auto t_start = Clock::now();
  {
    std::vector<std::jthread> pool;
    for (Locator& l : locators)
      pool.emplace_back([&] {
        try {
          locate(kernel, key, q, l);
        } catch (...) {
          l.error = std::current_exception();
          q.stop.store(true, std::memory_order_relaxed);
        }
      });
    try {
      modify(kernel, q, run, modifier, tally);
    } catch (...) {
      q.stop.store(true, std::memory_order_relaxed);
      throw;  // the pool's threads see `stop` and end; their destructors join them
    }
  }
  for (const Locator& l : locators)
    if (l.error) std::rethrow_exception(l.error);
  add_stats(modifier, locators, tally, seconds(Clock::now() - t_start), n, run);
}

}  // namespace ridt::detail
