#include "kernel.hpp"

#include <algorithm>
#include <cassert>
#include <stdexcept>

namespace ridt::detail {
namespace {

int sign(double a, double b) { return (a > b) - (a < b); }

// p strictly between a and b, the three being collinear.
bool between(const Point& p, const Point& a, const Point& b) {
  if (a.x != b.x) return (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x);
  return (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y);
}

}  // namespace

Kernel::Kernel(Block<Point> points, std::uint32_t n, bool symbolic,
               bool brio, bool history)
    : points_(std::move(points)), n_(n), first_symbolic_(symbolic ? n : kNone), brio_(brio),
      history_(history),
      // With history about 9 records a point: 3 from the split, 2 a flip. Without, 2 a point.
      tris_(std::uint64_t{n} * (history ? 9 : 2) + kFirstChild + 8) {
  Scratch s;
  // Ids 1 .. kMaxOwner are never triangles (mesh.hpp), nor written: the finish skips them.
  const TriangleId root = tris_.allocate(kFirstChild);
  make(root, n, n + 1, n + 2, kNone, kNone, kNone, s);
}

void Kernel::retire_pool(Scratch& s) {
  for (; s.pool_next < s.pool_end; ++s.pool_next) {
    Triangle& r = tris_[s.pool_next];
    r.v[0] = r.v[1] = r.v[2] = kNone;  // the finish keeps only triangles of real vertices
    r.n[0] = r.n[1] = r.n[2] = kNone;
    r.child = 0;
  }
}

// orient(p, q, Bk) for finite p, q is R^e * cross(q - p, Bk) + lower terms; its sign is the
// first non-zero of two coordinate comparisons. With two bounding vertices the R^3 or R^4 term
// of cross(Bi, Bj) decides, with three the orientation of B0 B1 B2.
int Kernel::orient_symbolic(VertexId a, VertexId b, VertexId c) const {
  const int bounds = (a >= n_) + (b >= n_) + (c >= n_);
  // Rotate (orientation is invariant under rotation): one bounding vertex goes last, and with
  // two of them the finite vertex goes first.
  while ((bounds == 1 && c < n_) || (bounds == 2 && a >= n_)) {
    const VertexId t = a;
    a = b, b = c, c = t;
  }
  if (bounds == 3) {
    // +1 for a rotation of (B0, B1, B2), -1 for a rotation of (B0, B2, B1).
    return ((a - n_ + 1) % 3 == b - n_) ? 1 : -1;
  }
  if (bounds == 2) return ((b - n_ + 1) % 3 == c - n_) ? 1 : -1;  // orient(B_i, B_j, a)
  const Point& p = points_[a];
  const Point& q = points_[b];
  switch (c - n_) {
    case 0: return sign(p.y, q.y) != 0 ? sign(p.y, q.y) : sign(q.x, p.x);  // B0 = (R, r)
    case 1: return sign(q.x, p.x) != 0 ? sign(q.x, p.x) : sign(q.y, p.y);  // B1 = (-r, R^2)
    default: return sign(p.x, q.x) != 0 ? sign(p.x, q.x) : sign(q.y, p.y); // B2 = (-r, -R^3)
  }
}

// incircle(a, b, c, p), p finite, (a, b, c) counter-clockwise with 1 or 2 bounding vertices.
// One: the circle through finite a, b and a far vertex tends to the half-plane left of a -> b;
// a point on the line a b is inside exactly when it lies strictly between a and b.
// Two: (a, Bi, Bj) is the lifted 4x4 determinant expanded in R and r; its leading term
// compares one coordinate of p and a, and the next term the other one.
int Kernel::incircle_symbolic(VertexId a, VertexId b, VertexId c, VertexId p) const {
  const int bounds = (a >= n_) + (b >= n_) + (c >= n_);
  if (bounds == 3) return 1;  // the root: everything is inside
  // Rotate so the finite vertices come first.
  while (c < n_ || (bounds == 2 && b < n_)) {
    const VertexId t = a;
    a = b, b = c, c = t;
  }
  const Point& d = points_[p];
  if (bounds == 1) {
    const int o = orient2d(points_[a], points_[b], d);
    if (o != 0) return o;
    return between(d, points_[a], points_[b]) ? 1 : -1;
  }
  const Point& f = points_[a];
  switch (b - n_) {
    case 0: return sign(d.y, f.y) != 0 ? sign(d.y, f.y) : sign(f.x, d.x);  // (a, B0, B1)
    case 1: return sign(f.x, d.x) != 0 ? sign(f.x, d.x) : sign(f.y, d.y);  // (a, B1, B2)
    default: return sign(f.y, d.y) != 0 ? sign(f.y, d.y) : sign(d.x, f.x); // (a, B2, B0)
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
    o[i] = orient(r.v[next(i)], r.v[prev(i)], p);
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
  return {u, rt.v[i], rt.v[next(i)], rt.v[prev(i)], ru.v[j],
          rt.n[next(i)], rt.n[prev(i)], ru.n[prev(j)], ru.n[next(j)]};
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
  return {rt.v[0], rt.v[1], rt.v[2], ru.v[j], rt.n[2], rt.n[1], ru.n[next(j)], ru.n[prev(j)]};
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

// Without history the split keeps t as the first child and makes two more; the edge split keeps
// t and u as t0 and u0; a flip turns t into n2 and u into n1. Only the neighbours that now
// border a different record are relinked.
void Kernel::split_triangle_in_place(TriangleId t, VertexId p, Scratch& s) {
  const TriangleId c1 = allocate(2, s), c2 = c1 + 1;
  const Triangle r = tris_[t];
  make(t, p, r.v[1], r.v[2], r.n[0], c1, c2, s);
  make(c1, p, r.v[2], r.v[0], r.n[1], c2, t, s);
  make(c2, p, r.v[0], r.v[1], r.n[2], t, c1, s);
  relink(r.n[1], t, c1, s);
  relink(r.n[2], t, c2, s);
  s.stack.push_back(t);
  s.stack.push_back(c1);
  s.stack.push_back(c2);
}

void Kernel::split_edge_in_place(TriangleId t, int i, VertexId p, Scratch& s) {
  ++s.edge_splits;
  const auto [u, a, b, c, d, tn_b, tn_c, un_b, un_c] = read_edge_split(t, i);

  const TriangleId t1 = allocate(2, s), u1 = t1 + 1;
  make(t, p, a, b, tn_c, u1, t1, s);
  make(t1, p, c, a, tn_b, t, u, s);
  make(u, p, d, c, un_b, t1, u1, s);
  make(u1, p, b, d, un_c, u, t, s);
  relink(tn_b, t, t1, s);
  relink(un_c, u, u1, s);
  s.stack.push_back(t);
  s.stack.push_back(t1);
  s.stack.push_back(u);
  s.stack.push_back(u1);
}

void Kernel::flip_in_place(TriangleId t, TriangleId u, int j, Scratch& s) {
  ++s.flips;
  const auto [p, a, b, q, ta, tb, uaq, uqb] = read_flip(t, u, j);

  make(t, p, q, b, uqb, tb, u, s);  // n2
  make(u, p, a, q, uaq, t, ta, s);  // n1
  relink(uqb, u, t, s);
  relink(ta, t, u, s);
  s.stack.push_back(u);
  s.stack.push_back(t);
}

// Fig. 5 with an explicit stack: each entry is a triangle (p, a, b) whose edge a b must be
// tested against the triangle on its other side.
void Kernel::legalize(VertexId p, Scratch& s) {
  while (!s.stack.empty()) {
    const TriangleId t = s.stack.back();
    s.stack.pop_back();
    const TriangleId u = tris_[t].n[0];
    if (u == kNone) continue;  // an edge of the bounding triangle
    const Triangle& ru = tris_[u];
    const bool illegal = s.cavity != nullptr
                             ? std::find(s.cavity->begin(), s.cavity->end(), u) != s.cavity->end()
                             : incircle(ru.v[0], ru.v[1], ru.v[2], p) > 0;
    if (illegal) {
      const int j = ru.n[0] == t ? 0 : (ru.n[1] == t ? 1 : 2);
      if (history_)
        flip(t, u, j, s);
      else
        flip_in_place(t, u, j, s);
    }
  }
}

}  // namespace ridt::detail
