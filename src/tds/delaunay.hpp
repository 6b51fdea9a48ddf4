// The walking kernel: the Delaunay triangulation as the one mutable triangulation (tds/tds.hpp)
// holds it, with the bounding vertices and the kernel's exact predicates (symbolic, and the
// lattice forms where every point lies on a small lattice). Points are located by walking and
// inserted by Bowyer-Watson cavities. It serves the serial method with Locate::Walk
// (methods/serial_walk.cpp), the partition method (methods/partition.cpp), whose threads share
// one structure without a lock, and the incremental triangulation (variants/incremental.cpp).
//
// An insertion replaces the m triangles whose circumcircle holds the new point p (the cavity:
// with exact predicates and the symbolic perturbation it is a disk whose triangles have all
// their vertices on its boundary, so its dual graph is a tree) by the m + 2 triangles that join
// p to the cavity's boundary edges, writing m of them over the cavity's slots. A triangulation
// of k points thus always fills exactly 2k + 1 slots, and the arrays made for n points
// (SlotArrays) never grow.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "output/output.hpp"
#include "predicates/symbolic.hpp"
#include "ridt/ridt.hpp"
#include "runtime/memory.hpp"
#include "tds/tds.hpp"

namespace ridt::detail {

/// The walking kernel's two arrays, made before it: room for the 2n + 1 slots of n points,
/// their pages made present by up to `threads` threads. Until the kernel takes them their
/// memory may serve other work (words(), numbers()): pages already present cost nothing more,
/// where fresh ones are faulted in and zeroed one by one, which on a virtual machine can cost
/// several times the work done in them.
struct SlotArrays {
  std::vector<VertexId> v;
  std::vector<Link> link;

  SlotArrays(std::uint64_t n, unsigned threads);
  /// The vertex array's memory as 3n + 1 words, and the link array's as 6n + 3 unsigned
  /// numbers, for work done before the kernel is made; what is written there is lost.
  std::span<std::uint64_t> words();
  /// After words(): the vertex numbers begin their lifetime again (their values unspecified).
  void vertices_again() { std::uninitialized_default_construct_n(v.data(), v.size()); }
  std::span<std::uint32_t> numbers() {
    // An unsigned view of signed numbers is an allowed alias.
    return {reinterpret_cast<std::uint32_t*>(link.data()), link.size()};
  }
};

class DelaunayTds : public Tds {
 public:
  /// The bounding triangle alone, in `arrays` (made for vertices.n() points).
  DelaunayTds(const Vertices& vertices, SlotArrays arrays);
  /// The bounding triangle alone, in arrays that grow (the incremental triangulation).
  explicit DelaunayTds(const Vertices& vertices);
  /// The triangles already in `tds`, of `vertices`.
  DelaunayTds(const Vertices& vertices, Tds&& tds) : Tds(std::move(tds)), vertices_(vertices) {}

  const Vertices& vertices() const { return vertices_; }
  /// The points changed (more points, their array moved): the bounding vertices must be at
  /// the same ids as before.
  void set_vertices(const Vertices& vertices) { vertices_ = vertices; }

  /// Tds::walk to vertex p's point, from triangle t to one whose closure holds it.
  /// kLattice: the predicates' lattice forms (Vertices::lattice() must hold).
  TriangleId walk(TriangleId t, VertexId p) const {
    walk(t, p, kAnywhere);
    return t;
  }
  template <bool kLattice = false, class Cross>
  bool walk(TriangleId& t, VertexId p, Cross&& cross) const {
    const Point q = vertices_[p];
    return static_cast<bool>(Tds::walk(
        t, [&](VertexId a, VertexId b) { return vertices_.orient<kLattice>(a, b, p, q); }, cross));
  }

  /// Whether point p coincides with a vertex of triangle t (whose closure holds it): the
  /// vertex, or kNoVertex. (A symbolic bounding vertex's point is NaN, equal to none.)
  VertexId coincident(TriangleId t, VertexId p) const {
    const Point& q = vertices_[p];
    for (int i = 0; i < 3; ++i)
      if (const VertexId w = vertex(t, i); vertices_[w] == q) return w;
    return kNoVertex;
  }

  /// Tds::find_cavity of p, which triangle t holds (its closure; p is no vertex of it), with
  /// the kernel's in-circle test; `owned` is its `enter`. Reads only.
  template <bool kLattice = false, class Owned>
  bool find_cavity(TriangleId t, VertexId p, CavityScratch& s, Owned&& owned) const {
    const Point q = vertices_[p];
    return Tds::find_cavity(
        t, s, [&](const VertexId* w) { return vertices_.incircle<kLattice>(w[0], w[1], w[2], p, q) > 0; }, owned,
        kNoWall, kNotSeen);
  }

  /// Inserts p with no regions: walks from `last` (left at a triangle by p), returns the
  /// vertex p coincides with (nothing inserted), else kNoVertex.
  template <bool kLattice = false>
  VertexId insert(VertexId p, TriangleId& last, CavityScratch& s, SlotPool& pool) {
    walk<kLattice>(last, p, kAnywhere);
    if (const VertexId hit = coincident(last, p); hit != kNoVertex) return hit;
    find_cavity<kLattice>(last, p, s, kAnywhere);
    last = fill_cavity(p, s, pool);
    return kNoVertex;
  }

 private:
  Vertices vertices_;
};

/// The walking kernel's finish: its arrays become the output's, in place
/// (tds/delaunay_finish.cpp). Vertex v is input point input_index[v]. With `links`, the
/// neighbours are links (3u + j: the neighbour u and its edge j), as the Tds keeps them.
Triangulation finish_walking(DelaunayTds& tds, const std::vector<std::uint32_t>& input_index,
                             const std::vector<DuplicateHit>& duplicates, const Options& options, unsigned threads,
                             bool links = false);

/// The same for a structure of other faces (the regular triangulation's): the slots whose
/// three vertices are below n (not at infinity, not free) become `triangles` and `neighbors`
/// (-1 across from a corner where the face beside is not kept), in place and on threads.
void finish_in_place(Tds& tds, std::uint32_t n, const std::vector<std::uint32_t>& input_index, unsigned threads,
                     std::vector<VertexId>& triangles, std::vector<std::int32_t>& neighbors);

/// triangulate() (src/triangulate.cpp), its result's neighbours given as links (3u + j) where
/// `linked` comes back true: where the walking kernel made it and no canonical order was asked
/// (the library's own callers then make a Tds without searching each neighbour's edge). Else
/// they are triangle ids, as triangulate() gives them.
Triangulation triangulate_linked(std::span<const Point> points, const Options& options, bool& linked);

/// triangulate() (src/triangulate.cpp) with each vertex numbered by its place in the insertion
/// order: vertex v is input point order.order[v], and order.points[v] that point (the three
/// after the n points are not points). The duplicates are places too (the least place of a
/// group standing for it). For a caller that reads the triangles' points: in that order, points
/// of nearby triangles lie near each other.
struct InOrder {
  std::vector<std::uint32_t> order;
  Block<Point> points;
};
Triangulation triangulate_in_order(std::span<const Point> points, const Options& options, InOrder& order);

}  // namespace ridt::detail
