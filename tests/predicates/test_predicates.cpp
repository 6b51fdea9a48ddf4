// Predicates on hard cases: near-collinear, exactly and nearly cocircular, extreme scales,
// integers near 2^53, and the symbolic perturbation.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "predicates/predicates.hpp"
#include "ridt/predicates.hpp"

namespace ridt::detail {
namespace {

// Exact orientation for points whose coordinates are integers times 2^-53 below 2^53 in
// magnitude: the determinant fits in 128-bit integers.
int orient_reference(Point a, Point b, Point c) {
  auto i = [](double v) { return static_cast<__int128>(std::ldexp(v, 53)); };
  const __int128 det = (i(a.x) - i(c.x)) * (i(b.y) - i(c.y)) - (i(a.y) - i(c.y)) * (i(b.x) - i(c.x));
  return (det > 0) - (det < 0);
}

TEST(Orient2d, SimpleSigns) {
  EXPECT_EQ(orient2d({0, 0}, {1, 0}, {0, 1}), 1);
  EXPECT_EQ(orient2d({0, 0}, {0, 1}, {1, 0}), -1);
  EXPECT_EQ(orient2d({0, 0}, {1, 1}, {2, 2}), 0);
}

// Shewchuk's classic: a 256 x 256 grid of points one ulp apart near (0.5, 0.5) against the
// line through (12, 12) and (24, 24); naive evaluation gets many of these wrong.
TEST(Orient2d, NearCollinearGridMatchesExactReference) {
  const double ulp = std::ldexp(1.0, -53);
  const Point b{12, 12}, c{24, 24};
  int zeros = 0, checked = 0;
  for (int i = 0; i < 256; ++i)
    for (int j = 0; j < 256; ++j) {
      const Point a{0.5 + i * ulp, 0.5 + j * ulp};
      const int s = orient2d(a, b, c);
      ASSERT_EQ(s, orient_reference(a, b, c)) << i << " " << j;
      zeros += s == 0;
      ++checked;
    }
  EXPECT_EQ(zeros, 256);  // exactly the diagonal i == j is collinear
  EXPECT_EQ(checked, 65536);
}

TEST(Orient2d, ExtremeScalesArePowerOfTwoInvariant) {
  const Point a{0.1, 0.3}, b{0.7, 0.2}, c{0.4, 0.9};
  const Point p{0.3, 0.3}, q{0.6, 0.6}, r{0.9, 0.9 + std::ldexp(1.0, -52)};
  for (int e : {-1000, -500, -150, 0, 150, 500, 900}) {
    auto s = [e](Point v) { return Point{std::ldexp(v.x, e), std::ldexp(v.y, e)}; };
    EXPECT_EQ(orient2d(s(a), s(b), s(c)), orient2d(a, b, c)) << e;
    EXPECT_EQ(orient2d(s(p), s(q), s(r)), 1) << e;
    EXPECT_EQ(orient2d(s(p), s(q), s({1.2, 1.2})), 0) << e;
  }
}

TEST(Orient2d, MixedMagnitudes) {
  // A point 1e-300 off a line through points of size 1e300: only exact arithmetic sees it.
  EXPECT_EQ(orient2d({-1e300, 0}, {1e300, 0}, {0, 1e-300}), 1);
  EXPECT_EQ(orient2d({-1e300, 0}, {1e300, 0}, {5, -1e-300}), -1);
  EXPECT_EQ(orient2d({-1e300, 0}, {1e300, 0}, {1e-300, 0}), 0);
  // Products overflow double here; the sign is still exact.
  EXPECT_EQ(orient2d({1e200, 1e200}, {-1e200, 1e200}, {0, 1e200 * (1 - 1e-16)}), 1);
}

TEST(Orient2d, IntegersNear2To53) {
  const double c = std::ldexp(1.0, 53) - 16;
  EXPECT_EQ(orient2d({c, c}, {c + 3, c + 3}, {c + 7, c + 7}), 0);
  EXPECT_EQ(orient2d({c, c}, {c + 3, c + 3}, {c + 7, c + 8}), 1);
  EXPECT_EQ(orient2d({c, c}, {c + 3, c + 3}, {c + 8, c + 7}), -1);
}

// The exponent that brings the points' box to about 1, where that is exact; 0 for boxes
// already in range, for no points, one point or a coordinate that is not finite. An extent
// merged from parts equals the whole one's.
TEST(ExactScale, ExponentFromTheExtent) {
  const std::vector<Point> tiny = {{1e-300, 2e-300}, {3e-300, -1e-300}};
  const int k = exact_scale_exponent(tiny);
  EXPECT_GT(k, 900);
  EXPECT_LT(std::ldexp(3e-300, k), 4.0);
  EXPECT_GE(std::ldexp(2e-300, k), 0.5);
  EXPECT_LT(exact_scale_exponent(std::vector<Point>{{1e300, 0}, {-1e300, 5e299}}), -900);
  EXPECT_EQ(exact_scale_exponent(std::vector<Point>{{0.5, 2}, {1, 3}}), 0);
  EXPECT_EQ(exact_scale_exponent(std::vector<Point>{}), 0);
  EXPECT_EQ(exact_scale_exponent(std::vector<Point>{{1e-300, 1e-300}}), 0);
  EXPECT_EQ(exact_scale_exponent(std::vector<Point>{{0, 0}, {0, 0}}), 0);
  // Scaling would make the subnormal coordinate's neighbour lose bits: no scale.
  EXPECT_EQ(exact_scale_exponent(std::vector<Point>{{1e200, 0}, {-1e200, 4.9e-324}}), 0);
  for (const std::size_t bad : {0u, 1u}) {
    std::vector<Point> pts = tiny;
    pts[bad].x = std::nan("");
    EXPECT_EQ(exact_scale_exponent(pts), 0) << bad;
    EXPECT_FALSE(extent_of(pts).finite);
    pts[bad].x = -INFINITY;
    EXPECT_FALSE(extent_of(pts).finite);
  }
  std::vector<Point> many;
  for (int i = 0; i < 1000; ++i) many.push_back({std::ldexp(1.0 + i, -700), std::ldexp(500.0 - i, -690)});
  Extent parts;
  for (std::size_t b = 0; b < many.size(); b += 333)
    parts.add(extent_of(std::span<const Point>(many).subspan(b, std::min<std::size_t>(333, many.size() - b))));
  const Extent whole = extent_of(many);
  EXPECT_EQ(parts.x0, whole.x0);
  EXPECT_EQ(parts.x1, whole.x1);
  EXPECT_EQ(parts.y0, whole.y0);
  EXPECT_EQ(parts.y1, whole.y1);
  EXPECT_EQ(parts.smallest, whole.smallest);
  EXPECT_EQ(parts.largest, whole.largest);
  EXPECT_EQ(exact_scale_exponent(parts), exact_scale_exponent(many));
  EXPECT_NE(exact_scale_exponent(many), 0);
}

TEST(Incircle, UnitCircleExactAndOneUlpOff) {
  const Point a{1, 0}, b{0, 1}, c{-1, 0};
  EXPECT_EQ(incircle(a, b, c, {0, -1}), 0);
  EXPECT_EQ(incircle(a, b, c, {0, std::nextafter(-1.0, 0.0)}), 1);
  EXPECT_EQ(incircle(a, b, c, {0, std::nextafter(-1.0, -2.0)}), -1);
  EXPECT_EQ(incircle(a, b, c, {0, 0}), 1);
  EXPECT_EQ(incircle(a, b, c, {5, 5}), -1);
}

TEST(Incircle, CocircularIntegerPointsNear2To53) {
  // Points at distance 5 from (c, c): (3,4), (-3,4), (5,0), (0,-5) and so on.
  for (double c : {0.0, 1e15, std::ldexp(1.0, 52), std::ldexp(1.0, 53) - 16}) {
    const Point a{c + 5, c}, b{c + 3, c + 4}, d{c - 3, c + 4};
    EXPECT_EQ(incircle(a, b, d, {c, c - 5}), 0) << c;
    EXPECT_EQ(incircle(a, b, d, {c - 4, c - 3}), 0) << c;
    EXPECT_EQ(incircle(a, b, d, {c + 5, c + 1}), -1) << c;  // 26 > 25
    EXPECT_EQ(incircle(a, b, d, {c + 4, c - 2}), 1) << c;  // 20 < 25
  }
}

TEST(Incircle, ExtremeScales) {
  const Point a{1, 0}, b{0, 1}, c{-1, 0}, on{0, -1}, in{0.5, 0.5}, out{1, 1};
  for (int e : {-1070, -1000, -600, -500, -150, 150, 500, 600, 1000}) {
    auto s = [e](Point v) { return Point{std::ldexp(v.x, e), std::ldexp(v.y, e)}; };
    EXPECT_EQ(incircle(s(a), s(b), s(c), s(on)), 0) << e;
    EXPECT_EQ(incircle(s(a), s(b), s(c), s(in)), 1) << e;
    EXPECT_EQ(incircle(s(a), s(b), s(c), s(out)), -1) << e;
  }
}

// Huge and tiny coordinates go through the filter again, rescaled by a power of two; the
// answer must stay the exact one, also for near-degenerate points and for scales that are not
// powers of two (1e300, 1e-300) or that push coordinates into the subnormals.
TEST(Predicates, RescaledFilterAgreesWithIntegers) {
  std::uint64_t state = 12345;
  auto next = [&state] {  // a small LCG: values 0..7 and a few ulps off
    state = state * 6364136223846793005u + 1442695040888963407u;
    return static_cast<int>(state >> 60);
  };
  auto value = [&] {
    const int v = next();
    double x = v % 8 - 3;
    if (v >= 8) x = std::nextafter(x, v % 2 ? 100.0 : -100.0);
    return x;
  };
  int orients = 0, circles = 0;
  for (double scale : {0x1p-1062, 0x1p-700, 1e-300, 0x1p-300, 0x1p300, 1e300, 0x1p700, 0x1p1018}) {
    for (int trial = 0; trial < 3000; ++trial) {
      Point p[4];
      for (Point& q : p) q = {value() * scale, value() * scale};
      const int o = orient2d(p[0], p[1], p[2]);
      ASSERT_EQ(o, orient2d_exact(p[0], p[1], p[2])) << scale << " " << trial;
      if (o <= 0) continue;
      ASSERT_EQ(incircle(p[0], p[1], p[2], p[3]), incircle_exact(p[0], p[1], p[2], p[3])) << scale << " " << trial;
      orients += 1;
      circles += incircle(p[0], p[1], p[2], p[3]) == 0;
    }
  }
  EXPECT_GT(orients, 1000);
  EXPECT_GT(circles, 10);  // exactly cocircular quadruples among them
}

// The filter's answer, whenever it gives one, is the exact sign: points drawn on a circle and
// rounded to doubles are within a few rounding errors of cocircular, where the filter's bounds
// are tight; among them are far offsets and scales down to the subnormals.
TEST(Incircle, FilterIsRightWheneverItDecides) {
  std::uint64_t state = 99;
  auto uniform = [&state] {
    state = state * 6364136223846793005u + 1442695040888963407u;
    return static_cast<double>(state >> 11) * 0x1p-53;
  };
  int decided = 0, abstained = 0;
  const double scales[][2] = {{0, 1}, {1e6, 1}, {3e12, 0.5}, {-7.5, 1e-8}, {1e-300, 1e-303}, {0, 0x1p-1020}};
  for (const auto& [centre, radius] : scales) {
    for (int trial = 0; trial < 20000; ++trial) {
      Point p[4];
      for (Point& q : p) {
        const double angle = 6.283185307179586 * uniform();
        q = {centre + radius * std::cos(angle), centre + radius * std::sin(angle)};
      }
      if (orient2d(p[0], p[1], p[2]) <= 0) continue;
      const int f = incircle_filter(p[0], p[1], p[2], p[3]);
      if (f == 0) {
        ++abstained;
        continue;
      }
      ++decided;
      ASSERT_EQ(f, incircle_exact(p[0], p[1], p[2], p[3])) << centre << " " << radius << " " << trial;
    }
  }
  EXPECT_GT(decided, 10000);
  EXPECT_GT(abstained, 1000);
}

TEST(Incircle, NearlyCocircularAfterShift) {
  // Shifted by 1e15, the unit square's corners stay exact and cocircular; moving the fourth
  // corner by one unit in the last place decides the sign.
  const double s = 1e15;
  const Point a{s, s}, b{s + 1, s}, c{s + 1, s + 1};
  EXPECT_EQ(incircle(a, b, c, {s, s + 1}), 0);
  EXPECT_EQ(incircle(a, b, c, {s, std::nextafter(s + 1, 0.0)}), 1);
  EXPECT_EQ(incircle(a, b, c, {s, std::nextafter(s + 1, 2 * s)}), -1);
}

TEST(IncircleSos, NeverZeroAndConsistentOnCocircularQuads) {
  // Corners of squares and of the 3-4-5 circle, in counter-clockwise order.
  const Point quads[][4] = {
      {{0, 0}, {1, 0}, {1, 1}, {0, 1}},
      {{5, 0}, {3, 4}, {-3, 4}, {0, -5}},
      {{1e15, 1e15}, {1e15 + 2, 1e15}, {1e15 + 2, 1e15 + 2}, {1e15, 1e15 + 2}},
  };
  for (const auto& q : quads) {
    for (int r = 0; r < 4; ++r) {
      const Point& a = q[r];
      const Point& b = q[(r + 1) % 4];
      const Point& c = q[(r + 2) % 4];
      const Point& d = q[(r + 3) % 4];
      ASSERT_EQ(incircle(a, b, c, d), 0);
      const int s = incircle_sos(a, b, c, d);
      EXPECT_NE(s, 0);
      // The same circle test under rotation of the triangle.
      EXPECT_EQ(s, incircle_sos(b, c, a, d));
      EXPECT_EQ(s, incircle_sos(c, a, b, d));
      // Exactly one diagonal of the quad is legal: a c is legal iff b d is not.
      EXPECT_EQ(s, -incircle_sos(b, c, d, a));
    }
  }
}

TEST(IncircleSos, AgreesWithExactWhenNotCocircular) {
  const Point a{0, 0}, b{4, 0}, c{0, 3};
  EXPECT_EQ(incircle_sos(a, b, c, {1, 1}), 1);
  EXPECT_EQ(incircle_sos(a, b, c, {9, 9}), -1);
}

TEST(Lattice, WhichPointSetsQualify) {
  const std::vector<Point> grid = {{0, 0}, {1, 0}, {4096, 4096}, {-3, 7}};
  EXPECT_TRUE(on_small_lattice(grid.data(), 3));
  EXPECT_FALSE(on_small_lattice(grid.data(), 4));  // the box is 4099 wide
  const std::vector<Point> offset = {{1e15, -1e15}, {1e15 + 4096, -1e15 + 1}};
  EXPECT_TRUE(on_small_lattice(offset.data(), 2));  // far from 0, but integers in a small box
  const std::vector<Point> half = {{0, 0}, {0.5, 1}};
  EXPECT_FALSE(on_small_lattice(half.data(), 2));
  const std::vector<Point> big = {{0x1p52, 0}, {0x1p52 + 2, 0}};
  EXPECT_FALSE(on_small_lattice(big.data(), 2));  // differences of such are not always exact
  EXPECT_FALSE(on_small_lattice(grid.data(), 0));
}

TEST(Lattice, PredicatesAgreeWithTheFilteredOnes) {
  // Every quadruple of a 5 x 5 grid within a 4096 box: many collinear triples and cocircular
  // quadruples, the cases where the lattice forms skip the filter.
  std::vector<Point> pts;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) pts.push_back({i * 1023.0 - 2000, j * 1024.0 + 1e12});
  ASSERT_TRUE(on_small_lattice(pts.data(), static_cast<std::uint32_t>(pts.size())));
  long ties = 0, collinear = 0;
  for (const Point& a : pts)
    for (const Point& b : pts)
      for (const Point& c : pts) {
        const int o = orient2d(a, b, c);
        ASSERT_EQ(orient2d_lattice(a, b, c), o);
        collinear += o == 0;
        if (o <= 0) continue;
        for (const Point& d : pts) {
          if (d == a || d == b || d == c) continue;
          ties += incircle(a, b, c, d) == 0;
          ASSERT_EQ(incircle_sos_lattice(a, b, c, d), incircle_sos(a, b, c, d));
        }
      }
  EXPECT_GT(ties, 0);
  EXPECT_GT(collinear, 0);
}

TEST(PublicPredicates, TheLibrarysSigns) {
  // A line of exactly representable points, a unit square (cocircular), near-collinear
  // triples a unit in the last place apart, huge and tiny coordinates.
  const Point a{0.5, 0.5}, b{12, 12}, c{24, 24};
  EXPECT_EQ(ridt::orientation(a, b, c), 0);
  EXPECT_EQ(ridt::orientation(a, b, {24, std::nextafter(24.0, 25.0)}), 1);
  EXPECT_EQ(ridt::orientation(a, b, {24, std::nextafter(24.0, 23.0)}), -1);
  EXPECT_EQ(ridt::in_circle({0, 0}, {1, 0}, {1, 1}, {0, 1}), 0);
  EXPECT_EQ(ridt::in_circle({0, 0}, {1, 0}, {1, 1}, {0.5, 0.5}), 1);
  EXPECT_EQ(ridt::in_circle({0, 0}, {1, 0}, {1, 1}, {2, 2}), -1);
  for (const double s : {1e-300, 1e300}) {
    EXPECT_EQ(ridt::orientation({0, 0}, {s, 0}, {0, s}), 1);
    EXPECT_EQ(ridt::in_circle({0, 0}, {s, 0}, {s, s}, {0, s}), 0);
  }
  EXPECT_EQ(ridt::orientation(a, b, c), orient2d(a, b, c));
}

}  // namespace
}  // namespace ridt::detail
