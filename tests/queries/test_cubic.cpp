// The cubic interpolant (ridt/interpolate.hpp, src/queries/cubic.cpp): gradients exact for linear data,
// quadratics reproduced from their gradients, the data at the points, continuity of the value
// and of the derivative across the triangles' sides, the grid's answers equal to the located
// queries', the same bits on threads, and exact barycentric coordinates on slivers.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "helpers.hpp"
#include "ridt/generate.hpp"
#include "ridt/interpolate.hpp"
#include "ridt/locate.hpp"

namespace ridt {
namespace {

double quadratic(const Point& p) { return 1 + 2 * p.x - p.y + 3 * p.x * p.x - 2 * p.x * p.y + 0.5 * p.y * p.y; }
Point quadratic_gradient(const Point& p) { return {2 + 6 * p.x - 2 * p.y, -1 - 2 * p.x + p.y}; }

struct Data {
  std::vector<Point> points;
  Triangulation t;
  std::vector<double> values, gradients;
};

Data quadratic_data(std::size_t n, unsigned seed) {
  Data d;
  d.points = generate(Distribution::Uniform, n, seed);
  d.t = triangulate(d.points);
  for (const Point& p : d.points) {
    d.values.push_back(quadratic(p));
    const Point g = quadratic_gradient(p);
    d.gradients.push_back(g.x), d.gradients.push_back(g.y);
  }
  return d;
}

std::vector<Point> inside(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.2, 0.8);
  std::vector<Point> q(n);
  for (Point& p : q) p = {u(rng), u(rng)};
  return q;
}

TEST(Cubic, GradientsOfLinearDataAreExact) {
  const std::vector<Point> pts = generate(Distribution::Normal, 3000, 2);
  const Triangulation t = triangulate(pts);
  std::vector<double> v;
  for (const Point& p : pts) v.push_back(3 - 2 * p.x + 14.15 * p.y);
  std::vector<double> g(2 * pts.size());
  EXPECT_GT(estimate_gradients(pts, t, Values{v, 1}, g, 1e-12, 400), 0);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    EXPECT_NEAR(g[2 * i], -2, 1e-9);
    EXPECT_NEAR(g[2 * i + 1], 14.15, 1e-9);
  }
}

TEST(Cubic, QuadraticsFromTheirGradientsAndTheDataAtThePoints) {
  const Data d = quadratic_data(2000, 3);
  const std::vector<Point> q = inside(20000, 4);
  std::vector<double> out(q.size());
  interpolate_clough_tocher(d.points, d.t, Values{d.values, 1}, d.gradients, q, out, -1, 2);
  for (std::size_t k = 0; k < q.size(); ++k) EXPECT_NEAR(out[k], quadratic(q[k]), 1e-12) << k;
  std::vector<double> at(d.points.size());
  interpolate_clough_tocher(d.points, d.t, Values{d.values, 1}, d.gradients, d.points, at);
  for (std::size_t i = 0; i < d.points.size(); ++i) EXPECT_EQ(at[i], d.values[i]);
}

