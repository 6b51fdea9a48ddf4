// What the methods share: the set-up of a run and its finish.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "dag/kernel.hpp"
#include "ridt/ridt.hpp"

namespace ridt::detail {

/// A point dropped during insertion and the mesh vertex it coincides with.
struct DuplicateHit {
  VertexId dropped;
  VertexId vertex;
};

/// What each thread of a threaded method keeps for itself, on its own cache lines: one type for
/// every method. `KernelScratch` is the kernel's: Scratch on the DAG (dag/kernel.hpp),
/// CavityScratch on the walking mesh (walk/mesh.hpp).
template <class KernelScratch>
struct alignas(64) WorkerState {
  KernelScratch scratch;
  std::vector<DuplicateHit> duplicates;  ///< the points it found equal to a vertex
  ThreadStats stats;  ///< its counters, and times it measured in seconds
  /// Time in its critical sections and waiting, in ticks (methods/threads.hpp), when timed.
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
  } else {  // the walking mesh: the triangles each cavity replaced beyond the first
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

class Mesh;

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
/// (null where it cannot): the history DAG's (dag/kernel.hpp) or the walking mesh
/// (walk/mesh.hpp). Each is registered by one line in registry.cpp.
struct MethodEntry {
  Method method;
  bool threaded;  ///< takes Options::threads (else one thread)
  bool keys;  ///< walking: needs each vertex's Hilbert key (Insertion::keys)
  void (*dag)(Kernel&, const Insertion&);
  void (*walk)(Mesh&, const Insertion&);
};

/// The registered methods, and the one for `method` (not Method::Auto).
std::span<const MethodEntry> methods();
const MethodEntry& method_entry(Method method);

/// The serial driver on the DAG (methods/serial.cpp): the paper's Fig. 4, lines 5-23. The batch method
/// falls back to it on one thread.
void insert_serial(Kernel& kernel, const Insertion& run);

/// The finish of the walking mesh: its arrays become the output's, in place (walk/mesh.cpp).
Triangulation finish_walking(Mesh& mesh, const std::vector<std::uint32_t>& input_index,
                             const std::vector<DuplicateHit>& duplicates, const Options& options, unsigned threads);

/// The input index that stands for a mesh vertex: its own, or for a group of equal points the
/// smallest among them.
struct Standing {
  explicit Standing(const std::vector<std::uint32_t>& input_index) : input_index(input_index) {}
  VertexId operator()(VertexId mesh_vertex) const {
    const VertexId v = input_index[mesh_vertex];
    if (keep.empty()) return v;
    const auto it = keep.find(v);
    return it == keep.end() ? v : it->second;
  }
  const std::vector<std::uint32_t>& input_index;
  std::unordered_map<VertexId, VertexId> keep;  // only the input indices that another stands for
};

/// The finish's steps that every mesh shares. Groups the duplicates (input indices, sorted by
/// the dropped one) and says who stands for whom.
Standing resolve_duplicates(const std::vector<std::uint32_t>& input_index, const std::vector<DuplicateHit>& duplicates,
                            std::vector<Duplicate>& out);
/// The hull, counter-clockwise from its smallest vertex, from its edges (sorted here).
std::vector<VertexId> trace_hull(std::vector<std::pair<VertexId, VertexId>>& edges);
/// The counts of the points and the warning of an empty or (finite bounding triangle) broken
/// result. `input_points` fills the points in input order when they are needed.
void set_warnings(Triangulation& out, std::uint32_t n, std::uint32_t count, std::size_t hull_edges,
                  const Options& options, const std::function<void(std::vector<Point>&)>& input_points);

/// Removes the bounding vertices, numbers the remaining triangles compactly, finds the
/// neighbours and the hull, and resolves duplicates (Fig. 4, line 24). Mesh vertex v is input
/// point input_index[v]. Uses up to `threads` threads.
Triangulation finish(Kernel& kernel, const std::vector<std::uint32_t>& input_index,
                     const std::vector<DuplicateHit>& duplicates, const Options& options, unsigned threads);

/// Rotates each triangle to start at its smallest vertex, then sorts the triangles, renumbering
/// neighbours: the output no longer depends on the order of insertion. Up to `threads` threads.
void canonicalize(Triangulation& out, unsigned threads = 1);

}  // namespace ridt::detail
