// The validator in passes (check_in_passes) must give check()'s verdict, whatever the chunks
// the triangles come in, the room it has a pass and the threads. Run under ThreadSanitizer too.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "predicates/predicates.hpp"
#include "ridt/check.hpp"
#include "ridt/generate.hpp"

namespace ridt {
namespace {

// A convex quadrilateral whose only Delaunay diagonal is 1-3 (the square's far corner pushed
// out to (2.5, 2.5), outside the circle through the other three).
const std::vector<Point> kQuad = {{0, 0}, {2, 0}, {2.5, 2.5}, {0, 2}};

// check_in_passes over the triangles in chunks of `chunk` triangles, with room for `budget`
// bytes of sides a pass.
CheckResult in_passes(std::span<const Point> pts, std::span<const VertexId> tris, std::size_t chunk, std::size_t budget,
                      unsigned threads) {
  std::size_t calls = 0;
  const TriangleFeed feed = [&](const TriangleSink& sink) {
    ++calls;
    for (std::size_t k = 0; k < tris.size(); k += 3 * chunk)
      sink(tris.subspan(k, std::min(3 * chunk, tris.size() - k)));
  };
  const CheckResult r = check_in_passes(pts, feed, budget, threads);
  // A pass a vertex at most, where there is room for one file only.
  EXPECT_LE(calls, pts.size() + 1);
  return r;
}

// The verdict in passes is check()'s, whatever the chunks, the room and the threads; where
// valid, the same words. Returns check()'s.
CheckResult same_verdict(std::span<const Point> pts, std::span<const VertexId> tris) {
  const CheckResult whole = check(pts, tris);
  struct Way {
    std::size_t chunk, budget;
    unsigned threads;
  };
  for (const Way w : {Way{1, 5000, 3}, Way{7, 1, 1}, Way{7, 5000, 1}, Way{1 << 20, 1 << 30, 3}}) {
    const CheckResult r = in_passes(pts, tris, w.chunk, w.budget, w.threads);
    EXPECT_EQ(r.valid, whole.valid) << "chunk " << w.chunk << ", room " << w.budget << ": " << r.message << " / "
                                    << whole.message;
    if (whole.valid) {
      EXPECT_EQ(r.message, whole.message);
    }
  }
  return whole;
}

TEST(CheckInPasses, TheVerdictsOfTheSmallCases) {
  EXPECT_TRUE(same_verdict(kQuad, std::vector<VertexId>{0, 1, 3, 1, 2, 3}).valid);
  EXPECT_FALSE(same_verdict(kQuad, std::vector<VertexId>{0, 1, 2, 0, 2, 3}).valid);  // the other diagonal
  EXPECT_FALSE(same_verdict(kQuad, std::vector<VertexId>{0, 3, 1, 1, 3, 2}).valid);  // clockwise
  EXPECT_FALSE(same_verdict(kQuad, std::vector<VertexId>{0, 1, 3}).valid);  // a point left out
  EXPECT_FALSE(same_verdict(kQuad, std::vector<VertexId>{0, 1, 3, 0, 1, 3, 1, 2, 3}).valid);  // an edge twice
  EXPECT_FALSE(same_verdict(kQuad, std::vector<VertexId>{0, 1, 3, 1, 2, 7}).valid);  // out of range
  EXPECT_FALSE(same_verdict(kQuad, std::vector<VertexId>{0, 1, 3, 1, 2}).valid);  // not whole triangles
  EXPECT_FALSE(same_verdict(kQuad, {}).valid);
  const std::vector<Point> five = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 1}};
  EXPECT_TRUE(same_verdict(five, std::vector<VertexId>{0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4}).valid);
  EXPECT_FALSE(same_verdict(five, std::vector<VertexId>{1, 2, 4, 2, 3, 4, 3, 0, 4}).valid);  // a hull edge missing
  EXPECT_FALSE(same_verdict(five, std::vector<VertexId>{0, 1, 2, 0, 2, 3}).valid);  // an inner point left out
  const std::vector<Point> flat = {{0, 0}, {2, 0}, {1, 0}, {1, 1}};
  EXPECT_TRUE(same_verdict(flat, std::vector<VertexId>{0, 2, 3, 2, 1, 3}).valid);
  EXPECT_FALSE(same_verdict(flat, std::vector<VertexId>{0, 2, 3, 2, 1, 3, 0, 2, 1}).valid);  // a flat triangle
  EXPECT_FALSE(same_verdict(flat, std::vector<VertexId>{0, 1, 3}).valid);  // a point on the hull left out
  EXPECT_TRUE(same_verdict(std::vector<Point>{{0, 0}, {1, 1}, {2, 2}}, {}).valid);
  EXPECT_FALSE(same_verdict(std::vector<Point>{{0, 0}, {1, 1}, {2, 2}}, std::vector<VertexId>{0, 1, 2}).valid);
  const std::vector<Point> sq = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_TRUE(same_verdict(sq, std::vector<VertexId>{0, 1, 2, 0, 2, 3}).valid);
  EXPECT_TRUE(same_verdict(sq, std::vector<VertexId>{0, 1, 3, 1, 2, 3}).valid);
  const std::vector<Point> twice = {{0, 0}, {1, 0}, {0, 1}, {1, 0}};
  EXPECT_TRUE(same_verdict(twice, std::vector<VertexId>{0, 1, 2}).valid);
  EXPECT_TRUE(same_verdict(twice, std::vector<VertexId>{0, 3, 2}).valid);
  // A centre given twice, each copy the corner of two of the four triangles; and a point given
  // twice and also left out, on the hull and inside.
  const std::vector<Point> square = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}, {1, 1}};
  EXPECT_TRUE(same_verdict(square, std::vector<VertexId>{0, 1, 5, 1, 2, 5, 2, 3, 5, 3, 0, 5}).valid);
  EXPECT_FALSE(same_verdict(square, std::vector<VertexId>{0, 1, 4, 1, 2, 4, 2, 3, 5, 3, 0, 5}).valid);
  EXPECT_FALSE(same_verdict(square, std::vector<VertexId>{0, 1, 2, 0, 2, 3}).valid);
}

