// Triangle's run (ridt/triangle.hpp): the triangulation or mesh its switches ask, then its
// markers and attributes; the extras (every edge, six-node triangles, the dual, jettisoned
// vertices) in triangle/extras.cpp.
#include "triangle/triangle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "ridt/interpolate.hpp"
#include "runtime/parallel.hpp"

namespace ridt::triangle {
namespace {

void check_sizes(const Input& in, const Switches& w) {
  const std::size_t n = in.vertices.size(), segments = in.segments.size() / 2, triangles = in.triangles.size() / 3;
  auto refuse = [](const std::string& what, std::size_t got, std::size_t want) {
    throw InputError(what + ": " + std::to_string(got) + " given for " + std::to_string(want));
  };
  if (!in.vertex_markers.empty() && in.vertex_markers.size() != n)
    refuse("vertex markers", in.vertex_markers.size(), n);
  if (in.vertex_attributes.size() != n * in.attribute_count)
    refuse("vertex attributes (" + std::to_string(in.attribute_count) + " a vertex)", in.vertex_attributes.size(),
           n * in.attribute_count);
  if (in.segments.size() % 2 != 0) throw InputError("a segment list needs an even size");
  if (!in.segment_markers.empty() && in.segment_markers.size() != segments)
    refuse("segment markers", in.segment_markers.size(), segments);
  if (!w.refine) return;
  if (in.triangles.empty()) throw InputError("switch 'r' refines a mesh: give its triangles");
  if (!in.triangle_attributes.empty() && in.triangle_attributes.size() != triangles)
    refuse("triangle attributes", in.triangle_attributes.size(), triangles);
  if (w.region_areas && in.triangle_max_area.size() != triangles)
    refuse("triangle area bounds (switches r and a with no number)", in.triangle_max_area.size(), triangles);
}

// The triangulation or mesh the switches ask of the input.
ConstrainedTriangulation run(const Input& in, const Switches& w, const Options& o, std::vector<Point>& holes) {
  Quality q = w.quality_bounds();
  const bool refining = !(w.limit_steiner && w.max_steiner == 0);  // S0: nothing refined
  if (refining) q.size = in.size;
  const std::span<const VertexId> segments = w.pslg ? std::span(in.segments) : std::span<const VertexId>{};
  if (w.refine) {
    const std::span<const double> areas =
        w.region_areas && refining ? std::span(in.triangle_max_area) : std::span<const double>{};
    return refine_mesh(in.vertices, in.triangles, segments, q, areas, in.triangle_attributes, o);
  }
  Domain domain;
  domain.convex_hull = w.convex_hull || !w.pslg;  // points alone: their hull
  if (w.pslg && !w.no_holes) domain.holes = holes = in.holes;
  if (w.pslg)
    for (Region r : in.regions) {
      if (!w.region_areas || !refining) r.max_area = 0;
      domain.regions.push_back(r);
    }
  return triangulate_constrained(in.vertices, segments, o, domain, q);
}

// Triangle's markers: a piece's, its segment's where not 0, else 1 on the boundary, 0 inside;
// a vertex's, the input's where not 0, else that of the last marked segment it ends a piece of,
// else 1 on the boundary, 0 inside.
void mark(const Input& in, const ConstrainedTriangulation& t, unsigned threads, Output& out) {
  const std::size_t pieces = t.edges.size() / 2;
  out.vertex_markers.assign(out.vertices.size(), 0);
  out.segment_markers.assign(pieces, 0);
  // The boundary's sides (those with no triangle across) and their pieces found on threads (a
  // binary search each), then marked.
  const EdgeIndex index(t.edges);
  const std::vector<std::uint32_t> sides =
      detail::indices_where(3 * t.size(), threads, [&](std::size_t s) { return t.neighbors[s] < 0; });
  auto ends = [&](std::size_t s) {
    const std::size_t first = s - s % 3;
    return std::pair{t.triangles[first + (s + 1) % 3], t.triangles[first + (s + 2) % 3]};
  };
  std::vector<std::size_t> piece(sides.size());
  detail::parallel_for(sides.size(), threads, 4096, [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) {
      const auto [a, b] = ends(sides[k]);
      piece[k] = index.find(a, b);
    }
  });
  for (std::size_t k = 0; k < sides.size(); ++k) {
    const auto [a, b] = ends(sides[k]);
    out.vertex_markers[a] = out.vertex_markers[b] = 1;
    if (piece[k] < pieces) out.segment_markers[piece[k]] = 1;
  }
  std::vector<std::int32_t> by(out.vertices.size(), -1);  // the marked segment that marks each vertex
  for (std::size_t k = 0; k < pieces; ++k) {
    const std::int32_t s = t.edge_segments[k];
    if (s < 0 || in.segment_markers.empty() || in.segment_markers[static_cast<std::size_t>(s)] == 0) continue;
    const std::int64_t marker = in.segment_markers[static_cast<std::size_t>(s)];
    out.segment_markers[k] = marker;
    for (const VertexId v : {t.edges[2 * k], t.edges[2 * k + 1]})
      if (s >= by[v]) by[v] = s, out.vertex_markers[v] = marker;
  }
  for (std::size_t v = 0; v < in.vertex_markers.size(); ++v)
    if (in.vertex_markers[v] != 0) out.vertex_markers[v] = in.vertex_markers[v];
}

// Every vertex's attributes: the input's as given, those of the points added interpolated
// linearly over the Delaunay triangulation of the input's vertices (exact on attributes linear
// in the position; Triangle interpolates in the triangle that holds a point when it is added,
// so the two differ where the attributes are not linear); the nearest input vertex's where a
// point added lies a rounding outside their hull.
void carry_attributes(const Input& in, const ConstrainedTriangulation& t, const Options& o, Output& out) {
  const std::size_t count = in.attribute_count;
  out.attribute_count = count;
  out.vertex_attributes = in.vertex_attributes;
  if (count == 0 || t.steiner.empty()) return;
  Options plain;
  plain.method = Method::Auto, plain.threads = o.threads;
  const Triangulation d = triangulate(in.vertices, plain);
  std::vector<double> added = interpolate_linear(in.vertices, d, {in.vertex_attributes, count}, t.steiner,
                                                 std::numeric_limits<double>::quiet_NaN(), o.threads);
  const std::vector<std::int32_t> near = nearest_vertex(in.vertices, d, t.steiner, o.threads);
  for (std::size_t k = 0; k < t.steiner.size(); ++k)
    if (std::isnan(added[k * count]) && near[k] >= 0)
      std::copy_n(&in.vertex_attributes[static_cast<std::size_t>(near[k]) * count], count, &added[k * count]);
  out.vertex_attributes.insert(out.vertex_attributes.end(), added.begin(), added.end());
}

// C: the exact check of the mesh (check_mesh): the segments as chains of edges, the holes
// empty, the bounds asked where refinement met them; with Y or YY a triangle may keep an angle
// below the bound (its point would fall on a segment), though none may keep an area above it.
CheckResult checked(const Input& in, const Switches& w, const ConstrainedTriangulation& t, const Output& out) {
  MeshSpec spec;
  spec.edges = t.edges;
  spec.segments = w.pslg ? std::span(in.segments) : std::span<const VertexId>{};
  spec.input_points = in.vertices.size();
  spec.holes = out.holes;
  const Quality q = w.quality_bounds();
  spec.min_angle = t.warning.empty() && q.split_boundary && q.split_segments ? q.min_angle : 0;
  spec.max_area = t.warning.empty() ? q.max_area : 0;
  return check_mesh(out.vertices, std::span(t.triangles).first(3 * t.size()), spec);
}

}  // namespace

