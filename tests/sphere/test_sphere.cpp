// The triangulation on the sphere (ridt/sphere.hpp) against a brute-force hull, on
// polyhedra and grids full of cocircular points, with points inside and copies; its validator
// against surfaces made wrong on purpose; the Voronoi cells and their areas.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <set>
#include <vector>

#include "predicates/orient3d.hpp"
#include "ridt/interpolate.hpp"
#include "ridt/predicates.hpp"
#include "ridt/sphere.hpp"

namespace ridt {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<Point3> on_sphere(std::size_t n, std::uint64_t seed, double radius = 1, Point3 c = {}) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal;
  std::vector<Point3> pts(n);
  for (Point3& p : pts) {
    const double x = normal(random), y = normal(random), z = normal(random), l = std::sqrt(x * x + y * y + z * z);
    p = {c.x + radius * x / l, c.y + radius * y / l, c.z + radius * z / l};
  }
  return pts;
}

// A triangle by its corners' coordinates, starting at the least: the same triangle whatever the
// points' numbering.
using Face = std::array<double, 9>;
std::set<Face> faces(const std::vector<Point3>& pts, const std::vector<VertexId>& tris) {
  std::set<Face> out;
  for (std::size_t f = 0; f < tris.size() / 3; ++f) {
    std::array<Point3, 3> c = {pts[tris[3 * f]], pts[tris[3 * f + 1]], pts[tris[3 * f + 2]]};
    auto less = [](const Point3& a, const Point3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); };
    const int s = less(c[1], c[0]) && !less(c[2], c[1]) ? 1 : less(c[2], c[0]) && less(c[2], c[1]) ? 2 : 0;
    std::rotate(c.begin(), c.begin() + s, c.end());
    out.insert({c[0].x, c[0].y, c[0].z, c[1].x, c[1].y, c[1].z, c[2].x, c[2].y, c[2].z});
  }
  return out;
}

SphericalTriangulation expect_valid(const std::vector<Point3>& pts) {
  SphericalTriangulation t = triangulate_sphere(pts);
  const CheckResult r = check_sphere(pts, t.triangles);
  EXPECT_TRUE(r.valid) << r.message;
  std::size_t corners = 0;
  std::vector<std::uint8_t> used(pts.size(), 0);
  for (const VertexId v : t.triangles) corners += !used[v], used[v] = 1;
  EXPECT_EQ(t.size(), 2 * corners - 4);
  EXPECT_EQ(corners + t.duplicates.size() + t.hidden.size(), pts.size());
  for (std::size_t f = 0; f < t.size(); ++f)
    for (int i = 0; i < 3; ++i) {
      const std::int32_t g = t.neighbors[3 * f + i];
      EXPECT_GE(g, 0);
      if (g < 0) continue;
      const VertexId* u = &t.triangles[3 * std::size_t(g)];
      EXPECT_EQ(std::count(u, u + 3, t.triangles[3 * f + i]), 0) << "neighbour " << i << " of " << f;
    }
  return t;
}

TEST(Sphere, RandomPointsEqualTheBruteForceHull) {
  for (const std::size_t n : {4u, 5u, 9u, 40u, 90u}) {
    const std::vector<Point3> pts = on_sphere(n, n);
    const SphericalTriangulation t = expect_valid(pts);
    // Every triple with all other points strictly below it (generic points: one answer).
    std::vector<VertexId> brute;
    for (VertexId a = 0; a < n; ++a)
      for (VertexId b = 0; b < n; ++b)
        for (VertexId c = 0; c < n; ++c) {
          if (!(a < b && a < c && b != c)) continue;
          bool face = true;
          for (VertexId d = 0; d < n && face; ++d)
            if (d != a && d != b && d != c) face = orientation(pts[a], pts[b], pts[c], pts[d]) > 0;
          if (face) brute.insert(brute.end(), {a, b, c});
        }
    EXPECT_EQ(faces(pts, t.triangles), faces(pts, brute)) << n << " points";
    EXPECT_TRUE(t.hidden.empty());
  }
}

TEST(Sphere, ManyPointsAnyCentreAndRadius) {
  for (const std::size_t n : {1000u, 100000u}) {
    const std::vector<Point3> pts = on_sphere(n, 3, 1e3, {1e6, -2e6, 5});
    const SphericalTriangulation t = expect_valid(pts);
    EXPECT_TRUE(t.hidden.empty());
    EXPECT_EQ(t.size(), 2 * n - 4);
  }
}

