// The regular (weighted Delaunay) triangulation of weighted points and its power diagram,
// decided exactly.
#pragma once

#include <span>
#include <vector>

#include "ridt/check.hpp"
#include "ridt/ridt.hpp"
#include "ridt/voronoi.hpp"

namespace ridt {

/// A regular triangulation: the Triangulation's arrays (triangles counter-clockwise, the
/// neighbour across each corner or -1, the hull, the copies dropped), and the points that are
/// no vertex because others' weights hide them.
struct RegularTriangulation : Triangulation {
  /// Input indices of the points whose lift lies above the lower hull of the others' (whose
  /// power cell is empty), sorted. A copy (same point, same weight) is a duplicate instead.
  std::vector<VertexId> hidden;
};

/// The regular triangulation of points with weights: the projection of the lower convex hull
/// of the lifted points (x, y, x^2 + y^2 - w), the dual of their power diagram (with equal
/// weights, the Delaunay triangulation; a larger weight pulls the triangles' circles towards
/// its point). Decided by the exact power test with a symbolic perturbation (ties, as four
/// points on one orthogonal circle, get one answer in any input order: with equal weights
/// triangulate()'s), built by randomized incremental insertion on the one mutable triangulation
/// (a vertex at infinity closes it), in a biased randomized order along a Hilbert curve;
/// `threads` (0: the machine's) sort the points, insert them (rounds of 4096 points or more
/// shared among them) and write the result: the same triangles on any number, the same arrays
/// from run to run on one number. Points with the same
/// coordinates but different weights: the lighter is hidden. Throws InputError for a point or
/// weight that is not finite, `weights` not one a point, fewer than three distinct points, or
/// all of them collinear.
RegularTriangulation triangulate_regular(std::span<const Point> points, std::span<const double> weights,
                                         unsigned threads = 0);

/// The power diagram (Laguerre cells) of the weighted points, in Voronoi's layout: vertex t is
/// the power centre of triangle t of `t` (the point of equal power from its three corners; each
/// coordinate within 2^-44 of its distance from a corner and a unit in its last place of the
/// exact one), each vertex's cell the centres round it counter-clockwise (-1 between the two
/// rays of a cell on the hull, each ray along ray_direction), the ridges the triangulation's
/// edges. A hidden point has no cell (point_cell -1). Throws InputError when `t` does not fit.
Voronoi power_diagram(std::span<const Point> points, std::span<const double> weights, const Triangulation& t,
                      unsigned threads = 1);

/// Checks exactly that `triangles` is the regular triangulation of the weighted points as
/// triangulate_regular decides it: every triangle counter-clockwise and proper, every edge used
/// once each way at most, every interior edge locally regular under the same perturbation (which
/// makes the whole regular), the boundary the convex hull traversed once (corners in order, the
/// points between them on its sides), Euler's count, every distinct weighted point a vertex once
/// or hidden (its lift above the triangle that holds it), no two vertices at one place.
CheckResult check_regular(std::span<const Point> points, std::span<const double> weights,
                          std::span<const VertexId> triangles);

}  // namespace ridt
