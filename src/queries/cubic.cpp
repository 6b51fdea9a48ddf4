// The cubic interpolant (ridt/interpolate.hpp): gradients estimated on the Delaunay graph, then
// the Clough-Tocher split of each triangle into three cubic Bezier pieces.
//
// The pieces' control points, for a triangle P0 P1 P2 with centroid C and, at each corner, the
// value f and gradient g (Farin, "Triangular Bernstein-Bezier patches", 1986):
//   at a corner:               f_i
//   on the sides, by a corner: f_i + (P_j - P_i).g_i / 3 (j the side's other end)
//   towards C, by a corner:    a_i = f_i + (C - P_i).g_i / 3
//   by each side's middle:     t, such that the derivative across the side is linear along it
//   next along P_i C:          s_i = (a_i + t of the two sides at P_i) / 3
//   at C:                      (s_0 + s_1 + s_2) / 3
// The last two rows make the pieces meet with continuous derivatives inside the triangle; the
// sides' t make two triangles meet so, since each side's cross derivative is then the linear
// function of the two corners' gradients, the same from both sides. The direction "across" must
// be the same from both sides: the line between the two triangles' centroids; on the hull, as
// if the triangle's mirror image through the side's midpoint lay across it (from the opposite
// corner to the side's midpoint), which keeps the whole construction affine-invariant.
#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include "queries/field.hpp"

namespace ridt {
namespace {

using detail::Field;
using detail::next3;
using detail::prev3;

// One triangle's Clough-Tocher interpolant at q. The field's values hold, a point, the k values
// and then their k gradients (d/dx, d/dy each). The triangle's control points are kept for the
// next query in the same triangle (a grid's nodes come a triangle at a time).
class CloughTocher {
 public:
  explicit CloughTocher(const Field& f) : f_(f), k_(f.values.components / 3), net_(k_) {}

  void operator()(std::size_t tri, const Point& q, double* out) {
    const Point p[3] = {f_.corner(tri, 0), f_.corner(tri, 1), f_.corner(tri, 2)};
    double b[3];
    detail::barycentric(p[0], p[1], p[2], q, b);
    for (int i = 0; i < 3; ++i)
      if (b[i] == 1) {  // at a corner (exactly: the weights are exact there): its values
        std::copy_n(f_.value(f_.vertex(tri, i)), k_, out);
        return;
      }
    if (tri != tri_) control_points(tri, p);
    // The piece: the one across from the corner of least weight.
    const int m = b[0] <= b[1] && b[0] <= b[2] ? 0 : b[1] <= b[2] ? 1 : 2;
    const int ia = next3(m), ib = prev3(m);
    const double u = b[ia] - b[m], v = b[ib] - b[m], w = 3 * b[m];
    for (std::size_t k = 0; k < k_; ++k) {
      const Net& n = net_[k];
      const Corner &a = n.corner[ia], &e = n.corner[ib];
      out[k] = a.f * u * u * u + e.f * v * v * v + n.centre * w * w * w +
          3 *
              (a.next * u * u * v + e.prev * u * v * v + a.in * u * u * w + e.in * v * v * w + n.s[ia] * u * w * w +
               n.s[ib] * v * w * w) +
          6 * n.t[m] * u * v * w;
    }
  }

 private:
  struct Corner {
    double f, next, prev, in;  // the value, the control points towards the next and previous corners and C
  };
  // One component's control points on the triangle.
  struct Net {
    Corner corner[3];
    double t[3];  // by the middle of side i, from corner next3(i) to prev3(i)
    double s[3];  // next to C on the way from corner i
    double centre;
  };
  struct Across {
    double a, b, c;  // weights of the side's first and second end and the centroid, summing to 0
  };

  void control_points(std::size_t tri, const Point* p) {
    tri_ = tri;
    const Point c = centroid(p[0], p[1], p[2]);
    // The direction across each side (side i is across from corner i) as barycentric weights
    // of its two ends and the centroid, the same for every component.
    Across across[3];
    for (int i = 0; i < 3; ++i) across[i] = direction(tri, i, p, c);
    const double* value[3] = {f_.value(f_.vertex(tri, 0)), f_.value(f_.vertex(tri, 1)), f_.value(f_.vertex(tri, 2))};
    for (std::size_t k = 0; k < k_; ++k) {
      Net& n = net_[k];
      for (int i = 0; i < 3; ++i) {
        const double gx = value[i][k_ + 2 * k], gy = value[i][k_ + 2 * k + 1];
        Corner& o = n.corner[i];
        o.f = value[i][k];
        o.next = o.f + ((p[next3(i)].x - p[i].x) * gx + (p[next3(i)].y - p[i].y) * gy) / 3;
        o.prev = o.f + ((p[prev3(i)].x - p[i].x) * gx + (p[prev3(i)].y - p[i].y) * gy) / 3;
        o.in = o.f + ((c.x - p[i].x) * gx + (c.y - p[i].y) * gy) / 3;
      }
      for (int i = 0; i < 3; ++i) {
        const Corner &a = n.corner[next3(i)], &e = n.corner[prev3(i)];
        const Across& d = across[i];
        const double d0 = d.a * a.f + d.b * a.next + d.c * a.in;
        const double d2 = d.a * e.prev + d.b * e.f + d.c * e.in;
        n.t[i] = ((d0 + d2) / 2 - d.a * a.next - d.b * e.prev) / d.c;
      }
      for (int i = 0; i < 3; ++i) n.s[i] = (n.corner[i].in + n.t[next3(i)] + n.t[prev3(i)]) / 3;
      n.centre = (n.s[0] + n.s[1] + n.s[2]) / 3;
    }
  }

