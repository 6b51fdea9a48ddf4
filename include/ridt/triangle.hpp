// Triangle's semantics, once: its switch string parsed into the library's options, and a run on
// its input (a .node/.poly/.ele/.area's content, the `triangle` package's dict) giving what
// Triangle writes: vertices with their markers and attributes, triangles (three or six nodes)
// with their attributes, the segments' pieces and every edge with their markers, neighbours,
// the mesh's dual. `ridt mesh` and Python's `ridt.triangle` are callers of it: they read and
// write files or dicts, and hold none of its rules.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ridt/check.hpp"
#include "ridt/constrained.hpp"
#include "ridt/ridt.hpp"

namespace ridt::triangle {

/// What a switch string asks (Triangle's own letters; those it takes for its choice of
/// algorithm, its arithmetic or its file names ignored: the exact result does not depend on
/// them).
struct Switches {
  bool pslg = false;  ///< p: the input is a planar straight-line graph (segments, holes, regions)
  bool refine = false;  ///< r: the input's triangles are a mesh to refine
  bool quality = false;  ///< q: a minimum angle, `min_angle` (20 where no number follows)
  double min_angle = 0;
  double max_area = 0;  ///< a with a number: no triangle larger (0: none)
  bool region_areas = false;  ///< a alone: the regions' own bounds (with r: each triangle's)
  bool attributes = false;  ///< A: each triangle's regional attribute
  bool convex_hull = false;  ///< c: keep every triangle of the convex hull
  bool conforming = false;  ///< D: every edge Delaunay
  bool no_boundary_steiner = false;  ///< Y: no point added on the boundary
  bool no_segment_steiner = false;  ///< YY: no point added on any segment
  bool limit_steiner = false;  ///< S: at most `max_steiner` points added (S0: no refinement at all)
  std::size_t max_steiner = 0;
  bool second_order = false;  ///< o2: six-node triangles
  bool no_holes = false;  ///< O: the input's holes ignored
  bool all_edges = false;  ///< e: every edge, with its marker
  bool neighbors = false;  ///< n: each triangle's neighbours
  bool zero_based = false;  ///< z: numbered from 0 (files; the arrays are always so)
  bool no_markers = false;  ///< B: no boundary markers
  bool jettison = false;  ///< j: the vertices of no triangle left out, the rest numbered in order
  bool no_node = false, no_ele = false, no_poly = false;  ///< N, E, P: files not written
  bool check = false;  ///< C: the result checked exactly (Output::check)
  bool off = false;  ///< g: an .off file (files)
  bool voronoi = false;  ///< v: the mesh's dual

  /// The refinement these ask of the library (none at all with S0).
  Quality quality_bounds() const;
};

/// Parses Triangle's switch string ("pq30a0.1", with or without a leading '-'). Throws
/// InputError for a switch ridt does not take (u: a test compiled into Triangle, which the
/// library takes as Quality::unsuitable; s), a number out of range or malformed, o without 2,
/// conforming with YY.
Switches parse_switches(std::string_view switches);

/// The letters parse_switches takes, for messages and help texts.
std::string_view switches_taken();

/// Triangle's input: a .node's vertices, a .poly's segments, holes and regions, a mesh's .ele
/// and .area. Every index is from 0.
struct Input {
  std::vector<Point> vertices;
  std::vector<std::int64_t> vertex_markers;  ///< one a vertex, or none
  std::size_t attribute_count = 0;  ///< attributes a vertex
  std::vector<double> vertex_attributes;  ///< `attribute_count` a vertex, row by row
  std::vector<VertexId> segments;  ///< pairs (p)
  std::vector<std::int64_t> segment_markers;  ///< one a segment, or none
  std::vector<Point> holes;  ///< (p, unless O)
  std::vector<Region> regions;  ///< seeds, attributes and area bounds (p; the bounds with a alone)
  std::vector<VertexId> triangles;  ///< a mesh to refine (r): three a triangle
  std::vector<double> triangle_attributes;  ///< (r) one a triangle, or none
  std::vector<double> triangle_max_area;  ///< (r with a alone) one a triangle
  /// A target edge length over the plane (Quality::size), beyond Triangle's switches: the mesh
  /// refined to it, with or without q and a.
  SizeField size;
};

/// What Triangle gives: its .node, .ele, .edge, .neigh, .v.node and .v.edge files' content,
/// numbered from 0. Vertices are the input's, in its numbering, then the points added (where
/// segments cross first: `crossings` of them), then with o2 the middles of the edges.
struct Output {
  std::vector<Point> vertices;
  std::vector<std::int64_t> vertex_markers;  ///< one a vertex (none with B)
  std::size_t attribute_count = 0;
  std::vector<double> vertex_attributes;  ///< `attribute_count` a vertex
  int nodes = 3;  ///< nodes a triangle: 3, or 6 (o2: the corners, then the middles of the
      ///< edges across from them)
  std::vector<VertexId> triangles;
  std::vector<double> triangle_attributes;  ///< one a triangle (A, or r with attributes given)
  /// The segments' pieces (the fixed edges: with q or a those of the boundary too), pairs
  /// (a, b) with a < b, sorted, their markers, and the input segment each lies on (-1 for a
  /// boundary edge that lies on none).
  std::vector<VertexId> segments;
  std::vector<std::int64_t> segment_markers;  ///< (none with B)
  std::vector<std::int32_t> segment_of;
  std::vector<VertexId> edges;  ///< e: every edge, (a, b) with a < b, sorted
  std::vector<std::int64_t> edge_markers;  ///< e (none with B)
  std::vector<std::int32_t> neighbors;  ///< three a triangle (n's file), -1 across the boundary
  std::vector<Point> holes;  ///< the holes used (p, unless O or r)
  /// v: vertex t the circumcentre of triangle t (NaN where it does not fit a double), its
  /// attributes the triangle's linear function of its corners' there; an edge (u, w) between
  /// two, or a ray from u (w = -1) along its direction, across each edge of the mesh.
  std::vector<Point> voronoi_vertices;
  std::vector<double> voronoi_attributes;
  std::vector<std::int32_t> voronoi_edges;  ///< pairs
  std::vector<Point> voronoi_directions;  ///< one an edge ((0, 0) for one between two vertices)
  std::size_t crossings = 0;
  std::string warning;  ///< what refinement could not do, or ""
  std::vector<Duplicate> duplicates;
  CheckResult check;  ///< C: the exact check of the result (check_mesh)
};

/// Triangle's run: the constrained Delaunay triangulation of the input's graph (p; else of its
/// vertices), its exterior and holes removed unless c, refined as q, a, Y, YY, D and S ask; with
/// r the input's mesh refined (refine_mesh), its boundary and (p) segments kept, each triangle to
/// its own area bound with a alone, its attributes carried. Markers follow Triangle's rules: a
/// piece keeps its segment's marker where that is not 0, else 1 on the boundary, 0 inside; a
/// vertex keeps the input's marker where not 0, else takes that of the last marked segment it
/// ends a piece of, else 1 on the boundary, 0 inside; with o2 a middle takes its edge's marker.
/// Vertex attributes: the input's, those of the points added interpolated linearly over the
/// Delaunay triangulation of the input's vertices (the nearest input vertex's where one lies a
/// rounding outside their hull), with o2 a middle's the mean of its edge's ends'. `options`:
/// method, threads and memory_limit. Throws InputError as the library's calls do for bad input,
/// and for arrays of the wrong length.
Output triangulate(const Input& input, const Switches& switches, const Options& options = {});
Output triangulate(const Input& input, std::string_view switches, const Options& options = {});

}  // namespace ridt::triangle
