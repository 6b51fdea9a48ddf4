// The constrained Delaunay triangulation and quality mesh (ridt/constrained.hpp): the Delaunay
// triangulation of the points, the segments inserted (constrained/segments.cpp), the domain
// carved (constrained/domain.cpp), then refined (constrained/refine.cpp), all on one mutable
// triangulation (constrained/cdt.hpp) in exactly scaled coordinates where the points are huge
// or tiny.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <unordered_map>

#include "constrained/cdt.hpp"
#include "constrained/domain.hpp"
#include "constrained/given_mesh.hpp"
#include "constrained/refine.hpp"
#include "constrained/segments.hpp"
#include "order/order.hpp"
#include "output/output.hpp"
#include "predicates/predicates.hpp"
#include "ridt/constrained.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"
#include "tds/delaunay.hpp"

namespace ridt {
namespace {

void check_input(std::span<const Point> points, std::span<const VertexId> segments, const Domain& domain,
                 const Quality& quality) {
  auto finite = [](const Point& p) { return std::isfinite(p.x) && std::isfinite(p.y); };
  for (const Point& h : domain.holes)
    if (!finite(h)) throw InputError("a hole's coordinate is not finite");
  for (const Region& r : domain.regions)
    if (!finite(r.seed) || !std::isfinite(r.attribute) || !std::isfinite(r.max_area))
      throw InputError("a region's seed, attribute or area bound is not finite");
  if (!(quality.min_angle >= 0 && quality.min_angle <= 34))
    throw InputError("the minimum angle must lie in [0, 34] degrees (got " + std::to_string(quality.min_angle) +
                     "); above about 34 degrees refinement need not end");
  if (!(quality.max_area >= 0) || !std::isfinite(quality.max_area))
    throw InputError("the maximum area must be finite and >= 0 (got " + std::to_string(quality.max_area) + ")");
  if (quality.conforming && !quality.split_segments)
    throw InputError(
        "a conforming Delaunay mesh splits segments until every edge is Delaunay: it cannot keep them whole "
        "(conforming with split_segments off; Triangle's -D with -YY)");
  if (segments.size() % 2 != 0)
    throw InputError("a segment list needs an even size (got " + std::to_string(segments.size()) + ")");
  if (segments.size() / 2 > 0x7fffffffu) throw InputError("ridt takes fewer than 2^31 segments");
  for (std::size_t k = 0; k < segments.size(); ++k)
    if (segments[k] >= points.size())
      throw InputError("segment " + std::to_string(k / 2) + " refers to point " + std::to_string(segments[k]) + " of " +
                       std::to_string(points.size()));
}

Point scaled(const Point& p, int scale) { return {std::ldexp(p.x, scale), std::ldexp(p.y, scale)}; }

// Refinement computes lengths, circumcentres and angles in doubles, on the points scaled by a
// power of two where that is exact: where the box's squared diagonal overflows even so (points
// near 10^154 and beyond beside others too small to be scaled with them), it cannot.
void check_refinable(const detail::Extent& e) {
  const int k = detail::exact_scale_exponent(e) + 1;
  const double w = std::ldexp(e.x1 / 2 - e.x0 / 2, k), h = std::ldexp(e.y1 / 2 - e.y0 / 2, k);
  auto g = [](long double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3Lg", v);
    return std::string(text);
  };
  // The angle tests square a triangle's doubled area and multiply squared lengths: products of
  // degree 4 in the coordinates, finite while the box's half diagonal is below 2^255.
  const double d2 = w * w + h * h;
  if (!std::isfinite(d2 * d2))
    throw InputError("quality meshing needs the points' box below about 1e76 across (it is " +
                     g(static_cast<long double>(e.x1) - e.x0) + " by " + g(static_cast<long double>(e.y1) - e.y0) +
                     ", and coordinates as small as " + g(e.smallest) + " keep it from being scaled exactly)");
}

// triangulate checks its own need against the memory limit (Options::memory_limit, else what
// the system can give); the steps here hold more beside its result (the points' copy, a
// constraint of 4 bytes an edge slot, a corner and a kept index a vertex, the carving's marks,
// the edges' lists). 44 bytes a point and 8 a segment cover it. Refinement keeps within what is
// left (detail::refine). Throws MemoryError before anything large is allocated.
void check_memory(std::size_t n, std::size_t segments, const Options& plain) {
  const std::size_t limit = detail::memory_room(plain.memory_limit);
  const std::size_t needed = estimate_memory(n, plain) + 44 * n + 8 * segments;
  if (limit == 0 || needed <= limit) return;
  throw MemoryError("the constrained triangulation of " + std::to_string(n) + " points and " +
                        std::to_string(segments) + " segments needs about " + detail::gigabytes(needed) + "; " +
                        detail::gigabytes(limit) + " is available",
                    needed, limit);
}

// What refinement may take under Options::memory_limit: the limit less what is held now (the
// mutable triangulation's arrays, and the blocks the triangulation's work space left in the
// memory cache); 0 (what the process has left) without a limit.
std::size_t room_left(const Options& options, const detail::Cdt& m) {
  if (options.memory_limit == 0) return 0;
  const std::size_t held =
      m.tds.bytes() + m.pts.capacity() * sizeof(Point) + m.corner.capacity() * sizeof(std::uint32_t) + cached_memory();
  return options.memory_limit > held ? options.memory_limit - held : 1;
}

// The fixed edges of the first `size` triangles of m (whose neighbours are ids by now:
// to_output), pairs (a, b) with a < b, sorted, into out.edges, and each one's input segment
// into out.edge_segments, on up to `threads` threads. Each is taken once (from the side where it
// runs a -> b, or the only side): found in the order of the slots, placed by a (a counting
// sort, stable), then each a's few sorted by b.
void fixed_edges(const detail::Cdt& m, std::size_t size, ConstrainedTriangulation& out, unsigned threads) {
  const VertexId* v = m.tds.vertex_array().data();
  const std::int32_t* neighbour = m.tds.link_array().data();
  const detail::Constraint* constraint = m.tds.constraint_array().data();
  auto ends = [&](std::size_t s) {
    const std::size_t t = s - s % 3;
    const auto j = static_cast<int>(s % 3);
    return std::pair{v[t + detail::next3(j)], v[t + detail::prev3(j)]};
  };
  const std::vector<std::uint32_t> slot = detail::indices_where(3 * size, threads, [&](std::size_t s) {
    const auto [a, b] = ends(s);
    return constraint[s] != detail::kFree && (a < b || neighbour[s] < 0);
  });
  const std::size_t count = slot.size();
  std::vector<std::uint32_t> place(count);  // each edge's smaller end, then its place
  detail::parallel_for(count, threads, 1 << 16, [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) {
      const auto [a, b] = ends(slot[k]);
      place[k] = std::min(a, b);
    }
  });
  detail::places_by_key(place.data(), count, m.pts.size(), threads);
  std::vector<VertexId>& edges = out.edges;
  std::vector<std::int32_t>& segment = out.edge_segments;
  edges.resize(2 * count), segment.resize(count);
  detail::parallel_for(count, threads, 1 << 16, [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) {
      const auto [a, b] = ends(slot[k]);
      const detail::Constraint c = constraint[slot[k]];
      edges[2 * std::size_t{place[k]}] = std::min(a, b), edges[2 * std::size_t{place[k]} + 1] = std::max(a, b);
      segment[place[k]] = c < detail::kUnnamed ? static_cast<std::int32_t>(c) : -1;
    }
  });
  // Each run of one a sorted by b (mostly a few, by insertion), the runs that begin in a part
  // sorted by that part.
  auto first_of_run = [&](std::size_t k) { return k == 0 || edges[2 * k] != edges[2 * k - 2]; };
  detail::parallel_for(count, threads, 1 << 16, [&](std::size_t from, std::size_t to) {
    std::vector<std::pair<VertexId, std::int32_t>> many;
    std::size_t first = from;
    while (first < to && !first_of_run(first)) ++first;
    while (first < to) {
      std::size_t last = first + 1;
      while (last < count && !first_of_run(last)) ++last;
      if (last - first <= 16) {
        for (std::size_t k = first + 1; k < last; ++k)
          for (std::size_t i = k; i > first && edges[2 * i - 1] > edges[2 * i + 1]; --i)
            std::swap(edges[2 * i - 1], edges[2 * i + 1]), std::swap(segment[i - 1], segment[i]);
      } else {
        many.clear();
        for (std::size_t k = first; k < last; ++k) many.push_back({edges[2 * k + 1], segment[k]});
        std::sort(many.begin(), many.end());
        for (std::size_t k = first; k < last; ++k)
          edges[2 * k + 1] = many[k - first].first, segment[k] = many[k - first].second;
      }
      first = last;
    }
  });
}

