// What Triangle adds to a mesh where its switches ask (triangle/triangle.hpp): every edge (e),
// the dual (v), six-node triangles (o2), the vertices of no triangle left out (j).
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include "ridt/interpolate.hpp"
#include "ridt/voronoi.hpp"
#include "tds/ids.hpp"
#include "triangle/triangle.hpp"

namespace ridt::triangle {

void every_edge(const ConstrainedTriangulation& t, Output& out) {
  std::vector<std::pair<std::uint64_t, bool>> keyed;
  for (std::size_t k = 0; k < t.size(); ++k)
    for (int i = 0; i < 3; ++i)
      if (const std::int32_t n = t.neighbors[3 * k + i]; n < 0 || static_cast<std::size_t>(n) > k) {
        const std::uint64_t a = t.triangles[3 * k + (i + 1) % 3], b = t.triangles[3 * k + (i + 2) % 3];
        keyed.push_back({std::min(a, b) << 32 | std::max(a, b), n < 0});
      }
  std::sort(keyed.begin(), keyed.end());
  const EdgeIndex pieces(t.edges);
  out.edges.clear(), out.edge_markers.clear();
  for (const auto& [key, boundary] : keyed) {
    const auto a = static_cast<VertexId>(key >> 32), b = static_cast<VertexId>(key);
    out.edges.push_back(a), out.edges.push_back(b);
    const std::size_t k = pieces.find(a, b);
    const std::int64_t own = k < out.segment_markers.size() ? out.segment_markers[k] : 0;
    out.edge_markers.push_back(own != 0 ? own : boundary);
  }
}

void add_dual(const ConstrainedTriangulation& t, unsigned threads, Output& out) {
  Triangulation mesh;
  mesh.triangles.assign(t.triangles.begin(), t.triangles.begin() + static_cast<std::ptrdiff_t>(3 * t.size()));
  mesh.neighbors.assign(t.neighbors.begin(), t.neighbors.begin() + static_cast<std::ptrdiff_t>(3 * t.size()));
  Voronoi v = voronoi(out.vertices, mesh, threads);
  out.voronoi_vertices = std::move(v.vertices);
  out.voronoi_edges.clear(), out.voronoi_directions.clear();
  for (const Ridge& r : v.ridges) {
    out.voronoi_edges.push_back(r.u), out.voronoi_edges.push_back(r.v);
    out.voronoi_directions.push_back(ray_direction(out.vertices, r));
  }
  // The vertices' attributes at each centre, as Triangle gives them: the triangle's linear
  // function of its corners', extended beyond it where the centre lies outside (its weights from
  // barycentric: exact where the centre lies on a side); NaN where the centre itself is not
  // finite (a sliver's, beyond the largest double).
  const std::size_t count = out.attribute_count;
  out.voronoi_attributes.assign(out.voronoi_vertices.size() * count, 0);
  for (std::size_t k = 0; k < out.voronoi_vertices.size() && count > 0; ++k) {
    const VertexId* c = &mesh.triangles[3 * k];
    const Point& centre = out.voronoi_vertices[k];
    if (!std::isfinite(centre.x) || !std::isfinite(centre.y)) {
      std::fill_n(&out.voronoi_attributes[k * count], count, std::numeric_limits<double>::quiet_NaN());
      continue;
    }
    const std::array<double, 3> w = barycentric(out.vertices[c[0]], out.vertices[c[1]], out.vertices[c[2]], centre);
    const double* a = out.vertex_attributes.data();
    for (std::size_t j = 0; j < count; ++j)
      out.voronoi_attributes[k * count + j] =
          w[0] * a[c[0] * count + j] + w[1] * a[c[1] * count + j] + w[2] * a[c[2] * count + j];
  }
}

void add_middles(const std::vector<std::int32_t>& neighbors, const std::vector<VertexId>& pieces, Output& out) {
  const std::size_t points = out.vertices.size(), count = out.attribute_count, triangles = out.triangles.size() / 3;
  Triangulation mesh;
  mesh.triangles = out.triangles;
  mesh.neighbors = neighbors;
  SecondOrder s = second_order(out.vertices, mesh);
  // A middle's marker by the vertices' rule: its piece's marker where not 0, else 1 on the
  // boundary, 0 inside; its attributes the mean of its ends', as linear interpolation along the
  // edge gives them.
  if (!out.vertex_markers.empty()) {
    out.vertex_markers.resize(points + s.nodes.size(), 0);
    for (std::size_t k = 0; k < triangles; ++k)
      for (int i = 0; i < 3; ++i)
        if (neighbors[3 * k + i] < 0) out.vertex_markers[s.triangles[6 * k + 3 + i]] = 1;
    const EdgeIndex index(pieces);
    for (std::size_t q = 0; q < s.nodes.size(); ++q)
      if (const std::size_t e = index.find(s.ends[2 * q], s.ends[2 * q + 1]);
          e < out.segment_markers.size() && out.segment_markers[e] != 0)
        out.vertex_markers[points + q] = out.segment_markers[e];
  }
  for (std::size_t q = 0; q < s.nodes.size() && count > 0; ++q)
    for (std::size_t j = 0; j < count; ++j)
      out.vertex_attributes.push_back(std::midpoint(out.vertex_attributes[s.ends[2 * q] * count + j],
                                                    out.vertex_attributes[s.ends[2 * q + 1] * count + j]));
  out.vertices.insert(out.vertices.end(), s.nodes.begin(), s.nodes.end());
  out.triangles = std::move(s.triangles);
  out.nodes = 6;
}

void jettison(Output& out) {
  std::vector<VertexId> id(out.vertices.size(), detail::kNoVertex);
  for (const VertexId v : out.triangles) id[v] = 0;
  const std::size_t count = out.attribute_count;
  VertexId next = 0;
  for (std::size_t v = 0; v < id.size(); ++v) {
    if (id[v] == detail::kNoVertex) continue;
    id[v] = next;
    out.vertices[next] = out.vertices[v];
    if (!out.vertex_markers.empty()) out.vertex_markers[next] = out.vertex_markers[v];
    for (std::size_t j = 0; j < count; ++j)
      out.vertex_attributes[next * count + j] = out.vertex_attributes[v * count + j];
    ++next;
  }
  out.vertices.resize(next);
  if (!out.vertex_markers.empty()) out.vertex_markers.resize(next);
  out.vertex_attributes.resize(next * count);
  for (std::vector<VertexId>* list : {&out.triangles, &out.segments, &out.edges})
    for (VertexId& v : *list) v = id[v];  // an edge's ends are corners of its triangles
}

}  // namespace ridt::triangle
