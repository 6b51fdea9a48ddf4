// Interpolation in a triangulation (ridt/interpolate.hpp). Every query is first located
// (ridt::locate, exact, on threads), or, for the nodes of a grid, found by the triangles that
// hold them; then each is answered on its own: barycentric in its triangle, Sibson's
// coordinates from the cavity it would dig, or a greedy walk on the Delaunay graph to a
// nearest vertex.
#include "ridt/interpolate.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <string>

#include "arrays.hpp"
#include "cavity.hpp"
#include "circumcentre.hpp"
#include "parallel.hpp"
#include "predicates.hpp"
#include "ridt/locate.hpp"

namespace ridt {
namespace {

using detail::next3;
using detail::prev3;

constexpr std::size_t kGrain = 1 << 14;  // queries a thread takes at least
constexpr Point kOrigin{0, 0};            // the query, in the coordinates relative to it

void check_values(const char* who, std::size_t n, const Values& values) {
  if (values.components == 0 || values.data.size() != n * values.components)
    throw InputError(std::string(who) + ": " + std::to_string(values.data.size()) + " values for " +
                     std::to_string(n) + " points of " + std::to_string(values.components) + " components");
}

// What interpolation reads: the points, the triangulation, the values.
struct Field {
  std::span<const Point> points;
  std::span<const VertexId> triangles;
  std::span<const std::int32_t> neighbors;
  Values values;

  const Point& corner(std::size_t tri, int i) const { return points[triangles[3 * tri + i]]; }
  VertexId vertex(std::size_t tri, int i) const { return triangles[3 * tri + i]; }
  std::int32_t neighbour(std::size_t tri, int i) const { return neighbors[3 * tri + i]; }
  const double* value(VertexId v) const { return values.data.data() + v * values.components; }

