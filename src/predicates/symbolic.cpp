// The predicates on the bounding vertices (predicates/symbolic.hpp).
#include "predicates/symbolic.hpp"

namespace ridt::detail {
namespace {

int sign(double a, double b) { return (a > b) - (a < b); }

// p strictly between a and b, the three being collinear.
bool between(const Point& p, const Point& a, const Point& b) {
  if (a.x != b.x) return (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x);
  return (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y);
}

}  // namespace

// orient(p, q, Bk) for finite p, q is R^e * cross(q - p, Bk) + lower terms; its sign is the
// first non-zero of two coordinate comparisons. With two bounding vertices the R^3 or R^4 term
// of cross(Bi, Bj) decides, with three the orientation of B0 B1 B2.
int Vertices::orient_symbolic(VertexId a, VertexId b, VertexId c) const {
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
    case 0:
      return sign(p.y, q.y) != 0 ? sign(p.y, q.y) : sign(q.x, p.x);  // B0 = (R, r)
    case 1:
      return sign(q.x, p.x) != 0 ? sign(q.x, p.x) : sign(q.y, p.y);  // B1 = (-r, R^2)
    default:
      return sign(p.x, q.x) != 0 ? sign(p.x, q.x) : sign(q.y, p.y);  // B2 = (-r, -R^3)
  }
}

// incircle(a, b, c, p), p finite, (a, b, c) counter-clockwise with 1 or 2 bounding vertices.
// One: the circle through finite a, b and a far vertex tends to the half-plane left of a -> b;
// a point on the line a b is inside exactly when it lies strictly between a and b.
// Two: (a, Bi, Bj) is the lifted 4x4 determinant expanded in R and r; its leading term
// compares one coordinate of p and a, and the next term the other one.
int Vertices::incircle_symbolic(VertexId a, VertexId b, VertexId c, VertexId p) const {
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
    case 0:
      return sign(d.y, f.y) != 0 ? sign(d.y, f.y) : sign(f.x, d.x);  // (a, B0, B1)
    case 1:
      return sign(f.x, d.x) != 0 ? sign(f.x, d.x) : sign(f.y, d.y);  // (a, B1, B2)
    default:
      return sign(f.y, d.y) != 0 ? sign(f.y, d.y) : sign(d.x, f.x);  // (a, B2, B0)
  }
}

int Vertices::orient_open(VertexId a, VertexId b, VertexId c) const { return orient(a, b, c); }

int Vertices::incircle_open(VertexId a, VertexId b, VertexId c, VertexId p) const { return incircle(a, b, c, p); }

int Vertices::orient_special(VertexId a, VertexId b, VertexId c) const {
  if (std::max(a, std::max(b, c)) >= first_symbolic_) return orient_symbolic(a, b, c);
  return orient2d_lattice(points_[a], points_[b], points_[c]);
}

int Vertices::incircle_special(VertexId a, VertexId b, VertexId c, VertexId p) const {
  if (std::max(a, std::max(b, c)) >= first_symbolic_) return incircle_symbolic(a, b, c, p);
  return incircle_sos_lattice(points_[a], points_[b], points_[c], points_[p]);
}

}  // namespace ridt::detail
