// The queue of bad triangles (constrained/buckets.hpp): smaller keys first, last in first out
// within a large bucket, by key within a small one, and the work of putting a bucket in curve
// order linear in the items pushed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "constrained/buckets.hpp"

namespace ridt::test {
namespace {

struct Item {
  double key;
  std::uint32_t where;
  int id;
};

// Keys from 0 up first, smaller first, then the negative ones, the most negative first (the
// shapes' keys, then the sizes'). Within a bucket of a few items, the shapes' smallest key first
// (the latest of equal ones), the sizes' last pushed first.
TEST(Buckets, SmallerKeysFirstExactlyInASmallBucket) {
  detail::Buckets<Item> q;
  q.push({4, 0, 0}), q.push({1, 0, 1}), q.push({-2, 0, 2}), q.push({1.01, 0, 3}), q.push({16, 0, 4});
  q.push({-8, 0, 5}), q.push({0.5, 0, 6}), q.push({1, 0, 7}), q.push({-2.1, 0, 8}), q.push({-2.05, 0, 9});
  std::vector<int> order;
  while (!q.empty()) order.push_back(q.pop().id);
  // 1 and 1.01 share a quarter octave, as do -2, -2.05 and -2.1
  EXPECT_EQ(order, (std::vector<int>{6, 7, 1, 3, 0, 4, 5, 9, 8, 2}));
}

// A bucket of more than a few items pops the last pushed first (after a sort along the curve, by
// `where`); once down to a few, by key.
TEST(Buckets, ALargeBucketPopsTheLastPushedFirst) {
  detail::Buckets<Item> q;
  for (int k = 0; k < 200; ++k) q.push({1 + (k % 7) * 0.01, 7, k});  // one quarter octave, one stretch
  std::vector<int> order;
  while (!q.empty()) order.push_back(q.pop().id);
  for (int k = 0; k + 64 < 200; ++k) EXPECT_EQ(order[k], 199 - k);
  // the last 64 (ids 0 to 63) by key, the latest of equal keys first
  for (std::size_t k = 137; k < 200; ++k) {
    const int a = order[k - 1], b = order[k];
    EXPECT_TRUE(a % 7 < b % 7 || (a % 7 == b % 7 && a > b)) << k;
  }
}

TEST(Buckets, ABucketLeftAndComeBackToIsNotSortedWholeEachTime) {
  // A large bucket the queue keeps leaving for a smaller key and coming back to with a few
  // more items: each return sorts its new items, not all of them again.
  detail::Buckets<Item> q;
  std::uint32_t where = 12345;
  auto next = [&] { return where = where * 1664525u + 1013904223u; };
  std::size_t pushed = 0;
  for (int k = 0; k < 100000; ++k) q.push({1, next(), k}), ++pushed;
  for (int round = 0; round < 500; ++round) {
    q.push({0.25, next(), -1}), ++pushed;
    EXPECT_EQ(q.pop().id, -1);
    for (int k = 0; k < 100; ++k) q.push({1, next(), k}), ++pushed;
    EXPECT_GE(q.pop().id, 0);  // back in the large bucket, its new items in order
  }
  EXPECT_LE(q.sorted(), 2 * pushed);
  EXPECT_GT(q.sorted(), 500u * 100u);  // every return did sort
}

// Keys of both signs from 10^-300 to 10^300, some in a bucket below every one queued before,
// pushed between pops: every item comes out once, and each pop's key comes no later in the
// order (the shapes' keys from 0 up, then the sizes' from the most negative) than any key left,
// within the quarter octave that shares a bucket.
TEST(Buckets, KeysOfEverySizeAndBothSignsComeOutInOrder) {
  detail::Buckets<Item> q;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> exponent(-300, 300), unit(0, 1);
  std::vector<Item> queued;  // what is in q
  // Whether a may come out before b: it is the same sign's, and no more than a quarter octave
  // later in its order, or a shape's key before a size's.
  auto not_after = [](double a, double b) {
    if ((a >= 0) != (b >= 0)) return a >= 0;
    return a >= 0 ? a <= b * 1.3 : -a * 1.3 >= -b;  // (a bucket's keys are within 1.25 times)
  };
  // One pop, checked against what is left.
  auto take = [&] {
    const Item out = q.pop();
    const auto at = std::find_if(queued.begin(), queued.end(), [&](const Item& i) { return i.id == out.id; });
    ASSERT_NE(at, queued.end()) << out.id;
    queued.erase(at);
    for (const Item& left : queued) EXPECT_TRUE(not_after(out.key, left.key)) << out.key << " before " << left.key;
  };
  int id = 0;
  for (int round = 0; round < 400; ++round) {
    const int pushes = 2 + static_cast<int>(unit(random) * 12);
    for (int k = 0; k < pushes; ++k) {
      // a shape's key that shrinks and a size's that grows from round to round (each most often
      // in a bucket below every one before, as a mesh's shortest edges shrink), the rest anywhere
      const double key = k == 0 ? std::pow(10.0, 250 - round)
          : k == 1              ? -std::pow(10.0, -250 + round)
                                : (unit(random) < 0.5 ? 1 : -1) * std::pow(10.0, exponent(random));
      const Item item{key, static_cast<std::uint32_t>(random()), id++};
      q.push(item), queued.push_back(item);
    }
    for (int k = 0; k < pushes - 1; ++k) take();
  }
  while (!q.empty()) take();
  EXPECT_TRUE(queued.empty());
}

}  // namespace
}  // namespace ridt::test