  static Point centroid(const Point& a, const Point& b, const Point& c) {
    return {a.x + ((b.x - a.x) + (c.x - a.x)) / 3, a.y + ((b.y - a.y) + (c.y - a.y)) / 3};
  }

  // Side i runs from A = p[next3(i)] to B = p[prev3(i)]; the direction d towards the
  // neighbour's centroid (on the hull, from corner i to the side's midpoint), written
  // d = b (B - A) + c (C - A). The determinant is exact (a third of the triangle's doubled
  // area), so that a sliver still gets finite weights.
  Across direction(std::size_t tri, int i, const Point* p, const Point& c) const {
    const Point& a = p[next3(i)];
    const Point& e = p[prev3(i)];
    Point d;
    const std::int32_t u = f_.neighbor(tri, i);
    if (u >= 0) {
      const auto n = static_cast<std::size_t>(u);
      const Point o = centroid(f_.corner(n, 0), f_.corner(n, 1), f_.corner(n, 2));
      d = {o.x - c.x, o.y - c.y};
    } else {
      d = {(a.x - p[i].x) + (e.x - p[i].x), (a.y - p[i].y) + (e.y - p[i].y)};
    }
    const double e1x = e.x - a.x, e1y = e.y - a.y, e2x = c.x - a.x, e2y = c.y - a.y;
    const double det = detail::doubled_area(a, e, p[i]) / 3;
    const double wb = (d.x * e2y - d.y * e2x) / det, wc = (e1x * d.y - e1y * d.x) / det;
    return {-wb - wc, wb, wc};
  }

  const Field& f_;
  std::size_t k_;
  std::vector<Net> net_;
  std::size_t tri_ = ~std::size_t{0};  // the triangle net_ is for
};

// A vertex's value and gradient during the sweeps, side by side for the neighbours' reads.
struct Node {
  double f, gx, gy;
};

// The minimum-norm network's system, its vertices numbered in the order the triangles first
// meet them (near in the plane, near in memory, where the input's order is often random):
// each vertex's neighbours on the Delaunay graph, once each, with 1 / L^3 of the edge, and the
// inverse of the vertex's matrix Q = sum 4 e e^T / L^3, which depends on the geometry alone.
struct Network {
  std::vector<VertexId> order;  // new number -> input index
  std::vector<Point> at;  // the points in the new order
  std::vector<std::uint32_t> offset;
  std::vector<std::uint32_t> to;
  std::vector<double> inv_l3;
  std::vector<std::array<double, 3>> q_inverse;  // [[a b] [b c]]; NaN where Q is singular
  // The vertices by colour, no two neighbours of one colour, so that a colour's vertices can
  // be updated at once on threads: colour c's are by_colour[first[c] .. first[c + 1]).
  std::vector<std::uint32_t> by_colour, first;

