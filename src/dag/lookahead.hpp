// Location with look-ahead, shared by the drivers.
//
// A DAG node's region never changes, so a point may start its descent early and stop at any
// node: the descent resumes from there when the point's turn comes, whatever was inserted
// meanwhile. While one point is inserted, the next points of the same sequence each go one
// step further and prefetch what the step after needs, so their cache misses overlap instead
// of following one another. The order of insertion, and so the result, does not change.
#pragma once

#include <cstdint>

#include "dag/kernel.hpp"

namespace ridt::detail {

class LookAhead {
 public:
  // Points advanced ahead of the one being inserted. Starting from the leaves the rounds
  // found (dag/rounds.hpp), a point has about two levels left: some six steps with the ring,
  // well within 16.
  static constexpr VertexId kWindow = 16;

  struct Hint {
    TriangleId node;  // a node whose closed region holds the point
    TriangleId parent;  // the node before it on the path (the node itself where the path began)
  };

  /// The points first, first + 1, ... below end; point v starts its descent at start[v -
  /// first], a node whose region holds it. A point that reaches a leaf prefetches the leaf's
  /// neighbours and, with `ring`, the ring beyond them and its vertices (the caller decides:
  /// the pessimistic method leaves the ring off with several threads, since it pulls in lines
  /// the lock holder may be writing).
  LookAhead(const Kernel& kernel, VertexId first, VertexId end, bool ring, const TriangleId* start)
      : kernel_(kernel), first_(first), count_(end > first ? end - first : 0), ring_(ring), start_(start) {
    for (VertexId j = 0; j < kWindow && j < count_; ++j) enter(j);
  }

  VertexId count() const { return count_; }
  VertexId point(VertexId i) const { return first_ + i; }

  /// Advances the points after the i-th one step each and hands out where the i-th stands.
  /// Call with i = 0, 1, 2, ... in turn.
  Hint take(VertexId i) {
    for (VertexId j = i + 1; j < i + kWindow && j < count_; ++j) advance(slots_[j % kWindow], point(j));
    const Slot& s = slots_[i % kWindow];
    const Hint h{s.node, s.parent};
    if (i + kWindow < count_) enter(i + kWindow);  // the slot passes on
    return h;
  }

 private:
  // A level takes two steps: kDescending prefetches the points that the node's test reads
  // (its record was prefetched the step before), kStepping takes the step and prefetches the
  // record reached. Both kinds of miss then overlap with the other points' work.
  // At the leaf, two more steps prefetch the first ring (records), then the second ring
  // (records, then vertices), which legalization reads.
  enum class State : std::uint8_t { kDescending, kStepping, kAtLeaf, kAtRing, kDone };
  struct Slot {
    TriangleId node, parent;
    State state;
  };

  void enter(VertexId j) {
    const TriangleId t = start_[j];
    kernel_.prefetch(t);  // read at its first step
    slots_[j % kWindow] = {t, t, State::kDescending};
  }

  void advance(Slot& s, VertexId p) {
    switch (s.state) {
      case State::kDone:
        return;
      case State::kAtLeaf:
        if (ring_) kernel_.prefetch_ring(s.node);
        s.state = ring_ ? State::kAtRing : State::kDone;
        return;
      case State::kAtRing:
        kernel_.prefetch_ring_points(s.node);
        s.state = State::kDone;
        return;
      case State::kDescending:
        if (kernel_.prefetch_step(s.node)) {
          s.state = State::kStepping;
        } else {
          kernel_.prefetch_around(s.node);  // a leaf: what the insertion into it reads
          s.state = State::kAtLeaf;
        }
        return;
      case State::kStepping: {
        const TriangleId next = kernel_.step(s.node, p);
        kernel_.prefetch(next);
        s.parent = s.node;
        s.node = next;
        s.state = State::kDescending;
      }
    }
  }

  const Kernel& kernel_;
  VertexId first_, count_;
  bool ring_;
  const TriangleId* start_;
  Slot slots_[kWindow];
};

}  // namespace ridt::detail
