// The Voronoi diagram of a triangulation's points: the dual of the Delaunay triangulation.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ridt/ridt.hpp"

namespace ridt {

/// The boundary between the cells of sites `a` and `b` (input indices): the segment from
/// Voronoi vertex `u` to vertex `v`, or, when `v` is -1, the ray from `u` along
/// ray_direction(points, ridge).
struct Ridge {
  VertexId a = 0, b = 0;
  std::int32_t u = -1, v = -1;
};

/// The direction of a ray (a ridge with v = -1): the outward normal of the hull edge a-b, not
/// normalized; (0, 0) for a segment.
inline Point ray_direction(std::span<const Point> points, const Ridge& r) {
  if (r.v >= 0) return {0, 0};
  // Triangle u runs a -> b with its inside on the left: outward is to the right.
  const Point& a = points[r.a];
  const Point& b = points[r.b];
  return {b.y - a.y, a.x - b.x};
}

/// The Voronoi diagram, in the layout of scipy.spatial.Voronoi, with -1 for the vertex at
/// infinity.
struct Voronoi {
  /// Vertex t is the circumcentre of triangle t of the triangulation: each coordinate within
  /// 2^-44 of the circumradius and a unit in its last place of the exact one, at any scale.
  std::vector<Point> vertices;
  /// Cell c's vertices are cell_vertices[cell_offsets[c] .. cell_offsets[c + 1]),
  /// counter-clockwise; an unbounded cell (a site on the hull) ends with -1, the vertex at
  /// infinity, which stands between the cell's two rays.
  std::vector<std::uint32_t> cell_offsets;
  std::vector<std::int32_t> cell_vertices;
  /// The site (input index) of each cell. Cells come in the order of the triangulation's
  /// triangles (each where its first triangle is), so that cells near in the plane lie near in
  /// memory; point_cell finds a site's cell.
  std::vector<VertexId> cell_site;
  /// For each input point its cell: a duplicate shares the cell of the point that stands for
  /// it; -1 when there is no triangle (fewer than three distinct points, or all collinear).
  std::vector<std::int32_t> point_cell;
  /// One ridge a Delaunay edge, u the lower-numbered of its two triangles: first the ridges
  /// with u = 0, then u = 1, ...
  std::vector<Ridge> ridges;

  std::size_t cells() const { return cell_site.size(); }
  std::span<const std::int32_t> cell(std::size_t c) const {
    return std::span(cell_vertices).subspan(cell_offsets[c], cell_offsets[c + 1] - cell_offsets[c]);
  }
};

/// The Voronoi diagram of `points` from their triangulation `t` (a result of triangulate on
/// the same points), on `threads` threads (0: the machine's hardware threads). The combinatorial
/// structure is exact (it is the triangulation's); the vertices are circumcentres within a
/// bound (Voronoi::vertices), computed exactly where floating point cannot keep to it. With `merge`, the diagram proper: as merge_cocircular makes it, the cocircular
/// neighbours found in the same pass as the circumcentres. Throws InputError when `t` does not
/// fit `points`.
Voronoi voronoi(std::span<const Point> points, const Triangulation& t, unsigned threads = 1, bool merge = false);

/// Makes `vd` (voronoi(points, t)) the diagram proper, as Qhull reports it: where neighbouring
/// triangles are cocircular (four points on one circle, decided by the exact in-circle test,
/// not the perturbation that picks the triangulation's diagonal), their circumcentres are one
/// Voronoi vertex; a grid's 2 x 2 squares give one vertex each, not two. The vertices are
/// renumbered in the order of their first triangle (vertex v is then the circumcentre of the
/// lowest-numbered triangle of its group, not of triangle v), cells list each vertex once, and
/// the ridges of length zero between the triangles of a group are dropped. Returns each
/// triangle's vertex. Without cocircular neighbours (points in general position) nothing
/// changes. A merged diagram's cells no longer name triangles: io::clipped_cell takes the
/// unmerged one.
std::vector<std::int32_t> merge_cocircular(std::span<const Point> points, const Triangulation& t, Voronoi& vd,
                                           unsigned threads = 1);

}  // namespace ridt
