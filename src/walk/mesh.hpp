// The walking kernel: a flat triangle mesh without history, points located by walking and
// inserted by Bowyer-Watson cavities. It serves the serial method with Locate::Walk and the
// partition method (methods/partition.cpp), whose threads share one mesh without a lock.
//
// Slot t of the mesh is a triangle: v[3t + i] its vertices, counter-clockwise, and
// link[3t + i] the edge across from v[3t + i], named by its place in the neighbour's arrays
// (3u + j: the neighbour is u, and the shared edge is u's edge j), or kNoLink on the outer
// edges of the bounding triangle. The edge across from v[i] runs v[next(i)] -> v[prev(i)], so
// going round a triangle counter-clockwise its edges come in the order i, next(i), prev(i).
//
// An insertion replaces the m triangles whose circumcircle holds the new point p (the cavity:
// with exact predicates and the symbolic perturbation it is a disk whose triangles have all
// their vertices on its boundary, so its dual graph is a tree) by the m + 2 triangles that join
// p to the cavity's boundary edges, writing m of them over the cavity's slots. A mesh of k
// points thus always fills exactly 2k + 1 slots, and the arrays never grow.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "predicates/symbolic.hpp"
#include "ridt/ridt.hpp"

namespace ridt::detail {

using Link = std::int32_t;
inline constexpr Link kNoLink = -1;
inline constexpr VertexId kNoVertex = 0xffffffffu;
inline constexpr TriangleId kNoTriangle = 0xffffffffu;
/// Links 3u + j must fit in a Link: 2n + 1 slots of 3 edges.
inline constexpr std::uint64_t kMaxWalkingPoints = (std::uint64_t{std::numeric_limits<Link>::max()} - 8) / 6;

// Without branches: a branch on the edge index is taken at random, and mispredicted often.
constexpr int next3(int i) { return (1 << i) & 3; }  // 0 -> 1, 1 -> 2, 2 -> 0
constexpr int prev3(int i) { return (0x12 >> (2 * i)) & 3; }  // 0 -> 2, 1 -> 0, 2 -> 1
/// The triangle and the edge a link names (unsigned: cheaper to divide; never kNoLink).
constexpr TriangleId triangle_of(Link l) { return static_cast<std::uint32_t>(l) / 3; }
constexpr int edge_of(Link l) { return static_cast<int>(static_cast<std::uint32_t>(l) % 3); }
static_assert(next3(0) == 1 && next3(1) == 2 && next3(2) == 0 && prev3(0) == 2 && prev3(1) == 0 && prev3(2) == 1);

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
  };
  std::vector<TriangleId> cavity;  // the cavity's slots, then the two new ones
  std::vector<Boundary> boundary;
  std::vector<Link> stack;
  std::vector<std::uint8_t> inside;  // beside each edge on the stack: the triangle across it is in the cavity
  std::size_t size = 0;  // triangles in the cavity
  std::size_t edges = 0;  // boundary edges found
  std::uint64_t replaced = 0;  // triangles replaced beyond the first, over all insertions

  CavityScratch() { make_room(64); }
  /// Room for a cavity of m triangles.
  void make_room(std::size_t m) {
    if (m + 3 <= cavity.size()) return;
    const std::size_t room = std::max<std::size_t>(2 * m, 64);
    cavity.resize(room + 3), boundary.resize(room + 3), stack.resize(room + 3), inside.resize(room + 3);
  }
};

/// The walking mesh's two arrays, made before the mesh: room for the 2n + 1 slots of n points,
/// their pages made present by up to `threads` threads. Until the mesh takes them their memory
/// may serve other work (words(), numbers()): pages already present cost nothing more, where fresh ones
/// are faulted in and zeroed one by one, which on a virtual machine can cost several times
/// the work done in them.
struct MeshArrays {
  std::vector<VertexId> v;
  std::vector<Link> link;

  MeshArrays(std::uint64_t n, unsigned threads);
  /// The vertex array's memory as 3n + 1 words, and the link array's as 6n + 3 unsigned
  /// numbers, for work done before the mesh is made; what is written there is lost.
  std::span<std::uint64_t> words();
  std::span<std::uint32_t> numbers() {
    // An unsigned view of signed numbers is an allowed alias.
    return {reinterpret_cast<std::uint32_t*>(link.data()), link.size()};
  }
};

class Mesh {
 public:
  /// walk's `cross` and find_cavity's `owned` that allow every edge and triangle.
  static constexpr auto kAnywhere = [](Link) { return true; };

