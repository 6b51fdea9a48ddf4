// The one mutable triangulation: the triangulation data structure that every triangulation of
// the library that changes after it is built stands on — the walking kernel's Delaunay
// triangulation (tds/delaunay.hpp: the serial walk, the partition method's threads, the
// incremental triangulation), the constrained triangulation and its quality refinement
// (constrained/cdt.hpp). Only the history DAG (dag/) keeps records of its own: they are the
// paper's kernel, and a node there is a triangle that was, not one that is.
//
// Slot t is a triangle: v[3t + i] its vertices, counter-clockwise, and link[3t + i] the edge
// across from v[3t + i], named by its place in the neighbour's arrays (3u + j: the neighbour is
// u, and the shared edge is u's edge j), or kNoLink where there is no neighbour. The edge
// across from v[i] runs v[next3(i)] -> v[prev3(i)]; going round a triangle counter-clockwise
// its edges come in the order i, next3(i), prev3(i). A link names the edge on both sides at
// once: link[link[e]] == e, so a neighbour's edge is found without searching it.
//
// Optionally each edge slot carries a constraint (constraints()): kFree, or the number of the
// input segment the edge lies on (a constrained triangulation's pieces know their segment, as
// Triangle's subsegments carry their markers), or kUnnamed for an edge fixed without one (the
// boundary of a domain being refined). Both sides of an edge carry the same value.
//
// The geometry is the caller's: the walk and the cavity take their predicates as function
// objects, so that the Delaunay kernel's symbolic and lattice predicates and the constrained
// triangulation's plain ones run the same code.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "ridt/ridt.hpp"
#include "tds/ids.hpp"

namespace ridt::detail {

/// Where an insertion finds its new slots: a list of free slots first, then a range.
struct SlotPool {
  const TriangleId* list = nullptr;
  std::size_t listed = 0;
  TriangleId next = 0, end = 0;

  bool empty() const { return listed == 0 && next == end; }
  TriangleId take() { return listed > 0 ? list[--listed] : next++; }
  std::size_t size() const { return listed + (end - next); }
};

/// What one inserting thread keeps to itself: the cavity's triangles and boundary, the
/// traversal's stack, counters. The arrays are used through raw pointers with room checked
/// once a cavity triangle (a cavity of m triangles has m + 2 boundary edges, at most m + 2 of
/// them pending on the stack, and m + 2 slots for its fan, and one more of each for a copy
/// of the first after the last).
struct alignas(64) CavityScratch {
  // A boundary edge a -> b, counter-clockwise round the cavity: b is the next edge's a.
  struct Boundary {
    VertexId a;
    Link outside;  // the edge's place in the triangle outside, or kNoLink
    Link inside;  // its place in the cavity's triangle (Tds::find_cavity records it with kInside)
  };
  std::vector<TriangleId> cavity;  // the cavity's slots, then the two new ones
  std::vector<Boundary> boundary;
  std::vector<Link> stack;
  std::vector<std::uint8_t> inside;  // beside each edge on the stack: the triangle across it is in the cavity
  std::vector<Constraint> kept;  // fill_cavity's: each boundary edge's constraint, where there are constraints
  std::size_t size = 0;  // triangles in the cavity
  std::size_t edges = 0;  // boundary edges found
  bool revisited = false;  // a triangle of the cavity was met again (Tds::find_cavity)
  std::uint64_t replaced = 0;  // triangles replaced beyond the first, over all insertions