// Triangles put in canonical order, their attributes following them.
void canonical(ConstrainedTriangulation& out, const Options& options) {
  auto key = [&](std::size_t t) {
    VertexId v[3] = {out.triangles[3 * t], out.triangles[3 * t + 1], out.triangles[3 * t + 2]};
    std::rotate(v, std::min_element(v, v + 3), v + 3);
    return std::pair{(std::uint64_t{v[0]} << 32) | v[1], v[2]};
  };
  std::unordered_map<std::uint64_t, std::vector<std::pair<VertexId, double>>> attribute;
  for (std::size_t t = 0; t < out.attributes.size(); ++t)
    attribute[key(t).first].push_back({key(t).second, out.attributes[t]});
  detail::canonicalize(out, options.threads, true, options.on_sorted);
  for (std::size_t t = 0; t < out.attributes.size(); ++t)
    for (const auto& [third, value] : attribute.at(key(t).first))
      if (third == key(t).second) out.attributes[t] = value;
}

// m's triangles but those `gone` marks (none where it is empty) renumbered in their order, in
// place, their links made neighbour ids (-1 across the boundary, or to a triangle gone), their
// constraints and regions moved with them; returns how many there are.
std::size_t to_output(detail::Cdt& m, const std::vector<std::uint8_t>& gone) {
  const std::size_t nt = m.size();
  VertexId* v = m.tds.vertex_array().data();
  detail::Link* link = m.tds.link_array().data();  // becomes the neighbours
  detail::Constraint* constraint = m.tds.constraint_array().data();
  if (gone.empty()) {  // every triangle kept where it is: the links alone become neighbours
    for (std::size_t s = 0; s < 3 * nt; ++s)
      link[s] = link[s] == detail::kNoLink ? -1 : static_cast<std::int32_t>(detail::triangle_of(link[s]));
    return nt;
  }
  std::vector<TriangleId> id(nt);
  TriangleId kept = 0;
  for (std::size_t t = 0; t < nt; ++t) id[t] = gone[t] ? detail::kNoTriangle : kept++;
  std::size_t to = 0;
  for (std::size_t t = 0; t < nt; ++t) {
    if (gone[t]) continue;
    for (std::size_t j = 0; j < 3; ++j) {
      const detail::Link l = link[3 * t + j];
      const TriangleId u = l == detail::kNoLink ? detail::kNoTriangle : detail::triangle_of(l);
      const TriangleId n = u == detail::kNoTriangle ? u : id[u];
      v[3 * to + j] = v[3 * t + j], constraint[3 * to + j] = constraint[3 * t + j];
      link[3 * to + j] = n == detail::kNoTriangle ? -1 : static_cast<std::int32_t>(n);
    }
    if (!m.region.empty()) m.region[to] = m.region[t];
    ++to;
  }
  return to;
}