  /// The mesh of the bounding triangle alone in `arrays` (made for vertices.n() points).
  Mesh(const Vertices& vertices, MeshArrays arrays);
  Mesh(const Mesh&) = delete;
  Mesh& operator=(const Mesh&) = delete;

  const Vertices& vertices() const { return vertices_; }
  /// Slots in use (each a triangle, or free: see free_slot).
  TriangleId slots() const { return top_; }
  VertexId vertex(TriangleId t, int i) const { return v_[3 * std::size_t{t} + i]; }
  Link link(TriangleId t, int i) const { return link_[3 * std::size_t{t} + i]; }
  /// The vertex of triangle_of(l) across from its edge edge_of(l).
  VertexId opposite(Link l) const { return v_[static_cast<std::uint32_t>(l)]; }

  /// Walks from triangle t to one whose closure holds point p, and returns it. Each step
  /// crosses an edge that has p strictly on its far side, never the one it came in by. In a
  /// Delaunay triangulation such a walk cannot cycle (Edelsbrunner, 1990: the in-front
  /// relation of its triangles seen from any point is acyclic), and the symbolic bounding
  /// vertices keep it one.
  TriangleId walk(TriangleId t, VertexId p) const {
    walk(t, p, kAnywhere);
    return t;
  }
  /// The same, crossing only the edges that `cross` allows: of the edges that have p on their
  /// far side it takes one that `cross` allows, asked either of the edge's two vertices
  /// (cross(a, b), before the link across the edge is read) or of that link (cross(l), the
  /// triangle it enters). True when it got there; else t is the last triangle it reached.
  /// (The partition method's regions: methods/partition.cpp.)
  /// kLattice: the predicates' lattice forms (Vertices::lattice() must hold).
  template <bool kLattice = false, class Cross>
  bool walk(TriangleId& t, VertexId p, Cross&& cross) const {
    constexpr bool kByVertices = std::is_invocable_v<Cross, VertexId, VertexId>;
    const Point q = vertices_[p];
    // At first all three edges; then the two that the edge we came in by is not, in turn.
    int first = 0, count = 3;
    for (;;) {
      const VertexId* tv = v_ + 3 * std::size_t{t};
      const Link* tl = link_ + 3 * std::size_t{t};
      int out = 3;
      bool blocked = false;
      for (int k = 0, i = first; k < count; ++k, i = next3(i)) {
        const VertexId a = tv[next3(i)], b = tv[prev3(i)];
        if (vertices_.orient<kLattice>(a, b, p, q) < 0) {
          bool crossed;
          if constexpr (kByVertices)
            crossed = cross(a, b);
          else
            crossed = cross(tl[i]);
          if (crossed) {
            out = i;
            break;
          }
          blocked = true;
        }
      }
      if (out == 3) return !blocked;
      const Link l = tl[out];
      t = triangle_of(l);
      first = next3(edge_of(l)), count = 2;
    }
  }

  /// Whether point p coincides with a vertex of triangle t (whose closure holds it): the
  /// vertex, or kNoVertex. (A symbolic bounding vertex's point is NaN, equal to none.)
  VertexId coincident(TriangleId t, VertexId p) const {
    const Point& q = vertices_[p];
    for (int i = 0; i < 3; ++i) {
      const VertexId w = vertex(t, i);
      if (vertices_[w] == q) return w;
    }
    return kNoVertex;
  }

