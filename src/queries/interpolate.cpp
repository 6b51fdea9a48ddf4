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
#include "queries/sibson.hpp"

namespace ridt {
namespace {

using detail::Field;
using detail::kGrain;
using detail::Linear;
using detail::Natural;
using detail::next3;
using detail::prev3;

}  // namespace

void interpolate_linear(std::span<const Point> points, const Triangulation& t, Values values,
                        std::span<const Point> queries, std::span<double> out, double fill, unsigned threads,
                        double hull_tolerance) {
  detail::interpolate<Linear>("interpolate_linear", points, t, values, values.components, queries, out, fill, threads,
                              hull_tolerance);
}

void interpolate_natural_neighbor(std::span<const Point> points, const Triangulation& t, Values values,
                                  std::span<const Point> queries, std::span<double> out, double fill, unsigned threads,
                                  double hull_tolerance) {
  detail::interpolate<Natural>("interpolate_natural_neighbor", points, t, values, values.components, queries, out, fill,
                               threads, hull_tolerance);
}

void interpolate_linear(std::span<const Point> points, const Triangulation& t, Values values, const Grid& grid,
                        std::span<double> out, double fill, unsigned threads, double hull_tolerance) {
  detail::interpolate_grid<Linear>("interpolate_linear", points, t, values, values.components, grid, out, fill, threads,
                                   hull_tolerance);
}

void interpolate_natural_neighbor(std::span<const Point> points, const Triangulation& t, Values values,
                                  const Grid& grid, std::span<double> out, double fill, unsigned threads,
                                  double hull_tolerance) {
  detail::interpolate_grid<Natural>("interpolate_natural_neighbor", points, t, values, values.components, grid, out,
                                    fill, threads, hull_tolerance);
}

std::vector<double> interpolate_linear(std::span<const Point> points, const Triangulation& t, Values values,
                                       std::span<const Point> queries, double fill, unsigned threads,
                                       double hull_tolerance) {
  std::vector<double> out(queries.size() * values.components);
  interpolate_linear(points, t, values, queries, out, fill, threads, hull_tolerance);
  return out;
}

std::vector<double> interpolate_natural_neighbor(std::span<const Point> points, const Triangulation& t, Values values,
                                                 std::span<const Point> queries, double fill, unsigned threads,
                                                 double hull_tolerance) {
  std::vector<double> out(queries.size() * values.components);
  interpolate_natural_neighbor(points, t, values, queries, out, fill, threads, hull_tolerance);
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
