// Interpolation in a triangulation (ridt/interpolate.hpp): linear (barycentric in the triangle
// that holds the query) and Sibson's natural-neighbour coordinates (from the cavity the query
// would dig), on the shared machinery of queries/field.hpp; a greedy walk on the Delaunay graph to a
// nearest vertex; exact barycentric coordinates and transforms.
#include "ridt/interpolate.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "queries/circumcentre.hpp"
#include "queries/field.hpp"

namespace ridt {
namespace {

using detail::Field;
using detail::kGrain;
using detail::next3;
using detail::prev3;

constexpr Point kOrigin{0, 0};  // the query, in the coordinates relative to it

class Sibson {
 public:
  explicit Sibson(const Field& f) : f_(f) {}

  void interpolate(std::size_t tri, const Point& q, double* out) {
    const std::size_t m = f_.values.components;
    // At a vertex, its value; on a hull edge, linear along it (the cell of q would be open).
    for (int i = 0; i < 3; ++i) {
      if (f_.corner(tri, i) == q) {
        std::copy_n(f_.value(f_.vertex(tri, i)), m, out);
        return;
      }
      if (f_.neighbor(tri, i) < 0 && detail::orient2d(f_.corner(tri, next3(i)), f_.corner(tri, prev3(i)), q) == 0) {
        f_.linear(tri, q, out);
        return;
      }
    }
    dig(tri, q);
    std::fill_n(out, m, 0.0);
    double total = 0;
    for (const Edge& e : boundary_) {
      const double w = stolen_area(e, q);
      total += w;
      const double* v = f_.value(e.to);
      for (std::size_t k = 0; k < m; ++k) out[k] += w * v[k];
    }
    for (std::size_t k = 0; k < m; ++k) out[k] /= total;
  }

 private:
  // A side of the cavity, from vertex `from` to `to` with q on its left, in cavity triangle
  // `tri` across from its corner `corner`.
  struct Edge {
    VertexId from, to;
    std::uint32_t tri;
    int corner;
  };

  bool in_cavity(std::int32_t u) const { return std::find(cavity_.begin(), cavity_.end(), u) != cavity_.end(); }

  // The cavity: the triangles whose circumcircle holds q strictly (exact), grown from tri, and
  // its boundary.
  void dig(std::size_t tri, const Point& q) {
    cavity_.assign(1, static_cast<std::int32_t>(tri));
    boundary_.clear();
    for (std::size_t k = 0; k < cavity_.size(); ++k) {
      const auto c = static_cast<std::size_t>(cavity_[k]);
      for (int i = 0; i < 3; ++i) {
        const std::int32_t u = f_.neighbor(c, i);
        if (u < 0 || in_cavity(u)) continue;
        const auto w = static_cast<std::size_t>(u);
        if (detail::incircle(f_.corner(w, 0), f_.corner(w, 1), f_.corner(w, 2), q) > 0) cavity_.push_back(u);
      }
    }
    for (const std::int32_t c : cavity_)
      for (int i = 0; i < 3; ++i) {
        const std::int32_t u = f_.neighbor(static_cast<std::size_t>(c), i);
        if (u < 0 || !in_cavity(u))
          boundary_.push_back({f_.vertex(static_cast<std::size_t>(c), next3(i)),
                               f_.vertex(static_cast<std::size_t>(c), prev3(i)), static_cast<std::uint32_t>(c), i});
      }
  }

  Point rel(VertexId v, const Point& q) const { return {f_.points[v].x - q.x, f_.points[v].y - q.y}; }

