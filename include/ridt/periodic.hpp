// The Delaunay triangulation of points on the flat torus (periodic boundary conditions) and
// its Voronoi cells, decided exactly.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ridt/check.hpp"
#include "ridt/ridt.hpp"

namespace ridt {

/// The flat torus [x0, x0 + width) x [y0, y0 + height), origin = (x0, y0): each point stands
/// for all its copies p + (i * width, j * height), i and j integers.
struct PeriodicDomain {
  Point origin{0, 0};
  double width = 1, height = 1;
};

/// Which copy of a point: p + (dx * width, dy * height). A triangle's offsets are a period or
/// two apart where the points are many; with few points in a long, narrow domain they can be
/// more, up to kMaxOffset (two bytes each: the offsets are a third of a large result's memory).
struct Offset {
  std::int16_t dx = 0, dy = 0;
  friend bool operator==(const Offset&, const Offset&) = default;
};
/// The largest offset triangulate_periodic gives (it refuses a domain that would need more).
inline constexpr int kMaxOffset = 1000;

/// The periodic Delaunay triangulation: the Delaunay triangulation of all the copies of the
/// points, which repeats with the domain, given by one triangle of each class of its copies.
/// With n distinct points it has exactly 2n triangles (the torus's Euler count), every one
/// with three neighbours.
struct PeriodicTriangulation {
  PeriodicDomain domain;
  /// #T by 3 input indices, counter-clockwise where the offsets place them. Corner 0 is the
  /// triangle's least index (and of its copies the least offset, x then y), at offset (0, 0);
  /// a small set may have two corners at copies of one point.
  std::vector<VertexId> triangles;
  /// #T by 3: the copy of corner i's point (points[triangles[3t + i]] + offsets[3t + i] scaled
  /// by the periods is the corner).
  std::vector<Offset> offsets;
  /// #T by 3: the triangle across from corner i, and the offset that moves that triangle (as
  /// its own offsets place it) onto the edge it shares with t.
  std::vector<std::int32_t> neighbors;
  std::vector<Offset> neighbor_offsets;
  /// Points at the same place as another (input indices; the least one is kept).
  std::vector<Duplicate> duplicates;

  std::size_t size() const { return triangles.size() / 3; }
};

/// The periodic Delaunay triangulation of `points`, which must lie in the domain (x0 <= x <
/// x0 + width, the same for y; exactly, not up to rounding). Decided by the exact predicates on
/// the copies' true coordinates (not their rounded ones), with the symbolic perturbation of
/// triangulate() (ties, as a lattice's cocircular squares, get one answer, in any input order).
/// From 4,096 points on: the triangles of the points' own triangulation (triangulate(), on
/// `threads` threads, 0: the machine's) whose circles lie inside the domain, and the rest from
/// the points near the domain's sides and their copies, inserted on the one mutable
/// triangulation; fewer points, or points on one line, all by the latter. Throws InputError
/// for no point, a point not finite or outside the domain, a width or height that is not
/// positive and finite, or points too few for a domain so long and narrow that copies more than
/// kMaxOffset periods away would be needed.
PeriodicTriangulation triangulate_periodic(std::span<const Point> points, const PeriodicDomain& domain,
                                           unsigned threads = 0);

/// The choices of a periodic triangulation; the triangles are the same whichever is made.
struct PeriodicOptions {
  unsigned threads = 0;  ///< 0: the machine's hardware threads
  /// Fill `neighbors` and `neighbor_offsets`. Off, they are left empty: a caller that needs only
  /// the triangles (a file of them, say) spares their memory (a third of the result's).
  bool neighbors = true;
};
PeriodicTriangulation triangulate_periodic(std::span<const Point> points, const PeriodicDomain& domain,
                                           const PeriodicOptions& options);

/// The periodic Voronoi diagram: vertex t the circumcentre of triangle t as its offsets place
/// it (each coordinate within 2^-44 of the circumradius, and the rounding of the copies'
/// coordinates), and each point's cell the circumcentres round it counter-clockwise, each
/// moved by its `cell_shifts` entry so that the cell surrounds the point where it is given.
/// The cells tile the domain: their areas add up to width * height.
struct PeriodicVoronoi {
  std::vector<Point> vertices;
  /// Point i's cell is cell_vertices[cell_offsets[i] .. cell_offsets[i + 1]) (a duplicate's is
  /// empty), each vertex moved by the same entry of cell_shifts (times the periods).
  std::vector<std::uint32_t> cell_offsets;
  std::vector<std::int32_t> cell_vertices;
  std::vector<Offset> cell_shifts;
};

/// The Voronoi cells of the periodic triangulation `t` of `points`. Throws InputError when `t`
/// does not fit the points.
PeriodicVoronoi periodic_voronoi(std::span<const Point> points, const PeriodicTriangulation& t);

/// Checks exactly that `triangles` with `offsets` is the periodic Delaunay triangulation of the
/// points as triangulate_periodic decides it: every triangle counter-clockwise and proper where
/// its offsets place it, every edge shared by exactly two triangles (copies matched by their
/// offsets), every edge locally Delaunay under the same perturbation, every vertex's triangles
/// once round it (so the triangles cover the torus once), 2n triangles, every distinct point a
/// vertex and no two at one place.
CheckResult check_periodic(std::span<const Point> points, const PeriodicDomain& domain,
                           std::span<const VertexId> triangles, std::span<const Offset> offsets);

}  // namespace ridt
