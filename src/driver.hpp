// What the methods share: the set-up of a run and its finish.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "kernel.hpp"
#include "ridt/ridt.hpp"

namespace ridt::detail {

/// A point dropped during insertion and the mesh vertex it coincides with.
struct DuplicateHit {
  VertexId dropped;
  VertexId vertex;
};

/// What each thread of a threaded method keeps for itself, on its own cache lines: one type for
/// every method. `KernelScratch` is the kernel's: Scratch on the DAG (kernel.hpp),
/// CavityScratch on the walking mesh (cavity.hpp).
template <class KernelScratch>
struct alignas(64) WorkerState {
  KernelScratch scratch;
  std::vector<DuplicateHit> duplicates;  ///< the points it found equal to a vertex
  ThreadStats stats;                     ///< its counters, and times it measured in seconds
  /// Time in its critical sections and waiting, in ticks (threads.hpp), when timed.
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

/// Serial insertion of vertices 0 .. n-1 in that order (the paper's Fig. 4, lines 5-23).
/// `from_root`: each point descends the DAG from its root, as the paper's does (Locate::Root);
/// else location runs in rounds with look-ahead (rounds.hpp, lookahead.hpp).
void insert_serial(Kernel& kernel, bool profile, bool from_root, std::vector<DuplicateHit>& duplicates,
                   Stats& stats, Progress& progress);

class Mesh;
/// Serial insertion of vertices 0 .. n-1 into the walking mesh (cavity.hpp): each walks from
/// the last insertion and is inserted by its cavity. `profile`: time the phases (Fig. 8).
void insert_walking(Mesh& mesh, bool profile, std::vector<DuplicateHit>& duplicates, Stats& stats,
                    Progress& progress);

/// The partition method with `threads` threads (partition.cpp); key[v] is vertex v's Hilbert
/// key (n of them), non-decreasing along each BRIO round.
void insert_partition(Mesh& mesh, const std::uint32_t* key, unsigned threads,
                      std::vector<DuplicateHit>& duplicates, Stats& stats, Progress& progress);

/// The finish of the walking mesh: its arrays become the output's, in place (walking.cpp).
Triangulation finish_walking(Mesh& mesh, const std::vector<std::uint32_t>& input_index,
                             const std::vector<DuplicateHit>& duplicates, const Options& options,
                             unsigned threads);

/// The paper's Fig. 10 with `threads` workers (pessimistic.cpp). `from_root` as for
/// insert_serial.
void insert_pessimistic(Kernel& kernel, unsigned threads, bool from_root, bool paper, bool timed,
                        std::vector<DuplicateHit>& duplicates, Stats& stats, Progress& progress);

/// The optimistic method with `threads` workers (optimistic.cpp).
void insert_optimistic(Kernel& kernel, unsigned threads, bool from_root, bool timed,
                       std::vector<DuplicateHit>& duplicates, Stats& stats, Progress& progress);

/// The batch method: threads - 1 locators and one modifier (batch.cpp).
void insert_batch(Kernel& kernel, unsigned threads, bool from_root, std::vector<DuplicateHit>& duplicates,
                  Stats& stats, Progress& progress);

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
Standing resolve_duplicates(const std::vector<std::uint32_t>& input_index,
                            const std::vector<DuplicateHit>& duplicates, std::vector<Duplicate>& out);
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
                     const std::vector<DuplicateHit>& duplicates, const Options& options,
                     unsigned threads);

/// Rotates each triangle to start at its smallest vertex, then sorts the triangles, renumbering
/// neighbours: the output no longer depends on the order of insertion. Up to `threads` threads.
void canonicalize(Triangulation& out, unsigned threads = 1);

}  // namespace ridt::detail
