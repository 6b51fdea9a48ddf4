// The incremental triangulation (ridt/incremental.hpp): after every batch of points, the same
// arrays as a fresh triangulate() of all of them in canonical order, on every distribution,
// with points inside and outside the hull, duplicates old and new, collinear and cocircular
// sets, and from a start with no triangle.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "helpers.hpp"
#include "ridt/check.hpp"
#include "ridt/generate.hpp"
#include "ridt/incremental.hpp"

namespace ridt {
namespace {

Options canonical() {
  Options o;
  o.canonical_order = true;
  return o;
}

// Adds `batches` to a triangulation of `first`, checking it against a fresh build each time.
void expect_fresh_after_each(std::vector<Point> first, const std::vector<std::vector<Point>>& batches) {
  IncrementalTriangulation inc(first, canonical());
  std::vector<Point> all = first;
  for (const auto& batch : batches) {
    inc.add(batch);
    all.insert(all.end(), batch.begin(), batch.end());
    const Triangulation fresh = triangulate(all, canonical());
    const Triangulation& got = inc.triangulation();
    ASSERT_EQ(got.triangles, fresh.triangles) << all.size() << " points";
    EXPECT_EQ(got.neighbors, fresh.neighbors);
    EXPECT_EQ(got.hull, fresh.hull);
    ASSERT_EQ(got.duplicates.size(), fresh.duplicates.size());
    for (std::size_t k = 0; k < got.duplicates.size(); ++k) {
      EXPECT_EQ(got.duplicates[k].dropped, fresh.duplicates[k].dropped);
      EXPECT_EQ(got.duplicates[k].kept, fresh.duplicates[k].kept);
    }
    EXPECT_EQ(got.warning, fresh.warning);
    EXPECT_EQ(got.stats.distinct, fresh.stats.distinct);
    EXPECT_TRUE(check(all, got.triangles).valid);
    EXPECT_EQ(inc.points().size(), all.size());
  }
}

std::vector<Point> slice(const std::vector<Point>& p, std::size_t from, std::size_t to) {
  return {p.begin() + static_cast<std::ptrdiff_t>(from), p.begin() + static_cast<std::ptrdiff_t>(to)};
}

class IncrementalOf : public ::testing::TestWithParam<Distribution> {};

TEST_P(IncrementalOf, EqualsAFreshBuildAfterEveryBatch) {
  const std::vector<Point> pts = generate(GetParam(), 6000, 11);
  // Small first sets grow their hull: later points fall outside it.
  expect_fresh_after_each(slice(pts, 0, 10), {slice(pts, 10, 11), slice(pts, 11, 500), slice(pts, 500, 6000)});
}

INSTANTIATE_TEST_SUITE_P(Distributions, IncrementalOf, test::every_distribution(), test::distribution_name);

TEST(Incremental, DuplicatesOldAndNew) {
  const std::vector<Point> grid = generate(Distribution::Grid, 400, 3);
  std::vector<Point> again = slice(grid, 0, 50);
  again.push_back({1e9, 1e9});
  again.push_back({1e9, 1e9});
  again.push_back(grid[7]);
  expect_fresh_after_each(slice(grid, 0, 200), {slice(grid, 200, 400), again, {{1e9, 1e9}}});
}

TEST(Incremental, FromNoTriangleAndOnLines) {
  // Collinear first, then still collinear, then a point off the line; one point; duplicates.
  std::vector<Point> line, more, off = {{0.5, 3}};
  for (int k = 0; k < 20; ++k) line.push_back({double(k), 2.0 * k});
  for (int k = -5; k < 0; ++k) more.push_back({double(k), 2.0 * k});
  expect_fresh_after_each(line, {more, off});
  expect_fresh_after_each({{1, 1}}, {{{1, 1}}, {{2, 2}}, {{0, 5}, {3, 3}}});
  // Cocircular: a regular grid's squares, added around a first square.
  std::vector<Point> square = {{0, 0}, {1, 0}, {0, 1}, {1, 1}}, ring;
  for (int i = -2; i <= 3; ++i)
    for (int j = -2; j <= 3; ++j)
      if (i < 0 || i > 1 || j < 0 || j > 1) ring.push_back({double(i), double(j)});
  expect_fresh_after_each(square, {ring});
}

TEST(Incremental, DelaunatorsRobustnessFixturesInThreeBatches) {
  for (const char* name : test::kDelaunatorFixtures) {
    SCOPED_TRACE(name);
    const std::vector<Point> pts = test::read_json_points(test::fixture_path(name));
    const std::size_t a = pts.size() / 3, b = 2 * pts.size() / 3;
    expect_fresh_after_each(slice(pts, 0, a), {slice(pts, a, b), slice(pts, b, pts.size())});
  }
}

TEST(Incremental, LargeCavitiesAroundACircle) {
  // Many cocircular points, then points whose cavities take most of the mesh: the centre, and
  // points far outside a hull of thousands of vertices.
  std::vector<Point> circle;
  for (int k = 0; k < 3000; ++k) circle.push_back({std::cos(k * 0.00209439510239), std::sin(k * 0.00209439510239)});
  expect_fresh_after_each(circle, {{{0, 0}}, {{1e6, 3}}, {{-1e6, -1e6}, {0.25, 0.5}}});
}

TEST(Incremental, HugeAndTinyCoordinates) {
  for (const double scale : {1e-300, 1e300}) {
    std::vector<Point> pts = generate(Distribution::Uniform, 600, 5);
    for (Point& p : pts) p = {p.x * scale, p.y * scale};
    expect_fresh_after_each(slice(pts, 0, 100), {slice(pts, 100, 600)});
  }
}

TEST(Incremental, RefusesPointsThatAreNotFinite) {
  IncrementalTriangulation inc(generate(Distribution::Uniform, 100, 1));
  const Triangulation before = inc.triangulation();
  EXPECT_THROW(inc.add(std::vector<Point>{{0.5, 0.5}, {NAN, 0}}), InputError);
  EXPECT_EQ(inc.triangulation().triangles, before.triangles);
  EXPECT_EQ(inc.points().size(), 100u);
}

}  // namespace
}  // namespace ridt
