// ridt against CGAL: Delaunay_triangulation_2 on points in general position, where the
// Delaunay triangulation is unique and the triangle sets must be identical; on cocircular
// fixtures, the triangles every Delaunay triangulation has; and the exact predicates.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "helpers.hpp"
#include "order/random.hpp"
#include "predicates/predicates.hpp"
#include "ridt/check.hpp"
#include "ridt/constrained.hpp"
#include "ridt/generate.hpp"

namespace ridt::test {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexId, K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb>;
using Delaunay = CGAL::Delaunay_triangulation_2<K, Tds>;

std::vector<VertexId> cgal_triangle_list(const std::vector<Point>& pts) {
  std::vector<std::pair<K::Point_2, VertexId>> in;
  for (VertexId i = 0; i < pts.size(); ++i) in.push_back({K::Point_2(pts[i].x, pts[i].y), i});
  Delaunay dt(in.begin(), in.end());
  std::vector<VertexId> tris;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    for (int i = 0; i < 3; ++i) tris.push_back(f->vertex(i)->info());
  return tris;
}

TriangleSet cgal_triangles(const std::vector<Point>& pts) { return canonical(cgal_triangle_list(pts)); }

class AgainstCgal : public ::testing::TestWithParam<std::tuple<Distribution, int>> {};

TEST_P(AgainstCgal, SameTriangles) {
  const auto [d, n] = GetParam();
  const std::vector<Point> pts = generate(d, n, 21);
  const Triangulation t = triangulate_checked(pts);
  EXPECT_EQ(canonical(t.triangles), cgal_triangles(pts));
}

// Grid points are cocircular: several triangulations are Delaunay, so only general-position
// distributions are compared.
INSTANTIATE_TEST_SUITE_P(GeneralPosition, AgainstCgal,
                         ::testing::Combine(::testing::Values(Distribution::Uniform, Distribution::Normal,
                                                              Distribution::Clusters),
                                            ::testing::Values(10, 1000, 100000)),
                         [](const auto& info) {
                           return std::string(to_string(std::get<0>(info.param))) + "_" +
                               std::to_string(std::get<1>(info.param));
                         });

// Each point's index mapped to the smallest index of an equal point: CGAL keeps whichever of
// equal points its spatial sort inserts first, ridt the smallest index.
std::vector<VertexId> representatives(const std::vector<Point>& pts) {
  std::map<std::pair<double, double>, VertexId> first;
  std::vector<VertexId> rep(pts.size());
  for (VertexId i = 0; i < pts.size(); ++i) rep[i] = first.try_emplace({pts[i].x, pts[i].y}, i).first->second;
  return rep;
}

// The triangles of a Delaunay triangulation `tris` (counter-clockwise triples) that are in
// every Delaunay triangulation of the points: those whose circumcircle has no fourth point on
// it. In a Delaunay triangulation a point on a triangle's circle lies, with the triangle, in
// one cell of cocircular points, and the triangle then has a diagonal of that cell as an edge:
// so testing the vertex across each edge, with CGAL's exact predicate, is enough.
TriangleSet unique_triangles(const std::vector<Point>& pts, const std::vector<VertexId>& tris) {
  const std::vector<VertexId> rep = representatives(pts);
  std::map<std::pair<VertexId, VertexId>, VertexId> across;  // edge a -> b: the third vertex
  for (std::size_t i = 0; i + 2 < tris.size(); i += 3)
    for (int k = 0; k < 3; ++k) across[{rep[tris[i + k]], rep[tris[i + (k + 1) % 3]]}] = rep[tris[i + (k + 2) % 3]];
  auto p2 = [&](VertexId v) { return K::Point_2(pts[v].x, pts[v].y); };
  std::vector<VertexId> kept;
  for (std::size_t i = 0; i + 2 < tris.size(); i += 3) {
    const VertexId a = rep[tris[i]], b = rep[tris[i + 1]], c = rep[tris[i + 2]];
    bool unique = true;
    for (const auto& [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
      const auto twin = across.find({v, u});
      if (twin != across.end() &&
          CGAL::side_of_oriented_circle(p2(a), p2(b), p2(c), p2(twin->second)) != CGAL::ON_NEGATIVE_SIDE)
        unique = false;
    }
    if (unique) kept.insert(kept.end(), {a, b, c});
  }
  return canonical(kept);
}

// The robustness fixtures hold cocircular points, where CGAL may pick other diagonals: the
// triangles that every Delaunay triangulation has must be the same in both, and the rest of
// ridt's triangles pass the exact validator.
TEST(AgainstCgal, DelaunatorFixtures) {
  for (const char* name : kDelaunatorFixtures) {
    const std::string path = fixture_path(name);
    const std::vector<Point> pts = read_json_points(path);
    ASSERT_FALSE(pts.empty()) << path;
    const Triangulation t = triangulate_checked(pts);
    const TriangleSet ours = unique_triangles(pts, t.triangles);
    EXPECT_EQ(ours, unique_triangles(pts, cgal_triangle_list(pts))) << name;
    EXPECT_GT(ours.size(), t.size() / 4) << name << ": hardly any triangle is unique";
  }
}

// ridt's predicates against CGAL's exact ones (an independent implementation) on cases built to
// defeat floating point: points on a line or a circle, then moved by a few units in the last
// place, at several scales, and integers near 2^53.
int sign(double v) { return (v > 0) - (v < 0); }
// The determinants in plain double arithmetic, as a naive code would: what makes a case hard.
int naive_orient(const Point& a, const Point& b, const Point& c) {
  return sign((a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x));
}
int naive_incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  return sign((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
              (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady));
}

class PredicatesAgainstCgal : public ::testing::TestWithParam<double> {};

TEST_P(PredicatesAgainstCgal, NearlyCollinearAndCocircular) {
  const double scale = GetParam();
  detail::Rng rng(static_cast<std::uint64_t>(std::ilogb(scale) + 2000));
  auto coord = [&] { return scale * (rng.uniform() - 0.5); };
  // Moves v by up to 3 units in the last place, often not at all.
  auto nudge = [&](double v) {
    for (int k = static_cast<int>(rng.below(7)) - 3; k != 0; k += k > 0 ? -1 : 1)
      v = std::nextafter(v, k > 0 ? HUGE_VAL : -HUGE_VAL);
    return v;
  };
  auto p2 = [](const Point& p) { return K::Point_2(p.x, p.y); };
  constexpr int kCases = 20000;
  int naive_orient_wrong = 0, naive_circle_wrong = 0, signs[3] = {0, 0, 0};
  for (int i = 0; i < kCases; ++i) {
    // On (nearly) the line through a and b.
    const Point a{coord(), coord()}, b{coord(), coord()};
    const double t = rng.uniform() * 3 - 1;
    const Point c{nudge(a.x + t * (b.x - a.x)), nudge(a.y + t * (b.y - a.y))};
    const int o = static_cast<int>(CGAL::orientation(p2(a), p2(b), p2(c)));
    ASSERT_EQ(detail::orient2d(a, b, c), o) << i;
    naive_orient_wrong += naive_orient(a, b, c) != o;

    // On (nearly) a circle: rounded, the points are a few ulps off it, and often exactly on it
    // when the angles are those of a square (±r, 0), (0, ±r).
    const Point m{coord(), coord()};
    const double r = scale * (0.1 + rng.uniform());
    Point q[4];
    for (Point& p : q) {
      const int quadrant = static_cast<int>(rng.below(5));
      const double angle = quadrant < 4 ? quadrant * M_PI / 2 : rng.uniform() * 2 * M_PI;
      p = {nudge(m.x + r * std::cos(angle)), nudge(m.y + r * std::sin(angle))};
    }
    if (CGAL::orientation(p2(q[0]), p2(q[1]), p2(q[2])) == CGAL::COLLINEAR) continue;
    const int s = static_cast<int>(CGAL::side_of_oriented_circle(p2(q[0]), p2(q[1]), p2(q[2]), p2(q[3])));
    ASSERT_EQ(detail::incircle(q[0], q[1], q[2], q[3]), s) << i;
    if (s != 0) ASSERT_EQ(detail::incircle_sos(q[0], q[1], q[2], q[3]), s) << i;
    naive_circle_wrong += naive_incircle(q[0], q[1], q[2], q[3]) != s;
    ++signs[s + 1];
  }
  // The cases are hard: plain floating point gets many of them wrong, and all three answers
  // occur.
  EXPECT_GT(naive_orient_wrong, kCases / 20);
  EXPECT_GT(naive_circle_wrong, kCases / 20);
  EXPECT_GT(signs[0], kCases / 20);
  EXPECT_GT(signs[1], kCases / 200);
  EXPECT_GT(signs[2], kCases / 20);
}

INSTANTIATE_TEST_SUITE_P(Scales, PredicatesAgainstCgal, ::testing::Values(1e-150, 1e-20, 1.0, 3.0e7, 1e20, 1e150),
                         [](const auto& info) {
                           const int e = std::ilogb(info.param);
                           return (e < 0 ? "two_to_minus_" : "two_to_") + std::to_string(std::abs(e));
                         });

// Circumcentres (the Voronoi diagram's vertices) against CGAL's exact construction: within
// 2^-44 of the circumradius and 2 units in the last place, on triangles of every shape (slivers
// among them, where the plain formula is far off) at every scale, far from the origin too.
TEST_P(PredicatesAgainstCgal, CircumcentresWithinTheirBound) {
  using E = CGAL::Exact_predicates_exact_constructions_kernel;
  const double scale = GetParam();
  detail::Rng rng(static_cast<std::uint64_t>(std::ilogb(scale) + 3000));
  auto coord = [&] { return scale * (rng.uniform() - 0.5); };
  auto e2 = [](const Point& p) { return E::Point_2(p.x, p.y); };
  int plain_off = 0;
  for (int i = 0; i < 5000; ++i) {
    const double far = i % 2 == 0 ? 0 : scale * 1e6;  // half the triangles far from the origin
    const Point a{far + coord(), far + coord()}, b{far + coord(), far + coord()};
    const double t = rng.uniform();
    // Every third c nearly on the line a-b: a sliver.
    const double lift = i % 3 == 0 ? 1e-9 * (rng.uniform() - 0.5) : rng.uniform() - 0.5;
    const Point c{a.x + t * (b.x - a.x) - lift * (b.y - a.y), a.y + t * (b.y - a.y) + lift * (b.x - a.x)};
    if (CGAL::orientation(e2(a), e2(b), e2(c)) == CGAL::COLLINEAR) continue;
    const E::Point_2 exact = CGAL::circumcenter(e2(a), e2(b), e2(c));
    const double ex = CGAL::to_double(CGAL::exact(exact.x())), ey = CGAL::to_double(CGAL::exact(exact.y()));
    const double radius = std::max(std::fabs(ex - a.x), std::fabs(ey - a.y));
    auto allowed = [&](double v) {
      return 0x1p-44 * radius + 2 * (std::nextafter(std::fabs(v), HUGE_VAL) - std::fabs(v));
    };
    const Point got = detail::circumcentre_bounded(a, b, c);
    ASSERT_LE(std::fabs(got.x - ex), allowed(ex)) << i;
    ASSERT_LE(std::fabs(got.y - ey), allowed(ey)) << i;
    const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y, d = 2 * (bx * cy - by * cx);
    const double px = a.x + (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / d;
    plain_off += !(std::fabs(px - ex) <= allowed(ex));
  }
  EXPECT_GT(plain_off, 0);  // the cases are hard: the plain formula misses some
}

TEST(PredicatesAgainstCgal, IntegersNear2To53) {
  detail::Rng rng(53);
  auto big = [&] { return 0x1p53 - 1 - static_cast<double>(rng.below(1u << 20)); };
  auto p2 = [](const Point& p) { return K::Point_2(p.x, p.y); };
  int zeros = 0;
  for (int i = 0; i < 20000; ++i) {
    const Point a{big(), big()}, b{big(), big()};
    // c = a + k (b - a) / 4, an exact integer when k (b - a) is a multiple of 4, then moved by
    // -1, 0 or 1.
    const double k = static_cast<double>(rng.below(3)) + 1;
    const Point c{std::round(a.x + k * (b.x - a.x) / 4) + static_cast<double>(rng.below(3)) - 1,
                  std::round(a.y + k * (b.y - a.y) / 4) + static_cast<double>(rng.below(3)) - 1};
    const int o = static_cast<int>(CGAL::orientation(p2(a), p2(b), p2(c)));
    ASSERT_EQ(detail::orient2d(a, b, c), o) << i;
    zeros += o == 0;
    const Point d{big(), big()};
    if (o != 0)
      ASSERT_EQ(detail::incircle(a, b, c, d),
                static_cast<int>(CGAL::side_of_oriented_circle(p2(a), p2(b), p2(c), p2(d))))
          << i;
  }
  EXPECT_GT(zeros, 100);
}

// CGAL's constrained Delaunay triangulation of `pts` with `segments` (pairs of indices), as a
// triangle list.
std::vector<VertexId> cgal_constrained(const std::vector<Point>& pts, const std::vector<VertexId>& segments) {
  using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
  using CTds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using Cdt =
      CGAL::Constrained_Delaunay_triangulation_2<K, CTds, CGAL::No_constraint_intersection_requiring_constructions_tag>;
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handle(pts.size());
  for (VertexId i = 0; i < pts.size(); ++i) {
    handle[i] = cdt.insert(K::Point_2(pts[i].x, pts[i].y));
    handle[i]->info() = i;
  }
  for (std::size_t s = 0; s < segments.size(); s += 2)
    cdt.insert_constraint(handle[segments[s]], handle[segments[s + 1]]);
  std::vector<VertexId> tris;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    for (int i = 0; i < 3; ++i) tris.push_back(f->vertex(i)->info());
  return tris;
}

// Whether the closed segments pq and rs share a point other than a common end (exactly).
bool touch(const Point& p, const Point& q, const Point& r, const Point& s) {
  const int a = detail::orient2d(p, q, r), b = detail::orient2d(p, q, s);
  const int c = detail::orient2d(r, s, p), d = detail::orient2d(r, s, q);
  if (a * b < 0 && c * d < 0) return true;
  auto on = [](const Point& u, const Point& v, const Point& w, int o) {  // w on segment uv
    return o == 0 && std::min(u.x, v.x) <= w.x && w.x <= std::max(u.x, v.x) && std::min(u.y, v.y) <= w.y &&
        w.y <= std::max(u.y, v.y);
  };
  return (!(r == p || r == q) && on(p, q, r, a)) || (!(s == p || s == q) && on(p, q, s, b)) ||
      (!(p == r || p == s) && on(r, s, p, c)) || (!(q == r || q == s) && on(r, s, q, d));
}

// Long segments between random points, none crossing or touching another but at a shared end.
std::vector<VertexId> random_segments(const std::vector<Point>& pts, std::size_t wanted, std::uint64_t seed) {
  detail::Rng rng(seed, 5);
  std::vector<VertexId> segs;
  for (std::size_t tries = 0; segs.size() < 2 * wanted && tries < 50 * wanted; ++tries) {
    const auto a = static_cast<VertexId>(rng.below(pts.size())), b = static_cast<VertexId>(rng.below(pts.size()));
    if (a == b || pts[a] == pts[b]) continue;
    bool free = true;
    for (std::size_t k = 0; free && k < segs.size(); k += 2)
      free = !touch(pts[a], pts[b], pts[segs[k]], pts[segs[k + 1]]) || (a == segs[k] && b == segs[k + 1]);
    if (free) segs.push_back(a), segs.push_back(b);
  }
  return segs;
}

// The validator accepts CGAL's constrained Delaunay triangulations, with long segments that
// break the Delaunay property, in general position and on a grid (segments through grid
// points, cocircular points everywhere), and check() without the segments rejects them.
TEST(CgalConstrained, TheValidatorAcceptsCgalsConstrainedTriangulations) {
  for (const Distribution d : {Distribution::Uniform, Distribution::Clusters, Distribution::Grid}) {
    SCOPED_TRACE(std::string(to_string(d)));
    const std::vector<Point> pts = generate(d, 5000, 5);
    const std::vector<VertexId> segs = random_segments(pts, 150, 9);
    ASSERT_GE(segs.size(), 2 * 100u);
    const std::vector<VertexId> tris = cgal_constrained(pts, segs);
    const CheckResult r = check_constrained(pts, tris, segs);
    EXPECT_TRUE(r.valid) << r.message;
    EXPECT_FALSE(check(pts, tris).valid);
    EXPECT_TRUE(check_constrained(pts, cgal_constrained(pts, {}), {}).valid);
    // Delaunay's triangles are no constrained triangulation of the segments.
    EXPECT_FALSE(check_constrained(pts, triangulate(pts).triangles, segs).valid);
    // ridt's: valid, and in general position (where the constrained triangulation is unique)
    // CGAL's triangles.
    const ConstrainedTriangulation ours = triangulate_constrained(pts, segs);
    EXPECT_TRUE(check_constrained(pts, ours.triangles, segs).valid);
    if (d != Distribution::Grid) EXPECT_EQ(canonical(ours.triangles), canonical(tris));
  }
}

}  // namespace
}  // namespace ridt::test
