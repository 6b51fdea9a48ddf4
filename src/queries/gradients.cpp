// The gradients the cubic interpolant takes (ridt/interpolate.hpp estimate_gradients): those
// that minimise the squared second derivative, along every Delaunay edge, of the cubic that the
// values and gradients at its ends define (Nielson's minimum-norm network), solved by
// Gauss-Seidel sweeps as scipy's estimate_gradients_2d_global does.
//
// At a vertex v with neighbours w, edges e = w - v of length L, the best gradient given the
// neighbours' solves Q g_v = b_v - sum_w (2 / L^3) e e^T g_w, where Q = sum 4 e e^T / L^3 and
// b_v = sum 6 (f_w - f_v) e / L^3. Q and b are fixed by the points and the values, so a sweep
// reads, for each edge, the neighbour's gradient and point and the edge's 2 / L^3.
#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "queries/gradients.hpp"

#include "order/order.hpp"
#include "queries/field.hpp"
#include "runtime/memory.hpp"

namespace ridt {
namespace {

using detail::next3;
using detail::prev3;

using Pair = std::array<double, 2>;

// The Delaunay graph on the renumbered field's vertices (along the Hilbert curve, so that
// neighbours are mostly near in memory), each vertex's neighbours once each, in order; across each hull
// side, the direction the one triangle misses. A point in no triangle (a dropped duplicate)
// has none. Its arrays are blocks written on threads, not vectors zeroed on one: at 10^6
// points some 36 MB of fresh pages, each faulted in by the thread that first writes it.
struct Graph {
  detail::Block<std::uint32_t> offset, to;
  std::size_t edges = 0;

  // Each of up to four parts of the triangles counts its corners a vertex, then writes its
  // edges after those of the parts before it; each list is sorted last.
  Graph(const detail::Field& f, unsigned threads) {
    const std::size_t count = f.points.size(), triangles = f.triangles.size() / 3;
    const auto parts = static_cast<unsigned>(std::clamp<std::size_t>(triangles >> 16, 1, std::min(threads, 4u)));
    auto each = [&](unsigned p, auto&& visit) {
      for (std::size_t k = triangles * p / parts; k < triangles * (p + 1) / parts; ++k)
        for (int i = 0; i < 3; ++i) {
          const std::uint32_t next = f.vertex(k, next3(i));
          visit(f.vertex(k, i), next);
          if (f.neighbor(k, i) < 0) visit(f.vertex(k, prev3(i)), next);
        }
    };
    // Part p's count, then place, for vertex v: at[p * count + v].
    const detail::Block<std::uint32_t> at = detail::allocate_huge<std::uint32_t>(parts * count);
    detail::parallel_for(parts * count, threads, 1 << 16,
                         [&](std::size_t from, std::size_t until) { std::fill(&at[from], &at[0] + until, 0u); });
    detail::on_threads(parts,
                       [&](unsigned p) { each(p, [&](std::uint32_t v, std::uint32_t) { ++at[p * count + v]; }); });
    offset = detail::allocate_huge<std::uint32_t>(count + 1);
    offset[0] = 0;
    detail::parallel_for(count, threads, 1 << 16, [&](std::size_t from, std::size_t until) {
      for (std::size_t v = from; v < until; ++v) {
        std::uint32_t sum = 0;
        for (unsigned p = 0; p < parts; ++p) sum += at[p * count + v];
        offset[v + 1] = sum;
      }
    });
    for (std::size_t v = 0; v < count; ++v) offset[v + 1] += offset[v];
    detail::parallel_for(count, threads, 1 << 16, [&](std::size_t from, std::size_t until) {
      for (std::size_t v = from; v < until; ++v)
        for (std::uint32_t p = 0, place = offset[v]; p < parts; ++p) place += std::exchange(at[p * count + v], place);
    });
    edges = offset[count];
    to = detail::allocate_huge<std::uint32_t>(edges);
    detail::on_threads(
        parts, [&](unsigned p) { each(p, [&](std::uint32_t v, std::uint32_t w) { to[at[p * count + v]++] = w; }); });
    // Each list in vertex order: the sums over it then come in an order that the triangles as a
    // set fix, not their places in the array (which a threaded triangulation's run decides).
    detail::parallel_for(count, threads, 1 << 14, [&](std::size_t from, std::size_t until) {
      for (std::size_t v = from; v < until; ++v) std::sort(&to[offset[v]], &to[0] + offset[v + 1]);
    });
  }
};

// The minimum-norm network's system on the graph's numbering, its vertices cut into blocks of
// kBlock along the curve (compact pieces of the plane) and the blocks coloured so that no
// edge joins two blocks of one colour. A sweep takes the colours one after another and the
// blocks of a colour on threads at once, each block's vertices in order: Gauss-Seidel in an
// order that depends on the triangles alone, so the same numbers on any thread count, with a
// block's gradients in cache while its vertices read one another's.
struct Network {
  static constexpr std::size_t kBlock = 2048;

