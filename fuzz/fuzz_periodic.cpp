// Fuzz target: small point sets on a lattice in a periodic domain, full of ties (a lattice's
// cocircular squares, copies of one point in one triangle, points at one place), triangulated
// on the torus (ridt/periodic.hpp).
//
// The first byte picks the domain (8 x 8; scaled by 2^-500; far from the origin; sevenths of a
// unit, whose copies are no doubles); every other byte is a point: x and y on the 8 x 8
// lattice (bits 0-2, 3-5), x nudged by bits 6-7 (0, a third, a half, 2^-40 of a step). Every
// result must pass the exact validator, have 2n triangles, give the same triangles for the
// points in reverse order, and cells that add up to the domain. Anything else aborts: a finding.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "ridt/periodic.hpp"

namespace {

using namespace ridt;

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_periodic: %s\n", what.c_str());
  std::abort();
}

struct Input {
  std::vector<Point> points;
  PeriodicDomain domain;
};

Input input_of(const std::uint8_t* bytes, std::size_t size) {
  static const double kNudge[4] = {0, 1.0 / 3, 0.5, 0x1p-40};
  const int kind = bytes[0] % 4;
  const double step = kind == 1 ? 0x1p-500 : kind == 3 ? 1.0 / 7 : 1;
  Input in;
  in.domain = {{kind == 2 ? 1e9 : 0, kind == 2 ? -1e9 : 0}, 8 * step, (bytes[0] & 4 ? 5 : 8) * step};
  for (std::size_t i = 1; i < size; ++i) {
    const double x = ((bytes[i] & 7) + kNudge[bytes[i] >> 6]) * step, y = ((bytes[i] >> 3) & 7) * step;
    Point p{in.domain.origin.x + x, in.domain.origin.y + std::fmod(y, in.domain.height)};
    p.x = std::min(p.x, std::nextafter(in.domain.origin.x + in.domain.width, 0.0));
    if (!(p.y < in.domain.origin.y + in.domain.height)) p.y = in.domain.origin.y;
    in.points.push_back(p);
  }
  return in;
}

// The triangles by their corners' coordinates and offsets, from the least: any numbering.
using Corner = std::tuple<double, double, int, int>;
std::set<std::array<Corner, 3>> faces(const std::vector<Point>& pts, const PeriodicTriangulation& t) {
  std::set<std::array<Corner, 3>> out;
  for (std::size_t f = 0; f < t.size(); ++f) {
    std::array<Corner, 3> c;
    for (int i = 0; i < 3; ++i) {
      const Point& p = pts[t.triangles[3 * f + i]];
      c[i] = {p.x, p.y, t.offsets[3 * f + i].dx, t.offsets[3 * f + i].dy};
    }
    while (c[1] < c[0] || c[2] < c[0]) std::rotate(c.begin(), c.begin() + 1, c.end());
    for (int i = 2; i >= 0; --i) std::get<2>(c[i]) -= std::get<2>(c[0]), std::get<3>(c[i]) -= std::get<3>(c[0]);
    out.insert(c);
  }
  return out;
}

double cell_areas(const std::vector<Point>& pts, const PeriodicTriangulation& t) {
  const PeriodicVoronoi v = periodic_voronoi(pts, t);
  double area = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::uint32_t k = v.cell_offsets[i]; k < v.cell_offsets[i + 1]; ++k) {
      const std::uint32_t l = k + 1 < v.cell_offsets[i + 1] ? k + 1 : v.cell_offsets[i];
      auto at = [&](std::uint32_t m) {
        const Point c = v.vertices[static_cast<std::size_t>(v.cell_vertices[m])];
        return Point{c.x + v.cell_shifts[m].dx * t.domain.width - pts[i].x,
                     c.y + v.cell_shifts[m].dy * t.domain.height - pts[i].y};
      };
      const Point p = at(k), q = at(l);
      area += (p.x * q.y - p.y * q.x) / 2;
    }
  return area;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  if (size < 2 || size > 65) return 0;
  const Input in = input_of(bytes, size);
  const PeriodicTriangulation t = triangulate_periodic(in.points, in.domain, 1 + size % 2);
  const CheckResult r = check_periodic(in.points, in.domain, t.triangles, t.offsets);
  if (!r.valid) finding(r.message);
  if (t.size() != 2 * (in.points.size() - t.duplicates.size())) finding("not 2n triangles");
  const std::vector<Point> reversed(in.points.rbegin(), in.points.rend());
  if (faces(in.points, t) != faces(reversed, triangulate_periodic(reversed, in.domain, 1)))
    finding("another order, other triangles");
  const double domain = in.domain.width * in.domain.height, area = cell_areas(in.points, t);
  if (!(std::fabs(area - domain) <= 1e-9 * domain)) finding("the cells do not add up to the domain");
  return 0;
}
