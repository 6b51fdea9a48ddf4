// Fuzz target: small weighted point sets on a lattice, full of ties (four points on one
// orthogonal circle, points at one place with other weights, copies), triangulated as regular
// triangulations (ridt/regular.hpp).
//
// The first byte picks a transformation (scaling by 2^-500 or 2^500, the weights by its square;
// a far offset); every other byte is a point: x and y on an 8 x 8 lattice (bits 0-2, 3-5) and a
// weight (bits 6-7: 0, 1, 2 or a rounding above 1/2). Every result must pass the exact
// validator and be the same, by coordinates and weights, for the points in reverse order; with
// all weights 0 it must be triangulate()'s; a refusal must be of points that are collinear or
// fewer than three places. Anything else aborts: a finding.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "ridt/predicates.hpp"
#include "ridt/regular.hpp"

namespace {

using namespace ridt;

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_regular: %s\n", what.c_str());
  std::abort();
}

struct Input {
  std::vector<Point> points;
  std::vector<double> weights;
};

Input input_of(const std::uint8_t* bytes, std::size_t size) {
  static const double kWeight[4] = {0, 1, 2, 0.5 + 0x1p-53};
  const int kind = bytes[0] % 4;
  const double scale = kind == 1 ? 0x1p-500 : kind == 2 ? 0x1p500 : 1, offset = kind == 3 ? 1e9 : 0;
  Input in;
  for (std::size_t i = 1; i < size; ++i) {
    in.points.push_back({(bytes[i] & 7) * scale + offset, ((bytes[i] >> 3) & 7) * scale - offset});
    in.weights.push_back(kWeight[bytes[i] >> 6] * scale * scale);
  }
  return in;
}

// Whether the points are at fewer than three places or all on one line (exactly).
bool flat(const std::vector<Point>& pts) {
  for (std::size_t a = 0; a < pts.size(); ++a)
    for (std::size_t b = a + 1; b < pts.size(); ++b)
      for (std::size_t c = b + 1; c < pts.size(); ++c)
        if (orientation(pts[a], pts[b], pts[c]) != 0) return false;
  return true;
}

std::set<std::array<double, 6>> faces(const std::vector<Point>& pts, std::span<const VertexId> tris) {
  std::set<std::array<double, 6>> out;
  for (std::size_t f = 0; f < tris.size() / 3; ++f) {
    std::array<Point, 3> c = {pts[tris[3 * f]], pts[tris[3 * f + 1]], pts[tris[3 * f + 2]]};
    auto less = [](const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
    while (less(c[1], c[0]) || less(c[2], c[0])) std::rotate(c.begin(), c.begin() + 1, c.end());
    out.insert({c[0].x, c[0].y, c[1].x, c[1].y, c[2].x, c[2].y});
  }
  return out;
}

std::set<std::array<double, 3>> hidden(const Input& in, const RegularTriangulation& t) {
  std::set<std::array<double, 3>> out;
  for (const VertexId h : t.hidden) out.insert({in.points[h].x, in.points[h].y, in.weights[h]});
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  if (size == 0 || size > 65) return 0;
  const Input in = input_of(bytes, size);
  RegularTriangulation t;
  try {
    t = triangulate_regular(in.points, in.weights, 1 + size % 2);
  } catch (const InputError& e) {
    if (!flat(in.points)) finding(std::string("refused points that are not collinear: ") + e.what());
    return 0;
  }
  const CheckResult r = check_regular(in.points, in.weights, t.triangles);
  if (!r.valid) finding(r.message);
  const Input reversed{{in.points.rbegin(), in.points.rend()}, {in.weights.rbegin(), in.weights.rend()}};
  const RegularTriangulation u = triangulate_regular(reversed.points, reversed.weights, 1);
  if (faces(in.points, t.triangles) != faces(reversed.points, u.triangles)) finding("another order, other triangles");
  if (hidden(in, t) != hidden(reversed, u)) finding("another order, other points hidden");
  if (std::all_of(in.weights.begin(), in.weights.end(), [](double w) { return w == 0; }) &&
      faces(in.points, t.triangles) != faces(in.points, triangulate(in.points).triangles))
    finding("equal weights, not the Delaunay triangulation");
  return 0;
}