// Points whose order in the input is changed: the same triangles (the perturbation is keyed
// on the coordinates).
void expect_order_free(std::vector<Point3> pts) {
  const SphericalTriangulation t = expect_valid(pts);
  std::mt19937_64 random(11);
  std::vector<Point3> shuffled = pts;
  std::shuffle(shuffled.begin(), shuffled.end(), random);
  const SphericalTriangulation u = expect_valid(shuffled);
  EXPECT_EQ(faces(pts, t.triangles), faces(shuffled, u.triangles));
}

TEST(Sphere, CocircularPointsOneAnswerInAnyOrder) {
  const double phi = (1 + std::sqrt(5.0)) / 2;
  std::vector<Point3> cube, octahedron, icosahedron;
  for (int i = 0; i < 8; ++i) cube.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
  for (int i = 0; i < 3; ++i)
    for (const double s : {-1.0, 1.0}) octahedron.push_back({i == 0 ? s : 0, i == 1 ? s : 0, i == 2 ? s : 0});
  for (const double a : {-1.0, 1.0})
    for (const double b : {-phi, phi}) icosahedron.insert(icosahedron.end(), {{0, a, b}, {a, b, 0}, {b, 0, a}});
  for (const auto& p : {cube, octahedron, icosahedron}) expect_order_free(p);
  EXPECT_EQ(triangulate_sphere(cube).size(), 12u);
  // A grid of longitudes and latitudes (its rows are circles; the poles and the equator).
  std::vector<Point3> grid{{0, 0, 1}, {0, 0, -1}};
  for (int i = 1; i < 12; ++i)
    for (int j = 0; j < 24; ++j) {
      const double lat = kPi * i / 12 - kPi / 2, lon = 2 * kPi * j / 24;
      grid.push_back({std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)});
    }
  expect_order_free(grid);
  // Small integers on a sphere of radius 5 (exactly on it: many quadruples on one circle).
  std::vector<Point3> lattice;
  for (int x = -5; x <= 5; ++x)
    for (int y = -5; y <= 5; ++y)
      for (int z = -5; z <= 5; ++z)
        if (x * x + y * y + z * z == 25) lattice.push_back({double(x), double(y), double(z)});
  expect_order_free(lattice);
  // One hemisphere: the inner point is far from the sphere's centre.
  std::vector<Point3> half = on_sphere(500, 5);
  for (Point3& p : half) p.x = std::fabs(p.x);
  expect_order_free(half);
}

TEST(Sphere, PointsInsideAreHiddenAndCopiesDropped) {
  std::vector<Point3> pts = on_sphere(300, 8);
  std::mt19937_64 random(2);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  const std::size_t on = pts.size();
  for (int i = 0; i < 3000; ++i) pts.push_back({u(random), u(random), u(random)});  // inside, most covering others
  pts.push_back(pts[5]);
  pts.push_back(pts[5]);
  // A point a rounding below the sphere among neighbours as close as 1e-9: hidden.
  const Point3 q = pts[7];
  for (const double e : {1e-9, -1e-9}) pts.push_back({q.x + e, q.y, q.z});
  pts.push_back({q.x * (1 - 1e-15), q.y * (1 - 1e-15), q.z * (1 - 1e-15)});
  const SphericalTriangulation t = expect_valid(pts);
  ASSERT_EQ(t.duplicates.size(), 2u);
  EXPECT_EQ(t.duplicates[0].dropped, on + 3000);
  EXPECT_EQ(t.duplicates[0].kept, 5u);
  EXPECT_GE(t.hidden.size(), 3000u);
  for (std::size_t i = on; i < on + 3000; ++i) EXPECT_TRUE(std::binary_search(t.hidden.begin(), t.hidden.end(), i));
  // Mostly points inside, inserted among the others: vertices covered as the hull grows.
  std::vector<Point3> ball;
  std::uniform_real_distribution<double> w(-1, 1);
  while (ball.size() < 5000)
    if (const Point3 p{w(random), w(random), w(random)}; p.x * p.x + p.y * p.y + p.z * p.z <= 1) ball.push_back(p);
  expect_valid(ball);
}

