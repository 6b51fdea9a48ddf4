// Linear interpolation on the sphere (ridt/sphere.hpp): each query located by a walk through the
// cones from the centre over the triangles, its weights the volumes about the centre.
#include <algorithm>
#include <cmath>

#include "predicates/orient3d.hpp"
#include "ridt/sphere.hpp"
#include "runtime/parallel.hpp"
#include "tds/ids.hpp"

namespace ridt {

std::vector<double> interpolate_sphere_linear(const SphericalTriangulation& t, std::span<const Point3> points,
                                              std::span<const double> values, std::size_t k,
                                              std::span<const Point3> queries, const Point3& centre, double fill,
                                              unsigned threads) {
  using detail::next3;
  using detail::prev3;
  const std::size_t m = t.size();
  if (k == 0 || values.size() != points.size() * k) throw InputError("interpolate_sphere_linear: k values a point");
  for (const VertexId v : t.triangles)
    if (v >= points.size()) throw InputError("interpolate_sphere_linear: a corner is not a point");
  std::vector<double> out(queries.size() * k, fill);
  if (m == 0) return out;
  // The triangles that face away from the centre (all of them where it lies inside the hull).
  std::vector<std::uint8_t> away(m);
  for (std::size_t f = 0; f < m; ++f) {
    const VertexId* c = &t.triangles[3 * f];
    away[f] = detail::orient3d(points[c[0]], points[c[1]], points[c[2]], centre) > 0;
  }
  // q's side of the plane through the centre, a and b: +1 on the side of the triangle left of a -> b.
  auto side = [&](VertexId a, VertexId b, const Point3& q) {
    return -detail::orient3d(centre, points[a], points[b], q);
  };
  auto holds = [&](std::size_t f, const Point3& q) {
    const VertexId* c = &t.triangles[3 * f];
    return side(c[0], c[1], q) >= 0 && side(c[1], c[2], q) >= 0 && side(c[2], c[0], q) >= 0;
  };
  detail::parallel_for(queries.size(), threads, 1024, [&](std::size_t from, std::size_t to) {
    std::size_t f = 0;
    for (std::size_t i = from; i < to; ++i) {
      const Point3& q = queries[i];
      if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z) || q == centre) continue;
      bool moved = true;
      for (std::size_t steps = 0; moved && steps < 4 * m + 8; ++steps) {
        moved = false;
        for (int j = 0; j < 3 && !moved; ++j)
          if (side(t.triangles[3 * f + next3(j)], t.triangles[3 * f + prev3(j)], q) < 0 && away[f])
            f = static_cast<std::size_t>(t.neighbors[3 * f + j]), moved = true;
      }
      if (!holds(f, q) || !away[f]) {  // a walk that cycled, or left the triangles facing away
        std::size_t g = 0;
        while (g < m && !(away[g] && holds(g, q))) ++g;
        if (g == m) continue;
        f = g;
      }
      const VertexId* c = &t.triangles[3 * f];
      const Point3 &a = points[c[0]], &b = points[c[1]], &cc = points[c[2]];
      // det[x - o, y - o, z - o] is orient3d(x, y, z, o) up to its sign convention: the same
      // for all three, so the ratios stand.
      const double w[3] = {detail::orient3d_value(q, b, cc, centre), detail::orient3d_value(a, q, cc, centre),
                           detail::orient3d_value(a, b, q, centre)};
      const double sum = w[0] + w[1] + w[2];
      if (!(sum != 0) || !std::isfinite(sum)) continue;
      for (std::size_t j = 0; j < k; ++j)
        out[i * k + j] =
            (w[0] * values[c[0] * k + j] + w[1] * values[c[1] * k + j] + w[2] * values[c[2] * k + j]) / sum;
    }
  });
  return out;
}

}  // namespace ridt