  Network(std::span<const Point> points, const Triangulation& t, unsigned threads) {
    std::vector<std::uint32_t> id(points.size(), kNone);
    std::vector<VertexId> tri(t.triangles.size());
    for (std::size_t k = 0; k < tri.size(); ++k) {
      std::uint32_t& v = id[t.triangles[k]];
      if (v == kNone) v = static_cast<std::uint32_t>(order.size()), order.push_back(t.triangles[k]);
      tri[k] = v;
    }
    const std::size_t count = order.size();
    at.resize(count);
    for (std::size_t v = 0; v < count; ++v) at[v] = points[order[v]];
    // The next corner of every triangle around a vertex, and across each hull side the one
    // that misses it.
    auto each = [&](auto&& visit) {
      for (std::size_t k = 0; k < tri.size(); k += 3)
        for (int i = 0; i < 3; ++i) {
          visit(tri[k + i], tri[k + next3(i)]);
          if (t.neighbors[k + i] < 0) visit(tri[k + prev3(i)], tri[k + next3(i)]);
        }
    };
    offset.assign(count + 1, 0);
    each([&](std::uint32_t v, std::uint32_t) { ++offset[v + 1]; });
    for (std::size_t v = 0; v < count; ++v) offset[v + 1] += offset[v];
    to.resize(offset[count]);
    std::vector<std::uint32_t> fill(offset.begin(), offset.end() - 1);
    each([&](std::uint32_t v, std::uint32_t w) { to[fill[v]++] = w; });
    inv_l3.resize(to.size());
    q_inverse.resize(count);
    detail::parallel_for(count, threads, 1 << 14, [&](std::size_t first_v, std::size_t last_v) {
      for (std::size_t v = first_v; v < last_v; ++v) {
        double q00 = 0, q01 = 0, q11 = 0;
        for (std::uint32_t j = offset[v]; j < offset[v + 1]; ++j) {
          const double ex = at[to[j]].x - at[v].x, ey = at[to[j]].y - at[v].y, l2 = ex * ex + ey * ey;
          inv_l3[j] = 1 / (l2 * std::sqrt(l2));
          q00 += 4 * ex * ex * inv_l3[j], q01 += 4 * ex * ey * inv_l3[j], q11 += 4 * ey * ey * inv_l3[j];
        }
        const double det = q00 * q11 - q01 * q01;
        q_inverse[v] = det != 0 && std::isfinite(det) ? std::array<double, 3>{q11 / det, -q01 / det, q00 / det}
                                                      : std::array<double, 3>{NAN, NAN, NAN};
      }
    });
    colour();
  }

  // Greedy colouring in vertex order: each vertex the least colour none of its coloured
  // neighbours has (a planar graph's take a handful).
  void colour() {
    const std::size_t count = at.size();
    std::vector<std::uint8_t> c(count, 0xff);
    std::size_t colours = 0;
    for (std::size_t v = 0; v < count; ++v) {
      std::uint64_t taken = 0;
      for (std::uint32_t j = offset[v]; j < offset[v + 1]; ++j)
        if (c[to[j]] < 64) taken |= std::uint64_t{1} << c[to[j]];
      int least = 0;
      while (taken >> least & 1) ++least;
      c[v] = static_cast<std::uint8_t>(least);
      colours = std::max<std::size_t>(colours, least + 1);
    }
    first.assign(colours + 1, 0);
    for (std::size_t v = 0; v < count; ++v) ++first[c[v] + 1];
    for (std::size_t k = 0; k < colours; ++k) first[k + 1] += first[k];
    by_colour.resize(count);
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::size_t v = 0; v < count; ++v) by_colour[fill[c[v]]++] = static_cast<std::uint32_t>(v);
  }

  // One Gauss-Seidel sweep, a colour at a time, each colour's vertices on threads: each
  // vertex's gradient set to the one that minimises its edges' curvature given its
  // neighbours' (Q g = sum (6 (f_w - f_v) - 2 e.g_w) e / L^3). The same numbers for every
  // thread count. Returns the largest change, relative to the gradient where that exceeds 1.
  double sweep(std::vector<Node>& node, unsigned threads) const {
    double worst = 0;
    std::mutex merge;
    for (std::size_t c = 0; c + 1 < first.size(); ++c)
      detail::parallel_for(first[c + 1] - first[c], threads, 1 << 13, [&](std::size_t from, std::size_t until) {
        double most = 0;
        for (std::size_t k = first[c] + from; k < first[c] + until; ++k)
          most = std::max(most, update(by_colour[k], node));
        const std::lock_guard<std::mutex> lock(merge);
        worst = std::max(worst, most);
      });
    return worst;
  }

  // The start of the sweeps: at each vertex the plane that fits its neighbours' values best,
  // each edge weighted 1 / L^3 as in Q (exact for linear data, which then need no sweep).
  // The sweeps reach the same minimum from it as from zero (scipy's start), in fewer sweeps.
  void start(std::vector<Node>& node, unsigned threads) const {
    detail::parallel_for(node.size(), threads, 1 << 14, [&](std::size_t first_v, std::size_t last_v) {
      for (std::size_t v = first_v; v < last_v; ++v) {
        const std::array<double, 3>& q = q_inverse[v];
        if (std::isnan(q[0])) continue;
        double s0 = 0, s1 = 0;
        for (std::uint32_t j = offset[v]; j < offset[v + 1]; ++j) {
          const double ex = at[to[j]].x - at[v].x, ey = at[to[j]].y - at[v].y;
          const double r = 4 * (node[to[j]].f - node[v].f) * inv_l3[j];
          s0 += r * ex, s1 += r * ey;
        }
        node[v].gx = q[0] * s0 + q[1] * s1, node[v].gy = q[1] * s0 + q[2] * s1;
      }
    });
  }

