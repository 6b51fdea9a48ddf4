// Inputs that once broke ridt, each named for what went wrong, run by every method. Each was
// found by a fuzz target (fuzz/) or an adversarial test; the comment says which and why.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "helpers.hpp"
#include "order/order.hpp"
#include "predicates/predicates.hpp"

namespace ridt::test {
namespace {

// fuzz_triangulate, first seed of the subnormal kind: with a subnormal extent the Hilbert
// scale 65535 / extent overflowed, 0 * inf gave NaN, and NaN was converted to an integer
// (undefined; UBSan stopped there).
TEST(Regression, HilbertKeysOfSubnormalPoints) {
  const double u = 0x1p-1070;
  const std::vector<Point> corners = {{0, 0}, {u, 0}, {0, u}, {u, u}, {-3 * u, 4 * u}};
  const std::vector<std::uint32_t> keys = detail::hilbert_keys(corners.data(), 5, 1);
  // The box is [-3u, u] x [0, 4u]: (-3u, 4u) is its upper left corner, (0, 0) three quarters
  // along its lower side.
  EXPECT_EQ(keys[4], detail::hilbert_key(0, 65535));
  EXPECT_EQ(keys[0], detail::hilbert_key(49151, 0));
  std::vector<Point> grid;
  for (int i = -3; i <= 4; ++i)
    for (int j = -3; j <= 4; ++j) grid.push_back({i * 0x1p-1060, j * 0x1p-1060});
  EXPECT_EQ(audit_every_mode(grid, every_mode(3)), "");
}

// fuzz_triangulate: one point at (4e300, 6.7e299) with the finite bounding triangle. Its box
// has size 0, so M was set to 1 and K = 10 vanished beside 4e300: the "triangle" was three
// copies of the point, which became a duplicate of a bounding vertex and was looked up past
// the end of the input (AddressSanitizer).
TEST(Regression, FiniteBoundingTriangleAroundOneHugePoint) {
  Options finite;
  finite.experiment.bounding = Bounding::Finite;
  const std::vector<Point> one = {{4e300, 2.0 / 3 * 1e300}};
  const Triangulation t = triangulate(one, finite);
  EXPECT_EQ(audit(one, t), "");
  EXPECT_EQ(t.size(), 0u);
}

// fuzz_triangulate, after the fix above: one subnormal point, where 2^-40 of its coordinate
// underflows to 0 and K was 0 again. And two boxes that are flat far from the origin.
TEST(Regression, FiniteBoundingTriangleAroundTinyAndFlatSets) {
  Options finite;
  finite.experiment.bounding = Bounding::Finite;
  const std::vector<std::vector<Point>> sets = {
      {{-3 * 0x1p-1060, -3 * 0x1p-1060}},
      {{1e15, 0}, {1e15, 1e-5}, {1e15, 2e-5}},
      {{0, 1e15}, {1e-9, 1e15}, {3e-9, 1e15}, {1e-9, 1e15}},
      {{1e15, 1e15}, {1e15 + 0.125, 1e15}, {1e15, 1e15 + 0.125}, {1e15 + 0.125, 1e15 + 0.125}},
  };
  for (const std::vector<Point>& pts : sets) {
    const Triangulation t = triangulate(pts, finite);
    const std::string problem = audit(pts, t);
    // Right, or the paper's defect, announced.
    if (!problem.empty()) {
      EXPECT_NE(t.warning.find("lost convex hull edges"), std::string::npos) << problem;
    }
  }
}

// fuzz_triangulate (30 minutes): three nearly collinear points (a vertical line rotated by
// 1e-3 radians, rounded) with the finite bounding triangle. The circle of their thin triangle
// holds a bounding vertex, so no triangle survives, and the run said "all points are
// collinear", which they are not. It must say that the finite triangle lost the hull.
TEST(Regression, FiniteBoundingTriangleLosingEveryTriangleSaysSo) {
  const double c = std::cos(1e-3), s = std::sin(1e-3);
  auto rotated = [&](double x, double y) { return Point{c * x - s * y, s * x + c * y}; };
  const std::vector<Point> pts = {rotated(-3, 1),  rotated(-3, -3), rotated(-3, -3), rotated(-3, -3),
                                  rotated(-3, -3), rotated(-3, -3), rotated(-3, 2)};
  ASSERT_NE(detail::orient2d(pts[0], pts[1], pts[6]), 0);  // not collinear
  Options finite;
  finite.experiment.bounding = Bounding::Finite;
  const Triangulation t = triangulate(pts, finite);
  EXPECT_EQ(t.size(), 0u);
  EXPECT_NE(t.warning.find("lost convex hull edges"), std::string::npos) << t.warning;
  // The symbolic triangle gets the one triangle.
  EXPECT_EQ(audit(pts, triangulate(pts)), "");
  EXPECT_EQ(triangulate(pts).size(), 1u);
}

}  // namespace
}  // namespace ridt::test
