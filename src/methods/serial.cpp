
// The serial driver: the paper's Fig. 4 (randomized incremental insertion), made exact.
// Points are inserted in the random order; their location is scheduled in rounds
// (dag/rounds.hpp) so that the descents of the DAG run mostly in cache.
#include <chrono>

#include "dag/lookahead.hpp"
#include "dag/rounds.hpp"
#include "methods/method.hpp"

namespace ridt::detail {
namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// Fig. 8: the share of location, subdivision and legalization. Three clock reads a point, and
// location descends from the root one point at a time, as the paper does (no look-ahead).
void insert_profiled(Kernel& kernel, Scratch& scratch, std::vector<DuplicateHit>& duplicates, Stats& stats,
                     Progress& progress) {
  for (VertexId p = 0; p < kernel.n(); ++p) {
    progress(p);
    const auto t0 = Clock::now();
    const TriangleId last = kernel.descend(Kernel::kRoot, p);
    const Kernel::Location where = kernel.classify(last, p);
    const auto t1 = Clock::now();
    stats.time_locate_s += seconds(t1 - t0);
    if (where.where == Kernel::Where::OnVertex) {
      duplicates.push_back({p, kernel.triangles()[where.t].v[where.i]});
      continue;
    }
    kernel.split_at(where, p, scratch);
    const auto t2 = Clock::now();
    stats.time_split_s += seconds(t2 - t1);
    kernel.legalize(p, scratch);
    stats.time_legalize_s += seconds(Clock::now() - t2);
  }
}

}  // namespace

void insert_serial(Kernel& kernel, const Insertion& run) {
  std::vector<DuplicateHit>& duplicates = run.duplicates;
  Progress& progress = run.progress;
  Scratch scratch;
  if (run.experiment.profile) {
    Stats& stats = run.stats;
    insert_profiled(kernel, scratch, duplicates, stats, progress);
  } else if (run.from_root) {
    // The paper's Fig. 4 as it stands: each point descends from the root when its turn comes.
    for (VertexId p = 0; p < kernel.n(); ++p) {
      progress(p);
      const TriangleId leaf = kernel.descend(Kernel::kRoot, p);
      const VertexId hit = kernel.insert_at(kernel.classify(leaf, p), p, scratch);
      if (hit != kNoVertex) duplicates.push_back({p, hit});
    }
  } else {
    // Rounds (dag/rounds.hpp): each round's points first descend the DAG along a Hilbert curve
    // and keep the leaf they reach; then they are inserted in the random order, each
    // finishing its descent from that leaf, with look-ahead over the next points.
    RoundLocator rounds(kernel);
    std::vector<TriangleId> hint;
    for (std::size_t r = 0; r < rounds.rounds(); ++r) {
      const VertexId first = rounds.first(r), end = rounds.first(r + 1);
      hint.resize(end - first);
      rounds.locate(r, hint.data());
      LookAhead ahead(kernel, first, end, /*ring=*/true, hint.data());
      for (VertexId i = 0; i < ahead.count(); ++i) {
        const VertexId p = first + i;
        progress(p);
        const TriangleId leaf = kernel.descend(ahead.take(i).node, p);
        const VertexId hit = kernel.insert_at(kernel.classify(leaf, p), p, scratch);
        if (hit != kNoVertex) duplicates.push_back({p, hit});
      }
    }
  }
  run.stats.flips += scratch.flips;
  run.stats.edge_splits += scratch.edge_splits;
}

}  // namespace ridt::detail
