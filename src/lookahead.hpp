// Location with look-ahead, shared by the drivers.
//
// A DAG node's region never changes, so a point may start its descent early and stop at any
// node: the descent resumes from there when the point's turn comes, whatever was inserted
// meanwhile. While one point is inserted, the next kWindow points of the same sequence each go
// one level down and prefetch the record they reach, so their cache misses overlap instead of
// following one another. The order of insertion, and so the result, does not change.
#pragma once

#include <cstdint>

#include "kernel.hpp"

namespace ridt::detail {

class LookAhead {
 public:
  static constexpr VertexId kWindow = 128;  // well above the DAG's mean depth, 46 for 10^6 points

  struct Hint {
    TriangleId node;    // a node whose closed region holds the point
    TriangleId parent;  // the node before it on the path (the root for the root)
  };

  /// The sequence first, first + stride, ... below end. A point that reaches a leaf prefetches
  /// the leaf's neighbours and, with `ring`, the ring beyond them. The ring pays on one
  /// thread (it brings 1-thread pessimistic to serial's time); with several it pulls in lines
  /// that the lock holder may be writing, and is left off there.
  LookAhead(const Kernel& kernel, VertexId first, VertexId stride, VertexId end, bool ring)
      : kernel_(kernel), first_(first), stride_(stride), ring_(ring) {
    count_ = end > first ? (end - first + stride - 1) / stride : 0;
    for (Slot& s : slots_) s = {Kernel::kRoot, Kernel::kRoot, State::kDescending};
  }

  VertexId count() const { return count_; }
  VertexId point(VertexId i) const { return first_ + i * stride_; }

  /// Advances the points after the i-th one level each and hands out where the i-th stands.
  /// Call with i = 0, 1, 2, ... in turn.
  Hint take(VertexId i) {
    for (VertexId j = i + 1; j < i + kWindow && j < count_; ++j) advance(slots_[j % kWindow], point(j));
    Slot& s = slots_[i % kWindow];
    const Hint h{s.node, s.parent};
    s = {Kernel::kRoot, Kernel::kRoot, State::kDescending};  // the slot passes to i + kWindow
    return h;
  }

 private:
  enum class State : std::uint8_t { kDescending, kAtLeaf, kDone };
  struct Slot {
    TriangleId node, parent;
    State state;
  };

  void advance(Slot& s, VertexId p) {
    switch (s.state) {
      case State::kDone:
        return;
      case State::kAtLeaf:
        if (ring_) kernel_.prefetch_ring(s.node);
        s.state = State::kDone;
        return;
      case State::kDescending: {
        const TriangleId next = kernel_.step(s.node, p);
        if (next == s.node) {
          kernel_.prefetch_around(next);  // what the insertion into the leaf reads
          s.state = State::kAtLeaf;
        } else {
          kernel_.prefetch(next);
          s.parent = s.node;
          s.node = next;
        }
      }
    }
  }

  const Kernel& kernel_;
  VertexId first_, stride_, count_;
  bool ring_;
  Slot slots_[kWindow];
};

}  // namespace ridt::detail