  double update(std::uint32_t v, std::vector<Node>& node) const {
    const std::array<double, 3>& q = q_inverse[v];
    if (std::isnan(q[0])) return 0;
    const Point p = at[v];
    const double f = node[v].f;
    double s0 = 0, s1 = 0;
    for (std::uint32_t j = offset[v]; j < offset[v + 1]; ++j) {
      const Node& w = node[to[j]];
      const double ex = at[to[j]].x - p.x, ey = at[to[j]].y - p.y;
      const double r = (6 * (w.f - f) - 2 * (ex * w.gx + ey * w.gy)) * inv_l3[j];
      s0 += r * ex, s1 += r * ey;
    }
    const double gx = q[0] * s0 + q[1] * s1, gy = q[1] * s0 + q[2] * s1;
    Node& u = node[v];
    const double change =
        std::max(std::fabs(u.gx - gx), std::fabs(u.gy - gy)) / std::max(1.0, std::max(std::fabs(gx), std::fabs(gy)));
    u.gx = gx, u.gy = gy;
    return change;
  }

  static constexpr std::uint32_t kNone = ~std::uint32_t{0};
};

}  // namespace

int estimate_gradients(std::span<const Point> points, const Triangulation& t, Values values,
                       std::span<double> gradients, double tol, int maxiter, unsigned threads) {
  detail::check_arrays("estimate_gradients", points.size(), t.triangles, t.neighbors);
  detail::check_values("estimate_gradients", points.size(), values);
  const std::size_t n = points.size(), m = values.components;
  if (gradients.size() != 2 * n * m)
    throw InputError("estimate_gradients: room for " + std::to_string(gradients.size()) + " numbers, not " +
                     std::to_string(2 * n * m));
  if (!(tol > 0)) throw InputError("estimate_gradients: tol must be positive");
  if (maxiter < 1) throw InputError("estimate_gradients: maxiter must be at least 1");
  std::fill(gradients.begin(), gradients.end(), 0.0);
  const Network net(points, t, threads);
  const std::size_t count = net.order.size();
  std::vector<Node> node(count);
  int most = 0;
  bool converged = true;
  for (std::size_t k = 0; k < m; ++k) {
    for (std::size_t v = 0; v < count; ++v) node[v] = {values.data[net.order[v] * m + k], 0, 0};
    net.start(node, threads);
    int done = 0;
    for (int sweep = 1; sweep <= maxiter && done == 0; ++sweep)
      if (net.sweep(node, threads) < tol) done = sweep;
    converged = converged && done > 0;
    most = std::max(most, done);
    for (std::size_t v = 0; v < count; ++v) {
      gradients[2 * (net.order[v] * m + k)] = node[v].gx;
      gradients[2 * (net.order[v] * m + k) + 1] = node[v].gy;
    }
  }
  for (const Duplicate& d : t.duplicates) std::copy_n(&gradients[2 * d.kept * m], 2 * m, &gradients[2 * d.dropped * m]);
  return converged ? most : 0;
}

namespace {

// The values and gradients side by side, a point's k values and then its 2k gradient numbers,
// as the field carries them through the renumbering.
std::vector<double> values_and_gradients(const char* who, std::size_t n, Values values,
                                         std::span<const double> gradients) {
  detail::check_values(who, n, values);
  const std::size_t m = values.components;
  if (gradients.size() != 2 * n * m)
    throw InputError(std::string(who) + ": " + std::to_string(gradients.size()) + " gradient numbers for " +
                     std::to_string(n) + " points of " + std::to_string(m) + " components (2 each)");
  std::vector<double> both(3 * n * m);
  for (std::size_t v = 0; v < n; ++v) {
    std::copy_n(&values.data[v * m], m, &both[3 * v * m]);
    std::copy_n(&gradients[2 * v * m], 2 * m, &both[3 * v * m + m]);
  }
  return both;
}

}  // namespace

void interpolate_clough_tocher(std::span<const Point> points, const Triangulation& t, Values values,
                               std::span<const double> gradients, std::span<const Point> queries, std::span<double> out,
                               double fill, unsigned threads) {
  const char* who = "interpolate_clough_tocher";
  const std::vector<double> both = values_and_gradients(who, points.size(), values, gradients);
  detail::interpolate<CloughTocher>(who, points, t, Values{both, 3 * values.components}, values.components, queries,
                                    out, fill, threads);
}

void interpolate_clough_tocher(std::span<const Point> points, const Triangulation& t, Values values,
                               std::span<const double> gradients, const Grid& grid, std::span<double> out, double fill,
                               unsigned threads) {
  const char* who = "interpolate_clough_tocher";
  const std::vector<double> both = values_and_gradients(who, points.size(), values, gradients);
  detail::interpolate_grid<CloughTocher>(who, points, t, Values{both, 3 * values.components}, values.components, grid,
                                         out, fill, threads);
}

}  // namespace ridt
