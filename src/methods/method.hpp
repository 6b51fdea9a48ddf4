// What the methods share: what a method is given (Insertion), its entry in the registry,
// each thread's state, the progress reports.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "dag/kernel.hpp"
#include "output/output.hpp"
#include "ridt/ridt.hpp"

namespace ridt::detail {

/// What each thread of a threaded method keeps for itself, on its own cache lines: one type for
/// every method. `KernelScratch` is the kernel's: Scratch on the DAG (dag/kernel.hpp),
/// CavityScratch on the walking kernel (tds/delaunay.hpp).
template <class KernelScratch>
struct alignas(64) WorkerState {
  KernelScratch scratch;
  std::vector<DuplicateHit> duplicates;  ///< the points it found equal to a vertex
  ThreadStats stats;  ///< its counters, and times it measured in seconds
  /// Time in its critical sections and waiting, in ticks (runtime/sync.hpp), when timed.
  std::uint64_t critical_ticks = 0, wait_ticks = 0;
};

/// Adds what one worker did to the run's results: its duplicates, counters and times (the
/// ticks at `tick` seconds each, plus `extra_wait_s`, e.g. at the ends of rounds); `total` is
/// the insertion's wall time.
template <class KernelScratch>
void add_worker(const WorkerState<KernelScratch>& w, double tick, double extra_wait_s, double total,
                std::vector<DuplicateHit>& duplicates, Stats& stats) {
  duplicates.insert(duplicates.end(), w.duplicates.begin(), w.duplicates.end());
  ThreadStats ts = w.stats;
  ts.time_insert_s = total;
  ts.time_critical_s += static_cast<double>(w.critical_ticks) * tick;
  ts.time_wait_s += static_cast<double>(w.wait_ticks) * tick + extra_wait_s;
  stats.time_critical_s += ts.time_critical_s;
  stats.time_wait_s += ts.time_wait_s;
  stats.retries += ts.retries;
  stats.per_thread.push_back(std::move(ts));
  if constexpr (requires { w.scratch.edge_splits; }) {  // the DAG's kernel: flips and edge splits
    stats.flips += w.scratch.flips;
    stats.edge_splits += w.scratch.edge_splits;
  } else {  // the walking kernel: the triangles each cavity replaced beyond the first
    stats.flips += w.scratch.replaced;
  }
}

/// Options::progress, called on the calling thread each time some 2^16 more points are in.
class Progress {
 public:
  Progress(const std::function<void(double)>& report, std::uint32_t n)
      : report_(report), n_(n), next_(report ? 0 : kNever) {}
  /// `done` of the n points are in; cheap when there is nothing to say.
  void operator()(std::uint64_t done) {
    if (done < next_) return;
    next_ = done + kStep;
    report_(n_ > 0 ? static_cast<double>(std::min<std::uint64_t>(done, n_)) / n_ : 1.0);
  }

 private:
  static constexpr std::uint64_t kStep = 1u << 16;
  static constexpr std::uint64_t kNever = std::numeric_limits<std::uint64_t>::max();
  const std::function<void(double)>& report_;
  std::uint64_t n_, next_;
};

class DelaunayTds;

/// What a method is given besides its kernel: the run's choices and where its findings go.
struct Insertion {
  unsigned threads = 1;
  /// Locate::Root: each point descends the DAG from its root, as the paper's do; else location
  /// runs in rounds with look-ahead (dag/rounds.hpp, dag/lookahead.hpp).
  bool from_root = false;
  const Experiment& experiment;
  /// Walking methods that asked for them (MethodEntry::keys): vertex v's Hilbert key,
  /// non-decreasing along each BRIO round.
  const std::uint32_t* keys = nullptr;
  std::vector<DuplicateHit>& duplicates;
  Stats& stats;
  Progress& progress;
};

/// A method: how it inserts vertices 0 .. n-1, in that order, into each kernel it can drive
/// (null where it cannot): the history DAG's (dag/kernel.hpp) or the walking kernel
/// (tds/delaunay.hpp). Each is registered by one line in registry.cpp.
struct MethodEntry {
  Method method;
  bool threaded;  ///< takes Options::threads (else one thread)
  bool keys;  ///< walking: needs each vertex's Hilbert key (Insertion::keys)
  void (*dag)(Kernel&, const Insertion&);
  void (*walk)(DelaunayTds&, const Insertion&);
};

/// The registered methods, and the one for `method` (not Method::Auto).
std::span<const MethodEntry> methods();
const MethodEntry& method_entry(Method method);

/// The serial driver on the DAG (methods/serial.cpp): the paper's Fig. 4, lines 5-23. The batch method
/// falls back to it on one thread.
void insert_serial(Kernel& kernel, const Insertion& run);

}  // namespace ridt::detail
