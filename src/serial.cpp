// The serial driver: the paper's Fig. 4 (randomized incremental insertion), made exact.
#include <chrono>

#include "driver.hpp"

namespace ridt::detail {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

void insert_serial(Kernel& kernel, bool profile, std::vector<DuplicateHit>& duplicates,
                   Stats& stats) {
  const VertexId n = kernel.n();
  if (!profile) {
    // Location with look-ahead. A DAG node's region never changes, so a point may start its
    // descent early and stop at any node: the descent resumes from there when the point's
    // turn comes, whatever was inserted meanwhile. The next kWindow points each go one level
    // down per insertion and prefetch the record they reach, so their cache misses overlap
    // instead of following one another. The order of insertion, and so the result, is the
    // paper's; only the memory traffic changes.
    constexpr VertexId kWindow = 128;  // well above the DAG's mean depth, 46 for 10^6 points
    enum State : std::uint8_t { kDescending, kAtLeaf, kDone };
    TriangleId hint[kWindow];
    State state[kWindow];
    for (VertexId k = 0; k < kWindow; ++k) hint[k] = Kernel::kRoot, state[k] = kDescending;
    for (VertexId p = 0; p < n; ++p) {
      for (VertexId q = p + 1; q < p + kWindow && q < n; ++q) {
        const VertexId k = q % kWindow;
        if (state[k] == kDone) continue;
        if (state[k] == kAtLeaf) {
          kernel.prefetch_ring(hint[k]);
          state[k] = kDone;
          continue;
        }
        const TriangleId next = kernel.step(hint[k], q);
        if (next == hint[k]) {
          kernel.prefetch_around(next);  // what the insertion into this leaf will read
          state[k] = kAtLeaf;
        } else {
          kernel.prefetch(next);
          hint[k] = next;
        }
      }
      const VertexId k = p % kWindow;
      const Kernel::Location where = kernel.classify(kernel.descend(hint[k], p), p);
      const VertexId hit = kernel.insert_at(where, p);
      if (hit != kNone) duplicates.push_back({p, hit});
      hint[k] = Kernel::kRoot, state[k] = kDescending;  // the slot passes to point p + kWindow
    }
    return;
  }
  // Fig. 8: the share of location, subdivision and legalization. Three clock reads a point.
  using Clock = std::chrono::steady_clock;
  for (VertexId p = 0; p < n; ++p) {
    const auto t0 = Clock::now();
    const Kernel::Location where = kernel.classify(kernel.descend(Kernel::kRoot, p), p);
    const auto t1 = Clock::now();
    stats.time_locate_s += std::chrono::duration<double>(t1 - t0).count();
    if (where.where == Kernel::Where::OnVertex) {
      duplicates.push_back({p, kernel.triangles()[where.t].v[where.i]});
      continue;
    }
    kernel.split_at(where, p);
    const auto t2 = Clock::now();
    stats.time_split_s += std::chrono::duration<double>(t2 - t1).count();
    kernel.legalize(p);
    stats.time_legalize_s += seconds_since(t2);
  }
}

}  // namespace ridt::detail
