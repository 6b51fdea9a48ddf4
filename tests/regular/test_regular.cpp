// The regular triangulation (ridt/regular.hpp) against a brute-force lower hull, against the
// Delaunay kernel where the weights are equal (lattices: every tie decided the same way), in any
// input order; hidden points and copies; its validator against triangulations made wrong on
// purpose; the power diagram.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <vector>

#include "predicates/power.hpp"
#include "ridt/predicates.hpp"
#include "ridt/regular.hpp"

namespace ridt {
namespace {

struct Weighted {
  std::vector<Point> points;
  std::vector<double> weights;
};

Weighted random_weighted(std::size_t n, std::uint64_t seed, double spread = 0.01) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(0, 1), w(0, spread);
  Weighted out;
  for (std::size_t i = 0; i < n; ++i) out.points.push_back({u(random), u(random)}), out.weights.push_back(w(random));
  return out;
}

// A triangle by its corners' coordinates, from the least: the same whatever the numbering.
using Face = std::array<double, 6>;
std::set<Face> faces(const std::vector<Point>& pts, const std::vector<VertexId>& tris) {
  std::set<Face> out;
  for (std::size_t f = 0; f < tris.size() / 3; ++f) {
    std::array<Point, 3> c = {pts[tris[3 * f]], pts[tris[3 * f + 1]], pts[tris[3 * f + 2]]};
    auto less = [](const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
    while (less(c[1], c[0]) || less(c[2], c[0])) std::rotate(c.begin(), c.begin() + 1, c.end());
    out.insert({c[0].x, c[0].y, c[1].x, c[1].y, c[2].x, c[2].y});
  }
  return out;
}

RegularTriangulation checked(const Weighted& in) {
  RegularTriangulation t = triangulate_regular(in.points, in.weights);
  const CheckResult r = check_regular(in.points, in.weights, t.triangles);
  EXPECT_TRUE(r.valid) << r.message;
  return t;
}

// The regular triangulation by definition: the counter-clockwise triangles no point's lift lies
// below (points in general position: no ties).
std::set<Face> brute_force(const Weighted& in) {
  const std::size_t n = in.points.size();
  std::vector<VertexId> tris;
  auto at = [&](std::size_t i) { return detail::Weighted{in.points[i], in.weights[i]}; };
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b)
      for (std::size_t c = 0; c < n; ++c) {
        if (a == b || b == c || a == c || detail::orient2d(in.points[a], in.points[b], in.points[c]) <= 0) continue;
        bool empty = true;
        for (std::size_t d = 0; d < n && empty; ++d)
          if (d != a && d != b && d != c) empty = detail::power(at(a), at(b), at(c), at(d)) < 0;
        if (empty) tris.insert(tris.end(), {VertexId(a), VertexId(b), VertexId(c)});
      }
  return faces(in.points, tris);
}

TEST(Regular, EqualsTheLowerHullByBruteForce) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const Weighted in = random_weighted(40, seed, seed % 2 ? 0.05 : 0.002);
    const RegularTriangulation t = checked(in);
    EXPECT_EQ(faces(in.points, t.triangles), brute_force(in)) << "seed " << seed;
    std::set<VertexId> vertices(t.triangles.begin(), t.triangles.end());
    for (VertexId v = 0; v < in.points.size(); ++v)
      EXPECT_NE(vertices.count(v), std::binary_search(t.hidden.begin(), t.hidden.end(), v)) << v;
  }
}

TEST(Regular, HeavyPointsHideTheirNeighbours) {
  Weighted in = random_weighted(3000, 7, 0.0001);
  // Every 50th point heavy: its power circle swallows the light points near it.
  for (std::size_t i = 0; i < in.points.size(); i += 50) in.weights[i] = 0.004;
  const RegularTriangulation t = checked(in);
  EXPECT_GT(t.hidden.size(), 100u);
  EXPECT_EQ(t.size(), 2 * (in.points.size() - t.hidden.size()) - 2 - t.hull.size());
}

TEST(Regular, EqualWeightsGiveTheDelaunayKernelsTriangulationTieForTie) {
  // A lattice (every square cocircular), shuffled, with all weights equal: the kernel's
  // perturbation and the power test's pick the same diagonals.
  std::vector<Point> grid;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) grid.push_back({double(i), double(j)});
  std::mt19937_64 random(3);
  for (int round = 0; round < 3; ++round) {
    std::shuffle(grid.begin(), grid.end(), random);
    const std::vector<double> w(grid.size(), round == 2 ? 7.5 : 0.0);
    const RegularTriangulation r = checked({grid, w});
    EXPECT_TRUE(r.hidden.empty());
    EXPECT_EQ(faces(grid, r.triangles), faces(grid, triangulate(grid).triangles));
  }
  const Weighted in = random_weighted(5000, 11, 0);
  EXPECT_EQ(faces(in.points, checked(in).triangles), faces(in.points, triangulate(in.points).triangles));
}