  std::size_t count;
  detail::Block<std::uint32_t> offset, to;
  const Point* at;  // the field's points
  detail::Block<double> weight;  // an edge's 2 / L^3
  detail::Block<std::array<double, 3>> q_inverse;  // [[a b] [b c]]; NaN where Q is singular
  detail::Block<Pair> b;  // component k's b_v at b[k * size() + v]
  std::vector<std::uint32_t> blocks, first;  // colour c's blocks: blocks[first[c] .. first[c + 1])

  Network(const detail::Field& f, Graph&& g, unsigned threads)
      : count(f.points.size()),
        offset(std::move(g.offset)),
        to(std::move(g.to)),
        at(f.points.data()),
        weight(detail::allocate_huge<double>(g.edges)),
        q_inverse(detail::allocate_huge<std::array<double, 3>>(count)),
        b(detail::allocate_huge<Pair>(count * f.values.components)) {
    detail::parallel_for(count, threads, 1 << 14, [&](std::size_t from, std::size_t until) {
      for (std::size_t v = from; v < until; ++v) equations(f, v);
    });
    colour_blocks(threads);
  }

  std::size_t size() const { return count; }
  std::size_t block_count() const { return (size() + kBlock - 1) / kBlock; }

  // Greedy colours for the blocks in order: each the least colour none of its coloured
  // neighbours has. Each block's neighbours are found on threads.
  void colour_blocks(unsigned threads) {
    const std::size_t nb = block_count();
    std::vector<std::vector<std::uint32_t>> near(nb);
    detail::parallel_for(nb, threads, 1, [&](std::size_t from, std::size_t until) {
      for (std::size_t k = from; k < until; ++k) {
        for (std::size_t j = offset[k * kBlock]; j < offset[std::min(size(), (k + 1) * kBlock)]; ++j)
          if (to[j] / kBlock != k) near[k].push_back(static_cast<std::uint32_t>(to[j] / kBlock));
        std::sort(near[k].begin(), near[k].end());
        near[k].erase(std::unique(near[k].begin(), near[k].end()), near[k].end());
      }
    });
    std::vector<std::uint32_t> colour(nb, ~0u);
    std::uint32_t colours = 0;
    for (std::size_t k = 0; k < nb; ++k) {
      std::vector<bool> taken(colours + 1, false);
      for (const std::uint32_t o : near[k])
        if (colour[o] != ~0u) taken[colour[o]] = true;
      colour[k] = static_cast<std::uint32_t>(std::find(taken.begin(), taken.end(), false) - taken.begin());
      colours = std::max(colours, colour[k] + 1);
    }
    first.assign(colours + 1, 0);
    for (const std::uint32_t c : colour) ++first[c + 1];
    for (std::size_t c = 0; c < colours; ++c) first[c + 1] += first[c];
    blocks.resize(nb);
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::size_t k = 0; k < nb; ++k) blocks[fill[colour[k]]++] = static_cast<std::uint32_t>(k);
  }

