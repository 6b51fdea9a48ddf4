// The constrained triangulation that segment insertion, the domain's carving and quality
// refinement share: the one mutable triangulation (tds/tds.hpp) with constraints on its edges
// (each a piece of an input segment, by its number, or fixed without one), its points, and the
// plain exact predicates. Points are added by a Bowyer-Watson cavity that stops at fixed edges,
// or by splitting a triangle or an edge and Lawson's flips of every edge that is not fixed.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "ridt/ridt.hpp"
#include "tds/tds.hpp"

namespace ridt::detail {

class Cdt {
 public:
  /// Takes t's triangles and neighbours (each edge free), the neighbours triangle ids or, where
  /// `linked`, links (detail::triangulate_linked), made links on up to `threads` threads (0:
  /// the hardware's); `points` are the points the predicates see.
  Cdt(std::vector<Point> points, Triangulation& t, bool linked = false, unsigned threads = 1);

  /// Where a point lies: in triangle t, on its edge k (across from corner k), at its corner k,
  /// or (the walk stopped) beyond its edge k, a fixed one (Blocked) or the boundary (Outside).
  struct Place {
    enum Kind { Inside, Edge, Corner, Blocked, Outside } kind;
    TriangleId t;
    int k;
  };
  /// The one visibility walk (tds/tds.hpp) from triangle `from` to p; `stop_at_fixed`: never
  /// across a fixed edge (then the walk always ends: every edge it crosses is locally Delaunay).
  Place locate(TriangleId from, const Point& p, bool stop_at_fixed) const;

  /// Where p lies, found by a walk from `from` that may cross fixed edges, or, where that walk
  /// circles or leaves the triangulation, by every triangle in turn; Outside where none holds it.
  Place find(TriangleId from, const Point& p) const;

  /// Where p, a rounding away from edge k of t, lies: in t or the triangle across (Inside,
  /// Edge or Corner), else Outside; k < 0: in t alone. No walk, so no fixed edge is crossed.
  Place beside(TriangleId t, int k, const Point& p) const;

  /// p added at `at` (Inside or Edge; a fixed edge stays fixed in both halves, with its
  /// constraint), then Lawson's flips; returns its id.
  VertexId insert(const Point& p, const Place& at);

  /// Whether p, added on edge k of t as though it lay on it (a rounded point lies off its
  /// segment by a rounding), leaves every triangle there counter-clockwise; on the boundary,
  /// whether also p is not beyond the edge (the domain never grows).
  bool fits_on_edge(TriangleId t, int k, const Point& p) const;
  /// p, or where it lies beyond edge k of t (on the side away from t, by a rounding) the
  /// nearest doubles toward t that do not: a point split off a boundary edge stays inside.
  Point not_beyond(TriangleId t, int k, Point p) const;

  /// The cavity of p, which `at` (Inside or Edge) holds: the triangles whose circles hold p,
  /// linked without crossing a fixed edge (Tds::find_cavity into cavity()). Its fixed boundary
  /// edges are those p would encroach where it lies in their diametral circles. Reads only.
  void find_cavity(const Point& p, const Place& at);
  const CavityScratch& cavity() const { return scratch_; }
  /// p added by replacing the cavity found (find_cavity, for the same p, with nothing changed
  /// since) by a fan about p (Bowyer and Watson); kNoVertex, with nothing changed, where the
  /// cavity is not a disc whose every boundary edge p sees from inside.
  VertexId insert_cavity(const Point& p);

  /// p added on edge k of t (fits_on_edge must hold); where p is off the edge's line, the
  /// edges from p to the two apexes are flipped as they need too.
  VertexId insert_on_edge(const Point& p, TriangleId t, int k);

  /// Edge e flipped (Tds::flip), the vertices' corners kept.
  void flip(Link e) {
    const TriangleId t = triangle_of(e), u = across(e);
    tds.flip(e);
    claim_corners(std::array<TriangleId, 2>{t, u});
  }

  /// Lawson's flips from the edges in `edges`: each that is not fixed and not locally
  /// Delaunay flipped, the four around it then checked in turn.
  void restore(std::vector<Link> edges);

  /// Vertex v taken out where it is free (every edge about it free, none on the boundary): the
  /// edges about it flipped away (each flip that keeps the triangles counter-clockwise) down to
  /// three triangles, merged into one, then Lawson's flips from the edges made; the two slots
  /// freed are listed in `freed`, v's corner set to kNoTriangle. False, nothing changed, where v
  /// is not free; also where no flip is left (a point on a line of its neighbours), the mesh then
  /// restored to constrained Delaunay with v in it.
  bool remove_free(VertexId v);
  std::vector<TriangleId> freed;
  /// The vertices `dead` (taken out by remove_free) and the slots `freed` dropped: the last
  /// vertex moved into each dead one's place, the last triangle into each freed slot.
  void compact(std::vector<VertexId> dead);
  /// The triangles whose `gone` is set dropped (links to them become the boundary), the rest
  /// renumbered in their order with their constraints and regions, the corners indexed again.
  void drop_slots(const std::vector<std::uint8_t>& gone);

