// Interpolation (ridt/interpolate.hpp): exact on linear functions, the data at the points,
// Sibson's coordinates against an independent construction from half-planes, nearest vertices
// against a scan.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "helpers.hpp"
#include "predicates/predicates.hpp"
#include "ridt/generate.hpp"
#include "ridt/interpolate.hpp"

namespace ridt {
namespace {

double linear_f(const Point& p) { return 2 * p.x - 3 * p.y + 1; }

std::vector<double> values_of(const std::vector<Point>& pts, double (*f)(const Point&)) {
  std::vector<double> v;
  for (const Point& p : pts) v.push_back(f(p));
  return v;
}

std::vector<Point> random_queries(std::size_t n, double lo, double hi, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<Point> q(n);
  for (Point& p : q) p = {u(rng), u(rng)};
  return q;
}

// Whether q lies in the closed hull (counter-clockwise) of t, exactly.
bool in_hull(const std::vector<Point>& pts, const Triangulation& t, const Point& q) {
  for (std::size_t h = 0; h < t.hull.size(); ++h)
    if (detail::orient2d(pts[t.hull[h]], pts[t.hull[(h + 1) % t.hull.size()]], q) < 0) return false;
  return true;
}

class Interpolation : public ::testing::TestWithParam<Distribution> {};

TEST_P(Interpolation, ExactOnLinearFunctionsAndFillOutside) {
  const std::vector<Point> pts = generate(GetParam(), 5000, 3);
  const Triangulation t = triangulate(pts);
  const std::vector<double> f = values_of(pts, linear_f);
  double lo = pts[0].x, hi = lo;
  for (const Point& p : pts) lo = std::min({lo, p.x, p.y}), hi = std::max({hi, p.x, p.y});
  std::vector<Point> q = random_queries(20000, lo - 0.1 * (hi - lo), hi + 0.1 * (hi - lo), 5);
  q.insert(q.end(), pts.begin(), pts.begin() + 100);  // at the points
  for (std::size_t k = 0; k < 100; ++k) {  // on edges: midpoints
    const VertexId* v = &t.triangles[3 * k];
    q.push_back({(pts[v[0]].x + pts[v[1]].x) / 2, (pts[v[0]].y + pts[v[1]].y) / 2});
  }
  const double scale = std::max(std::fabs(lo), std::fabs(hi)) * 6 + 1;
  for (const bool natural : {false, true}) {
    // The fill is NaN: any number could be the linear function's value at some query.
    const double fill = std::numeric_limits<double>::quiet_NaN();
    const std::vector<double> r = natural ? interpolate_natural_neighbor(pts, t, {f, 1}, q, fill, 2)
                                          : interpolate_linear(pts, t, {f, 1}, q, fill, 2);
    ASSERT_EQ(r.size(), q.size());
    std::size_t inside = 0;
    for (std::size_t k = 0; k < q.size(); ++k) {
      // The fill value exactly outside the hull.
      ASSERT_EQ(!std::isnan(r[k]), in_hull(pts, t, q[k])) << "query " << k;
      if (std::isnan(r[k])) continue;
      ++inside;
      EXPECT_NEAR(r[k], linear_f(q[k]), 1e-10 * scale) << (natural ? "natural" : "linear") << " query " << k;
    }
    EXPECT_GT(inside, 2000u);
  }
}

INSTANTIATE_TEST_SUITE_P(Distributions, Interpolation, test::every_distribution(), test::distribution_name);

TEST(Interpolation, SeveralComponentsAndTheDataAtThePoints) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 2000, 9);
  const Triangulation t = triangulate(pts);
  std::vector<double> v;
  for (const Point& p : pts) v.insert(v.end(), {std::sin(7 * p.x), p.x * p.y, 3.0});
  for (const bool natural : {false, true}) {
    const std::vector<double> r =
        natural ? interpolate_natural_neighbor(pts, t, {v, 3}, pts) : interpolate_linear(pts, t, {v, 3}, pts);
    ASSERT_EQ(r.size(), 3 * pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(r[3 * i + k], v[3 * i + k], 1e-12) << i;
  }
}

// Sibson's coordinate of site s at q, from scratch: the area of s's cell among `sites` minus
// its area once q is added, each cell the box cut by the half-planes nearer s than another site.
double area(const std::vector<Point>& poly) {
  double s = 0;
  for (std::size_t k = 0; k < poly.size(); ++k)
    s += poly[k].x * poly[(k + 1) % poly.size()].y - poly[k].y * poly[(k + 1) % poly.size()].x;
  return s / 2;
}

double cell_area(const std::vector<Point>& sites, std::size_t s, const Point* extra) {
  std::vector<Point> poly = {{-20, -20}, {20, -20}, {20, 20}, {-20, 20}};  // holds the cell of q
  auto cut = [&](const Point& o) {  // keep the points nearer sites[s] than o
    const Point& p = sites[s];
    const double nx = o.x - p.x, ny = o.y - p.y, c = (o.x * o.x + o.y * o.y - p.x * p.x - p.y * p.y) / 2;
    auto g = [&](const Point& x) { return nx * x.x + ny * x.y - c; };  // <= 0 inside
    std::vector<Point> out;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Point& a = poly[k];
      const Point& b = poly[(k + 1) % poly.size()];
      if (g(a) <= 0) out.push_back(a);
      if ((g(a) <= 0) != (g(b) <= 0)) {
        const double r = g(a) / (g(a) - g(b));
        out.push_back({a.x + r * (b.x - a.x), a.y + r * (b.y - a.y)});
      }
    }
    poly = std::move(out);
  };
  for (std::size_t o = 0; o < sites.size(); ++o)
    if (o != s) cut(sites[o]);
  if (extra) cut(*extra);
  return area(poly);
}

