// The constrained Delaunay triangulation and quality mesh (ridt/constrained.hpp): the Delaunay
// triangulation of the points, the segments inserted (constrained/segments.cpp), the domain
// carved (constrained/domain.cpp), then refined (constrained/refine.cpp), all on one mutable
// triangulation (constrained/cdt.hpp) in exactly scaled coordinates where the points are huge
// or tiny.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_map>

#include "constrained/cdt.hpp"
#include "constrained/domain.hpp"
#include "constrained/given_mesh.hpp"
#include "constrained/refine.hpp"
#include "constrained/segments.hpp"
#include "finish/finish.hpp"
#include "order/order.hpp"
#include "predicates/predicates.hpp"
#include "ridt/constrained.hpp"
#include "runtime/memory.hpp"

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
  if (!std::isfinite(w * w + h * h))
    throw InputError("quality meshing needs the points' box below about 1e154 across (it is " +
                     g(static_cast<long double>(e.x1) - e.x0) + " by " + g(static_cast<long double>(e.y1) - e.y0) +
                     ", and coordinates as small as " + g(e.smallest) + " keep it from being scaled exactly)");
}

// triangulate checks its own need against the memory limit (Options::memory_limit, else what
// the system can give); the steps here hold more beside its result (the points' copy, a flag an
// edge slot, a corner and a kept index a vertex, the carving's marks, the edges' lists). 24 bytes
// a point and 8 a segment cover it: the CDT of generate_coastline's 4 * 10^6 and 10^7 vertices
// peaked 10 and 8 bytes a point above triangulate's estimate. Refinement keeps within what is
// left (detail::refine). Throws MemoryError before anything large is allocated.
void check_memory(std::size_t n, std::size_t segments, const Options& plain) {
  const std::size_t limit = detail::memory_room(plain.memory_limit);
  const std::size_t needed = estimate_memory(n, plain) + 24 * n + 8 * segments;
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
  const std::size_t held = m.tris.capacity() * sizeof(VertexId) + m.nbrs.capacity() * sizeof(std::int32_t) +
      m.fixed.capacity() + m.pts.capacity() * sizeof(Point) + m.corner.capacity() * sizeof(std::uint32_t) +
      cached_memory();
  return options.memory_limit > held ? options.memory_limit - held : 1;
}