  CavityScratch() { make_room(64); }
  /// Room for a cavity of m triangles.
  void make_room(std::size_t m) {
    if (m + 3 <= cavity.size()) return;
    const std::size_t room = std::max<std::size_t>(2 * m, 64);
    cavity.resize(room + 3), boundary.resize(room + 3), stack.resize(room + 3), inside.resize(room + 3);
  }
};

/// What a walk's `cross` says of an edge that has the point beyond it: cross it, leave it for
/// another edge of the triangle (the walk ends blocked where none is left), or end the walk there.
enum class Step { Cross, Blocked, Stop };

/// Where a walk ended (Tds::walk): in a triangle whose closure holds the point (`reached`;
/// `zeros` has bit i set where the point lies on the line of edge i), or at a triangle whose
/// edge `edge` it was told to stop at (Step::Stop), or, every edge beyond which the point lies
/// refused (Step::Blocked), at the last triangle it reached (edge -1).
struct Walked {
  bool reached = false;
  int edge = -1;
  std::uint8_t zeros = 0;
  explicit operator bool() const { return reached; }
};

template <class Topology, class Side, class Cross>
inline Walked visibility_walk(const Topology& topology, TriangleId& t, Side&& side, Cross&& cross);

class Tds {
 public:
  /// walk's `cross` and find_cavity's `enter` and `wall` that allow every edge and triangle.
  static constexpr auto kAnywhere = [](Link) { return true; };
  static constexpr auto kNoWall = [](Link) { return false; };
  static constexpr auto kNotSeen = [](TriangleId, const TriangleId*, std::size_t) { return false; };

  /// An empty structure whose arrays grow as slots are added.
  Tds() : growable_(true) {}
  /// A structure in arrays made beforehand (3 numbers a slot), which never grow: `slots` of
  /// them in use, the rest room for grow().
  Tds(std::vector<VertexId> v, std::vector<Link> link, TriangleId slots);
  /// The arrays of a triangulation whose neighbours are triangle ids (Triangulation's: -1
  /// where there is none), made links on up to `threads` threads; growable.
  static Tds from_neighbours(std::vector<VertexId> triangles, std::vector<std::int32_t> neighbours,
                             unsigned threads = 1);
  /// The arrays of a triangulation whose neighbours are links already; growable.
  static Tds from_links(std::vector<VertexId> triangles, std::vector<Link> links);
  Tds(Tds&& o) noexcept { *this = std::move(o); }
  /// A copy of the slots in use (growable).
  Tds copy() const;
  Tds& operator=(Tds&& o) noexcept;
  Tds(const Tds&) = delete;
  Tds& operator=(const Tds&) = delete;

  /// Slots in use (each a triangle, or free: see free_slot).
  TriangleId slots() const { return top_; }
  VertexId vertex(TriangleId t, int i) const { return v_[3 * std::size_t{t} + i]; }
  Link link(TriangleId t, int i) const { return link_[3 * std::size_t{t} + i]; }
  VertexId vertex_at(Link e) const { return v_[static_cast<std::uint32_t>(e)]; }
  Link link_at(Link e) const { return link_[static_cast<std::uint32_t>(e)]; }
  /// The vertex of triangle_of(l) across from its edge edge_of(l).
  VertexId opposite(Link l) const { return v_[static_cast<std::uint32_t>(l)]; }
  /// The ends of edge e, in its triangle's counter-clockwise direction.
  VertexId tail(Link e) const { return v_[3 * std::size_t{triangle_of(e)} + next3(edge_of(e))]; }
  VertexId head(Link e) const { return v_[3 * std::size_t{triangle_of(e)} + prev3(edge_of(e))]; }
  /// The triangle across edge i of t, or kNoTriangle.
  TriangleId neighbour(TriangleId t, int i) const {
    const Link l = link(t, i);
    return l == kNoLink ? kNoTriangle : triangle_of(l);
  }
  /// The corner of t that is vertex w (t must have it).
  int corner_of(TriangleId t, VertexId w) const { return vertex(t, 0) == w ? 0 : vertex(t, 1) == w ? 1 : 2; }

  /// Writes vertex and link; glue(a, b) links two edges to each other (either may be kNoLink,
  /// then only the other is written).
  void set_vertex(TriangleId t, int i, VertexId w) { v_[3 * std::size_t{t} + i] = w; }
  void set_link(Link e, Link to) { link_[static_cast<std::uint32_t>(e)] = to; }
  void glue(Link a, Link b) {
    if (a != kNoLink) link_[static_cast<std::uint32_t>(a)] = b;
    if (b != kNoLink) link_[static_cast<std::uint32_t>(b)] = a;
  }

