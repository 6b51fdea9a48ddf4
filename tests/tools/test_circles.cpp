// The widened circumcircles that ridt-mpi and the out-of-core strips choose cells and ranks by
// (ridt/regions.hpp): every point that the exact in-circle test puts inside or on the
// circle lies in the widened disc, for triangles from fat to nearly flat at scales from 1e-300
// to 1e300; the disc of a flat triangle is not widened far beyond its error.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "ridt/predicates.hpp"
#include "ridt/regions.hpp"

namespace ridt::test {
namespace {

TEST(Circles, TheWidenedDiscHoldsEveryPointTheExactTestFindsInside) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_real_distribution<double> exponent(-15, 0);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI);
  int near = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double scale = std::pow(10.0, std::round(unit(rng) * 300)), flat = std::pow(10.0, exponent(rng));
    const Point a{unit(rng) * scale, unit(rng) * scale}, b{unit(rng) * scale, unit(rng) * scale};
    const double t = unit(rng);
    // c near the line through a and b: the flatter the triangle, the larger its circle.
    Point c{a.x + t * (b.x - a.x) - flat * (b.y - a.y), a.y + t * (b.y - a.y) + flat * (b.x - a.x)};
    const int turn = orientation(a, b, c);
    if (turn == 0) continue;
    const Point& p = turn > 0 ? b : c;
    const Point& q = turn > 0 ? c : b;
    const regions::Disc d = regions::circle(a, p, q);
    if (!std::isfinite(d.r)) continue;
    const double radius = std::hypot(a.x - d.x, a.y - d.y);
    for (int k = 0; k < 16; ++k) {
      // Points about the computed circle, off it by up to a thousandth of its radius.
      const double off = (k % 2 ? 1 : -1) * std::pow(10.0, -16 + 13 * std::abs(unit(rng)));
      const double th = angle(rng);
      const Point x{d.x + radius * (1 + off) * std::cos(th), d.y + radius * (1 + off) * std::sin(th)};
      if (!std::isfinite(x.x) || !std::isfinite(x.y) || in_circle(a, p, q, x) < 0) continue;
      ++near;
      ASSERT_LE(std::hypot(x.x - d.x, x.y - d.y), d.r) << "trial " << trial << " off " << off;
    }
    // Widened by its error (some 56 eps / |D| of the radius, D the scaled triangle's doubled
    // area), not by a fixed share of the radius: a triangle flat to 1e-9 of its size grows by
    // well under a thousandth.
    if (flat >= 1e-9) {
      EXPECT_LT(d.r - radius, 1e-3 * radius + 1e-12 * scale) << trial;
    }
  }
  EXPECT_GT(near, 100000);
}

}  // namespace
}  // namespace ridt::test