TEST(Interpolation, NaturalNeighbourAgainstHalfPlanes) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 25, 4);
  const Triangulation t = triangulate(pts);
  const std::vector<Point> q = random_queries(200, 0.2, 0.8, 6);
  std::vector<double> f(pts.size());
  std::mt19937_64 rng(2);
  for (double& x : f) x = std::uniform_real_distribution<double>(-1, 1)(rng);
  const std::vector<double> r = interpolate_natural_neighbor(pts, t, {f, 1}, q);
  for (std::size_t k = 0; k < q.size(); ++k) {
    if (!in_hull(pts, t, q[k])) continue;
    double total = 0, sum = 0;
    for (std::size_t s = 0; s < pts.size(); ++s) {
      const double w = cell_area(pts, s, nullptr) - cell_area(pts, s, &q[k]);
      total += w, sum += w * f[s];
    }
    EXPECT_NEAR(r[k], sum / total, 1e-9) << "query " << k;
  }
}

TEST(Interpolation, NaturalNeighbourIsContinuous) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 500, 8);
  const Triangulation t = triangulate(pts);
  std::vector<double> f;
  for (const Point& p : pts) f.push_back(std::sin(5 * p.x) * std::cos(3 * p.y));
  // Along a line, steps of about 1e-5: no jump larger than what the slope allows.
  std::vector<Point> q;
  for (int k = 0; k < 20000; ++k) q.push_back({0.3 + 1e-5 * k, 0.4 + 0.3e-5 * k});
  const std::vector<double> r = interpolate_natural_neighbor(pts, t, {f, 1}, q);
  for (std::size_t k = 1; k < q.size(); ++k) EXPECT_LT(std::fabs(r[k] - r[k - 1]), 1e-3) << k;
}

// Sibson's coordinates are ratios of areas: the points and queries scaled by a power of two,
// however large or small, give the same bits, where the areas would overflow or underflow.
TEST(Interpolation, NaturalNeighbourAtEveryScale) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 2000, 12);
  const std::vector<Point> q = random_queries(3000, 0.05, 0.95, 13);
  std::vector<double> f;
  for (const Point& p : pts) f.push_back(std::sin(5 * p.x) * std::cos(3 * p.y));
  const std::vector<double> plain = interpolate_natural_neighbor(pts, triangulate(pts), {f, 1}, q);
  for (const int e : {-990, -700, -300, 300, 700, 1000}) {  // the points stay normal doubles
    SCOPED_TRACE(e);
    auto scaled = [e](std::vector<Point> v) {
      for (Point& p : v) p = {std::ldexp(p.x, e), std::ldexp(p.y, e)};
      return v;
    };
    const std::vector<Point> sp = scaled(pts);
    EXPECT_EQ(interpolate_natural_neighbor(sp, triangulate(sp), {f, 1}, scaled(q)), plain);
  }
}