  // The area that q's cell takes from the cell of e.to: the polygon from the circumcentre of
  // (q, e.from, e.to), through the circumcentres of the cavity's triangles around e.to, to
  // that of (q, e.to, next), where the next side of the cavity starts at e.to.
  double stolen_area(const Edge& e, const Point& q) {
    const VertexId v = e.to;
    const Edge* out_edge = nullptr;
    for (const Edge& x : boundary_)
      if (x.from == v) out_edge = &x;
    polygon_.clear();
    polygon_.push_back(detail::circumcentre(kOrigin, rel(e.from, q), rel(v, q)));
    // Around v from the triangle of side from -> v to the one of side v -> next, across the
    // sides v-w inside the cavity.
    std::size_t tri = e.tri;
    for (std::size_t guard = 0; guard <= cavity_.size(); ++guard) {
      polygon_.push_back(
          detail::circumcentre(rel(f_.vertex(tri, 0), q), rel(f_.vertex(tri, 1), q), rel(f_.vertex(tri, 2), q)));
      if (out_edge != nullptr && tri == out_edge->tri) break;
      // v's corner i in tri: the side v -> next vertex, across from the previous corner, leads
      // on (the other side at v is the one we came by).
      const int i = f_.vertex(tri, 0) == v ? 0 : f_.vertex(tri, 1) == v ? 1 : 2;
      const std::int32_t u = f_.neighbor(tri, prev3(i));
      if (u < 0) break;
      tri = static_cast<std::size_t>(u);
    }
    polygon_.push_back(detail::circumcentre(kOrigin, rel(v, q), rel(out_edge != nullptr ? out_edge->to : v, q)));
    double area = 0;
    for (std::size_t k = 0, s = polygon_.size(); k < s; ++k) {
      const Point& a = polygon_[k];
      const Point& b = polygon_[(k + 1) % s];
      area += a.x * b.y - a.y * b.x;
    }
    return area / 2;
  }

