// Adversarial point sets, each triangulated by every method, order and location mode. Every
// result passes the whole audit (the exact validator, neighbours, hull, duplicates) and all of
// them are the same triangulation.
//
// The sets: 100,000 integer points on one circle; a triangle with 30,000 points on each edge;
// a 1000 x 1000 grid rotated by a small angle; these three scaled by 1e-300 and by 1e300 and
// shifted by 1e15; integers near 2^53; one far outlier beside a million points; points on a
// parabola; many copies of one point and one other point.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <numeric>
#include <ostream>
#include <string>
#include <vector>

#include "helpers.hpp"
#include "order/random.hpp"
#include "ridt/generate.hpp"

namespace ridt::test {
namespace {

// RIDT_ADVERSARIAL_SCALE (default 1) multiplies the number of points of every set: scripts/test.sh
// runs them at 0.3 of their size in the Release build and at a tenth under the sanitizers.
double size_factor() {
  const char* s = std::getenv("RIDT_ADVERSARIAL_SCALE");
  const double f = s != nullptr ? std::atof(s) : 1.0;
  return f > 0 && f <= 1 ? f : 1.0;
}
int scaled_count(double count) { return std::max(1, static_cast<int>(std::lround(count * size_factor()))); }
// The side of a square grid with scaled_count(side^2) points.
int scaled_side(double side) { return std::max(2, static_cast<int>(std::lround(side * std::sqrt(size_factor())))); }

// --- The sets ---

// Integer points on the circle x^2 + y^2 = N, N the product of the 15 smallest primes that are
// 1 mod 4. Each such prime is a product of Gaussian primes (a + bi)(a - bi); picking one of the
// two for each prime, times a unit, gives every one of the 4 * 2^15 = 131,072 lattice points on
// the circle. Their coordinates stay below 4.2e12, so they are exact in doubles. `count` of
// them, picked at random.
std::vector<Point> cocircular(std::size_t count) {
  const int primes[] = {5, 13, 17, 29, 37, 41, 53, 61, 73, 89, 97, 101, 109, 113, 137};
  struct Gaussian {
    std::int64_t re, im;
  };
  std::vector<Gaussian> factor;
  for (int p : primes)
    for (std::int64_t a = 1; a * a < p; ++a) {
      const auto b = static_cast<std::int64_t>(std::llround(std::sqrt(p - a * a)));
      if (a * a + b * b == p && a > b) factor.push_back({a, b});
    }
  EXPECT_EQ(factor.size(), 15u);
  std::vector<Point> pts;
  for (std::uint32_t pick = 0; pick < (1u << 15); ++pick) {
    Gaussian z{1, 0};
    for (std::size_t i = 0; i < factor.size(); ++i) {
      const std::int64_t a = factor[i].re, b = (pick >> i & 1) ? -factor[i].im : factor[i].im;
      z = {z.re * a - z.im * b, z.re * b + z.im * a};
    }
    for (int unit = 0; unit < 4; ++unit) {
      pts.push_back({static_cast<double>(z.re), static_cast<double>(z.im)});
      z = {-z.im, z.re};  // times i
    }
  }
  detail::Rng rng(5);
  for (std::size_t i = pts.size(); i > 1; --i) std::swap(pts[i - 1], pts[rng.below(i)]);
  pts.resize(count);
  return pts;
}

// The triangle (0, 0), (2^20, 0), (0, 2^20) with `per_edge` integer points on each edge, all
// of them on the hull, and `inside` random integer points strictly inside.
std::vector<Point> collinear_hull(int per_edge, int inside) {
  const double n = 0x1p20;
  std::vector<Point> pts;
  detail::Rng rng(6);
  for (int i = 0; i < per_edge; ++i) {
    const double t = std::floor(n * i / per_edge);
    pts.push_back({t, 0});
    pts.push_back({0, n - t});
    pts.push_back({n - t, t});
  }
  while (static_cast<int>(pts.size()) < 3 * per_edge + inside) {
    const double x = 1 + static_cast<double>(rng.below(1u << 20)), y = 1 + static_cast<double>(rng.below(1u << 20));
    if (x + y < n) pts.push_back({x, y});
  }
  return pts;
}

// A side x side integer grid rotated by `angle` radians about the origin (rounded).
std::vector<Point> rotated_grid(int side, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  std::vector<Point> pts;
  pts.reserve(static_cast<std::size_t>(side) * side);
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) pts.push_back({c * i - s * j, s * i + c * j});
  return pts;
}

// Scaled by `factor` after an exact power-of-two scaling that brings the largest coordinate
// below 2^12, so that 1e300 cannot overflow.
std::vector<Point> scaled(std::vector<Point> pts, double factor) {
  double largest = 0;
  for (const Point& p : pts) largest = std::max({largest, std::fabs(p.x), std::fabs(p.y)});
  int e = 0;
  std::frexp(largest, &e);
  const int down = std::min(0, 12 - e);
  for (Point& p : pts) p = {std::ldexp(p.x, down) * factor, std::ldexp(p.y, down) * factor};
  return pts;
}

std::vector<Point> shifted(std::vector<Point> pts, double by) {
  for (Point& p : pts) p = {p.x + by, p.y + by};
  return pts;
}

// A 300 x 300 grid of integers just below 2^53 and 10,000 random integers among them (some
// land on grid points: duplicates).
std::vector<Point> near_2_to_53(int side, int random) {
  const double top = 0x1p53;
  std::vector<Point> pts;
  for (int i = 1; i <= side; ++i)
    for (int j = 1; j <= side; ++j) pts.push_back({top - i, top - j});
  detail::Rng rng(7);
  for (int k = 0; k < random; ++k)
    pts.push_back({top - 1 - static_cast<double>(rng.below(side)), top - 1 - static_cast<double>(rng.below(1u << 20))});
  return pts;
}

// `count` uniform points in the unit square and one at (1e30, -1e30).
std::vector<Point> far_outlier(int count) {
  std::vector<Point> pts = generate(Distribution::Uniform, count, 8);
  pts.push_back({1e30, -1e30});
  return pts;
}

// (t, t^2) for the integers -half <= t < half: all on the hull, and every symmetric
// quadruple (+-s, s^2), (+-t, t^2) is cocircular.
std::vector<Point> parabola(int half) {
  std::vector<Point> pts;
  for (int t = -half; t < half; ++t) pts.push_back({double(t), double(t) * t});
  return pts;
}

// `copies` copies of one point and one other point: nothing to triangulate.
std::vector<Point> identical_but_one(int copies) {
  std::vector<Point> pts(copies, Point{0.1, 0.7});
  pts.insert(pts.begin() + copies / 2, Point{0.3, 0.7});
  return pts;
}

struct Set {
  std::string name;
  std::function<std::vector<Point>()> make;
  std::size_t hull = 0;  // the hull's size where the set fixes it
};

std::vector<Set> sets() {
  const int circle = scaled_count(100000), per_edge = scaled_count(30000);
  const int side = scaled_side(1000);
  std::vector<Set> out = {
      {"cocircular", [=] { return cocircular(circle); }, std::size_t(circle)},
      {"collinear_hull", [=] { return collinear_hull(per_edge, scaled_count(100000)); }, 3 * std::size_t(per_edge)},
      {"rotated_grid", [=] { return rotated_grid(side, 1e-3); }},
  };
  for (std::size_t i = 0; i < 3; ++i) {
    const Set base = out[i];
    // Shifted integers stay exact below 2^53, so the circle stays a circle; scaled, it does not.
    out.push_back({base.name + "_times_1e_minus_300", [base] { return scaled(base.make(), 1e-300); }});
    out.push_back({base.name + "_times_1e300", [base] { return scaled(base.make(), 1e300); }});
    out.push_back({base.name + "_plus_1e15", [base] { return shifted(base.make(), 1e15); }, i == 0 ? base.hull : 0});
  }
  const int grid = scaled_side(300);
  out.push_back({"near_2_to_53", [=] { return near_2_to_53(grid, scaled_count(10000)); }});
  out.push_back({"far_outlier", [] { return far_outlier(scaled_count(1000000)); }});
  const int half = scaled_count(50000);
  out.push_back({"parabola", [=] { return parabola(half); }, 2 * std::size_t(half)});
  out.push_back({"identical_but_one", [] { return identical_but_one(scaled_count(100000)); }});
  return out;
}

// --- Every method on each set ---

// Test names and failure messages show the set's name, not its bytes.
void PrintTo(const Set& set, std::ostream* os) { *os << set.name; }

class Adversarial : public ::testing::TestWithParam<Set> {};

TEST_P(Adversarial, EveryMethodGivesTheSameSoundTriangulation) {
  const std::vector<Point> pts = GetParam().make();
  Triangulation first;
  ASSERT_EQ(audit_every_mode(pts, every_mode(2), 1, &first), "");
  // What each set must give, beyond soundness.
  if (GetParam().hull != 0) {
    EXPECT_EQ(first.hull.size(), GetParam().hull);
  }
  if (GetParam().name == "identical_but_one") {
    EXPECT_EQ(first.size(), 0u);
    EXPECT_EQ(first.duplicates.size(), pts.size() - 2);
    EXPECT_NE(first.warning.find("fewer than three distinct points"), std::string::npos) << first.warning;
  }
}

INSTANTIATE_TEST_SUITE_P(Sets, Adversarial, ::testing::ValuesIn(sets()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace ridt::test
