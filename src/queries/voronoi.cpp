// The Voronoi diagram as the dual of the triangulation (ridt/voronoi.hpp): a vertex for each
// triangle, a ridge for each edge, and for each vertex of the triangulation its cell, the
// circumcentres of the triangles around it in counter-clockwise order.
//
// Every pass runs over the triangles in their order, where triangles near in memory lie near
// in the plane, and writes its output in that order: a pass driven by the sites' input order
// would miss the cache at nearly every step. Each thread takes a stretch of the triangles,
// fills its own part, and the parts are then copied into place.
#include "ridt/voronoi.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "predicates/power.hpp"
#include "predicates/predicates.hpp"
#include "queries/arrays.hpp"
#include "ridt/regular.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"
#include "tds/ids.hpp"

namespace ridt {
namespace {

using detail::next3;
using detail::prev3;

constexpr std::size_t kGrain = 1 << 15;  // triangles a part takes at least

// The stretches of the triangles that the parts take: part p has [cut[p], cut[p + 1]).
std::vector<std::size_t> stretches(std::size_t count, unsigned threads) {
  const std::size_t parts = std::clamp<std::size_t>(count / kGrain, 1, 4 * detail::thread_count(threads));
  std::vector<std::size_t> cut(parts + 1);
  for (std::size_t p = 0; p <= parts; ++p) cut[p] = count * p / parts;
  return cut;
}

// Runs body(p, first, last) for every part, on up to `threads` threads.
template <class Body>
void each_part(const std::vector<std::size_t>& cut, unsigned threads, Body&& body) {
  detail::parallel_for(cut.size() - 1, threads, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t p = first; p < last; ++p) body(p, cut[p], cut[p + 1]);
  });
}

// For each vertex the corner (triangle * 3 + corner) where its cell starts: its first corner
// in triangle order, or, on the hull, the corner whose clockwise side is a hull edge, so that
// the walk counter-clockwise from it meets every triangle before it leaves the hull. -1 for a
// point that is no vertex (a duplicate dropped, or no triangle at all).
std::vector<std::int32_t> cell_starts(std::size_t n, const Triangulation& t) {
  std::vector<std::int32_t> start(n, -1);
  for (std::size_t k = t.triangles.size(); k-- > 0;) start[t.triangles[k]] = static_cast<std::int32_t>(k);
  // The side clockwise from corner i runs from v to the next vertex, across from the previous.
  for (std::size_t k = 0; k < t.neighbors.size(); ++k)
    if (t.neighbors[k] < 0) {
      const std::size_t tri = k / 3, i = k % 3;
      start[t.triangles[3 * tri + next3(static_cast<int>(i))]] =
          static_cast<std::int32_t>(3 * tri + next3(static_cast<int>(i)));
    }
  return start;
}

// The cells that start in one stretch of the triangles, in their order.
struct Part {
  std::vector<VertexId> sites;
  std::vector<std::uint32_t> ends;  // the end of each cell's vertices in `vertices`
  std::vector<std::int32_t> vertices;
};

// Counter-clockwise around v from corner k: from triangle (v, a, b) to the one across its side
// v-b, which is across from a, its next corner, until the walk comes back to its first
// triangle or leaves the hull (then -1 closes the cell, between its two rays). The triangle
// entered, u, has v at the corner after that of its edge back to the one left, found among u's
// neighbours: the walk reads only the neighbours' array, whose entry it needs next anyway.
void walk_cell(const Triangulation& t, VertexId v, std::size_t k, std::vector<std::int32_t>& out) {
  auto tri = static_cast<std::int32_t>(k / 3);
  int i = static_cast<int>(k % 3);
  const std::int32_t first = tri;
  for (std::size_t steps = 0;; ++steps) {
    out.push_back(tri);
    const std::int32_t u = t.neighbors[3 * std::size_t(tri) + next3(i)];
    if (u < 0) {
      out.push_back(-1);
      return;
    }
    if (u == first) return;
    if (steps > t.size())
      throw InputError("voronoi: the triangles around vertex " + std::to_string(v) +
                       " do not close: not a triangulation");
    const std::int32_t* n = &t.neighbors[3 * std::size_t(u)];
    const int back = n[0] == tri ? 0 : n[1] == tri ? 1 : 2;
    tri = u;
    i = next3(back);
  }
}

