// A triangulation that takes more points (ridt/incremental.hpp).
//
// It keeps the whole mesh the kernels build before their finish: the points' triangles and,
// around them, those of the three bounding vertices at infinity (predicates/symbolic.hpp), so that a new
// point anywhere, inside the hull or outside it, lies in some triangle. Each insertion walks
// there, digs the cavity of the triangles whose circle holds the point (exact, never a tie:
// the symbolic perturbation), and fans it from the point (Bowyer-Watson). The predicates are
// the kernels' own, so the mesh is the one a fresh build makes, and the same finish-like
// extraction gives the same triangles.
//
// The mesh starts from a triangulation already made: its triangles, and the bounding
// vertices' triangles, which depend on the hull's vertices alone (each such triangle's circle
// is a half-plane beyond a hull edge, or a quadrant beyond an extreme point), found by
// inserting just the hull's vertices into an empty mesh.
#include "ridt/incremental.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "finish/finish.hpp"
#include "order/order.hpp"
#include "predicates/symbolic.hpp"
#include "walk/mesh.hpp"

namespace ridt {

using detail::next3;
using detail::prev3;

namespace {
constexpr VertexId kNone = ~VertexId{0};
}  // namespace

struct IncrementalTriangulation::Mesh {
  static constexpr VertexId kDead = ~VertexId{0};  // a slot's first vertex when it is free

  std::vector<Point> pts;  // the n points, then the three bounding vertices' NaN points
  std::uint32_t n = 0;
  std::vector<VertexId> v;  // three a slot, counter-clockwise
  std::vector<std::int32_t> nb;  // three a slot: the slot across from each corner, -1 beyond the bounding triangle
  std::vector<std::uint32_t> free;
  std::uint32_t last = 0;  // where the next walk starts
  std::vector<Duplicate> duplicates;
  Options options;
  // Scratch, kept between insertions.
  std::vector<std::uint8_t> in_cavity;
  std::vector<std::uint32_t> cavity;
  struct Side {
    VertexId from, to;
    std::int32_t outside;
  };
  std::vector<Side> sides;
  std::vector<std::pair<VertexId, std::uint32_t>> starts;  // (a side's first vertex, the side)
  std::uint32_t turn = 0;

  Mesh(std::span<const Point> points, const Options& o) : options(o) {
    n = static_cast<std::uint32_t>(points.size());
    pts.assign(points.begin(), points.end());
    pts.insert(pts.end(), 3, detail::Vertices::kBoundingNaN);
  }

  detail::Vertices vertices() const { return detail::Vertices(pts.data(), n, true); }
  bool finite(std::size_t t) const { return v[3 * t] < n && v[3 * t + 1] < n && v[3 * t + 2] < n; }
  bool alive(std::size_t t) const { return v[3 * t] != kDead; }

  std::uint32_t slot() {
    if (!free.empty()) {
      const std::uint32_t s = free.back();
      free.pop_back();
      return s;
    }
    v.resize(v.size() + 3), nb.resize(nb.size() + 3), in_cavity.push_back(0);
    return static_cast<std::uint32_t>(v.size() / 3 - 1);
  }

  void root() {
    v = {n, n + 1, n + 2};
    nb = {-1, -1, -1};
    in_cavity = {0};
    free.clear();
    last = 0;
  }

  // The triangle that holds point p (closed), by a visibility walk from `last`; Delaunay
  // meshes never make it cycle. Starting at a turning side spreads ties.
  std::uint32_t locate(const detail::Vertices& vs, VertexId p) {
    std::uint32_t t = last;
    for (bool moved = true; moved;) {
      moved = false;
      const int first = static_cast<int>(turn++ % 3);
      for (int k = 0; k < 3 && !moved; ++k) {
        const int i = (first + k) % 3;
        if (vs.orient(v[3 * t + next3(i)], v[3 * t + prev3(i)], p) < 0) {
          t = static_cast<std::uint32_t>(nb[3 * t + i]);
          moved = true;
        }
      }
    }
    return t;
  }