// The constrained triangulation's arrays into `out` (whose duplicates, stats and warning the
// Delaunay step set), but the triangles `gone` marks.
void collect(detail::Cdt& m, ConstrainedTriangulation& out, const Domain& domain, std::size_t n, int scale,
             unsigned threads, bool reshaped, const std::vector<std::uint8_t>& gone = {}) {
  const std::size_t size = to_output(m, gone);
  fixed_edges(m, size, out, threads);
  out.neighbors = std::move(m.tds.link_array());
  out.neighbors.resize(3 * size);
  out.triangles = std::move(m.tds.vertex_array());
  out.triangles.resize(3 * size);
  if (reshaped) out.hull.clear();
  out.steiner.reserve(out.steiner.size() + (m.pts.size() - n));
  if (scale == 0)
    out.steiner.insert(out.steiner.end(), m.pts.begin() + static_cast<std::ptrdiff_t>(n), m.pts.end());
  else
    for (std::size_t v = n; v < m.pts.size(); ++v) out.steiner.push_back(scaled(m.pts[v], -scale));
  if (!m.region.empty()) {
    out.attributes.resize(size, 0.0);
    for (std::size_t t = 0; t < size; ++t)
      if (m.region[t] >= 0) out.attributes[t] = domain.regions[static_cast<std::size_t>(m.region[t])].attribute;
  }
}

