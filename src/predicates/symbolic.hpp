// The vertices of a mesh and the two predicates on them, with the bounding vertices.
//
// Vertex ids 0 .. n-1 are the points; n, n + 1, n + 2 are the bounding vertices B0, B1, B2,
// counter-clockwise. Symbolic bounding vertices lie infinitely far away, at B0 = (R, r),
// B1 = (-r, R^2), B2 = (-r, -R^3), with 1 << r << R. Every predicate that involves them is
// then a polynomial in R and r whose leading coefficient is a plain comparison of coordinates;
// those rules are in orient_symbolic and incircle_symbolic, and tests check them against a
// concrete far-away instance with exact integers. No coordinate is huge, the predicates never
// tie on a bounding vertex, and removing B0, B1, B2 leaves exactly the Delaunay triangulation
// of the points with its whole convex hull. Finite bounding vertices (the paper's) are
// ordinary points at ids n .. n+2.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "predicates/predicates.hpp"
#include "ridt/ridt.hpp"

namespace ridt::detail {

class Vertices {
 public:
  Vertices() = default;
  /// `points` holds n + 3 points: the n vertices, then the three bounding ones, which when
  /// `symbolic` must be NaN (kBoundingNaN; never used as coordinates).
  Vertices(const Point* points, std::uint32_t n, bool symbolic)
      : points_(points),
        n_(n),
        first_symbolic_(symbolic ? n : 0xffffffffu),
        special_(symbolic && on_small_lattice(points, n) ? 0 : first_symbolic_) {
    if (symbolic && !(std::isnan(points[n].x) && std::isnan(points[n + 1].x) && std::isnan(points[n + 2].x)))
      throw std::logic_error("ridt: the symbolic bounding vertices' points must be NaN");
  }
  /// The point that stands for a symbolic bounding vertex.
  static constexpr Point kBoundingNaN{std::numeric_limits<double>::quiet_NaN(),
                                      std::numeric_limits<double>::quiet_NaN()};

  std::uint32_t n() const { return n_; }
  const Point& operator[](VertexId v) const { return points_[v]; }
  const Point* data() const { return points_; }
  /// Whether v is a bounding vertex at infinity.
  bool symbolic(VertexId v) const { return v >= first_symbolic_; }

  /// +1 counter-clockwise, -1 clockwise, 0 collinear (never 0 with a symbolic vertex).
  int orient(VertexId a, VertexId b, VertexId c) const {
    if (std::max(a, std::max(b, c)) >= special_) return orient_special(a, b, c);
    return orient2d(points_[a], points_[b], points_[c]);
  }
  /// +1 if point p lies inside the circle of the counter-clockwise triangle (a, b, c), -1
  /// outside; never 0 (symbolic perturbation). p is never a bounding vertex.
  int incircle(VertexId a, VertexId b, VertexId c, VertexId p) const {
    if (std::max(a, std::max(b, c)) >= special_) return incircle_special(a, b, c, p);
    return incircle_sos(points_[a], points_[b], points_[c], points_[p]);
  }

  /// The same with c's point already at hand (the walk's and the cavity's point, kept in
  /// registers across their tests; c is never a bounding vertex), for the walking kernel. The
  /// symbolic bounding vertices' points are NaN, so a test with one fails the filter as an
  /// unsure one does, and only then are the vertex ids looked at, off the common path (comparing
  /// them first would cost some 6.5 % of a uniform insertion's instructions). kLattice: only where
  /// lattice() holds, whose forms it then computes in line (a grid's every test takes them);
  /// they test the ids first, as a grid's many zero determinants would otherwise each ask
  /// again out of line.
  template <bool kLattice = false>
  int orient(VertexId a, VertexId b, VertexId c, const Point& pc) const {
    if constexpr (kLattice) {
      if (std::max(a, b) >= first_symbolic_) return orient_symbolic(a, b, c);
      return orient2d_lattice(points_[a], points_[b], pc);
    } else {
      if (const int s = orient2d_filter(points_[a], points_[b], pc); s != 0) return s;
      return orient_open(a, b, c);
    }
  }
  template <bool kLattice = false>
  int incircle(VertexId a, VertexId b, VertexId c, VertexId p, const Point& pp) const {
    if constexpr (kLattice) {
      if (std::max(a, std::max(b, c)) >= first_symbolic_) return incircle_symbolic(a, b, c, p);
      return incircle_sos_lattice(points_[a], points_[b], points_[c], pp);
    } else {
      if (const int s = incircle_filter(points_[a], points_[b], points_[c], pp); s != 0) return s;
      return incircle_open(a, b, c, p);
    }
  }
  /// Whether every point lies on a small lattice (on_small_lattice), with symbolic bounding
  /// vertices: the predicates' kLattice forms then apply.
  bool lattice() const { return special_ == 0; }

  /// The 3-vertex forms, out of line: where the filter is unsure or meets a NaN.
  int orient_open(VertexId a, VertexId b, VertexId c) const;
  int incircle_open(VertexId a, VertexId b, VertexId c, VertexId p) const;

  int orient_symbolic(VertexId a, VertexId b, VertexId c) const;
  int incircle_symbolic(VertexId a, VertexId b, VertexId c, VertexId p) const;
  /// The predicates where a vertex id reaches special_: the symbolic rules for a bounding
  /// vertex, else the points' lattice forms.
  int orient_special(VertexId a, VertexId b, VertexId c) const;
  int incircle_special(VertexId a, VertexId b, VertexId c, VertexId p) const;

 private:
  const Point* points_ = nullptr;
  std::uint32_t n_ = 0;
  // n when the bounding vertices are symbolic, else past every vertex id: the predicates take
  // the symbolic rules exactly when a vertex id reaches it (one comparison, on every test).
  std::uint32_t first_symbolic_ = 0xffffffffu;
  // Where the predicates leave their common path, on the same one comparison: first_symbolic_,
  // or 0 when every point lies on a small lattice (on_small_lattice), whose predicates compute
  // exactly without a filter (a grid's cocircular squares then skip the filter's failed bound
  // and the exactness check, every other incircle test). Only with symbolic bounding
  // vertices: the paper's finite ones lie far off any such lattice.
  std::uint32_t special_ = 0xffffffffu;
};

}  // namespace ridt::detail
