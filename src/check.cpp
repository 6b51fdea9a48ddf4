// The validator: independent of the triangulator beyond the predicates. It builds its own
// edge table and its own convex hull (Andrew's monotone chain with exact orientation).
#include "ridt/check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "predicates.hpp"

namespace ridt {
namespace {

using detail::incircle;
using detail::orient2d;

class Report {
 public:
  template <typename... Args>
  void problem(const Args&... args) {
    if (problems_++ == 0) {
      std::ostringstream s;
      (s << ... << args);
      first_ = s.str();
    }
  }
  std::size_t problems() const { return problems_; }
  const std::string& first() const { return first_; }

 private:
  std::size_t problems_ = 0;
  std::string first_;
};

// The convex hull, counter-clockwise, with points on its edges kept, over distinct points
// given as indices sorted lexicographically. Requires at least three non-collinear points.
std::vector<VertexId> hull_with_collinear(std::span<const Point> pts,
                                          const std::vector<VertexId>& sorted) {
  std::vector<VertexId> h;
  auto chain = [&](auto begin, auto end) {
    const std::size_t base = h.size();
    for (auto it = begin; it != end; ++it) {
      while (h.size() >= base + 2 && orient2d(pts[h[h.size() - 2]], pts[h.back()], pts[*it]) < 0)
        h.pop_back();
      h.push_back(*it);
    }
    h.pop_back();  // the last point starts the other chain
  };
  chain(sorted.begin(), sorted.end());
  chain(sorted.rbegin(), sorted.rend());
  return h;
}

}  // namespace

CheckResult check(std::span<const Point> input, std::span<const VertexId> tris) {
  // The edge table below files 3 sides a triangle and names a side by 2 * triangle + direction,
  // both in 32 bits: refused before anything is counted, where either would wrap.
  if (tris.size() / 3 > kCheckMaxTriangles) {
    throw InputError(std::to_string(tris.size() / 3) + " triangles are more than the validator "
                     "takes (at most " + std::to_string(kCheckMaxTriangles) + ")");
  }
  // Huge or tiny coordinates: an exactly scaled copy keeps the predicates on their fast path.
  std::vector<Point> scaled;
  if (const int k = detail::exact_scale_exponent(input); k != 0) {
    scaled.reserve(input.size());
    for (const Point& p : input) scaled.push_back({std::ldexp(p.x, k), std::ldexp(p.y, k)});
  }
  const std::span<const Point> pts = scaled.empty() ? input : std::span<const Point>(scaled);
  Report report;
  const std::size_t n = pts.size();
  const std::size_t count = tris.size() / 3;
  if (tris.size() % 3 != 0) report.problem("the triangle list is not a multiple of 3 long");

  // Distinct points: sort (the coordinates travel with the index, so the comparisons read
  // memory in order), then group equal coordinates.
  std::vector<VertexId> sorted(n);
  {
    struct Entry {
      Point p;
      VertexId i;
    };
    std::vector<Entry> entries(n);
    for (std::size_t i = 0; i < n; ++i) entries[i] = {pts[i], static_cast<VertexId>(i)};
    std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
      return detail::lex_less(a.p, b.p) || (a.p == b.p && a.i < b.i);
    });
    for (std::size_t i = 0; i < n; ++i) sorted[i] = entries[i].i;
  }
  std::vector<VertexId> distinct;  // first index of each group, in lexicographic order
  for (std::size_t i = 0; i < n; ++i)
    if (i == 0 || !(pts[sorted[i]] == pts[sorted[i - 1]])) distinct.push_back(sorted[i]);

  bool collinear = true;
  for (std::size_t i = 2; collinear && i < distinct.size(); ++i)
    collinear = orient2d(pts[distinct[0]], pts[distinct[1]], pts[distinct[i]]) == 0;
  const bool degenerate = distinct.size() < 3 || collinear;

  // Triangles: indices and orientation.
  std::vector<std::uint8_t> used(n, 0);
  for (std::size_t t = 0; t < count; ++t) {
    const VertexId* v = &tris[3 * t];
    if (v[0] >= n || v[1] >= n || v[2] >= n) {
      report.problem("triangle ", t, " has a vertex index out of range");
      continue;
    }
    if (orient2d(pts[v[0]], pts[v[1]], pts[v[2]]) <= 0)
      report.problem("triangle ", t, " (", v[0], " ", v[1], " ", v[2],
                     ") is not counter-clockwise or is degenerate");
    used[v[0]] = used[v[1]] = used[v[2]] = 1;
  }
  if (report.problems() > 0) {
    std::ostringstream s;
    s << "invalid: " << report.first() << " (" << report.problems() << " problems)";
    return {false, s.str(), report.problems()};
  }

  // Edges: every side of every triangle, filed under its smaller vertex (a counting sort),
  // then ordered by the larger one within each file, so that the two sides of an interior
  // edge lie next to each other. Linear time but for vertices of very high degree.
  struct Side {
    VertexId hi;
    std::uint32_t tri_dir;  // triangle * 2 + (1 if the triangle runs lo -> hi)
  };
  std::vector<std::uint32_t> file(n + 1, 0);
  for (std::size_t k = 0; k < 3 * count; ++k) {
    const VertexId a = tris[k], b = tris[k % 3 == 2 ? k - 2 : k + 1];
    ++file[std::min(a, b) + 1];
  }
  std::partial_sum(file.begin(), file.end(), file.begin());
  std::vector<Side> sides(3 * count);
  {
    std::vector<std::uint32_t> at(file.begin(), file.end() - 1);
    for (std::size_t k = 0; k < 3 * count; ++k) {
      const VertexId a = tris[k], b = tris[k % 3 == 2 ? k - 2 : k + 1];
      const auto t = static_cast<std::uint32_t>(k / 3);
      sides[at[std::min(a, b)]++] = {std::max(a, b), 2 * t + (a < b ? 1u : 0u)};
    }
  }
  // The vertex of triangle t opposite its edge {a, b}.
  auto opposite = [&](std::uint32_t t, VertexId a, VertexId b) {
    const VertexId* w = &tris[3 * std::size_t{t}];
    return w[0] != a && w[0] != b ? w[0] : (w[1] != a && w[1] != b ? w[1] : w[2]);
  };
  std::vector<std::pair<VertexId, VertexId>> boundary;  // directed as their triangles run
  for (VertexId lo = 0; lo < n; ++lo) {
    Side* const begin = sides.data() + file[lo];
    Side* const end = sides.data() + file[lo + 1];
    std::sort(begin, end, [](const Side& x, const Side& y) {
      return x.hi < y.hi || (x.hi == y.hi && x.tri_dir < y.tri_dir);
    });
    for (Side* e = begin; e != end;) {
      Side* run = e;
      while (e != end && e->hi == run->hi) ++e;
      const VertexId hi = run->hi;
      if (e - run == 1) {
        if (run->tri_dir & 1) boundary.emplace_back(lo, hi); else boundary.emplace_back(hi, lo);
      } else if (e - run > 2 || (run[0].tri_dir & 1) == (run[1].tri_dir & 1)) {
        report.problem("edge ", lo, "-", hi, " is used by two triangles in the same direction");
      } else {
        const std::uint32_t t = run[0].tri_dir >> 1, u = run[1].tri_dir >> 1;
        const VertexId* v = &tris[3 * std::size_t{t}];
        const VertexId o = opposite(u, lo, hi);
        if (incircle(pts[v[0]], pts[v[1]], pts[v[2]], pts[o]) > 0)
          report.problem("edge ", lo, "-", hi, " is not locally Delaunay (vertex ", o,
                         " lies inside the circle of triangle ", t, ")");
      }
    }
  }

  // Vertices: every distinct point exactly once.
  std::size_t vertices = 0;
  for (std::size_t i = 0, g = 0; i < n; i = g) {
    std::size_t in_use = 0;
    for (g = i; g < n && pts[sorted[g]] == pts[sorted[i]]; ++g) in_use += used[sorted[g]];
    vertices += in_use > 0;
    if (count > 0 && in_use == 0)
      report.problem("point ", sorted[i], " is not a vertex of any triangle");
    if (in_use > 1) report.problem("point ", sorted[i], " appears as ", in_use, " vertices");
  }

  if (degenerate) {
    if (count > 0)
      report.problem("the points are ", distinct.size() < 3 ? "fewer than three" : "collinear",
                     " but there are triangles");
  } else if (count == 0) {
    report.problem("no triangles for ", distinct.size(), " non-collinear points");
  } else {
    // Boundary = convex hull.
    const std::vector<VertexId> hull = hull_with_collinear(pts, distinct);
    std::vector<std::pair<VertexId, VertexId>> expected;
    for (std::size_t i = 0; i < hull.size(); ++i)
      expected.emplace_back(hull[i], hull[(i + 1) % hull.size()]);
    // The triangulation may name another index of a duplicate group: compare by coordinates.
    auto canonical = [&](VertexId v) {
      return *std::lower_bound(distinct.begin(), distinct.end(), v, [&](VertexId a, VertexId b) {
        return detail::lex_less(pts[a], pts[b]);
      });
    };
    for (auto& e : boundary) e = {canonical(e.first), canonical(e.second)};
    std::sort(expected.begin(), expected.end());
    std::sort(boundary.begin(), boundary.end());
    if (boundary != expected) {
      std::vector<std::pair<VertexId, VertexId>> missing;
      std::set_difference(expected.begin(), expected.end(), boundary.begin(), boundary.end(),
                          std::back_inserter(missing));
      if (!missing.empty())
        report.problem("convex hull edge ", missing[0].first, "->", missing[0].second,
                       " is missing (", missing.size(), " hull edges missing)");
      else
        report.problem("the boundary has ", boundary.size(), " edges, the convex hull ",
                       expected.size());
    }
    // Euler.
    const std::size_t h = hull.size();
    if (count != 2 * vertices - 2 - h)
      report.problem(count, " triangles, but ", vertices, " vertices with ", h,
                     " on the hull need ", 2 * vertices - 2 - h);
  }

  std::ostringstream s;
  if (report.problems() > 0) {
    s << "invalid: " << report.first() << " (" << report.problems() << " problem"
      << (report.problems() == 1 ? "" : "s") << ")";
    return {false, s.str(), report.problems()};
  }
  s << "valid: " << count << " triangles, " << vertices << " vertices of " << n << " points ("
    << distinct.size() << " distinct), exactly Delaunay";
  if (degenerate) s << " (no triangle: " << (distinct.size() < 3 ? "fewer than three distinct points" : "all points collinear") << ")";
  return {true, s.str(), 0};
}

}  // namespace ridt