// Refines m as `quality` and the domain's regions ask, from the triangulation made: vertices
// below `corners` are the input's and the crossings.
void refine(detail::Cdt& m, ConstrainedTriangulation& out, const Options& options, const Quality& quality,
            const Domain& domain, VertexId corners, int scale, const detail::GivenMesh* given = nullptr) {
  const auto first = static_cast<VertexId>(m.pts.size());
  const std::vector<VertexId> pinched = detail::split_pinches(m);  // walks round a vertex see all
  detail::Refinement r{quality.min_angle,
                       std::ldexp(quality.max_area, 2 * scale),
                       {},
                       quality.split_boundary,
                       quality.split_segments,
                       quality.conforming,
                       quality.max_steiner,
                       static_cast<VertexId>(corners + pinched.size()),
                       room_left(options, m),
                       given,
                       {},
                       {}};
  r.threads = options.threads;
  for (const Region& g : domain.regions)
    r.region_area.push_back(g.max_area > 0 ? std::ldexp(g.max_area, 2 * scale) : 0);
  if (quality.unsuitable)  // the caller's coordinates, not the scaled ones (exactly: powers of two)
    r.unsuitable = [&quality, scale](const Point& a, const Point& b, const Point& c, double twice) {
      return quality.unsuitable(scaled(a, -scale), scaled(b, -scale), scaled(c, -scale),
                                std::ldexp(twice, -2 * scale - 1));
    };
  if (quality.size)
    r.sizes = [&quality, scale](std::span<const Point> at, std::span<double> out) {
      std::vector<Point> p(at.size());
      for (std::size_t k = 0; k < at.size(); ++k) p[k] = scaled(at[k], -scale);
      quality.size.sizes(p, out);
      for (double& h : out) h = std::ldexp(h, scale);
    };
  if (std::string w = detail::refine(m, r); !w.empty()) out.warning = w;
  detail::merge_pinches(m, first, pinched);
}

void check_mesh_input(std::span<const Point> points, std::span<const VertexId> triangles,
                      std::span<const double> max_areas, std::span<const double> attributes) {
  if (triangles.size() % 3 != 0)
    throw InputError("a triangle list needs a size that is a multiple of 3 (got " + std::to_string(triangles.size()) +
                     ")");
  if (triangles.empty()) throw InputError("a mesh to refine needs at least one triangle");
  for (std::size_t k = 0; k < triangles.size(); ++k)
    if (triangles[k] >= points.size())
      throw InputError("triangle " + std::to_string(k / 3) + " refers to point " + std::to_string(triangles[k]) +
                       " of " + std::to_string(points.size()));
  const std::size_t count = triangles.size() / 3;
  for (const auto& [values, what] : {std::pair{max_areas, "area bound"}, std::pair{attributes, "attribute"}}) {
    if (!values.empty() && values.size() != count)
      throw InputError(std::string("a mesh of ") + std::to_string(count) + " triangles needs as many of each " + what +
                       " (got " + std::to_string(values.size()) + ")");
    for (std::size_t t = 0; t < values.size(); ++t)
      if (!std::isfinite(values[t]))
        throw InputError(std::string("triangle ") + std::to_string(t) + "'s " + what + " is not finite");
  }
}

