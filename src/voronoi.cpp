// The Voronoi diagram as the dual of the triangulation (ridt/voronoi.hpp): a vertex for each
// triangle, a ridge for each edge, and for each vertex of the triangulation its cell, the
// circumcentres of the triangles around it in counter-clockwise order.
#include "ridt/voronoi.hpp"

#include <numeric>

#include "arrays.hpp"
#include "cavity.hpp"
#include "circumcentre.hpp"
#include "parallel.hpp"

namespace ridt {
namespace {

using detail::next3;
using detail::prev3;

constexpr std::size_t kGrain = 1 << 15;  // triangles or vertices a thread takes at least

// The triangles around each vertex: for vertex v, a triangle holding it (one whose clockwise
// side from v is a hull edge, for a vertex on the hull) and its corner there.
struct Fans {
  std::vector<std::int32_t> start;  // triangle * 3 + corner, -1 for a point that is no vertex
  std::vector<std::uint32_t> size;  // triangles around v, +1 (the vertex at infinity) on the hull
};

Fans fans(std::size_t n, const Triangulation& t) {
  Fans f{std::vector<std::int32_t>(n, -1), std::vector<std::uint32_t>(n, 0)};
  const std::size_t count = t.size();
  for (std::size_t k = 0; k < 3 * count; ++k) {
    const VertexId v = t.triangles[k];
    ++f.size[v];
    if (f.start[v] < 0) f.start[v] = static_cast<std::int32_t>(k);
  }
  // The side clockwise from corner i runs from v to the next vertex, across from the previous.
  for (std::size_t k = 0; k < 3 * count; ++k) {
    const std::size_t tri = k / 3;
    const int i = static_cast<int>(k % 3);
    if (t.neighbors[3 * tri + prev3(i)] < 0) {
      const VertexId v = t.triangles[k];
      f.start[v] = static_cast<std::int32_t>(k);
      ++f.size[v];
    }
  }
  return f;
}

}  // namespace

Voronoi voronoi(std::span<const Point> points, const Triangulation& t, unsigned threads) {
  detail::check_arrays("voronoi", points.size(), t.triangles, t.neighbors);
  const std::size_t n = points.size(), count = t.size();
  Voronoi out;

  out.vertices.resize(count);
  detail::parallel_for(count, threads, kGrain, [&](std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k) {
      const VertexId* v = &t.triangles[3 * k];
      out.vertices[k] = detail::circumcentre(points[v[0]], points[v[1]], points[v[2]]);
    }
  });

  // Cells, one for each vertex in increasing order, and their places.
  const Fans f = fans(n, t);
  out.point_cell.assign(n, -1);
  out.cell_offsets.push_back(0);
  for (VertexId v = 0; v < n; ++v) {
    if (f.start[v] < 0) continue;
    out.point_cell[v] = static_cast<std::int32_t>(out.cell_site.size());
    out.cell_site.push_back(v);
    out.cell_offsets.push_back(out.cell_offsets.back() + f.size[v]);
  }
  for (const Duplicate& d : t.duplicates) out.point_cell[d.dropped] = out.point_cell[d.kept];
  out.cell_vertices.resize(out.cell_offsets.back());
  // Counter-clockwise around v: from triangle (v, a, b) to the one across its side v-b, which
  // is across from a, its next corner. The cells are filled in the order of their first
  // triangles, where the triangles near in memory lie near in the plane: in the order of the
  // sites, the walks around them would miss the cache at every step.
  detail::parallel_for(count, threads, kGrain, [&](std::size_t first, std::size_t last) {
    for (std::size_t k = 3 * first; k < 3 * last; ++k) {
      const VertexId v = t.triangles[k];
      if (f.start[v] != static_cast<std::int32_t>(k)) continue;
      const auto c = static_cast<std::size_t>(out.point_cell[v]);
      std::int32_t* at = &out.cell_vertices[out.cell_offsets[c]];
      std::int32_t* const end = &out.cell_vertices[out.cell_offsets[c + 1]];
      auto tri = static_cast<std::int32_t>(k / 3);
      int i = static_cast<int>(k % 3);
      const std::int32_t first_tri = tri;
      for (;;) {
        *at++ = tri;
        const std::int32_t u = t.neighbors[3 * std::size_t(tri) + next3(i)];
        if (u < 0) {
          *at++ = -1;  // the hull: the cell is open between this ray and the first one
          break;
        }
        if (u == first_tri || at == end) break;
        tri = u;
        const VertexId* w = &t.triangles[3 * std::size_t(tri)];
        i = w[0] == v ? 0 : w[1] == v ? 1 : 2;
      }
    }
  });

  // Ridges: each interior edge once, from its lower-numbered triangle, and each hull edge.
  out.ridges.reserve(count * 3 / 2 + 3);
  for (std::size_t k = 0; k < count; ++k) {
    for (int i = 0; i < 3; ++i) {
      const std::int32_t u = t.neighbors[3 * k + i];
      if (u >= 0 && static_cast<std::size_t>(u) < k) continue;
      const VertexId a = t.triangles[3 * k + next3(i)], b = t.triangles[3 * k + prev3(i)];
      Ridge r{a, b, static_cast<std::int32_t>(k), u, {}};
      // The triangle runs a -> b with its inside on the left: outward is to the right.
      if (u < 0) r.direction = {points[b].y - points[a].y, points[a].x - points[b].x};
      out.ridges.push_back(r);
    }
  }
  return out;
}

}  // namespace ridt
