// The terrain calls: heights of duplicates merged by each policy, the raster's geometry, a DEM
// equal cell by cell to the interpolation calls at the cells' centres (every method, any
// thread count, bands or whole), long edges killed, nearest against brute force, hillshade of
// planes whose shade is known.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "helpers.hpp"
#include "ridt/interpolate.hpp"
#include "ridt/terrain.hpp"

namespace ridt {
namespace {

std::vector<Point> random_points(std::size_t n, std::uint64_t seed, double side = 100) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, side);
  std::vector<Point> p(n);
  for (Point& q : p) q = {u(rng), u(rng)};
  return p;
}

std::vector<double> heights(std::span<const Point> p) {
  std::vector<double> z;
  for (const Point& q : p) z.push_back(std::sin(q.x / 7) * 10 + q.y * 0.3);
  return z;
}

bool same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

TEST(MergeHeights, EveryPolicyOverAGroupOfEqualPoints) {
  const std::vector<Point> p = {{0, 0}, {1, 0}, {0, 1}, {1, 0}, {1, 1}, {1, 0}};
  const Triangulation t = triangulate(p);
  ASSERT_EQ(t.duplicates.size(), 2u);  // 3 and 5 stand for 1
  const std::vector<double> z0 = {0, 5, 0, 2, 0, 8};
  const std::pair<Merge, double> cases[] = {
      {Merge::First, 5}, {Merge::Last, 8}, {Merge::Lowest, 2}, {Merge::Highest, 8}, {Merge::Mean, 5}};
  for (const auto& [how, want] : cases) {
    std::vector<double> z = z0;
    merge_heights(t, z, how);
    EXPECT_EQ(z[1], want) << to_string(how);
    EXPECT_EQ(z[0], 0);
    EXPECT_EQ(z[3], 2);  // a dropped point's own stays
  }
  std::vector<double> few(2);
  EXPECT_THROW(merge_heights(t, few, Merge::Mean), InputError);
}

TEST(RasterGrid, EdgesOnMultiplesOfTheCell) {
  const RasterGrid g = RasterGrid::around(0.3, -1.2, 10.1, 4.0, 0.5);
  EXPECT_EQ(g.x0, 0.0);
  EXPECT_EQ(g.y1, 4.0);
  EXPECT_EQ(g.nx, 21u);  // 0 .. 10.5
  EXPECT_EQ(g.ny, 11u);  // -1.5 .. 4.0
  EXPECT_EQ(g.x(0), 0.25);
  EXPECT_EQ(g.y(0), 3.75);
  EXPECT_EQ(RasterGrid::around(2, 2, 2, 2, 1).size(), 1u);
  EXPECT_THROW(RasterGrid::around(0, 0, 1, 1, 0), InputError);
  EXPECT_THROW(RasterGrid::around(0, 0, 1, 1, std::nan("")), InputError);
  EXPECT_THROW(RasterGrid::around(1, 0, 0, 1, 1), InputError);
  EXPECT_THROW(RasterGrid::around(0, 0, 1e9, 1e9, 1e-3), InputError);
  // Cells of a few units in the last place of their coordinates: centres that would coincide
  // (the fuzzer's LAS file far from the origin), refused here and by a Dem given such a grid.
  EXPECT_THROW(RasterGrid::around(1e16, 0, 1e16 + 64, 1, 1), InputError);  // an ulp there is 2
  EXPECT_EQ(RasterGrid::around(1e15, 0, 1e15 + 64, 1, 1).nx, 64u);  // an ulp there is 1/8
  const std::vector<Point> pts = {{1e16, 0}, {1e16 + 64, 0}, {1e16, 64}};
  const RasterGrid fine{1e16, 64, 1, 64, 64};
  EXPECT_THROW(Dem(pts, triangulate(pts), std::vector<double>{1, 2, 3}, fine), InputError);
}

