// The Delaunay triangulation on the sphere and its Voronoi diagram, decided exactly.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "ridt/check.hpp"
#include "ridt/ridt.hpp"

namespace ridt {

/// The Delaunay triangulation of points on a sphere: the convex hull of the points as given
/// (for points on a sphere its faces are the triangles whose circles hold no other point).
struct SphericalTriangulation {
  /// #T by 3 input indices, counter-clockwise seen from outside.
  std::vector<VertexId> triangles;
  /// #T by 3: the triangle across from corner i.
  std::vector<std::int32_t> neighbors;
  /// Copies dropped, each with the input index that stands for it (the least of the equal
  /// points), sorted by `dropped`.
  std::vector<Duplicate> duplicates;
  /// Points strictly inside the hull of the others, so on no face (a point given a rounding
  /// below the sphere among close neighbours), sorted.
  std::vector<VertexId> hidden;

  std::size_t size() const { return triangles.size() / 3; }
};

/// The convex hull of `points` in space, by an exact orientation test with a symbolic
/// perturbation (four points on one circle of the sphere get one answer, whatever their order
/// in the input), built by randomized incremental insertion; `threads` (0: the machine's) sort
/// the points, insert them and write the result, the same on any number. Throws InputError for a point that is not finite, for fewer
/// than four distinct points, where all are coplanar, and where they are so nearly coplanar
/// that no double lies strictly inside the fattest tetrahedron of them ("too nearly coplanar":
/// a few units in the last place from flat).
SphericalTriangulation triangulate_sphere(std::span<const Point3> points, unsigned threads = 0);

/// The Voronoi diagram on the sphere of centre `centre` and radius `radius`: a vertex for each
/// triangle (the point of the sphere its outward normal points to: the centre of its circle,
/// equally far from its three corners; the normal within a relative 2^-50 of the exact one), and for each input point its cell, as the triangles
/// round it, counter-clockwise seen from outside (empty for a copy or a hidden point).
struct SphericalVoronoi {
  std::vector<Point3> vertices;
  std::vector<std::uint32_t> region_start;  ///< #points + 1: cell i is regions[start[i], start[i + 1])
  std::vector<std::uint32_t> regions;
  /// With `areas`: each cell's area, from the solid angles of the triangles it fans into (Van
  /// Oosterom and Strackee's formula, with the triple product taken of differences; summed as
  /// the argument of a product of complex numbers, one arc tangent a cell). Where all
  /// the points lie on one great circle (within rounding) the cells are lunes whose corners are
  /// antipodal, and their areas are not computed reliably (Python's SphericalVoronoi refuses
  /// such points, as scipy's does).
  std::vector<double> areas;
};

SphericalVoronoi spherical_voronoi(const SphericalTriangulation& t, std::span<const Point3> points,
                                   const Point3& centre, double radius, bool areas = true, unsigned threads = 0);

/// The length of the shortest edge of `t`: the distance between the closest two of the points
/// it joins (the closest pair of distinct points of a sphere is a Delaunay edge); HUGE_VAL
/// where there is none. Correctly rounded squares where they neither underflow nor overflow,
/// else the lengths themselves (std::hypot).
double shortest_edge(const SphericalTriangulation& t, std::span<const Point3> points, unsigned threads = 0);

/// Linear interpolation on the sphere: each query's direction from `centre` is located in the
/// triangle whose cone from the centre holds it (a walk from the last query's), and its value
/// is the combination of the corners' values (k a point, point-major) whose weights are the
/// ratios of the volumes det[q, b, c] : det[a, q, c] : det[a, b, q] about the centre (the
/// barycentric coordinates of the query's central projection onto the triangle's plane), each
/// volume within a relative 2^-50 of the exact one. `fill` (NaN) where no triangle facing away
/// from the centre holds the query (the points in one hemisphere, the query beyond them).
/// Returns queries.size() * k values.
std::vector<double> interpolate_sphere_linear(const SphericalTriangulation& t, std::span<const Point3> points,
                                              std::span<const double> values, std::size_t k,
                                              std::span<const Point3> queries, const Point3& centre,
                                              double fill = std::numeric_limits<double>::quiet_NaN(),
                                              unsigned threads = 0);

/// Natural-neighbour (Sibson) interpolation on the sphere: each query's weights are the areas
/// (spherical, as solid angles) that its Voronoi cell on the sphere would take from its natural
/// neighbours' cells were it inserted, its point on the sphere taken at the mean distance of the
/// located triangle's corners from `centre`; the cells' vertices as spherical_voronoi's (each
/// within a bound however thin its triangle). The weights are positive and sum to 1, the value
/// at a data point is its own, and it is continuous. Where the query's point lies on or below
/// its triangle's plane (within rounding of a data point, or of the edge of a triangle a few
/// ulps across) the linear weights of that triangle; `fill` where no triangle facing away from
/// the centre holds the query, or its cavity reaches one that faces the centre (beyond the
/// points of one hemisphere). Returns queries.size() * k values.
std::vector<double> interpolate_sphere_natural(const SphericalTriangulation& t, std::span<const Point3> points,
                                               std::span<const double> values, std::size_t k,
                                               std::span<const Point3> queries, const Point3& centre,
                                               double fill = std::numeric_limits<double>::quiet_NaN(),
                                               unsigned threads = 0);

/// Checks exactly that `triangles` (#T by 3 input indices) is the convex hull of `points` as
/// triangulate_sphere decides it: a closed surface of consistently oriented triangles, every
/// edge convex (under the same perturbation), wrapped once round an inner point, every distinct
/// point a corner or inside it, every corner a distinct point.
CheckResult check_sphere(std::span<const Point3> points, std::span<const VertexId> triangles);

}  // namespace ridt
