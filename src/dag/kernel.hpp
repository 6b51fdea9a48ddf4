// The insertion kernel of randomized incremental Delaunay triangulation (de Berg et al.,
// Computational Geometry, ch. 9; the paper's Figs. 4 and 5): locate in the history DAG, split
// 1->3 or 2->4, legalize by flips. Every method drives this one kernel.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "dag/records.hpp"
#include "output/output.hpp"
#include "predicates/predicates.hpp"
#include "predicates/symbolic.hpp"
#include "ridt/ridt.hpp"
#include "runtime/memory.hpp"

namespace ridt::detail {

/// The bounding vertices have ids n, n + 1, n + 2 (predicates/symbolic.hpp).
///
/// What one inserting thread keeps to itself, on its own cache lines: the edges still to
/// legalize (triangles with the new point at v[0]) and counters.
struct alignas(64) Scratch {
  std::vector<TriangleId> stack;
  std::uint64_t flips = 0;
  std::uint64_t edge_splits = 0;
  // The optimistic method only. `owner` (1 .. kMaxOwner) marks the records this thread makes
  // and must own before each write (0: no ownership is kept); `made` lists them, to be
  // released after the insertion. Records come from the thread's own block of ids,
  // [pool_next, pool_end), when `pooled`.
  std::uint32_t owner = 0;
  std::vector<TriangleId> made;
  // When set: the triangles whose circumcircle holds the point being inserted, found by the
  // caller with the same incircle test. Every triangle legalization tests is one that existed
  // before the insertion, so it flips exactly these, and the test need not run twice.
  const std::vector<TriangleId>* cavity = nullptr;
  bool pooled = false;
  TriangleId pool_next = 0, pool_end = 0;
};

class Kernel {
 public:
  /// `points` holds n points (vertex v is points[v]) followed by three bounding vertices
  /// (their coordinates are used only when `symbolic` is false). `brio`: the vertices come in
  /// the BRIO order (order/order.hpp), each round already along the curve.
  Kernel(Block<Point> points, std::uint32_t n, bool symbolic, bool brio = false);

  enum class Where { Inside, OnEdge, OnVertex };
  struct Location {
    TriangleId t;
    Where where;
    int i;  // OnEdge: the edge opposite v[i]; OnVertex: the vertex v[i]
  };

  /// Descends the DAG from `t` to the leaf whose closure contains point p.
  TriangleId descend(TriangleId t, VertexId p) const;

  /// One level of the descent: the child of t whose closure contains p, or t for a leaf.
  /// An internal node keeps what the choice needs in its dead neighbour slots (see
  /// set_separator), so one record is read a level.
  TriangleId step(TriangleId t, VertexId p) const {
    // acquire: pairs with the release store that published the children (dag/records.hpp).
    const Triangle& r = tris_[t];
    const std::uint32_t c = r.load_child();
    if (is_leaf(c)) return t;
    const TriangleId first = c & kIdMask;
    if (c & kThreeChildren) {
      // Children (q, v1, v2), (q, v2, v0), (q, v0, v1) fill the wedges between the rays
      // q->v1, q->v2, q->v0; two orientation tests pick the wedge holding p.
      const VertexId q = r.n[0];
      if (orient(q, r.v[0], p) >= 0) return orient(q, r.v[1], p) > 0 ? first : first + 2;
      return orient(q, r.v[2], p) >= 0 ? first + 1 : first;
    }
    // Two children split by the edge n[0] -> n[1]; the first lies to its left.
    return orient(r.n[0], r.n[1], p) >= 0 ? first : first + 1;
  }
  /// Whether the closed region of node t (a triangle ever made) holds point p.
  bool holds(TriangleId t, VertexId p) const {
    const Triangle& r = tris_[t];
    return orient(r.v[1], r.v[2], p) >= 0 && orient(r.v[2], r.v[0], p) >= 0 && orient(r.v[0], r.v[1], p) >= 0;
  }
  /// Where p lies in leaf t (whose closure contains p).
  Location classify(TriangleId t, VertexId p) const;

  /// Inserts p from a known location. Returns kNoVertex, or the vertex that p duplicates.
  VertexId insert_at(const Location& where, VertexId p, Scratch& s) {
    if (where.where == Where::OnVertex) return tris_[where.t].v[where.i];
    split_at(where, p, s);
    legalize(p, s);
    return kNoVertex;
  }
  void split_at(const Location& where, VertexId p, Scratch& s) {
    if (where.where == Where::Inside)
      split_triangle(where.t, p, s);
    else
      split_edge(where.t, where.i, p, s);
  }
  void legalize(VertexId p, Scratch& s);

  int orient(VertexId a, VertexId b, VertexId c) const { return vertices_.orient(a, b, c); }
  /// +1 if finite point p lies inside the circle of the counter-clockwise triangle (a, b, c),
  /// -1 outside; never 0 (symbolic perturbation).
  int incircle(VertexId a, VertexId b, VertexId c, VertexId p) const { return vertices_.incircle(a, b, c, p); }

