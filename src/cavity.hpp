// The walking kernel: a flat triangle mesh without history, points located by walking and
// inserted by Bowyer-Watson cavities. It serves the serial method with Locate::Walk and the
// partition method (partition.cpp), whose threads share one mesh without a lock.
//
// Slot t of the mesh is a triangle: v[3t + i] its vertices, counter-clockwise, and
// link[3t + i] the edge across from v[3t + i], named by its place in the neighbour's arrays
// (3u + j: the neighbour is u, and the shared edge is u's edge j), or kNoLink on the outer
// edges of the bounding triangle. The edge across from v[i] runs v[next(i)] -> v[prev(i)], so
// going round a triangle counter-clockwise its edges come in the order i, next(i), prev(i).
//
// An insertion replaces the m triangles whose circumcircle holds the new point p (the cavity:
// with exact predicates and the symbolic perturbation it is a disk whose triangles have all
// their vertices on its boundary, so its dual graph is a tree) by the m + 2 triangles that join
// p to the cavity's boundary edges, writing m of them over the cavity's slots. A mesh of k
// points thus always fills exactly 2k + 1 slots, and the arrays never grow.
#pragma once

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "ridt/ridt.hpp"
#include "symbolic.hpp"

namespace ridt::detail {

using Link = std::int32_t;
inline constexpr Link kNoLink = -1;
inline constexpr VertexId kNoVertex = 0xffffffffu;
inline constexpr TriangleId kNoTriangle = 0xffffffffu;
/// Links 3u + j must fit in a Link: 2n + 1 slots of 3 edges.
inline constexpr std::uint64_t kMaxWalkingPoints = (std::uint64_t{std::numeric_limits<Link>::max()} - 8) / 6;

constexpr int next3(int i) { return i == 2 ? 0 : i + 1; }
constexpr int prev3(int i) { return i == 0 ? 2 : i - 1; }

/// Where an insertion finds its new slots: a list of free slots first, then a range.
struct SlotPool {
  const TriangleId* list = nullptr;
  std::size_t listed = 0;
  TriangleId next = 0, end = 0;

  bool empty() const { return listed == 0 && next == end; }
  TriangleId take() { return listed > 0 ? list[--listed] : next++; }
  std::size_t size() const { return listed + (end - next); }
};

/// What one inserting thread keeps to itself: the cavity's triangles and boundary, the
/// traversal's stack, counters.
struct alignas(64) CavityScratch {
  struct Boundary {
    VertexId a, b;  // the edge a -> b, counter-clockwise round the cavity
    Link outside;   // the edge's place in the triangle outside, or kNoLink
  };
  std::vector<TriangleId> cavity;
  std::vector<Boundary> boundary;
  std::vector<Link> stack;
  std::vector<TriangleId> slots;
  std::uint64_t replaced = 0;  // triangles replaced beyond the first, over all insertions
};

class Mesh {
 public:
  /// The mesh of the bounding triangle alone, with room for n points; its memory made ready
  /// by up to `threads` threads.
  explicit Mesh(const Vertices& vertices, unsigned threads = 1);

  const Vertices& vertices() const { return vertices_; }
  /// Slots in use (each a triangle, or free: see free_slot).
  TriangleId slots() const { return top_; }
  VertexId vertex(TriangleId t, int i) const { return v_[3 * std::size_t{t} + i]; }
  Link link(TriangleId t, int i) const { return link_[3 * std::size_t{t} + i]; }

  /// Walks from triangle t to one whose closure holds point p, and returns it. Each step
  /// crosses an edge that has p strictly on its far side, never the one it came in by. In a
  /// Delaunay triangulation such a walk cannot cycle (Edelsbrunner, 1990: the in-front
  /// relation of its triangles seen from any point is acyclic), and the symbolic bounding
  /// vertices keep it one.
  TriangleId walk(TriangleId t, VertexId p) const {
    walk(t, p, [](TriangleId) { return true; });
    return t;
  }
  /// The same, entering only the triangles that `owned` allows (the partition method's
  /// regions; it is asked before a triangle's vertices are read): of the edges that have p on
  /// their far side it takes one into such a triangle. True when it got there; else t is the
  /// last triangle it reached.
  template <class Owned>
  bool walk(TriangleId& t, VertexId p, Owned&& owned) const {
    int from = 3;  // the edge of t we came in by, none at first
    for (;;) {
      const std::size_t base = 3 * std::size_t{t};
      int out = 3;
      bool blocked = false;
      for (int i = 0; i < 3; ++i) {
        if (i == from) continue;
        if (vertices_.orient(v_[base + next3(i)], v_[base + prev3(i)], p) < 0) {
          if (owned(static_cast<TriangleId>(link_[base + i] / 3))) {
            out = i;
            break;
          }
          blocked = true;
        }
      }
      if (out == 3) return !blocked;
      const Link l = link_[base + out];
      t = static_cast<TriangleId>(l / 3);
      from = l % 3;
    }
  }