  // out = the barycentric interpolant of triangle tri at q, its weights within 2^-44 of the
  // exact ones (detail::barycentric): at a corner the corner's value, on a side the side's
  // linear interpolant, bounded for the thinnest sliver.
  void linear(std::size_t tri, const Point& q, double* out) const {
    double w[3];
    detail::barycentric(corner(tri, 0), corner(tri, 1), corner(tri, 2), q, w);
    const double *va = value(vertex(tri, 0)), *vb = value(vertex(tri, 1)), *vc = value(vertex(tri, 2));
    for (std::size_t k = 0; k < values.components; ++k) out[k] = w[0] * va[k] + w[1] * vb[k] + w[2] * vc[k];
  }
};

// Sibson's coordinates at q, which triangle tri holds. Scratch space is reused between queries.
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
      if (f_.neighbour(tri, i) < 0 && detail::orient2d(f_.corner(tri, next3(i)), f_.corner(tri, prev3(i)), q) == 0) {
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
        const std::int32_t u = f_.neighbour(c, i);
        if (u < 0 || in_cavity(u)) continue;
        const auto w = static_cast<std::size_t>(u);
        if (detail::incircle(f_.corner(w, 0), f_.corner(w, 1), f_.corner(w, 2), q) > 0) cavity_.push_back(u);
      }
    }
    for (const std::int32_t c : cavity_)
      for (int i = 0; i < 3; ++i) {
        const std::int32_t u = f_.neighbour(static_cast<std::size_t>(c), i);
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
      const std::int32_t u = f_.neighbour(tri, prev3(i));
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
struct Renumbered {
  std::vector<Point> points;
  std::vector<VertexId> triangles;
  std::vector<double> values;

  Renumbered(const Field& f, unsigned threads) : triangles(f.triangles.size()) {
    std::vector<VertexId> id(f.points.size(), kNone), old;
    old.reserve(f.points.size());
    for (std::size_t k = 0; k < triangles.size(); ++k) {
      VertexId& v = id[f.triangles[k]];
      if (v == kNone) {
        v = static_cast<VertexId>(old.size());
        old.push_back(f.triangles[k]);
      }
      triangles[k] = v;
    }
    const std::size_t m = f.values.components;
    points.resize(old.size());
    values.resize(old.size() * m);
    detail::parallel_for(old.size(), threads, kGrain, [&](std::size_t first, std::size_t last) {
      for (std::size_t k = first; k < last; ++k) {
        points[k] = f.points[old[k]];
        std::copy_n(f.value(old[k]), m, &values[k * m]);
      }
    });
  }

  Field field(std::span<const std::int32_t> neighbors, std::size_t m) const {
    return {points, triangles, neighbors, Values{values, m}};
  }

  static constexpr VertexId kNone = ~VertexId{0};
};

// What both kinds of call read, checked: the field, renumbered when there are about as many
// answers (`count` of `what`, queries or nodes) as triangles.
class Input {
 public:
  Input(const char* who, std::span<const Point> points, const Triangulation& t, Values values, std::size_t count,
        const char* what, std::span<double> out, unsigned threads)
      : field_{points, t.triangles, t.neighbors, values} {
    detail::check_arrays(who, points.size(), t.triangles, t.neighbors);
    check_values(who, points.size(), values);
    const std::size_t m = values.components;
    if (out.size() != count * m)
      throw InputError(std::string(who) + ": room for " + std::to_string(out.size()) + " numbers, not " +
                       std::to_string(count) + " " + what + " of " + std::to_string(m) + " components");
    if (count >= t.size()) {
      renumbered_.emplace(field_, threads);
      field_ = renumbered_->field(t.neighbors, m);
    }
  }
  Input(const Input&) = delete;
  Input& operator=(const Input&) = delete;

  const Field& field() const { return field_; }

 private:
  Field field_;
  std::optional<Renumbered> renumbered_;
};

template <class Answer>
void interpolate(const char* who, std::span<const Point> points, const Triangulation& t, Values values,
                 std::span<const Point> queries, std::span<double> out, double fill, unsigned threads,
                 Answer&& answer) {
  const Input input(who, points, t, values, queries.size(), "queries", out, threads);
  const Field& field = input.field();
  const std::size_t m = values.components;
  std::vector<std::int32_t> where(queries.size());
  locate(field.points, field.triangles, field.neighbors, queries, where, threads);
  detail::parallel_for(queries.size(), threads, kGrain, [&](std::size_t first, std::size_t last) {
    Sibson sibson(field);
    for (std::size_t k = first; k < last; ++k) {
      if (where[k] >= 0)
        answer(field, sibson, static_cast<std::size_t>(where[k]), queries[k], &out[k * m]);
      else
        std::fill_n(&out[k * m], m, fill);
    }
  });
}

// One axis of a grid, seen as increasing: value(k) is the k-th smallest coordinate and
// index(k) its place in the caller's array.
class Axis {
 public:
  Axis(const char* who, const char* name, std::span<const double> v) : v_(v), n_(v.size()) {
    bool up = true, down = true;
    for (std::size_t k = 0; k < n_; ++k) {
      if (!std::isfinite(v[k]))
        throw InputError(std::string(who) + ": grid " + name + "[" + std::to_string(k) + "] is not finite");
      if (k > 0) up = up && v[k] > v[k - 1], down = down && v[k] < v[k - 1];
    }
    if (!up && !down)
      throw InputError(std::string(who) + ": the grid's " + name + " must be strictly increasing or decreasing");
    reversed_ = n_ > 1 && down;
    if (n_ > 1) lowest_ = value(0), per_step_ = static_cast<double>(n_ - 1) / (value(n_ - 1) - lowest_);
  }

  double value(std::size_t k) const { return v_[index(k)]; }
  std::size_t index(std::size_t k) const { return reversed_ ? n_ - 1 - k : k; }

  // The nodes with lo <= value <= hi: [first, last). A guess from the mean step, then steps to
  // the exact ends, so uneven axes are right too, only slower.
  std::pair<std::size_t, std::size_t> within(double lo, double hi) const {
    std::size_t first = guess(lo), last = guess(hi);
    while (first > 0 && value(first - 1) >= lo) --first;
    while (first < n_ && value(first) < lo) ++first;
    while (last < n_ && value(last) <= hi) ++last;
    while (last > first && value(last - 1) > hi) --last;
    return {first, std::max(first, last)};
  }

 private:
  std::size_t guess(double x) const {
    if (!(per_step_ > 0)) return 0;
    const double k = std::floor((x - lowest_) * per_step_);
    return k <= 0 ? 0 : k >= static_cast<double>(n_) ? n_ : static_cast<std::size_t>(k);
  }

  std::span<const double> v_;
  std::size_t n_;
  bool reversed_ = false;
  double lowest_ = 0, per_step_ = 0;  // nodes a unit, on average
};

// The lowest-numbered triangle around the vertex at corner i of triangle tri.
std::size_t lowest_around(const Field& f, std::size_t tri, int i) {
  const VertexId v = f.vertex(tri, i);
  std::size_t lowest = tri;
  // Counter-clockwise (across the side v -> next, across from the previous corner), then, if
  // that reaches the hull, clockwise from tri.
  for (int turn = 0; turn < 2; ++turn) {
    std::size_t at = tri;
    int corner = i;
    for (std::size_t steps = 0; steps <= f.triangles.size(); ++steps) {
      const std::int32_t u = f.neighbour(at, turn == 0 ? prev3(corner) : next3(corner));
      if (u < 0) break;
      at = static_cast<std::size_t>(u);
      if (at == tri) return lowest;
      corner = f.vertex(at, 0) == v ? 0 : f.vertex(at, 1) == v ? 1 : 2;
      lowest = std::min(lowest, at);
    }
  }
  return lowest;
}

// Calls take(tri, node, p), with take = make_take() on each thread, once for every grid node p that the closed hull holds, with a
// triangle tri that holds it: each triangle visits the nodes of its bounding box and takes
// those strictly inside, those on a hull side, those on an inner side whose other triangle
// has a higher number, and a vertex when it is the lowest-numbered triangle around it. So
// every node in the hull is taken exactly once, and threads that take stretches of the
// triangles never write the same node.
template <class MakeTake>
void cover(const Field& f, const Axis& ax, const Axis& ay, const Grid& grid, unsigned threads, MakeTake&& make_take) {
  const std::size_t count = f.triangles.size() / 3, nx = grid.x.size(), ny = grid.y.size();
  detail::parallel_for(count, threads, kGrain, [&](std::size_t first, std::size_t last) {
    auto take = make_take();  // this thread's own, with its scratch space
    for (std::size_t tri = first; tri < last; ++tri) {
      const Point& a = f.corner(tri, 0);
      const Point& b = f.corner(tri, 1);
      const Point& c = f.corner(tri, 2);
      const auto [i0, i1] = ax.within(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}));
      if (i0 == i1) continue;
      const auto [j0, j1] = ay.within(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}));
      for (std::size_t j = j0; j < j1; ++j) {
        const double y = ay.value(j);
        for (std::size_t i = i0; i < i1; ++i) {
          const Point p{ax.value(i), y};
          const int o[3] = {detail::orient2d(b, c, p), detail::orient2d(c, a, p), detail::orient2d(a, b, p)};
          if (o[0] < 0 || o[1] < 0 || o[2] < 0) continue;
          const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
          if (zeros == 1) {
            const int e = o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2;
            const std::int32_t u = f.neighbour(tri, e);
            if (u >= 0 && static_cast<std::size_t>(u) < tri) continue;
          } else if (zeros == 2) {
            const int corner = o[0] != 0 ? 0 : o[1] != 0 ? 1 : 2;  // p is this vertex
            if (lowest_around(f, tri, corner) != tri) continue;
          }
          const std::size_t gi = ax.index(i), gj = ay.index(j);
          take(tri, grid.x_major ? gi * ny + gj : gj * nx + gi, p);
        }
      }
    }
  });
}

