// The periodic triangulation's neighbours and its Voronoi cells (ridt/periodic.hpp).
//
// A periodic triangle's edge u -> w joins copies of u and w a fixed offset apart (w's offset
// minus u's); its twin, in the triangle beside it, runs w -> u with that offset negated. The
// edges are bucketed by their first point, and each twin is found among the few edges out of
// the far end: linear time, and the same matching serves the validator.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "periodic/periodic.hpp"
#include "predicates/predicates.hpp"
#include "predicates/shifted.hpp"
#include "runtime/parallel.hpp"
#include "tds/ids.hpp"

namespace ridt::detail {

std::vector<std::int64_t> periodic_twins(std::span<const VertexId> triangles, std::span<const Offset> offsets,
                                         std::size_t points) {
  const std::size_t edges = triangles.size();
  // Edge e runs from corner e + 1 to corner e + 2 of its triangle (e's place in it).
  auto tail = [&](std::size_t e) { return e - e % 3 + next3(static_cast<int>(e % 3)); };
  auto head = [&](std::size_t e) { return e - e % 3 + prev3(static_cast<int>(e % 3)); };
  // The edges out of each point, start[u] .. start[u + 1], each with its head's point beside it:
  // a twin is looked for among a handful of them without reading their triangles.
  struct Out {
    VertexId head;
    std::uint32_t edge;
  };
  std::vector<std::uint32_t> start(points + 1, 0);
  for (std::size_t e = 0; e < edges; ++e) ++start[triangles[tail(e)] + 1];
  for (std::size_t u = 0; u < points; ++u) start[u + 1] += start[u];
  std::vector<Out> out(edges);
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t e = 0; e < edges; ++e)
      out[fill[triangles[tail(e)]]++] = {triangles[head(e)], static_cast<std::uint32_t>(e)};
  }
  auto offset = [&](std::size_t e) {  // from the edge's tail to its head (in int: any offsets)
    return std::pair{offsets[head(e)].dx - offsets[tail(e)].dx, offsets[head(e)].dy - offsets[tail(e)].dy};
  };
  std::vector<std::int64_t> twin(edges, -1);
  parallel_for(edges, 0, 65536, [&](std::size_t from, std::size_t to) {
    for (std::size_t e = from; e < to; ++e) {
      const VertexId u = triangles[tail(e)], w = triangles[head(e)];
      const auto d = offset(e);
      for (std::uint32_t k = start[w]; k < start[w + 1]; ++k) {
        if (out[k].head != u) continue;
        const auto b = offset(out[k].edge);
        if (b.first != -d.first || b.second != -d.second) continue;
        twin[e] = twin[e] == -1 ? static_cast<std::int64_t>(out[k].edge) : -2;
      }
    }
  });
  return twin;
}

}  // namespace ridt::detail

namespace ridt {

PeriodicVoronoi periodic_voronoi(std::span<const Point> points, const PeriodicTriangulation& t) {
  using namespace detail;
  const std::size_t n = points.size(), triangles = t.size();
  if (t.offsets.size() != t.triangles.size() || t.neighbors.size() != t.triangles.size() ||
      t.neighbor_offsets.size() != t.triangles.size())
    throw InputError("periodic_voronoi: the triangulation's arrays differ in length");
  for (const VertexId v : t.triangles)
    if (v >= n)
      throw InputError("periodic_voronoi: a triangle names point " + std::to_string(v) + " of " + std::to_string(n));
  const Periods l{t.domain.width, t.domain.height};
  PeriodicVoronoi out;
  out.vertices.resize(triangles);
  for (std::size_t k = 0; k < triangles; ++k) {
    Point c[3];
    for (int i = 0; i < 3; ++i) {
      const Offset o = t.offsets[3 * k + i];
      c[i] = rounded({points[t.triangles[3 * k + i]], o.dx, o.dy}, l);
    }
    out.vertices[k] = circumcentre_bounded(c[0], c[1], c[2]);
  }
  // One corner of each point (its first), then round it counter-clockwise: from triangle k,
  // where the point is corner i, the next is across from corner i + 1.
  std::vector<std::int64_t> first(n, -1);
  for (std::size_t e = 0; e < t.triangles.size(); ++e)
    if (first[t.triangles[e]] < 0) first[t.triangles[e]] = static_cast<std::int64_t>(e);
  out.cell_offsets.assign(n + 1, 0);
  for (std::size_t v = 0; v < n; ++v) {
    out.cell_offsets[v] = static_cast<std::uint32_t>(out.cell_vertices.size());
    if (first[v] < 0) continue;
    auto e = static_cast<std::size_t>(first[v]);
    Offset at = t.offsets[e];  // the point's copy in the placement walked so far
    Offset moved{0, 0};  // how far the current triangle is moved from its own offsets
    do {
      const std::size_t k = e / 3;
      out.cell_vertices.push_back(static_cast<std::int32_t>(k));
      out.cell_shifts.push_back(make_offset(-t.offsets[e].dx, -t.offsets[e].dy));
      const std::size_t across = 3 * k + next3(static_cast<int>(e % 3));
      moved = make_offset(moved.dx + t.neighbor_offsets[across].dx, moved.dy + t.neighbor_offsets[across].dy);
      const std::size_t u = static_cast<std::size_t>(t.neighbors[across]);
      std::size_t next = 3 * u;
      for (int i = 0; i < 3; ++i)
        if (t.triangles[3 * u + i] == v && t.offsets[3 * u + i].dx + moved.dx == at.dx &&
            t.offsets[3 * u + i].dy + moved.dy == at.dy)
          next = 3 * u + i;
      e = next;
      if (out.cell_vertices.size() - out.cell_offsets[v] > 3 * triangles)
        throw InputError("periodic_voronoi: the triangles round point " + std::to_string(v) + " do not close");
    } while (e != static_cast<std::size_t>(first[v]) || moved.dx != 0 || moved.dy != 0);
  }
  out.cell_offsets[n] = static_cast<std::uint32_t>(out.cell_vertices.size());
  return out;
}

}  // namespace ridt
