// A triangulation that takes more points (ridt/incremental.hpp).
//
// It keeps the whole triangulation the walking kernel builds before its finish, in the one
// mutable triangulation (tds/delaunay.hpp): the points' triangles and, around them, those of
// the three bounding vertices at infinity (predicates/symbolic.hpp), so that a new point
// anywhere, inside the hull or outside it, lies in some triangle. Each insertion is the
// kernel's own: a walk there, the cavity of the triangles whose circle holds the point (exact,
// never a tie: the symbolic perturbation), fanned from the point (Bowyer-Watson). So the
// triangulation is the one a fresh build makes, and the same extraction gives the same
// triangles.
//
// It starts from a triangulation already made: its triangles, and the bounding vertices'
// triangles, which depend on the hull's vertices alone (each such triangle's circle is a
// half-plane beyond a hull edge, or a quadrant beyond an extreme point), found by inserting
// just the hull's vertices into an empty one.
#include "ridt/incremental.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>

#include "order/order.hpp"
#include "output/output.hpp"
#include "predicates/symbolic.hpp"
#include "tds/delaunay.hpp"

namespace ridt {

using detail::kNoTriangle;
using detail::kNoVertex;
using detail::Link;

struct IncrementalTriangulation::State {
  std::vector<Point> pts;  // the n points, then the three bounding vertices' NaN points
  std::uint32_t n = 0;
  std::unique_ptr<detail::DelaunayTds> tds;
  std::vector<TriangleId> free;  // slots no triangle holds
  TriangleId last = 0;  // where the next walk starts
  detail::CavityScratch scratch;
  std::vector<Duplicate> duplicates;
  Options options;

  State(std::span<const Point> points, const Options& o) : options(o) {
    n = static_cast<std::uint32_t>(points.size());
    pts.assign(points.begin(), points.end());
    pts.insert(pts.end(), 3, detail::Vertices::kBoundingNaN);
  }

  detail::Vertices vertices() const { return detail::Vertices(pts.data(), n, true); }
  bool finite(TriangleId t) const { return tds->vertex(t, 0) < n && tds->vertex(t, 1) < n && tds->vertex(t, 2) < n; }
  bool alive(TriangleId t) const { return tds->live(t); }

  // The bounding triangle alone.
  void root() {
    tds = std::make_unique<detail::DelaunayTds>(vertices());
    free.clear();
    last = 0;
  }

  // Inserts point p; returns the vertex equal to it (p is then left out), else kNoVertex.
  VertexId insert(VertexId p) {
    while (free.size() < 2) free.push_back(tds->grow(1));
    detail::SlotPool pool;
    pool.list = free.data();
    pool.listed = free.size();
    const VertexId hit = tds->insert(p, last, scratch, pool);
    free.resize(pool.listed);
    return hit;
  }

  // The bounding vertices' triangles around triangulation t of the points: those of a
  // triangulation of the hull's vertices alone, joined to t's triangles along the hull.
  void around(const Triangulation& t) {
    State outer(std::span<const Point>(pts.data(), n), options);
    outer.root();
    for (const VertexId h : t.hull) outer.insert(h);
    tds = std::make_unique<detail::DelaunayTds>(vertices(), detail::Tds::from_neighbours(t.triangles, t.neighbors));
    std::unordered_map<std::uint64_t, Link> hull_side;  // (a, b) -> t's edge that runs a -> b
    auto key = [](VertexId a, VertexId b) { return (std::uint64_t{a} << 32) | b; };
    for (TriangleId k = 0; k < tds->slots(); ++k)
      for (int i = 0; i < 3; ++i)
        if (tds->link(k, i) == detail::kNoLink)
          hull_side[key(tds->vertex(k, detail::next3(i)), tds->vertex(k, detail::prev3(i)))] = detail::link_to(k, i);
    const detail::DelaunayTds& o = *outer.tds;
    std::vector<TriangleId> moved(o.slots(), kNoTriangle);
    for (TriangleId u = 0; u < o.slots(); ++u)
      if (outer.alive(u) && !outer.finite(u)) moved[u] = tds->grow(1);
    for (TriangleId u = 0; u < o.slots(); ++u) {
      if (moved[u] == kNoTriangle) continue;
      for (int j = 0; j < 3; ++j) {
        tds->set_vertex(moved[u], j, o.vertex(u, j));
        const Link l = o.link(u, j);
        if (l == detail::kNoLink) {
          tds->set_link(detail::link_to(moved[u], j), detail::kNoLink);
        } else if (const TriangleId w = detail::triangle_of(l); moved[w] != kNoTriangle) {
          tds->set_link(detail::link_to(moved[u], j), detail::link_to(moved[w], detail::edge_of(l)));
        } else {  // across a hull side from outside: t's triangle on it
          tds->glue(detail::link_to(moved[u], j),
                    hull_side.at(key(o.vertex(u, detail::prev3(j)), o.vertex(u, detail::next3(j)))));
        }
      }
    }
    last = 0;
  }

  // The bounding vertices are numbered after the points: n grows by `more`, and the points
  // move.
  void renumber_bounding(std::uint32_t more) {
    for (VertexId& x : tds->vertex_array())
      if (x != kNoVertex && x >= n) x += more;
    n += more;
    tds->set_vertices(vertices());
  }

