// Insertion orders and the Hilbert curve that schedules location in rounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

#include "methods/ranges.hpp"
#include "order/order.hpp"
#include "ridt/generate.hpp"

namespace ridt::detail {
namespace {

TEST(RandomPermutation, IsAPermutationAndDependsOnTheSeed) {
  const auto a = random_permutation(1000, 1), b = random_permutation(1000, 2);
  auto sorted = a;
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t i = 0; i < 1000; ++i) ASSERT_EQ(sorted[i], i);
  EXPECT_NE(a, b);
  EXPECT_EQ(a, random_permutation(1000, 1));
}

// The curve one level at a time, the textbook way: the table-driven key must agree.
std::uint32_t hilbert_key_by_levels(std::uint32_t x, std::uint32_t y) {
  std::uint32_t key = 0;
  for (std::uint32_t half = 1u << 15; half != 0; half >>= 1) {
    const std::uint32_t right = (x & half) ? 1 : 0, up = (y & half) ? 1 : 0;
    key += half * half * ((3 * right) ^ up);
    if (up == 0) {
      if (right == 1) x = ~x & 0xffffu, y = ~y & 0xffffu;
      std::swap(x, y);
    }
  }
  return key;
}

TEST(HilbertKey, AgreesWithTheCurveLevelByLevel) {
  std::uint64_t z = 12345;
  for (int i = 0; i < 200000; ++i) {
    z = z * 6364136223846793005ULL + 1442695040888963407ULL;
    const auto x = static_cast<std::uint32_t>(z >> 48), y = static_cast<std::uint32_t>((z >> 32) & 0xffff);
    ASSERT_EQ(hilbert_key(x, y), hilbert_key_by_levels(x, y)) << x << " " << y;
  }
}

// On the cells of a 2^k x 2^k subgrid (coordinates multiples of 2^(16-k)) the order-16 curve
// visits the cells of the order-k curve: sorted by key, consecutive cells share a side, and
// the keys are distinct.
TEST(HilbertKey, ConsecutiveCellsAreNeighbours) {
  for (int k : {1, 2, 3, 6}) {
    const std::uint32_t side = 1u << k, step = 1u << (16 - k);
    std::vector<std::pair<std::uint32_t, std::pair<int, int>>> cells;
    for (std::uint32_t x = 0; x < side; ++x)
      for (std::uint32_t y = 0; y < side; ++y) cells.push_back({hilbert_key(x * step, y * step), {int(x), int(y)}});
    std::sort(cells.begin(), cells.end());
    EXPECT_EQ(cells.front().second, std::make_pair(0, 0)) << k;
    for (std::size_t i = 1; i < cells.size(); ++i) {
      ASSERT_NE(cells[i].first, cells[i - 1].first) << k;
      const int d = std::abs(cells[i].second.first - cells[i - 1].second.first) +
          std::abs(cells[i].second.second - cells[i - 1].second.second);
      ASSERT_EQ(d, 1) << "k=" << k << " at " << i;
    }
  }
  EXPECT_EQ(hilbert_key(0, 0), 0u);
  EXPECT_EQ(hilbert_key(0xffff, 0), 0xffffffffu);  // the curve ends at the lower right
}

TEST(HilbertOrder, SortsByKeyAndKeepsEveryIndex) {
  const std::vector<Point> pts = generate(Distribution::Uniform, 5000, 4);
  const std::vector<std::uint32_t> order = hilbert_order(pts.data(), 5000);
  ASSERT_EQ(order.size(), 5000u);
  EXPECT_EQ(std::set<std::uint32_t>(order.begin(), order.end()).size(), 5000u);
  EXPECT_LT(*std::max_element(order.begin(), order.end()), 5000u);
  // Along the curve over the whole box: keys never go down (equal keys are refined further).
  const std::vector<std::uint32_t> key = hilbert_keys(pts.data(), 5000);
  for (std::size_t i = 1; i < order.size(); ++i) ASSERT_LE(key[order[i - 1]], key[order[i]]) << i;
  // Neighbours along the curve are close: the mean step is far below the mean distance of
  // two random points in the unit square (about 0.52).
  double sum = 0;
  for (std::size_t i = 1; i < order.size(); ++i)
    sum += std::hypot(pts[order[i]].x - pts[order[i - 1]].x, pts[order[i]].y - pts[order[i - 1]].y);
  EXPECT_LT(sum / 4999, 0.05);
}

// The counting sort's places are those of a stable sort, on any number of threads: keys of a
// small range repeated many times (as a vertex is the least corner of several triangles), past
// the size where the items are cut into parts.
TEST(PlacesByKey, AreTheStableSortsPlacesOnAnyThreads) {
  const std::size_t n = 300000, keys = 70000;
  std::vector<std::uint32_t> key(n);
  std::uint64_t z = 99;
  for (std::uint32_t& k : key) z = z * 6364136223846793005u + 1442695040888963407u, k = (z >> 33) % keys;
  std::vector<std::uint32_t> order(n);
  for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
  std::vector<std::uint32_t> expected(n);
  for (std::uint32_t k = 0; k < n; ++k) expected[order[k]] = k;
  for (unsigned threads : {1u, 2u, 3u, 8u}) {
    std::vector<std::uint32_t> place = key;
    places_by_key(place.data(), n, keys, threads);
    EXPECT_EQ(place, expected) << threads << " threads";
  }
  std::vector<std::uint32_t> none;
  places_by_key(none.data(), 0, 5, 2);  // nothing to place
}

// The BRIO order: a permutation whose rounds are sorted along the curve, the keys handed back
// in the order's terms, and the same order from any number of threads (the permutation runs
// beside the keys on more than one).
TEST(BrioOrder, RoundsAlongTheCurveAndTheSameForAnyThreads) {
  const std::uint32_t n = 200000;
  const std::vector<Point> pts = generate(Distribution::Uniform, n, 9);
  std::vector<std::uint32_t> keys;
  const std::vector<std::uint32_t> order = brio_order(pts.data(), n, 5, 1, &keys);
  ASSERT_EQ(order.size(), n);
  ASSERT_EQ(keys.size(), n);
  std::vector<std::uint32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t i = 0; i < n; ++i) ASSERT_EQ(sorted[i], i);
  const std::vector<std::uint32_t> key = hilbert_keys(pts.data(), n);
  for (std::uint32_t v = 0; v < n; ++v) ASSERT_EQ(keys[v], key[order[v]]) << v;
  std::uint32_t rounds = 0;
  for (std::uint32_t b = 0; b < n; b = round_end(b), ++rounds) {
    const std::uint32_t e = std::min(round_end(b), n);
    for (std::uint32_t v = b + 1; v < e; ++v) ASSERT_LE(keys[v - 1], keys[v]) << v;
    // A random sample: about as many points of each round from either half of the input.
    const auto low = std::count_if(order.begin() + b, order.begin() + e, [&](std::uint32_t i) { return i < n / 2; });
    EXPECT_NEAR(static_cast<double>(low) / (e - b), 0.5, 0.1) << b;
  }
  EXPECT_GT(rounds, 5u);
  for (unsigned threads : {2u, 3u}) {
    std::vector<std::uint32_t> k;
    EXPECT_EQ(brio_order(pts.data(), n, 5, threads, &k), order) << threads;
    EXPECT_EQ(k, keys) << threads;
  }
  EXPECT_NE(brio_order(pts.data(), n, 6, 2), order);
  // The same in memory the caller hands over, whatever it held (the walking mesh's arrays).
  std::vector<std::uint64_t> words(2 * n, 0x5555555555555555u);
  std::vector<std::uint32_t> numbers(n, 0xaaaaaaaau), k;
  EXPECT_EQ(brio_order(pts.data(), n, 5, 2, &k, {words, numbers}), order);
  EXPECT_EQ(k, keys);
  // Scratch too small is not used.
  std::vector<std::uint64_t> few(n);
  EXPECT_EQ(brio_order(pts.data(), n, 5, 2, nullptr, {few, numbers}), order);
}