// The rounds of 4096 points or more are shared among the threads, each inserting in a region
// of its own and putting off the points whose walk or cavity leaves it: the same triangles, in
// the same order, on any number of threads (the hull is unique, the output's order the
// triangles' own), on points far apart, in clusters, full of cocircular quadruples, with
// copies, and mostly inside (points hidden, vertices covered as the hull grows).
TEST(Sphere, SameOutputOnAnyNumberOfThreads) {
  std::mt19937_64 random(21);
  std::vector<std::vector<Point3>> inputs;
  inputs.push_back(on_sphere(60000, 9, 3e2, {-4e5, 1e5, 7}));
  std::vector<Point3> clusters;
  std::normal_distribution<double> near(0, 1e-2);
  const std::vector<Point3> centres = on_sphere(8, 10);
  for (int i = 0; i < 40000; ++i) {
    const Point3& c = centres[i % 8];
    const Point3 p{c.x + near(random), c.y + near(random), c.z + near(random)};
    const double l = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    clusters.push_back({p.x / l, p.y / l, p.z / l});
  }
  inputs.push_back(clusters);
  std::vector<Point3> grid{{0, 0, 1}, {0, 0, -1}};
  for (int i = 1; i < 120; ++i)
    for (int j = 0; j < 240; ++j) {
      const double lat = kPi * i / 120 - kPi / 2, lon = 2 * kPi * j / 240;
      grid.push_back({std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)});
    }
  inputs.push_back(grid);
  std::vector<Point3> copies = on_sphere(20000, 12);
  for (int i = 0; i < 2000; ++i) copies.push_back(copies[(i * 7919) % 20000]);
  inputs.push_back(copies);
  std::vector<Point3> ball = on_sphere(10000, 13);
  std::uniform_real_distribution<double> w(-1, 1);
  while (ball.size() < 40000)
    if (const Point3 p{w(random), w(random), w(random)}; p.x * p.x + p.y * p.y + p.z * p.z <= 1) ball.push_back(p);
  std::shuffle(ball.begin(), ball.end(), random);
  inputs.push_back(ball);
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const SphericalTriangulation one = triangulate_sphere(inputs[k], 1);
    const CheckResult r = check_sphere(inputs[k], one.triangles);
    EXPECT_TRUE(r.valid) << "input " << k << ": " << r.message;
    for (const unsigned threads : {2u, 3u, 8u}) {
      const SphericalTriangulation t = triangulate_sphere(inputs[k], threads);
      EXPECT_EQ(t.triangles, one.triangles) << "input " << k << ", " << threads << " threads";
      EXPECT_EQ(t.neighbors, one.neighbors) << "input " << k << ", " << threads << " threads";
      EXPECT_EQ(t.hidden, one.hidden) << "input " << k << ", " << threads << " threads";
      EXPECT_EQ(t.duplicates.size(), one.duplicates.size()) << "input " << k << ", " << threads << " threads";
    }
  }
}

// Copies found whatever the signs of zeros and however close the points: -0 and 0 are one
// coordinate, and points whose x differ in the last bits only are told apart.
TEST(Sphere, CopiesOfZeroAndNeighboursInTheLastBits) {
  std::vector<Point3> pts = {{0.0, 0.0, 1}, {-0.0, 0.0, 1}, {0.0, -0.0, 1}, {1, 0, 0},    {-1, 0, 0},
                             {0, 1, 0},     {0, -1, 0},     {0, 0, -1},     {-0.0, 0, -1}};
  const double x = std::nextafter(0.6, 1.0), y = std::sqrt(1 - x * x);
  pts.push_back({0.6, 0.8, 0});
  pts.push_back({x, y, 0});
  pts.push_back({x, y, 0});
  const SphericalTriangulation t = expect_valid(pts);
  ASSERT_EQ(t.duplicates.size(), 4u);
  const std::pair<VertexId, VertexId> want[4] = {{1, 0}, {2, 0}, {8, 7}, {11, 10}};
  for (int i = 0; i < 4; ++i) EXPECT_EQ(std::make_pair(t.duplicates[i].dropped, t.duplicates[i].kept), want[i]) << i;
}

// A point whose difference from the points' box's centre is subnormal, among an octahedron of
// radius 1e-300: a point inside, hidden. Its insertion order's key once cast NaN to an integer
// (32767.5 over the difference, infinite, times 0): the sanitizer suite's float-cast-overflow
// (which gcc's -fsanitize=undefined leaves out) reports it here, the triangulation is checked,
// and the fuzz corpus keeps the input that found it.
TEST(Sphere, APointASubnormalFromTheCentre) {
  std::vector<Point3> pts = {{1e-300, 0, 0}, {-1e-300, 0, 0}, {0, 1e-300, 0}, {0, -1e-300, 0},
                             {0, 0, 1e-300}, {0, 0, -1e-300}, {1e-320, 0, 0}};
  const SphericalTriangulation t = expect_valid(pts);
  EXPECT_EQ(t.size(), 8u);
  EXPECT_EQ(t.hidden, (std::vector<VertexId>{6}));
}