  /// Finds the cavity of p, which holds triangle t (whose closure holds p, and p is no
  /// vertex of it), into s.cavity and s.boundary. False, with nothing found, when it would
  /// take a triangle that `owned` refuses. `owned(l)` is asked of the triangle the cavity
  /// enters by link l (its edge edge_of(l)) from one already in it, before any vertex of it
  /// but opposite(l) is read. (The partition method: a cavity of the thread's own triangles
  /// grows by one that shares two vertices with one of them, so the vertex opposite the edge
  /// decides.) Reads only.
  template <bool kLattice = false, class Owned>
  bool find_cavity(TriangleId t, VertexId p, CavityScratch& s, Owned&& owned) const {
    const Point q = vertices_[p];
    TriangleId* cavity = s.cavity.data();
    CavityScratch::Boundary* boundary = s.boundary.data();
    Link* stack = s.stack.data();
    std::uint8_t* inside = s.inside.data();
    // Whether the triangle across edge e has p inside its circle. The edges of a triangle that
    // joins the cavity are tested together, as it joins, not one by one as they leave the
    // stack: the tests are independent, so the processor overlaps them, where each test after
    // a branch on the last one's result (taken at random) waited for that result. The tests
    // are the same ones; a triangle tested is a neighbour of one in the cavity, which the
    // partition method's threads may read (methods/partition.cpp).
    auto in_circle = [&](Link e) {
      const Link l = link_[e];
      if (l == kNoLink) return false;
      const VertexId* uv = v_ + 3 * std::size_t{triangle_of(l)};
      return vertices_.incircle<kLattice>(uv[0], uv[1], uv[2], p, q) > 0;
    };
    std::size_t size = 1, edges = 0, top = 0;
    cavity[0] = t;
    // Edges to look across, last first: round the cavity counter-clockwise, so that its
    // boundary comes out in order.
    const Link base = static_cast<Link>(3 * t);
    const bool in2 = in_circle(base + 2), in1 = in_circle(base + 1), in0 = in_circle(base);
    stack[top] = base + 2, inside[top++] = in2;
    stack[top] = base + 1, inside[top++] = in1;
    stack[top] = base, inside[top++] = in0;
    while (top > 0) {
      const Link e = stack[--top];
      const Link l = link_[e];
      if (inside[top]) {
        if (!owned(l)) return false;
        const TriangleId u = triangle_of(l);
        if (size + 1 + 3 > s.cavity.size()) {  // rare: a large cavity
          s.make_room(size + 1);
          cavity = s.cavity.data(), boundary = s.boundary.data(), stack = s.stack.data(), inside = s.inside.data();
        }
        cavity[size++] = u;
        // Entered by its edge j: the other two, counter-clockwise from there.
        const int j = edge_of(l);
        const Link ub = static_cast<Link>(3 * u);
        const Link before = ub + prev3(j), after = ub + next3(j);
        const bool in_before = in_circle(before), in_after = in_circle(after);
        stack[top] = before, inside[top++] = in_before;
        stack[top] = after, inside[top++] = in_after;
        continue;
      }
      const int i = edge_of(e);
      boundary[edges++] = {v_[e - i + next3(i)], l};
    }
    s.size = size, s.edges = edges;
    return true;
  }

  /// Replaces the cavity in s by the fan of p round its boundary: the cavity's slots, then two
  /// from `pool`. Returns the new triangle on the cavity's first boundary edge.
  TriangleId fill_cavity(VertexId p, CavityScratch& s, SlotPool& pool) {
    const std::size_t k = s.edges;  // the cavity's size + 2
    TriangleId* slots = s.cavity.data();
    slots[s.size] = pool.take();
    slots[s.size + 1] = pool.take();
    s.replaced += s.size - 1;
    CavityScratch::Boundary* boundary = s.boundary.data();
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
    return slots[0];
  }

  /// Inserts p with no regions: walks from `last` (left at a triangle by p), returns the
  /// vertex p coincides with (nothing inserted), else kNoVertex.
  template <bool kLattice = false>
  VertexId insert(VertexId p, TriangleId& last, CavityScratch& s, SlotPool& pool) {
    walk<kLattice>(last, p, kAnywhere);
    if (const VertexId hit = coincident(last, p); hit != kNoVertex) return hit;
    find_cavity<kLattice>(last, p, s, [](Link) { return true; });
    last = fill_cavity(p, s, pool);
    return kNoVertex;
  }

  /// Marks slot t free (no triangle): the finish leaves it out.
  void free_slot(TriangleId t) {
    const std::size_t tb = 3 * std::size_t{t};
    v_[tb] = v_[tb + 1] = v_[tb + 2] = kNoVertex;
    link_[tb] = link_[tb + 1] = link_[tb + 2] = kNoLink;
  }
  /// `count` slots past those in use, for a pool.
  TriangleId grow(TriangleId count) {
    const TriangleId first = top_;
    check_room(top_ + count);
    top_ += count;
    return first;
  }
  /// What `pool` did not hand out becomes free slots (or, at the top, no slots at all).
  void give_back(SlotPool& pool);

  /// The arrays, for the finish, which turns them into the output in place.
  std::vector<VertexId>& vertex_array() { return vertex_store_; }
  std::vector<Link>& link_array() { return link_store_; }

 private:
  void check_room(TriangleId end) const;

  Vertices vertices_;
  std::vector<VertexId> vertex_store_;
  std::vector<Link> link_store_;
  // Their storage, which never moves while the mesh is in use: the hot loops index these, with
  // nothing to reload after a store.
  VertexId* v_ = nullptr;
  Link* link_ = nullptr;
  TriangleId top_ = 0;
};

}  // namespace ridt::detail
