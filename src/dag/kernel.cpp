#include "dag/kernel.hpp"

#include <algorithm>
#include <cassert>
#include <stdexcept>

namespace ridt::detail {

Kernel::Kernel(Block<Point> points, std::uint32_t n, bool symbolic, bool brio)
    : points_(std::move(points)),
      n_(n),
      vertices_(points_.get(), n, symbolic),
      brio_(brio),
      // About 9 records a point: 3 from the split, 2 a flip.
      tris_(std::uint64_t{n} * 9 + kFirstChild + 8) {
  Scratch s;
  // Ids 1 .. kMaxOwner are never triangles (dag/records.hpp), nor written: the finish skips them.
  const TriangleId root = tris_.allocate(kFirstChild);
  make(root, n, n + 1, n + 2, kNoTriangle, kNoTriangle, kNoTriangle, s);
}

void Kernel::retire_pool(Scratch& s) {
  for (; s.pool_next < s.pool_end; ++s.pool_next) {
    Triangle& r = tris_[s.pool_next];
    r.v[0] = r.v[1] = r.v[2] = kNoVertex;  // the finish keeps only triangles of real vertices
    r.n[0] = r.n[1] = r.n[2] = kNoTriangle;
    r.child = 0;
  }
}

TriangleId Kernel::descend(TriangleId t, VertexId p) const {
  for (;;) {
    const TriangleId next = step(t, p);
    if (next == t) return t;
    t = next;
  }
}

Kernel::Location Kernel::classify(TriangleId t, VertexId p) const {
  const Triangle& r = tris_[t];
  int o[3];
  int zeros = 0;
  for (int i = 0; i < 3; ++i) {
    o[i] = orient(r.v[next3(i)], r.v[prev3(i)], p);
    if (o[i] < 0) throw std::logic_error("ridt: point location left its triangle");
    zeros += o[i] == 0;
  }
  if (zeros == 0) return {t, Where::Inside, 0};
  if (zeros == 1) return {t, Where::OnEdge, o[0] == 0 ? 0 : (o[1] == 0 ? 1 : 2)};
  return {t, Where::OnVertex, o[0] != 0 ? 0 : (o[1] != 0 ? 1 : 2)};
}

/*
 * Split 1 -> 3: p strictly inside t = (v0, v1, v2).
 *
 *                 v2
 *                /|\            c0 = (p, v1, v2), neighbour n0 across v1 v2
 *               / | \           c1 = (p, v2, v0), neighbour n1 across v2 v0
 *          n1  /  |  \  n0      c2 = (p, v0, v1), neighbour n2 across v0 v1
 *             / c1|c0 \         p sits at v[0] of every child, so legalize
 *            /   _p_   \        tests the edge opposite v[0].
 *           / _-  c2 -_ \
 *         v0 ----------- v1
 *                n2
 */
void Kernel::split_triangle(TriangleId t, VertexId p, Scratch& s) {
  const TriangleId c = allocate(3, s);
  const Triangle& r = tris_[t];
  const VertexId v0 = r.v[0], v1 = r.v[1], v2 = r.v[2];
  const TriangleId n0 = r.n[0], n1 = r.n[1], n2 = r.n[2];
  make(c, p, v1, v2, n0, c + 1, c + 2, s);
  make(c + 1, p, v2, v0, n1, c + 2, c, s);
  make(c + 2, p, v0, v1, n2, c, c + 1, s);
  relink(n0, t, c, s);
  relink(n1, t, c + 1, s);
  relink(n2, t, c + 2, s);
  require_owned(t, s);
  store_link(tris_[t].n[0], p);  // t's neighbours are dead now; the descent reads p here
  publish_children(t, c | kThreeChildren, s);
  s.stack.push_back(c);
  s.stack.push_back(c + 1);
  s.stack.push_back(c + 2);
}

/*
 * Split 2 -> 4: p on the edge b c shared by t = (a, b, c) and u = (d, c, b).
 *
 *              a                  t0 = (p, a, b)   t1 = (p, c, a)    children of t,
 *            / | \                u0 = (p, d, c)   u1 = (p, b, d)    children of u;
 *      tn_c /  |  \ tn_b          t0 | t1 split along p -> a, u0 | u1 along p -> d.
 *          / t0|t1 \
 *         b----p----c
 *          \ u1|u0 /
 *      un_c \  |  / un_b
 *            \ | /
 *              d
 */
Kernel::EdgeSplit Kernel::read_edge_split(TriangleId t, int i) const {
  const Triangle& rt = tris_[t];
  const TriangleId u = rt.n[i];
  const Triangle& ru = tris_[u];
  const int j = ru.n[0] == t ? 0 : (ru.n[1] == t ? 1 : 2);
  return {u,
          rt.v[i],
          rt.v[next3(i)],
          rt.v[prev3(i)],
          ru.v[j],
          rt.n[next3(i)],
          rt.n[prev3(i)],
          ru.n[prev3(j)],
          ru.n[next3(j)]};
}

void Kernel::split_edge(TriangleId t, int i, VertexId p, Scratch& s) {
  ++s.edge_splits;
  const auto [u, a, b, c, d, tn_b, tn_c, un_b, un_c] = read_edge_split(t, i);

  const TriangleId t0 = allocate(4, s), t1 = t0 + 1, u0 = t0 + 2, u1 = t0 + 3;
  make(t0, p, a, b, tn_c, u1, t1, s);
  make(t1, p, c, a, tn_b, t0, u0, s);
  make(u0, p, d, c, un_b, t1, u1, s);
  make(u1, p, b, d, un_c, u0, t0, s);
  relink(tn_c, t, t0, s);
  relink(tn_b, t, t1, s);
  relink(un_b, u, u0, s);
  relink(un_c, u, u1, s);
  set_separator(t, p, a, s);
  set_separator(u, p, d, s);
  publish_children(t, t0, s);
  publish_children(u, u0, s);
  s.stack.push_back(t0);
  s.stack.push_back(t1);
  s.stack.push_back(u0);
  s.stack.push_back(u1);
}

// Flip the edge a b between t = (p, a, b) and u = (q, b, a) (q = u.v[j]).
//
//            a                          a
//          / | \                      /   \          n1 = (p, a, q)
//    ta   /  |  \   uaq         ta   / n1  \  uaq    n2 = (p, q, b)
//        /   |   \                  /       \        both are children of t and of u;
//       p  t | u  q      ->        p ------- q       n2 lies left of p -> q, the edge
//        \   |   /                  \       /        that separates them in the DAG.
//    tb   \  |  /   uqb         tb   \ n2  /  uqb
//          \ | /                      \   /
//            b                          b
Kernel::Flip Kernel::read_flip(TriangleId t, TriangleId u, int j) const {
  const Triangle& rt = tris_[t];
  const Triangle& ru = tris_[u];
  return {rt.v[0], rt.v[1], rt.v[2], ru.v[j], rt.n[2], rt.n[1], ru.n[next3(j)], ru.n[prev3(j)]};
}

void Kernel::flip(TriangleId t, TriangleId u, int j, Scratch& s) {
  ++s.flips;
  const auto [p, a, b, q, ta, tb, uaq, uqb] = read_flip(t, u, j);

  const TriangleId n2 = allocate(2, s), n1 = n2 + 1;
  make(n2, p, q, b, uqb, tb, n1, s);
  make(n1, p, a, q, uaq, n2, ta, s);
  relink(uqb, u, n2, s);
  relink(tb, t, n2, s);
  relink(uaq, u, n1, s);
  relink(ta, t, n1, s);
  set_separator(t, p, q, s);
  set_separator(u, p, q, s);
  publish_children(t, n2, s);
  publish_children(u, n2, s);
  s.stack.push_back(n1);
  s.stack.push_back(n2);
}

// Fig. 5 with an explicit stack: each entry is a triangle (p, a, b) whose edge a b must be
// tested against the triangle on its other side.
void Kernel::legalize(VertexId p, Scratch& s) {
  while (!s.stack.empty()) {
    const TriangleId t = s.stack.back();
    s.stack.pop_back();
    const TriangleId u = tris_[t].n[0];
    if (u == kNoTriangle) continue;  // an edge of the bounding triangle
    const Triangle& ru = tris_[u];
    const bool illegal = s.cavity != nullptr ? std::find(s.cavity->begin(), s.cavity->end(), u) != s.cavity->end()
                                             : incircle(ru.v[0], ru.v[1], ru.v[2], p) > 0;
    if (illegal) {
      const int j = ru.n[0] == t ? 0 : (ru.n[1] == t ? 1 : 2);
      flip(t, u, j, s);
    }
  }
}

}  // namespace ridt::detail