// The shortest edge is the closest pair (brute force), at scales whose squares underflow or
// overflow too, on 1 and 2 threads.
TEST(Sphere, ShortestEdgeIsTheClosestPair) {
  for (const double radius : {1.0, 1e-300, 1e300}) {
    const std::vector<Point3> pts = on_sphere(3000, 14, radius, {radius, 0, 0});
    double closest = HUGE_VAL;
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        closest = std::min(closest, std::hypot(pts[i].x - pts[j].x, pts[i].y - pts[j].y, pts[i].z - pts[j].z));
    const SphericalTriangulation t = triangulate_sphere(pts);
    for (const unsigned threads : {1u, 2u})
      EXPECT_NEAR(shortest_edge(t, pts, threads), closest, 1e-15 * closest) << radius;
  }
}

TEST(Sphere, BadInputIsRefused) {
  EXPECT_THROW(triangulate_sphere(std::vector<Point3>{{0, 0, 1}, {0, 1, 0}, {1, 0, 0}}), InputError);
  EXPECT_THROW(triangulate_sphere(std::vector<Point3>{{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {1, 0, 0}}), InputError);
  EXPECT_THROW(triangulate_sphere(std::vector<Point3>{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {5, 5, 5}}),
               InputError);
  EXPECT_THROW(triangulate_sphere(std::vector<Point3>{{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0.6, 0.8, 0}}),
               InputError);
  std::vector<Point3> nan = on_sphere(10, 1);
  nan[4].y = std::nan("");
  EXPECT_THROW(triangulate_sphere(nan), InputError);
}

TEST(Sphere, ValidatorRefusesWrongSurfaces) {
  const std::vector<Point3> pts = on_sphere(200, 4);
  const SphericalTriangulation t = triangulate_sphere(pts);
  ASSERT_TRUE(check_sphere(pts, t.triangles).valid);
  // One edge flipped: (a, b, c) and (d, c, b) across b-c become (a, b, d) and (a, d, c).
  {
    std::vector<VertexId> tris = t.triangles;
    const std::size_t g = static_cast<std::size_t>(t.neighbors[0]);
    const VertexId a = tris[0], b = tris[1], c = tris[2];
    VertexId d = 0;
    for (int i = 0; i < 3; ++i)
      if (tris[3 * g + i] != b && tris[3 * g + i] != c) d = tris[3 * g + i];
    tris[0] = a, tris[1] = b, tris[2] = d;
    tris[3 * g] = a, tris[3 * g + 1] = d, tris[3 * g + 2] = c;
    const CheckResult r = check_sphere(pts, tris);
    EXPECT_FALSE(r.valid);
    EXPECT_NE(r.message.find("not convex"), std::string::npos) << r.message;
  }
  // One triangle dropped; every triangle turned over; a point left out.
  {
    std::vector<VertexId> tris(t.triangles.begin() + 3, t.triangles.end());
    EXPECT_FALSE(check_sphere(pts, tris).valid);
    tris = t.triangles;
    for (std::size_t f = 0; f < tris.size(); f += 3) std::swap(tris[f + 1], tris[f + 2]);
    EXPECT_FALSE(check_sphere(pts, tris).valid);
    std::vector<Point3> fewer(pts.begin() + 1, pts.end());
    std::vector<VertexId> without = triangulate_sphere(fewer).triangles;
    for (VertexId& v : without) ++v;
    const CheckResult r = check_sphere(pts, without);
    EXPECT_FALSE(r.valid);
    EXPECT_NE(r.message.find("outside the hull"), std::string::npos) << r.message;
  }
}

TEST(Sphere, SymbolicTieIsConsistent) {
  // Four points on one circle: the perturbed sign flips with every swap of two of them, and
  // equals the determinant's sign with the ranks' order.
  const Point3 p[4] = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  const std::uint32_t rank[4] = {3, 2, 1, 0};
  const int s = detail::orient3d_sos(p[0], p[1], p[2], p[3], rank[0], rank[1], rank[2], rank[3]);
  EXPECT_NE(s, 0);
  EXPECT_EQ(detail::orient3d_sos(p[1], p[0], p[2], p[3], rank[1], rank[0], rank[2], rank[3]), -s);
  EXPECT_EQ(detail::orient3d_sos(p[0], p[1], p[3], p[2], rank[0], rank[1], rank[3], rank[2]), -s);
  EXPECT_EQ(detail::orient3d_sos(p[1], p[2], p[3], p[0], rank[1], rank[2], rank[3], rank[0]), -s);
}

TEST(SphericalVoronoiCells, CirclesCellsAndAreas) {
  const Point3 c{3, -1, 2};
  const double r = 2.5;
  for (const std::size_t n : {10u, 5000u}) {
    const std::vector<Point3> pts = on_sphere(n, 9, r, c);
    const SphericalTriangulation t = triangulate_sphere(pts);
    const SphericalVoronoi one = spherical_voronoi(t, pts, c, r, true, 1);
    const SphericalVoronoi two = spherical_voronoi(t, pts, c, r, true, 2);
    EXPECT_EQ(one.regions, two.regions);
    EXPECT_EQ(one.areas, two.areas);
    ASSERT_EQ(one.vertices.size(), t.size());
    auto d = [](const Point3& a, const Point3& b) { return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z); };
    for (std::size_t f = 0; f < t.size(); ++f) {
      const Point3& v = one.vertices[f];
      EXPECT_NEAR(d(v, c), r, 1e-12 * r);
      const double da = d(v, pts[t.triangles[3 * f]]);
      EXPECT_NEAR(d(v, pts[t.triangles[3 * f + 1]]), da, 1e-9 * r);
      EXPECT_NEAR(d(v, pts[t.triangles[3 * f + 2]]), da, 1e-9 * r);
    }
    double total = 0;
    for (std::size_t g = 0; g < n; ++g) {
      const std::uint32_t* cell = one.regions.data() + one.region_start[g];
      const std::size_t size = one.region_start[g + 1] - one.region_start[g];
      ASSERT_GE(size, 3u);
      // Counter-clockwise round the point, seen from outside.
      for (std::size_t k = 0; k < size; ++k)
        EXPECT_LT(orientation(c, pts[g], one.vertices[cell[k]], one.vertices[cell[(k + 1) % size]]), 0);
      EXPECT_GT(one.areas[g], 0);
      total += one.areas[g];
    }
    EXPECT_NEAR(total, 4 * kPi * r * r, 1e-10 * r * r);
  }
  // A cube's eight cells are equal.
  std::vector<Point3> cube;
  for (int i = 0; i < 8; ++i) cube.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
  const SphericalVoronoi v = spherical_voronoi(triangulate_sphere(cube), cube, {}, std::sqrt(3.0));
  for (const double a : v.areas) EXPECT_NEAR(a, 4 * kPi * 3 / 8, 1e-12);
}