void cells(const Triangulation& t, const std::vector<std::size_t>& cut, unsigned threads, Voronoi& out) {
  const std::vector<std::int32_t> start = cell_starts(out.point_cell.size(), t);
  std::vector<Part> parts(cut.size() - 1);
  each_part(cut, threads, [&](std::size_t p, std::size_t first, std::size_t last) {
    Part& part = parts[p];
    part.vertices.reserve(3 * (last - first) + (last - first) / 4 + 1024);  // about 3 a triangle, more near the hull
    part.sites.reserve(last - first);
    part.ends.reserve(last - first);
    for (std::size_t k = 3 * first; k < 3 * last; ++k) {
      const VertexId v = t.triangles[k];
      if (start[v] != static_cast<std::int32_t>(k)) continue;
      walk_cell(t, v, k, part.vertices);
      part.sites.push_back(v);
      part.ends.push_back(static_cast<std::uint32_t>(part.vertices.size()));
    }
  });
  // Each part's first cell and first vertex, then the parts copied into place.
  std::vector<std::size_t> cell0(parts.size() + 1, 0), vertex0(parts.size() + 1, 0);
  for (std::size_t p = 0; p < parts.size(); ++p) {
    cell0[p + 1] = cell0[p] + parts[p].sites.size();
    vertex0[p + 1] = vertex0[p] + parts[p].vertices.size();
  }
  if (vertex0.back() > 0xffffffffu) throw InputError("voronoi: more than 2^32 cell vertices");
  out.cell_site.resize(cell0.back());
  out.cell_offsets.resize(cell0.back() + 1);
  detail::resize_present(out.cell_vertices, vertex0.back(), detail::thread_count(threads));
  out.cell_offsets[0] = 0;
  each_part(cut, threads, [&](std::size_t p, std::size_t, std::size_t) {
    const Part& part = parts[p];
    std::copy(part.vertices.begin(), part.vertices.end(), out.cell_vertices.begin() + std::ptrdiff_t(vertex0[p]));
    for (std::size_t c = 0; c < part.sites.size(); ++c) {
      const std::size_t at = cell0[p] + c;
      out.cell_site[at] = part.sites[c];
      out.cell_offsets[at + 1] = static_cast<std::uint32_t>(vertex0[p] + part.ends[c]);
      out.point_cell[part.sites[c]] = static_cast<std::int32_t>(at);
    }
  });
  for (const Duplicate& d : t.duplicates) out.point_cell[d.dropped] = out.point_cell[d.kept];
}

// Each interior edge once, from its lower-numbered triangle, and each hull edge: counted a
// stretch at a time, then written in place.
void ridges(const Triangulation& t, const std::vector<std::size_t>& cut, unsigned threads, Voronoi& out) {
  auto kept = [&](std::size_t k, int i) {
    const std::int32_t u = t.neighbors[3 * k + i];
    return u < 0 || static_cast<std::size_t>(u) > k;
  };
  std::vector<std::size_t> first_ridge(cut.size(), 0);
  each_part(cut, threads, [&](std::size_t p, std::size_t first, std::size_t last) {
    std::size_t c = 0;
    for (std::size_t k = first; k < last; ++k) c += kept(k, 0) + kept(k, 1) + kept(k, 2);
    first_ridge[p + 1] = c;
  });
  for (std::size_t p = 1; p < cut.size(); ++p) first_ridge[p] += first_ridge[p - 1];
  detail::resize_present(out.ridges, first_ridge.back(), detail::thread_count(threads));
  each_part(cut, threads, [&](std::size_t p, std::size_t first, std::size_t last) {
    Ridge* r = out.ridges.data() + first_ridge[p];
    for (std::size_t k = first; k < last; ++k)
      for (int i = 0; i < 3; ++i)
        if (kept(k, i))
          *r++ = Ridge{t.triangles[3 * k + next3(i)], t.triangles[3 * k + prev3(i)], static_cast<std::int32_t>(k),
                       t.neighbors[3 * k + i]};
  });
}

using Pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

// The neighbours of triangle k, higher-numbered, whose fourth point lies on k's circle (exact
// in-circle test; the perturbation plays no part): (k, neighbour) appended to `found`. `p`
// holds k's three points; `only` (0 to 2) asks of that side alone.
void cocircular_with(std::span<const Point> points, const Triangulation& t, std::size_t k, const Point* p, Pairs& found,
                     int only = -1) {
  for (int i = only < 0 ? 0 : only; i < (only < 0 ? 3 : only + 1); ++i) {
    const std::int32_t u = t.neighbors[3 * k + i];
    if (u < 0 || static_cast<std::size_t>(u) < k) continue;
    // u's vertex across the shared side: the one that is not on it.
    const VertexId* w = &t.triangles[3 * static_cast<std::size_t>(u)];
    const VertexId a = t.triangles[3 * k + next3(i)], b = t.triangles[3 * k + prev3(i)];
    const VertexId d = w[0] != a && w[0] != b ? w[0] : w[1] != a && w[1] != b ? w[1] : w[2];
    if (detail::incircle(p[0], p[1], p[2], points[d]) == 0)
      found.emplace_back(static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(u));
  }
}

