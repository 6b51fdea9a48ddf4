#include <gtest/gtest.h>

#include <cmath>

#include "ridt/generate.hpp"

namespace ridt {
namespace {

TEST(Generate, SameSeedSamePointsOtherSeedOtherPoints) {
  for (Distribution d : {Distribution::Uniform, Distribution::Normal, Distribution::Clusters}) {
    EXPECT_EQ(generate(d, 1000, 5), generate(d, 1000, 5));
    EXPECT_NE(generate(d, 1000, 5), generate(d, 1000, 6));
  }
}

// Pinned values: the files must be bit-identical on every machine.
TEST(Generate, PinnedBits) {
  const auto u = generate(Distribution::Uniform, 2, 1);
  const auto n = generate(Distribution::Normal, 2, 1);
  EXPECT_EQ(u.size(), 2u);
  // Regenerate these by printing with %a if the generator is ever changed on purpose.
  EXPECT_EQ(u[0].x, 0x1.278b7b7ce8d71p-1);
  EXPECT_EQ(n[1].y, 0x1.8c3270303d0e3p-1);
}

TEST(Generate, Moments) {
  auto mean_var = [](const std::vector<Point>& p) {
    double m = 0, v = 0;
    for (const Point& q : p) m += q.x;
    m /= p.size();
    for (const Point& q : p) v += (q.x - m) * (q.x - m);
    return std::pair{m, v / p.size()};
  };
  const auto [um, uv] = mean_var(generate(Distribution::Uniform, 100000, 3));
  EXPECT_NEAR(um, 0.5, 0.01);
  EXPECT_NEAR(uv, 1.0 / 12, 0.002);
  const auto [nm, nv] = mean_var(generate(Distribution::Normal, 100000, 3));
  EXPECT_NEAR(nm, 0.0, 0.02);
  EXPECT_NEAR(nv, 1.0, 0.02);
}

TEST(Generate, GridIsIntegerRows) {
  const auto g = generate(Distribution::Grid, 10, 1);
  ASSERT_EQ(g.size(), 10u);
  EXPECT_EQ(g[0], (Point{0, 0}));
  EXPECT_EQ(g[3], (Point{3, 0}));
  EXPECT_EQ(g[4], (Point{0, 1}));
  EXPECT_EQ(g[9], (Point{1, 2}));
}

TEST(Generate, Names) {
  EXPECT_EQ(parse<Distribution>("clusters"), Distribution::Clusters);
  EXPECT_EQ(to_string(Distribution::Grid), "grid");
  EXPECT_THROW(parse<Distribution>("gaussian"), InputError);
  for (const Named<Method>& m : names<Method>()) EXPECT_EQ(parse<Method>(m.name), m.value);
  try {
    parse<Locate>("jump");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "unknown location 'jump' (use auto, dag, walk or root)");
  }
}

}  // namespace
}  // namespace ridt
