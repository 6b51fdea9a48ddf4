// The serial driver on the walking kernel (tds/delaunay.hpp): each point in turn located by a
// walk from the last one's triangle and inserted by its cavity.
#include <chrono>

#include "methods/method.hpp"
#include "tds/delaunay.hpp"

namespace ridt::detail {
namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// insert_walking with the predicates' lattice forms (kLattice) or the general ones.
template <bool kLattice>
void insert_all(DelaunayTds& tds, bool profile, std::vector<DuplicateHit>& duplicates, Stats& stats,
                Progress& progress) {
  const std::uint32_t n = tds.vertices().n();
  CavityScratch s;
  SlotPool pool;
  pool.next = tds.grow(2 * n);
  pool.end = pool.next + 2 * n;
  TriangleId last = 0;
  if (!profile) {
    for (VertexId p = 0; p < n; ++p) {
      progress(p);
      if (const VertexId hit = tds.insert<kLattice>(p, last, s, pool); hit != kNoVertex) duplicates.push_back({p, hit});
    }
  } else {
    // Fig. 8's phases: location is the walk, legalization finding the cavity (the triangles
    // Lawson's flips would replace), subdivision writing the new triangles over it.
    for (VertexId p = 0; p < n; ++p) {
      progress(p);
      const auto t0 = Clock::now();
      TriangleId t = last;
      tds.walk<kLattice>(t, p, Tds::kAnywhere);
      const VertexId hit = tds.coincident(t, p);
      const auto t1 = Clock::now();
      stats.time_locate_s += seconds(t1 - t0);
      if (hit != kNoVertex) {
        duplicates.push_back({p, hit});
        last = t;
        continue;
      }
      tds.find_cavity<kLattice>(t, p, s, Tds::kAnywhere);
      const auto t2 = Clock::now();
      stats.time_legalize_s += seconds(t2 - t1);
      last = tds.fill_cavity(p, s, pool);
      stats.time_split_s += seconds(Clock::now() - t2);
    }
  }
  tds.give_back(pool);
  stats.flips += s.replaced;
}

}  // namespace

void insert_walking(DelaunayTds& tds, const Insertion& run) {
  const bool profile = run.experiment.profile;
  if (tds.vertices().lattice())
    insert_all<true>(tds, profile, run.duplicates, run.stats, run.progress);
  else
    insert_all<false>(tds, profile, run.duplicates, run.stats, run.progress);
}

}  // namespace ridt::detail