// A feed that gives a pass other triangles than the first (a part rewritten meanwhile) is
// refused, never written past the sides' room.
TEST(CheckInPasses, AFeedThatChangesIsRefused) {
  const std::vector<VertexId> tris = {0, 1, 3, 1, 2, 3};
  std::size_t calls = 0;
  const TriangleFeed growing = [&](const TriangleSink& sink) {
    sink(tris);
    if (calls++ > 0) sink(tris);
  };
  EXPECT_THROW(check_in_passes(kQuad, growing, 1 << 20, 2), InputError);
  calls = 0;
  const TriangleFeed shrinking = [&](const TriangleSink& sink) {
    sink(std::span<const VertexId>(tris).first(calls++ == 0 ? 6 : 3));
  };
  EXPECT_THROW(check_in_passes(kQuad, shrinking, 1 << 20, 2), InputError);
}

// Every distribution, with duplicates and at tiny and huge scales: valid, and each kind of
// damage found.
TEST(CheckInPasses, TheVerdictsOnTriangulationsAndTheirDamage) {
  for (const Distribution d :
       {Distribution::Uniform, Distribution::Normal, Distribution::Grid, Distribution::Clusters}) {
    for (const double scale : {1.0, 0x1p-900, 0x1p+900}) {
      std::vector<Point> pts = generate(d, 600, 3);
      for (std::size_t i = 0; i < 30; ++i) pts.push_back(pts[i * 7]);  // duplicates
      for (Point& p : pts) p = {p.x * scale, p.y * scale};
      const Triangulation t = triangulate(pts);
      ASSERT_TRUE(same_verdict(pts, t.triangles).valid);
      // An interior edge flipped (its quadrilateral convex): valid only where cocircular.
      bool flipped = false;
      for (std::size_t k = 0; k < t.size() && !flipped; ++k)
        for (int i = 0; i < 3 && !flipped; ++i) {
          const std::int32_t u = t.neighbors[3 * k + i];
          if (u < 0) continue;
          const VertexId a = t.triangles[3 * k + i], b = t.triangles[3 * k + (i + 1) % 3],
                         c = t.triangles[3 * k + (i + 2) % 3];
          VertexId e = 0;
          for (int j = 0; j < 3; ++j)
            if (const VertexId w = t.triangles[3 * static_cast<std::size_t>(u) + j]; w != b && w != c) e = w;
          if (detail::orient2d(pts[a], pts[b], pts[e]) <= 0 || detail::orient2d(pts[a], pts[e], pts[c]) <= 0) continue;
          std::vector<VertexId> other = t.triangles;
          const VertexId first[3] = {a, b, e}, second[3] = {a, e, c};
          std::copy_n(first, 3, &other[3 * k]);
          std::copy_n(second, 3, &other[3 * static_cast<std::size_t>(u)]);
          EXPECT_EQ(same_verdict(pts, other).valid, detail::incircle_exact(pts[a], pts[b], pts[c], pts[e]) == 0);
          flipped = true;
        }
      EXPECT_TRUE(flipped);
      std::vector<VertexId> fewer(t.triangles.begin() + 3, t.triangles.end());
      EXPECT_FALSE(same_verdict(pts, fewer).valid);
      std::vector<VertexId> more = t.triangles;
      more.insert(more.end(), t.triangles.end() - 3, t.triangles.end());
      EXPECT_FALSE(same_verdict(pts, more).valid);
    }
  }
}

}  // namespace
}  // namespace ridt
