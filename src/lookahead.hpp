// Location with look-ahead, shared by the drivers.
//
// A DAG node's region never changes, so a point may start its descent early and stop at any
// node: the descent resumes from there when the point's turn comes, whatever was inserted
// meanwhile. While one point is inserted, the next points of the same sequence each go one
// step further and prefetch what the step after needs, so their cache misses overlap instead
// of following one another. The order of insertion, and so the result, does not change.
#pragma once

#include <bit>
#include <cstdint>

#include "kernel.hpp"

namespace ridt::detail {

class LookAhead {
 public:
  static constexpr VertexId kMaxWindow = 128;  // above twice the DAG's mean depth, 46 for 10^6 points

  struct Hint {
    TriangleId node;    // a node whose closed region holds the point
    TriangleId parent;  // the node before it on the path (the node itself where the path began)
  };

  /// The sequence first, first + stride, ... below end; point v of it starts its descent at
  /// start[v - first], or at the root without `start`. `window` (a power of two at most
  /// kMaxWindow): how many points ahead are advanced. A point that reaches a leaf prefetches
  /// the leaf's neighbours and, with `ring`, the ring beyond them. The ring pays on one
  /// thread; with several it pulls in lines that the lock holder may be writing, and is left
  /// off there.
  LookAhead(const Kernel& kernel, VertexId first, VertexId stride, VertexId end, bool ring,
            const TriangleId* start = nullptr, VertexId window = kMaxWindow)
      : kernel_(kernel), first_(first), stride_(stride), ring_(ring), start_(start),
        mask_(window - 1) {
    count_ = end > first ? (end - first + stride - 1) / stride : 0;
    for (VertexId j = 0; j < window && j < count_; ++j) enter(j);
  }

  VertexId count() const { return count_; }
  VertexId point(VertexId i) const { return first_ + i * stride_; }

  /// Advances the points after the i-th one step each and hands out where the i-th stands.
  /// Call with i = 0, 1, 2, ... in turn.
  Hint take(VertexId i) {
    for (VertexId j = i + 1; j <= i + mask_ && j < count_; ++j) advance(slots_[j & mask_], point(j));
    const Slot& s = slots_[i & mask_];
    const Hint h{s.node, s.parent};
    if (i + mask_ + 1 < count_) enter(i + mask_ + 1);  // the slot passes on
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
    const TriangleId t = start_ != nullptr ? start_[j * stride_] : Kernel::kRoot;
    kernel_.prefetch(t);  // read at its first step
    slots_[j & mask_] = {t, t, State::kDescending};
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
  VertexId first_, stride_, count_;
  bool ring_;
  const TriangleId* start_;
  VertexId mask_;
  Slot slots_[kMaxWindow];
};

}  // namespace ridt::detail