TEST(Cubic, ValueAndDerivativeContinuousAcrossSides) {
  // Random data and gradients: the pieces must still meet with a continuous value and slope.
  Data d = quadratic_data(400, 5);
  std::mt19937_64 rng(6);
  std::normal_distribution<double> z;
  for (double& v : d.values) v = z(rng);
  for (double& g : d.gradients) g = z(rng);
  auto height = [&](std::size_t tri, int i) {  // of triangle tri over its side across from corner i
    const Point& c = d.points[d.t.triangles[3 * tri + i]];
    const Point& a = d.points[d.t.triangles[3 * tri + (i + 1) % 3]];
    const Point& b = d.points[d.t.triangles[3 * tri + (i + 2) % 3]];
    return std::fabs((a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x)) / std::hypot(b.x - a.x, b.y - a.y);
  };
  for (std::size_t tri = 0; tri < d.t.size(); ++tri)
    for (int i = 0; i < 3; ++i) {
      const std::int32_t u = d.t.neighbors[3 * tri + i];
      if (u < 0) continue;
      const Point& a = d.points[d.t.triangles[3 * tri + (i + 1) % 3]];
      const Point& b = d.points[d.t.triangles[3 * tri + (i + 2) % 3]];
      int j = 0;  // u's corner across the side
      while (d.t.neighbors[3 * std::size_t(u) + j] != static_cast<std::int32_t>(tri)) ++j;
      const Point m{a.x + 0.5 * (b.x - a.x), a.y + 0.5 * (b.y - a.y)};
      const Point n{(b.y - a.y), -(b.x - a.x)};  // across the side, either way
      const double len = std::hypot(n.x, n.y);
      // One-sided slopes at the side from each triangle, second-order differences at steps h
      // and h / 2 extrapolated (Richardson) so that thin triangles' large third derivatives
      // cancel; h small against both triangles' heights, so the probes stay in the two.
      auto slopes = [&](double h) {
        std::vector<Point> q;
        for (double s : {-2.0, -1.0, 0.0, 1.0, 2.0}) q.push_back({m.x + s * h * n.x / len, m.y + s * h * n.y / len});
        std::vector<double> v(q.size());
        interpolate_clough_tocher(d.points, d.t, Values{d.values, 1}, d.gradients, q, v);
        return std::array<double, 4>{(3 * v[2] - 4 * v[1] + v[0]) / (2 * h), (-3 * v[2] + 4 * v[3] - v[4]) / (2 * h),
                                     v[1] - v[2], v[3] - v[2]};
      };
      const double h = 1e-3 * std::min(height(tri, i), height(std::size_t(u), j));
      const auto coarse = slopes(h), fine = slopes(h / 2);
      const double left = (4 * fine[0] - coarse[0]) / 3, right = (4 * fine[1] - coarse[1]) / 3;
      EXPECT_NEAR(left, right, 1e-5 * (1 + std::fabs(left))) << tri << " " << i;
      // And both sides tend to the value on it.
      EXPECT_LE(std::fabs(fine[2]), h * (1 + 2 * std::fabs(left)));
      EXPECT_LE(std::fabs(fine[3]), h * (1 + 2 * std::fabs(left)));
    }
}

// The minimum-norm network's gradients by plain Gauss-Seidel in the points' order, as scipy
// sweeps (each vertex's neighbours from the triangles), from each point's best plane through
// its neighbours' values, until a sweep changes no gradient by more than 1e-12.
std::vector<double> plain_gauss_seidel(const std::vector<Point>& pts, const Triangulation& t,
                                       const std::vector<double>& f) {
  std::vector<std::vector<std::size_t>> around(pts.size());
  for (std::size_t k = 0; k < t.triangles.size(); ++k) {
    const std::size_t a = t.triangles[k], b = t.triangles[k - k % 3 + (k + 1) % 3];
    around[a].push_back(b), around[b].push_back(a);
  }
  for (std::vector<std::size_t>& a : around) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
  std::vector<double> g(2 * pts.size(), 0.0);
  // plane: g from 4 (f_w - f_v) / L^3 alone; else the sweep's 6 (f_w - f_v) - 2 e.g_w
  auto best = [&](std::size_t v, bool plane) {
    double q00 = 0, q01 = 0, q11 = 0, s0 = 0, s1 = 0;
    for (const std::size_t w : around[v]) {
      const double ex = pts[w].x - pts[v].x, ey = pts[w].y - pts[v].y, l2 = ex * ex + ey * ey;
      const double l3 = l2 * std::sqrt(l2);
      q00 += 4 * ex * ex / l3, q01 += 4 * ex * ey / l3, q11 += 4 * ey * ey / l3;
      const double r = (plane ? 4 * (f[w] - f[v]) : 6 * (f[w] - f[v]) - 2 * (ex * g[2 * w] + ey * g[2 * w + 1])) / l3;
      s0 += r * ex, s1 += r * ey;
    }
    const double det = q00 * q11 - q01 * q01;
    return std::array<double, 2>{(q11 * s0 - q01 * s1) / det, (q00 * s1 - q01 * s0) / det};
  };
  std::vector<double> start(g.size());
  for (std::size_t v = 0; v < pts.size(); ++v) {
    const std::array<double, 2> s = best(v, true);
    start[2 * v] = s[0], start[2 * v + 1] = s[1];
  }
  g = start;
  double change = 1;
  int sweeps = 0;
  for (; change > 1e-12 && sweeps < 400; ++sweeps) {  // 18 sweeps here
    change = 0;
    for (std::size_t v = 0; v < pts.size(); ++v) {
      const std::array<double, 2> n = best(v, false);
      change = std::max({change, std::fabs(n[0] - g[2 * v]), std::fabs(n[1] - g[2 * v + 1])});
      g[2 * v] = n[0], g[2 * v + 1] = n[1];
    }
  }
  return g;
}

