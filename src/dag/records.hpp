// Triangle records: the live mesh and the history DAG in one.
//
// Conventions, used everywhere:
//   t  a triangle id, v a vertex id, i a local index 0..2;
//   v[i] counter-clockwise; n[i] is the neighbour across the edge opposite v[i], that is the
//   edge v[next3(i)] -> v[prev3(i)]; kNoTriangle where there is none (the outer edges of the
//   bounding triangle).
//   child: at most kMaxOwner while the triangle is a leaf (a current triangle): 0, or the
//   thread that owns it (the optimistic method's per-triangle lock, dag/kernel.hpp). Otherwise the
//   id of its first child, with kThreeChildren set when it has three (a 1->3 split) and two
//   otherwise (a 2->4 split or a flip). Children are allocated consecutively, so one id names
//   them all. Id 0 is the root and ids 1 .. kMaxOwner are never used, which frees the small
//   values to mean "leaf". Publishing a triangle's children thus also ends its ownership.
// See docs/dag.md for drawings.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>
#include <type_traits>

#include "ridt/ridt.hpp"
#include "runtime/memory.hpp"
#include "tds/ids.hpp"

namespace ridt::detail {

inline constexpr std::uint32_t kThreeChildren = 0x80000000u;
inline constexpr std::uint32_t kIdMask = 0x7fffffffu;

/// The most threads that can own triangles; ids 1 .. kMaxOwner are left unused (see above).
inline constexpr std::uint32_t kMaxOwner = kMaxThreads;
inline constexpr TriangleId kFirstChild = kMaxOwner + 1;
/// Whether a child word (Triangle::child) belongs to a leaf.
constexpr bool is_leaf(std::uint32_t child_word) { return child_word <= kMaxOwner; }

struct Triangle {
  VertexId v[3];
  // While a leaf: the neighbours. Once internal they are dead, and the descent keeps what it
  // needs to choose a child here: the split point in n[0] (three children), or the separating
  // edge n[0] -> n[1] (two children, the first on its left).
  TriangleId n[3];
  // Written once, when the triangle stops being a leaf. Stored with release after the children
  // are complete, read with acquire (child_link), so a thread that sees the link sees the
  // children whole. A plain integer under std::atomic_ref keeps the record trivial: records
  // are then made without being zeroed first.
  std::uint32_t child;

  std::atomic_ref<std::uint32_t> child_link() { return std::atomic_ref<std::uint32_t>(child); }
  std::uint32_t load_child() const {
    // atomic_ref needs a non-const object; the load itself does not modify it.
    return std::atomic_ref<std::uint32_t>(const_cast<std::uint32_t&>(child)).load(std::memory_order_acquire);
  }
};
static_assert(std::is_trivial_v<Triangle>);
static_assert(sizeof(Triangle) == 28, "a record should stay small: it is most of the memory");

/// Prefetches both cache lines a record may span: 28-byte records packed back to back straddle
/// a line boundary 6 times in 16, and the child link, read first, is then in the second line.
/// `for_write`: the record is about to be written (a leaf near an insertion), so the line is
/// asked for in exclusive state; an atomic read-modify-write on a line not held that way
/// stalls until the line arrives, and keeps other misses from overlapping it.
/// (GCC folds a second prefetch at a small constant offset into the first, so the address of
/// the last byte goes through an integer.)
template <bool kForWrite = false>
inline void prefetch_record(const Triangle* r) {
  const auto first = reinterpret_cast<std::uintptr_t>(r);
  __builtin_prefetch(r, kForWrite);
  const auto last = (first + sizeof(Triangle) - 1) & ~std::uintptr_t{63};
  if (last != (first & ~std::uintptr_t{63})) __builtin_prefetch(reinterpret_cast<const void*>(last), kForWrite);
}

/// Records in one reserved range of address space (runtime/memory.hpp) that never moves, so an id stays
/// valid while the store grows, and record t is at base + t.
class TriangleStore {
 public:
  // The range is made usable 2^19 records at a time: 28-byte records then fill exactly 7 huge
  // pages of 2 MiB. The fuzz targets build with smaller steps: each of their thousands of tiny
  // runs would otherwise have the sanitizer map and poison a whole step.
#ifdef RIDT_COMMIT_BITS
  static constexpr int kStepBits = RIDT_COMMIT_BITS;
#else
  static constexpr int kStepBits = 19;
#endif
  static constexpr std::uint32_t kStep = 1u << kStepBits;

  /// `expected`: about how many records will be made.
  explicit TriangleStore(std::uint64_t expected = kStep)
      // Room for every id; a small run touches a few 4 KiB pages, where huge pages would
      // zero 2 MiB.
      : range_(std::size_t{kIdMask + 1ull} * sizeof(Triangle), expected >= kStep / 4,
               expected / 4 * 5 * sizeof(Triangle)),
        base_(reinterpret_cast<Triangle*>(range_.data())) {
    // What a run will need, at once and from the calling thread: worker threads then rarely
    // take the growth lock. Pages not touched cost nothing.
    grow(std::min<std::uint64_t>(expected, kIdMask));
  }
  TriangleStore(const TriangleStore&) = delete;
  TriangleStore& operator=(const TriangleStore&) = delete;

