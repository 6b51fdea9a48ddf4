// Linear interpolation on the sphere (ridt/sphere.hpp): each query located by a walk through the
// cones from the centre over the triangles, its weights the volumes about the centre.
#include <algorithm>
#include <cmath>

#include "predicates/orient3d.hpp"
#include "ridt/sphere.hpp"
#include "runtime/parallel.hpp"
#include "sphere/geometry.hpp"
#include "tds/ids.hpp"

namespace ridt {

std::vector<double> interpolate_sphere_linear(const SphericalTriangulation& t, std::span<const Point3> points,
                                              std::span<const double> values, std::size_t k,
                                              std::span<const Point3> queries, const Point3& centre, double fill,
                                              unsigned threads) {
  const std::size_t m = t.size();
  if (k == 0 || values.size() != points.size() * k) throw InputError("interpolate_sphere_linear: k values a point");
  for (const VertexId v : t.triangles)
    if (v >= points.size()) throw InputError("interpolate_sphere_linear: a corner is not a point");
  std::vector<double> out(queries.size() * k, fill);
  if (m == 0) return out;
  const detail::sphere::ConeWalk walk(t, points, centre);
  detail::parallel_for(queries.size(), threads, 1024, [&](std::size_t from, std::size_t to) {
    std::size_t f = 0;
    for (std::size_t i = from; i < to; ++i) {
      const Point3& q = queries[i];
      if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z) || q == centre) continue;
      if (!walk.locate(q, f)) continue;
      const VertexId* c = &t.triangles[3 * f];
      double w[3];
      if (!detail::sphere::linear_weights(points[c[0]], points[c[1]], points[c[2]], q, centre, w)) continue;
      for (std::size_t j = 0; j < k; ++j)
        out[i * k + j] = w[0] * values[c[0] * k + j] + w[1] * values[c[1] * k + j] + w[2] * values[c[2] * k + j];
    }
  });
  return out;
}

}  // namespace ridt
