// check_convex_hull (ridt/check.hpp): by other means than convex_hull() finds it: the
// corners' turns, and each point located in their fan.
#include <atomic>

#include "check/parts.hpp"
#include "predicates/predicates.hpp"
#include "ridt/check.hpp"
#include "runtime/parallel.hpp"

namespace ridt {

namespace {

using detail::orient2d;

// Whether the points hold three that are not collinear.
bool spread(std::span<const Point> pts) {
  if (pts.size() < 3) return false;
  std::size_t second = 1;
  while (second < pts.size() && pts[second] == pts[0]) ++second;
  for (std::size_t i = second + 1; i < pts.size(); ++i)
    if (orient2d(pts[0], pts[second], pts[i]) != 0) return true;
  return false;
}

// Whether p lies inside the convex polygon c (counter-clockwise, strictly convex) or on it:
// the wedge of the fan from c[0] that holds it by bisection, then its far side.
bool holds(std::span<const Point> pts, std::span<const VertexId> c, const Point& p) {
  const Point& o = pts[c[0]];
  const std::size_t h = c.size();
  if (orient2d(o, pts[c[1]], p) < 0 || orient2d(o, pts[c[h - 1]], p) > 0) return false;
  std::size_t lo = 1, hi = h - 1;  // orient(o, c[lo], p) >= 0 and orient(o, c[hi], p) <= 0
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    (orient2d(o, pts[c[mid]], p) >= 0 ? lo : hi) = mid;
  }
  return orient2d(pts[c[lo]], pts[c[hi]], p) >= 0;
}

}  // namespace

CheckResult check_convex_hull(std::span<const Point> pts, std::span<const VertexId> c, unsigned threads) {
  detail::Report report;
  for (const VertexId v : c)
    if (v >= pts.size()) {
      report.problem("corner ", v, " is not a point's index (", pts.size(), " points)");
      return report.result();
    }
  if (c.empty()) {
    if (spread(pts)) report.problem("no corners, but the points are not all collinear");
    return report.result("valid: no hull (fewer than three distinct points, or collinear ones)");
  }
  const std::size_t h = c.size();
  if (h < 3) {
    report.problem(h, " corners");
    return report.result();
  }
  // Strict left turns, and round once: the corners' lexicographic order rises once and falls
  // once going round (a polygon of left turns that winds twice rises and falls twice).
  std::size_t changes = 0;
  for (std::size_t i = 0; i < h; ++i) {
    const Point &a = pts[c[(i + h - 1) % h]], &b = pts[c[i]], &d = pts[c[(i + 1) % h]];
    if (orient2d(a, b, d) <= 0) report.problem("corner ", c[i], " (", i, ") is not a left turn");
    changes += detail::lex_less(a, b) != detail::lex_less(b, d);
  }
  if (changes != 2) report.problem("the corners go round more than once");
  if (report.problems() > 0) return report.result();
  std::atomic<std::size_t> outside{pts.size()};  // the least index outside
  detail::parallel_for(pts.size(), threads, 1 << 14, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i)
      if (!holds(pts, c, pts[i])) {
        std::size_t seen = outside.load();
        while (i < seen && !outside.compare_exchange_weak(seen, i)) {}
        return;
      }
  });
  if (outside.load() < pts.size()) report.problem("point ", outside.load(), " lies outside the hull");
  return report.result("valid: a convex hull of " + std::to_string(h) + " corners holds all " +
                       std::to_string(pts.size()) + " points");
}

}  // namespace ridt
