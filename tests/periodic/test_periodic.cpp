// The periodic triangulation (ridt/periodic.hpp): against the ordinary triangulation of the
// copies laid out explicitly where they are exact doubles (lattices, where every tie lives),
// on uniform, clustered and tiny sets, on domains far from the origin; the same triangles in
// any input order and on any thread count; duplicates; its validator against triangulations
// made wrong on purpose; the Voronoi cells tiling the domain.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include "periodic/periodic.hpp"
#include "ridt/periodic.hpp"
#include "ridt/ridt.hpp"
#include "tds/delaunay.hpp"

namespace ridt {
namespace {

using Corner = std::tuple<VertexId, int, int>;
using Face = std::array<Corner, 3>;

// A triangle by its corners (index, dx, dy), its least index first at offset 0.
Face face(std::array<Corner, 3> c) {
  while (c[1] < c[0] || c[2] < c[0]) std::rotate(c.begin(), c.begin() + 1, c.end());
  const int dx = std::get<1>(c[0]), dy = std::get<2>(c[0]);
  for (Corner& k : c) std::get<1>(k) -= dx, std::get<2>(k) -= dy;
  return c;
}

Point centre(const Point& a, const Point& b, const Point& c) {  // rounded: the tests leave a wide berth
  const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const double d = 2 * (bx * cy - by * cx), b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  return {a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d};
}

std::set<Face> faces(const PeriodicTriangulation& t) {
  std::set<Face> out;
  for (std::size_t f = 0; f < t.size(); ++f)
    out.insert(face({Corner{t.triangles[3 * f], t.offsets[3 * f].dx, t.offsets[3 * f].dy},
                     Corner{t.triangles[3 * f + 1], t.offsets[3 * f + 1].dx, t.offsets[3 * f + 1].dy},
                     Corner{t.triangles[3 * f + 2], t.offsets[3 * f + 2].dx, t.offsets[3 * f + 2].dy}}));
  return out;
}

PeriodicTriangulation checked(const std::vector<Point>& pts, const PeriodicDomain& d, unsigned threads = 0) {
  PeriodicTriangulation t = triangulate_periodic(pts, d, threads);
  const CheckResult r = check_periodic(pts, d, t.triangles, t.offsets);
  EXPECT_TRUE(r.valid) << r.message;
  EXPECT_EQ(t.size(), 2 * (pts.size() - t.duplicates.size()));
  EXPECT_EQ(t.neighbors.size(), t.triangles.size());
  for (std::size_t e = 0; e < t.triangles.size(); ++e) {  // corner 0: the least index, at offset 0
    EXPECT_LE(t.triangles[e - e % 3], t.triangles[e]);
    if (e % 3 == 0) {
      EXPECT_TRUE(t.offsets[e] == (Offset{0, 0}));
    }
  }
  return t;
}

// The periodic triangulation from the ordinary one of the copies in a (2k + 1) x (2k + 1)
// block of domains, exact where every copy's coordinates are doubles: the triangles whose
// least corner is a point as given and whose circle stays within the block.
std::set<Face> by_copies(const std::vector<Point>& pts, const PeriodicDomain& d, int k) {
  std::vector<Point> copies;
  std::vector<Corner> corner;
  for (int dy = -k; dy <= k; ++dy)
    for (int dx = -k; dx <= k; ++dx)
      for (VertexId i = 0; i < pts.size(); ++i) {
        const Point q{pts[i].x + dx * d.width, pts[i].y + dy * d.height};
        EXPECT_EQ(q.x - dx * d.width, pts[i].x);  // exact copies only
        copies.push_back(q), corner.emplace_back(i, dx, dy);
      }
  const Triangulation t = triangulate(copies);
  std::set<Face> out;
  for (std::size_t f = 0; f < t.size(); ++f) {
    std::array<Corner, 3> c;
    for (int i = 0; i < 3; ++i) c[i] = corner[t.triangles[3 * f + i]];
    const auto low = std::min_element(c.begin(), c.end());
    if (std::get<1>(*low) != 0 || std::get<2>(*low) != 0) continue;
    const Point a = copies[t.triangles[3 * f]], b = copies[t.triangles[3 * f + 1]], e = copies[t.triangles[3 * f + 2]];
    const Point o = centre(a, b, e);
    const double r = std::hypot(a.x - o.x, a.y - o.y);
    const double inner = (k - 1) * std::min(d.width, d.height);  // the block reaches k - 1 past the domain
    if (o.x - r < d.origin.x - inner || o.x + r > d.origin.x + d.width + inner || o.y - r < d.origin.y - inner ||
        o.y + r > d.origin.y + d.height + inner)
      continue;
    out.insert(face(c));
  }
  return out;
}

std::vector<Point> uniform(std::size_t n, std::uint64_t seed, const PeriodicDomain& d = {}) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point> pts;
  for (std::size_t i = 0; i < n; ++i) {
    Point p{d.origin.x + u(random) * d.width, d.origin.y + u(random) * d.height};
    if (!(p.x < d.origin.x + d.width)) p.x = d.origin.x;
    if (!(p.y < d.origin.y + d.height)) p.y = d.origin.y;
    pts.push_back(p);
  }
  return pts;
}

TEST(Periodic, LatticesAgreeWithTheCopiesTriangulated) {
  // Integer points in an integer domain: every copy is exact, and a lattice's squares are all
  // cocircular, so only the perturbation decides (the same as triangulate()'s).
  for (const auto& [w, h, step] : {std::tuple{8, 8, 1}, std::tuple{12, 6, 2}, std::tuple{5, 7, 1}}) {
    std::vector<Point> pts;
    for (int y = 0; y < h; y += step)
      for (int x = 0; x < w; x += step) pts.push_back({double(x), double(y)});
    const PeriodicDomain d{{0, 0}, double(w), double(h)};
    EXPECT_EQ(faces(checked(pts, d)), by_copies(pts, d, 2)) << w << "x" << h;
  }
  // Random small integers: collinear and cocircular sets everywhere.
  std::mt19937_64 random(3);
  for (int round = 0; round < 20; ++round) {
    std::vector<Point> pts;
    std::set<std::pair<int, int>> seen;
    const int n = 3 + round * 2;
    while (int(pts.size()) < n) {
      const int x = int(random() % 10), y = int(random() % 10);
      if (seen.insert({x, y}).second) pts.push_back({double(x), double(y)});
    }
    const PeriodicDomain d{{0, 0}, 10, 10};
    EXPECT_EQ(faces(checked(pts, d)), by_copies(pts, d, 3)) << "round " << round;
  }
}

TEST(Periodic, RandomPointsAgreeWithTheCopiesWhereExact) {
  // Coordinates on a grid of 2^-20 in a domain of width 1: the copies are exact doubles.
  std::mt19937_64 random(11);
  std::vector<Point> pts;
  for (int i = 0; i < 3000; ++i)
    pts.push_back({std::ldexp(double(random() % (1u << 20)), -20), std::ldexp(double(random() % (1u << 20)), -20)});
  std::sort(pts.begin(), pts.end(),
            [](const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  EXPECT_EQ(faces(checked(pts, {})), by_copies(pts, {}, 2));
}

TEST(Periodic, TinySetsCoverTheTorus) {
  // One point: its copies are a lattice; two triangles. Up to a handful: copies of one point
  // may be corners of one triangle.
  for (std::size_t n = 1; n <= 6; ++n)
    for (std::uint64_t seed = 0; seed < 5; ++seed) {
      const std::vector<Point> pts = uniform(n, seed);
      const PeriodicVoronoi v = periodic_voronoi(pts, checked(pts, {}));
      double area = 0;  // the cells, each round its point, add up to the domain
      for (std::size_t i = 0; i < n; ++i)
        for (std::uint32_t k = v.cell_offsets[i]; k < v.cell_offsets[i + 1]; ++k) {
          const std::uint32_t l = k + 1 < v.cell_offsets[i + 1] ? k + 1 : v.cell_offsets[i];
          const Point p = v.vertices[static_cast<std::size_t>(v.cell_vertices[k])],
                      q = v.vertices[static_cast<std::size_t>(v.cell_vertices[l])];
          const double px = p.x + v.cell_shifts[k].dx - pts[i].x, py = p.y + v.cell_shifts[k].dy - pts[i].y;
          const double qx = q.x + v.cell_shifts[l].dx - pts[i].x, qy = q.y + v.cell_shifts[l].dy - pts[i].y;
          area += (px * qy - py * qx) / 2;
        }
      EXPECT_NEAR(area, 1.0, 1e-12) << n << " points, seed " << seed;
    }
  const PeriodicTriangulation one = checked({{0.25, 0.5}}, {});
  EXPECT_EQ(one.size(), 2u);
  checked({{0, 0}}, {{0, 0}, 3, 1});  // a long thin domain
}

TEST(Periodic, FarFromTheOriginAndOddDomains) {
  for (const PeriodicDomain& d : {PeriodicDomain{{1e6, -2e6}, 3.7, 0.9}, PeriodicDomain{{-1e-9, 5e-10}, 1e-9, 3e-9},
                                  PeriodicDomain{{0.1, 0.1}, 0.3, 0.3}, PeriodicDomain{{1e15, 1e15}, 1024, 1024}})
    checked(uniform(2000, 5, d), d);
}

TEST(Periodic, ClusteredAndAstrideTheSides) {
  std::mt19937_64 random(17);
  std::normal_distribution<double> g(0, 0.003);
  std::vector<Point> pts = uniform(300, 1);
  for (int i = 0; i < 3000; ++i) {
    double x = std::fmod(1.0 + g(random), 1.0), y = std::fmod(1.0 + 0.5 + g(random), 1.0);
    if (!(x < 1)) x = 0;
    pts.push_back({x, y});
  }
  checked(pts, {});
}

TEST(Periodic, SameOnAnyOrderAndThreadCount) {
  std::vector<Point> pts = uniform(20000, 9);
  const std::set<Face> base = faces(checked(pts, {}, 1));
  for (const unsigned threads : {2u, 3u, 8u}) EXPECT_EQ(faces(checked(pts, {}, threads)), base);
  for (const std::size_t n : {std::size_t{300}, pts.size()})  // the whole way and the split way
    for (const unsigned threads : {1u, 2u}) {
      const std::vector<Point> some(pts.begin(), pts.begin() + static_cast<std::ptrdiff_t>(n));
      const PeriodicTriangulation with = triangulate_periodic(some, {}, PeriodicOptions{threads, true});
      const PeriodicTriangulation bare = triangulate_periodic(some, {}, PeriodicOptions{threads, false});
      EXPECT_TRUE(bare.neighbors.empty() && bare.neighbor_offsets.empty());
      EXPECT_EQ(faces(bare), faces(with));
      if (threads == 1) {  // one thread: the same arrays (on more the triangles' order may vary)
        EXPECT_EQ(bare.triangles, with.triangles);
        EXPECT_EQ(bare.offsets, with.offsets);
      }
    }
  std::vector<VertexId> order(pts.size());
  std::iota(order.begin(), order.end(), VertexId{0});
  std::shuffle(order.begin(), order.end(), std::mt19937_64(4));
  std::vector<Point> shuffled;
  for (const VertexId i : order) shuffled.push_back(pts[i]);
  std::set<Face> back;
  for (const Face& f : faces(checked(shuffled, {}))) {
    std::array<Corner, 3> c = f;
    for (Corner& k : c) std::get<0>(k) = order[std::get<0>(k)];
    back.insert(face(c));
  }
  EXPECT_EQ(back, base);
}

// The two ways (the points' triangulation with two strips across the sides, and all the copies
// near the domain) give the same triangles, in any order: both are the periodic triangulation.
TEST(Periodic, SplitAndWholeAgree) {
  std::mt19937_64 random(21);
  std::normal_distribution<double> g(0, 0.01);
  std::vector<std::pair<std::vector<Point>, PeriodicDomain>> cases;
  cases.emplace_back(uniform(30000, 3), PeriodicDomain{});
  cases.emplace_back(uniform(8000, 4, {{-5, 7}, 2, 0.5}), PeriodicDomain{{-5, 7}, 2, 0.5});
  std::vector<Point> lattice;  // every square cocircular; copies exact
  for (int y = 0; y < 80; ++y)
    for (int x = 0; x < 64; ++x) lattice.push_back({double(x), double(y)});
  cases.emplace_back(lattice, PeriodicDomain{{0, 0}, 64, 80});
  std::vector<Point> clusters = uniform(2000, 6);  // clusters astride the sides, and duplicates
  for (int i = 0; i < 6000; ++i) {
    double x = std::fmod(1.0 + g(random), 1.0), y = std::fmod(1.0 + 0.3 * (i % 3) + g(random), 1.0);
    clusters.push_back({x < 1 ? x : 0, y < 1 ? y : 0});
  }
  for (int i = 0; i < 50; ++i) clusters.push_back(clusters[std::size_t(i) * 97]);
  cases.emplace_back(clusters, PeriodicDomain{});
  std::vector<Point> gap = uniform(20000, 8);  // none within 0.03 of x = 0: circles across that side
  for (Point& p : gap) p.x = 0.03 + 0.94 * p.x;  // too wide for the first strips (the margin doubles)
  cases.emplace_back(gap, PeriodicDomain{});
  for (const auto& [pts, d] : cases) {
    const std::optional<PeriodicTriangulation> band = detail::triangulate_periodic_split(pts, d, 2);
    ASSERT_TRUE(band.has_value()) << pts.size() << " points";
    const PeriodicTriangulation whole = detail::triangulate_periodic_whole(pts, d, 2);
    EXPECT_TRUE(check_periodic(pts, d, band->triangles, band->offsets).valid);
    EXPECT_EQ(faces(*band), faces(whole)) << pts.size() << " points";
    ASSERT_EQ(band->duplicates.size(), whole.duplicates.size());
    for (std::size_t k = 0; k < whole.duplicates.size(); ++k) {
      EXPECT_EQ(band->duplicates[k].dropped, whole.duplicates[k].dropped);
      EXPECT_EQ(band->duplicates[k].kept, whole.duplicates[k].kept);
    }
    // Each neighbour, moved by its offset, has the shared edge's two corners.
    for (std::size_t e = 0; e < band->triangles.size(); ++e) {
      const std::size_t u = static_cast<std::size_t>(band->neighbors[e]), b = e - e % 3;
      const Offset s = band->neighbor_offsets[e];
      for (const std::size_t c : {b + (e + 1) % 3, b + (e + 2) % 3}) {
        bool found = false;
        for (std::size_t j = 0; j < 3; ++j)
          found = found ||
              (band->triangles[3 * u + j] == band->triangles[c] &&
               band->offsets[3 * u + j].dx + s.dx == band->offsets[c].dx &&
               band->offsets[3 * u + j].dy + s.dy == band->offsets[c].dy);
        ASSERT_TRUE(found) << "edge " << e;
      }
    }
  }
}

TEST(Periodic, DuplicatesKeepTheLeastIndex) {
  std::vector<Point> pts = uniform(500, 2);
  pts.push_back(pts[7]), pts.push_back(pts[3]), pts.push_back(pts[7]);
  const PeriodicTriangulation t = checked(pts, {});
  ASSERT_EQ(t.duplicates.size(), 3u);
  EXPECT_EQ(t.duplicates[0].dropped, 500u);
  EXPECT_EQ(t.duplicates[0].kept, 7u);
  EXPECT_EQ(t.duplicates[1].dropped, 501u);
  EXPECT_EQ(t.duplicates[1].kept, 3u);
  EXPECT_EQ(t.duplicates[2].kept, 7u);
}

// The split way's first step: triangulate() numbering the vertices by their places in the
// insertion order, with the points in that order (the kernel's copy, or a copy where the kernel
// scaled them: 2^-1000); the same triangles as triangulate()'s once mapped back, duplicates too.
TEST(Periodic, PointsTriangulatedInInsertionOrder) {
  for (const double scale : {1.0, 0x1p-1000})
    for (const unsigned threads : {1u, 2u}) {
      std::vector<Point> pts = uniform(20000, 9);
      for (std::size_t i = 0; i < 300; ++i) pts.push_back(pts[(i * 37) % 20000]);
      for (Point& p : pts) p = {p.x * scale, p.y * scale};
      Options options;
      options.threads = threads;
      detail::InOrder in;
      const Triangulation t = detail::triangulate_in_order(pts, options, in);
      const Triangulation plain = triangulate(pts, options);
      ASSERT_EQ(in.order.size(), pts.size());
      std::vector<VertexId> sorted = in.order;
      std::sort(sorted.begin(), sorted.end());
      for (VertexId i = 0; i < pts.size(); ++i) ASSERT_EQ(sorted[i], i);
      for (VertexId v = 0; v < pts.size(); ++v) ASSERT_EQ(in.points[v], pts[in.order[v]]);
      ASSERT_EQ(t.duplicates.size(), plain.duplicates.size());
      std::vector<VertexId> least(pts.size());
      std::iota(least.begin(), least.end(), VertexId{0});
      for (const Duplicate& d : plain.duplicates) least[d.dropped] = d.kept;
      for (const Duplicate& d : t.duplicates) {  // places, the least place of a group standing
        EXPECT_LT(d.kept, d.dropped);
        EXPECT_EQ(least[in.order[d.dropped]], least[in.order[d.kept]]);
      }
      auto triples = [&](const Triangulation& x, bool places) {
        std::set<std::array<VertexId, 3>> out;
        for (std::size_t f = 0; f < x.size(); ++f) {
          std::array<VertexId, 3> c;
          for (int i = 0; i < 3; ++i) {
            const VertexId v = x.triangles[3 * f + i];
            c[i] = places ? least[in.order[v]] : v;
          }
          std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
          out.insert(c);
        }
        return out;
      };
      EXPECT_EQ(triples(t, true), triples(plain, false)) << "scale " << scale << ", threads " << threads;
    }
}

TEST(Periodic, BadInputIsRefused) {
  EXPECT_THROW(triangulate_periodic({}, {}), InputError);
  EXPECT_THROW(triangulate_periodic(std::vector<Point>{{1.0, 0.5}}, {}), InputError);  // x = x0 + width
  EXPECT_THROW(triangulate_periodic(std::vector<Point>{{-1e-300, 0.5}}, {}), InputError);
  EXPECT_THROW(triangulate_periodic(std::vector<Point>{{NAN, 0.5}}, {}), InputError);
  EXPECT_THROW(triangulate_periodic(std::vector<Point>{{0.5, 0.5}}, {{0, 0}, 0, 1}), InputError);
  EXPECT_THROW(triangulate_periodic(std::vector<Point>{{0.5, 0.5}}, {{0, 0}, 1, INFINITY}), InputError);
  // The domain's far side is exact: the double just below it is inside.
  checked({{std::nextafter(1.0, 0.0), std::nextafter(1.0, 0.0)}, {0.5, 0.5}}, {});
}

TEST(Periodic, ValidatorRefusesWrongTriangulations) {
  const std::vector<Point> pts = uniform(400, 8);
  const PeriodicTriangulation t = checked(pts, {});
  auto refuses = [&](std::vector<VertexId> tris, std::vector<Offset> offs) {
    EXPECT_FALSE(check_periodic(pts, {}, tris, offs).valid);
  };
  {  // an offset moved
    std::vector<Offset> offs = t.offsets;
    offs[4].dx += 1;
    refuses(t.triangles, offs);
  }
  {  // a triangle moved farther than an offset may be (its sums could leave the type's range)
    std::vector<Offset> offs = t.offsets;
    for (int k = 0; k < 3; ++k) offs[k].dx = static_cast<std::int16_t>(kMaxOffset + 1);
    const CheckResult r = check_periodic(pts, {}, t.triangles, offs);
    EXPECT_FALSE(r.valid);
    EXPECT_EQ(r.message, "an offset is more than 1000 periods");
  }
  {  // two corners swapped: clockwise
    std::vector<VertexId> tris = t.triangles;
    std::vector<Offset> offs = t.offsets;
    std::swap(tris[1], tris[2]), std::swap(offs[1], offs[2]);
    refuses(tris, offs);
  }
  {  // a triangle dropped
    std::vector<VertexId> tris(t.triangles.begin() + 3, t.triangles.end());
    std::vector<Offset> offs(t.offsets.begin() + 3, t.offsets.end());
    refuses(tris, offs);
  }
  {  // an edge flipped: still a triangulation of the torus, but not Delaunay
    std::vector<VertexId> tris = t.triangles;
    std::vector<Offset> offs = t.offsets;
    // Triangle 0 = (p, a, b) and its neighbour u across from p, placed beside it: (d, b, a).
    const std::size_t u = static_cast<std::size_t>(t.neighbors[0]);
    const Offset s = t.neighbor_offsets[0];
    int j = 0;
    while (t.neighbors[3 * u + j] != 0 ||
           !(t.triangles[3 * u + (j + 1) % 3] == t.triangles[2] &&
             t.offsets[3 * u + (j + 1) % 3].dx + s.dx == t.offsets[2].dx &&
             t.offsets[3 * u + (j + 1) % 3].dy + s.dy == t.offsets[2].dy))
      ++j;
    const VertexId p = t.triangles[0], a = t.triangles[1], b = t.triangles[2], dv = t.triangles[3 * u + j];
    const Offset op = t.offsets[0], oa = t.offsets[1], ob = t.offsets[2];
    const Offset od = detail::make_offset(t.offsets[3 * u + j].dx + s.dx, t.offsets[3 * u + j].dy + s.dy);
    tris[0] = p, tris[1] = a, tris[2] = dv, offs[0] = op, offs[1] = oa, offs[2] = od;
    tris[3 * u] = p, tris[3 * u + 1] = dv, tris[3 * u + 2] = b, offs[3 * u] = op, offs[3 * u + 1] = od,
             offs[3 * u + 2] = ob;
    const CheckResult r = check_periodic(pts, {}, tris, offs);
    EXPECT_FALSE(r.valid);
    EXPECT_NE(r.message.find("not"), std::string::npos) << r.message;
  }
}

TEST(Periodic, VoronoiCellsTileTheDomain) {
  for (const PeriodicDomain& d : {PeriodicDomain{}, PeriodicDomain{{-3, 2}, 2.5, 0.75}}) {
    std::vector<Point> pts = uniform(3000, 12, d);
    pts.push_back(pts[0]);  // a duplicate: no cell of its own
    const PeriodicTriangulation t = checked(pts, d);
    const PeriodicVoronoi v = periodic_voronoi(pts, t);
    ASSERT_EQ(v.vertices.size(), t.size());
    ASSERT_EQ(v.cell_offsets.size(), pts.size() + 1);
    EXPECT_EQ(v.cell_offsets[pts.size()], v.cell_offsets[pts.size() - 1]);
    double total = 0;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      double area = 0, worst = 0;
      const std::uint32_t from = v.cell_offsets[i], to = v.cell_offsets[i + 1];
      ASSERT_GE(to - from, 3u);
      for (std::uint32_t k = from; k < to; ++k) {
        auto at = [&](std::uint32_t m) {
          const Point c = v.vertices[static_cast<std::size_t>(v.cell_vertices[m])];
          return Point{c.x + v.cell_shifts[m].dx * d.width, c.y + v.cell_shifts[m].dy * d.height};
        };
        const Point p = at(k), q = at(k + 1 < to ? k + 1 : from);
        area += (p.x - pts[i].x) * (q.y - pts[i].y) - (p.y - pts[i].y) * (q.x - pts[i].x);
        worst =
            std::max(worst, (p.x - pts[i].x) * (q.y - pts[i].y) - (p.y - pts[i].y) * (q.x - pts[i].x) < 0 ? 1.0 : 0.0);
      }
      EXPECT_EQ(worst, 0.0) << "cell " << i << " turns clockwise";
      total += area / 2;
    }
    EXPECT_NEAR(total, d.width * d.height, 1e-9 * d.width * d.height);
  }
}

}  // namespace
}  // namespace ridt
