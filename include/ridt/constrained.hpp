// Constrained Delaunay triangulations and quality meshes: points and segments between them.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "ridt/ridt.hpp"
#include "ridt/size_field.hpp"

namespace ridt {

/// A constrained Delaunay triangulation: the triangulation's arrays, the edges that make up
/// the segments, and the points it added. Vertex ids below the input's size are the input's
/// points; id n + k is steiner[k]. Where triangles were removed (Domain), `hull` is empty: the
/// boundary is then the edges with neighbour -1.
struct ConstrainedTriangulation : Triangulation {
  /// The fixed edges: the segments' pieces (and, where the triangulation was refined, the
  /// boundary's edges), pairs (a, b) with a < b, sorted.
  std::vector<VertexId> edges;
  /// Per edge of `edges`, the input segment it lies on (k for the pair at 2k of the segments
  /// given), or -1 for a boundary edge that lies on none. Where segments overlap, their shared
  /// pieces name the last of them; where two cross, each piece names its own.
  std::vector<std::int32_t> edge_segments;
  /// Points added: first where two segments cross (`crossings` of them, each the exact
  /// crossing rounded to the nearest doubles), then those of quality refinement.
  std::vector<Point> steiner;
  std::size_t crossings = 0;
  /// Per triangle, its region's attribute (Domain::regions); empty without regions.
  std::vector<double> attributes;
};

/// A region of the domain (Triangle's regional attributes and area constraints): every
/// triangle reached from `seed` without crossing a segment carries `attribute`, and its
/// triangles are refined to areas of at most `max_area` (<= 0: no bound of its own; a bound
/// refines even where Quality asks nothing).
struct Region {
  Point seed;
  double attribute = 0;
  double max_area = 0;
};

/// The region a constrained triangulation covers: the convex hull, or what the segments
/// enclose, less holes (Triangle's -c, and its holes); and its regions.
struct Domain {
  /// Keep every triangle of the convex hull (the default); false: remove those that can be
  /// reached from the hull without crossing a segment, leaving what the segments enclose.
  bool convex_hull = true;
  /// Seeds of holes: every triangle that holds one, inside or on its boundary (a seed on an
  /// edge or at a vertex empties the triangles on each side of it), and every triangle reached
  /// from those without crossing a segment are removed. A seed outside the convex hull removes
  /// nothing.
  std::vector<Point> holes;
  /// Regions, marked after the holes are removed; where two share triangles, the later wins.
  std::vector<Region> regions;
};

/// Delaunay refinement of the triangulation (Triangle's -q, -a, -Y): points added at
/// off-centres of bad triangles and on the segments those would encroach, the boundary's edges
/// treated as segments. Every triangle ends with no angle below `min_angle` and no area above
/// its bound, except the triangles at a small angle between two segments, which no point can
/// mend (check_quality names them).
struct Quality {
  double min_angle = 0;  ///< degrees, in [0, 34]; 0: no angle bound
  double max_area = 0;  ///< 0: no bound of all triangles (regions may still have their own)
  bool split_boundary = true;  ///< false: no point added on the boundary's segments (-Y)
  /// false: no point added on any segment, those inside the domain too, nor on the boundary
  /// (-YY); the segments stay whole (but where they cross), and a triangle whose point would
  /// fall on one may keep an angle below min_angle. Not with `conforming`.
  bool split_segments = true;
  std::size_t max_steiner = 0;  ///< stop after adding this many points (0: no limit)
  /// Conforming Delaunay (-D): segments split until no vertex lies in a subsegment's diametral
  /// circle, so that every edge, the segments' too, is Delaunay (with `split_boundary`).
  bool conforming = false;
  /// A test of the caller's own (Triangle's -u, its triunsuitable): a triangle for which it
  /// returns true is refined as one above the area bound is, at its off-centre. It is given the
  /// triangle's corners, counter-clockwise, and its area (in floating point; infinite or 0 where
  /// that overflows or underflows a double, with coordinates beyond about 10^154 or below
  /// 10^-154), and is called once for each triangle refinement makes or first sees, on the calling
  /// thread; what it throws comes out of the call. It must hold for no triangle small enough (as
  /// an area bound that depends on the position: `area > size(centroid)`), or refinement goes on
  /// until `max_steiner` or the memory left stops it.
  std::function<bool(const Point& a, const Point& b, const Point& c, double area)> unsuitable;
  /// A target edge length over the plane (ridt/size_field.hpp): no triangle's longest edge
  /// above the size at its centroid, but where the angle bound or the input forces one. The
  /// field is asked for the sizes of many triangles at once, on the calling thread.
  SizeField size;
  bool enabled() const { return min_angle > 0 || max_area > 0 || conforming || unsuitable || size; }
};

/// The constrained Delaunay triangulation of `points` with `segments` (pairs of indices into
/// `points`, a flat array a0, b0, a1, b1, ...): every segment is a union of edges (split at
/// the points that lie exactly on it, and where two segments cross, at their exact crossing
/// rounded to doubles, a point added), and every other edge is locally Delaunay, so that no
/// triangle's circle holds a point its triangle can see without crossing a segment
/// (check_constrained validates it). Exact predicates throughout; the Delaunay triangulation
/// is made by triangulate() with `options`, the segments then inserted one by one, each
/// replacing the triangles it crosses by the constrained Delaunay triangulations of the
/// polygons on either side. A segment's end that is a duplicate stands for its group's kept
/// point; a segment whose ends coincide is left out; a segment given twice, or two that
/// overlap, make one chain of edges. `domain` says which triangles to keep, `quality` how to
/// refine them: from the Delaunay triangulation in canonical order, so that the mesh is the
/// same whatever `options.method` and `options.threads`. `options.canonical_order` and
/// `on_sorted` apply to the result's triangles, `neighbors` off leaves its neighbours empty
/// (they are made all the same: the work needs them). Throws InputError for an index out of
/// range, an odd list, a seed's coordinate that is not finite, or a quality bound out of range.
ConstrainedTriangulation triangulate_constrained(std::span<const Point> points, std::span<const VertexId> segments,
                                                 const Options& options = {}, const Domain& domain = {},
                                                 const Quality& quality = {});

/// Refines a mesh already made (Triangle's -r): `triangles` (counter-clockwise, 3 indices into
/// `points` a triangle) cover the domain, whose boundary and `segments` (pairs, each an edge of
/// the mesh, either way) stay fixed. The mesh is first made constrained Delaunay by Lawson's
/// flips (a constrained Delaunay mesh, as triangulate_constrained and Triangle make, has none),
/// then refined as `quality` asks and, where `max_areas` is given (one a triangle, <= 0: none;
/// Triangle's .area file), each triangle of the result to the bound of the given triangle that
/// holds its centroid; `attributes` (one a triangle, optional) go by the same rule. Every point
/// keeps its index, those unused too; the result's steiner points are the ones added, its
/// `edges` the fixed edges (the segments and the boundary). `options`: canonical_order,
/// neighbors, threads (the sort) and memory_limit. Throws InputError for an index out of range,
/// a triangle clockwise or without area, two triangles running along an edge the same way,
/// triangles about a vertex that turn round it more than once or overlap there, pieces of the
/// mesh that overlap elsewhere (boundary edges that cross, two boundary vertices at one point,
/// a vertex inside a boundary edge, a piece inside another), a segment that is no edge, or
/// per-triangle values not one a triangle or not finite.
ConstrainedTriangulation refine_mesh(std::span<const Point> points, std::span<const VertexId> triangles,
                                     std::span<const VertexId> segments, const Quality& quality,
                                     std::span<const double> max_areas = {}, std::span<const double> attributes = {},
                                     const Options& options = {});

/// Six-node triangles for quadratic finite elements (Triangle's -o2): a node at the middle of
/// every edge.
struct SecondOrder {
  /// Node vertices.size() + k: the middle of the edge from ends[2k] to ends[2k + 1], each
  /// coordinate the exact mean of the ends' rounded to the nearest double.
  std::vector<Point> nodes;
  std::vector<VertexId> ends;
  /// Six a triangle: its three corners as the triangulation has them, then the nodes of the
  /// edges across from corners 0, 1 and 2 (Triangle's order).
  std::vector<VertexId> triangles;
};

/// The six-node triangles of `t`, whose vertices are `vertices` (a constrained triangulation's:
/// the input's points, then its steiner points). Nodes are numbered as the triangles, in order,
/// first meet their edges. Throws InputError where t has no neighbours (they pair the two
/// triangles of an edge: Options::neighbors), they do not match, a vertex is not one of
/// `vertices`, or the nodes would not fit in VertexId.
SecondOrder second_order(std::span<const Point> vertices, const Triangulation& t);

}  // namespace ridt
