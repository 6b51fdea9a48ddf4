// Location in rounds: the same descents of the history DAG, in a cache-friendly schedule.
//
// The points are inserted in the paper's random order, vertex 0, 1, 2, ...; that order, the
// DAG and every split and flip stay as they are. What changes is when each descent happens. A
// DAG node's region never changes, so a descent may stop at any node and resume from it later.
// The points are cut into rounds of doubling size, [0, kFirstRound), [kFirstRound, 2 kFirstRound),
// [2 kFirstRound, 4 kFirstRound), ... Before a round is inserted, all its points descend the DAG as it
// stands, one after the other along a Hilbert curve: neighbours on the curve follow nearly the
// same path, so the path of one is in cache for the next, and each descent starts from the
// deepest node of the previous path that still holds its point. Each point keeps the leaf it
// reached as a hint. When its turn comes it descends only what its own round added above that
// leaf: about 3 ln 2, two levels, instead of 3 ln n, 46 for 10^6 points, each a cache miss in
// random order.
//
// The idea is that of biased randomized insertion orders (Amenta, Choi and Rote, "Incremental
// constructions con BRIO", 2003) turned around: BRIO sorts the insertions within a round; here
// only the location is sorted, and the insertions keep their random order. In the BRIO order
// itself (order/order.hpp) both are sorted, and the same schedule serves it unchanged.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <thread>
#include <vector>

#include "dag/kernel.hpp"
#include "order/order.hpp"

namespace ridt::detail {

/// One lane of descend_along: a stretch of the list, the point descending, and the path of its
/// last descent.
struct DescentLane {
  enum class State : std::uint8_t { kStart, kClimb, kFetch, kStep, kDone };
  VertexId next, stop;  // the lane's stretch of the list still to locate
  VertexId v;  // the point descending
  State state;
  std::vector<TriangleId> path;  // the lane's last descent, root first

  /// One step of the lane; false once its stretch is done.
  template <class Sink>
  bool advance(const Kernel& kernel, const VertexId* points, Sink& sink) {
    switch (state) {
      case State::kDone:
        return false;
      case State::kStart:
        // Neighbours on the curve are numbered at random: v's coordinates are a miss, and so
        // are the vertices of the last leaf, which the climb tests first.
        v = points[next++];
        kernel.prefetch_point(v);
        kernel.prefetch_vertices(path.back());
        state = State::kClimb;
        return true;
      case State::kClimb:
        // The root holds everything; below it, climb to the deepest node that holds v. The
        // rest of the path was read by the last descent and is in cache.
        while (path.size() > 1 && !kernel.holds(path.back(), v)) path.pop_back();
        state = State::kFetch;
        [[fallthrough]];
      case State::kFetch:
        // The record at the end of the path was prefetched; now the points its test reads.
        if (kernel.prefetch_step(path.back())) {
          state = State::kStep;
          return true;
        }
        sink(v, path.back());  // a leaf: the descent of v is done
        state = next < stop ? State::kStart : State::kDone;
        return state != State::kDone;
      case State::kStep: {
        const TriangleId t = kernel.step(path.back(), v);
        kernel.prefetch(t);
        path.push_back(t);
        state = State::kFetch;
        return true;
      }
    }
    return false;
  }
};

/// Descends the DAG for each point of `points` (count of them, best in an order along a
/// curve) and calls sink(v, leaf) with a leaf whose closed region holds v. Each descent starts
/// from the deepest node of the previous path that still holds its point: for neighbours on a
/// curve that saves most of the path, and what is left of it is in cache. The list is cut into
/// kLanes stretches descended side by side, one step each in turn: a step prefetches what the
/// lane's next step reads, and the misses of the lanes overlap.
template <class Sink>
void descend_along(const Kernel& kernel, const VertexId* points, VertexId count, Sink&& sink) {
  // Enough lanes to cover the latency of a miss (about 200 ns) with other lanes' steps.
  constexpr unsigned kLanes = 16;
  using State = DescentLane::State;
  // Short lists do not pay for the lanes' set-up.
  const unsigned used = std::clamp<unsigned>(count / 64, 1, kLanes);
  DescentLane lanes[kLanes];
  unsigned active = 0;
  for (unsigned l = 0; l < used; ++l) {
    DescentLane& lane = lanes[l];
    lane.next = static_cast<VertexId>(std::uint64_t{count} * l / used);
    lane.stop = static_cast<VertexId>(std::uint64_t{count} * (l + 1) / used);
    lane.path.assign(1, Kernel::kRoot);
    lane.state = lane.next < lane.stop ? State::kStart : State::kDone;
    active += lane.state != State::kDone;
  }
  while (active > 0)
    for (unsigned l = 0; l < used; ++l)
      if (lanes[l].state != State::kDone && !lanes[l].advance(kernel, points, sink)) --active;
}

class RoundLocator {
 public:
  /// Sorts the points of each round of vertices 0 .. n-1 (order/order.hpp) along the Hilbert curve,
  /// with up to `threads` threads; in the BRIO order (Kernel::brio) they already are.
  explicit RoundLocator(const Kernel& kernel, unsigned threads = 1) : kernel_(kernel) {
    const VertexId n = kernel.n();
    // Round r holds the vertices [first(r), first(r + 1)), consecutive numbers: each round is
    // sorted on its own (sort_rounds, order/order.hpp).
    for (VertexId b = 0; b < n; b = round_end(b)) first_.push_back(b);
    first_.push_back(n);
    by_round_.resize(n);
    std::iota(by_round_.begin(), by_round_.end(), VertexId{0});
    if (kernel.brio()) return;
    const std::vector<std::uint32_t> key = hilbert_keys(&kernel.point(0), n, threads);
    sort_rounds(&kernel.point(0), key.data(), by_round_.data(), first_, threads);
  }

  /// The number of rounds and the vertices [first(r), first(r + 1)) of round r.
  std::size_t rounds() const { return first_.size() - 1; }
  /// The most points in one round.
  VertexId largest() const {
    VertexId m = 0;
    for (std::size_t r = 0; r < rounds(); ++r) m = std::max(m, first_[r + 1] - first_[r]);
    return m;
  }
  VertexId first(std::size_t r) const { return first_[r]; }

  /// Descends the DAG as it stands for every point of round r, along the curve, and writes
  /// in hint[v - first(r)] a leaf whose closed region holds point v.
  void locate(std::size_t r, TriangleId* hint) const { locate(r, 0, first_[r + 1] - first_[r], hint); }

  /// The same for positions [begin, end) of round r's curve (0 is its first): each of
  /// several threads can locate its own stretch while the DAG is read by all (descents read
  /// only what was published, dag/records.hpp).
  void locate(std::size_t r, VertexId begin, VertexId end, TriangleId* hint) const {
    const VertexId base = first_[r];
    descend_along(kernel_, by_round_.data() + base + begin, end - begin,
                  [&](VertexId v, TriangleId leaf) { hint[v - base] = leaf; });
  }

 private:
  const Kernel& kernel_;
  std::vector<VertexId> first_;  // first vertex of each round, then n
  std::vector<VertexId> by_round_;  // each round's vertices along the curve
};

}  // namespace ridt::detail
