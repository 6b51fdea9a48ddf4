// A mesh given to be refined (refine_mesh, Triangle's -r): its neighbours found from its
// triangles, and the checks that it is one.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "constrained/cdt.hpp"
#include "ridt/ridt.hpp"

namespace ridt::detail {

/// The neighbours of `triangles` (3 a triangle, as Triangulation::neighbors has them: -1 on
/// the boundary). Throws InputError where a triangle is clockwise or has no area, or where two
/// triangles run along an edge the same way (they overlap, or one is the other turned over).
std::vector<std::int32_t> neighbours_of(std::span<const Point> points, std::span<const VertexId> triangles);

/// The mesh as given, kept beside the one refined: each triangle of that one takes the region
/// (bound and attribute) of the given triangle that holds its centroid.
class GivenMesh {
 public:
  /// `pts` (whose first points are the given mesh's, as the mesh refined has them) must outlive this.
  GivenMesh(const std::vector<Point>& pts, std::vector<VertexId> tris, std::vector<std::int32_t> nbrs)
      : pts_(pts), tris_(std::move(tris)), nbrs_(std::move(nbrs)) {}

  /// The given triangle whose closure holds p, found by a walk from `hint` (a triangle near
  /// it), else, where the walk leaves the mesh or circles (the given mesh need not be
  /// Delaunay), by every triangle in turn; `hint` where none holds it.
  std::uint32_t locate(const Point& p, std::uint32_t hint) const;
  /// The region of m's triangle t, its centroid located from its region now.
  std::int32_t region_of(const Cdt& m, std::uint32_t t) const;

 private:
  const std::vector<Point>& pts_;
  std::vector<VertexId> tris_;
  std::vector<std::int32_t> nbrs_;
};

/// Throws InputError where the triangles about a vertex of m, taken in turn across their
/// shared edges, turn round it more than once (or, closing round it, other than once): they
/// overlap there. Exact: directions compared by half-plane, then by orientation.
void check_fans(const Cdt& m);

}  // namespace ridt::detail