TEST(Cubic, GradientsReachTheMinimumWithTheSameBitsOnAnyThreads) {
  // Enough points that every colour class is shared among the threads.
  const std::vector<Point> pts = generate(Distribution::Uniform, 60000, 11);
  const Triangulation t = triangulate(pts);
  std::vector<double> f;
  for (const Point& p : pts) f.push_back(std::sin(6 * p.x) * std::cos(5 * p.y) + p.x * p.y);
  std::vector<double> one(2 * pts.size()), two(one.size()), three(one.size());
  const int sweeps = estimate_gradients(pts, t, Values{f, 1}, one, 1e-12, 2000, 1);
  EXPECT_GT(sweeps, 0);
  EXPECT_EQ(estimate_gradients(pts, t, Values{f, 1}, two, 1e-12, 2000, 2), sweeps);
  EXPECT_EQ(estimate_gradients(pts, t, Values{f, 1}, three, 1e-12, 2000, 3), sweeps);
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, three);
  const std::vector<double> reference = plain_gauss_seidel(pts, t, f);
  double worst = 0;
  for (std::size_t k = 0; k < one.size(); ++k) worst = std::max(worst, std::fabs(one[k] - reference[k]));
  EXPECT_LT(worst, 1e-10);
}

TEST(Cubic, GriddataEqualsTheGradientsAndTheGridCallOnAnyThreads) {
  // Two components, a duplicate point with other values (point 17's stand), nodes outside the
  // hull; the one call, the one call that triangulates, and the two give the same bits, on one
  // thread and on three.
  std::vector<Point> pts = generate(Distribution::Normal, 30000, 12);
  pts.push_back(pts[17]);
  const Triangulation t = triangulate(pts);
  std::vector<double> f;
  for (const Point& p : pts) f.push_back(std::sin(3 * p.x) * p.y), f.push_back(p.x * p.x - p.y);
  f[f.size() - 2] = 100, f[f.size() - 1] = -100;
  std::vector<double> x, y;
  for (int i = 0; i < 150; ++i) x.push_back(-4 + 8 * i / 149.0);
  for (int i = 0; i < 120; ++i) y.push_back(3.5 - 7 * i / 119.0);
  const Grid grid{x, y, true};
  std::vector<double> g(4 * pts.size()), two_calls(2 * grid.size());
  const int sweeps = estimate_gradients(pts, t, Values{f, 2}, g, 1e-6, 400, 2);
  interpolate_clough_tocher(pts, t, Values{f, 2}, g, grid, two_calls, -5, 2);
  for (const unsigned threads : {1u, 3u}) {
    std::vector<double> one_call(two_calls.size());
    EXPECT_EQ(griddata_cubic(pts, t, Values{f, 2}, grid, one_call, -5, 1e-6, 400, threads), sweeps);
    EXPECT_EQ(one_call, two_calls);
    std::vector<double> triangulating(two_calls.size());
    EXPECT_EQ(griddata_cubic(pts, Values{f, 2}, grid, triangulating, -5, 1e-6, 400, threads), sweeps);
    EXPECT_EQ(triangulating, two_calls);
  }
  std::vector<double> short_out(5);
  EXPECT_THROW(griddata_cubic(pts, t, Values{f, 2}, grid, short_out, -5), InputError);
  EXPECT_THROW(griddata_cubic(pts, t, Values{f, 2}, grid, two_calls, -5, 0.0), InputError);
  EXPECT_GT(std::count(two_calls.begin(), two_calls.end(), -5.0), 0);  // nodes outside the hull
  EXPECT_EQ(std::count(two_calls.begin(), two_calls.end(), 100.0), 0);  // the duplicate's values unread
}

