// The queue of bad triangles (constrained/buckets.hpp): smaller keys first, last in first out
// within a bucket, and the work of putting a bucket in curve order linear in the items pushed.
#include <gtest/gtest.h>

#include <cstdint>
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
// shapes' keys, then the sizes').
TEST(Buckets, SmallerKeysFirstAndTheLastPushedFirstWithinABucket) {
  detail::Buckets<Item> q;
  q.push({4, 0, 0}), q.push({1, 0, 1}), q.push({-2, 0, 2}), q.push({1.01, 0, 3}), q.push({16, 0, 4});
  q.push({-8, 0, 5}), q.push({0.5, 0, 6});
  std::vector<int> order;
  while (!q.empty()) order.push_back(q.pop().id);
  EXPECT_EQ(order, (std::vector<int>{6, 3, 1, 0, 4, 5, 2}));  // 1 and 1.01 share a quarter octave
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

}  // namespace
}  // namespace ridt::test