// A given mesh's neighbours (checked: mesh_edges), and each segment's edge slot (either way
// along it; kNoTriangle for one whose ends coincide) into `slots`; InputError for a segment
// that is no edge.
std::vector<std::int32_t> mesh_links(std::span<const Point> pts, std::span<const VertexId> triangles,
                                     std::span<const VertexId> segments, std::vector<std::uint32_t>& slots) {
  const detail::MeshEdges edges(pts, triangles);
  for (std::size_t k = 0; k < segments.size(); k += 2) {
    const VertexId a = segments[k], b = segments[k + 1];
    if (a == b) {
      slots.push_back(detail::kNoTriangle);
      continue;
    }
    const std::uint32_t s = edges.slot(a, b) != detail::kNoTriangle ? edges.slot(a, b) : edges.slot(b, a);
    if (s == detail::kNoTriangle)
      throw InputError("segment " + std::to_string(k / 2) + " (" + std::to_string(a) + ", " + std::to_string(b) +
                       ") is not an edge of the mesh");
    slots.push_back(s);
  }
  return edges.neighbours();
}

// A given mesh's domain: its segments (their slots) and its boundary fixed, the mesh made
// constrained Delaunay by Lawson's flips (refinement needs it), and, with bounds or attributes, a
// region a given triangle (m.region numbers them, each triangle's found again by its centroid).
Domain mark_mesh(detail::Cdt& m, const std::vector<std::uint32_t>& segment_slots, std::span<const double> max_areas,
                 std::span<const double> attributes) {
  for (std::size_t k = 0; k < segment_slots.size(); ++k)
    if (const std::uint32_t s = segment_slots[k]; s != detail::kNoTriangle)
      m.constrain(static_cast<detail::Link>(s), static_cast<detail::Constraint>(k));
  for (detail::Link s = 0; s < static_cast<detail::Link>(3 * m.size()); ++s)
    if (m.boundary(s) && !m.fixed(s)) m.constrain(s, detail::kUnnamed);
  Domain domain;
  domain.convex_hull = false;
  if (!max_areas.empty() || !attributes.empty()) {
    m.region.resize(m.size());
    for (std::size_t t = 0; t < m.size(); ++t) {
      m.region[t] = static_cast<std::int32_t>(t);
      domain.regions.push_back({{}, attributes.empty() ? 0.0 : attributes[t], max_areas.empty() ? 0.0 : max_areas[t]});
    }
  }
  std::vector<detail::Link> all(3 * m.size());
  for (std::size_t s = 0; s < all.size(); ++s) all[s] = static_cast<detail::Link>(s);
  m.restore(std::move(all));
  return domain;
}

}  // namespace