TEST(Cubic, GriddataOfPointsWithoutATriangleFillsAndSaysSo) {
  const std::vector<double> x = {0, 0.5, 1}, y = {0, 1};
  const Grid grid{x, y, true};
  std::vector<double> out(grid.size(), 7);
  const std::vector<double> f = {1, 2, 3, 4};
  for (const std::vector<Point>& pts : {std::vector<Point>{{0, 0}, {1, 1}, {2, 2}, {3, 3}},
                                        std::vector<Point>{{0, 0}, {1, 0}, {0, 0}, {1, 0}}, std::vector<Point>{}}) {
    const Values v{std::span<const double>(f).first(pts.size()), 1};
    EXPECT_EQ(griddata_cubic(pts, v, grid, out, -2, 1e-6, 400, 2), -1);
    EXPECT_EQ(std::count(out.begin(), out.end(), -2.0), static_cast<std::ptrdiff_t>(out.size()));
  }
  const std::vector<Point> bad = {{0, 0}, {1, 0}, {0, std::numeric_limits<double>::quiet_NaN()}};
  EXPECT_THROW(griddata_cubic(bad, Values{std::span<const double>(f).first(3), 1}, grid, out), InputError);
  EXPECT_THROW(griddata_cubic(bad, Values{f, 1}, grid, out), InputError);  // four values for three points
}

TEST(Cubic, GridEqualsTheLocatedQueriesAndThreadsGiveTheSameBits) {
  const Data d = quadratic_data(5000, 7);
  std::vector<double> x, y;
  for (int i = 0; i < 101; ++i) x.push_back(i / 100.0), y.push_back(1 - i / 100.0);
  const Grid grid{x, y, false};
  std::vector<Point> q;
  for (const double yy : y)
    for (const double xx : x) q.push_back({xx, yy});
  std::vector<double> by_grid(grid.size()), by_queries(q.size()), on_two(q.size());
  interpolate_clough_tocher(d.points, d.t, Values{d.values, 1}, d.gradients, grid, by_grid, -7, 1);
  interpolate_clough_tocher(d.points, d.t, Values{d.values, 1}, d.gradients, q, by_queries, -7, 1);
  interpolate_clough_tocher(d.points, d.t, Values{d.values, 1}, d.gradients, q, on_two, -7, 2);
  for (std::size_t k = 0; k < q.size(); ++k) {
    EXPECT_EQ(by_grid[k], by_queries[k]) << k;
    EXPECT_EQ(by_queries[k], on_two[k]) << k;
  }
}

// The same points numbered by `place` (point i becomes place[i]), the triangles with them.
Triangulation renumbered(const Triangulation& t, const std::vector<std::uint32_t>& place) {
  Triangulation r = t;
  for (VertexId& v : r.triangles) v = place[v];
  return r;
}