// Rounds of a thread's share of the points and more are sorted on all threads (each radix pass
// counted and placed stretch by stretch, the cells refined in stretches cut where the key
// changes): the same order as one thread's, also where many points share a key (a grid).
TEST(BrioOrder, LargeRoundsOnAllThreadsGiveTheSameOrder) {
  const std::uint32_t n = 600000;  // its largest round, 262144 points, is large on 3 threads and more
  for (const Distribution dist : {Distribution::Uniform, Distribution::Grid}) {
    const std::vector<Point> pts = generate(dist, n, 2);
    std::vector<std::uint32_t> keys;
    const std::vector<std::uint32_t> order = brio_order(pts.data(), n, 3, 1, &keys);
    for (unsigned threads : {2u, 3u, 8u}) {
      std::vector<std::uint32_t> k;
      EXPECT_EQ(brio_order(pts.data(), n, 3, threads, &k), order) << threads;
      EXPECT_EQ(k, keys) << threads;
    }
  }
}

// A partition thread's region tested by id (methods/ranges.hpp) holds exactly the vertices whose
// keys lie in its interval of keys: intervals that start or end at a vertex's key or between
// keys, that wrap past key 0, hold nothing or the whole circle, on rounds of every size and on
// points many of which share a key (a grid's coarse cells).
TEST(KeyRange, HoldsTheVerticesWhoseKeysLieInIt) {
  std::uint64_t z = 77;
  auto next = [&z] { return z = z * 6364136223846793005u + 1442695040888963407u, static_cast<std::uint32_t>(z >> 32); };
  for (const Distribution dist : {Distribution::Uniform, Distribution::Grid})
    for (const std::uint32_t n : {1u, 700u, 1024u, 1025u, 3000u, 70001u}) {
      const std::vector<Point> pts = generate(dist, n, 3);
      std::vector<std::uint32_t> keys;
      brio_order(pts.data(), n, 5, 1, &keys);
      constexpr std::uint64_t kCircle = std::uint64_t{1} << 32;
      std::vector<std::pair<std::uint32_t, std::uint64_t>> cases = {
          {0, 0},
          {0, kCircle},
          {123456, kCircle},
          {0, kCircle / 2},
          {0x80000000u, kCircle / 2},
          {0xffffffffu, 1},
          {0xffffffffu, 2},
          {keys[0], 0},
          {keys[0], 1},
          {keys[n - 1], kCircle - 1},
          {keys[n / 2], kCircle - keys[n / 2]},
          {5, kCircle - 3},
          {keys[n / 3] + 1, kCircle - 1},
          {keys[n - 1], kCircle - 1 - (keys[n - 1] - keys[0])}};
      for (int k = 0; k < 60; ++k) {
        const std::uint32_t lo = k % 2 ? keys[next() % n] : next();
        const std::uint64_t len =
            k % 3 == 0 ? static_cast<std::uint32_t>(keys[next() % n] - lo) : next() + (k % 5 == 0 ? kCircle / 2 : 0);
        cases.emplace_back(lo, std::min(len, kCircle));
      }
      for (const auto& [lo, len] : cases) {
        const KeyRange r(keys.data(), n, lo, len);
        for (std::uint32_t v = 0; v < n; ++v)
          ASSERT_EQ(r.holds(v), static_cast<std::uint32_t>(keys[v] - lo) < len)
              << "n " << n << " lo " << lo << " len " << len << " v " << v << " key " << keys[v];
      }
    }
}

