// Sibson's natural-neighbour coordinates and the two answers that queries/field.hpp's
// templates take (Linear, Natural): shared by the interpolation calls (queries/interpolate.cpp)
// and the DEM (terrain/dem.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "queries/circumcentre.hpp"
#include "queries/field.hpp"

namespace ridt::detail {

inline constexpr Point kOrigin{0, 0};  // the query, in the coordinates relative to it

// Sibson's coordinates at q, which triangle tri holds. Scratch space is reused between queries.
class Sibson {
 public:
  explicit Sibson(const Field& f) : f_(f) {}

  void interpolate(std::size_t tri, const Point& q, double* out) {
    const std::size_t m = f_.values.components;
    // At a vertex, its value; on a hull edge, linear along it (the cell of q would be open),
    // and so beyond one, where a tolerance at the hull gives tri a query just outside it.
    for (int i = 0; i < 3; ++i) {
      if (f_.corner(tri, i) == q) {
        std::copy_n(f_.value(f_.vertex(tri, i)), m, out);
        return;
      }
      if (f_.neighbor(tri, i) < 0 && orient2d(f_.corner(tri, next3(i)), f_.corner(tri, prev3(i)), q) <= 0) {
        f_.linear(tri, q, out);
        return;
      }
    }
    dig(tri, q);
    scale_by(q);
    // Summed in an order of the points, not of the walk around the cavity (which starts where
    // the triangles' order puts it): the same bits for the same triangles in any order.
    std::sort(boundary_.begin(), boundary_.end(),
              [&](const Edge& a, const Edge& b) { return lex_less(f_.points[a.to], f_.points[b.to]); });
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
        if (incircle(f_.corner(w, 0), f_.corner(w, 1), f_.corner(w, 2), q) > 0) cavity_.push_back(u);
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

  // Where the cavity is huge or tiny (beyond 2^+-200), its points relative to q are scaled by
  // 2^scale_ (exactly: the weights are ratios of areas) to near 1, so that the circumcentres
  // and areas (of degree 4) neither overflow nor underflow.
  void scale_by(const Point& q) {
    double far = 0;  // half the largest distance along an axis, which cannot overflow
    for (const Edge& e : boundary_) {
      const Point& p = f_.points[e.to];
      far = std::max({far, std::fabs(p.x / 2 - q.x / 2), std::fabs(p.y / 2 - q.y / 2)});
    }
    scale_ = far > 0x1p-200 && far < 0x1p200 ? 0 : far > 0 && std::isfinite(far) ? -std::ilogb(far) - 1 : 0;
  }

  Point rel(VertexId v, const Point& q) const {
    const Point& p = f_.points[v];
    if (scale_ == 0) return {p.x - q.x, p.y - q.y};
    return {std::ldexp(p.x, scale_) - std::ldexp(q.x, scale_), std::ldexp(p.y, scale_) - std::ldexp(q.y, scale_)};
  }

  // The area that q's cell takes from the cell of e.to: the polygon from the circumcentre of
  // (q, e.from, e.to), through the circumcentres of the cavity's triangles around e.to, to
  // that of (q, e.to, next), where the next side of the cavity starts at e.to.
  double stolen_area(const Edge& e, const Point& q) {
    const VertexId v = e.to;
    const Edge* out_edge = nullptr;
    for (const Edge& x : boundary_)
      if (x.from == v) out_edge = &x;
    polygon_.clear();
    polygon_.push_back(circumcentre(kOrigin, rel(e.from, q), rel(v, q)));
    // Around v from the triangle of side from -> v to the one of side v -> next, across the
    // sides v-w inside the cavity.
    std::size_t tri = e.tri;
    for (std::size_t guard = 0; guard <= cavity_.size(); ++guard) {
      const int s = f_.first(tri);  // the triangle read from its first corner (Field::first)
      polygon_.push_back(
          circumcentre(rel(f_.vertex(tri, s), q), rel(f_.vertex(tri, next3(s)), q), rel(f_.vertex(tri, prev3(s)), q)));
      if (out_edge != nullptr && tri == out_edge->tri) break;
      // v's corner i in tri: the side v -> next vertex, across from the previous corner, leads
      // on (the other side at v is the one we came by).
      const int i = f_.vertex(tri, 0) == v ? 0 : f_.vertex(tri, 1) == v ? 1 : 2;
      const std::int32_t u = f_.neighbor(tri, prev3(i));
      if (u < 0) break;
      tri = static_cast<std::size_t>(u);
    }
    polygon_.push_back(circumcentre(kOrigin, rel(v, q), rel(out_edge != nullptr ? out_edge->to : v, q)));
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
  int scale_ = 0;
};

// The two answers, as queries/field.hpp's templates take them.
struct Linear {
  const Field& f;
  explicit Linear(const Field& field) : f(field) {}
  void operator()(std::size_t tri, const Point& q, double* out, const double* weights = nullptr, int from = -1) const {
    f.linear(tri, q, out, weights, from);
  }
};

struct Natural {
  Sibson sibson;
  explicit Natural(const Field& field) : sibson(field) {}
  void operator()(std::size_t tri, const Point& q, double* out, const double* /*weights*/ = nullptr,
                  int /*from*/ = -1) {
    sibson.interpolate(tri, q, out);
  }
};

}  // namespace ridt::detail
