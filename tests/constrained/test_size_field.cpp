// Size fields (ridt/size_field.hpp, Quality::size): the values each kind gives (a grid, a
// background mesh, scattered points), every triangle of a mesh refined to one within the size
// at its centroid with the angle bound and the exact validator, the mesh graded by the field,
// the same mesh on any number of threads, and bad fields refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "ridt/check.hpp"
#include "ridt/constrained.hpp"
#include "ridt/generate.hpp"
#include "ridt/size_field.hpp"

namespace ridt::test {
namespace {

double longest(const Point& a, const Point& b, const Point& c) {
  auto d = [](const Point& p, const Point& q) { return std::hypot(p.x - q.x, p.y - q.y); };
  return std::max({d(a, b), d(b, c), d(c, a)});
}

// The unit square with a square hole.
Pslg holed_square() {
  Pslg g;
  g.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.4, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.4, 0.6}};
  g.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
  g.holes = {{0.5, 0.5}};
  return g;
}

struct Meshed {
  ConstrainedTriangulation t;
  std::vector<Point> all;  // the input's points, then those added
  std::vector<Point> centroids;
};

// g meshed as q asks with `threads`, checked exactly (the angle bound with it).
Meshed meshed(const Pslg& g, const Quality& q, unsigned threads = 1) {
  Domain d;
  d.holes = g.holes;
  Options o;
  o.threads = threads;
  Meshed m{triangulate_constrained(g.points, g.segments, o, d, q), g.points, {}};
  EXPECT_TRUE(m.t.warning.empty()) << m.t.warning;
  m.all.insert(m.all.end(), m.t.steiner.begin(), m.t.steiner.end());
  MeshSpec spec;
  spec.edges = m.t.edges;
  spec.segments = g.segments;
  spec.input_points = g.points.size();
  spec.holes = g.holes;
  spec.min_angle = q.min_angle;
  const CheckResult r = check_mesh(m.all, m.t.triangles, spec);
  EXPECT_TRUE(r.valid) << r.message;
  for (std::size_t k = 0; k < m.t.size(); ++k) {
    const Point &a = m.all[m.t.triangles[3 * k]], &b = m.all[m.t.triangles[3 * k + 1]],
                &c = m.all[m.t.triangles[3 * k + 2]];
    m.centroids.push_back({a.x / 3 + b.x / 3 + c.x / 3, a.y / 3 + b.y / 3 + c.y / 3});
  }
  return m;
}

// Every triangle's longest edge within the field's size at its centroid.
void expect_within(const Meshed& m, const SizeField& field) {
  const std::vector<double> h = field.sizes(m.centroids);
  for (std::size_t k = 0; k < m.t.size(); ++k) {
    const Point &a = m.all[m.t.triangles[3 * k]], &b = m.all[m.t.triangles[3 * k + 1]],
                &c = m.all[m.t.triangles[3 * k + 2]];
    ASSERT_LE(longest(a, b, c), h[k] * (1 + 1e-12)) << "triangle " << k;
  }
}

TEST(SizeField, GridIsBilinearAndClampedBeyond) {
  // h = 1 + x + 2y on a 3 by 2 grid over [0, 2] x [0, 1]: bilinear is exact on it.
  const std::vector<double> v = {1, 2, 3, 3, 4, 5};
  const SizeField f = SizeField::on_grid(v, 3, 2, 0, 0, 2, 1);
  const std::vector<Point> at = {{0, 0}, {2, 1}, {0.5, 0.25}, {1.5, 0.75}, {-5, 0.5}, {9, 9}};
  const std::vector<double> h = f.sizes(at);
  const std::vector<double> want = {1, 5, 2, 4, 2, 5};
  for (std::size_t k = 0; k < at.size(); ++k) EXPECT_NEAR(h[k], want[k], 1e-14) << k;
  // An image's rows, the top first (y1 < y0): the same field.
  const std::vector<double> flipped = {3, 4, 5, 1, 2, 3};
  const std::vector<double> g = SizeField::on_grid(flipped, 3, 2, 0, 1, 2, 0).sizes(at);
  for (std::size_t k = 0; k < at.size(); ++k) EXPECT_NEAR(g[k], want[k], 1e-14) << k;
}