// The circle centres' directions (sphere/geometry.hpp's unit_normal) within their bound, 2^-48,
// of the normal computed in long double from exactly subtracted sides: on caps of three points
// an ulp to 10^-3 apart, about each axis (a normal along an axis leaves two components near 0,
// which a bound relative to each would send to the exact path), and at scales from 2^-600 to
// 2^600 (scaled there by a power of two).
TEST(SphericalVoronoiCells, CircleCentresWithinTheirBound) {
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> u(-1, 1);
  int tried = 0;
  for (const double scale : {0x1p-600, 1e-3, 1.0, 7e5, 0x1p600})
    for (const double spread : {1e-3, 1e-8, 1e-13})
      for (int axis = 0; axis < 4; ++axis)
        for (int k = 0; k < 20; ++k) {
          // A cap about an axis (or a random direction), three points within `spread` of its centre.
          Point3 centre = axis == 0 ? Point3{1, 0, 0}
              : axis == 1           ? Point3{0, 1, 0}
              : axis == 2           ? Point3{0, 0, 1}
                                    : Point3{u(random), u(random), u(random)};
          std::vector<Point3> pts;
          for (int i = 0; i < 3; ++i) {
            const Point3 p{centre.x + spread * u(random), centre.y + spread * u(random), centre.z + spread * u(random)};
            const double l = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
            pts.push_back({p.x / l * scale, p.y / l * scale, p.z / l * scale});
          }
          pts.push_back({-centre.x * scale, -centre.y * scale, -centre.z * scale});  // a fourth, far off
          if (orientation(pts[0], pts[1], pts[2], pts[3]) == 0) continue;
          const SphericalTriangulation t = triangulate_sphere(pts);
          const SphericalVoronoi v = spherical_voronoi(t, pts, {}, 1);
          for (std::size_t f = 0; f < t.size(); ++f) {
            // From the corner across the longest side (from another, a needle's two long sides
            // nearly parallel would cancel the products' digits), sides exact in long double,
            // scaled to keep the products in range.
            const Point3* q[3] = {&pts[t.triangles[3 * f]], &pts[t.triangles[3 * f + 1]], &pts[t.triangles[3 * f + 2]]};
            auto length = [&](int i) {
              const Point3 &x = *q[(i + 1) % 3], &y = *q[(i + 2) % 3];
              return std::hypot(x.x / scale - y.x / scale, x.y / scale - y.y / scale, x.z / scale - y.z / scale);
            };
            const int o = length(0) >= length(1) && length(0) >= length(2) ? 0 : length(1) >= length(2) ? 1 : 2;
            const Point3 &a = *q[o], &b = *q[(o + 1) % 3], &c = *q[(o + 2) % 3];
            const long double s = 1 / static_cast<long double>(scale);
            const long double bx = (static_cast<long double>(b.x) - a.x) * s,
                              by = (static_cast<long double>(b.y) - a.y) * s,
                              bz = (static_cast<long double>(b.z) - a.z) * s;
            const long double cx = (static_cast<long double>(c.x) - a.x) * s,
                              cy = (static_cast<long double>(c.y) - a.y) * s,
                              cz = (static_cast<long double>(c.z) - a.z) * s;
            const long double nx = by * cz - bz * cy, ny = bz * cx - bx * cz, nz = bx * cy - by * cx;
            const long double l = std::sqrt(nx * nx + ny * ny + nz * nz);
            const Point3& got = v.vertices[f];
            const long double error =
                std::sqrt((got.x - nx / l) * (got.x - nx / l) + (got.y - ny / l) * (got.y - ny / l) +
                          (got.z - nz / l) * (got.z - nz / l));
            EXPECT_LT(static_cast<double>(error), 0x1p-48) << scale << " " << spread << " " << axis;
            ++tried;
          }
        }
  EXPECT_GT(tried, 1000);
}