  const Field& f_;
  std::vector<std::int32_t> cavity_;
  std::vector<Edge> boundary_;
  std::vector<Point> polygon_;
};

// The field renumbered for many queries: the vertices numbered in the order the triangles
// first meet them, their points and values copied in that order. The triangles lie in memory
// in an order near in the plane; the points and values in the caller's order, often a random
// one. Walks and answers then read points near in memory instead of missing the cache at
// every corner, which more than pays for the copy once there are about as many queries as
// triangles.

// The two answers, as queries/field.hpp's templates take them.
struct Linear {
  const Field& f;
  explicit Linear(const Field& field) : f(field) {}
  void operator()(std::size_t tri, const Point& q, double* out) const { f.linear(tri, q, out); }
};

struct Natural {
  Sibson sibson;
  explicit Natural(const Field& field) : sibson(field) {}
  void operator()(std::size_t tri, const Point& q, double* out) { sibson.interpolate(tri, q, out); }
};

}  // namespace

void interpolate_linear(std::span<const Point> points, const Triangulation& t, Values values,
                        std::span<const Point> queries, std::span<double> out, double fill, unsigned threads) {
  detail::interpolate<Linear>("interpolate_linear", points, t, values, values.components, queries, out, fill, threads);
}

void interpolate_natural_neighbor(std::span<const Point> points, const Triangulation& t, Values values,
                                  std::span<const Point> queries, std::span<double> out, double fill,
                                  unsigned threads) {
  detail::interpolate<Natural>("interpolate_natural_neighbor", points, t, values, values.components, queries, out, fill,
                               threads);
}

void interpolate_linear(std::span<const Point> points, const Triangulation& t, Values values, const Grid& grid,
                        std::span<double> out, double fill, unsigned threads) {
  detail::interpolate_grid<Linear>("interpolate_linear", points, t, values, values.components, grid, out, fill,
                                   threads);
}

void interpolate_natural_neighbor(std::span<const Point> points, const Triangulation& t, Values values,
                                  const Grid& grid, std::span<double> out, double fill, unsigned threads) {
  detail::interpolate_grid<Natural>("interpolate_natural_neighbor", points, t, values, values.components, grid, out,
                                    fill, threads);
}

std::vector<double> interpolate_linear(std::span<const Point> points, const Triangulation& t, Values values,
                                       std::span<const Point> queries, double fill, unsigned threads) {
  std::vector<double> out(queries.size() * values.components);
  interpolate_linear(points, t, values, queries, out, fill, threads);
  return out;
}

std::vector<double> interpolate_natural_neighbor(std::span<const Point> points, const Triangulation& t, Values values,
                                                 std::span<const Point> queries, double fill, unsigned threads) {
  std::vector<double> out(queries.size() * values.components);
  interpolate_natural_neighbor(points, t, values, queries, out, fill, threads);
  return out;
}

std::vector<std::int32_t> nearest_vertex(std::span<const Point> points, const Triangulation& t,
                                         std::span<const Point> queries, unsigned threads) {
  detail::check_arrays("nearest_vertex", points.size(), t.triangles, t.neighbors);
  std::vector<std::int32_t> out(queries.size(), -1);
  if (t.size() == 0) return out;
  // The Delaunay graph: each vertex's neighbours, from the triangles' sides.
  const std::size_t n = points.size();
  std::vector<std::uint32_t> offset(n + 1, 0);
  for (std::size_t k = 0; k < t.triangles.size(); ++k) offset[t.triangles[k] + 1] += 2;
  std::partial_sum(offset.begin(), offset.end(), offset.begin());
  std::vector<VertexId> adjacent(offset[n]);
  {
    std::vector<std::uint32_t> at(offset.begin(), offset.end() - 1);
    for (std::size_t tri = 0; tri < t.size(); ++tri)
      for (int i = 0; i < 3; ++i) {
        const VertexId v = t.triangles[3 * tri + i];
        adjacent[at[v]++] = t.triangles[3 * tri + next3(i)];
        adjacent[at[v]++] = t.triangles[3 * tri + prev3(i)];
      }
  }
  const std::vector<std::int32_t> where = locate(points, t, queries, threads);
  auto distance2 = [&](VertexId v, const Point& q) {
    const double dx = points[v].x - q.x, dy = points[v].y - q.y;
    return dx * dx + dy * dy;
  };
  detail::parallel_for(queries.size(), threads, kGrain, [&](std::size_t first, std::size_t last) {
    VertexId v = t.triangles[0];
    for (std::size_t k = first; k < last; ++k) {
      const Point& q = queries[k];
      if (!std::isfinite(q.x) || !std::isfinite(q.y)) continue;
      if (where[k] >= 0) v = t.triangles[3 * static_cast<std::size_t>(where[k])];
      // Greedy: to a closer neighbour while there is one. On the Delaunay graph a vertex with
      // no closer neighbour is a nearest one.
      for (double d = distance2(v, q);;) {
        VertexId best = v;
        for (std::uint32_t a = offset[v]; a < offset[v + 1]; ++a)
          if (const double e = distance2(adjacent[a], q); e < d) d = e, best = adjacent[a];
        if (best == v) break;
        v = best;
      }
      out[k] = static_cast<std::int32_t>(v);
    }
  });
  return out;
}

std::array<double, 3> barycentric(const Point& a, const Point& b, const Point& c, const Point& q) {
  std::array<double, 3> w{};
  detail::barycentric(a, b, c, q, w.data());
  return w;
}

double doubled_area(const Point& a, const Point& b, const Point& c) { return detail::doubled_area(a, b, c); }

void barycentric_transforms(std::span<const Point> points, std::span<const VertexId> triangles, std::span<double> out,
                            unsigned threads) {
  if (triangles.size() % 3 != 0 || out.size() != triangles.size() * 2)
    throw InputError("barycentric_transforms: " + std::to_string(out.size()) + " numbers of room for " +
                     std::to_string(triangles.size() / 3) + " triangles (6 each)");
  for (const VertexId v : triangles)
    if (v >= points.size()) throw InputError("barycentric_transforms: a vertex is not one of the points");
  detail::parallel_for(triangles.size() / 3, threads, kGrain, [&](std::size_t first, std::size_t last) {
    for (std::size_t t = first; t < last; ++t) {
      const Point &p0 = points[triangles[3 * t]], &p1 = points[triangles[3 * t + 1]], &r = points[triangles[3 * t + 2]];
      // M = [p0 - r, p1 - r] as columns; T = M^-1 = adj(M) / det(M).
      const double a = p0.x - r.x, b = p1.x - r.x, c = p0.y - r.y, d = p1.y - r.y;
      const double det = detail::doubled_area(p0, p1, r);
      const double norm = std::max(std::fabs(a) + std::fabs(c), std::fabs(b) + std::fabs(d));
      const double inverse_norm = std::max(std::fabs(d) + std::fabs(c), std::fabs(b) + std::fabs(a)) / std::fabs(det);
      double* o = &out[6 * t];
      if (!(norm * inverse_norm <= 0x1p40)) {
        std::fill_n(o, 4, std::numeric_limits<double>::quiet_NaN());
      } else {
        o[0] = d / det, o[1] = -b / det, o[2] = -c / det, o[3] = a / det;
      }
      o[4] = r.x, o[5] = r.y;
    }
  });
}

}  // namespace ridt