Output triangulate(const Input& in, const Switches& w, const Options& options) {
  check_sizes(in, w);
  Options o = options;
  o.canonical_order = true;
  o.neighbors = true;
  Output out;
  ConstrainedTriangulation t = run(in, w, o, out.holes);
  out.vertices = in.vertices;
  out.vertices.insert(out.vertices.end(), t.steiner.begin(), t.steiner.end());
  out.crossings = t.crossings;
  out.warning = t.warning;
  out.duplicates = t.duplicates;
  mark(in, t, o.threads, out);
  carry_attributes(in, t, o, out);
  if (w.check) out.check = checked(in, w, t, out);
  if (w.attributes || (w.refine && !in.triangle_attributes.empty())) out.triangle_attributes = std::move(t.attributes);
  if (w.all_edges) every_edge(t, out);
  if (w.voronoi) add_dual(t, o.threads, out);
  out.triangles = std::move(t.triangles);
  if (w.second_order) add_middles(t.neighbors, t.edges, out);
  out.neighbors = std::move(t.neighbors);
  out.segments = std::move(t.edges);
  out.segment_of = std::move(t.edge_segments);
  if (w.no_markers) out.vertex_markers.clear(), out.segment_markers.clear(), out.edge_markers.clear();
  if (w.jettison) jettison(out);
  return out;
}

Output triangulate(const Input& input, std::string_view switches, const Options& options) {
  return triangulate(input, parse_switches(switches), options);
}

}  // namespace ridt::triangle
