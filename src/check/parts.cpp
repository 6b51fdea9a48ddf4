// The validator's shared parts (check/parts.hpp).
#include "check/parts.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "predicates/predicates.hpp"
#include "runtime/parallel.hpp"

namespace ridt::detail {

// Huge or tiny coordinates: an exactly scaled copy keeps the predicates on their fast path.
// Empty when the input needs none.
std::vector<Point> exactly_scaled(std::span<const Point> input) {
  std::vector<Point> scaled;
  if (const int k = detail::exact_scale_exponent(input); k != 0) {
    scaled.reserve(input.size());
    for (const Point& p : input) scaled.push_back({std::ldexp(p.x, k), std::ldexp(p.y, k)});
  }
  return scaled;
}

Adjacency Adjacency::of_pairs(std::size_t n, std::span<const VertexId> pairs) {
  Adjacency a{std::vector<std::size_t>(n + 1, 0), std::vector<VertexId>(pairs.size())};
  for (const VertexId v : pairs) ++a.start[v + 1];
  std::partial_sum(a.start.begin(), a.start.end(), a.start.begin());
  std::vector<std::size_t> at(a.start.begin(), a.start.end() - 1);
  for (std::size_t k = 0; k + 1 < pairs.size(); k += 2)
    a.list[at[pairs[k]]++] = pairs[k + 1], a.list[at[pairs[k + 1]]++] = pairs[k];
  return a;
}

Adjacency Adjacency::of_triangles(std::size_t n, std::span<const VertexId> tris) {
  Adjacency a{std::vector<std::size_t>(n + 1, 0), std::vector<VertexId>(2 * tris.size())};
  for (const VertexId v : tris) a.start[v + 1] += 2;
  std::partial_sum(a.start.begin(), a.start.end(), a.start.begin());
  std::vector<std::size_t> at(a.start.begin(), a.start.end() - 1);
  for (std::size_t t = 0; t + 2 < tris.size(); t += 3)
    for (int i = 0; i < 3; ++i) {
      const VertexId u = tris[t + i], w = tris[t + (i + 1) % 3];
      a.list[at[u]++] = w, a.list[at[w]++] = u;
    }
  return a;
}

// Every index in range, every triangle counter-clockwise and not degenerate; marks the
// vertices used.
void check_triangles(std::span<const Point> pts, std::span<const VertexId> tris, std::vector<std::uint8_t>& used,
                     Report& report) {
  const std::size_t n = pts.size();
  for (std::size_t t = 0; t < tris.size() / 3; ++t) {
    const VertexId* v = &tris[3 * t];
    if (v[0] >= n || v[1] >= n || v[2] >= n) {
      report.problem("triangle ", t, " has a vertex index out of range");
      continue;
    }
    if (orient2d(pts[v[0]], pts[v[1]], pts[v[2]]) <= 0)
      report.problem("triangle ", t, " (", v[0], " ", v[1], " ", v[2], ") is not counter-clockwise or is degenerate");
    used[v[0]] = used[v[1]] = used[v[2]] = 1;
  }
}

namespace {

// A side of a triangle filed under its smaller vertex.
struct Side {
  VertexId hi;
  std::uint32_t tri_dir;  // triangle * 2 + (1 if the triangle runs lo -> hi)
};

// The sides filed under vertex lo, [begin, end): sorted by their other end, then each edge
// checked; the boundary's edges appended to `boundary`, directed as their triangles run.
void check_file(std::span<const Point> pts, std::span<const VertexId> tris, const std::vector<Edge>& constrained,
                VertexId lo, Side* begin, Side* end, std::vector<Edge>& boundary, Report& report) {
  // The vertex of triangle t opposite its edge {a, b}.
  auto opposite = [&](std::uint32_t t, VertexId a, VertexId b) {
    const VertexId* w = &tris[3 * std::size_t{t}];
    return w[0] != a && w[0] != b ? w[0] : (w[1] != a && w[1] != b ? w[1] : w[2]);
  };
  std::sort(begin, end,
            [](const Side& x, const Side& y) { return x.hi < y.hi || (x.hi == y.hi && x.tri_dir < y.tri_dir); });
  for (Side* e = begin; e != end;) {
    Side* run = e;
    while (e != end && e->hi == run->hi) ++e;
    const VertexId hi = run->hi;
    if (e - run == 1) {
      if (run->tri_dir & 1)
        boundary.emplace_back(lo, hi);
      else
        boundary.emplace_back(hi, lo);
    } else if (e - run > 2 || (run[0].tri_dir & 1) == (run[1].tri_dir & 1)) {
      report.problem("edge ", lo, "-", hi, " is used by two triangles in the same direction");
    } else {
      if (std::binary_search(constrained.begin(), constrained.end(), Edge{lo, hi})) continue;  // a segment's
      const std::uint32_t t = run[0].tri_dir >> 1, u = run[1].tri_dir >> 1;
      const VertexId* v = &tris[3 * std::size_t{t}];
      const VertexId o = opposite(u, lo, hi);
      if (incircle(pts[v[0]], pts[v[1]], pts[v[2]], pts[o]) > 0)
        report.problem("edge ", lo, "-", hi, " is not locally Delaunay (vertex ", o,
                       " lies inside the circle of triangle ", t, ")");
    }
  }
}

}  // namespace

// Every directed edge used once, every interior edge locally Delaunay but those of segments
// (`constrained`: (lo, hi), sorted). Returns the boundary edges, directed as their triangles run.
//
// Every side of every triangle is filed under its smaller vertex (a counting sort), then
// ordered by the larger one within each file, so that the two sides of an interior edge lie
// next to each other. Linear time but for vertices of very high degree. The files are checked
// on threads, each part's boundary and problems merged in order: what one thread would find,
// in its order.
std::vector<Edge> check_edges(std::span<const Point> pts, std::span<const VertexId> tris,
                              const std::vector<Edge>& constrained, Report& report) {
  const std::size_t n = pts.size(), count = tris.size() / 3;
  auto side_end = [&](std::size_t k) { return tris[k % 3 == 2 ? k - 2 : k + 1]; };
  std::vector<std::uint32_t> file(n + 1, 0);
  for (std::size_t k = 0; k < 3 * count; ++k) ++file[std::min(tris[k], side_end(k)) + 1];
  std::partial_sum(file.begin(), file.end(), file.begin());
  std::vector<Side> sides(3 * count);
  {
    std::vector<std::uint32_t> at(file.begin(), file.end() - 1);
    for (std::size_t k = 0; k < 3 * count; ++k) {
      const VertexId a = tris[k], b = side_end(k);
      sides[at[std::min(a, b)]++] = {std::max(a, b), 2 * static_cast<std::uint32_t>(k / 3) + (a < b ? 1u : 0u)};
    }
  }
  struct Part {
    std::vector<Edge> boundary;
    Report report;
  };
  InOrder<Part> parts;
  parallel_for(n, thread_count(0), 1 << 14, [&](std::size_t first, std::size_t last) {
    Part p;
    for (std::size_t lo = first; lo < last; ++lo)
      check_file(pts, tris, constrained, static_cast<VertexId>(lo), sides.data() + file[lo],
                 sides.data() + file[lo + 1], p.boundary, p.report);
    parts.put(first, std::move(p));
  });
  std::vector<Edge> boundary;
  for (Part& p : parts.take()) {
    boundary.insert(boundary.end(), p.boundary.begin(), p.boundary.end());
    report.merge(p.report);
  }
  return boundary;
}

// The convex hull, counter-clockwise, with points on its edges kept, over distinct points
// given as indices sorted lexicographically (Andrew's monotone chain). Requires at least three
// non-collinear points.
std::vector<VertexId> hull_with_collinear(std::span<const Point> pts, const std::vector<VertexId>& sorted) {
  std::vector<VertexId> h;
  auto chain = [&](auto begin, auto end) {
    const std::size_t base = h.size();
    for (auto it = begin; it != end; ++it) {
      while (h.size() >= base + 2 && orient2d(pts[h[h.size() - 2]], pts[h.back()], pts[*it]) < 0) h.pop_back();
      h.push_back(*it);
    }
    h.pop_back();  // the last point starts the other chain
  };
  chain(sorted.begin(), sorted.end());
  chain(sorted.rbegin(), sorted.rend());
  return h;
}

// Triangles exactly when the points are not degenerate; then the boundary is the convex hull
// and Euler's count holds: #T = 2V - 2 - H.
void check_hull_and_count(std::span<const Point> pts, const Distinct& d, std::vector<Edge> boundary, std::size_t count,
                          std::size_t vertices, Report& report) {
  if (d.degenerate) {
    if (count > 0)
      report.problem("the points are ", d.first.size() < 3 ? "fewer than three" : "collinear",
                     " but there are triangles");
    return;
  }
  if (count == 0) {
    report.problem("no triangles for ", d.first.size(), " non-collinear points");
    return;
  }
  const std::vector<VertexId> hull = hull_with_collinear(pts, d.first);
  std::vector<Edge> expected;
  for (std::size_t i = 0; i < hull.size(); ++i) expected.emplace_back(hull[i], hull[(i + 1) % hull.size()]);
  // The triangulation may name another index of a duplicate group: compare by coordinates.
  auto canonical = [&](VertexId v) {
    return *std::lower_bound(d.first.begin(), d.first.end(), v,
                             [&](VertexId a, VertexId b) { return detail::lex_less(pts[a], pts[b]); });
  };
  for (Edge& e : boundary) e = {canonical(e.first), canonical(e.second)};
  std::sort(expected.begin(), expected.end());
  std::sort(boundary.begin(), boundary.end());
  if (boundary != expected) {
    std::vector<Edge> missing;
    std::set_difference(expected.begin(), expected.end(), boundary.begin(), boundary.end(),
                        std::back_inserter(missing));
    if (!missing.empty())
      report.problem("convex hull edge ", missing[0].first, "->", missing[0].second, " is missing (", missing.size(),
                     " hull edges missing)");
    else
      report.problem("the boundary has ", boundary.size(), " edges, the convex hull ", expected.size());
  }
  const std::size_t h = hull.size();
  if (count != 2 * vertices - 2 - h)
    report.problem(count, " triangles, but ", vertices, " vertices with ", h, " on the hull need ",
                   2 * vertices - 2 - h);
}

// Some extreme points' convex polygon, counter-clockwise: the least and greatest
// lexicographically, by y, by x + y and by x - y (the sums rounded: they only choose points).
// Empty where those points are fewer than three distinct or collinear.
namespace {

std::vector<VertexId> extreme_polygon(std::span<const Point> pts) {
  if (pts.size() < 3) return {};
  VertexId e[8] = {};
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const Point& p = pts[i];
    auto take = [&](int k, bool better) {
      if (better) e[k] = static_cast<VertexId>(i);
    };
    take(0, lex_less(p, pts[e[0]]));
    take(1, lex_less(pts[e[1]], p));
    take(2, p.y < pts[e[2]].y);
    take(3, p.y > pts[e[3]].y);
    take(4, p.x + p.y < pts[e[4]].x + pts[e[4]].y);
    take(5, p.x + p.y > pts[e[5]].x + pts[e[5]].y);
    take(6, p.x - p.y < pts[e[6]].x - pts[e[6]].y);
    take(7, p.x - p.y > pts[e[7]].x - pts[e[7]].y);
  }
  std::vector<VertexId> corners(e, e + 8);
  std::sort(corners.begin(), corners.end(), [&](VertexId a, VertexId b) { return lex_less(pts[a], pts[b]); });
  corners.erase(std::unique(corners.begin(), corners.end(), [&](VertexId a, VertexId b) { return pts[a] == pts[b]; }),
                corners.end());
  bool flat = true;
  for (std::size_t i = 2; flat && i < corners.size(); ++i)
    flat = orient2d(pts[corners[0]], pts[corners[1]], pts[corners[i]]) == 0;
  if (corners.size() < 3 || flat) return {};
  return hull_with_collinear(pts, corners);
}

}  // namespace

