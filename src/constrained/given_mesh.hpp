// A mesh given to be refined (refine_mesh, Triangle's -r): its edges and neighbours found from
// its triangles, the checks that it is one, and the given triangles kept to locate points in.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "constrained/cdt.hpp"
#include "ridt/ridt.hpp"

namespace ridt::detail {

/// The edge slots of `triangles` (slot 3t + k: triangle t's edge from its corner k + 1 to its
/// corner k + 2), listed by their first end, each end's by their second. Throws InputError
/// where a triangle is clockwise or has no area, or where two triangles run along an edge the
/// same way (they overlap, or one is the other turned over). `triangles` must outlive it.
class MeshEdges {
 public:
  MeshEdges(std::span<const Point> points, std::span<const VertexId> triangles);
  /// The slot that runs from a to b, or kNoTriangle.
  std::uint32_t slot(VertexId a, VertexId b) const;
  /// The neighbours (3 a triangle, as Triangulation::neighbors has them: -1 on the boundary).
  std::vector<std::int32_t> neighbours() const;

 private:
  VertexId from(std::size_t s) const { return tris_[s - s % 3 + (s + 1) % 3]; }
  VertexId to(std::size_t s) const { return tris_[s - s % 3 + (s + 2) % 3]; }

  std::span<const VertexId> tris_;
  std::vector<std::uint32_t> start_, slots_;
};

/// The mesh as given, kept beside the one refined: each triangle of that one takes the region
/// (bound and attribute) of the given triangle that holds its centroid.
class GivenMesh {
 public:
  /// `pts` (whose first points are the given mesh's, as the mesh refined has them) must outlive this.
  GivenMesh(const std::vector<Point>& pts, const Tds& given) : pts_(pts), tds_(given.copy()), seen_(tds_.slots(), 0) {}

  /// The given triangle whose closure holds p, found by a walk from `hint` (a triangle near
  /// it), else, where the walk meets the boundary or circles (the given mesh need not be
  /// Delaunay), by a search outward from where it stopped, neighbour by neighbour; `hint` where
  /// none holds it.
  TriangleId locate(const Point& p, TriangleId hint) const;
  /// The region of m's triangle t, its centroid located from its region now.
  std::int32_t region_of(const Cdt& m, TriangleId t) const;

 private:
  bool holds(TriangleId t, const Point& p) const;
  TriangleId search(const Point& p, TriangleId from) const;

  const std::vector<Point>& pts_;
  Tds tds_;
  mutable std::vector<std::uint32_t> seen_;  // search's marks: the search's number, so none is cleared
  mutable std::uint32_t searches_ = 0;
};

/// Throws InputError where the triangles about a vertex of m, taken in turn across their
/// shared edges, turn round it more than once, or where two such fans at one vertex overlap
/// (one that closes round it must be its only one). Exact: directions compared by half-plane,
/// then by orientation. Pieces of the mesh that overlap without sharing a vertex pass (they are
/// check_one_layer's).
void check_fans(const Cdt& m);

/// Throws InputError, naming what it found, unless `triangles` (each counter-clockwise, no two
/// along an edge the same way, the fans about each vertex sound: check_fans) lie in one layer.
/// Exact, from the boundary alone (`neighbours` < 0): the constrained Delaunay triangulation
/// of its vertices with its edges as segments must find no two of them at one point, no edge
/// crossing another or passing through a vertex, and, counting across the boundary edges from
/// outside, no place the mesh covers twice (a piece inside another, or a strip that winds over
/// itself). `options`: method, threads and memory_limit for that triangulation.
void check_one_layer(std::span<const Point> points, std::span<const VertexId> triangles,
                     std::span<const std::int32_t> neighbours, const Options& options);

}  // namespace ridt::detail
