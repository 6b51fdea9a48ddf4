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
#include <string>
#include <vector>

#include "order/order.hpp"
#include "queries/field.hpp"
#include "queries/gradients.hpp"
#include "runtime/memory.hpp"

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

  // `weights`, when given, are q's barycentric coordinates in tri as barycentric gives them,
  // from the corner f.first(tri) (`from`, where the caller has it); so are the corners here.
  void operator()(std::size_t tri, const Point& q, double* out, const double* weights = nullptr, int from = -1) {
    // The turn a compile-time constant: corner[i] below indexes without arithmetic, as the
    // triangles of a renumbered field (all from their first corner) have it.
    switch (from >= 0 ? from : f_.first(tri)) {
      case 0:
        return answer<0>(tri, q, out, weights);
      case 1:
        return answer<1>(tri, q, out, weights);
      default:
        return answer<2>(tri, q, out, weights);
    }
  }

 private:
  // The answer with the triangle read from its stored corner First.
  template <int First>
  void answer(std::size_t tri, const Point& q, double* out, const double* weights) {
    constexpr int corner[3] = {First, (First + 1) % 3, (First + 2) % 3};
    const Point p[3] = {f_.corner(tri, corner[0]), f_.corner(tri, corner[1]), f_.corner(tri, corner[2])};
    double b[3];
    if (weights != nullptr)
      std::copy_n(weights, 3, b);
    else
      detail::barycentric(p[0], p[1], p[2], q, b);
    for (int i = 0; i < 3; ++i)
      if (b[i] == 1) {  // at a corner (exactly: the weights are exact there): its values
        std::copy_n(f_.value(f_.vertex(tri, corner[i])), k_, out);
        return;
      }
    if (tri != tri_) control_points(tri, corner, p);
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

  // The control points of triangle tri, its corners p read from the stored corners `corner`.
  void control_points(std::size_t tri, const int* corner, const Point* p) {
    tri_ = tri;
    const Point c = centroid(p[0], p[1], p[2]);
    // The direction across each side (side i is across from corner i) as barycentric weights
    // of its two ends and the centroid, the same for every component.
    Across across[3];
    const double third = detail::doubled_area(p[0], p[1], p[2]) / 3;
    for (int i = 0; i < 3; ++i) across[i] = direction(f_.neighbor(tri, corner[i]), i, p, c, third);
    const double* value[3] = {f_.value(f_.vertex(tri, corner[0])), f_.value(f_.vertex(tri, corner[1])),
                              f_.value(f_.vertex(tri, corner[2]))};
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

  // The centroid of a triangle's corners from Field::first.
  static Point centroid(const Point& a, const Point& b, const Point& c) {
    return {a.x + ((b.x - a.x) + (c.x - a.x)) / 3, a.y + ((b.y - a.y) + (c.y - a.y)) / 3};
  }

  // Side i runs from A = p[next3(i)] to B = p[prev3(i)]; the direction d towards the centroid
  // of neighbour u across it (on the hull, u < 0, from corner i to the side's midpoint),
  // written d = b (B - A) + c (C - A). The determinant `det` is a third of the triangle's
  // doubled area, within 2^-50 of the exact one, so that a sliver still gets finite weights.
  Across direction(std::int32_t u, int i, const Point* p, const Point& c, double det) const {
    const Point& a = p[next3(i)];
    const Point& e = p[prev3(i)];
    Point d;
    if (u >= 0) {
      const auto n = static_cast<std::size_t>(u);
      const int s = f_.first(n);
      const Point o = centroid(f_.corner(n, s), f_.corner(n, next3(s)), f_.corner(n, prev3(s)));
      d = {o.x - c.x, o.y - c.y};
    } else {
      d = {(a.x - p[i].x) + (e.x - p[i].x), (a.y - p[i].y) + (e.y - p[i].y)};
    }
    const double e1x = e.x - a.x, e1y = e.y - a.y, e2x = c.x - a.x, e2y = c.y - a.y;
    const double wb = (d.x * e2y - d.y * e2x) / det, wc = (e1x * d.y - e1y * d.x) / det;
    return {-wb - wc, wb, wc};
  }

  const Field& f_;
  std::size_t k_;
  std::vector<Net> net_;
  std::size_t tri_ = ~std::size_t{0};  // the triangle net_ is for
};

// What griddata_cubic lets the memory cache keep beyond its limit while it runs, a point and
// component: more than its sweeps' blocks (some 130 bytes a point for one component).
constexpr std::size_t kReuseBytesPerPoint = 160;
// And more, a point, where it triangulates the points itself: the triangulation's blocks.
constexpr std::size_t kTriangulationBytesPerPoint = 64;

// The values and gradients side by side, a point's k values and then its 2k gradient numbers,
// as the field carries them through the renumbering: 3 n k numbers, each written on threads (a
// block, not a vector zeroed first on one thread).
detail::Block<double> values_and_gradients(const char* who, std::size_t n, Values values,
                                           std::span<const double> gradients, unsigned threads) {
  detail::check_values(who, n, values);
  const std::size_t m = values.components;
  if (gradients.size() != 2 * n * m)
    throw InputError(std::string(who) + ": " + std::to_string(gradients.size()) + " gradient numbers for " +
                     std::to_string(n) + " points of " + std::to_string(m) + " components (2 each)");
  detail::Block<double> both = detail::allocate_huge<double>(3 * n * m);
  detail::parallel_for(n, threads, detail::kGrain, [&](std::size_t first, std::size_t last) {
    for (std::size_t v = first; v < last; ++v) {
      std::copy_n(&values.data[v * m], m, &both[3 * v * m]);
      std::copy_n(&gradients[2 * v * m], 2 * m, &both[3 * v * m + m]);
    }
  });
  return both;
}

}  // namespace