  // Inserts point p; returns the vertex equal to it (p is then left out), else kNone.
  VertexId insert(const detail::Vertices& vs, VertexId p) {
    const std::uint32_t t = locate(vs, p);
    for (int i = 0; i < 3; ++i)
      if (v[3 * t + i] < n && pts[v[3 * t + i]] == pts[p]) return v[3 * t + i];
    // The cavity: every triangle whose circle holds p, grown from t (which does: p is in it).
    cavity.assign(1, t);
    in_cavity[t] = 1;
    for (std::size_t k = 0; k < cavity.size(); ++k)
      for (int i = 0; i < 3; ++i) {
        const std::int32_t u = nb[3 * cavity[k] + i];
        if (u < 0 || in_cavity[u]) continue;
        const VertexId* w = &v[3 * std::size_t(u)];
        if (vs.incircle(w[0], w[1], w[2], p) > 0) in_cavity[u] = 1, cavity.push_back(static_cast<std::uint32_t>(u));
      }
    sides.clear();
    for (const std::uint32_t c : cavity)
      for (int i = 0; i < 3; ++i) {
        const std::int32_t u = nb[3 * c + i];
        if (u < 0 || !in_cavity[u]) sides.push_back({v[3 * c + next3(i)], v[3 * c + prev3(i)], u});
      }
    for (const std::uint32_t c : cavity) in_cavity[c] = 0;
    // A fan from p: side s gives triangle (from, to, p). Slots: the cavity's, then more.
    std::vector<std::uint32_t> made(sides.size());
    for (std::size_t s = 0; s < sides.size(); ++s) made[s] = s < cavity.size() ? cavity[s] : slot();
    for (std::size_t s = 0; s < sides.size(); ++s) {
      const Side& e = sides[s];
      const std::uint32_t m = made[s];
      v[3 * m] = e.from, v[3 * m + 1] = e.to, v[3 * m + 2] = p;
      nb[3 * m + 2] = e.outside;
      if (e.outside >= 0) {
        std::int32_t* back = &nb[3 * std::size_t(e.outside)];
        const VertexId* w = &v[3 * std::size_t(e.outside)];
        // The outside triangle's corner across this side: the one not on it.
        for (int j = 0; j < 3; ++j)
          if (w[j] != e.from && w[j] != e.to) back[j] = static_cast<std::int32_t>(m);
      }
    }
    // Around p: across from `from` lies the fan triangle of the next side (the one that starts
    // at `to`), across from `to` that of the previous one. The sides form one cycle, each
    // vertex the start of one: found by their starts, sorted (a cavity can be large: a point
    // far outside a hull of many vertices).
    starts.clear();
    for (std::size_t s = 0; s < sides.size(); ++s) starts.emplace_back(sides[s].from, static_cast<std::uint32_t>(s));
    std::sort(starts.begin(), starts.end());
    for (std::size_t s = 0; s < sides.size(); ++s) {
      const auto next = std::lower_bound(starts.begin(), starts.end(), std::pair{sides[s].to, std::uint32_t{0}});
      const std::uint32_t r = next->second;
      nb[3 * made[s]] = static_cast<std::int32_t>(made[r]);
      nb[3 * made[r] + 1] = static_cast<std::int32_t>(made[s]);
    }
    last = made[0];
    return kNone;
  }

  // The bounding vertices' triangles around triangulation t of the points: those of a mesh
  // of the hull's vertices alone, joined to t's triangles along the hull.
  void around(const Triangulation& t) {
    Mesh outer(std::span<const Point>(pts.data(), n), options);
    outer.root();
    const detail::Vertices vs = outer.vertices();
    for (const VertexId h : t.hull) outer.insert(vs, h);
    v = t.triangles;
    nb = t.neighbors;
    in_cavity.assign(t.size(), 0);
    std::map<std::pair<VertexId, VertexId>, std::pair<std::uint32_t, int>> hull_side;  // (a, b) -> (triangle, corner)
    for (std::size_t k = 0; k < t.size(); ++k)
      for (int i = 0; i < 3; ++i)
        if (t.neighbors[3 * k + i] < 0)
          hull_side[{t.triangles[3 * k + next3(i)], t.triangles[3 * k + prev3(i)]}] = {static_cast<std::uint32_t>(k),
                                                                                       i};
    std::vector<std::int32_t> moved(outer.v.size() / 3, -1);
    for (std::size_t o = 0; o < outer.v.size() / 3; ++o)
      if (outer.alive(o) && !outer.finite(o)) moved[o] = static_cast<std::int32_t>(slot());
    for (std::size_t o = 0; o < moved.size(); ++o) {
      if (moved[o] < 0) continue;
      const auto m = static_cast<std::size_t>(moved[o]);
      for (int j = 0; j < 3; ++j) {
        v[3 * m + j] = outer.v[3 * o + j];
        const std::int32_t u = outer.nb[3 * o + j];
        if (u < 0 || moved[u] >= 0) {
          nb[3 * m + j] = u < 0 ? -1 : moved[u];
          continue;
        }
        // Across a hull side from inside: t's triangle on it.
        const auto [tri, corner] = hull_side.at({outer.v[3 * o + prev3(j)], outer.v[3 * o + next3(j)]});
        nb[3 * m + j] = static_cast<std::int32_t>(tri);
        nb[3 * std::size_t(tri) + corner] = static_cast<std::int32_t>(m);
      }
    }
    last = 0;
  }