  // Vertex v's edges' weights, its Q's inverse and its b for each of the m components.
  void equations(const detail::Field& field, std::size_t v) {
    const double* f = field.values.data.data();
    const std::size_t m = field.values.components;
    double q00 = 0, q01 = 0, q11 = 0;
    for (std::size_t k = 0; k < m; ++k) b[k * size() + v] = {0, 0};
    for (std::uint32_t j = offset[v]; j < offset[v + 1]; ++j) {
      const std::uint32_t w = to[j];
      const double ex = at[w].x - at[v].x, ey = at[w].y - at[v].y, l2 = ex * ex + ey * ey;
      const double inv_l3 = 1 / (l2 * std::sqrt(l2));
      weight[j] = 2 * inv_l3;
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
  void start(std::span<const Pair> bk, std::span<Pair> grad, unsigned threads) const {
    detail::parallel_for(size(), threads, 1 << 14, [&](std::size_t from, std::size_t until) {
      for (std::size_t v = from; v < until; ++v) {
        const std::array<double, 3>& q = q_inverse[v];
        const double s0 = bk[v][0] * 2 / 3, s1 = bk[v][1] * 2 / 3;
        grad[v] = std::isnan(q[0]) ? Pair{0, 0} : Pair{q[0] * s0 + q[1] * s1, q[1] * s0 + q[2] * s1};
      }
    });
  }

  // One Gauss-Seidel sweep, a colour at a time, each colour's blocks on threads. Returns the
  // largest change, relative to the gradient where that exceeds 1.
  double sweep(std::span<const Pair> bk, std::span<Pair> grad, unsigned threads) const {
    double worst = 0;
    std::mutex merge;
    for (std::size_t c = 0; c + 1 < first.size(); ++c)
      detail::parallel_for(first[c + 1] - first[c], threads, 1, [&](std::size_t from, std::size_t until) {
        double most = 0;
        for (std::size_t k = first[c] + from; k < first[c] + until; ++k) {
          const std::size_t block = blocks[k];
          for (std::size_t v = block * kBlock; v < std::min(size(), (block + 1) * kBlock); ++v)
            most = std::max(most, update(v, bk, grad));
        }
        const std::lock_guard<std::mutex> lock(merge);
        worst = std::max(worst, most);
      });
    return worst;
  }

  double update(std::size_t v, std::span<const Pair> bk, std::span<Pair> grad) const {
    const std::array<double, 3>& q = q_inverse[v];
    if (std::isnan(q[0])) return 0;
    const Point p = at[v];
    double s0 = bk[v][0], s1 = bk[v][1];
    for (std::uint32_t j = offset[v]; j < offset[v + 1]; ++j) {
      const Pair& w = grad[to[j]];
      const double ex = at[to[j]].x - p.x, ey = at[to[j]].y - p.y, d = (ex * w[0] + ey * w[1]) * weight[j];
      s0 -= d * ex, s1 -= d * ey;
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

namespace detail {

int solve_gradients(const Renumbered& field, double tol, int maxiter, unsigned threads, std::span<double> grad) {
  const Field f = field.field();
  const std::size_t count = field.count, m = field.components;
  const Network net(f, Graph(f, threads), threads);
  // Each component's gradients as the sweeps take them, pairs; with one component, that is
  // grad itself (its pairs lie side by side there; each written by start first).
  const detail::Block<Pair> block = m == 1 ? nullptr : detail::allocate_huge<Pair>(count);
  const std::span<Pair> g(m == 1 ? reinterpret_cast<Pair*>(grad.data()) : block.get(), count);
  int most = 0;
  bool converged = true;
  for (std::size_t k = 0; k < m; ++k) {
    const std::span<const Pair> bk(&net.b[k * count], count);
    net.start(bk, g, threads);
    int done = 0;
    for (int sweep = 1; sweep <= maxiter && done == 0; ++sweep)
      if (net.sweep(bk, g, threads) < tol) done = sweep;
    converged = converged && done > 0;
    most = std::max(most, done);
    if (m > 1)
      parallel_for(count, threads, 1 << 14, [&](std::size_t from, std::size_t until) {
        for (std::size_t v = from; v < until; ++v) std::copy_n(g[v].data(), 2, &grad[2 * (v * m + k)]);
      });
  }
  return converged ? most : 0;
}

}  // namespace detail

int estimate_gradients(std::span<const Point> points, const Triangulation& t, Values values,
                       std::span<double> gradients, double tol, int maxiter, unsigned threads) {
  detail::check_arrays("estimate_gradients", points.size(), t.triangles, t.neighbors);
  detail::check_values("estimate_gradients", points.size(), values);
  const std::size_t n = points.size(), m = values.components;
  if (gradients.size() != 2 * n * m)
    throw InputError("estimate_gradients: room for " + std::to_string(gradients.size()) + " numbers, not " +
                     std::to_string(2 * n * m));
  detail::check_sweeps("estimate_gradients", tol, maxiter);
  if (t.triangles.empty()) {
    std::fill(gradients.begin(), gradients.end(), 0.0);
    return 1;
  }
  const detail::Renumbered field({points, t.triangles, t.neighbors, values}, threads);
  const detail::Block<double> grad = detail::allocate_huge<double>(2 * n * m);
  const int sweeps = detail::solve_gradients(field, tol, maxiter, threads, {grad.get(), 2 * n * m});
  detail::parallel_for(n, threads, 1 << 14, [&](std::size_t from, std::size_t until) {
    for (std::size_t v = from; v < until; ++v) std::copy_n(&grad[2 * v * m], 2 * m, &gradients[2 * field.input[v] * m]);
  });
  for (const Duplicate& d : t.duplicates) std::copy_n(&gradients[2 * d.kept * m], 2 * m, &gradients[2 * d.dropped * m]);
  return sweeps;
}

}  // namespace ridt
