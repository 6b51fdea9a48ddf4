// Fuzz target: small point sets full of degeneracies, triangulated by every method.
//
// The first byte picks a transformation of the coordinates (scaling towards underflow or
// overflow, a shift that leaves few bits, integers near 2^53, a small rotation); every other
// byte is a point whose x and y are picked, four bits each, from sixteen values. With so few
// values, duplicates, collinear and cocircular points abound.
//
// Every method, order and location mode must give a result that passes the whole audit (the
// exact validator, neighbours, hull, duplicates), and all must give the same triangles, hull
// and duplicates. The finite bounding triangle may lose hull edges (the paper's defect) but
// then must say so. The convex hull (ridt/hull.hpp) must pass its validator and be the
// triangulation's boundary where it turns. Anything else aborts: a finding.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "audit.hpp"
#include "ridt/check.hpp"
#include "ridt/hull.hpp"
#include "ridt/ridt.hpp"

namespace {

using namespace ridt;

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_triangulate: %s\n", what.c_str());
  std::abort();
}

// Small integers, halves, thirds and values a few units in the last place from them.
constexpr double kValues[16] = {-3,  -2,   -1,      0,       1,           2,           3,       4,
                                0.5, -0.5, 1.0 / 3, 2.0 / 3, 1 + 0x1p-52, 2 - 0x1p-51, 0x1p-30, -1 - 0x1p-52};

// The transformation `kind` (bytes[0] % 8) of a point.
Point transform(int kind, Point p) {
  switch (kind) {
    case 1:
      return {p.x * 1e-300, p.y * 1e-300};  // tiny: products underflow
    case 2:
      return {p.x * 1e300, p.y * 1e300};  // huge: squares overflow
    case 3:
      return {p.x + 1e15, p.y + 1e15};  // few bits left for the fraction
    case 4:
      return {std::floor(p.x) + 0x1p53 - 8,  // integers near 2^53
              std::floor(p.y) + 0x1p53 - 8};
    case 5:
      return {p.x * 0x1p-1060, p.y * 0x1p-1060};  // subnormal differences
    case 6:
      return {p.x * 0x1p1000, p.y * 0x1p1000};  // near the top of the range
    case 7: {  // a small rotation, rounded
      const double c = std::cos(1e-3), s = std::sin(1e-3);
      return {c * p.x - s * p.y, s * p.x + c * p.y};
    }
    default:
      return p;
  }
}

std::vector<Point> points_of(const std::uint8_t* bytes, std::size_t size) {
  std::vector<Point> pts;
  for (std::size_t i = 1; i < size; ++i)
    pts.push_back(transform(bytes[0] % 8, {kValues[bytes[i] >> 4], kValues[bytes[i] & 15]}));
  return pts;
}

// Every method and mode; the threaded ones on 2 threads in the BRIO order and on 3 in the
// random order.
const std::vector<test::Mode>& modes() {
  static const std::vector<test::Mode> all = [] {
    std::vector<test::Mode> m = test::every_mode(2);
    for (const test::Mode& more : test::every_mode(3, Order::Random))
      if (more.method != Method::Serial) m.push_back(more);
    return m;
  }();
  return all;
}

// The hull's corners against the triangulation's boundary (points on its sides left out).
void check_hull(const std::vector<Point>& pts) {
  const ConvexHull h = convex_hull(pts, true, 2);
  if (const CheckResult r = check_convex_hull(pts, h.corners); !r.valid) finding("convex hull: " + r.message);
  std::vector<Point> corners;
  for (const VertexId v : h.corners) corners.push_back(pts[v]);
  if (corners != test::hull_turns(pts, triangulate(pts)))
    finding("the convex hull's corners are not the triangulation's");
  if (h.corners.size() + h.on_sides.size() > pts.size()) finding("the convex hull lists more points than given");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  if (size == 0 || size > 4097) return 0;
  const std::vector<Point> pts = points_of(bytes, size);
  // A different order for each length.
  if (const std::string problem = test::audit_every_mode(pts, modes(), size); !problem.empty()) finding(problem);
  check_hull(pts);
  // The paper's finite bounding triangle: right, or it says that it lost hull edges.
  Options finite;
  finite.experiment.bounding = Bounding::Finite;
  try {
    const Triangulation t = triangulate(pts, finite);
    const std::string problem = test::audit(pts, t);
    if (!problem.empty() && t.warning.find("lost convex hull edges") == std::string::npos)
      finding("finite bounding triangle, no warning: " + problem);
  } catch (const InputError& e) {
    // Only where K = k * M overflows.
    if (std::string(e.what()).find("overflows") == std::string::npos)
      finding(std::string("finite bounding triangle threw: ") + e.what());
  }
  return 0;
}