  // The bounding vertices are numbered after the points: n grows by `more`.
  void renumber_bounding(std::uint32_t more) {
    for (VertexId& x : v)
      if (x != kDead && x >= n) x += more;
    n += more;
  }

  Triangulation extract(unsigned threads) const {
    Triangulation out;
    std::vector<std::int32_t> id(v.size() / 3, -1);
    std::int32_t count = 0;
    for (std::size_t t = 0; t < id.size(); ++t)
      if (alive(t) && finite(t)) id[t] = count++;
    out.triangles.reserve(3 * std::size_t(count));
    out.neighbors.reserve(3 * std::size_t(count));
    std::vector<std::pair<VertexId, VertexId>> hull_edges;
    for (std::size_t t = 0; t < id.size(); ++t) {
      if (id[t] < 0) continue;
      for (int i = 0; i < 3; ++i) {
        out.triangles.push_back(v[3 * t + i]);
        const std::int32_t u = nb[3 * t + i];
        out.neighbors.push_back(u < 0 ? -1 : id[u]);
        if (u < 0 || id[u] < 0) hull_edges.emplace_back(v[3 * t + next3(i)], v[3 * t + prev3(i)]);
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
    : mesh_(std::make_unique<Mesh>(points, options)) {
  if (options.experiment.bounding != Bounding::Symbolic)
    throw InputError("an incremental triangulation needs the symbolic bounding vertices");
  check_finite(points, 0);
  Mesh& m = *mesh_;
  m.duplicates = t.duplicates;
  if (t.size() > 0) {
    m.around(t);
  } else {
    // No triangle yet (fewer than three distinct points, or all collinear): the mesh of the
    // distinct points, inserted one by one.
    m.root();
    const detail::Vertices vs = m.vertices();
    std::vector<std::uint8_t> dropped(points.size(), 0);
    for (const Duplicate& d : t.duplicates) dropped[d.dropped] = 1;
    for (const std::uint32_t p : detail::hilbert_order(points.data(), static_cast<std::uint32_t>(points.size())))
      if (!dropped[p]) m.insert(vs, p);
  }
  result_ = std::move(t);  // the triangulation of these points, as triangulate() gave it
}

IncrementalTriangulation::~IncrementalTriangulation() = default;
IncrementalTriangulation::IncrementalTriangulation(IncrementalTriangulation&&) noexcept = default;
IncrementalTriangulation& IncrementalTriangulation::operator=(IncrementalTriangulation&&) noexcept = default;

std::span<const Point> IncrementalTriangulation::points() const { return {mesh_->pts.data(), mesh_->n}; }

void IncrementalTriangulation::add(std::span<const Point> more) {
  Mesh& m = *mesh_;
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
  std::vector<VertexId> stands(count, kNone);  // for a new point left out: the new point it equals
  for (std::uint32_t k = 1; k < count; ++k)
    if (m.pts[by_point[k]] == m.pts[by_point[k - 1]])
      stands[by_point[k] - first] =
          stands[by_point[k - 1] - first] == kNone ? by_point[k - 1] : stands[by_point[k - 1] - first];
  const detail::Vertices vs = m.vertices();
  std::vector<VertexId> old(count, kNone);  // for a new point equal to an old vertex: that vertex
  for (const std::uint32_t k : detail::hilbert_order(more.data(), count))
    if (stands[k] == kNone) old[k] = m.insert(vs, first + k);
  for (std::uint32_t k = 0; k < count; ++k) {
    if (old[k] != kNone) m.duplicates.push_back({first + k, old[k]});
    if (stands[k] != kNone) {
      const VertexId kept = old[stands[k] - first] != kNone ? old[stands[k] - first] : stands[k];
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
