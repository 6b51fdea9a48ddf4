// Interpolation of values given at a triangulation's points: nearest, linear (barycentric) and
// natural neighbour (Sibson).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "ridt/ridt.hpp"

namespace ridt {

/// Values at the points: `components` numbers a point, row by row (point i's are
/// data[i * components .. (i + 1) * components)).
struct Values {
  std::span<const double> data;
  std::size_t components = 1;
};

/// For each query, the linear interpolant of the triangle that holds it (barycentric
/// coordinates), exact on linear functions up to rounding; `fill` outside the convex hull or
/// for a query that is not finite. With `hull_tolerance` > 0 (kScipyTolerance: scipy's
/// interpolators'), a query outside the hull that locate with that tolerance gives a hull
/// triangle is answered from that triangle (its coordinates there just below 0), as scipy's
/// LinearNDInterpolator and CloughTocher2DInterpolator answer it; the natural-neighbour
/// interpolant answers such a query as on the hull edge, linearly. The result has queries.size() * values.components numbers,
/// row by row. `t` is a result of triangulate on `points`; a dropped duplicate's value is not
/// read (the point that stands for it gives the value). Runs on `threads` threads (0: the
/// machine's hardware threads). Throws InputError for sizes that do not match.
std::vector<double> interpolate_linear(std::span<const Point> points, const Triangulation& t, Values values,
                                       std::span<const Point> queries,
                                       double fill = std::numeric_limits<double>::quiet_NaN(), unsigned threads = 1,
                                       double hull_tolerance = 0);

/// The same with Sibson's natural-neighbour coordinates: the share of each point's Voronoi
/// cell that the query's cell would take were it inserted. Smooth (C1 away from the points),
/// exact on linear functions up to rounding, equal to the data at the points; which points
/// are natural neighbours is decided exactly (the in-circle predicate). On the hull's edges it
/// is linear along the edge, its limit from inside.
std::vector<double> interpolate_natural_neighbor(std::span<const Point> points, const Triangulation& t, Values values,
                                                 std::span<const Point> queries,
                                                 double fill = std::numeric_limits<double>::quiet_NaN(),
                                                 unsigned threads = 1, double hull_tolerance = 0);

/// The same two, writing into `out` (queries.size() * values.components numbers) instead of a
/// new vector: for callers that own the memory (a numpy array, a mapped file).
void interpolate_linear(std::span<const Point> points, const Triangulation& t, Values values,
                        std::span<const Point> queries, std::span<double> out,
                        double fill = std::numeric_limits<double>::quiet_NaN(), unsigned threads = 1,
                        double hull_tolerance = 0);
void interpolate_natural_neighbor(std::span<const Point> points, const Triangulation& t, Values values,
                                  std::span<const Point> queries, std::span<double> out,
                                  double fill = std::numeric_limits<double>::quiet_NaN(), unsigned threads = 1,
                                  double hull_tolerance = 0);

/// The nodes of a grid as queries: node (i, j) is (x[i], y[j]). Each axis is finite and
/// strictly increasing or strictly decreasing. Node (i, j)'s answer is row j * x.size() + i of
/// the result (rows of constant y, an image's order), or row i * y.size() + j when x_major
/// (the order of numpy.mgrid).
struct Grid {
  std::span<const double> x, y;
  bool x_major = false;