TEST(Regular, TiesOnALatticeWithWeightsAreDecidedInAnyOrder) {
  // Integer points with weights 0, 1 and 2: many orthogonal circles through four points.
  Weighted in;
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j) in.points.push_back({double(i), double(j)}), in.weights.push_back((i * 7 + j * 3) % 3);
  const std::set<Face> first = faces(in.points, checked(in).triangles);
  std::vector<std::size_t> order(in.points.size());
  std::iota(order.begin(), order.end(), 0);
  std::mt19937_64 random(5);
  for (int round = 0; round < 4; ++round) {
    std::shuffle(order.begin(), order.end(), random);
    Weighted s;
    for (const std::size_t i : order) s.points.push_back(in.points[i]), s.weights.push_back(in.weights[i]);
    EXPECT_EQ(faces(s.points, checked(s).triangles), first);
  }
}

// Rounds of 4096 points or more are shared among the threads, each inserting in a region of
// its own and putting off what leaves it: the same triangles, hidden points, hull and copies on
// any number of threads, and on one number the same arrays from run to run (what a thread
// reads is its own or what no thread changes, so its choices do not hang on timing), on light
TEST(Regular, SameOutputOnAnyNumberOfThreads) {
  // Heavy weights (most points hidden), and light ones (some 14 % hidden, as many covered after
  // they came: the slots they free are taken again by the part on whose thread they were freed).
  std::vector<Weighted> inputs = {random_weighted(60000, 21), random_weighted(40000, 22, 0.2),
                                  random_weighted(60000, 25, 1.0 / 60000)};
  Weighted lattice;
  for (int i = 0; i < 150; ++i)
    for (int j = 0; j < 150; ++j)
      lattice.points.push_back({double(i), double(j)}), lattice.weights.push_back((i * 7 + j * 3) % 3);
  inputs.push_back(lattice);
  std::mt19937_64 random(23);
  std::normal_distribution<double> near(0, 1e-3);
  Weighted clusters;
  for (int i = 0; i < 40000; ++i)
    clusters.points.push_back({(i % 5) + near(random), (i % 7) + near(random)}), clusters.weights.push_back(0);
  inputs.push_back(clusters);
  Weighted copies = random_weighted(20000, 24);
  for (int i = 0; i < 3000; ++i) {
    const std::size_t k = (std::size_t(i) * 7919) % 20000;
    copies.points.push_back(copies.points[k]),
        copies.weights.push_back(copies.weights[k] + (i % 3 - 1) * 1e-3 * (i % 2));
  }
  inputs.push_back(copies);
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const RegularTriangulation one = triangulate_regular(inputs[k].points, inputs[k].weights, 1);
    const CheckResult r = check_regular(inputs[k].points, inputs[k].weights, one.triangles);
    EXPECT_TRUE(r.valid) << "input " << k << ": " << r.message;
    for (const unsigned threads : {2u, 3u, 8u}) {
      const RegularTriangulation t = triangulate_regular(inputs[k].points, inputs[k].weights, threads);
      EXPECT_EQ(faces(inputs[k].points, t.triangles), faces(inputs[k].points, one.triangles))
          << "input " << k << ", " << threads << " threads";
      const RegularTriangulation again = triangulate_regular(inputs[k].points, inputs[k].weights, threads);
      EXPECT_EQ(again.triangles, t.triangles) << "input " << k << ", " << threads << " threads";
      EXPECT_EQ(again.neighbors, t.neighbors) << "input " << k << ", " << threads << " threads";
      EXPECT_EQ(t.hidden, one.hidden) << "input " << k << ", " << threads << " threads";
      EXPECT_EQ(t.hull, one.hull) << "input " << k << ", " << threads << " threads";
      ASSERT_EQ(t.duplicates.size(), one.duplicates.size()) << "input " << k << ", " << threads << " threads";
      for (std::size_t i = 0; i < t.duplicates.size(); ++i)
        EXPECT_TRUE(t.duplicates[i].dropped == one.duplicates[i].dropped &&
                    t.duplicates[i].kept == one.duplicates[i].kept);
    }
  }
}