  /// Whether point p coincides with a vertex of triangle t (whose closure holds it): the
  /// vertex, or kNoVertex.
  VertexId coincident(TriangleId t, VertexId p) const {
    const Point& q = vertices_[p];
    for (int i = 0; i < 3; ++i) {
      const VertexId w = vertex(t, i);
      if (!vertices_.symbolic(w) && vertices_[w] == q) return w;
    }
    return kNoVertex;
  }

  /// Finds the cavity of p, which holds triangle t (whose closure holds p, and p is no
  /// vertex of it), into s.cavity and s.boundary. False, with nothing found, when it would
  /// take a triangle that `owned` refuses. Reads only.
  template <class Owned>
  bool find_cavity(TriangleId t, VertexId p, CavityScratch& s, Owned&& owned) const {
    s.cavity.assign(1, t);
    s.boundary.clear();
    s.stack.clear();
    // Edges to look across, last first: round the cavity counter-clockwise, so that its
    // boundary comes out in order.
    const Link base = static_cast<Link>(3 * t);
    s.stack.push_back(base + 2);
    s.stack.push_back(base + 1);
    s.stack.push_back(base);
    while (!s.stack.empty()) {
      const Link e = s.stack.back();
      s.stack.pop_back();
      const Link l = link_[e];
      if (l != kNoLink) {
        const auto u = static_cast<TriangleId>(l / 3);
        const std::size_t ub = 3 * std::size_t{u};
        if (vertices_.incircle(v_[ub], v_[ub + 1], v_[ub + 2], p) > 0) {
          if (!owned(u)) return false;
          s.cavity.push_back(u);
          // Entered by its edge j: the other two, counter-clockwise from there.
          const int j = l % 3;
          s.stack.push_back(static_cast<Link>(ub) + prev3(j));
          s.stack.push_back(static_cast<Link>(ub) + next3(j));
          continue;
        }
      }
      const int i = e % 3;
      const std::size_t tb = static_cast<std::size_t>(e - i);
      s.boundary.push_back({v_[tb + next3(i)], v_[tb + prev3(i)], l});
    }
    return true;
  }

  /// Replaces the cavity in s by the fan of p round its boundary: the cavity's slots, then two
  /// from `pool`. Returns one of the new triangles.
  TriangleId fill_cavity(VertexId p, CavityScratch& s, SlotPool& pool) {
    const std::size_t k = s.boundary.size();  // the cavity's size + 2
    s.slots.assign(s.cavity.begin(), s.cavity.end());
    s.slots.push_back(pool.take());
    s.slots.push_back(pool.take());
    s.replaced += s.cavity.size() - 1;
    for (std::size_t i = 0; i < k; ++i) {
      const TriangleId t = s.slots[i];
      const std::size_t tb = 3 * std::size_t{t};
      const CavityScratch::Boundary& e = s.boundary[i];
      v_[tb] = p, v_[tb + 1] = e.a, v_[tb + 2] = e.b;
      // Edge 0 (a -> b) is the boundary edge; edge 1 (b -> p) borders the next triangle of the
      // fan at its edge 2 (p -> b), and edge 2 the previous one at its edge 1.
      link_[tb] = e.outside;
      if (e.outside != kNoLink) link_[e.outside] = static_cast<Link>(tb);
      link_[tb + 1] = static_cast<Link>(3 * s.slots[i + 1 < k ? i + 1 : 0] + 2);
      link_[tb + 2] = static_cast<Link>(3 * s.slots[i > 0 ? i - 1 : k - 1] + 1);
    }
    return s.slots[0];
  }

  /// Inserts p with no regions: walks from `last` (left at a triangle by p), returns the
  /// vertex p coincides with (nothing inserted), else kNoVertex.
  VertexId insert(VertexId p, TriangleId& last, CavityScratch& s, SlotPool& pool) {
    last = walk(last, p);
    if (const VertexId hit = coincident(last, p); hit != kNoVertex) return hit;
    find_cavity(last, p, s, [](TriangleId) { return true; });
    last = fill_cavity(p, s, pool);
    return kNoVertex;
  }

  /// Marks slot t free (no triangle): the finish leaves it out.
  void free_slot(TriangleId t) {
    const std::size_t tb = 3 * std::size_t{t};
    v_[tb] = v_[tb + 1] = v_[tb + 2] = kNoVertex;
    link_[tb] = link_[tb + 1] = link_[tb + 2] = kNoLink;
  }
  /// `count` slots past those in use, for a pool.
  TriangleId grow(TriangleId count) {
    const TriangleId first = top_;
    check_room(top_ + count);
    top_ += count;
    return first;
  }
  /// What `pool` did not hand out becomes free slots (or, at the top, no slots at all).
  void give_back(SlotPool& pool);

  /// The arrays, for the finish, which turns them into the output in place.
  std::vector<VertexId>& vertex_array() { return v_; }
  std::vector<Link>& link_array() { return link_; }

 private:
  void check_room(TriangleId end) const;

  Vertices vertices_;
  std::vector<VertexId> v_;
  std::vector<Link> link_;
  TriangleId top_ = 0;
};

}  // namespace ridt::detail
