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
using detail::sphere::solid_angle_parts;
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

// The solid angle of the cell of unit vector p whose corners are normals[cell[0 .. size)],
// counter-clockwise: the sum of the fan's solid angles 2 atan2(t_k, b_k) (solid_angle), taken
// as twice the argument of the product of the complex numbers b_k + i t_k, one atan2 a cell
// in place of one a corner. Round a point of the sphere the t_k are positive, so the product's
// parts add terms of one sign and keep a relative error of some `size` roundings. Where the
// product turns past a quarter turn (a cell over a quarter of the sphere, or a fan triangle
// facing back) the angles are summed one by one. A power of two keeps the product's size in range.
double cell_area(const Point3& p, const std::vector<Point3>& normals, const std::uint32_t* cell, std::size_t size) {
  double re = 1, im = 0;
  for (std::size_t k = 0; k < size; ++k) {
    const Point3 &b = normals[cell[k]], &c = normals[cell[k + 1 < size ? k + 1 : 0]];
    const auto [t, u] = solid_angle_parts(p, b, c);
    const double r = re * u - im * t;
    im = re * t + im * u, re = r;
    if (!(re > 0)) {
      double sum = 0;
      for (std::size_t j = 0; j < size; ++j)
        sum += solid_angle(p, normals[cell[j]], normals[cell[j + 1 < size ? j + 1 : 0]]);
      return sum;
    }
    if (re > 0x1p500) re = std::ldexp(re, -500), im = std::ldexp(im, -500);
  }
  return 2 * std::atan2(im, re);
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
  std::vector<std::uint32_t> one;
  detail::resize_present(one, n, threads), detail::resize_present(out.region_start, n + 1, threads);
  std::fill(one.begin(), one.end(), 0xffffffffu);
  for (std::size_t f = 0; f < m; ++f)
    for (int i = 0; i < 3; ++i) {
      const VertexId g = t.triangles[3 * f + i];
      one[g] = static_cast<std::uint32_t>(3 * f + i);
      ++out.region_start[g + 1];
    }
  for (std::size_t i = 0; i < n; ++i) out.region_start[i + 1] += out.region_start[i];
  detail::resize_present(out.regions, out.region_start[n], threads);
  if (areas) detail::resize_present(out.areas, n, threads);
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
      out.areas[g] = cell_area(unit(minus(points[g], centre)), normals, cell, size) * radius * radius;
    }
  });
  return out;
}

double shortest_edge(const SphericalTriangulation& t, std::span<const Point3> points, unsigned threads) {
  threads = detail::thread_count(threads);
  const std::size_t m = t.size();
  // Each part's least, by the edges' squares, then by their lengths where a square is lost.
  auto least = [&](auto length) {
    const unsigned parts = static_cast<unsigned>(std::clamp<std::size_t>(m / 65536, 1, threads));
    std::vector<double> part(parts, HUGE_VAL);
    detail::parallel_for(parts, parts, 1, [&](std::size_t first, std::size_t last) {
      for (std::size_t p = first; p < last; ++p)
        for (std::size_t f = m * p / parts; f < m * (p + 1) / parts; ++f)
          for (int i = 0; i < 3; ++i)
            part[p] =
                std::min(part[p], length(points[t.triangles[3 * f + i]], points[t.triangles[3 * f + (i + 1) % 3]]));
    });
    return *std::min_element(part.begin(), part.end());
  };
  const double square = least([](const Point3& a, const Point3& b) {
    const double dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
    return dx * dx + dy * dy + dz * dz;
  });
  if (m == 0 || (square >= 0x1p-1000 && square <= 0x1p1000)) return std::sqrt(square);
  return least([](const Point3& a, const Point3& b) { return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z); });
}

}  // namespace ridt