// The fixed edges, pairs (a, b) with a < b, sorted. Each is taken once (from the side where it
// runs a -> b, or the only side), counted, then collected in a pass that appends without a
// branch: a third of the slots are fixed, at random, and a branch on each mispredicted often.
// Then counted by a, and each a's few sorted.
std::vector<VertexId> fixed_edges(const detail::Cdt& m) {
  auto taken = [&m](std::size_t s, VertexId a, VertexId b) {
    return static_cast<std::size_t>(m.fixed[s] & ((a < b) | (m.nbrs[s] < 0)));
  };
  std::size_t count = 0;
  for (std::size_t s = 0; s < m.tris.size(); s += 3)
    for (int j = 0; j < 3; ++j) count += taken(s + j, m.tris[s + (j + 1) % 3], m.tris[s + (j + 2) % 3]);
  std::vector<std::uint64_t> pairs(count + 1);  // one more: the last slot's write when it is not taken
  count = 0;
  for (std::size_t s = 0; s < m.tris.size(); s += 3)
    for (int j = 0; j < 3; ++j) {
      const std::uint64_t a = m.tris[s + (j + 1) % 3], b = m.tris[s + (j + 2) % 3];
      pairs[count] = a < b ? a << 32 | b : b << 32 | a;
      count += taken(s + j, static_cast<VertexId>(a), static_cast<VertexId>(b));
    }
  std::vector<std::uint32_t> start(m.pts.size() + 1, 0);
  for (std::size_t k = 0; k < count; ++k) ++start[(pairs[k] >> 32) + 1];
  for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<VertexId> out(2 * count);
  std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
  for (std::size_t k = 0; k < count; ++k) {
    const auto a = static_cast<VertexId>(pairs[k] >> 32);
    const std::uint32_t at = next[a]++;
    out[2 * at] = a, out[2 * at + 1] = static_cast<VertexId>(pairs[k]);
  }
  std::vector<VertexId> many;
  for (VertexId a = 0; a + 1 < start.size(); ++a) {  // each a's pairs by b: mostly a few, by insertion
    const std::uint32_t first = start[a], last = start[a + 1];
    if (last - first <= 16) {
      for (std::uint32_t k = first + 1; k < last; ++k)
        for (std::uint32_t i = k; i > first && out[2 * i - 1] > out[2 * i + 1]; --i)
          std::swap(out[2 * i - 1], out[2 * i + 1]);
      continue;
    }
    many.clear();
    for (std::uint32_t k = first; k < last; ++k) many.push_back(out[2 * k + 1]);
    std::sort(many.begin(), many.end());
    for (std::uint32_t k = first; k < last; ++k) out[2 * k + 1] = many[k - first];
  }
  return out;
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

// The mesh's arrays into `out` (whose duplicates, stats and warning the Delaunay step set).
void collect(detail::Cdt& m, ConstrainedTriangulation& out, const Domain& domain, std::size_t n, int scale,
             bool reshaped) {
  out.edges = fixed_edges(m);
  out.triangles = std::move(m.tris);
  out.neighbors = std::move(m.nbrs);
  if (reshaped) out.hull.clear();
  for (std::size_t v = n; v < m.pts.size(); ++v) out.steiner.push_back(scaled(m.pts[v], -scale));
  if (!m.region.empty()) {
    out.attributes.resize(m.region.size(), 0.0);
    for (std::size_t t = 0; t < m.region.size(); ++t)
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
                       {}};
  for (const Region& g : domain.regions)
    r.region_area.push_back(g.max_area > 0 ? std::ldexp(g.max_area, 2 * scale) : 0);
  if (quality.unsuitable)  // the caller's coordinates, not the scaled ones (exactly: powers of two)
    r.unsuitable = [&quality, scale](const Point& a, const Point& b, const Point& c, double twice) {
      return quality.unsuitable(scaled(a, -scale), scaled(b, -scale), scaled(c, -scale),
                                std::ldexp(twice, -2 * scale - 1));
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
// along it) into `slots`; InputError for a segment that is no edge.
std::vector<std::int32_t> mesh_links(std::span<const Point> pts, std::span<const VertexId> triangles,
                                     std::span<const VertexId> segments, std::vector<std::uint32_t>& slots) {
  const detail::MeshEdges edges(pts, triangles);
  for (std::size_t k = 0; k < segments.size(); k += 2) {
    const VertexId a = segments[k], b = segments[k + 1];
    if (a == b) continue;
    const std::uint32_t s = edges.slot(a, b) != detail::Cdt::kNone ? edges.slot(a, b) : edges.slot(b, a);
    if (s == detail::Cdt::kNone)
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
  for (const std::uint32_t s : segment_slots) m.set_fixed(s / 3, static_cast<int>(s % 3), true);
  for (std::size_t s = 0; s < m.nbrs.size(); ++s)
    if (m.nbrs[s] < 0) m.fixed[s] = 1;
  Domain domain;
  domain.convex_hull = false;
  if (!max_areas.empty() || !attributes.empty()) {
    m.region.resize(m.size());
    for (std::size_t t = 0; t < m.size(); ++t) {
      m.region[t] = static_cast<std::int32_t>(t);
      domain.regions.push_back({{}, attributes.empty() ? 0.0 : attributes[t], max_areas.empty() ? 0.0 : max_areas[t]});
    }
  }
  std::vector<std::uint32_t> all(m.tris.size());
  for (std::uint32_t s = 0; s < all.size(); ++s) all[s] = s;
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
  static_cast<Triangulation&>(out) = triangulate(points, plain);
  if (out.size() == 0) return out;
  std::vector<VertexId> kept(points.size());
  for (VertexId v = 0; v < kept.size(); ++v) kept[v] = v;
  for (const Duplicate& d : out.duplicates) kept[d.dropped] = d.kept;
  // The predicates on an exactly scaled copy where the coordinates are huge or tiny.
  const int scale = detail::exact_scale_exponent(extent);
  std::vector<Point> pts(points.begin(), points.end());
  if (scale != 0)
    for (Point& p : pts) p = scaled(p, scale);
  detail::Cdt m(std::move(pts), out);
  detail::insert_segments(m, segments, kept);
  out.crossings = m.pts.size() - points.size();
  std::vector<Point> holes = domain.holes;
  std::vector<Region> regions = domain.regions;
  for (Point& h : holes) h = scaled(h, scale);
  for (Region& r : regions) r.seed = scaled(r.seed, scale);
  const bool carved = detail::carve(m, holes, regions, domain.convex_hull, refined);
  if (refined) refine(m, out, options, quality, domain, static_cast<VertexId>(points.size() + out.crossings), scale);
  collect(m, out, domain, points.size(), scale, carved || refined);
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
  out.neighbors = mesh_links(pts, out.triangles, segments, segment_slots);
  out.stats.points = out.stats.distinct = points.size();
  detail::Cdt m(std::move(pts), out);
  detail::check_fans(m);
  Options layer = options;  // the boundary's triangulation within what the mesh leaves of the limit
  layer.memory_limit = room_left(options, m);
  detail::check_one_layer(points, m.tris, m.nbrs, layer);
  const detail::GivenMesh given(m.pts, m.tris, m.nbrs);
  const Domain domain = mark_mesh(m, segment_slots, max_areas, attributes);
  if (refined) refine(m, out, options, quality, domain, static_cast<VertexId>(points.size()), scale, &given);
  if (!m.region.empty())
    for (std::uint32_t t = 0; t < m.size(); ++t) m.region[t] = given.region_of(m, t);
  collect(m, out, domain, points.size(), scale, true);
  if (attributes.empty()) out.attributes.clear();
  if (options.canonical_order) canonical(out, options);
  if (!options.neighbors) out.neighbors = {};
  return out;
}

}  // namespace ridt
