// The convex hull (ridt/hull.hpp): the validator's cull of the points near the hull, then
// the chain over the few it keeps.
#include "ridt/hull.hpp"

#include <cmath>
#include <string>

#include "check/parts.hpp"
#include "predicates/predicates.hpp"
#include "tds/ids.hpp"

namespace ridt {

namespace {

// a + b exactly as hi + lo (Knuth's two-sum).
void two_sum(double a, double b, double& hi, double& lo) {
  hi = a + b;
  const double bv = hi - a;
  lo = (a - (hi - bv)) + (b - bv);
}

// Twice the signed area of the polygon, exactly, then rounded: each product x_i y_j is exact as
// a pair (its error term by a fused multiply-add), and the terms are summed into a
// nonoverlapping expansion (Shewchuk's grow-expansion, zeros dropped), whose components,
// added from the least, give the sum within one unit in the last place.
double twice_area(std::span<const Point> pts, const std::vector<VertexId>& c) {
  std::vector<double> e;
  auto add = [&](double b) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < e.size(); ++i) {
      double hi = 0, lo = 0;
      two_sum(b, e[i], hi, lo);
      if (lo != 0) e[k++] = lo;
      b = hi;
    }
    e.resize(k);
    if (b != 0) e.push_back(b);
  };
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Point &a = pts[c[i]], &b = pts[c[(i + 1) % c.size()]];
    const double p = a.x * b.y, q = a.y * b.x;
    add(p), add(std::fma(a.x, b.y, -p)), add(-q), add(-std::fma(a.y, b.x, -q));
  }
  double sum = 0;
  for (const double x : e) sum += x;
  return sum;
}

}  // namespace

ConvexHull convex_hull(std::span<const Point> points, bool boundary, unsigned threads) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
      throw InputError("point " + std::to_string(i) + " is not finite");
  ConvexHull out;
  const detail::Distinct d = detail::near_the_hull(points, threads);
  if (d.degenerate) return out;
  // Round the boundary with the points on the sides; a corner is where it turns.
  const std::vector<VertexId> round = detail::hull_with_collinear(points, d.first);
  const std::size_t m = round.size();
  std::vector<std::uint8_t> turns(m);
  for (std::size_t i = 0; i < m; ++i)
    turns[i] = detail::orient2d(points[round[(i + m - 1) % m]], points[round[i]], points[round[(i + 1) % m]]) != 0;
  for (std::size_t i = 0; i < m; ++i)
    if (turns[i]) out.corners.push_back(round[i]);
  if (boundary) {
    // The copies of each point of the boundary follow it in d.sorted (equal points by index).
    std::vector<VertexId> rank(points.size(), detail::kNoVertex);
    for (std::size_t i = 0; i < m; ++i) rank[round[i]] = static_cast<VertexId>(i);
    std::vector<std::vector<VertexId>> copies(m);
    for (std::size_t i = 1, group = 0; i < d.sorted.size(); ++i) {
      if (points[d.sorted[i]] == points[d.sorted[group]]) {
        if (rank[d.sorted[group]] != detail::kNoVertex) copies[rank[d.sorted[group]]].push_back(d.sorted[i]);
      } else {
        group = i;
      }
    }
    std::uint32_t k = 0;  // the side the walk is on (round[0] is corner 0)
    for (std::size_t i = 0; i < m; ++i) {
      if (turns[i] && i > 0) ++k;
      if (!turns[i]) out.on_sides.push_back(round[i]), out.side.push_back(k);
      for (const VertexId c : copies[i]) out.on_sides.push_back(c), out.side.push_back(k);
    }
  }
  out.area = twice_area(points, out.corners) / 2;
  double sum = 0, compensation = 0;  // Kahan's
  for (std::size_t i = 0; i < out.corners.size(); ++i) {
    const Point &a = points[out.corners[i]], &b = points[out.corners[(i + 1) % out.corners.size()]];
    const double y = std::hypot(b.x - a.x, b.y - a.y) - compensation, t = sum + y;
    compensation = (t - sum) - y;
    sum = t;
  }
  out.perimeter = sum;
  return out;
}

}  // namespace ridt