  /// Per-edge constraints: on (each edge kFree; its pages made present by up to `threads`
  /// threads) or off (no array at all, the default).
  void use_constraints(bool on, unsigned threads = 2);
  bool has_constraints() const { return !constraints_.empty(); }
  Constraint constraint(Link e) const { return constraints_[static_cast<std::uint32_t>(e)]; }
  bool fixed(Link e) const { return constraints_[static_cast<std::uint32_t>(e)] != kFree; }
  /// Edge e's constraint set on both its sides.
  void constrain(Link e, Constraint c) {
    constraints_[static_cast<std::uint32_t>(e)] = c;
    if (const Link o = link_at(e); o != kNoLink) constraints_[static_cast<std::uint32_t>(o)] = c;
  }
  /// One side only (where the other is written on its own).
  void set_constraint(Link e, Constraint c) { constraints_[static_cast<std::uint32_t>(e)] = c; }

  /// Walks from triangle t towards a point (visibility_walk, below).
  template <class Side, class Cross>
  [[gnu::always_inline]] Walked walk(TriangleId& t, Side&& side, Cross&& cross) const {
    return visibility_walk(*this, t, side, cross);
  }
  /// What visibility_walk reads: a triangle's corners, and the link across its edge i.
  const VertexId* corners(TriangleId t) const { return v_ + 3 * std::size_t{t}; }

  /// Finds the cavity of a point (the triangles whose circle holds it, grown from triangle t,
  /// which does) into s.cavity and s.boundary, the boundary counter-clockwise. in_circle(w)
  /// says whether the triangle with vertices w[0], w[1], w[2] has the point inside its circle.
  /// The cavity does not cross an edge e of its own triangles where wall(e) holds (such edges
  /// are on its boundary). False, with nothing found, when it would take a triangle that
  /// `enter` refuses: enter(l) is asked of the triangle the cavity enters by link l (its edge
  /// edge_of(l)) from one already in it, before any vertex of it but opposite(l) is read (the
  /// partition method: a cavity of the thread's own triangles grows by one that shares two
  /// vertices with one of them, so the vertex opposite the edge decides). In a Delaunay
  /// triangulation the cavity is a disc and its dual graph a tree, met once each; elsewhere
  /// (walls, ties left out) it may not be: seen(u, cavity, size) says whether triangle u is
  /// among the `size` already in it, and one met again is left out, its edge counted on the
  /// boundary, and s.revisited set (kNotSeen: never). kInside: record each boundary edge's own
  /// slot too (Boundary::inside), for callers that carry its constraint. Reads only.
  ///
  /// The edges of a triangle that joins the cavity are tested together, as it joins, not one
  /// by one as they leave the stack: the tests are independent, so the processor overlaps
  /// them, where each test after a branch on the last one's result (taken at random) waited for
  /// that result. A triangle tested is a neighbour of one in the cavity, which the partition
  /// method's threads may read (methods/partition.cpp).
  template <bool kInside = false, class InCircle, class Enter, class Wall, class Seen>
  bool find_cavity(TriangleId t, CavityScratch& s, InCircle&& in_circle, Enter&& enter, Wall&& wall,
                   Seen&& seen) const {
    TriangleId* cavity = s.cavity.data();
    CavityScratch::Boundary* boundary = s.boundary.data();
    Link* stack = s.stack.data();
    std::uint8_t* inside = s.inside.data();
    // Whether the triangle across edge e has the point inside its circle.
    auto across = [&](Link e) {
      const Link l = link_[e];
      if (l == kNoLink || wall(e)) return false;
      return static_cast<bool>(in_circle(v_ + 3 * std::size_t{triangle_of(l)}));
    };
    std::size_t size = 1, edges = 0, top = 0;
    cavity[0] = t;
    s.revisited = false;
    // Edges to look across, last first: round the cavity counter-clockwise, so that its
    // boundary comes out in order.
    const Link base = static_cast<Link>(3 * t);
    const bool in2 = across(base + 2), in1 = across(base + 1), in0 = across(base);
    stack[top] = base + 2, inside[top++] = in2;
    stack[top] = base + 1, inside[top++] = in1;
    stack[top] = base, inside[top++] = in0;
    while (top > 0) {
      const Link e = stack[--top];
      const Link l = link_[e];
      if (inside[top]) {
        if (!enter(l)) return false;
        const TriangleId u = triangle_of(l);
        if (!seen(u, static_cast<const TriangleId*>(cavity), size)) {
          if (size + 1 + 3 > s.cavity.size()) {  // rare: a large cavity
            s.make_room(s.revisited ? 3 * size + 3 : size + 1);
            cavity = s.cavity.data(), boundary = s.boundary.data(), stack = s.stack.data(), inside = s.inside.data();
          }
          cavity[size++] = u;
          // Entered by its edge j: the other two, counter-clockwise from there.
          const int j = edge_of(l);
          const Link ub = static_cast<Link>(3 * u);
          const Link before = ub + prev3(j), after = ub + next3(j);
          const bool in_before = across(before), in_after = across(after);
          stack[top] = before, inside[top++] = in_before;
          stack[top] = after, inside[top++] = in_after;
          continue;
        }
        // Not a disc: its boundary edges may number up to three a triangle.
        if (!s.revisited && 3 * size + 3 > s.boundary.size()) {
          s.make_room(3 * size + 3);
          cavity = s.cavity.data(), boundary = s.boundary.data(), stack = s.stack.data(), inside = s.inside.data();
        }
        s.revisited = true;
      }
      const int i = edge_of(e);
      boundary[edges].a = v_[e - i + next3(i)];
      boundary[edges].outside = l;
      if constexpr (kInside) boundary[edges].inside = e;
      ++edges;
    }
    s.size = size, s.edges = edges;
    return true;
  }