TEST(SizeField, MeshIsLinearInItsTrianglesAndNearestBeyond) {
  // Two triangles of the unit square, one clockwise, h = 1 + x + 2y; a point beyond takes its
  // nearest vertex's value.
  const std::vector<Point> v = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<VertexId> t = {0, 1, 2, 0, 3, 2};
  const std::vector<double> values = {1, 2, 4, 3};
  for (const SizeField& f : {SizeField::on_mesh(v, t, values), SizeField::on_points(v, values)}) {
    const std::vector<Point> at = {{0.25, 0.25}, {0.75, 0.5}, {0.5, 0.5}, {1, 1}, {3, 0.1}, {-1, 2}};
    const std::vector<double> h = f.sizes(at);
    const std::vector<double> want = {1.75, 2.75, 2.5, 4, 2, 3};
    for (std::size_t k = 0; k < at.size(); ++k) EXPECT_NEAR(h[k], want[k], 1e-14) << k;
  }
}

TEST(SizeField, EveryTriangleWithinItsSizeAndTheMeshGrades) {
  // Small at the left side, ten times as large at the right.
  const std::vector<double> v = {0.01, 0.1, 0.01, 0.1};
  const SizeField field = SizeField::on_grid(v, 2, 2, 0, 0, 1, 1);
  Quality q;
  q.min_angle = 28;
  q.size = field;
  const Meshed m = meshed(holed_square(), q);
  expect_within(m, field);
  std::size_t left = 0, right = 0;
  for (const Point& c : m.centroids) (c.x < 0.5 ? left : right) += 1;
  EXPECT_GT(left, 5 * right) << left << " on the left, " << right << " on the right";
  EXPECT_GT(m.t.size(), 2000u);
}

TEST(SizeField, TheSameMeshOnAnyNumberOfThreadsAndFromAFunction) {
  const std::vector<Point> p = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.5, 0.5}};
  const std::vector<double> v = {0.02, 0.05, 0.05, 0.02, 0.2};
  const SizeField field = SizeField::on_points(p, v);
  Quality q;
  q.min_angle = 30;
  q.size = field;
  const Meshed one = meshed(holed_square(), q, 1);
  expect_within(one, field);
  for (const unsigned threads : {2u, 3u, 8u}) {
    const Meshed m = meshed(holed_square(), q, threads);
    EXPECT_EQ(m.t.triangles, one.t.triangles) << threads << " threads";
    EXPECT_EQ(m.t.steiner, one.t.steiner) << threads << " threads";
  }
  // The field given as a function of the caller's: the same values, so the same mesh.
  std::size_t calls = 0, asked = 0;
  q.size = SizeField::of([&](std::span<const Point> at, std::span<double> h) {
    ++calls, asked += at.size();
    field.sizes(at, h);
  });
  const Meshed f = meshed(holed_square(), q);
  EXPECT_EQ(f.t.triangles, one.t.triangles);
  EXPECT_LT(calls * 100, asked) << "the field is asked for many triangles a call";
}

TEST(SizeField, WithTheAreaBoundTheSmallerWins) {
  Quality q;
  q.min_angle = 20;
  q.max_area = 0.0005;
  q.size = SizeField::uniform(0.2);
  const Meshed m = meshed(holed_square(), q);
  expect_within(m, q.size);
  for (std::size_t k = 0; k < m.t.size(); ++k) {
    const Point &a = m.all[m.t.triangles[3 * k]], &b = m.all[m.t.triangles[3 * k + 1]],
                &c = m.all[m.t.triangles[3 * k + 2]];
    ASSERT_LE(((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / 2, q.max_area);
  }
}

TEST(SizeField, ARefinedMeshKeepsItToo) {
  const Pslg g = holed_square();
  Domain d;
  d.holes = g.holes;
  const ConstrainedTriangulation coarse = triangulate_constrained(g.points, g.segments, {}, d);
  Quality q;
  q.min_angle = 25;
  q.size = SizeField::uniform(0.05);
  const ConstrainedTriangulation t = refine_mesh(g.points, coarse.triangles, g.segments, q);
  std::vector<Point> all = g.points;
  all.insert(all.end(), t.steiner.begin(), t.steiner.end());
  for (std::size_t k = 0; k < t.size(); ++k)
    ASSERT_LE(longest(all[t.triangles[3 * k]], all[t.triangles[3 * k + 1]], all[t.triangles[3 * k + 2]]), 0.05);
}

TEST(SizeField, GradationMakesAConeOfASingleSmallValueOnAGrid) {
  // h = 1 on a 41 x 41 grid of spacing 0.05 but 0.01 at its centre; graded by 0.2 it becomes
  // min(1, 0.01 + 0.2 * the grid path to the centre), whose length through rows, columns and
  // diagonals is 0.05 ((sqrt 2 - 1) min(di, dj) + max(di, dj)).
  const std::size_t n = 41;
  std::vector<double> v(n * n, 1.0);
  v[20 * n + 20] = 0.01;
  const double g = 0.2, s = 0.05;
  const SizeField f = SizeField::on_grid(v, n, n, 0, 0, 2, 2, g);
  std::vector<Point> nodes;
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) nodes.push_back({static_cast<double>(i) * s, static_cast<double>(j) * s});
  const std::vector<double> h = f.sizes(nodes);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const double di = std::fabs(double(i) - 20), dj = std::fabs(double(j) - 20);
      const double path = s * ((std::sqrt(2.0) - 1) * std::min(di, dj) + std::max(di, dj));
      ASSERT_NEAR(h[j * n + i], std::min(1.0, 0.01 + g * path), 1e-12) << i << ", " << j;
    }
  // Without a gradation (or 0), the values as given.
  EXPECT_EQ(SizeField::on_grid(v, n, n, 0, 0, 2, 2, 0).sizes(nodes), v);
  EXPECT_EQ(SizeField::on_grid(v, n, n, 0, 0, 2, 2).sizes(nodes), v);
}