TEST(Regular, CopiesAndPointsAtOnePlace) {
  Weighted in = random_weighted(200, 13);
  in.points.push_back(in.points[5]), in.weights.push_back(in.weights[5]);  // a copy
  in.points.push_back(in.points[6]), in.weights.push_back(in.weights[6] + 0.01);  // heavier, same place
  in.points.push_back(in.points[7]), in.weights.push_back(in.weights[7] - 0.01);  // lighter, same place
  const RegularTriangulation t = checked(in);
  ASSERT_EQ(t.duplicates.size(), 1u);
  EXPECT_EQ(t.duplicates[0].dropped, 200u);
  EXPECT_EQ(t.duplicates[0].kept, 5u);
  EXPECT_TRUE(std::binary_search(t.hidden.begin(), t.hidden.end(), 6u));
  EXPECT_TRUE(std::binary_search(t.hidden.begin(), t.hidden.end(), 202u));
  EXPECT_FALSE(std::binary_search(t.hidden.begin(), t.hidden.end(), 201u));
}

TEST(Regular, CopiesOfHiddenPointsAreDuplicatesTheLeastIndexKept) {
  // Copies before and after their point, some of them hidden at once, some covered later by a
  // heavy point given last: every copy a duplicate of the least index of its group, which is a
  // vertex or hidden, never both, never neither.
  Weighted in = random_weighted(400, 31, 0.0005);
  const std::size_t n = in.points.size();
  for (std::size_t i = 0; i < 40; ++i) in.points.push_back(in.points[i]), in.weights.push_back(in.weights[i]);
  in.points.insert(in.points.begin(), in.points[45]), in.weights.insert(in.weights.begin(), in.weights[45]);
  in.points.push_back({0.5, 0.5}), in.weights.push_back(0.05);  // covers the middle
  const RegularTriangulation t = checked(in);
  EXPECT_EQ(t.duplicates.size(), 41u);
  std::set<VertexId> vertices(t.triangles.begin(), t.triangles.end());
  for (const Duplicate& d : t.duplicates) {
    EXPECT_LT(d.kept, d.dropped);
    EXPECT_EQ(in.points[d.kept], in.points[d.dropped]);
    EXPECT_NE(vertices.count(d.kept), std::binary_search(t.hidden.begin(), t.hidden.end(), d.kept)) << d.kept;
    EXPECT_FALSE(vertices.count(d.dropped) || std::binary_search(t.hidden.begin(), t.hidden.end(), d.dropped));
  }
  EXPECT_EQ(vertices.size() + t.hidden.size() + t.duplicates.size(), n + 42);
}

// 200,000 copies of one point, hidden by a heavy point beside it (some taken as copies of its
// vertex before it was covered, the rest hidden one by one): one group, the least index kept.
// Their hashes are one: the group is sorted whole, not pair by pair.
TEST(Regular, ManyCopiesOfAHiddenPointAreOneGroup) {
  Weighted in = random_weighted(2000, 37, 0.0001);
  const auto n = static_cast<VertexId>(in.points.size());
  for (int i = 0; i < 200000; ++i) in.points.push_back({0.25, 0.75}), in.weights.push_back(0);
  in.points.push_back({0.25, 0.7501}), in.weights.push_back(0.01);
  const RegularTriangulation t = checked(in);
  ASSERT_EQ(t.duplicates.size(), 199999u);
  std::size_t kept_first = 0;
  for (const Duplicate& d : t.duplicates) kept_first += d.kept == n;
  EXPECT_EQ(kept_first, 199999u);
  EXPECT_TRUE(std::binary_search(t.hidden.begin(), t.hidden.end(), n));
}