  /// The triangles around vertex v, in order (around a boundary vertex, from one side).
  std::vector<TriangleId> ring(VertexId v) const;
  /// visit(t) for the triangles around v, in ring()'s order, until it returns true; returns
  /// whether it did.
  template <class Visit>
  bool around(VertexId v, Visit visit) const {
    const TriangleId start = corner[v] / 3;
    for (TriangleId t = start;;) {
      if (visit(t)) return true;
      const TriangleId n = tds.neighbour(t, prev3(corner_of(t, v)));  // across the edge (v, next)
      if (n == kNoTriangle) break;
      t = n;
      if (t == start) return false;
    }
    for (TriangleId t = start;;) {
      const TriangleId n = tds.neighbour(t, next3(corner_of(t, v)));  // across the edge (previous, v)
      if (n == kNoTriangle) return false;
      t = n;
      if (visit(t)) return true;
    }
  }

  int corner_of(TriangleId t, VertexId v) const { return tds.corner_of(t, v); }
  /// Corner k (taken modulo 3) of t.
  VertexId at(TriangleId t, int k) const { return tds.vertex(t, k % 3); }
  /// The triangle across edge s (a slot 3t + k), or kNoTriangle.
  TriangleId across(Link s) const {
    const Link l = tds.link_at(s);
    return l == kNoLink ? kNoTriangle : triangle_of(l);
  }
  /// The vertex across edge s, in the triangle beyond it, or kNoVertex on the boundary.
  VertexId apex_across(Link s) const {
    const Link l = tds.link_at(s);
    return l == kNoLink ? kNoVertex : tds.opposite(l);
  }
  bool boundary(Link s) const { return tds.link_at(s) == kNoLink; }
  bool fixed(Link s) const { return tds.fixed(s); }
  /// Edge s given constraint c on both sides (kFree frees it).
  void constrain(Link s, Constraint c) { tds.constrain(s, c); }
  /// The edge a-b, as a triangle at a sees it (its slot 3t + k); kNoLink when none.
  Link find_edge(VertexId a, VertexId b) const;
  std::size_t size() const { return tds.slots(); }
  /// How many more points (each with its corner and two triangles) the arrays take as they are;
  /// make_room(points, least) grows those that cannot take `least` more to take `points` more
  /// (geometrically where memory allows), or throws std::bad_alloc with the mesh unchanged.
  /// Growth copies an array, so needs the old and the new at once: asked for between
  /// insertions, a shortage is met with no point half added; and an array with room enough is
  /// not copied for another's shortage.
  std::size_t room() const;
  void make_room(std::size_t points, std::size_t least = SIZE_MAX);
  /// Each vertex's corner set again from the triangles (kNoTriangle for a vertex in none).
  void index_corners();

  Tds tds;
  std::vector<Point> pts;  ///< the points, then those added
  std::vector<std::int32_t> region;  ///< per triangle: its region's index, -1 none (empty: none kept)
  std::vector<std::uint32_t> corner;  ///< per vertex: a slot that holds it, kNoTriangle when none

  /// Sets of triangles up to this size are searched, not marked.
  static constexpr std::size_t kSearched = 32;
  /// A number no triangle's mark holds yet, the marks grown to every triangle: a set of
  /// triangles is marked with it, and its members are known at a glance (new_mark() again
  /// forgets them all).
  std::uint32_t new_mark();
  std::vector<std::uint32_t> mark;  ///< per triangle: the last mark it was given

 private:
  // Slots for `count` new triangles, each in the region of `like`.
  SlotPool fresh(TriangleId count, TriangleId like);
  // The corners of the triangles in `ts` set as theirs.
  template <std::size_t N>
  void claim_corners(const std::array<TriangleId, N>& ts) {
    for (const TriangleId t : ts)
      if (t != kNoTriangle)
        for (int k = 0; k < 3; ++k) corner[at(t, k)] = 3 * t + static_cast<TriangleId>(k);
  }
  // Lawson's flips about p, from the triangles in todo_.
  void legalize(VertexId p);
  void flip_from(std::vector<Link>& edges);  // restore's, on edges kept
  VertexId add_point(const Point& p);
  // remove_free's last step: v's three triangles (`star`) made one.
  void merge_three(VertexId v, const std::vector<TriangleId>& star);

  CavityScratch scratch_;
  // An insertion's lists (legalize's triangles, insert_on_edge's edges), kept between them, so
  // that where make_room has run an insertion allocates nothing (a few dozen items at most).
  static constexpr std::size_t kScratch = 256;
  std::vector<TriangleId> todo_;
  std::vector<Link> spokes_;
  std::uint32_t marks_ = 0;  // new_mark's last
};

}  // namespace ridt::detail