// Sizes below a round, a bin, and at the edges: a permutation, the same in scratch memory.
TEST(BrioOrder, SmallSizes) {
  for (const std::uint32_t n : {0u, 1u, 2u, 3u, 1023u, 1024u, 1025u, 40000u}) {
    const std::vector<Point> pts = generate(Distribution::Uniform, n, 4);
    const std::vector<std::uint32_t> order = brio_order(pts.data(), n, 7, 1);
    std::vector<std::uint32_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (std::uint32_t i = 0; i < n; ++i) ASSERT_EQ(sorted[i], i) << n;
    ASSERT_EQ(sorted.size(), n);
    std::vector<std::uint64_t> words(2 * std::size_t{n}, ~std::uint64_t{0});
    std::vector<std::uint32_t> numbers(n, ~0u);
    EXPECT_EQ(brio_order(pts.data(), n, 7, 3, nullptr, {words, numbers}), order) << n;
  }
}

// A box as wide as the doubles go, and a box of no width: still a permutation (and, under
// UBSan, no overflowing conversion to an integer cell).
TEST(HilbertOrder, SurvivesExtremeAndDegenerateBoxes) {
  auto is_permutation = [](std::vector<std::uint32_t> order) {
    std::sort(order.begin(), order.end());
    for (std::uint32_t i = 0; i < order.size(); ++i)
      if (order[i] != i) return false;
    return true;
  };
  const std::vector<Point> huge = {{-1.7e308, -1.7e308}, {1.7e308, 1.7e308}, {0, 0}, {1.7e308, -1.7e308}};
  const std::vector<std::uint32_t> h = hilbert_order(huge.data(), 4);
  EXPECT_EQ(h.size(), 4u);
  EXPECT_TRUE(is_permutation(h));
  EXPECT_EQ(h.front(), 0u);  // the lower left corner comes first on the curve
  const std::vector<Point> same(10, Point{3, 3});
  EXPECT_TRUE(is_permutation(hilbert_order(same.data(), 10)));
  EXPECT_TRUE(hilbert_order(nullptr, 0).empty());
}