TEST(SphereInterpolation, LinearOnTheSphere) {
  const Point3 c{1, -2, 3};
  const std::vector<Point3> pts = on_sphere(20000, 12, 2, c);
  const SphericalTriangulation t = triangulate_sphere(pts);
  // Two values a point: a constant and the height above the centre.
  std::vector<double> values;
  for (const Point3& p : pts) values.insert(values.end(), {7.25, p.z - c.z});
  const std::vector<Point3> queries = on_sphere(5000, 13, 3, c);
  const std::vector<double> one = interpolate_sphere_linear(t, pts, values, 2, queries, c, -1, 1);
  const std::vector<double> two = interpolate_sphere_linear(t, pts, values, 2, queries, c, -1, 2);
  EXPECT_EQ(one, two);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    EXPECT_NEAR(one[2 * i], 7.25, 1e-14);
    // The height of the query's direction on the sphere of radius 2, within the mesh's error.
    EXPECT_NEAR(one[2 * i + 1], (queries[i].z - c.z) * 2 / 3, 2e-3);
  }
  // At the data points (any distance along their direction) the data.
  std::vector<Point3> at;
  for (std::size_t i = 0; i < 500; ++i)
    at.push_back({c.x + (pts[i].x - c.x) * 5, c.y + (pts[i].y - c.y) * 5, c.z + (pts[i].z - c.z) * 5});
  const std::vector<double> data = interpolate_sphere_linear(t, pts, values, 2, at, c);
  for (std::size_t i = 0; i < at.size(); ++i) EXPECT_NEAR(data[2 * i + 1], values[2 * i + 1], 1e-13);
  // Points in one hemisphere: beyond them, the fill.
  std::vector<Point3> half = on_sphere(2000, 14);
  for (Point3& p : half) p.x = std::fabs(p.x);
  const SphericalTriangulation h = triangulate_sphere(half);
  const std::vector<double> ones(half.size(), 1.0);
  const std::vector<Point3> probes{{1, 0.1, 0.2}, {-1, 0.1, 0.2}, {-1, -0.5, 0}};
  const std::vector<double> got = interpolate_sphere_linear(h, half, ones, 1, probes, {});
  EXPECT_NEAR(got[0], 1, 1e-14);
  EXPECT_TRUE(std::isnan(got[1]) && std::isnan(got[2]));
  EXPECT_THROW(interpolate_sphere_linear(h, half, ones, 2, probes, {}), InputError);
}

