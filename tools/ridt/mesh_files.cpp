// ridt mesh's files (mesh_files.hpp): Triangle's markers and attributes, every edge (-e), the
// unused vertices left out (-j), six-node triangles (-o2).
#include "mesh_files.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include "command.hpp"
#include "ridt/interpolate.hpp"
#include "ridt/predicates.hpp"
#include "ridt/voronoi.hpp"

namespace ridt::tool {
namespace {

// The segment edges (pairs of indices) as lists of neighbours, each with the edge's index.
class SegmentEdges {
 public:
  SegmentEdges(std::span<const VertexId> edges, std::size_t points) : start_(points + 1, 0), count_(edges.size() / 2) {
    for (const VertexId v : edges) ++start_[v + 1];
    for (std::size_t v = 1; v < start_.size(); ++v) start_[v] += start_[v - 1];
    next_.resize(edges.size());
    std::vector<std::size_t> at(start_.begin(), start_.end() - 1);
    for (std::size_t k = 0; k < edges.size(); k += 2) {
      next_[at[edges[k]]++] = {edges[k + 1], static_cast<std::uint32_t>(k / 2)};
      next_[at[edges[k + 1]]++] = {edges[k], static_cast<std::uint32_t>(k / 2)};
    }
  }
  /// The neighbours of v, each with the index of the edge to it.
  std::span<const std::pair<VertexId, std::uint32_t>> around(VertexId v) const {
    return std::span(next_).subspan(start_[v], start_[v + 1] - start_[v]);
  }
  /// The index of edge a-b, or the number of edges where it is none.
  std::size_t index(VertexId a, VertexId b) const {
    for (const auto& [w, k] : around(a))
      if (w == b) return k;
    return count_;
  }

