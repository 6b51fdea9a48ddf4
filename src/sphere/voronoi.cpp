// The Voronoi diagram on the sphere (ridt/sphere.hpp), from the triangulation: a vertex a
// triangle, each cell the triangles round its point, each cell's area the sum of the solid
// angles of the triangles (point, vertex k, vertex k + 1) it fans into.
#include <algorithm>
#include <cmath>

#include "predicates/predicates.hpp"
#include "ridt/sphere.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"
#include "sphere/geometry.hpp"
#include "tds/ids.hpp"

namespace ridt {
namespace {

using detail::sphere::minus;
using detail::sphere::solid_angle;
using detail::sphere::unit;
using detail::sphere::unit_normal;

// How many corners ahead the cells' loop asks for a point's arrays.
constexpr std::size_t kAhead = 32;

// A triangle's circle on the sphere is centred where its outward normal points (unit_normal:
// within a bound however thin the triangle). `normals` (where not empty) gets the unit normals.
void circle_centres(const SphericalTriangulation& t, std::span<const Point3> points, const Point3& centre,
                    double radius, std::vector<Point3>& vertices, std::vector<Point3>& normals, unsigned threads) {
  detail::parallel_for(t.size(), threads, 4096, [&](std::size_t from, std::size_t to) {
    for (std::size_t f = from; f < to; ++f) {
      const Point3 &a = points[t.triangles[3 * f]], &b = points[t.triangles[3 * f + 1]],
                   &c = points[t.triangles[3 * f + 2]];
      const Point3 normal = unit_normal(a, b, c);
      vertices[f] = {centre.x + radius * normal.x, centre.y + radius * normal.y, centre.z + radius * normal.z};
      if (!normals.empty()) normals[f] = normal;
    }
  });
}

}  // namespace

SphericalVoronoi spherical_voronoi(const SphericalTriangulation& t, std::span<const Point3> points,
                                   const Point3& centre, double radius, bool areas, unsigned threads) {
  using detail::next3;
  threads = detail::thread_count(threads);
  const std::size_t m = t.size(), n = points.size();
  SphericalVoronoi out;
  detail::resize_present(out.vertices, m, threads);
  std::vector<Point3> normals;  // the vertices on the unit sphere
  if (areas) detail::resize_present(normals, m, threads);
  circle_centres(t, points, centre, radius, out.vertices, normals, threads);
  // Each point's cell: one triangle of it, then round it. In triangle (g, b, c) the next
  // triangle counter-clockwise round g is the one across g-c, from b.
  std::vector<std::uint32_t> one(n, 0xffffffffu);
  out.region_start.assign(n + 1, 0);
  for (std::size_t f = 0; f < m; ++f)
    for (int i = 0; i < 3; ++i) {
      const VertexId g = t.triangles[3 * f + i];
      one[g] = static_cast<std::uint32_t>(3 * f + i);
      ++out.region_start[g + 1];
    }
  for (std::size_t i = 0; i < n; ++i) out.region_start[i + 1] += out.region_start[i];
  detail::resize_present(out.regions, out.region_start[n], threads);
  if (areas) out.areas.assign(n, 0);
  // The points in the triangles' order (where they lie close together), not the input's.
  detail::parallel_for(3 * m, threads, 4096, [&](std::size_t from, std::size_t to) {
    for (std::size_t corner = from; corner < to; ++corner) {
      // The points come in the triangles' order, their arrays in the input's: what a corner
      // ahead will read, asked for now, arrives while this one's cell is walked.
      if (corner + kAhead < to) {
        const VertexId h = t.triangles[corner + kAhead];
        __builtin_prefetch(&one[h]), __builtin_prefetch(&out.region_start[h]);
        if (areas) __builtin_prefetch(&points[h]), __builtin_prefetch(&out.areas[h], 1);
      }
      if (corner + kAhead / 2 < to) {  // then where the cell goes, its start arrived by now
        const VertexId h = t.triangles[corner + kAhead / 2];
        if (one[h] == corner + kAhead / 2) __builtin_prefetch(out.regions.data() + out.region_start[h], 1);
      }
      const VertexId g = t.triangles[corner];
      if (one[g] != corner) continue;
      std::uint32_t* cell = out.regions.data() + out.region_start[g];
      const std::size_t size = out.region_start[g + 1] - out.region_start[g];
      std::uint32_t f = one[g] / 3;
      int i = static_cast<int>(one[g] % 3);
      for (std::size_t k = 0; k < size; ++k) {
        cell[k] = f;
        const std::uint32_t next = static_cast<std::uint32_t>(t.neighbors[3 * std::size_t{f} + next3(i)]);
        f = next;
        i = t.triangles[3 * std::size_t{f}] == g ? 0 : t.triangles[3 * std::size_t{f} + 1] == g ? 1 : 2;
      }
      if (!areas) continue;
      const Point3 p = unit(minus(points[g], centre));
      double sum = 0;
      for (std::size_t k = 0; k < size; ++k) {
        sum += solid_angle(p, normals[cell[k]], normals[cell[k + 1 < size ? k + 1 : 0]]);
      }
      out.areas[g] = sum * radius * radius;
    }
  });
  return out;
}

}  // namespace ridt
