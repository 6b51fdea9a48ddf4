// Size fields for quality meshes: a target edge length that varies over the plane
// (Quality::size), given as values on a grid, at the vertices of a background mesh or of
// scattered points, or by a function of many points at once.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "ridt/ridt.hpp"

namespace ridt {

/// A target edge length h(x, y): a quality mesh refined to it has no triangle whose longest
/// edge is above h at the triangle's centroid, but where the angle bound or the input forces
/// one (a segment kept whole, a small input angle). Sizes are positive; an infinite size sets
/// no bound there. Every kind is a function of many points at once, and refinement asks it for
/// the sizes of the triangles it makes a batch at a time, so a field given as values and one
/// given as a function that computes the same values give the same mesh.
///
/// A SizeField is cheap to copy (its data are shared) and is read from one thread at a time.
class SizeField {
 public:
  /// Fills sizes[k] with h(points[k]), for points.size() == sizes.size().
  using Function = std::function<void(std::span<const Point> points, std::span<double> sizes)>;

  /// No field: no bound.
  SizeField() = default;

  /// h everywhere. Throws InputError unless h > 0 (infinite: no bound).
  static SizeField uniform(double h);

  /// `gradation` (the three below): where it is above 0, the values are first lowered where
  /// they grow faster than that along the grid's or the mesh's edges (the gradient limit of
  /// ocean and coastal meshers: each value the least, over every node, of that node's value
  /// plus `gradation` times the shortest path there), so that neighbouring triangles' sizes
  /// differ by about that fraction at most (0.2: neighbours within some 20 %). No value rises;
  /// the smallest stay. Throws InputError unless it is finite and >= 0.
  ///
  /// Values at the nodes of a regular grid of nx by ny nodes, row by row: node (i, j), value
  /// values[j * nx + i], lies at (x0 + i (x1 - x0) / (nx - 1), y0 + j (y1 - y0) / (ny - 1)), so
  /// that y1 < y0 reads an image's rows, the top first (a single node along an axis spans it
  /// whole). Bilinear within a cell; beyond the grid, the value on its edge nearest. Throws
  /// InputError for values.size() != nx * ny, nx or ny 0, an extent not finite or empty, or a
  /// value not > 0.
  static SizeField on_grid(std::span<const double> values, std::size_t nx, std::size_t ny, double x0, double y0,
                           double x1, double y1, double gradation = 0);

  /// Values at the vertices of a background mesh (`triangles`: 3 indices into `vertices` a
  /// triangle, either orientation; any mesh, Delaunay or not, with holes or not), linear within
  /// each triangle (the first that holds a point on a shared edge); beyond the mesh, the value of
  /// the nearest vertex. Throws InputError for sizes that do not match, an index out of range,
  /// a vertex not finite, or a value not > 0.
  static SizeField on_mesh(std::span<const Point> vertices, std::span<const VertexId> triangles,
                           std::span<const double> values, double gradation = 0);

  /// Values at scattered points: linear over their Delaunay triangulation, the nearest point's
  /// value beyond its hull (on_mesh of triangulate(points)).
  static SizeField on_points(std::span<const Point> points, std::span<const double> values, double gradation = 0);

  /// A function of the caller's. What it throws comes out of the call that refines; a size it
  /// gives that is NaN or not > 0 throws InputError there.
  static SizeField of(Function f);

  /// Whether there is a field.
  explicit operator bool() const { return static_cast<bool>(f_); }

  /// h at each point, checked: throws InputError where a size is NaN or not > 0.
  void sizes(std::span<const Point> points, std::span<double> out) const;
  std::vector<double> sizes(std::span<const Point> points) const;

 private:
  explicit SizeField(Function f) : f_(std::move(f)) {}
  Function f_;
};

}  // namespace ridt