  void prefetch(TriangleId t) const { prefetch_record(&tris_[t]); }
  void prefetch_point(VertexId v) const { __builtin_prefetch(&points_[v]); }
  /// Prefetches the vertices of node t, whose record is in cache (holds reads them).
  void prefetch_vertices(TriangleId t) const {
    const Triangle& r = tris_[t];
    for (int i = 0; i < 3; ++i) __builtin_prefetch(&points_[load_word(r.v[i])]);
  }
  /// Prefetches the points that step(t, p) compares p with, once t's record is in cache, so
  /// that the step after it finds them there. Returns false for a leaf (nothing to step).
  /// Safe while other threads change the triangulation: an internal node never changes after its
  /// child link is published, and that link is read with acquire.
  bool prefetch_step(TriangleId t) const {
    const Triangle& r = tris_[t];
    const std::uint32_t c = r.load_child();
    if (is_leaf(c)) return false;
    __builtin_prefetch(&points_[r.n[0]]);
    if (c & kThreeChildren) {
      for (int i = 0; i < 3; ++i) __builtin_prefetch(&points_[r.v[i]]);
    } else {
      __builtin_prefetch(&points_[r.n[1]]);
    }
    return true;
  }
  /// Prefetches the second ring around leaf t, once its neighbours are in cache: the
  /// neighbours' far vertices and their other neighbours, which the first flips read. Safe
  /// while another thread changes the triangulation: every word is read atomically, and a stale or
  /// half-made record only sends a prefetch to the wrong line.
  void prefetch_ring(TriangleId t) const {
    const Triangle& r = tris_[t];
    if (!is_leaf(r.load_child())) return;  // split since: its n[] no longer names neighbours
    for (int i = 0; i < 3; ++i) {
      const Triangle* u = tris_.find(load_link(r.n[i]));
      if (u == nullptr || !is_leaf(u->load_child())) continue;  // none, or split since
      for (int j = 0; j < 3; ++j) {
        const VertexId v = load_word(u->v[j]);
        if (v < n_ + 3) __builtin_prefetch(&points_[v]);
        const TriangleId w = load_link(u->n[j]);
        if (w != t) tris_.prefetch</*kForWrite=*/true>(w);  // relinked if u flips
      }
    }
  }
  /// Prefetches the vertices of the second ring around leaf t, once prefetch_ring has brought
  /// its records: a flip exposes the edges of the second ring, and testing them reads those
  /// vertices. Safe under threads for the same reasons as prefetch_ring.
  void prefetch_ring_points(TriangleId t) const {
    const Triangle& r = tris_[t];
    if (!is_leaf(r.load_child())) return;
    for (int i = 0; i < 3; ++i) {
      const Triangle* u = tris_.find(load_link(r.n[i]));
      if (u == nullptr || !is_leaf(u->load_child())) continue;
      for (int j = 0; j < 3; ++j) {
        const TriangleId w = load_link(u->n[j]);
        if (w == t) continue;
        const Triangle* x = tris_.find(w);
        if (x == nullptr) continue;
        for (int k = 0; k < 3; ++k) {
          const VertexId v = load_word(x->v[k]);
          if (v < n_ + 3) __builtin_prefetch(&points_[v]);
        }
      }
    }
  }
  /// Prefetches what inserting into leaf t will read: its neighbours and its vertices. Safe
  /// while other threads change the triangulation: t's vertices never change, its links are read
  /// atomically, and a stale link only prefetches the wrong line.
  void prefetch_around(TriangleId t) const {
    const Triangle& r = tris_[t];
    for (int i = 0; i < 3; ++i) {
      tris_.prefetch</*kForWrite=*/true>(load_link(r.n[i]));  // relinked by the split
      __builtin_prefetch(&points_[r.v[i]]);
    }
  }

  // Ownership, for the optimistic method: the one-word lock of each leaf is its child word
  // (dag/records.hpp), 0 when free and the owner's number while owned. Only leaves are ever owned.

  /// Takes leaf t for `me` if nobody has it. False if another thread owns it or t is no
  /// longer a leaf (then its child word is a link, and the caller descends on from it).
  bool try_acquire(TriangleId t, std::uint32_t me) {
    std::uint32_t expected = 0;
    // acquire: what the last owner wrote to t (its links) happens before our reads of it.
    return tris_[t].child_link().compare_exchange_strong(expected, me, std::memory_order_acquire,
                                                         std::memory_order_relaxed);
  }
  /// Gives t back, if `me` still owns it: a triangle killed meanwhile holds its child link
  /// now, published by us, and stays as it is.
  void release(TriangleId t, std::uint32_t me) {
    auto word = tris_[t].child_link();
    // Only the owner writes an owned word, so reading then storing cannot race.
    // release: our writes to t happen before the next owner's reads.
    if (word.load(std::memory_order_relaxed) == me) word.store(0, std::memory_order_release);
  }
  bool owns(TriangleId t, std::uint32_t me) const { return tris_[t].load_child() == me; }
  /// Marks the unused rest of a pooled thread's block as no triangle, for the finish.
  void retire_pool(Scratch& s);