TEST(SizeField, GradationBoundsTheGrowthAlongEveryEdgeOfAMesh) {
  // Scattered points with sizes at random over two orders of magnitude: graded, the values at
  // the ends of every edge of their triangulation differ by at most 0.3 times its length; none
  // rose, and the least is kept.
  const std::vector<Point> p = generate(Distribution::Uniform, 3000, 4);
  std::vector<double> v(p.size());
  for (std::size_t k = 0; k < v.size(); ++k) v[k] = std::exp2(-7.0 * static_cast<double>((k * 7919) % 1000) / 1000);
  const double g = 0.3;
  const std::vector<double> h = SizeField::on_points(p, v, g).sizes(p);
  const Triangulation t = triangulate(p, {});
  for (std::size_t k = 0; k < t.triangles.size(); ++k) {
    const VertexId a = t.triangles[k], b = t.triangles[k - k % 3 + (k + 1) % 3];
    const double length = std::hypot(p[a].x - p[b].x, p[a].y - p[b].y);
    ASSERT_LE(std::fabs(h[a] - h[b]), g * length * (1 + 1e-12) + 1e-15) << a << " - " << b;
  }
  for (std::size_t k = 0; k < v.size(); ++k) ASSERT_LE(h[k], v[k]);
  EXPECT_EQ(*std::min_element(h.begin(), h.end()), *std::min_element(v.begin(), v.end()));
  // A mesh refined to the graded field keeps it.
  Quality q;
  q.min_angle = 25;
  q.size = SizeField::on_points(p, v, g);
  const Meshed m = meshed(holed_square(), q);
  expect_within(m, q.size);
  EXPECT_THROW(SizeField::on_points(p, v, -0.1), InputError);
  EXPECT_THROW(SizeField::on_grid(std::vector<double>{1, 1, 1, 1}, 2, 2, 0, 0, 1, 1, NAN), InputError);
}

TEST(SizeField, BadFieldsAreRefused) {
  const std::vector<double> v = {1, 2, 3};
  EXPECT_THROW(SizeField::on_grid(v, 2, 2, 0, 0, 1, 1), InputError);  // 3 values for 4 nodes
  const std::vector<double> zero = {1, 0, 1, 1};
  EXPECT_THROW(SizeField::on_grid(zero, 2, 2, 0, 0, 1, 1), InputError);
  EXPECT_THROW(SizeField::on_grid(std::vector<double>{1, 1, 1, 1}, 2, 2, 0, 0, 0, 1), InputError);  // no width
  EXPECT_THROW(SizeField::uniform(-1), InputError);
  const std::vector<Point> p = {{0, 0}, {1, 0}, {0, 1}};
  EXPECT_THROW(SizeField::on_mesh(p, std::vector<VertexId>{0, 1, 5}, v), InputError);
  EXPECT_THROW(SizeField::on_points(p, std::vector<double>{1, NAN, 1}), InputError);
  // A function's sizes are checked where refinement asks them; what it throws comes out.
  const Pslg g = holed_square();
  Quality q;
  q.size = SizeField::of([](std::span<const Point>, std::span<double> h) { std::fill(h.begin(), h.end(), 0.0); });
  EXPECT_THROW(triangulate_constrained(g.points, g.segments, {}, {}, q), InputError);
  q.size = SizeField::of([](std::span<const Point>, std::span<double>) { throw std::runtime_error("mine"); });
  EXPECT_THROW(triangulate_constrained(g.points, g.segments, {}, {}, q), std::runtime_error);
}

}  // namespace
}  // namespace ridt::test