// A DEM with a max_edge gives the same cells from the triangles in any order and stored from
// any corner: a cell centre on a vertex or side shared by a short and a long triangle is the
// short one's. Cell centres here are the vertices of a lattice, with far points whose long
// triangles reach it.
TEST(Dem, TheSameCellsFromTheTrianglesInAnyOrder) {
  std::vector<Point> p;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) p.push_back({i + 0.5, j + 0.5});
  for (const Point& far : {Point{-30, 10.2}, Point{50, 9.7}, Point{10.3, -30}, Point{9.6, 50}}) p.push_back(far);
  const std::vector<double> z = heights(p);
  const Triangulation t = triangulate(p), s = test::shuffled(t, 3);
  const RasterGrid g = RasterGrid::around(0, 0, 20, 20, 1);
  for (const Surface m : {Surface::Linear, Surface::Natural})
    for (const unsigned threads : {1u, 2u}) {
      DemOptions o;
      o.method = m;
      o.threads = threads;
      o.max_edge = 3;
      const std::vector<double> want = Dem(p, t, z, g, o).all(), got = Dem(p, s, z, g, o).all();
      ASSERT_EQ(want.size(), got.size());
      std::size_t on_vertices = 0;
      for (std::size_t k = 0; k < want.size(); ++k) {
        EXPECT_TRUE(same(want[k], got[k])) << to_string(m) << " cell " << k;
        const double i = g.x(k % g.nx) - 0.5, j = g.y(k / g.nx) - 0.5;  // the lattice point there, if any
        if (i == std::floor(i) && j == std::floor(j) && i >= 0 && i < 20 && j >= 0 && j < 20) {
          EXPECT_EQ(want[k], z[static_cast<std::size_t>(i) * 20 + static_cast<std::size_t>(j)]) << to_string(m);
          ++on_vertices;
        }
      }
      EXPECT_EQ(on_vertices, 400u);  // every lattice point has its cell
    }
}

// Every cell equals the interpolation call at its centre, for each method and thread count.
TEST(Dem, EqualsTheInterpolationAtTheCellCentres) {
  const std::vector<Point> p = random_points(3000, 7);
  const std::vector<double> z = heights(p);
  const Triangulation t = triangulate(p);
  const RasterGrid g = RasterGrid::around(-3, -3, 103, 103, 0.7);  // cells outside the hull too
  std::vector<Point> centres;
  for (std::size_t j = 0; j < g.ny; ++j)
    for (std::size_t i = 0; i < g.nx; ++i) centres.push_back({g.x(i), g.y(j)});
  const std::vector<double> linear = interpolate_linear(p, t, {z, 1}, centres);
  const std::vector<double> natural = interpolate_natural_neighbor(p, t, {z, 1}, centres);
  const std::vector<std::int32_t> near = nearest_vertex(p, t, centres);
  for (const Surface s : {Surface::Linear, Surface::Natural, Surface::Nearest})
    for (const unsigned threads : {1u, 3u}) {
      DemOptions o;
      o.method = s;
      o.threads = threads;
      const std::vector<double> v = Dem(p, t, z, g, o).all();
      ASSERT_EQ(v.size(), centres.size());
      std::size_t inside = 0;
      for (std::size_t k = 0; k < v.size(); ++k) {
        if (std::isnan(linear[k])) {
          EXPECT_TRUE(std::isnan(v[k])) << k;  // outside the hull
          continue;
        }
        ++inside;
        if (s == Surface::Nearest) {
          // A nearest point: the same distance as the one nearest_vertex found (ties may differ).
          const Point& q = centres[k];
          const auto dist = [&](double h) {
            double best = HUGE_VAL;
            for (std::size_t i = 0; i < p.size(); ++i)
              if (z[i] == h) best = std::min(best, std::hypot(p[i].x - q.x, p[i].y - q.y));
            return best;
          };
          if (v[k] != z[static_cast<std::size_t>(near[k])]) {
            EXPECT_EQ(dist(v[k]), dist(z[near[k]])) << k;
          }
        } else {
          EXPECT_TRUE(same(v[k], s == Surface::Linear ? linear[k] : natural[k])) << to_string(s) << " cell " << k;
        }
      }
      EXPECT_GT(inside, v.size() * 8 / 10);
    }
}