TEST(Cubic, AnswersDependOnTheTrianglesAloneNotTheirOrderOrFirstCorners) {
  // A lattice (grid nodes on vertices and on sides, every square cocircular), uniform points,
  // and uniform points with a blob of 500 in one cell of the renumbering's curve; the gradients, linear,
  // cubic and natural neighbours on grids and at located queries, many (the field renumbered)
  // and few (not), and griddata: the same bits from the triangles shuffled and each stored
  // from another corner, and from the points numbered otherwise.
  for (const Distribution dist : {Distribution::Grid, Distribution::Uniform, Distribution::Clusters}) {
    std::vector<Point> pts = generate(dist, 3000, 4);
    const std::string name = dist == Distribution::Clusters ? "uniform with a blob" : std::string(to_string(dist));
    if (dist == Distribution::Clusters) {  // here: the blob
      pts = generate(Distribution::Uniform, 2500, 4);
      for (const Point& p : generate(Distribution::Uniform, 500, 6))
        pts.push_back({0.5 + 1e-7 * p.x, 0.5 + 1e-7 * p.y});
    }
    const Triangulation t = triangulate(pts);
    double x0 = pts[0].x, x1 = x0, y0 = pts[0].y, y1 = y0;
    for (const Point& p : pts)
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    auto axis = [](double from, double to, int steps) {
      std::vector<double> v;
      for (int i = 0; i <= steps; ++i) v.push_back(from + (to - from) * i / steps);
      return v;
    };
    const std::vector<double> x = axis(x0, x1, 120), y = axis(y0, y1, 120), xs = axis(x0, x1, 24),
                              ys = axis(y0, y1, 24);
    const Grid many{x, y, true}, few{xs, ys, false};  // 14,641 nodes and 625, about 6,000 triangles
    std::vector<Point> q;
    for (const double yy : y)
      for (const double xx : x) q.push_back({xx, yy});
    const std::span<const Point> q_few = std::span<const Point>(q).subspan(7000, 500);
    std::vector<double> f;
    for (const Point& p : pts) f.push_back(std::sin(3 * (p.x - x0) / (x1 - x0)) * p.y + p.x);
    // Every answer; the gradients in the caller's numbering of `place`.
    auto answers = [&](const std::vector<Point>& p, const Triangulation& tri, const std::vector<double>& v,
                       const std::vector<std::uint32_t>& place) {
      std::vector<std::vector<double>> r;
      std::vector<double> g(2 * p.size()), out;
      estimate_gradients(p, tri, Values{v, 1}, g, 1e-9, 400, 2);
      std::vector<double> g_back(g.size());
      for (std::size_t i = 0; i < pts.size(); ++i)
        g_back[2 * i] = g[2 * place[i]], g_back[2 * i + 1] = g[2 * place[i] + 1];
      r.push_back(g_back);
      for (const Grid* grid : {&many, &few}) {
        out.assign(grid->size(), 0);
        interpolate_linear(p, tri, Values{v, 1}, *grid, out, -1, 2), r.push_back(out);
        interpolate_clough_tocher(p, tri, Values{v, 1}, g, *grid, out, -1, 2), r.push_back(out);
        interpolate_natural_neighbor(p, tri, Values{v, 1}, *grid, out, -1, 2), r.push_back(out);
        griddata_cubic(p, tri, Values{v, 1}, *grid, out, -1, 1e-9, 400, 2), r.push_back(out);
      }
      for (const std::span<const Point> at : {std::span<const Point>(q), q_few}) {
        out.assign(at.size(), 0);
        interpolate_linear(p, tri, Values{v, 1}, at, out, -1, 2), r.push_back(out);
        interpolate_clough_tocher(p, tri, Values{v, 1}, g, at, out, -1, 2), r.push_back(out);
        if (at.size() < 1000) interpolate_natural_neighbor(p, tri, Values{v, 1}, at, out, -1, 2), r.push_back(out);
      }
      return r;
    };
    std::vector<std::uint32_t> same(pts.size()), place(pts.size());
    std::iota(same.begin(), same.end(), 0u);
    std::iota(place.begin(), place.end(), 0u);
    std::shuffle(place.begin(), place.end(), std::mt19937_64(5));
    std::vector<Point> moved(pts.size());
    std::vector<double> f_moved(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) moved[place[i]] = pts[i], f_moved[place[i]] = f[i];
    const Triangulation s = test::shuffled(t, 9);
    ASSERT_EQ(test::compare(t, s), "");
    const auto want = answers(pts, t, f, same);
    const auto got_shuffled = answers(pts, s, f, same);
    const auto got_renumbered = answers(moved, test::shuffled(renumbered(t, place), 3), f_moved, place);
    const char* what[] = {"gradients",         "many nodes linear",  "many nodes cubic", "many nodes natural",
                          "many griddata",     "few nodes linear",   "few nodes cubic",  "few nodes natural",
                          "few griddata",      "queries linear",     "queries cubic",    "few queries linear",
                          "few queries cubic", "few queries natural"};
    ASSERT_EQ(want.size(), std::size(what));
    for (std::size_t k = 0; k < want.size(); ++k) {
      EXPECT_EQ(want[k], got_shuffled[k]) << name << ", shuffled: " << what[k];
      EXPECT_EQ(want[k], got_renumbered[k]) << name << ", renumbered: " << what[k];
    }
  }
}