double mean_step(const std::vector<Point>& pts, const std::vector<std::uint32_t>& order, std::uint32_t skip) {
  double sum = 0;
  std::size_t steps = 0;
  for (std::size_t i = 1; i < order.size(); ++i) {
    if (order[i] == skip || order[i - 1] == skip) continue;
    sum += std::hypot(pts[order[i]].x - pts[order[i - 1]].x, pts[order[i]].y - pts[order[i - 1]].y);
    ++steps;
  }
  return sum / static_cast<double>(steps);
}

// One point at 1e30 beside 5,000 in the unit square: on the curve over the whole box they all
// share one cell. Sorted again within it, their order is as fine as without the outlier (the
// walk of --locate walk took minutes on such a set when it was not).
TEST(HilbertOrder, AFarOutlierDoesNotCoarsenTheOrder) {
  std::vector<Point> pts = generate(Distribution::Uniform, 5000, 4);
  const double plain = mean_step(pts, hilbert_order(pts.data(), 5000), 5000);
  pts.push_back({1e30, 1e30});
  const double with_outlier = mean_step(pts, hilbert_order(pts.data(), 5001), 5000);
  EXPECT_LT(with_outlier, 1.5 * plain);
}

// Clusters inside clusters, down to the subnormals, and many equal points: the refinement
// ends (some 66 levels deep here), keeps every index, and keeps each level together.
TEST(HilbertOrder, NestedClustersAndEqualPoints) {
  std::vector<Point> pts;
  const std::vector<Point> unit = generate(Distribution::Uniform, 100, 2);
  for (int level = 0; level < 66; ++level)
    for (const Point& p : unit) pts.push_back({std::ldexp(p.x, -16 * level), std::ldexp(p.y, -16 * level)});
  pts.insert(pts.end(), 500, Point{0.5, 0.5});
  const auto n = static_cast<std::uint32_t>(pts.size());
  std::vector<std::uint32_t> order = hilbert_order(pts.data(), n);
  std::vector<int> level_of(n);
  for (std::uint32_t i = 0; i < n; ++i) level_of[i] = i < 6600 ? static_cast<int>(i / 100) : -1;
  int changes = 0;
  for (std::uint32_t i = 1; i < n; ++i) changes += level_of[order[i]] != level_of[order[i - 1]];
  EXPECT_LT(changes, 2 * 67 + 4);
  std::sort(order.begin(), order.end());
  for (std::uint32_t i = 0; i < n; ++i) ASSERT_EQ(order[i], i);
}

}  // namespace
}  // namespace ridt::detail