TEST(SphereInterpolation, NaturalNeighbourOnTheSphere) {
  const Point3 c{1, -2, 3};
  const std::vector<Point3> pts = on_sphere(20000, 15, 2, c);
  const SphericalTriangulation t = triangulate_sphere(pts);
  std::vector<double> values;
  for (const Point3& p : pts) values.insert(values.end(), {7.25, p.z - c.z});
  std::vector<Point3> queries = on_sphere(5000, 16, 3, c);
  for (std::size_t i = 0; i < 300; ++i)  // at the data points (any distance along their direction)
    queries.push_back({c.x + (pts[i].x - c.x) * 5, c.y + (pts[i].y - c.y) * 5, c.z + (pts[i].z - c.z) * 5});
  const std::vector<double> one = interpolate_sphere_natural(t, pts, values, 2, queries, c, -1, 1);
  EXPECT_EQ(one, interpolate_sphere_natural(t, pts, values, 2, queries, c, -1, 2));
  for (std::size_t i = 0; i < 5000; ++i) {
    EXPECT_NEAR(one[2 * i], 7.25, 1e-13);
    EXPECT_NEAR(one[2 * i + 1], (queries[i].z - c.z) * 2 / 3, 2e-3);
  }
  for (std::size_t i = 0; i < 300; ++i) EXPECT_NEAR(one[2 * (5000 + i) + 1], values[2 * i + 1], 1e-9);
  // Points in one hemisphere: beyond them, the fill.
  std::vector<Point3> half = on_sphere(2000, 14);
  for (Point3& p : half) p.x = std::fabs(p.x);
  const SphericalTriangulation h = triangulate_sphere(half);
  const std::vector<double> ones(half.size(), 1.0);
  const std::vector<double> got =
      interpolate_sphere_natural(h, half, ones, 1, std::vector<Point3>{{1, 0.1, 0.2}, {-1, 0.1, 0.2}}, {});
  EXPECT_NEAR(got[0], 1, 1e-13);
  EXPECT_TRUE(std::isnan(got[1]));
}

TEST(SphereInterpolation, NaturalNeighbourInASmallCapIsThePlanesSibson) {
  // In a cap 0.01 across the sphere is nearly flat: the weights differ from the plane's (of the
  // points projected stereographically, which keeps circles circles) by about the cap's size
  // squared.
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> u(-0.01, 0.01);
  std::vector<Point3> pts;
  std::vector<Point> flat;
  auto lift = [](double x, double y) {  // the inverse stereographic projection from the south pole
    const double s = x * x + y * y;
    return Point3{4 * x / (4 + s), 4 * y / (4 + s), (4 - s) / (4 + s)};
  };
  for (int i = 0; i < 600; ++i) {
    const double x = u(random), y = u(random);
    flat.push_back({x, y}), pts.push_back(lift(x, y));
  }
  // Seven more points far away, so that the hull holds the centre.
  for (const Point3& p : std::vector<Point3>{
           {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0.6, 0.6, -0.53}, {-0.6, 0.6, -0.53}})
    pts.push_back(p);
  std::vector<double> values;
  for (const Point3& p : pts) values.push_back(p.x * 100 + std::sin(p.y * 300));
  const SphericalTriangulation t = triangulate_sphere(pts);
  const Triangulation planar = triangulate(flat);
  std::vector<Point3> queries;
  std::vector<Point> flat_queries;
  for (int i = 0; i < 400; ++i) {
    const double x = u(random) * 0.8, y = u(random) * 0.8;
    flat_queries.push_back({x, y}), queries.push_back(lift(x, y));
  }
  const std::vector<double> sphere = interpolate_sphere_natural(t, pts, values, 1, queries, {});
  const std::vector<double> plane =
      interpolate_natural_neighbor(flat, planar, {std::span<const double>(values).first(600), 1}, flat_queries);
  for (std::size_t i = 0; i < queries.size(); ++i) EXPECT_NEAR(sphere[i], plane[i], 1e-5) << i;
}

}  // namespace
}  // namespace ridt