// The points not strictly inside the extreme polygon (all of them where it is empty), grouped:
// `first` the least index of each group of equal points, in lexicographic order, and
// `degenerate` where those are fewer than three or collinear (then so are all the points: the
// extreme polygon is empty). They hold the convex hull's corners and the points on its sides.
Distinct near_the_hull(std::span<const Point> pts, unsigned threads) {
  const std::vector<VertexId> polygon = extreme_polygon(pts);
  InOrder<std::vector<VertexId>> kept;
  parallel_for(pts.size(), threads, 1 << 16, [&](std::size_t first, std::size_t last) {
    std::vector<VertexId> near;
    for (std::size_t i = first; i < last; ++i) {
      bool inside = !polygon.empty();
      for (std::size_t k = 0; inside && k < polygon.size(); ++k)
        inside = orient2d(pts[polygon[k]], pts[polygon[(k + 1) % polygon.size()]], pts[i]) > 0;
      if (!inside) near.push_back(static_cast<VertexId>(i));
    }
    kept.put(first, std::move(near));
  });
  std::vector<VertexId> sorted;
  for (const std::vector<VertexId>& part : kept.take()) sorted.insert(sorted.end(), part.begin(), part.end());
  std::sort(sorted.begin(), sorted.end(),
            [&](VertexId a, VertexId b) { return lex_less(pts[a], pts[b]) || (pts[a] == pts[b] && a < b); });
  return grouped(pts, std::move(sorted));
}

Distinct grouped(std::span<const Point> pts, std::vector<VertexId> sorted) {
  Distinct d;
  d.sorted = std::move(sorted);
  for (std::size_t i = 0; i < d.sorted.size(); ++i)
    if (i == 0 || !(pts[d.sorted[i]] == pts[d.sorted[i - 1]])) d.first.push_back(d.sorted[i]);
  bool collinear = true;
  for (std::size_t i = 2; collinear && i < d.first.size(); ++i)
    collinear = orient2d(pts[d.first[0]], pts[d.first[1]], pts[d.first[i]]) == 0;
  d.degenerate = d.first.size() < 3 || collinear;
  return d;
}

}  // namespace ridt::detail