  const TriangleStore& triangles() const { return tris_; }
  /// For the finish only: it gives the records' pages back as it copies them out.
  TriangleStore& triangles_for_finish() { return tris_; }
  const Point& point(VertexId v) const { return points_[v]; }
  /// For the finish, once no predicate runs: frees the points' copy, to lower the peak.
  void release_points() { points_.reset(); }
  std::uint32_t n() const { return n_; }
  bool brio() const { return brio_; }

  static constexpr TriangleId kRoot = 0;

 private:
  /// `count` consecutive new ids: from the shared store, or from the thread's pool.
  TriangleId allocate(std::uint32_t count, Scratch& s) {
    TriangleId first;
    if (!s.pooled) {
      first = tris_.allocate(count);
    } else {
      if (s.pool_end - s.pool_next < count) {
        retire_pool(s);
        s.pool_next = tris_.allocate_shared(kPoolBlock);
        s.pool_end = s.pool_next + kPoolBlock;
      }
      first = s.pool_next;
      s.pool_next += count;
    }
    // Records are handed out in order: ask for the lines of those a few allocations on, so
    // the writes to new records do not wait for memory (and an atomic operation behind them,
    // which waits for earlier writes, does not either).
    if (const Triangle* ahead = tris_.find(first + kWriteAhead)) prefetch_record<true>(ahead);
    return first;
  }
  static constexpr std::uint32_t kWriteAhead = 32;  // records: some ten allocations on
  // Ids a pooled thread takes at once: one shared atomic add per some 450 insertions.
  static constexpr std::uint32_t kPoolBlock = 4096;

  /// Before every write to an existing triangle: with ownership kept, the writer must own it.
  /// A failure here is a broken locking protocol, never bad input.
  void require_owned(TriangleId t, const Scratch& s) const {
    if (s.owner != 0 && !owns(t, s.owner)) throw std::logic_error("ridt: a thread wrote a triangle it does not own");
  }

  // What an edge split and a flip read before they write (the names of the drawings in
  // dag/kernel.cpp).
  struct EdgeSplit {
    TriangleId u;
    VertexId a, b, c, d;
    TriangleId tn_b, tn_c, un_b, un_c;
  };
  EdgeSplit read_edge_split(TriangleId t, int i) const;
  struct Flip {
    VertexId p, a, b, q;
    TriangleId ta, tb, uaq, uqb;
  };
  Flip read_flip(TriangleId t, TriangleId u, int j) const;

  void split_triangle(TriangleId t, VertexId p, Scratch& s);
  void split_edge(TriangleId t, int i, VertexId p, Scratch& s);
  void flip(TriangleId t, TriangleId u, int j, Scratch& s);
  // Neighbour u of `old` now borders `now` instead.
  void relink(TriangleId u, TriangleId old, TriangleId now, const Scratch& s) {
    if (u == kNoTriangle) return;
    require_owned(u, s);
    Triangle& r = tris_[u];
    store_link(r.n[r.n[0] == old ? 0 : (r.n[1] == old ? 1 : 2)], now);
  }
  // The two children of t are split by the directed edge a -> b, the first on its left.
  void set_separator(TriangleId t, VertexId a, VertexId b, const Scratch& s) {
    require_owned(t, s);
    store_link(tris_[t].n[0], a);
    store_link(tris_[t].n[1], b);
  }
  // t's children are complete: make them reachable. This also ends t's ownership.
  void publish_children(TriangleId t, std::uint32_t link, const Scratch& s) {
    require_owned(t, s);
    // release: the children are complete before a locating thread can reach them.
    tris_[t].child_link().store(link, std::memory_order_release);
  }
  // A new triangle, owned from birth by the thread that makes it (if it keeps ownership).
  void make(TriangleId t, VertexId a, VertexId b, VertexId c, TriangleId na, TriangleId nb, TriangleId nc, Scratch& s) {
    Triangle& r = tris_[t];
    store_word(r.v[0], a), store_word(r.v[1], b), store_word(r.v[2], c);
    store_link(r.n[0], na), store_link(r.n[1], nb), store_link(r.n[2], nc);
    // Published by the parent's release store; atomic all the same, since a thread that
    // prefetches around its leaf may follow a link to this record while it is being made.
    store_word(r.child, s.owner);
    if (s.owner != 0) s.made.push_back(t);
  }

  Block<Point> points_;
  std::uint32_t n_;
  Vertices vertices_;  // the predicates on points_, with the bounding vertices
  bool brio_;
  TriangleStore tris_;
};

/// The DAG's finish (dag/finish.cpp): removes the bounding vertices, numbers the remaining triangles compactly, finds the
/// neighbours and the hull, and resolves duplicates (Fig. 4, line 24). Mesh vertex v is input
/// point input_index[v]. Uses up to `threads` threads.
Triangulation finish(Kernel& kernel, const std::vector<std::uint32_t>& input_index,
                     const std::vector<DuplicateHit>& duplicates, const Options& options, unsigned threads);

}  // namespace ridt::detail