  /// Replaces the cavity in s by the fan of vertex p round its boundary: the cavity's slots,
  /// then two from `pool`. Returns the new triangle on the cavity's first boundary edge. Each
  /// fan triangle (p, a, b) has its boundary edge as edge 0. With constraints, a boundary
  /// edge keeps its own (find_cavity must have recorded Boundary::inside), the fan's own edges
  /// are free.
  TriangleId fill_cavity(VertexId p, CavityScratch& s, SlotPool& pool) {
    const std::size_t k = s.edges;  // the cavity's size + 2
    TriangleId* slots = s.cavity.data();
    slots[s.size] = pool.take();
    slots[s.size + 1] = pool.take();
    s.replaced += s.size - 1;
    CavityScratch::Boundary* boundary = s.boundary.data();
    const bool constrained = !constraints_.empty();
    if (constrained) keep_constraints(s);
    // The first slot and edge again after the last: the fan closes without a test.
    slots[k] = slots[0];
    boundary[k] = boundary[0];
    TriangleId before = slots[k - 1];
    for (std::size_t i = 0; i < k; ++i) {
      const TriangleId t = slots[i];
      VertexId* tv = v_ + 3 * std::size_t{t};
      Link* tl = link_ + 3 * std::size_t{t};
      const CavityScratch::Boundary& e = boundary[i];
      tv[0] = p, tv[1] = e.a, tv[2] = boundary[i + 1].a;
      // Edge 0 (a -> b) is the boundary edge; edge 1 (b -> p) borders the next triangle of the
      // fan at its edge 2 (p -> b), and edge 2 the previous one at its edge 1.
      tl[0] = e.outside;
      if (e.outside != kNoLink) link_[e.outside] = static_cast<Link>(3 * t);
      tl[1] = static_cast<Link>(3 * slots[i + 1] + 2);
      tl[2] = static_cast<Link>(3 * before + 1);
      before = t;
    }
    if (constrained) set_fan_constraints(s);
    return slots[0];
  }