// Many groups of copies among many hidden points (heavy weights: most points hidden), copies
// of vertices and of hidden points, before and after them, with points at the same place and
// another weight: on 1, 2 and 3 threads (some 250,000 hidden points: the table of bits that
// picks out the possible copies is cut among three threads, not at a power of two), the
// duplicates are exactly the groups of equal weighted points found by a map, each dropped index
// kept as its group's least, and every index is a vertex, hidden or dropped, one of them.
TEST(Regular, CopiesAmongManyHiddenPointsAreTheGroupsOfEqualValues) {
  Weighted in = random_weighted(200000, 41, 0.001);  // some 80 % hidden
  std::mt19937_64 random(42);
  const std::size_t base = in.points.size();
  for (int i = 0; i < 100000; ++i) {
    const std::size_t k = random() % base;
    const double w = random() % 4 == 0 ? in.weights[k] * 0.5 : in.weights[k];  // (some at one place only)
    in.points.push_back(in.points[k]), in.weights.push_back(w);
  }
  // Some copies before their point: the input shuffled.
  std::vector<std::size_t> order(in.points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::shuffle(order.begin(), order.end(), random);
  Weighted shuffled;
  for (const std::size_t i : order) shuffled.points.push_back(in.points[i]), shuffled.weights.push_back(in.weights[i]);
  in = std::move(shuffled);
  const std::size_t n = in.points.size();
  constexpr VertexId kNone = ~VertexId{0};
  std::map<std::array<double, 3>, VertexId> least;
  std::vector<VertexId> expected(n, kNone);  // the index each one's group keeps, where it is dropped
  for (std::size_t i = 0; i < n; ++i) {
    const auto [it, first] = least.try_emplace({in.points[i].x, in.points[i].y, in.weights[i]}, VertexId(i));
    if (!first) expected[i] = it->second;
  }
  for (const unsigned threads : {1u, 2u, 3u}) {
    const RegularTriangulation t = triangulate_regular(in.points, in.weights, threads);
    EXPECT_TRUE(check_regular(in.points, in.weights, t.triangles).valid);
    EXPECT_GT(t.hidden.size(), 196608u);  // (more words than 3 times 65,536: three threads)
    std::vector<VertexId> got(n, kNone);
    for (const Duplicate& d : t.duplicates) got[d.dropped] = d.kept;
    EXPECT_EQ(got, expected) << threads << " threads";
    EXPECT_TRUE(std::is_sorted(t.hidden.begin(), t.hidden.end()));
    std::vector<int> roles(n, 0);
    for (const VertexId v : t.triangles) roles[v] = 1;
    for (const VertexId v : t.hidden) roles[v] += 2;
    for (const Duplicate& d : t.duplicates) roles[d.dropped] += 4;
    for (std::size_t i = 0; i < n; ++i) ASSERT_TRUE(roles[i] == 1 || roles[i] == 2 || roles[i] == 4) << i;
  }
}

// Zeros of either sign are one value, in the coordinates and in the weight: hidden copies that
// differ only there are one group; a point at the same place with another weight is not of it.
TEST(Regular, HiddenCopiesWithSignedZerosAreOneGroup) {
  Weighted in;  // lifts -1 at the corners, 0 and 1 in the middle: the middle ones hidden
  in.points = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, 0}, {-0.0, 0}, {0, -0.0}, {0, 0}};
  in.weights = {3, 3, 3, 3, 0, -0.0, 0, -1};
  const RegularTriangulation t = checked(in);
  EXPECT_EQ(t.hidden, (std::vector<VertexId>{4, 7}));
  ASSERT_EQ(t.duplicates.size(), 2u);
  EXPECT_EQ(t.duplicates[0].dropped, 5u);
  EXPECT_EQ(t.duplicates[0].kept, 4u);
  EXPECT_EQ(t.duplicates[1].dropped, 6u);
  EXPECT_EQ(t.duplicates[1].kept, 4u);
}

TEST(Regular, CollinearHullPointsAndHiddenOnesOnTheHull) {
  // A square's sides full of points; some of those on the bottom side made light enough that
  // their neighbours on the side hide them.
  Weighted in;
  for (int i = 0; i <= 20; ++i) {
    in.points.push_back({double(i), 0}), in.weights.push_back(i % 4 == 1 ? -3.0 : 0.0);
    in.points.push_back({double(i), 20}), in.weights.push_back(0);
    if (i > 0 && i < 20) in.points.push_back({0, double(i)}), in.weights.push_back(0);
    if (i > 0 && i < 20) in.points.push_back({20, double(i)}), in.weights.push_back(0);
  }
  in.points.push_back({10, 10}), in.weights.push_back(30);
  const RegularTriangulation t = checked(in);
  EXPECT_EQ(t.hidden.size(), 5u);  // x = 1, 5, 9, 13, 17 on the bottom side
}

