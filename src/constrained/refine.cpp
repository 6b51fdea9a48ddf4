// Delaunay refinement (constrained/refine.hpp), after Ruppert ("A Delaunay refinement
// algorithm for quality 2-dimensional mesh generation", 1995) and Shewchuk ("Delaunay
// refinement algorithms for triangular mesh generation", 2002): a subsegment is encroached
// when a vertex it sees (not one added on another subsegment, but for a conforming
// triangulation) lies strictly inside its diametral circle. A conforming triangulation splits
// each as it is found; a constrained one where it is encroached through a triangle that the
// angle bound exempts, or where a point to be added would encroach it (Refiner::run says why).
// A split falls at the midpoint, or, where one end is a corner, at a power-of-two distance from
// it, so that splits near a small input angle fall on concentric shells and stop. Each bad
// triangle (a smallest angle below the bound, or an area above it) gets a point at its
// off-centre (Üngör, "Off-centers", 2004): the circumcentre, or, where that lies far from the
// shortest edge, the point on its bisector that makes an angle a little above the bound with it.
// A point that would encroach a subsegment is not added; the subsegment is split instead.
// Near small input angles: constrained/small_angles.cpp.
#include "constrained/refiner.hpp"

namespace ridt::detail {
namespace refining {

// Subsegment s split at its split point, or, where that cannot be placed (a vertex a rounding
// from the subsegment folds the triangles there), at a quarter or three eighths from either
// end instead; left whole where none can.
void Refiner::split(Link s) {
  if (!splittable(s)) return;
  const Unsplit key = unsplit_key(s);
  if (unsplit_.count(key) != 0) return;
  const VertexId x = m_.tds.tail(s), y = m_.tds.head(s);
  const std::pair<VertexId, VertexId> ends = chain(x, y);
  const Point &a = m_.pts[x], &b = m_.pts[y];
  auto at = [&](double f) { return Point{a.x + (b.x - a.x) * f, a.y + (b.y - a.y) * f}; };
  const Point tries[5] = {split_point(x, y), at(0.25), at(0.75), at(0.375), at(0.625)};
  for (const Point& p : tries)
    if (const VertexId v = split_at(s, p); v != kNoVertex) {
      ends_.resize(m_.pts.size(), {kNoVertex, kNoVertex});
      ends_[v] = ends;
      added(v);
      return;
    }
  unsplit_.insert(key);
}

// p added on subsegment s as though it lay on it (it does, up to rounding; on the boundary never
// beyond it, lest the domain grow over a hole's seed); where that folds a triangle, inside the one
// beside it that holds p (x-y freed, p added, x-p and p-y given its constraint, the regions
// kept); else kNoVertex.
VertexId Refiner::split_at(Link s, const Point& given) {
  const TriangleId t = triangle_of(s);
  const int k = edge_of(s);
  const Point p = boundary(s) ? m_.not_beyond(t, k, given) : given;
  if (m_.fits_on_edge(t, k, p)) return m_.insert_on_edge(p, t, k);
  if (boundary(s)) return kNoVertex;
  const Cdt::Place at = m_.beside(t, static_cast<int>(k), p);
  if (at.kind != Cdt::Place::Inside) return kNoVertex;
  const VertexId x = m_.tds.tail(s), y = m_.tds.head(s);
  // The regions of t (left of x -> y) and across, which the flips about p could mix.
  const TriangleId across = m_.across(s);
  const std::int32_t left = m_.region.empty() ? -1 : m_.region[t];
  const std::int32_t right = m_.region.empty() || across == kNoTriangle ? left : m_.region[across];
  const Constraint c = m_.tds.constraint(s);
  m_.constrain(s, kFree);
  const VertexId v = m_.insert(p, at);
  for (const VertexId e : {x, y})
    if (const Link f = m_.find_edge(v, e); f != kNoLink) m_.constrain(f, c);
  if (left != right) relabel(v, x, y, left, right);
  return v;
}

// The triangles about v, added beside segment x-y (now x-v-y), given the regions left and
// right of x -> v -> y: the flips made triangles about v, which v-x and v-y part into two fans.
// Triangle (v, p, q) is in the left one where v->p lies in the angle from v->y counter-clockwise
// to v->x (exact orientations; the angle is near a half-turn, either side of it).
void Refiner::relabel(VertexId v, VertexId x, VertexId y, std::int32_t left, std::int32_t right) {
  const Point &pv = m_.pts[v], &px = m_.pts[x], &py = m_.pts[y];
  const bool reflex = orient2d(pv, py, px) <= 0;  // the left angle is a half-turn or more
  m_.around(v, [&](std::uint32_t u) {
    const VertexId p = m_.at(u, m_.corner_of(u, v) + 1);
    bool in_left = p == y;
    if (p != x && p != y) {
      const bool after_y = orient2d(pv, py, m_.pts[p]) > 0, before_x = orient2d(pv, px, m_.pts[p]) < 0;
      in_left = reflex ? after_y || before_x : after_y && before_x;
    }
    m_.region[u] = in_left ? left : right;
    return false;
  });
}

// After v is added: its triangles queued where bad, its fixed edges where encroached.
void Refiner::added(VertexId v) {
  ends_.resize(m_.pts.size(), {kNoVertex, kNoVertex});
  m_.around(v, [&](TriangleId t) {
    queue_bad(t);
    for (int k = 0; k < 3; ++k)
      if (const Link e = link_to(t, k); m_.fixed(e) && encroached(e, !r_.conforming)) queue_split(e, false);
    return false;
  });
}

}  // namespace refining

std::string refine(Cdt& m, const Refinement& r) { return refining::Refiner(m, r).run(); }

}  // namespace ridt::detail