Pairs joined(std::vector<Pairs>& parts) {
  Pairs pairs;
  for (const Pairs& f : parts) pairs.insert(pairs.end(), f.begin(), f.end());
  return pairs;
}

// All pairs of neighbouring triangles (lower, higher) whose four points are cocircular.
Pairs cocircular_pairs(std::span<const Point> points, const Triangulation& t, const std::vector<std::size_t>& cut,
                       unsigned threads) {
  std::vector<Pairs> found(cut.size() - 1);
  each_part(cut, threads, [&](std::size_t part, std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k) {
      const Point p[3] = {points[t.triangles[3 * k]], points[t.triangles[3 * k + 1]], points[t.triangles[3 * k + 2]]};
      cocircular_with(points, t, k, p, found[part]);
    }
  });
  return joined(found);
}

// Each triangle's group of cocircular neighbours, named by its lowest triangle.
std::vector<std::uint32_t> groups(std::size_t count, const Pairs& pairs) {
  std::vector<std::uint32_t> root(count);
  for (std::size_t k = 0; k < count; ++k) root[k] = static_cast<std::uint32_t>(k);
  auto find = [&](std::uint32_t k) {
    while (root[k] != k) k = root[k] = root[root[k]];
    return k;
  };
  for (const auto& [a, b] : pairs) {
    const std::uint32_t ra = find(a), rb = find(b);
    if (ra != rb) root[std::max(ra, rb)] = std::min(ra, rb);
  }
  for (std::size_t k = 0; k < count; ++k) root[k] = find(static_cast<std::uint32_t>(k));
  return root;
}

// The merge itself, given the cocircular pairs: see merge_cocircular.
std::vector<std::int32_t> apply_merge(Voronoi& vd, std::size_t count, const Pairs& pairs) {
  std::vector<std::int32_t> vertex(count);
  for (std::size_t k = 0; k < count; ++k) vertex[k] = static_cast<std::int32_t>(k);
  if (pairs.empty()) return vertex;
  // New vertex numbers in the order of each group's lowest triangle, which comes first.
  const std::vector<std::uint32_t> root = groups(count, pairs);
  std::size_t kept = 0;  // the vertices kept, moved down in place
  for (std::size_t k = 0; k < count; ++k) {
    if (root[k] == k) {
      vertex[k] = static_cast<std::int32_t>(kept);
      vd.vertices[kept++] = vd.vertices[k];
    } else {
      vertex[k] = vertex[root[k]];
    }
  }
  vd.vertices.resize(kept);
  // Cells: each group's triangles around a site are consecutive (the group is a convex
  // polygon's), so a repeat follows its first, or closes a bounded cell onto its start.
  std::size_t at = 0;
  for (std::size_t c = 0; c < vd.cells(); ++c) {
    const std::size_t first = vd.cell_offsets[c], last = vd.cell_offsets[c + 1], start = at;
    for (std::size_t k = first; k < last; ++k) {
      const std::int32_t v = vd.cell_vertices[k] < 0 ? -1 : vertex[static_cast<std::size_t>(vd.cell_vertices[k])];
      if (at > start && vd.cell_vertices[at - 1] == v) continue;
      vd.cell_vertices[at++] = v;
    }
    if (at - start > 1 && vd.cell_vertices[at - 1] == vd.cell_vertices[start]) --at;
    vd.cell_offsets[c] = static_cast<std::uint32_t>(start);
  }
  vd.cell_offsets[vd.cells()] = static_cast<std::uint32_t>(at);
  vd.cell_vertices.resize(at);
  // Ridges: both ends renumbered; those inside a group have length zero.
  kept = 0;
  for (const Ridge& r : vd.ridges) {
    Ridge m = r;
    m.u = vertex[static_cast<std::size_t>(r.u)];
    if (r.v >= 0) m.v = vertex[static_cast<std::size_t>(r.v)];
    if (m.u != m.v) vd.ridges[kept++] = m;
  }
  vd.ridges.resize(kept);
  return vertex;
}