 private:
  std::vector<std::size_t> start_;
  std::vector<std::pair<VertexId, std::uint32_t>> next_;
  std::size_t count_;
};

// The pieces of input segment a-b, marked `marker`, followed from a through the segment edges
// to points on it (exactly, or added points within a rounding of it), each piece and its ends
// marked; the walk stops where the chain does (a stretch of the segment in a hole).
void mark_pieces(std::span<const Point> all, std::size_t input, VertexId a, VertexId b, std::int64_t marker,
                 const SegmentEdges& edges, std::vector<std::int64_t>& markers, std::vector<std::int64_t>& ends) {
  const Point &pa = all[a], &pb = all[b];
  const double dx = pb.x - pa.x, dy = pb.y - pa.y, length2 = dx * dx + dy * dy;
  auto along = [&](VertexId v) { return ((all[v].x - pa.x) * dx + (all[v].y - pa.y) * dy) / length2; };
  auto on = [&](VertexId v) {
    if (v == b || orientation(pa, pb, all[v]) == 0) return true;
    const double cross = dx * (all[v].y - pa.y) - dy * (all[v].x - pa.x);
    return v >= input && std::fabs(cross) <= 0x1p-40 * length2;
  };
  for (VertexId v = a; v != b;) {
    VertexId next = v;
    for (const auto& [w, k] : edges.around(v))
      if (along(w) > along(v) && along(w) <= 1 && on(w) && (next == v || along(w) < along(next))) next = w;
    if (next == v) return;
    markers[edges.index(v, next)] = marker;
    ends[v] = ends[next] = marker;
    v = next;
  }
}

struct Markers {
  std::vector<std::int64_t> edges, points;
};

// The markers Triangle writes. A segment edge's: that of the input segment it is a piece of
// where not 0; else 1 on the boundary (an edge with no triangle across), 0 inside. A vertex's:
// the input's where not 0; else that of a marked segment edge it ends; else 1 on the boundary,
// 0 inside.
Markers markers_of(const io::Pslg& g, const ConstrainedTriangulation& t, std::span<const Point> all) {
  const SegmentEdges edges(t.edges, all.size());
  Markers m{std::vector<std::int64_t>(t.edges.size() / 2, 0), std::vector<std::int64_t>(all.size(), 0)};
  for (std::size_t s = 0; s < 3 * t.size() && s < t.neighbors.size(); ++s)
    if (t.neighbors[s] < 0) {
      const std::size_t first = s - s % 3;
      const VertexId a = t.triangles[first + (s + 1) % 3], b = t.triangles[first + (s + 2) % 3];
      m.points[a] = m.points[b] = 1;
      if (const std::size_t k = edges.index(a, b); k < m.edges.size()) m.edges[k] = 1;
    }
  std::vector<VertexId> kept(g.points.size());  // a duplicate end stands for the point kept
  for (VertexId v = 0; v < kept.size(); ++v) kept[v] = v;
  for (const Duplicate& d : t.duplicates) kept[d.dropped] = d.kept;
  for (std::size_t s = 0; s < g.segment_markers.size(); ++s)
    if (const VertexId a = kept[g.segments[2 * s]], b = kept[g.segments[2 * s + 1]];
        g.segment_markers[s] != 0 && a != b)
      mark_pieces(all, g.points.size(), a, b, g.segment_markers[s], edges, m.edges, m.points);
  for (std::size_t v = 0; v < g.point_markers.size(); ++v)
    if (g.point_markers[v] != 0) m.points[v] = g.point_markers[v];
  return m;
}

// Every vertex's attributes: the input's as given, those of the points added interpolated
// linearly over the Delaunay triangulation of the input's points (exact on attributes linear
// in the position; Triangle interpolates in the triangle that holds a point when it is added,
// so the two differ where the attributes are not linear); the nearest input point's where a
// point added lies a rounding outside their hull.
std::vector<double> vertex_attributes(const io::Pslg& g, const ConstrainedTriangulation& t, unsigned threads) {
  const std::size_t count = g.vertex_attributes;
  std::vector<double> out(g.point_attributes);
  if (t.steiner.empty()) return out;
  Options o;
  o.threads = threads;
  const Triangulation d = triangulate(g.points, o);
  std::vector<double> added = interpolate_linear(g.points, d, {g.point_attributes, count}, t.steiner,
                                                 std::numeric_limits<double>::quiet_NaN(), threads);
  const std::vector<std::int32_t> near = nearest_vertex(g.points, d, t.steiner, threads);
  for (std::size_t k = 0; k < t.steiner.size(); ++k)
    if (std::isnan(added[k * count]) && near[k] >= 0)
      std::copy_n(&g.point_attributes[static_cast<std::size_t>(near[k]) * count], count, &added[k * count]);
  out.insert(out.end(), added.begin(), added.end());
  return out;
}

// The markers of every vertex, then of the middles of the edges (-o2), by the vertices' rule: a
// marked segment edge's marker; else 1 on the boundary, 0 inside.
std::vector<std::int64_t> with_middles(const std::vector<std::int64_t>& points, const std::vector<std::int64_t>& edges,
                                       const ConstrainedTriangulation& t, const SecondOrder& s) {
  std::vector<std::int64_t> out(points);
  out.resize(points.size() + s.nodes.size(), 0);
  for (std::size_t k = 0; k < t.size(); ++k)
    for (int i = 0; i < 3; ++i)
      if (t.neighbors[3 * k + i] < 0) out[s.triangles[6 * k + 3 + i]] = 1;
  const SegmentEdges segment(t.edges, points.size());
  for (std::size_t q = 0; q < s.nodes.size(); ++q)
    if (const std::size_t e = segment.index(s.ends[2 * q], s.ends[2 * q + 1]); e < edges.size() && edges[e] != 0)
      out[points.size() + q] = edges[e];
  return out;
}

// The attributes of every vertex (`count` each, row by row), then of the middles of the edges
// (-o2): the mean of their ends', as linear interpolation along the edge gives them.
std::vector<double> with_middles(const std::vector<double>& attributes, std::size_t count, const SecondOrder& s) {
  std::vector<double> out(attributes);
  for (std::size_t q = 0; q < s.nodes.size() && count > 0; ++q)
    for (std::size_t j = 0; j < count; ++j)
      out.push_back(std::midpoint(attributes[s.ends[2 * q] * count + j], attributes[s.ends[2 * q + 1] * count + j]));
  return out;
}

// Every edge once, (a, b) with a < b, sorted, and its marker by Triangle's rule: a segment
// edge's own (`segment_markers`, one each of t.edges), else 1 on the boundary, 0 inside (-e).
void every_edge(const ConstrainedTriangulation& t, std::size_t points, std::span<const std::int64_t> segment_markers,
                std::vector<VertexId>& edges, std::vector<std::int64_t>& markers) {
  std::vector<std::pair<std::uint64_t, bool>> keyed;
  for (std::size_t k = 0; k < t.size(); ++k)
    for (int i = 0; i < 3; ++i)
      if (const std::int32_t n = t.neighbors[3 * k + i]; n < 0 || static_cast<std::size_t>(n) > k) {
        const std::uint64_t a = t.triangles[3 * k + (i + 1) % 3], b = t.triangles[3 * k + (i + 2) % 3];
        keyed.push_back({std::min(a, b) << 32 | std::max(a, b), n < 0});
      }
  std::sort(keyed.begin(), keyed.end());
  const SegmentEdges segments(t.edges, points);
  edges.clear(), markers.clear();
  for (const auto& [key, boundary] : keyed) {
    const auto a = static_cast<VertexId>(key >> 32), b = static_cast<VertexId>(key);
    edges.push_back(a), edges.push_back(b);
    const std::size_t s = segments.index(a, b);
    markers.push_back(s < segment_markers.size() && segment_markers[s] != 0 ? segment_markers[s] : boundary);
  }
}

// The mesh's files without the vertices of no element (-j): the rest numbered in order, and the
// elements, the edges and the vertices' markers and attributes with them. `kept` keeps the arrays.
struct Jettisoned {
  std::vector<Point> points;
  std::vector<VertexId> triangles, edges;
  std::vector<std::int64_t> markers;
  std::vector<double> attributes;
};

void jettison(io::MeshFiles& m, Jettisoned& kept) {
  constexpr VertexId kUnused = 0xffffffffu;
  std::vector<VertexId> id(m.points.size(), kUnused);
  for (const VertexId v : m.triangles) id[v] = 0;
  VertexId next = 0;
  for (std::size_t v = 0; v < id.size(); ++v)
    if (id[v] == 0) {
      id[v] = next++;
      kept.points.push_back(m.points[v]);
      if (!m.point_markers.empty()) kept.markers.push_back(m.point_markers[v]);
      for (std::size_t j = 0; j < m.point_attribute_count; ++j)
        kept.attributes.push_back(m.point_attributes[v * m.point_attribute_count + j]);
    }
  for (const VertexId v : m.triangles) kept.triangles.push_back(id[v]);
  for (const VertexId v : m.edges) kept.edges.push_back(id[v]);  // an edge's ends are corners
  m.points = kept.points, m.triangles = kept.triangles, m.edges = kept.edges;
  if (!m.point_markers.empty()) m.point_markers = kept.markers;
  m.point_attributes = kept.attributes;
}

// The mesh's dual, as Triangle's -v writes it: a vertex at each triangle's circumcentre (within
// the bound of ridt::voronoi), an edge across each edge of the mesh between the circumcentres of
// the triangles on its two sides, and a ray across each boundary edge, along its outward normal.
// It is the Voronoi diagram of the vertices where the mesh is Delaunay and fills their convex
// hull; else, across a segment or a hole, circumcentres need not lie in their triangles.
struct Dual {
  std::vector<Point> vertices;
  std::vector<std::int32_t> edges;
  std::vector<Point> directions;
  std::vector<double> attributes;
};

// The vertices' attributes (`count` a vertex) at each triangle's circumcentre, as Triangle gives
// them: the linear function of the triangle's three, extended beyond it where the centre lies
// outside (its weights from barycentric: exact where the centre lies on a side); NaN where the
// centre itself is not finite (a sliver's, beyond the largest double).
std::vector<double> at_centres(std::span<const Point> all, const ConstrainedTriangulation& t,
                               std::span<const Point> centres, std::span<const double> attributes, std::size_t count) {
  std::vector<double> out(centres.size() * count);
  for (std::size_t k = 0; k < centres.size() && count > 0; ++k) {
    const VertexId* v = &t.triangles[3 * k];
    if (!std::isfinite(centres[k].x) || !std::isfinite(centres[k].y)) {
      std::fill_n(&out[k * count], count, std::numeric_limits<double>::quiet_NaN());
      continue;
    }
    const std::array<double, 3> w = barycentric(all[v[0]], all[v[1]], all[v[2]], centres[k]);
    for (std::size_t j = 0; j < count; ++j)
      out[k * count + j] = w[0] * attributes[v[0] * count + j] + w[1] * attributes[v[1] * count + j] +
          w[2] * attributes[v[2] * count + j];
  }
  return out;
}

Dual dual_of(std::span<const Point> all, const ConstrainedTriangulation& t, unsigned threads) {
  Triangulation mesh;
  mesh.triangles.assign(t.triangles.begin(), t.triangles.begin() + static_cast<std::ptrdiff_t>(3 * t.size()));
  mesh.neighbors.assign(t.neighbors.begin(), t.neighbors.begin() + static_cast<std::ptrdiff_t>(3 * t.size()));
  Voronoi v = voronoi(all, mesh, threads);
  Dual d{std::move(v.vertices), {}, {}, {}};
  d.edges.reserve(2 * v.ridges.size());
  d.directions.reserve(v.ridges.size());
  for (const Ridge& r : v.ridges) {
    d.edges.push_back(r.u), d.edges.push_back(r.v);
    d.directions.push_back(ray_direction(all, r));
  }
  return d;
}

}  // namespace

void write_mesh(const MeshOutput& o, const io::Pslg& g, const ConstrainedTriangulation& t) {
  std::vector<Point> all = g.points;
  all.insert(all.end(), t.steiner.begin(), t.steiner.end());
  if (io::extension(o.path) == ".svg") return io::write_mesh_svg(o.path, all, t, t.edges);
  const unsigned threads = thread_count(o.threads);
  io::MeshFiles m;
  m.points = all;
  m.triangles = std::span(t.triangles).first(3 * t.size());
  if (o.attributes) m.attributes = t.attributes;
  m.edges = t.edges;
  const Markers markers = markers_of(g, t, all);
  m.edge_markers = markers.edges;
  m.point_markers = markers.points;
  std::vector<VertexId> edges;
  std::vector<std::int64_t> edge_markers;
  if (o.all_edges) {
    every_edge(t, all.size(), markers.edges, edges, edge_markers);
    m.edges = edges, m.edge_markers = edge_markers;
  }
  const std::vector<double> attributes =
      g.vertex_attributes > 0 ? vertex_attributes(g, t, threads) : std::vector<double>{};
  m.point_attributes = attributes;
  m.point_attribute_count = g.vertex_attributes;
  m.files = o.files;
  const auto sides = std::span(t.neighbors).first(std::min(t.neighbors.size(), 3 * t.size()));
  if (o.files.neighbors) m.neighbors = sides;
  m.first_index = o.zero_based ? 0 : g.first_index;
  m.markers = o.markers;
  Dual dual;
  if (o.files.voronoi) {
    dual = dual_of(all, t, threads);
    dual.attributes = at_centres(all, t, dual.vertices, attributes, g.vertex_attributes);
  }
  m.voronoi_vertices = dual.vertices, m.voronoi_edges = dual.edges, m.voronoi_directions = dual.directions;
  m.voronoi_attributes = dual.attributes;
  if (o.files.off) {  // each edge inside is two triangles' side, each on the boundary one's
    const auto boundary = static_cast<std::size_t>(std::count(sides.begin(), sides.end(), -1));
    m.edge_count = boundary + (3 * t.size() - boundary) / 2;
  }
  SecondOrder s;
  std::vector<std::int64_t> point_markers;
  std::vector<double> point_attributes;
  if (o.second_order) {
    s = second_order(all, t);
    point_markers = with_middles(markers.points, markers.edges, t, s);
    point_attributes = with_middles(attributes, g.vertex_attributes, s);
    all.insert(all.end(), s.nodes.begin(), s.nodes.end());
    m.points = all;
    m.triangles = s.triangles;
    m.nodes = 6;
    m.point_markers = point_markers;
    m.point_attributes = point_attributes;
  }
  Jettisoned kept;
  if (o.jettison) jettison(m, kept);
  io::write_mesh_files(o.path, m, threads);
}

}  // namespace ridt::tool