TEST(Cubic, SliversGetFiniteAnswers) {
  // Points rounded onto a line's neighbourhood: triangles whose area rounds to nothing in
  // double precision; every query inside the hull gets a finite answer, the data at the data.
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point> pts = {{0, 1}, {1, 0}};
  for (int k = 0; k < 300; ++k) {
    const double t = u(rng);
    pts.push_back({t, std::nextafter(t, k % 2 ? 2.0 : -1.0)});
  }
  const Triangulation t = triangulate(pts);
  std::vector<double> v;
  for (const Point& p : pts) v.push_back(std::sin(7 * p.x) + p.y);
  std::vector<double> g(2 * pts.size());
  estimate_gradients(pts, t, Values{v, 1}, g);
  std::vector<Point> centroids;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const Point &a = pts[t.triangles[3 * k]], &b = pts[t.triangles[3 * k + 1]], &c = pts[t.triangles[3 * k + 2]];
    centroids.push_back({(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3});
  }
  std::vector<double> out(centroids.size()), at(pts.size());
  interpolate_clough_tocher(pts, t, Values{v, 1}, g, centroids, out);
  interpolate_clough_tocher(pts, t, Values{v, 1}, g, pts, at);
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (locate(pts, t, std::span(&centroids[k], 1))[0] >= 0) {
      EXPECT_TRUE(std::isfinite(out[k])) << k;
    }
  }
  for (std::size_t i = 0; i < pts.size(); ++i) EXPECT_EQ(at[i], v[i]);
}

TEST(Cubic, BadArgumentsAreRefused) {
  const Data d = quadratic_data(100, 9);
  std::vector<double> g(2 * d.points.size()), out(3);
  const std::vector<Point> q(3, Point{0.5, 0.5});
  EXPECT_THROW(estimate_gradients(d.points, d.t, Values{d.values, 1}, std::span(g).first(10)), InputError);
  EXPECT_THROW(estimate_gradients(d.points, d.t, Values{d.values, 1}, g, 0.0), InputError);
  EXPECT_THROW(estimate_gradients(d.points, d.t, Values{d.values, 1}, g, 1e-6, 0), InputError);
  EXPECT_THROW(interpolate_clough_tocher(d.points, d.t, Values{d.values, 1}, std::span(g).first(4), q, out),
               InputError);
  EXPECT_EQ(estimate_gradients(d.points, d.t, Values{d.values, 1}, g, 1e-300, 1), 0);  // did not settle
}

}  // namespace
}  // namespace ridt
