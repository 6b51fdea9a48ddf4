// A Delaunay triangulation that takes more points (scipy's incremental mode).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "ridt/ridt.hpp"

namespace ridt {

/// A triangulation to which points can be added: each new point is inserted into the existing
/// triangulation (located by a walk, its cavity of triangles whose circle holds it replaced by
/// a fan around it), with the library's exact predicates, its symbolic perturbation and its
/// bounding vertices at infinity. So after every add() the result is the Delaunay
/// triangulation of all the points so far, triangle for triangle the one triangulate() gives
/// for them (with Options::canonical_order, array for array). The first points are
/// triangulated by triangulate() with `options` (any method and thread count); the insertions
/// run on one thread, along a Hilbert curve over each batch. Duplicates are left out as
/// triangulate() leaves them: the smallest index of each group of equal points stands for it.
class IncrementalTriangulation {
 public:
  explicit IncrementalTriangulation(std::span<const Point> points, const Options& options = {});
  /// The same, taking the triangulation of `points` that triangulate() already gave.
  IncrementalTriangulation(std::span<const Point> points, Triangulation triangulation, const Options& options = {});
  ~IncrementalTriangulation();
  IncrementalTriangulation(IncrementalTriangulation&&) noexcept;
  IncrementalTriangulation& operator=(IncrementalTriangulation&&) noexcept;

  /// Inserts `more` (numbered after the points so far). Throws InputError for a coordinate
  /// that is not finite, before anything changes.
  void add(std::span<const Point> more);

  /// The Delaunay triangulation of every point so far, in triangulate()'s layout.
  const Triangulation& triangulation() const { return result_; }
  /// Every point so far, in the order given.
  std::span<const Point> points() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
  Triangulation result_;
};

}  // namespace ridt