  /// Flips edge e (between triangle t = (p, a, b), e its edge across from p, and u = (d, b, a)
  /// beyond it; e must have a neighbour): t becomes (p, a, d) and u (p, d, b), in their slots,
  /// the new edge p-d their edges 1 and 2 respectively (free: the constraints of the four
  /// outer edges move with them).
  void flip(Link e);

  /// Vertex p put inside triangle t (1 -> 3): t keeps (a, b, p), two slots from `pool` take
  /// (b, c, p) and (c, a, p). Returns the three, t first.
  std::array<TriangleId, 3> split_triangle(TriangleId t, VertexId p, SlotPool& pool);
  /// Vertex p put on edge e (2 -> 4, or 1 -> 2 where e has no neighbour): e's triangle t =
  /// (a, x, y) (e across from a) becomes (a, x, p), a slot from `pool` takes (a, p, y); beyond,
  /// u = (d, y, x) becomes (d, y, p) and another slot takes (d, p, x). Each half of e keeps its
  /// constraint. Returns the new triangles (t, the first slot, then u and the second slot, or
  /// kNoTriangle for those two where there is no u).
  std::array<TriangleId, 4> split_edge(Link e, VertexId p, SlotPool& pool);

  /// Whether slot t holds a triangle (kNoTriangle, a free slot, one past those in use: no).
  bool live(TriangleId t) const { return t < top_ && v_[3 * std::size_t{t}] != kNoVertex; }
  /// Marks slot t free (no triangle): the finish leaves it out.
  void free_slot(TriangleId t) {
    const std::size_t tb = 3 * std::size_t{t};
    v_[tb] = v_[tb + 1] = v_[tb + 2] = kNoVertex;
    link_[tb] = link_[tb + 1] = link_[tb + 2] = kNoLink;
  }
  /// `count` slots past those in use, for a pool (unset; the arrays grow where growable).
  /// (threads: those that make the new pages present where the arrays grow; runtime/memory.hpp)
  TriangleId grow(TriangleId count, unsigned threads = 1) {
    const TriangleId first = top_;
    make_room(top_ + count, threads);
    top_ += count;
    return first;
  }
  /// How many more slots past those in use fit in the arrays as they are (no copy).
  std::size_t room() const {
    std::size_t most = std::min(vertex_store_.capacity(), link_store_.capacity());
    if (!constraints_.empty()) most = std::min(most, constraints_.capacity());
    return most / 3 - std::min<std::size_t>(most / 3, top_);
  }
  /// Capacity for slots up to `end` (geometrically: see tds.cpp), the slots themselves not
  /// made; throws std::bad_alloc, the triangulation unchanged, where even `end` is refused.
  void reserve(TriangleId end);
  /// A pool of `count` fresh slots past those in use.
  SlotPool fresh(TriangleId count) {
    SlotPool pool;
    pool.next = grow(count);
    pool.end = pool.next + count;
    return pool;
  }
  /// What `pool` did not hand out becomes free slots (or, at the top, no slots at all).
  void give_back(SlotPool& pool);
  /// Slots from `from` on dropped (they must hold nothing that is kept).
  void truncate(TriangleId from) { top_ = std::min(top_, from); }

  /// The arrays, 3 numbers a slot (the finish turns them into the output in place). Their
  /// size is that of the storage, which may exceed 3 * slots().
  std::vector<VertexId>& vertex_array() { return vertex_store_; }
  std::vector<Link>& link_array() { return link_store_; }
  const std::vector<VertexId>& vertex_array() const { return vertex_store_; }
  const std::vector<Link>& link_array() const { return link_store_; }
  const std::vector<Constraint>& constraint_array() const { return constraints_; }
  std::vector<Constraint>& constraint_array() { return constraints_; }
  /// Bytes the arrays use (their capacity beyond is address space never touched).
  std::size_t bytes() const {
    return vertex_store_.size() * sizeof(VertexId) + link_store_.size() * sizeof(Link) +
        constraints_.size() * sizeof(Constraint);
  }