TEST(Interpolation, GridQueriesOnEdgesAndVertices) {
  // Cocircular everywhere: any diagonal is Delaunay, and both interpolants are still exact on
  // linear functions, at vertices, edge midpoints and cell centres.
  const std::vector<Point> pts = generate(Distribution::Grid, 100, 1);
  const Triangulation t = triangulate(pts);
  const std::vector<double> f = values_of(pts, linear_f);
  std::vector<Point> q;
  for (double x = 0; x <= 9; x += 0.5)
    for (double y = 0; y <= 9; y += 0.5) q.push_back({x, y});
  for (const bool natural : {false, true}) {
    const std::vector<double> r =
        natural ? interpolate_natural_neighbor(pts, t, {f, 1}, q) : interpolate_linear(pts, t, {f, 1}, q);
    for (std::size_t k = 0; k < q.size(); ++k) EXPECT_NEAR(r[k], linear_f(q[k]), 1e-12) << k;
  }
}

// The nodes of a grid in the order the Grid call answers them.
std::vector<Point> nodes_of(const Grid& g) {
  std::vector<Point> q(g.size());
  for (std::size_t i = 0; i < g.x.size(); ++i)
    for (std::size_t j = 0; j < g.y.size(); ++j)
      q[g.x_major ? i * g.y.size() + j : j * g.x.size() + i] = {g.x[i], g.y[j]};
  return q;
}

std::vector<double> axis(double from, double to, std::size_t n) {
  std::vector<double> v(n);
  for (std::size_t k = 0; k < n; ++k) v[k] = from + (to - from) * static_cast<double>(k) / static_cast<double>(n - 1);
  return v;
}

// The grid call gives, at every node, what the call on located queries gives: the same fill
// outside the hull (every node in the closed hull is taken by one triangle) and the same
// values inside, the same bits (a node on a side is answered by the same one of its two
// triangles, each read from the same corner).
class GridInterpolation : public ::testing::TestWithParam<Distribution> {};

TEST_P(GridInterpolation, EqualsTheLocatedQueries) {
  const std::vector<Point> pts = generate(GetParam(), 4000, 11);
  const Triangulation t = triangulate(pts);
  double x0 = pts[0].x, x1 = x0, y0 = pts[0].y, y1 = y0;
  for (const Point& p : pts)
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  const std::vector<double> f = values_of(pts, [](const Point& p) { return std::sin(3 * p.x) + p.y * p.y; });
  // Axes past the hull on every side; on the grid distribution, nodes on every vertex and
  // every edge; one axis decreasing and uneven.
  const double wx = x1 - x0, wy = y1 - y0;
  std::vector<double> xs, ys;
  if (GetParam() == Distribution::Grid) {  // steps of a half: vertices, edge midpoints, centres
    xs = axis(x0 - 1, x1 + 1, 2 * static_cast<std::size_t>(wx) + 5);
    ys = axis(y1 + 1, y0 - 1, 2 * static_cast<std::size_t>(wy) + 5);
  } else {
    xs = axis(x0 - 0.1 * wx, x1 + 0.1 * wx, 97);
    ys = axis(y1 + 0.1 * wy, y0 - 0.1 * wy, 61);
    for (double& y : ys) y += 0.01 * wy * std::sin(y / wy);  // uneven, still decreasing
  }
  for (const bool x_major : {false, true})
    for (const bool natural : {false, true}) {
      const Grid g{xs, ys, x_major};
      const std::vector<Point> q = nodes_of(g);
      std::vector<double> got(g.size());
      if (natural)
        interpolate_natural_neighbor(pts, t, {f, 1}, g, got, -7.0, 2);
      else
        interpolate_linear(pts, t, {f, 1}, g, got, -7.0, 2);
      const std::vector<double> want =
          natural ? interpolate_natural_neighbor(pts, t, {f, 1}, q, -7.0) : interpolate_linear(pts, t, {f, 1}, q, -7.0);
      std::size_t inside = 0;
      for (std::size_t k = 0; k < q.size(); ++k) {
        ASSERT_EQ(got[k] == -7.0, !in_hull(pts, t, q[k])) << k << " at " << q[k].x << ", " << q[k].y;
        EXPECT_EQ(got[k], want[k]) << k;
        inside += got[k] != -7.0;
      }
      EXPECT_GT(inside, q.size() / 3);
    }
}

