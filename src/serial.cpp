// The serial driver: the paper's Fig. 4 (randomized incremental insertion), made exact.
#include <chrono>

#include "driver.hpp"
#include "lookahead.hpp"

namespace ridt::detail {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

void insert_serial(Kernel& kernel, bool profile, std::vector<DuplicateHit>& duplicates,
                   Stats& stats) {
  const VertexId n = kernel.n();
  Scratch scratch;
  struct Totals {  // the counters reach the stats however the loop ends
    Scratch& s;
    Stats& stats;
    ~Totals() { stats.flips += s.flips, stats.edge_splits += s.edge_splits; }
  } totals{scratch, stats};
  if (!profile) {
    LookAhead ahead(kernel, 0, 1, n, /*ring=*/true);
    for (VertexId p = 0; p < n; ++p) {
      const TriangleId start = ahead.take(p).node;
      const VertexId hit = kernel.insert_at(kernel.classify(kernel.descend(start, p), p), p, scratch);
      if (hit != kNone) duplicates.push_back({p, hit});
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
    kernel.split_at(where, p, scratch);
    const auto t2 = Clock::now();
    stats.time_split_s += std::chrono::duration<double>(t2 - t1).count();
    kernel.legalize(p, scratch);
    stats.time_legalize_s += seconds_since(t2);
  }
}

}  // namespace ridt::detail