ConstrainedTriangulation triangulate_constrained(std::span<const Point> points, std::span<const VertexId> segments,
                                                 const Options& options, const Domain& domain, const Quality& quality) {
  check_input(points, segments, domain, quality);
  const bool refined = quality.enabled() ||
      std::any_of(domain.regions.begin(), domain.regions.end(), [](const Region& g) { return g.max_area > 0; });
  const detail::Extent extent = detail::extent_of(points);
  if (refined) check_refinable(extent);
  // Refinement's points depend on the order it meets the triangles in: from the canonical
  // order, the same mesh whatever method and threads made the Delaunay triangulation. The
  // constrained triangulation alone is unique whatever the order.
  // The walks and flips need the neighbours, and the Delaunay triangles are not the result: the
  // caller's on_sorted sees the constrained ones (canonical), its neighbours choice is kept at
  // the end.
  Options plain = options;
  plain.canonical_order = refined;
  plain.neighbors = true;
  plain.on_sorted = {};
  check_memory(points.size(), segments.size() / 2, plain);
  ConstrainedTriangulation out;
  bool linked = false;
  static_cast<Triangulation&>(out) = detail::triangulate_linked(points, plain, linked);
  if (out.size() == 0) return out;
  std::vector<VertexId> kept(points.size());
  for (VertexId v = 0; v < kept.size(); ++v) kept[v] = v;
  for (const Duplicate& d : out.duplicates) kept[d.dropped] = d.kept;
  // The predicates on an exactly scaled copy where the coordinates are huge or tiny.
  const int scale = detail::exact_scale_exponent(extent);
  std::vector<Point> pts(points.begin(), points.end());
  if (scale != 0)
    for (Point& p : pts) p = scaled(p, scale);
  detail::Cdt m(std::move(pts), out, linked, options.threads);
  detail::insert_segments(m, segments, kept);
  out.crossings = m.pts.size() - points.size();
  std::vector<Point> holes = domain.holes;
  std::vector<Region> regions = domain.regions;
  for (Point& h : holes) h = scaled(h, scale);
  for (Region& r : regions) r.seed = scaled(r.seed, scale);
  const std::vector<std::uint8_t> gone = detail::carve(m, holes, regions, domain.convex_hull, refined);
  const bool carved = refined || !gone.empty();
  if (refined) refine(m, out, options, quality, domain, static_cast<VertexId>(points.size() + out.crossings), scale);
  collect(m, out, domain, points.size(), scale, options.threads, carved, gone);
  if (options.canonical_order) canonical(out, options);
  if (!options.neighbors) out.neighbors = {};
  return out;
}

ConstrainedTriangulation refine_mesh(std::span<const Point> points, std::span<const VertexId> triangles,
                                     std::span<const VertexId> segments, const Quality& quality,
                                     std::span<const double> max_areas, std::span<const double> attributes,
                                     const Options& options) {
  check_input(points, segments, {}, quality);
  check_mesh_input(points, triangles, max_areas, attributes);
  const detail::Extent extent = detail::checked_extent(points, 1);
  const bool refined =
      quality.enabled() || std::any_of(max_areas.begin(), max_areas.end(), [](double a) { return a > 0; });
  if (refined) check_refinable(extent);
  check_memory(points.size(), segments.size() / 2, options);
  const int scale = detail::exact_scale_exponent(extent);
  std::vector<Point> pts(points.begin(), points.end());
  if (scale != 0)
    for (Point& p : pts) p = scaled(p, scale);
  ConstrainedTriangulation out;
  out.triangles.assign(triangles.begin(), triangles.end());
  std::vector<std::uint32_t> segment_slots;
  const std::vector<std::int32_t> neighbours = mesh_links(pts, triangles, segments, segment_slots);
  out.neighbors = neighbours;
  out.stats.points = out.stats.distinct = points.size();
  detail::Cdt m(std::move(pts), out, false, options.threads);
  detail::check_fans(m);
  Options layer = options;  // the boundary's triangulation within what the mesh leaves of the limit
  layer.memory_limit = room_left(options, m);
  detail::check_one_layer(points, triangles, neighbours, layer);
  const detail::GivenMesh given(m.pts, m.tds);
  const Domain domain = mark_mesh(m, segment_slots, max_areas, attributes);
  if (refined) refine(m, out, options, quality, domain, static_cast<VertexId>(points.size()), scale, &given);
  if (!m.region.empty())
    for (TriangleId t = 0; t < m.size(); ++t) m.region[t] = given.region_of(m, t);
  collect(m, out, domain, points.size(), scale, options.threads, true);
  if (attributes.empty()) out.attributes.clear();
  if (options.canonical_order) canonical(out, options);
  if (!options.neighbors) out.neighbors = {};
  return out;
}

}  // namespace ridt
