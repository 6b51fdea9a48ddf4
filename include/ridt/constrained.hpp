// Constrained Delaunay triangulations: points and segments between them.
#pragma once

#include <span>
#include <vector>

#include "ridt/ridt.hpp"

namespace ridt {

/// A constrained Delaunay triangulation: the triangulation's arrays, and the edges that make
/// up the segments. Where triangles were removed (Domain), `hull` is empty: the boundary is
/// then the edges with neighbour -1.
struct ConstrainedTriangulation : Triangulation {
  std::vector<VertexId> edges;  ///< the segments' edges, pairs (a, b) with a < b, sorted
};

/// The region a constrained triangulation covers: the convex hull, or what the segments
/// enclose, less holes (Triangle's -c, and its holes).
struct Domain {
  /// Keep every triangle of the convex hull (the default); false: remove those that can be
  /// reached from the hull without crossing a segment, leaving what the segments enclose.
  bool convex_hull = true;
  /// Seeds of holes: the triangle that holds each (the first found where one lies on an edge)
  /// and every triangle reached from it without crossing a segment are removed. A seed outside
  /// the convex hull removes nothing.
  std::vector<Point> holes;
};

/// The constrained Delaunay triangulation of `points` with `segments` (pairs of indices into
/// `points`, a flat array a0, b0, a1, b1, ...), its boundary the convex hull: every segment is
/// a union of edges (split at the points that lie exactly on it), and every other edge is
/// locally Delaunay, so that no triangle's circle holds a point its triangle can see without
/// crossing a segment (check_constrained validates it). Exact predicates throughout; the
/// Delaunay triangulation is made by triangulate() with `options`, the segments then inserted
/// one by one, each replacing the triangles it crosses by the constrained Delaunay
/// triangulations of the polygons on either side. A segment's end that is a duplicate stands
/// for its group's kept point; a segment whose ends coincide is left out. Throws InputError
/// for an index out of range, an odd list, or two segments that cross at a point that is not
/// one of the points (splitting them there is not done yet), and for a hole's coordinate that
/// is not finite. `domain` says which triangles to keep.
ConstrainedTriangulation triangulate_constrained(std::span<const Point> points, std::span<const VertexId> segments,
                                                 const Options& options = {}, const Domain& domain = {});

}  // namespace ridt