TEST(Dem, LongEdgesLeaveNoData) {
  // Two clusters far apart: the triangles that bridge them have sides over 50.
  std::vector<Point> p = random_points(400, 3, 20);
  for (const Point& q : random_points(400, 4, 20)) p.push_back({q.x + 80, q.y});
  const std::vector<double> z(p.size(), 1.0);
  const Triangulation t = triangulate(p);
  const RasterGrid g = RasterGrid::around(0, 0, 100, 20, 1);
  DemOptions o;
  o.max_edge = 10;
  o.nodata = -9999;
  const std::vector<double> v = Dem(p, t, z, g, o).all();
  std::size_t gap = 0, data = 0;
  for (std::size_t j = 2; j + 2 < g.ny; ++j)
    for (std::size_t i = 0; i < g.nx; ++i) {
      const double x = g.x(i), value = v[j * g.nx + i];
      if (x > 30 && x < 70) {
        EXPECT_EQ(value, -9999) << i << "," << j;
        ++gap;
      }
      if ((x > 3 && x < 17) || (x > 83 && x < 97)) data += std::abs(value - 1.0) < 1e-12;
    }
  EXPECT_GT(gap, 0u);
  EXPECT_GT(data, 2u * 14 * 14);
  EXPECT_THROW(Dem(p, t, z, g, DemOptions{Surface::Linear, 0}), InputError);
}

TEST(Dem, BandsAreTheWholeRasterInPieces) {
  const std::vector<Point> p = random_points(20000, 11, 1000);
  const std::vector<double> z = heights(p);
  const Triangulation t = triangulate(p);
  const RasterGrid g = RasterGrid::around(0, 0, 1000, 1000, 3.3);
  DemOptions options;
  options.band_rows = 64;
  const Dem dem(p, t, z, g, options);
  ASSERT_GT(dem.bands(), 2u);
  EXPECT_EQ(Dem(p, t, z, g).bands(), 1u);  // 303 rows of 303 cells: one band by default
  const std::vector<double> whole = dem.all();
  std::vector<double> band((dem.band_rows()) * g.nx);
  dem.band(1, band);
  for (std::size_t k = 0; k < band.size(); ++k) ASSERT_TRUE(same(band[k], whole[dem.band_rows() * g.nx + k])) << k;
  EXPECT_THROW(dem.band(dem.bands(), band), InputError);
  std::vector<double> small(3);
  EXPECT_THROW(dem.band(0, small), InputError);
  const std::vector<double> wrong(p.size() - 1);
  EXPECT_THROW(Dem(p, t, wrong, g), InputError);
}

TEST(Hillshade, PlanesLitAsTheSunSees) {
  const std::size_t n = 5;
  std::vector<double> flat(n * n, 3.0), west(n * n), hole(n * n, 1.0);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) west[j * n + i] = -static_cast<double>(i);  // falls to the east
  hole[12] = std::nan("");
  const std::vector<std::uint8_t> f = hillshade(flat, n, n, 1, std::nan(""));
  // Flat ground under a sun 45 degrees high: cos 45 of the light.
  EXPECT_EQ(f[12], 1 + std::lround(254 * std::cos(M_PI / 4)));
  EXPECT_EQ(f[0], 0);  // the border has no full window
  // A slope of 45 degrees falling east, the sun in the east 45 degrees high: lit straight on.
  EXPECT_EQ(hillshade(west, n, n, 1, std::nan(""), 90, 45)[12], 255);
  // The same slope with the sun in the west, 45 degrees high: grazing light, none.
  EXPECT_EQ(hillshade(west, n, n, 1, std::nan(""), 270, 45)[12], 1);
  const std::vector<std::uint8_t> h = hillshade(hole, n, n, 1, std::nan(""));
  for (const std::size_t k : {6u, 7u, 8u, 11u, 12u, 13u, 16u, 17u, 18u}) EXPECT_EQ(h[k], 0) << k;
}

}  // namespace
}  // namespace ridt
