// The driver that takes the threaded DAG methods' workers through the rounds of dag/rounds.hpp
// (their locks, back-off and clock: runtime/sync.hpp).
#pragma once

#include <algorithm>
#include <atomic>
#include <barrier>
#include <chrono>
#include <cstdint>
#include <exception>
#include <optional>
#include <thread>
#include <vector>

#include "dag/kernel.hpp"
#include "dag/rounds.hpp"
#include "methods/method.hpp"
#include "runtime/parallel.hpp"
#include "runtime/sync.hpp"

namespace ridt::detail {

/// The rounds of run_in_rounds and the counters that hand out their work in chunks. From the
/// root (Locate::Root): one round of all the points, no location phase, no hints.
class RoundSchedule {
 public:
  RoundSchedule(const Kernel& kernel, unsigned threads, bool from_root)
      : kernel_(kernel), threads_(threads), from_root_(from_root) {
    if (!from_root) rounds_.emplace(kernel, threads);
    count_ = from_root ? 1 : rounds_->rounds();
    hint_.resize(from_root ? 0 : rounds_->largest());
    located_ = std::vector<std::atomic<VertexId>>(count_);
    inserted_ = std::vector<std::atomic<VertexId>>(count_);
    for (std::size_t r = 0; r < count_; ++r) {
      located_[r].store(first(r), std::memory_order_relaxed);
      inserted_[r].store(first(r), std::memory_order_relaxed);
    }
  }

  std::size_t count() const { return count_; }
  bool locates() const { return !from_root_; }
  VertexId first(std::size_t r) const { return from_root_ ? (r == 0 ? 0 : kernel_.n()) : rounds_->first(r); }

  /// Locates chunks of round r's points along the curve until none is left or `stop`.
  /// Chunks: enough of them that the workers finish together, each still long enough for the
  /// lanes of the descent to get going.
  void locate(std::size_t r, const std::atomic<bool>& stop) {
    const VertexId begin = first(r), end = first(r + 1);
    const VertexId chunk = std::clamp<VertexId>((end - begin) / (8 * threads_), 256, 4096);
    for (VertexId b;
         !stop.load(std::memory_order_relaxed) && (b = located_[r].fetch_add(chunk, std::memory_order_relaxed)) < end;)
      rounds_->locate(r, b - begin, std::min<std::uint64_t>(end, std::uint64_t{b} + chunk) - begin, hint_.data());
  }

  /// Calls insert(b, e, hint) for chunks [b, e) of round r until none is left or `stop`; hint
  /// is null from the root.
  template <class Insert>
  void insert(std::size_t r, const std::atomic<bool>& stop, Insert&& insert) {
    constexpr VertexId kChunk = 256;  // long enough for the look-ahead of the insertion
    const VertexId begin = first(r), end = first(r + 1);
    for (VertexId b; !stop.load(std::memory_order_relaxed) &&
         (b = inserted_[r].fetch_add(kChunk, std::memory_order_relaxed)) < end;)
      insert(b, static_cast<VertexId>(std::min<std::uint64_t>(end, std::uint64_t{b} + kChunk)),
             from_root_ ? nullptr : hint_.data() + (b - begin));
  }

 private:
  const Kernel& kernel_;
  unsigned threads_;
  bool from_root_;
  std::optional<RoundLocator> rounds_;
  std::size_t count_ = 1;
  std::vector<TriangleId> hint_;
  // Per round, the next position to locate (along the curve) and to insert (in the order).
  std::vector<std::atomic<VertexId>> located_, inserted_;
};

/// Runs `threads` workers through the rounds: in each round the workers first locate the
/// round's points along the curve (the DAG is only read then; dag/rounds.hpp), all wait, then
/// they insert the round's points [first, end) in the random order; all wait again. Work is
/// handed out in chunks from a counter, so a worker on a faster (or less shared) core takes
/// more of it and nobody waits long at the end of a round: insert_chunk(w, begin, end, hint)
/// inserts the points [begin, end), hint[v - begin] being a leaf that held point v when the
/// round began. `from_root`: no rounds and no location phase, one pass over all the points with
/// hint null (each descent starts at the root, Locate::Root). Worker 0 is the calling thread,
/// and reports `progress` after its chunks. `wait[w]` receives the time worker w spent waiting
/// for the others. The first exception of any worker is rethrown once all have
/// stopped; the others stop at the next phase.
template <class InsertChunk>
void run_in_rounds(const Kernel& kernel, unsigned threads, bool from_root, std::vector<Clock::duration>& wait,
                   Progress& progress, InsertChunk&& insert_chunk) {
  RoundSchedule schedule(kernel, threads, from_root);
  std::barrier<> sync(static_cast<std::ptrdiff_t>(threads));
  std::atomic<bool> stop{false};
  std::vector<std::exception_ptr> errors(threads);
  wait.assign(threads, Clock::duration{});
  auto worker = [&](unsigned w) {
    auto arrive = [&] {
      const auto t0 = Clock::now();
      sync.arrive_and_wait();
      wait[w] += Clock::now() - t0;
    };
    try {
      // The first report says the insertion has begun (0), as the serial method's does: worker
      // 0 reports only after its own chunks, and the other workers may take all of the early,
      // small rounds.
      if (w == 0) progress(0);
      for (std::size_t r = 0; r < schedule.count(); ++r) {
        if (schedule.locates()) {
          schedule.locate(r, stop);
          arrive();
        }
        schedule.insert(r, stop, [&](VertexId b, VertexId e, const TriangleId* hint) {
          insert_chunk(w, b, e, hint);
          if (w == 0) progress(e);
        });
        arrive();
      }
    } catch (...) {
      // Thrown inside a phase, before this worker arrived: leaving the barrier lets the
      // others finish their rounds without it.
      errors[w] = std::current_exception();
      stop.store(true, std::memory_order_relaxed);
      sync.arrive_and_drop();
    }
  };
  {
    std::vector<std::jthread> pool;
    pool.reserve(threads - 1);
    for (unsigned w = 1; w < threads; ++w) pool.emplace_back(worker, w);
    worker(0);
  }
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace ridt::detail