  std::size_t size() const { return x.size() * y.size(); }
};

/// Interpolation at every node of a grid: the answers of the calls above at the nodes, found
/// without locating them one by one. Each triangle visits the nodes in its bounding box and
/// takes those it holds (exact orientation tests; a node on an edge or at a vertex goes to one
/// of its triangles only), so the cost grows with the triangles and the nodes, not with walks.
/// `hull_tolerance` > 0 then gives the nodes just outside the hull to the hull triangles that
/// accept them (a node beside a hull corner, near two, to one of them).
/// Throws InputError for an axis that is not finite and monotone, or sizes that do not match.
void interpolate_linear(std::span<const Point> points, const Triangulation& t, Values values, const Grid& grid,
                        std::span<double> out, double fill = std::numeric_limits<double>::quiet_NaN(),
                        unsigned threads = 1, double hull_tolerance = 0);
void interpolate_natural_neighbor(std::span<const Point> points, const Triangulation& t, Values values,
                                  const Grid& grid, std::span<double> out,
                                  double fill = std::numeric_limits<double>::quiet_NaN(), unsigned threads = 1,
                                  double hull_tolerance = 0);

/// The barycentric coordinates of q in the counter-clockwise triangle (a, b, c), not
/// degenerate: weight i is the area of the triangle with q in corner i's place over the whole
/// triangle's. Each is within 2^-44 of its exact value: double precision where the
/// orientation filter vouches for it, exact arithmetic where it cannot (slivers, q on or next
/// to a side, huge or tiny coordinates). q at a corner gets exactly 1 there and 0 elsewhere; q
/// on a side exactly 0 for the opposite corner.
std::array<double, 3> barycentric(const Point& a, const Point& b, const Point& c, const Point& q);

/// Twice the signed area of (a, b, c), positive counter-clockwise, within a relative 2^-50 of
/// the exact value (exact arithmetic where double precision cannot tell).
double doubled_area(const Point& a, const Point& b, const Point& c);

/// scipy.spatial.Delaunay's `transform`: for triangle t, the 2 x 2 matrix T and the point r
/// (its third corner) with which (w0, w1) = T (x - r) are x's first two barycentric
/// coordinates, written as out[6 t .. 6 t + 6) = T row by row, then r. The determinant is
/// exact (doubled_area); where the triangle is so thin that T's reciprocal condition number
/// is below 2^-40, T's entries are NaN, as scipy's are for its near-degenerate simplices.
void barycentric_transforms(std::span<const Point> points, std::span<const VertexId> triangles, std::span<double> out,
                            unsigned threads = 1);

/// Gradients for the cubic (Clough-Tocher) interpolant, as scipy's
/// estimate_gradients_2d_global finds them: those that minimise, over the triangulation's
/// edges, the integral of the squared second derivative of the cubic along each edge that the
/// values and gradients at its ends define (Nielson's minimum-norm network). Solved by sweeps
/// over the points, each point's gradient set to the best for its neighbours' (Gauss-Seidel;
/// the points taken along a Hilbert curve in blocks, blocks that share no edge on `threads`
/// threads at once, the same numbers for any thread count), from each point's best-fitting plane through its
/// neighbours' values, until a sweep changes no gradient by more than `tol` (relative to the
/// gradient where it exceeds 1) or after `maxiter` sweeps. `gradients` receives
/// points.size() * values.components * 2 numbers: for point i and component c, d/dx at
/// 2 (i * components + c) and d/dy after it; a duplicate left out gets its kept point's.
/// Returns the sweeps made, or 0 when `maxiter` were not enough (the gradients are then those
/// of the last sweep). Linear data get their exact gradient. Throws InputError for sizes that
/// do not match, a tol that is not positive or a maxiter below 1.
int estimate_gradients(std::span<const Point> points, const Triangulation& t, Values values,
                       std::span<double> gradients, double tol = 1e-6, int maxiter = 400, unsigned threads = 1);

/// The piecewise cubic Clough-Tocher interpolant: each triangle split at its centroid into
/// three cubic pieces that take the values and `gradients` (laid out as estimate_gradients
/// writes them) at the corners, continuously differentiable inside and across the triangles;
/// the derivative across each side is linear along it, taken along the line between the
/// centroids of the two triangles that share it (across a hull side, along its normal), as
/// scipy's CloughTocher2DInterpolator does. Exact on quadratics whose gradients are given.
/// The piece is chosen and evaluated with the exact barycentric coordinates (barycentric), so
/// at a data point the answer is its value. `fill` outside the hull; on threads.
void interpolate_clough_tocher(std::span<const Point> points, const Triangulation& t, Values values,
                               std::span<const double> gradients, std::span<const Point> queries, std::span<double> out,
                               double fill = std::numeric_limits<double>::quiet_NaN(), unsigned threads = 1,
                               double hull_tolerance = 0);
void interpolate_clough_tocher(std::span<const Point> points, const Triangulation& t, Values values,
                               std::span<const double> gradients, const Grid& grid, std::span<double> out,
                               double fill = std::numeric_limits<double>::quiet_NaN(), unsigned threads = 1,
                               double hull_tolerance = 0);

/// scipy's griddata(method='cubic') onto a grid: the Clough-Tocher interpolant at the grid's
/// nodes with the gradients that estimate_gradients(tol, maxiter) finds, in one call that
/// numbers the points once for both and passes nothing between them through the caller's
/// order; the same numbers as those two calls. Returns estimate_gradients' count of sweeps (0:
/// they did not settle within maxiter).
int griddata_cubic(std::span<const Point> points, const Triangulation& t, Values values, const Grid& grid,
                   std::span<double> out, double fill = std::numeric_limits<double>::quiet_NaN(), double tol = 1e-6,
                   int maxiter = 400, unsigned threads = 1, double hull_tolerance = 0);
/// The same of the points' own Delaunay triangulation, made here (Method::Auto on `threads`)
/// with the points already in the order the gradients and the answers read them: the same
/// numbers as triangulate and the call above, in less time and memory. Returns -1 where the
/// points have no triangle (fewer than three distinct ones, or all on a line): `out` is then
/// `fill` throughout. Non-finite points throw InputError, as triangulate does.
int griddata_cubic(std::span<const Point> points, Values values, const Grid& grid, std::span<double> out,
                   double fill = std::numeric_limits<double>::quiet_NaN(), double tol = 1e-6, int maxiter = 400,
                   unsigned threads = 1, double hull_tolerance = 0);

/// For each query, the index of a nearest point among the triangulation's vertices (a greedy
/// walk on the Delaunay graph, which ends at a nearest one), or -1 for a query that is not
/// finite or when there is no triangle.
std::vector<std::int32_t> nearest_vertex(std::span<const Point> points, const Triangulation& t,
                                         std::span<const Point> queries, unsigned threads = 1);

}  // namespace ridt
