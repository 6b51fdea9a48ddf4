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
#include <string>

#include "arrays.hpp"
#include "cavity.hpp"
#include "circumcentre.hpp"
#include "parallel.hpp"

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
      start[t.triangles[3 * tri + next3(static_cast<int>(i))]] = static_cast<std::int32_t>(3 * tri + next3(static_cast<int>(i)));
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
// triangle or leaves the hull (then -1 closes the cell, between its two rays).
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
      throw InputError("voronoi: the triangles around vertex " + std::to_string(v) + " do not close: not a triangulation");
    tri = u;
    const VertexId* w = &t.triangles[3 * std::size_t(tri)];
    i = w[0] == v ? 0 : w[1] == v ? 1 : 2;
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
  out.cell_vertices.resize(vertex0.back());
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
  out.ridges.resize(first_ridge.back());
  each_part(cut, threads, [&](std::size_t p, std::size_t first, std::size_t last) {
    Ridge* r = out.ridges.data() + first_ridge[p];
    for (std::size_t k = first; k < last; ++k)
      for (int i = 0; i < 3; ++i)
        if (kept(k, i))
          *r++ = Ridge{t.triangles[3 * k + next3(i)], t.triangles[3 * k + prev3(i)], static_cast<std::int32_t>(k),
                       t.neighbors[3 * k + i]};
  });
}

}  // namespace

Voronoi voronoi(std::span<const Point> points, const Triangulation& t, unsigned threads) {
  detail::check_arrays("voronoi", points.size(), t.triangles, t.neighbors);
  const std::size_t count = t.size();
  const std::vector<std::size_t> cut = stretches(count, threads);
  Voronoi out;
  out.vertices.resize(count);
  each_part(cut, threads, [&](std::size_t, std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k) {
      const VertexId* v = &t.triangles[3 * k];
      out.vertices[k] = detail::circumcentre(points[v[0]], points[v[1]], points[v[2]]);
    }
  });
  out.point_cell.assign(points.size(), -1);
  cells(t, cut, threads, out);
  ridges(t, cut, threads, out);
  return out;
}

}  // namespace ridt
