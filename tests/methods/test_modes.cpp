// Insertion orders and location modes: the paper's random order with the DAG,
// BRIO with the DAG, BRIO with walking. Each result passes the exact validator,
// and all give the same triangles, hull and duplicates.
#include <gtest/gtest.h>

#include <cmath>

#include "helpers.hpp"
#include "ridt/generate.hpp"

namespace ridt::test {
namespace {

struct Mode {
  Order order;
  Locate locate;
  const char* name;
};
constexpr Mode kModes[] = {{Order::Random, Locate::Dag, "random_dag"},
                           {Order::Brio, Locate::Dag, "brio_dag"},
                           {Order::Brio, Locate::Walk, "brio_walk"},
                           {Order::Random, Locate::Root, "random_root"}};

Options with(const Mode& m, std::uint64_t seed = 1) {
  Options o;
  o.order = m.order;
  o.locate = m.locate;
  o.seed = seed;
  return o;
}

// Every mode passes the validator and agrees with the others on everything but
// the order.
void expect_all_modes_agree(const std::vector<Point>& pts, const std::string& what) {
  const Triangulation first = triangulate_checked(pts, with(kModes[0]));
  const TriangleSet expected = canonical(first.triangles);
  for (const Mode& m : kModes) {
    for (std::uint64_t seed : {1u, 7u}) {
      const Triangulation t = triangulate_checked(pts, with(m, seed));
      EXPECT_EQ(canonical(t.triangles), expected) << what << ", " << m.name << ", seed " << seed;
      EXPECT_EQ(t.hull.size(), first.hull.size()) << what << ", " << m.name;
      ASSERT_EQ(t.duplicates.size(), first.duplicates.size()) << what << ", " << m.name;
      for (std::size_t i = 0; i < t.duplicates.size(); ++i) {
        EXPECT_EQ(t.duplicates[i].dropped, first.duplicates[i].dropped);
        EXPECT_EQ(t.duplicates[i].kept, first.duplicates[i].kept);
      }
    }
  }
}

class ModesOnDistributions : public ::testing::TestWithParam<std::tuple<Distribution, int>> {};

TEST_P(ModesOnDistributions, AgreeAndPassTheValidator) {
  const auto [d, n] = GetParam();
  expect_all_modes_agree(generate(d, n, 23), std::string(to_string(d)));
}

INSTANTIATE_TEST_SUITE_P(Sizes, ModesOnDistributions,
                         ::testing::Combine(::testing::Values(Distribution::Uniform, Distribution::Normal,
                                                              Distribution::Grid, Distribution::Clusters),
                                            ::testing::Values(10, 1000, 100000)),
                         [](const auto& info) {
                           return std::string(to_string(std::get<0>(info.param))) + "_" +
                               std::to_string(std::get<1>(info.param));
                         });

TEST(Modes, DegenerateSets) {
  std::vector<Point> lines, polygon, dup = generate(Distribution::Uniform, 3000, 4), cocircular;
  for (int i = 0; i < 700; ++i) lines.push_back({double(i), 0}), lines.push_back({i + 0.5, 5});
  for (int i = 0; i < 1000; ++i) polygon.push_back({std::cos(2 * M_PI * i / 1000), std::sin(2 * M_PI * i / 1000)});
  for (int i = 0; i < 900; ++i) dup.push_back(dup[(i * 7) % 3000]);
  const long r2 = 5L * 5 * 13 * 13 * 17 * 17;  // many integer points on one circle
  for (long x = -1105; x <= 1105; ++x) {
    const long y2 = r2 - x * x;
    const long y = std::lround(std::sqrt(double(y2)));
    if (y * y == y2) {
      cocircular.push_back({double(x), double(y)});
      if (y != 0) cocircular.push_back({double(x), double(-y)});
    }
  }
  expect_all_modes_agree(lines, "two lines");
  expect_all_modes_agree(polygon, "1000-gon");
  expect_all_modes_agree(dup, "duplicates");
  expect_all_modes_agree(cocircular, "cocircular");
  std::vector<Point> grid = generate(Distribution::Grid, 2500, 1);
  for (double s : {std::ldexp(1.0, -500), 1e-9, 1e9, std::ldexp(1.0, 500)}) {
    std::vector<Point> scaled = grid;
    for (Point& p : scaled) p = {p.x * s, p.y * s};
    expect_all_modes_agree(scaled, "grid scaled");
  }
  for (const auto& few : std::vector<std::vector<Point>>{{}, {{1, 2}}, {{0, 0}, {1, 1}}, {{0, 0}, {1, 0}, {0, 1}}})
    expect_all_modes_agree(few, "a few points");
}

TEST(Modes, DelaunatorFixturesAtEveryScale) {
  for (const char* name : kDelaunatorFixtures) {
    const std::string path = fixture_path(name);
    const std::vector<Point> base = read_json_points(path);
    ASSERT_GT(base.size(), 2u) << path;
    for (double s : {1.0, 1e-9, 1e-2, 1e2, 1e9}) {
      std::vector<Point> pts = base;
      for (Point& p : pts) p = {p.x * s, p.y * s};
      expect_all_modes_agree(pts, std::string(name) + " x " + std::to_string(s));
    }
  }
}

TEST(Modes, WalkingKeepsNoDag) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 5000, 2);
  EXPECT_GT(triangulate(pts, with(kModes[1])).stats.dag_nodes, 0u);
  EXPECT_EQ(triangulate(pts, with(kModes[2])).stats.dag_nodes, 0u);
}

TEST(Modes, WalkingProfilesToo) {
  Options o = with(kModes[2]);
  o.experiment.profile = true;
  const Triangulation t = triangulate_checked(generate(Distribution::Clusters, 5000, 2), o);
  EXPECT_GT(t.stats.time_locate_s, 0);
}

TEST(Modes, RefusedCombinationsSayWhy) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 100, 2);
  Options o = with(kModes[2]);
  o.method = Method::Optimistic;
  try {
    triangulate(pts, o);
    ADD_FAILURE() << "walking with a threaded method should be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("serial and partition methods only"), std::string::npos) << e.what();
  }
  o = with({Order::Random, Locate::Walk, "random_walk"});
  EXPECT_THROW(triangulate(pts, o), InputError);
}

}  // namespace
}  // namespace ridt::test