void interpolate_clough_tocher(std::span<const Point> points, const Triangulation& t, Values values,
                               std::span<const double> gradients, std::span<const Point> queries, std::span<double> out,
                               double fill, unsigned threads, double hull_tolerance) {
  const char* who = "interpolate_clough_tocher";
  const detail::Block<double> both = values_and_gradients(who, points.size(), values, gradients, threads);
  const std::size_t width = 3 * values.components;
  detail::interpolate<CloughTocher>(who, points, t, Values{{both.get(), points.size() * width}, width},
                                    values.components, queries, out, fill, threads, hull_tolerance);
}

void interpolate_clough_tocher(std::span<const Point> points, const Triangulation& t, Values values,
                               std::span<const double> gradients, const Grid& grid, std::span<double> out, double fill,
                               unsigned threads, double hull_tolerance) {
  const char* who = "interpolate_clough_tocher";
  const detail::Block<double> both = values_and_gradients(who, points.size(), values, gradients, threads);
  const std::size_t width = 3 * values.components;
  detail::interpolate_grid<CloughTocher>(who, points, t, Values{{both.get(), points.size() * width}, width},
                                         values.components, grid, out, fill, threads, hull_tolerance);
}

namespace {

// griddata_cubic's gradients and answers on the renumbered field.
int cubic_on_grid(const detail::Renumbered& field, const detail::Axis& ax, const detail::Axis& ay, const Grid& grid,
                  std::span<double> out, double fill, double tol, int maxiter, unsigned threads,
                  double hull_tolerance) {
  const std::size_t n = field.count, m = field.components;
  const detail::Block<double> grad = detail::allocate_huge<double>(2 * n * m);
  const int sweeps = detail::solve_gradients(field, tol, maxiter, threads, {grad.get(), 2 * n * m});
  // Each point's values and then its gradients, in the field's numbering.
  const detail::Block<double> both = values_and_gradients("griddata_cubic", n, Values{{field.values.get(), n * m}, m},
                                                          {grad.get(), 2 * n * m}, threads);
  detail::answer_grid<CloughTocher>(field.field({both.get(), 3 * n * m}, 3 * m), ax, ay, grid, m, out, fill, threads,
                                    hull_tolerance);
  return sweeps;
}

}  // namespace

int griddata_cubic(std::span<const Point> points, const Triangulation& t, Values values, const Grid& grid,
                   std::span<double> out, double fill, double tol, int maxiter, unsigned threads,
                   double hull_tolerance) {
  const char* who = "griddata_cubic";
  const detail::Axis ax(who, "x", grid.x), ay(who, "y", grid.y);
  detail::check_arrays(who, points.size(), t.triangles, t.neighbors);
  detail::check_values(who, points.size(), values);
  detail::check_room(who, out, grid.size(), "nodes", values.components);
  detail::check_sweeps(who, tol, maxiter);
  if (t.triangles.empty()) {
    std::fill(out.begin(), out.end(), fill);
    return 1;
  }
  // The sweeps' blocks, given back, hold the answers' values and gradients after.
  const MemoryReuse reuse(kReuseBytesPerPoint * points.size() * values.components);
  const detail::Renumbered field({points, t.triangles, t.neighbors, values}, threads);
  return cubic_on_grid(field, ax, ay, grid, out, fill, tol, maxiter, threads, hull_tolerance);
}

int griddata_cubic(std::span<const Point> points, Values values, const Grid& grid, std::span<double> out, double fill,
                   double tol, int maxiter, unsigned threads, double hull_tolerance) {
  const char* who = "griddata_cubic";
  threads = detail::thread_count(threads);
  const detail::Axis ax(who, "x", grid.x), ay(who, "y", grid.y);
  detail::check_values(who, points.size(), values);
  detail::check_room(who, out, grid.size(), "nodes", values.components);
  detail::check_sweeps(who, tol, maxiter);
  // The triangulation's refusals (too many points, one that is not finite) before the points
  // are ordered.
  Options options;
  options.method = Method::Auto;
  options.threads = threads;
  estimate_memory(points.size(), options);
  detail::checked_extent(points, threads);
  // The triangulation's blocks, given back, serve the sweeps'; theirs the answers'.
  const MemoryReuse reuse((kReuseBytesPerPoint * values.components + kTriangulationBytesPerPoint) * points.size());
  const detail::Renumbered field(points, values, options);
  if (field.triangle_count == 0) {
    std::fill(out.begin(), out.end(), fill);
    return -1;
  }
  return cubic_on_grid(field, ax, ay, grid, out, fill, tol, maxiter, threads, hull_tolerance);
}

}  // namespace ridt