TEST(Regular, RefusesWhatHasNoTriangulation) {
  EXPECT_THROW(triangulate_regular(std::vector<Point>{{0, 0}, {1, 1}, {2, 2}}, std::vector<double>{0, 1, 2}),
               InputError);
  EXPECT_THROW(triangulate_regular(std::vector<Point>{{0, 0}, {1, 0}}, std::vector<double>{0, 0}), InputError);
  EXPECT_THROW(triangulate_regular(std::vector<Point>{{0, 0}, {1, 0}, {0, 1}}, std::vector<double>{0, 0}), InputError);
  EXPECT_THROW(triangulate_regular(std::vector<Point>{{0, 0}, {1, 0}, {0, 1}}, std::vector<double>{0, NAN, 0}),
               InputError);
  EXPECT_THROW(triangulate_regular(std::vector<Point>{{0, 0}, {1, 0}, {0, INFINITY}}, std::vector<double>{0, 0, 0}),
               InputError);
  // Three places, one of them twice with other weights: a triangle.
  const RegularTriangulation t =
      triangulate_regular(std::vector<Point>{{0, 0}, {1, 0}, {0, 1}, {0, 0}}, std::vector<double>{0, 0, 0, 1});
  EXPECT_EQ(t.size(), 1u);
  EXPECT_EQ(t.hidden, std::vector<VertexId>{0});
}

TEST(Regular, HugeAndTinyCoordinatesAndWeightsGiveTheSameTriangles) {
  // Scaled by powers of two (coordinates by s, weights by s^2, exactly): the same triangles.
  const Weighted in = random_weighted(2000, 17, 0.001);
  auto triples = [](const RegularTriangulation& t) {
    std::set<std::array<VertexId, 3>> out;
    for (std::size_t f = 0; f < t.size(); ++f) {
      std::array<VertexId, 3> c = {t.triangles[3 * f], t.triangles[3 * f + 1], t.triangles[3 * f + 2]};
      std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
      out.insert(c);
    }
    return out;
  };
  const RegularTriangulation plain = checked(in);
  for (const double scale : {0x1p-500, 0x1p-20, 0x1p20, 0x1p500}) {
    Weighted s = in;
    for (std::size_t i = 0; i < s.points.size(); ++i)
      s.points[i] = {s.points[i].x * scale + 3 * scale, s.points[i].y * scale}, s.weights[i] *= scale * scale;
    const RegularTriangulation t = checked(s);
    EXPECT_EQ(triples(t), triples(plain)) << scale;
    EXPECT_EQ(t.hidden, plain.hidden);
  }
}

TEST(RegularCheck, RefusesWrongTriangulations) {
  const Weighted in = random_weighted(300, 19, 0.004);
  const RegularTriangulation t = triangulate_regular(in.points, in.weights);
  ASSERT_TRUE(check_regular(in.points, in.weights, t.triangles).valid);
  ASSERT_FALSE(t.hidden.empty());
  // The Delaunay triangulation of the same points: some edge is not locally regular, or a
  // hidden point is a vertex.
  EXPECT_FALSE(check_regular(in.points, in.weights, triangulate(in.points).triangles).valid);
  // A triangle left out, one turned over.
  std::vector<VertexId> fewer(t.triangles.begin() + 3, t.triangles.end());
  EXPECT_FALSE(check_regular(in.points, in.weights, fewer).valid);
  std::vector<VertexId> turned = t.triangles;
  std::swap(turned[0], turned[1]);
  EXPECT_FALSE(check_regular(in.points, in.weights, turned).valid);
  // A hidden point made heavy: its cell is no longer empty.
  std::vector<double> heavier = in.weights;
  heavier[t.hidden[0]] += 0.01;
  EXPECT_FALSE(check_regular(in.points, heavier, t.triangles).valid);
  // An interior edge flipped.
  for (std::size_t k = 0; k < t.neighbors.size(); ++k) {
    const std::int32_t u = t.neighbors[k];
    if (u < 0) continue;
    const std::size_t f = k / 3;
    const int i = static_cast<int>(k % 3);
    const VertexId p = t.triangles[3 * f + i], a = t.triangles[3 * f + (i + 1) % 3],
                   b = t.triangles[3 * f + (i + 2) % 3];
    VertexId d = 0;
    for (int j = 0; j < 3; ++j)
      if (t.triangles[3 * u + j] != a && t.triangles[3 * u + j] != b) d = t.triangles[3 * u + j];
    const Point &pp = in.points[p], &pa = in.points[a], &pb = in.points[b], &pd = in.points[d];
    if (orientation(pp, pa, pd) <= 0 || orientation(pp, pd, pb) <= 0) continue;  // not convex: no flip
    std::vector<VertexId> flipped = t.triangles;
    flipped[3 * f] = p, flipped[3 * f + 1] = a, flipped[3 * f + 2] = d;
    flipped[3 * u] = p, flipped[3 * u + 1] = d, flipped[3 * u + 2] = b;
    const CheckResult r = check_regular(in.points, in.weights, flipped);
    EXPECT_FALSE(r.valid);
    EXPECT_NE(r.message.find("not locally regular"), std::string::npos) << r.message;
    break;
  }
}