  Triangulation extract(unsigned threads) const {
    Triangulation out;
    std::vector<std::int32_t> id(tds->slots(), -1);
    std::int32_t count = 0;
    for (TriangleId t = 0; t < tds->slots(); ++t)
      if (alive(t) && finite(t)) id[t] = count++;
    out.triangles.reserve(3 * std::size_t(count));
    out.neighbors.reserve(3 * std::size_t(count));
    std::vector<std::pair<VertexId, VertexId>> hull_edges;
    for (TriangleId t = 0; t < tds->slots(); ++t) {
      if (id[t] < 0) continue;
      for (int i = 0; i < 3; ++i) {
        out.triangles.push_back(tds->vertex(t, i));
        const TriangleId u = tds->neighbour(t, i);
        const std::int32_t nb = u == kNoTriangle ? -1 : id[u];
        out.neighbors.push_back(nb);
        if (nb < 0) hull_edges.emplace_back(tds->vertex(t, detail::next3(i)), tds->vertex(t, detail::prev3(i)));
      }
    }
    out.duplicates = duplicates;
    const std::size_t edges = hull_edges.size();
    out.hull = detail::trace_hull(hull_edges);
    detail::set_warnings(out, n, static_cast<std::uint32_t>(count), edges, options,
                         [&](std::vector<Point>& p) { std::copy_n(pts.begin(), n, p.begin()); });
    out.stats.threads = 1;
    out.stats.locate = Locate::Walk;
    detail::apply_output_options(out, options, threads);
    return out;
  }
};

namespace {

void check_finite(std::span<const Point> points, std::size_t first) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
      throw InputError("point " + std::to_string(first + i) +
                       " is not finite: every coordinate must be a finite number");
}

}  // namespace

IncrementalTriangulation::IncrementalTriangulation(std::span<const Point> points, const Options& options)
    : IncrementalTriangulation(points, triangulate(points, options), options) {}

IncrementalTriangulation::IncrementalTriangulation(std::span<const Point> points, Triangulation t,
                                                   const Options& options)
    : state_(std::make_unique<State>(points, options)) {
  if (options.experiment.bounding != Bounding::Symbolic)
    throw InputError("an incremental triangulation needs the symbolic bounding vertices");
  check_finite(points, 0);
  State& m = *state_;
  m.duplicates = t.duplicates;
  if (t.size() > 0) {
    m.around(t);
  } else {
    // No triangle yet (fewer than three distinct points, or all collinear): the triangulation
    // of the distinct points, inserted one by one.
    m.root();
    std::vector<std::uint8_t> dropped(points.size(), 0);
    for (const Duplicate& d : t.duplicates) dropped[d.dropped] = 1;
    for (const std::uint32_t p : detail::hilbert_order(points.data(), static_cast<std::uint32_t>(points.size())))
      if (!dropped[p]) m.insert(p);
  }
  result_ = std::move(t);  // the triangulation of these points, as triangulate() gave it
}

IncrementalTriangulation::~IncrementalTriangulation() = default;
IncrementalTriangulation::IncrementalTriangulation(IncrementalTriangulation&&) noexcept = default;
IncrementalTriangulation& IncrementalTriangulation::operator=(IncrementalTriangulation&&) noexcept = default;

std::span<const Point> IncrementalTriangulation::points() const { return {state_->pts.data(), state_->n}; }

void IncrementalTriangulation::add(std::span<const Point> more) {
  State& m = *state_;
  check_finite(more, m.n);
  if (std::uint64_t{m.n} + more.size() >= (std::uint64_t{1} << 31) - 3)
    throw InputError("ridt takes fewer than 2^31 points");
  if (more.empty()) return;
  const auto count = static_cast<std::uint32_t>(more.size());
  const std::uint32_t first = m.n;
  m.pts.resize(m.pts.size() - 3);
  m.pts.insert(m.pts.end(), more.begin(), more.end());
  m.pts.insert(m.pts.end(), 3, detail::Vertices::kBoundingNaN);
  m.renumber_bounding(count);
  // Equal new points: the smallest index stands for the others (and, if it meets an old
  // point, that one for all of them).
  std::vector<std::uint32_t> by_point(count);
  for (std::uint32_t k = 0; k < count; ++k) by_point[k] = first + k;
  std::sort(by_point.begin(), by_point.end(), [&](std::uint32_t a, std::uint32_t b) {
    return detail::lex_less(m.pts[a], m.pts[b]) || (m.pts[a] == m.pts[b] && a < b);
  });
  std::vector<VertexId> stands(count, kNoVertex);  // for a new point left out: the new point it equals
  for (std::uint32_t k = 1; k < count; ++k)
    if (m.pts[by_point[k]] == m.pts[by_point[k - 1]])
      stands[by_point[k] - first] =
          stands[by_point[k - 1] - first] == kNoVertex ? by_point[k - 1] : stands[by_point[k - 1] - first];
  std::vector<VertexId> old(count, kNoVertex);  // for a new point equal to an old vertex: that vertex
  for (const std::uint32_t k : detail::hilbert_order(more.data(), count))
    if (stands[k] == kNoVertex) old[k] = m.insert(first + k);
  for (std::uint32_t k = 0; k < count; ++k) {
    if (old[k] != kNoVertex) m.duplicates.push_back({first + k, old[k]});
    if (stands[k] != kNoVertex) {
      const VertexId kept = old[stands[k] - first] != kNoVertex ? old[stands[k] - first] : stands[k];
      m.duplicates.push_back({first + k, kept});
    }
  }
  std::sort(m.duplicates.begin(), m.duplicates.end(),
            [](const Duplicate& a, const Duplicate& b) { return a.dropped < b.dropped; });
  const Stats before = result_.stats;
  result_ = m.extract(m.options.threads);
  result_.stats.time_triangulate_s = before.time_triangulate_s;
}

}  // namespace ridt