 private:
  void make_room(TriangleId end, unsigned threads = 1);
  void keep_constraints(CavityScratch& s) const;
  void set_fan_constraints(const CavityScratch& s);
  void refresh() {
    // Laundered: the vertex array's memory may have served as other objects before
    // (SlotArrays::words), whose lifetimes the kernel ended.
    v_ = std::launder(vertex_store_.data());
    link_ = link_store_.data();
  }

  bool growable_ = false;
  std::vector<VertexId> vertex_store_;
  std::vector<Link> link_store_;
  std::vector<Constraint> constraints_;
  // Their storage, which never moves while the arrays do not grow: the hot loops index these,
  // with nothing to reload after a store.
  VertexId* v_ = nullptr;
  Link* link_ = nullptr;
  TriangleId top_ = 0;
};

/// The one visibility walk, on any triangulation that gives its triangles' corners
/// (topology.corners(t), three vertex ids counter-clockwise) and the link across each edge
/// (topology.link(t, i), kNoLink where there is none): the Tds, or a finished triangulation's
/// arrays whose neighbours are triangle ids (queries/locate.cpp).
///
/// It walks from triangle t towards a point, by the point's side of each edge: side(a, b) is
/// +1, 0 or -1 as the point lies left of, on or right of a -> b. Each step crosses an edge
/// that has the point strictly on its far side, never the one it came in by, as cross(...)
/// allows: it is asked either of the edge's two vertices (cross(a, b), before the link across
/// the edge is read) or of that link (cross(l), the triangle it enters; kNoLink where there is
/// none), and returns a Step (or true for Cross, false for Blocked). In a Delaunay
/// triangulation such a walk cannot cycle (Edelsbrunner, 1990: the in-front relation of its
/// triangles seen from any point is acyclic), nor across locally Delaunay edges of any
/// triangulation (the point's power with respect to the circles falls at each step); a walk
/// that may cross other edges has its `cross` stop it after enough steps. t is left at the
/// triangle where the walk ended.
template <class Topology, class Side, class Cross>
[[gnu::always_inline]] inline Walked visibility_walk(const Topology& topology, TriangleId& t, Side&& side,
                                                     Cross&& cross) {
  constexpr bool kByVertices = std::is_invocable_v<Cross, VertexId, VertexId>;
  auto as_step = [](auto r) {
    if constexpr (std::is_same_v<decltype(r), bool>)
      return r ? Step::Cross : Step::Blocked;
    else
      return r;
  };
  // At first all three edges; then the two that the edge we came in by is not, in turn.
  int first = 0, count = 3;
  for (;;) {
    const VertexId* tv = topology.corners(t);
    Link l = kNoLink;
    bool blocked = false;
    std::uint8_t zeros = 0;
    for (int k = 0, i = first; k < count; ++k, i = next3(i)) {
      const VertexId a = tv[next3(i)], b = tv[prev3(i)];
      const int o = side(a, b);
      zeros |= static_cast<std::uint8_t>((o == 0) << i);
      if (o < 0) {
        Step step;
        if constexpr (kByVertices) {
          step = as_step(cross(a, b));
          if (step == Step::Cross) l = topology.link(t, i);
        } else {
          l = topology.link(t, i);
          step = as_step(cross(l));
        }
        if (step == Step::Cross) break;
        if (step == Step::Stop) return {false, i, 0};
        blocked = true;
        l = kNoLink;
      }
    }
    if (l == kNoLink) return {!blocked, -1, blocked ? std::uint8_t{0} : zeros};
    t = triangle_of(l);
    first = next3(edge_of(l)), count = 2;
  }
}

}  // namespace ridt::detail