TEST(PowerDiagram, VerticesAreEquallyPoweredAndHiddenPointsHaveNoCell) {
  const Weighted in = random_weighted(2000, 23, 0.002);
  const RegularTriangulation t = checked(in);
  const Voronoi vd = power_diagram(in.points, in.weights, t, 2);
  ASSERT_EQ(vd.vertices.size(), t.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    const Point c = vd.vertices[k];
    double power[3];
    for (int i = 0; i < 3; ++i) {
      const Point& p = in.points[t.triangles[3 * k + i]];
      power[i] = (c.x - p.x) * (c.x - p.x) + (c.y - p.y) * (c.y - p.y) - in.weights[t.triangles[3 * k + i]];
    }
    const double scale = 1e-12 * std::max(1.0, std::fabs(power[0]));
    EXPECT_NEAR(power[0], power[1], scale);
    EXPECT_NEAR(power[0], power[2], scale);
  }
  for (const VertexId h : t.hidden) EXPECT_EQ(vd.point_cell[h], -1);
  std::size_t cells = 0;
  for (VertexId v = 0; v < in.points.size(); ++v) cells += vd.point_cell[v] >= 0;
  EXPECT_EQ(cells, in.points.size() - t.hidden.size());
  // Equal weights: the Voronoi diagram's vertices.
  const std::vector<double> zero(in.points.size(), 0.0);
  const RegularTriangulation z = triangulate_regular(in.points, zero);
  const Voronoi pd = power_diagram(in.points, zero, z), v = voronoi(in.points, z);
  ASSERT_EQ(pd.vertices.size(), v.vertices.size());
  for (std::size_t k = 0; k < v.vertices.size(); ++k) EXPECT_EQ(pd.vertices[k], v.vertices[k]);
}

TEST(PowerPredicates, FilterAgreesWithExactAndCentresWithinTheirBound) {
  std::mt19937_64 random(29);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 20000; ++k) {
    // Near-degenerate: d on (or a rounding off) the orthogonal circle of a, b, c.
    const detail::Weighted a{{u(random), u(random)}, 0.1 * u(random)}, b{{u(random), u(random)}, 0.1 * u(random)},
        c{{u(random), u(random)}, 0.1 * u(random)};
    if (detail::orient2d(a.p, b.p, c.p) <= 0) continue;
    const Point o = detail::power_centre_bounded(a, b, c);
    const double pa = (o.x - a.p.x) * (o.x - a.p.x) + (o.y - a.p.y) * (o.y - a.p.y) - a.w;
    const double angle = u(random) * 3.14159265358979;
    const double r = std::sqrt(std::fabs(pa) + 0.25);
    const detail::Weighted d{{o.x + r * std::cos(angle), o.y + r * std::sin(angle)}, 0};
    const detail::Weighted e{d.p, r * r - pa};  // exactly on it, but for rounding
    for (const detail::Weighted* q : {&d, &e}) {
      const int f = detail::power_filter(a, b, c, *q);
      if (f != 0) {
        EXPECT_EQ(f, detail::power_exact(a, b, c, *q));
      }
      // Scaled by a power of two (the weights by its square: the same sign), up to where the
      // products near overflow and down to where they near underflow: the filter's bounds
      // either hold or give no answer.
      for (const int e2 : {-520, -300, 240, 250, 255, 300}) {
        auto scaled = [e2](const detail::Weighted& w) {
          return detail::Weighted{{std::ldexp(w.p.x, e2), std::ldexp(w.p.y, e2)}, std::ldexp(w.w, 2 * e2)};
        };
        const int g = detail::power_filter(scaled(a), scaled(b), scaled(c), scaled(*q));
        if (g != 0) {
          EXPECT_EQ(g, detail::power_exact(scaled(a), scaled(b), scaled(c), scaled(*q))) << e2;
        }
      }
    }
    const Point x = detail::power_centre_exact(a, b, c);
    const double far = std::hypot(o.x - a.p.x, o.y - a.p.y);
    EXPECT_LE(std::fabs(o.x - x.x), 0x1p-44 * far + std::fabs(x.x) * 0x1p-52);
    EXPECT_LE(std::fabs(o.y - x.y), 0x1p-44 * far + std::fabs(x.y) * 0x1p-52);
  }
}

}  // namespace
}  // namespace ridt