  // A thread holds an id only through a child link read with acquire, or under the lock, and
  // either orders the growth that made the record usable before the read.
  Triangle& operator[](TriangleId t) { return base_[t]; }
  const Triangle& operator[](TriangleId t) const { return base_[t]; }

  /// Record t if it is usable, else null: for ids from a racy, possibly stale read.
  const Triangle* find(TriangleId t) const {
    // acquire: pairs with grow's release.
    return t < capacity_.load(std::memory_order_acquire) ? base_ + t : nullptr;
  }

  /// Prefetches record t if it may exist: t may come from a racy, possibly stale read.
  template <bool kForWrite = false>
  void prefetch(TriangleId t) const {
    if (const Triangle* r = find(t)) prefetch_record<kForWrite>(r);
  }

  /// Reserves `count` consecutive ids. One thread at a time (the serial method, or whoever
  /// holds the pessimistic lock).
  TriangleId allocate(std::uint32_t count) {
    const TriangleId first = size_.load(std::memory_order_relaxed);
    const std::uint64_t end = std::uint64_t{first} + count;
    if (end > kIdMask) throw std::length_error("ridt: more than 2^31 triangle records");
    if (end > capacity_.load(std::memory_order_relaxed)) grow(end);
    size_.store(static_cast<std::uint32_t>(end), std::memory_order_relaxed);
    return first;
  }

  /// The same, safe for several threads at once: for blocks that each thread then hands out
  /// on its own (the optimistic method's pools).
  TriangleId allocate_shared(std::uint32_t count) {
    // relaxed: the ids need only be distinct; the records are reached through links published
    // later with release.
    const std::uint64_t first = size_.fetch_add(count, std::memory_order_relaxed);
    const std::uint64_t end = first + count;
    if (end > kIdMask) throw std::length_error("ridt: more than 2^31 triangle records");
    // acquire: pairs with grow's release, so the records below capacity are usable.
    if (end > capacity_.load(std::memory_order_acquire)) grow(end);
    return static_cast<TriangleId>(first);
  }

  std::uint32_t size() const { return size_.load(std::memory_order_relaxed); }

  /// How many records release_pages should give back at once: a huge page's worth on huge
  /// pages (a part of one would split it), else some 64 KiB.
  std::uint32_t release_step() const {
    return static_cast<std::uint32_t>((range_.huge() ? kHugePage : std::size_t{1} << 16) / sizeof(Triangle));
  }

  /// Gives the pages that hold nothing but records [begin, end) back to the kernel, once no
  /// thread reads them again (they would read as zeros). The finish does this behind its copy,
  /// so the output does not come on top of the records. Not the pages that the cache would
  /// keep for the next call (runtime/memory.hpp): they would have to be faulted in again.
  void release_pages(TriangleId begin, TriangleId end) {
    const std::size_t from = std::max(std::size_t{begin} * sizeof(Triangle), range_.keepable());
    range_.discard(from, std::size_t{end} * sizeof(Triangle));
  }

 private:
  void grow(std::uint64_t end) {
    const std::lock_guard<std::mutex> guard(grow_);
    range_.commit(end * sizeof(Triangle), std::size_t{kStep} * sizeof(Triangle));
    // release: pairs with find's racy load (the others are ordered as said above).
    capacity_.store(static_cast<std::uint32_t>(std::min<std::size_t>(range_.committed() / sizeof(Triangle), kIdMask)),
                    std::memory_order_release);
  }

  Reservation range_;
  Triangle* base_;  // range_.data(), read by every thread at every step
  // Written at every allocation: a line of their own, or each write would evict the line
  // above from the other threads' caches.
  alignas(64) std::atomic<std::uint32_t> size_{0};
  std::atomic<std::uint32_t> capacity_{0};  // usable records
  std::mutex grow_;
};

/// Neighbour links and vertices are written, and outside the lock read, through these: a
/// worker that prefetches around its leaf reads them while the lock holder may rewrite them.
/// On x86 these atomics are plain moves and cost nothing. Links are stored with release and
/// loaded with acquire: a triangle is complete before a link to it is stored.
inline void store_link(TriangleId& slot, TriangleId value) {
  std::atomic_ref<TriangleId>(slot).store(value, std::memory_order_release);
}
inline TriangleId load_link(const TriangleId& slot) {
  return std::atomic_ref<TriangleId>(const_cast<TriangleId&>(slot)).load(std::memory_order_acquire);
}
inline void store_word(std::uint32_t& slot, std::uint32_t value) {
  std::atomic_ref<std::uint32_t>(slot).store(value, std::memory_order_relaxed);
}
inline std::uint32_t load_word(const std::uint32_t& slot) {
  return std::atomic_ref<std::uint32_t>(const_cast<std::uint32_t&>(slot)).load(std::memory_order_relaxed);
}

}  // namespace ridt::detail