template <class Answer>
void interpolate_grid(const char* who, std::span<const Point> points, const Triangulation& t, Values values,
                      const Grid& grid, std::span<double> out, double fill, unsigned threads, Answer&& answer) {
  const Axis ax(who, "x", grid.x), ay(who, "y", grid.y);
  const Input input(who, points, t, values, grid.size(), "nodes", out, threads);
  const Field& field = input.field();
  const std::size_t m = values.components;
  detail::parallel_for(out.size(), threads, kGrain, [&](std::size_t first, std::size_t last) {
    std::fill(out.begin() + static_cast<std::ptrdiff_t>(first), out.begin() + static_cast<std::ptrdiff_t>(last), fill);
  });
  cover(field, ax, ay, grid, threads, [&] {
    return [&, sibson = Sibson(field)](std::size_t tri, std::size_t node, const Point& p) mutable {
      answer(field, sibson, tri, p, &out[node * m]);
    };
  });
}

void linear(const Field& f, Sibson&, std::size_t tri, const Point& q, double* out) { f.linear(tri, q, out); }
void natural(const Field&, Sibson& s, std::size_t tri, const Point& q, double* out) { s.interpolate(tri, q, out); }

}  // namespace

void interpolate_linear(std::span<const Point> points, const Triangulation& t, Values values,
                        std::span<const Point> queries, std::span<double> out, double fill, unsigned threads) {
  interpolate("interpolate_linear", points, t, values, queries, out, fill, threads, linear);
}

void interpolate_natural_neighbor(std::span<const Point> points, const Triangulation& t, Values values,
                                  std::span<const Point> queries, std::span<double> out, double fill,
                                  unsigned threads) {
  interpolate("interpolate_natural_neighbor", points, t, values, queries, out, fill, threads, natural);
}

void interpolate_linear(std::span<const Point> points, const Triangulation& t, Values values, const Grid& grid,
                        std::span<double> out, double fill, unsigned threads) {
  interpolate_grid("interpolate_linear", points, t, values, grid, out, fill, threads, linear);
}

void interpolate_natural_neighbor(std::span<const Point> points, const Triangulation& t, Values values,
                                  const Grid& grid, std::span<double> out, double fill, unsigned threads) {
  interpolate_grid("interpolate_natural_neighbor", points, t, values, grid, out, fill, threads, natural);
}

std::vector<double> interpolate_linear(std::span<const Point> points, const Triangulation& t, Values values,
                                       std::span<const Point> queries, double fill, unsigned threads) {
  std::vector<double> out(queries.size() * values.components);
  interpolate_linear(points, t, values, queries, out, fill, threads);
  return out;
}

std::vector<double> interpolate_natural_neighbor(std::span<const Point> points, const Triangulation& t,
                                                 Values values, std::span<const Point> queries, double fill,
                                                 unsigned threads) {
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

void barycentric_transforms(std::span<const Point> points, std::span<const VertexId> triangles,
                            std::span<double> out, unsigned threads) {
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
