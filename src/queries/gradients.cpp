// The gradients the cubic interpolant takes (ridt/interpolate.hpp estimate_gradients): those
// that minimise the squared second derivative, along every Delaunay edge, of the cubic that the
// values and gradients at its ends define (Nielson's minimum-norm network), solved by
// Gauss-Seidel sweeps as scipy's estimate_gradients_2d_global does.
//
// At a vertex v with neighbours w, edges e = w - v of length L, the best gradient given the
// neighbours' solves Q g_v = b_v - sum_w (2 / L^3) e e^T g_w, where Q = sum 4 e e^T / L^3 and
// b_v = sum 6 (f_w - f_v) e / L^3. Q and b are fixed by the points and the values, so a sweep
// reads, for each edge, only the neighbour's gradient and u = e sqrt(2 / L^3), whose outer
// product is the edge's term.
#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include "order/order.hpp"
#include "queries/field.hpp"
#include "runtime/memory.hpp"

namespace ridt {
namespace {

using detail::next3;
using detail::prev3;

using Pair = std::array<double, 2>;

constexpr std::uint32_t kNone = ~std::uint32_t{0};

// The Delaunay graph numbered for locality, its vertices along the Hilbert curve (the points
// may come in any order; neighbours along the curve are mostly near in memory), each vertex's
// neighbours once each; across each hull side, the direction the one triangle misses. A
// point in no triangle (a dropped duplicate) has none.
struct Graph {
  std::vector<VertexId> input;  // number -> input index
  std::vector<std::uint32_t> offset, to;

  Graph(std::span<const Point> points, const Triangulation& t, unsigned threads)
      : input(detail::hilbert_cells_order(points.data(), static_cast<std::uint32_t>(points.size()), threads)) {
    const std::size_t count = input.size();
    std::vector<std::uint32_t> id(count);
    for (std::size_t v = 0; v < count; ++v) id[input[v]] = static_cast<std::uint32_t>(v);
    std::vector<std::uint32_t> tri(t.triangles.size());
    detail::parallel_for(tri.size(), threads, 1 << 16, [&](std::size_t from, std::size_t until) {
      for (std::size_t k = from; k < until; ++k) tri[k] = id[t.triangles[k]];
    });
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
  }

  std::size_t size() const { return input.size(); }

  // Greedy colours in this order: each vertex the least colour none of its coloured
  // neighbours has (a planar graph's take a handful).
  std::vector<std::uint8_t> colours() const {
    std::vector<std::uint8_t> c(size(), 0xff);
    for (std::size_t v = 0; v < size(); ++v) {
      std::uint64_t taken = 0;
      for (std::uint32_t j = offset[v]; j < offset[v + 1]; ++j)
        if (c[to[j]] < 64) taken |= std::uint64_t{1} << c[to[j]];
      int least = 0;
      while (taken >> least & 1) ++least;
      c[v] = static_cast<std::uint8_t>(least);
    }
    return c;
  }
};

// The minimum-norm network's system, its vertices renumbered by colour (no two neighbours of
// one colour, so that a colour's vertices can be updated at once on threads), in the graph's
// order within a colour: a colour's vertices and their edges lie together in memory, and a
// sweep over them reads the other colours' gradients in order. Colour c is
// [first[c], first[c + 1]). The numbering follows the triangles alone, so the sweeps give the
// same numbers on any thread count.
struct Network {
  std::vector<VertexId> input;  // number -> input index
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> offset, to;
  detail::Block<Pair> u;  // an edge's e sqrt(2 / L^3)
  detail::Block<std::array<double, 3>> q_inverse;  // [[a b] [b c]]; NaN where Q is singular
  detail::Block<Pair> b;  // component k's b_v at b[k * size() + v]

  Network(std::span<const Point> points, const Graph& g, Values values, unsigned threads)
      : input(g.size()),
        offset(g.size() + 1),
        q_inverse(detail::allocate_huge<std::array<double, 3>>(g.size())),
        b(detail::allocate_huge<Pair>(g.size() * values.components)) {
    const std::size_t count = g.size(), m = values.components;
    const std::vector<std::uint8_t> colour = g.colours();
    first.assign(*std::max_element(colour.begin(), colour.end()) + 2u, 0);
    for (std::uint8_t c : colour) ++first[c + 1];
    for (std::size_t c = 0; c + 1 < first.size(); ++c) first[c + 1] += first[c];
    std::vector<std::uint32_t> number(count), fill(first.begin(), first.end() - 1);
    for (std::size_t v = 0; v < count; ++v) number[v] = fill[colour[v]]++;
    // The points and values in the new order, read once each, so that the edges read them
    // near in memory.
    std::vector<std::uint32_t> local(count);  // number -> the graph's
    std::vector<Point> at;
    std::vector<double> f;
    detail::resize_present(at, count, threads);
    detail::resize_present(f, count * m, threads);
    detail::parallel_for(count, threads, 1 << 14, [&](std::size_t from, std::size_t until) {
      for (std::size_t v = from; v < until; ++v) {
        const std::uint32_t w = number[v];
        local[w] = static_cast<std::uint32_t>(v);
        input[w] = g.input[v];
        offset[w + 1] = g.offset[v + 1] - g.offset[v];
        at[w] = points[g.input[v]];
        std::copy_n(&values.data[g.input[v] * m], m, &f[w * m]);
      }
    });
    for (std::size_t v = 0; v < count; ++v) offset[v + 1] += offset[v];
    detail::resize_present(to, offset[count], threads);
    u = detail::allocate_huge<Pair>(offset[count]);
    detail::parallel_for(count, threads, 1 << 14, [&](std::size_t from, std::size_t until) {
      for (std::size_t v = from; v < until; ++v) {
        std::uint32_t j = offset[v];
        for (std::uint32_t i = g.offset[local[v]]; i < g.offset[local[v] + 1]; ++i) to[j++] = number[g.to[i]];
        equations(at, f, m, v);
      }
    });
  }

