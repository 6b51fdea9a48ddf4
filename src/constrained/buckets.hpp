// The queue of bad triangles of refinement (constrained/refine.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace ridt::detail {

// A priority queue of items with a `key` (smaller first), in buckets of a quarter octave of
// it, last in first out within one: the order refinement needs within a few per cent, without a
// heap's misses. Where a bucket holds kExact items or fewer and its keys are from 0 up (the
// shapes'), it pops its smallest key exactly, the latest of equal ones: a small mesh's size hangs
// on the order of its few bad triangles, and the scan costs little beside a point's insertion
// (docs/constrained.md). A bucket is put in order along the Hilbert curve (by `where`, in 1024
// stretches) when the queue comes to it and more than a few of its items came since: then one
// pop's triangle lies near the last one's in the plane, and the slots they free and take, near in
// memory. The whole bucket where its new items are at least as many as those in order, else its
// new items alone: each sort then costs at most twice the items that came since the last, where
// sorting every item each time took time quadratic in a bucket the queue kept leaving and coming
// back to (a bucket of 350,000 sorted 503 times: 3 s for a mesh of 5000 points added).
template <class Item>
class Buckets {
 public:
  bool empty() const { return size_ == 0; }
  void push(const Item& item) {
    const std::size_t b = bucket(item.key);
    cover(b);
    list(b).push_back(item);
    lowest_ = std::min(lowest_, b);
    ++size_;
  }
  Item pop() {
    while (true) {  // the lowest bucket that holds an item, across the gap between the windows
      const Window& w = window(lowest_);
      if (lowest_ < w.base + w.lists.size()) {
        if (!w.lists[lowest_ - w.base].empty()) break;
        ++lowest_;
      } else {
        lowest_ = std::max(kSpan, windows_[1].base);  // (only the negative keys' window is left)
      }
    }
    std::vector<Item>& l = list(lowest_);
    std::size_t& ordered = in_order(lowest_);
    if (lowest_ != current_ && l.size() > ordered + 64) along_curve(lowest_);
    current_ = lowest_;
    std::size_t at = l.size() - 1;
    if (l.size() <= kExact && l[at].key >= 0)
      for (std::size_t k = at; k-- > 0;)
        if (l[k].key < l[at].key) at = k;
    const Item item = l[at];
    l.erase(l.begin() + static_cast<std::ptrdiff_t>(at));
    ordered = std::min(at < ordered ? ordered - 1 : ordered, l.size());  // (what stays keeps its order)
    --size_;
    return item;
  }
  /// The items put in curve order so far, counted once each time a sort moves them.
  std::size_t sorted() const { return sorted_; }
  // The item that would come k pops after the next, in the lowest bucket, or null (a guess in
  // a bucket of kExact items or fewer, which pops by key).
  const Item* ahead(std::size_t k) const {
    if (size_ == 0) return nullptr;
    const Window& w = window(lowest_);
    if (lowest_ < w.base || lowest_ >= w.base + w.lists.size()) return nullptr;
    const std::vector<Item>& l = w.lists[lowest_ - w.base];
    return l.size() > k ? &l[l.size() - 1 - k] : nullptr;
  }

 private:
  static constexpr std::size_t kExact = 64;
  // Keys from 0 up first, then the negative ones (the most negative first), each by quarter
  // octaves: refinement splits the triangles bad for their shape before those too large, whose
  // splits the shapes' own points mostly make (docs/constrained.md).
  static constexpr std::size_t kSpan = 4 * 2200;  // quarter octaves of every double's exponent
  static std::size_t bucket(double key) {
    int e = 0;
    const double f = std::frexp(std::fabs(key), &e);  // |key| = f 2^e, f in [0.5, 1)
    const int quarter = 4 * (e + 1100) + static_cast<int>((f - 0.5) * 8);  // f's quarters of [0.5, 1)
    const auto q = static_cast<std::size_t>(std::clamp(quarter, 0, static_cast<int>(kSpan) - 1));
    return key < 0 ? 2 * kSpan - 1 - q : q;
  }

  // Bucket b's items, or its items since those in order, sorted by the first bits of `where`
  // (a counting sort: stable, linear).
  void along_curve(std::size_t b) {
    std::vector<Item>& l = list(b);
    std::size_t& ordered = in_order(b);
    const std::size_t first = l.size() - ordered >= ordered ? 0 : ordered;
    constexpr int kBits = 10;
    std::vector<std::uint32_t> at((1u << kBits) + 1, 0);
    for (std::size_t k = first; k < l.size(); ++k) ++at[(l[k].where >> (32 - kBits)) + 1];
    std::partial_sum(at.begin(), at.end(), at.begin());
    sorted_ += l.size() - first;
    std::vector<Item> sorted(l.size() - first);
    for (std::size_t k = first; k < l.size(); ++k) sorted[at[l[k].where >> (32 - kBits)]++] = l[k];
    if (first == 0)
      l.swap(sorted);  // the old array freed, none of its spare room kept
    else
      std::copy(sorted.begin(), sorted.end(), l.begin() + static_cast<std::ptrdiff_t>(first));
    ordered = l.size();
  }

  // The buckets that a run's keys reach, for each sign apart (a few dozen octaves of each, far
  // apart in bucket()'s numbering, which spans every double's): window w holds buckets
  // [base, base + lists.size()). A refinement of a tile makes a queue of its own, so a queue
  // costs what its keys span, not 17,600 empty buckets.
  struct Window {
    std::size_t base = 0;
    std::vector<std::vector<Item>> lists;
    std::vector<std::size_t> ordered;  // per bucket: how many of its first items were put in curve order
  };
  const Window& window(std::size_t b) const { return windows_[b >= kSpan ? 1 : 0]; }
  Window& window(std::size_t b) { return windows_[b >= kSpan ? 1 : 0]; }
  std::vector<Item>& list(std::size_t b) { return window(b).lists[b - window(b).base]; }
  std::size_t& in_order(std::size_t b) { return window(b).ordered[b - window(b).base]; }
  // Bucket b's window grown to hold it.
  void cover(std::size_t b) {
    Window& w = window(b);
    if (w.lists.empty()) w.base = b;
    if (b < w.base) {
      w.lists.insert(w.lists.begin(), w.base - b, {});
      w.ordered.insert(w.ordered.begin(), w.base - b, 0);
      w.base = b;
    } else if (b - w.base >= w.lists.size()) {
      w.lists.resize(b - w.base + 1), w.ordered.resize(b - w.base + 1, 0);
    }
  }

  Window windows_[2];  // the keys from 0 up, and the negative ones
  std::size_t lowest_ = std::numeric_limits<std::size_t>::max(), current_ = lowest_, size_ = 0;
  std::size_t sorted_ = 0;
};

}  // namespace ridt::detail
