// The mutable constrained triangulation that segment insertion, the domain's carving and
// quality refinement share: triangles with their neighbours (as ridt::Triangulation has them)
// and, per edge, whether it is a segment's ("fixed"); points can be added, each inserted by
// splitting its triangle or edge and flipping every edge that is not fixed back to locally
// Delaunay (Lawson), with the exact predicates.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "ridt/ridt.hpp"

namespace ridt::detail {

class Cdt {
 public:
  static constexpr std::uint32_t kNone = 0xffffffffu;

  /// Takes t's triangles and neighbours; `points` are the points the predicates see.
  Cdt(std::vector<Point> points, Triangulation& t);

  /// Where a point lies: in triangle t, on its edge k (across from corner k), at its corner k,
  /// or (the walk stopped) beyond its edge k, a fixed one (Blocked) or the boundary (Outside).
  struct Place {
    enum Kind { Inside, Edge, Corner, Blocked, Outside } kind;
    std::uint32_t t;
    int k;
  };
  /// A visibility walk from triangle `from` to p; `stop_at_fixed`: never across a fixed edge
  /// (then the walk always ends: every edge it crosses is locally Delaunay).
  Place locate(std::uint32_t from, const Point& p, bool stop_at_fixed) const;

  /// Where p lies, found by a walk from `from` that may cross fixed edges, or, where that walk
  /// circles or leaves the triangulation, by every triangle in turn; Outside where none holds it.
  Place find(std::uint32_t from, const Point& p) const;

  /// Where p, a rounding away from edge k of t, lies: in t or the triangle across (Inside,
  /// Edge or Corner), else Outside; k < 0: in t alone. No walk, so no fixed edge is crossed.
  Place beside(std::uint32_t t, int k, const Point& p) const;

  /// p added at `at` (Inside or Edge; a fixed edge stays fixed in both halves); returns its id.
  VertexId insert(const Point& p, const Place& at);

  /// Whether p, added on edge k of t as though it lay on it (a rounded point lies off its
  /// segment by a rounding), leaves every triangle there counter-clockwise; on the boundary,
  /// whether also p is not beyond the edge (the domain never grows).
  bool fits_on_edge(std::uint32_t t, int k, const Point& p) const;
  /// p, or where it lies beyond edge k of t (on the side away from t, by a rounding) the
  /// nearest doubles toward t that do not: a point split off a boundary edge stays inside.
  Point not_beyond(std::uint32_t t, int k, Point p) const;

  /// p added by replacing `cavity` (triangles linked without crossing a fixed edge, whose
  /// circles hold p: Bowyer and Watson) with a fan about p; kNone, with nothing changed, where
  /// the cavity is not a disc whose every boundary edge p sees from inside.
  VertexId insert_cavity(const Point& p, const std::vector<std::uint32_t>& cavity);

  /// p added on edge k of t (fits_on_edge must hold); where p is off the edge's line, the
  /// edges from p to the two apexes are flipped as they need too.
  VertexId insert_on_edge(const Point& p, std::uint32_t t, int k);

  /// Lawson's flips from the edges in `slots`: each that is not fixed and not locally
  /// Delaunay flipped, the four around it then checked in turn.
  void restore(std::vector<std::uint32_t> slots);

  /// The triangles around vertex v, in order (around a boundary vertex, from one side).
  std::vector<std::uint32_t> ring(VertexId v) const;
  /// visit(t) for the triangles around v, in ring()'s order, until it returns true; returns
  /// whether it did.
  template <class Visit>
  bool around(VertexId v, Visit visit) const {
    const std::uint32_t start = corner[v] / 3;
    for (std::uint32_t t = start;;) {
      if (visit(t)) return true;
      const std::int32_t n = nbrs[3 * t + (corner_of(t, v) + 2) % 3];  // across the edge (v, next)
      if (n < 0) break;
      t = static_cast<std::uint32_t>(n);
      if (t == start) return false;
    }
    for (std::uint32_t t = start;;) {
      const std::int32_t n = nbrs[3 * t + (corner_of(t, v) + 1) % 3];  // across the edge (previous, v)
      if (n < 0) return false;
      t = static_cast<std::uint32_t>(n);
      if (visit(t)) return true;
    }
  }

  int corner_of(std::uint32_t t, VertexId v) const { return tris[3 * t] == v ? 0 : tris[3 * t + 1] == v ? 1 : 2; }
  VertexId at(std::uint32_t t, int k) const { return tris[3 * t + k % 3]; }
  /// The slot of triangle n that looks back at t.
  int back(std::uint32_t n, std::uint32_t t) const {
    return nbrs[3 * n] == std::int32_t(t) ? 0 : nbrs[3 * n + 1] == std::int32_t(t) ? 1 : 2;
  }
  /// Edge k of t fixed or freed, on both sides.
  void set_fixed(std::uint32_t t, int k, bool on);
  /// The slot (3 t + k) of an edge a-b, as a triangle at a sees it; kNone when none.
  std::uint32_t find_edge(VertexId a, VertexId b) const;
  std::size_t size() const { return tris.size() / 3; }
  /// Each vertex's corner set again from the triangles (kNone for a vertex in none).
  void index_corners();

  std::vector<Point> pts;  ///< the points, then those added
  std::vector<VertexId> tris;
  std::vector<std::int32_t> nbrs;
  std::vector<std::uint8_t> fixed;  ///< per edge slot: a segment's edge
  std::vector<std::int32_t> region;  ///< per triangle: its region's index, -1 none (empty: none kept)
  std::vector<std::uint32_t> corner;  ///< per vertex: a slot that holds it, kNone when none

  /// Sets of triangles up to this size are searched, not marked (insert_cavity).
  static constexpr std::size_t kSearched = 32;
  /// A number no triangle's mark holds yet, the marks grown to every triangle: a set of
  /// triangles is marked with it, and its members are known at a glance (new_mark() again
  /// forgets them all).
  std::uint32_t new_mark();
  std::vector<std::uint32_t> mark;  ///< per triangle: the last mark it was given

 private:
  void set(std::uint32_t t, const VertexId (&v)[3], const std::int32_t (&n)[3], const std::uint8_t (&f)[3]);
  void relink(std::int32_t n, std::uint32_t from, std::uint32_t to);
  std::uint32_t add_triangle(std::uint32_t like);
  void flip(std::uint32_t t, int i);
  void legalize(VertexId p, std::vector<std::uint32_t> todo);

  struct Rim {  // a boundary edge of a cavity: x -> y, the triangle beyond it and its slot there
    VertexId x, y;
    std::int32_t out;
    int back;
    std::uint8_t fixed;
  };
  std::vector<Rim> rim_;
  std::vector<std::uint32_t> fan_;  // insert_cavity's triangles, a rim edge each
  std::vector<std::pair<VertexId, std::uint32_t>> from_, to_;  // insert_cavity's rim edges by their ends
  std::uint32_t marks_ = 0;  // new_mark's last
};

}  // namespace ridt::detail