  std::size_t size() const { return input.size(); }

  // Vertex v's edges' u, its Q's inverse and its b for each of the m components.
  void equations(const std::vector<Point>& at, const std::vector<double>& f, std::size_t m, std::size_t v) {
    double q00 = 0, q01 = 0, q11 = 0;
    for (std::size_t k = 0; k < m; ++k) b[k * size() + v] = {0, 0};
    for (std::uint32_t j = offset[v]; j < offset[v + 1]; ++j) {
      const std::uint32_t w = to[j];
      const double ex = at[w].x - at[v].x, ey = at[w].y - at[v].y, l2 = ex * ex + ey * ey;
      const double inv_l3 = 1 / (l2 * std::sqrt(l2)), root = std::sqrt(2 * inv_l3);
      u[j] = {ex * root, ey * root};
      q00 += 4 * ex * ex * inv_l3, q01 += 4 * ex * ey * inv_l3, q11 += 4 * ey * ey * inv_l3;
      for (std::size_t k = 0; k < m; ++k) {
        const double r = 6 * (f[w * m + k] - f[v * m + k]) * inv_l3;
        Pair& s = b[k * size() + v];
        s[0] += r * ex, s[1] += r * ey;
      }
    }
    const double det = q00 * q11 - q01 * q01;
    q_inverse[v] = det != 0 && std::isfinite(det) ? std::array<double, 3>{q11 / det, -q01 / det, q00 / det}
                                                  : std::array<double, 3>{NAN, NAN, NAN};
  }

  // The start of the sweeps: at each vertex the plane that fits its neighbours' values best,
  // each edge weighted 1 / L^3 as in Q (Q g = 2/3 b; exact for linear data, which then need
  // no sweep). The sweeps reach the same minimum from it as from zero (scipy's start), in
  // fewer sweeps. Where Q is singular the gradient stays zero.
  void start(std::span<const Pair> bk, std::vector<Pair>& grad, unsigned threads) const {
    detail::parallel_for(size(), threads, 1 << 14, [&](std::size_t from, std::size_t until) {
      for (std::size_t v = from; v < until; ++v) {
        const std::array<double, 3>& q = q_inverse[v];
        const double s0 = bk[v][0] * 2 / 3, s1 = bk[v][1] * 2 / 3;
        grad[v] = std::isnan(q[0]) ? Pair{0, 0} : Pair{q[0] * s0 + q[1] * s1, q[1] * s0 + q[2] * s1};
      }
    });
  }

  // One Gauss-Seidel sweep, a colour at a time, each colour's vertices on threads. Returns the
  // largest change, relative to the gradient where that exceeds 1.
  double sweep(std::span<const Pair> bk, std::vector<Pair>& grad, unsigned threads) const {
    double worst = 0;
    std::mutex merge;
    for (std::size_t c = 0; c + 1 < first.size(); ++c)
      detail::parallel_for(first[c + 1] - first[c], threads, 1 << 13, [&](std::size_t from, std::size_t until) {
        double most = 0;
        for (std::size_t v = first[c] + from; v < first[c] + until; ++v) most = std::max(most, update(v, bk, grad));
        const std::lock_guard<std::mutex> lock(merge);
        worst = std::max(worst, most);
      });
    return worst;
  }

  double update(std::size_t v, std::span<const Pair> bk, std::vector<Pair>& grad) const {
    const std::array<double, 3>& q = q_inverse[v];
    if (std::isnan(q[0])) return 0;
    double s0 = bk[v][0], s1 = bk[v][1];
    for (std::uint32_t j = offset[v]; j < offset[v + 1]; ++j) {
      const Pair& w = grad[to[j]];
      const double d = u[j][0] * w[0] + u[j][1] * w[1];
      s0 -= d * u[j][0], s1 -= d * u[j][1];
    }
    const double gx = q[0] * s0 + q[1] * s1, gy = q[1] * s0 + q[2] * s1;
    Pair& g = grad[v];
    const double change =
        std::max(std::fabs(g[0] - gx), std::fabs(g[1] - gy)) / std::max(1.0, std::max(std::fabs(gx), std::fabs(gy)));
    g = {gx, gy};
    return change;
  }
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
  if (t.triangles.empty()) return 1;
  const Network net(points, Graph(points, t, threads), values, threads);
  const std::size_t count = net.size();
  std::vector<Pair> grad(count);
  int most = 0;
  bool converged = true;
  for (std::size_t k = 0; k < m; ++k) {
    const std::span<const Pair> bk(&net.b[k * count], count);
    net.start(bk, grad, threads);
    int done = 0;
    for (int sweep = 1; sweep <= maxiter && done == 0; ++sweep)
      if (net.sweep(bk, grad, threads) < tol) done = sweep;
    converged = converged && done > 0;
    most = std::max(most, done);
    detail::parallel_for(count, threads, 1 << 14, [&](std::size_t from, std::size_t until) {
      for (std::size_t v = from; v < until; ++v) std::copy_n(grad[v].data(), 2, &gradients[2 * (net.input[v] * m + k)]);
    });
  }
  for (const Duplicate& d : t.duplicates) std::copy_n(&gradients[2 * d.kept * m], 2 * m, &gradients[2 * d.dropped * m]);
  return converged ? most : 0;
}

}  // namespace ridt