// The cocircular pairs among neighbours, from their circumcentres: two neighbours are
// cocircular exactly when their circles are one, their exact centres equal; each computed centre
// lies within 2^-44 of its radius and an ulp of the exact one (circumcentre_bounded), so a pair
// whose centres lie further apart than twice that is not, and only the few that do not are tested
// exactly. The centres of neighbours lie near in memory (triangles near in the plane are near in
// the triangulation's order), where the fourth point of each pair lies anywhere.
Pairs cocircular_by_centres(std::span<const Point> points, const Triangulation& t, const Voronoi& out,
                            const std::vector<float>& radius, const std::vector<std::size_t>& cut, unsigned threads) {
  std::vector<Pairs> found(cut.size() - 1);
  each_part(cut, threads, [&](std::size_t part, std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k) {
      const Point& c = out.vertices[k];
      for (int i = 0; i < 3; ++i) {
        const std::int32_t u = t.neighbors[3 * k + i];
        if (u < 0 || static_cast<std::size_t>(u) < k) continue;
        const Point& d = out.vertices[static_cast<std::size_t>(u)];
        const double r = std::max(radius[k], radius[static_cast<std::size_t>(u)]);
        const double size = std::max({std::fabs(c.x), std::fabs(c.y), std::fabs(d.x), std::fabs(d.y)});
        const double apart = 0x1p-42 * r + 0x1p-50 * size;  // twice each bound, with room
        if (!(std::fabs(c.x - d.x) <= apart && std::fabs(c.y - d.y) <= apart) && std::isfinite(apart)) continue;
        const VertexId* v = &t.triangles[3 * k];
        const Point p[3] = {points[v[0]], points[v[1]], points[v[2]]};
        cocircular_with(points, t, k, p, found[part], i);
      }
    }
  });
  return joined(found);
}

// The diagram's vertices, vertex(k, corners) each (the triangles' points read some triangles
// ahead: they are in the caller's order, so each read may miss), its cells and ridges.
template <class Vertex>
Voronoi diagram(std::span<const Point> points, const Triangulation& t, unsigned threads,
                const std::vector<std::size_t>& cut, Vertex&& vertex) {
  const std::size_t count = t.size();
  Voronoi out;
  // The large arrays' pages made present on the threads, not faulted in one by one as written.
  const unsigned workers = detail::thread_count(threads);
  detail::resize_present(out.vertices, count, workers);
  each_part(cut, threads, [&](std::size_t, std::size_t first, std::size_t last) {
    constexpr std::size_t kAhead = 8;
    for (std::size_t k = first; k < last; ++k) {
      if (k + kAhead < last)
        for (int j = 0; j < 3; ++j) __builtin_prefetch(&points[t.triangles[3 * (k + kAhead) + j]]);
      out.vertices[k] = vertex(k, &t.triangles[3 * k]);
    }
  });
  detail::resize_present(out.point_cell, points.size(), workers);
  std::fill(out.point_cell.begin(), out.point_cell.end(), -1);
  cells(t, cut, threads, out);
  ridges(t, cut, threads, out);
  return out;
}

}  // namespace

Voronoi voronoi(std::span<const Point> points, const Triangulation& t, unsigned threads, bool merge) {
  detail::check_arrays("voronoi", points.size(), t.triangles, t.neighbors);
  const std::size_t count = t.size();
  const std::vector<std::size_t> cut = stretches(count, threads);
  // With `merge` each circle's radius, rounded up.
  std::vector<float> radius;
  if (merge) detail::resize_present(radius, count, detail::thread_count(threads));
  Voronoi out = diagram(points, t, threads, cut, [&](std::size_t k, const VertexId* v) {
    const Point c = detail::circumcentre_bounded(points[v[0]], points[v[1]], points[v[2]]);
    const double dx = c.x - points[v[0]].x,
                 dy = c.y - points[v[0]].y;  // (overflow: an infinite radius, tested exactly)
    if (merge) radius[k] = static_cast<float>(std::sqrt(dx * dx + dy * dy) * (1 + 0x1p-20));
    return c;
  });
  if (merge)
    if (const Pairs pairs = cocircular_by_centres(points, t, out, radius, cut, threads); !pairs.empty())
      apply_merge(out, count, pairs);
  return out;
}

Voronoi power_diagram(std::span<const Point> points, std::span<const double> weights, const Triangulation& t,
                      unsigned threads) {
  detail::check_arrays("power_diagram", points.size(), t.triangles, t.neighbors);
  if (weights.size() != points.size())
    throw InputError("power_diagram: " + std::to_string(weights.size()) + " weights for " +
                     std::to_string(points.size()) + " points");
  return diagram(points, t, threads, stretches(t.size(), threads), [&](std::size_t, const VertexId* v) {
    const detail::Weighted a{points[v[0]], weights[v[0]]}, b{points[v[1]], weights[v[1]]},
        c{points[v[2]], weights[v[2]]};
    return detail::power_centre_bounded(a, b, c);
  });
}

std::vector<std::int32_t> merge_cocircular(std::span<const Point> points, const Triangulation& t, Voronoi& vd,
                                           unsigned threads) {
  detail::check_arrays("merge_cocircular", points.size(), t.triangles, t.neighbors);
  if (vd.vertices.size() != t.size())
    throw InputError("merge_cocircular: the diagram is not this triangulation's, or is merged already");
  return apply_merge(vd, t.size(), cocircular_pairs(points, t, stretches(t.size(), threads), threads));
}

}  // namespace ridt
