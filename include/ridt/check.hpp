// An exact validator for Delaunay triangulations, independent of the triangulator's code
// (it shares only the exact predicates).
#pragma once

#include <functional>
#include <span>
#include <string>

#include "ridt/ridt.hpp"

namespace ridt {

/// The verdict of check().
struct CheckResult {
  bool valid = false;
  std::string message;  ///< one line: what was checked, or the first problem found
  std::size_t problems = 0;  ///< number of problems found
};

/// The most triangles check() takes: its edge table counts the 3 sides of each in 32 bits.
inline constexpr std::size_t kCheckMaxTriangles = 0xffffffffu / 3;

/// Checks with exact arithmetic that `triangles` (#T by 3, 0-based indices into `points`) is a
/// Delaunay triangulation of the distinct points:
///  - every index is in range; every triangle is counter-clockwise and not degenerate;
///  - each directed edge is used at most once;
///  - each interior edge is locally Delaunay (the opposite vertex is not strictly inside);
///  - the boundary edges are exactly the convex hull of the distinct points (collinear hull
///    points included as vertices);
///  - every distinct point is a vertex, exactly once (no two vertices coincide);
///  - Euler: #T = 2V - 2 - H for V vertices and H of them on the hull.
/// An empty triangle list is valid only when there are fewer than three distinct points or
/// all of them are collinear. Points must be finite. Throws InputError for more than
/// kCheckMaxTriangles triangles (the triangulation of some 715 million points).
CheckResult check(std::span<const Point> points, std::span<const VertexId> triangles);

/// Triangles handed over a chunk at a time: a TriangleFeed, called, passes every triangle
/// once to the sink, in chunks of whole triangles (each chunk #T by 3 indices), and the same
/// triangles in the same order on every call.
using TriangleSink = std::function<void(std::span<const VertexId>)>;
using TriangleFeed = std::function<void(const TriangleSink&)>;

/// check() for triangulations too large to hold with its edge table: the triangles are read
/// from `feed` in passes and never held all at once. Beside the points it keeps 5 bytes a
/// point, the boundary's edges, the few points near the convex hull, and per pass at most
/// `side_bytes` of sides (12 bytes a side; 0: a quarter of available_memory()), each pass
/// after the first checking the edges of a range of vertices: about 36 bytes a triangle over
/// all passes. Its verdict is check()'s; the message names the same kind of problem, but where
/// there are several, not always the same first one (and two vertices at one point show as
/// the boundary they make, not by name). Work on `threads` (0: the hardware's). With no
/// triangle from the feed, check() in memory. Any number of triangles. Throws InputError where
/// a pass gets other triangles than the first did.
CheckResult check_in_passes(std::span<const Point> points, const TriangleFeed& feed, std::size_t side_bytes = 0,
                            unsigned threads = 0);

/// The same for a constrained Delaunay triangulation of `points` with `segments` (pairs of
/// indices into `points`, a flat array a0, b0, a1, b1, ...), its boundary the convex hull:
///  - every segment is a union of edges: it is followed from end to end along edges through
///    the points that lie exactly on it (a segment's end stands for its group of equal points);
///  - an interior edge need be locally Delaunay only where it is not part of a segment (with
///    the rest, this makes every triangle's circle hold no point that its triangle can see
///    without crossing a segment);
///  - and everything else check() asks. Without segments it is check().
CheckResult check_constrained(std::span<const Point> points, std::span<const VertexId> triangles,
                              std::span<const VertexId> segments);

/// What a constrained triangulation or quality mesh (triangulate_constrained's) must be.
struct MeshSpec {
  /// The mesh's segment edges (pairs, ConstrainedTriangulation::edges): each must be an edge;
  /// they alone may be not locally Delaunay; every boundary edge must be one of them or lie on
  /// the convex hull. Empty, with `segments`: the mesh's edges that lie along the segments (a
  /// mesh from files that do not name its segment edges, as Triangle's without -e).
  std::span<const VertexId> edges;
  /// The input's segments (pairs of indices below `input_points`): each must be a chain of
  /// `edges` from end to end through points added (index >= input_points) or points on it.
  std::span<const VertexId> segments;
  std::size_t input_points = 0;  ///< points before this index are the input's (0: all)
  std::span<const Point> holes;  ///< seeds no triangle may hold, inside or on its boundary
  /// No triangle with an angle below `min_angle` degrees (but those beside an input angle
  /// below 60 degrees between two segments, which refinement cannot mend, and those with an
  /// edge below 2^-39 of the points' extent, which it does not split: counted apart) or an
  /// area above `max_area`; 0: not checked.
  double min_angle = 0;
  double max_area = 0;
};

/// Checks a constrained triangulation or quality mesh: every triangle counter-clockwise and
/// not degenerate, each directed edge used once, every interior edge locally Delaunay but the
/// segment edges, and all that `spec` asks; exact predicates for all but the angles and areas
/// (computed in long double, with a relative tolerance of 1e-9). `points` are every vertex:
/// the input's, then those added.
CheckResult check_mesh(std::span<const Point> points, std::span<const VertexId> triangles, const MeshSpec& spec);

/// Checks six-node triangles (second_order's, Triangle's -o2) beside their corners, which check()
/// or check_mesh() validate: `middles` (3 a triangle of `triangles`) are, for each corner i, the
/// node of the edge across from it, each exactly the mean of the edge's ends rounded once
/// (std::midpoint, coordinate by coordinate), the same node from the edge's two triangles, no
/// node the middle of two edges, and none a corner of any triangle.
CheckResult check_second_order(std::span<const Point> points, std::span<const VertexId> triangles,
                               std::span<const VertexId> middles);

/// Checks with exact arithmetic that `triangles` is the farthest-point Delaunay triangulation
/// of `points` (triangulate_furthest_site's, counter-clockwise): every triangle
/// counter-clockwise and not degenerate; each directed edge used at most once; across each
/// interior edge the opposite vertex inside or on the circle (locally farthest-point
/// Delaunay, which with the boundary below makes every circle hold every point); the boundary
/// edges exactly the convex hull's corners in order; no other vertex. Empty is valid only
/// when the points have fewer than three hull corners.
CheckResult check_furthest_site(std::span<const Point> points, std::span<const VertexId> triangles);

/// Checks with exact arithmetic that `corners` is the convex hull of `points` (convex_hull()'s,
/// ridt/hull.hpp): indices in range; at least three corners, each a strict left turn (so no
/// copies and no point on a side among them) and the polygon round once, counter-clockwise;
/// every point inside it or on it (located in the fan from the first corner by bisection,
/// on `threads` threads). Empty is valid only when fewer than three distinct points are given
/// or all are collinear.
CheckResult check_convex_hull(std::span<const Point> points, std::span<const VertexId> corners, unsigned threads = 0);

}  // namespace ridt