INSTANTIATE_TEST_SUITE_P(Distributions, GridInterpolation, test::every_distribution(), test::distribution_name);

TEST(GridInterpolation, ThreadsGiveTheSameBits) {
  // Enough triangles for each thread to take a stretch: every node still has one owner.
  const std::vector<Point> pts = generate(Distribution::Uniform, 60000, 5);
  const Triangulation t = triangulate(pts);
  const std::vector<double> f = values_of(pts, [](const Point& p) { return std::exp(p.x) * p.y; });
  const std::vector<double> xs = axis(-0.05, 1.05, 301), ys = axis(-0.05, 1.05, 257);
  for (const bool natural : {false, true}) {
    std::vector<double> one(xs.size() * ys.size()), two(one.size());
    const Grid g{xs, ys};
    if (natural) {
      interpolate_natural_neighbor(pts, t, {f, 1}, g, one, 0.0, 1);
      interpolate_natural_neighbor(pts, t, {f, 1}, g, two, 0.0, 2);
    } else {
      interpolate_linear(pts, t, {f, 1}, g, one, 0.0, 1);
      interpolate_linear(pts, t, {f, 1}, g, two, 0.0, 2);
    }
    EXPECT_EQ(one, two);
  }
}

TEST(GridInterpolation, OneNodeAxesAndBadGridsAreRefused) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 300, 2);
  const Triangulation t = triangulate(pts);
  const std::vector<double> f = values_of(pts, linear_f);
  const std::vector<double> one = {0.5}, some = {0.25, 0.5, 0.75};
  std::vector<double> out(3);
  interpolate_linear(pts, t, {f, 1}, Grid{one, some}, out);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(out[k], linear_f({0.5, some[k]}), 1e-12);
  const std::vector<double> bumpy = {0.1, 0.3, 0.2}, nan = {0.1, std::numeric_limits<double>::quiet_NaN()},
                            flat = {0.2, 0.2};
  std::vector<double> room(6), small(2);
  EXPECT_THROW(interpolate_linear(pts, t, {f, 1}, Grid{bumpy, one}, small), InputError);
  EXPECT_THROW(interpolate_linear(pts, t, {f, 1}, Grid{nan, one}, small), InputError);
  EXPECT_THROW(interpolate_natural_neighbor(pts, t, {f, 1}, Grid{flat, one}, small), InputError);
  EXPECT_THROW(interpolate_linear(pts, t, {f, 1}, Grid{some, one}, room), InputError);
}

TEST(Interpolation, NearestVertexAgainstAScan) {
  const std::vector<Point> pts = generate(Distribution::Clusters, 3000, 5);
  const Triangulation t = triangulate(pts);
  const std::vector<Point> q = random_queries(5000, -0.2, 1.2, 7);
  const std::vector<std::int32_t> r = nearest_vertex(pts, t, q, 2);
  for (std::size_t k = 0; k < q.size(); ++k) {
    double best = std::numeric_limits<double>::infinity();
    for (const Point& p : pts) best = std::min(best, std::hypot(p.x - q[k].x, p.y - q[k].y));
    ASSERT_GE(r[k], 0);
    EXPECT_DOUBLE_EQ(std::hypot(pts[r[k]].x - q[k].x, pts[r[k]].y - q[k].y), best) << k;
  }
}

TEST(Interpolation, BadSizesAreRefused) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 100, 1);
  const Triangulation t = triangulate(pts);
  const std::vector<double> f(99);
  EXPECT_THROW(interpolate_linear(pts, t, {f, 1}, pts), InputError);
  EXPECT_THROW(interpolate_natural_neighbor(pts, t, {f, 0}, pts), InputError);
  const std::vector<double> g(100);
  const std::vector<Point> odd = {{0.5, std::numeric_limits<double>::quiet_NaN()}};
  EXPECT_TRUE(std::isnan(interpolate_linear(pts, t, {g, 1}, odd)[0]));
  EXPECT_EQ(nearest_vertex(pts, t, odd)[0], -1);
}

}  // namespace
}  // namespace ridt
