// Triangle records: the live mesh and the history DAG in one.
//
// Conventions, used everywhere:
//   t  a triangle id, v a vertex id, i a local index 0..2;
//   v[i] counter-clockwise; n[i] is the neighbour across the edge opposite v[i], that is the
//   edge v[next(i)] -> v[prev(i)]; kNone where there is none (the outer edges of the
//   bounding triangle).
//   child: at most kMaxOwner while the triangle is a leaf (a current triangle): 0, or the
//   thread that owns it (the optimistic method's per-triangle lock, kernel.hpp). Otherwise the
//   id of its first child, with kThreeChildren set when it has three (a 1->3 split) and two
//   otherwise (a 2->4 split or a flip). Children are allocated consecutively, so one id names
//   them all. Id 0 is the root and ids 1 .. kMaxOwner are never used, which frees the small
//   values to mean "leaf". Publishing a triangle's children thus also ends its ownership.
// See docs/mesh.md for drawings.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>
#include <type_traits>

#include "memory.hpp"
#include "ridt/ridt.hpp"

namespace ridt::detail {

inline constexpr std::uint32_t kNone = 0xffffffffu;
inline constexpr std::uint32_t kThreeChildren = 0x80000000u;
inline constexpr std::uint32_t kIdMask = 0x7fffffffu;

/// The most threads that can own triangles; ids 1 .. kMaxOwner are left unused (see above).
inline constexpr std::uint32_t kMaxOwner = 1024;
inline constexpr TriangleId kFirstChild = kMaxOwner + 1;
/// Whether a child word (Triangle::child) belongs to a leaf.
constexpr bool is_leaf(std::uint32_t child_word) { return child_word <= kMaxOwner; }

constexpr int next(int i) { return i == 2 ? 0 : i + 1; }
constexpr int prev(int i) { return i == 0 ? 2 : i - 1; }

struct Triangle {
  VertexId v[3];
  // While a leaf: the neighbours. Once internal they are dead, and the descent keeps what it
  // needs to choose a child here: the split point in n[0] (three children), or the separating
  // edge n[0] -> n[1] (two children, the first on its left).
  TriangleId n[3];
  // Written once, when the triangle stops being a leaf. Stored with release after the children
  // are complete, read with acquire (child_link), so a thread that sees the link sees the
  // children whole. A plain integer under std::atomic_ref keeps the record trivial: chunks are
  // then allocated without being zeroed first.
  std::uint32_t child;

  std::atomic_ref<std::uint32_t> child_link() { return std::atomic_ref<std::uint32_t>(child); }
  std::uint32_t load_child() const {
    // atomic_ref needs a non-const object; the load itself does not modify it.
    return std::atomic_ref<std::uint32_t>(const_cast<std::uint32_t&>(child))
        .load(std::memory_order_acquire);
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

/// Records in fixed-size chunks that never move, so an id stays valid while the store grows.
class TriangleStore {
 public:
  // 2^19 records of 28 bytes fill exactly 7 huge pages of 2 MiB (memory.hpp). The fuzz targets
  // build with smaller chunks: each of their thousands of tiny runs would otherwise have the
  // sanitizer map and poison a whole chunk.
#ifdef RIDT_CHUNK_BITS
  static constexpr int kChunkBits = RIDT_CHUNK_BITS;
#else
  static constexpr int kChunkBits = 19;
#endif
  static constexpr std::uint32_t kChunkSize = 1u << kChunkBits;
  static constexpr std::uint32_t kMaxChunks = (kIdMask + 1u) >> kChunkBits;

  /// `expected`: about how many records will be made.
  explicit TriangleStore(std::uint64_t expected = kChunkSize)
      : expected_(expected), chunks_(new std::atomic<Triangle*>[kMaxChunks]()) {
    // The chunks a run will need, at once and from the calling thread: worker threads then
    // rarely take the growth lock, and every method gets its memory from the same heap (the
    // caller's; a thread's own malloc arena would hand out fresh pages where the caller's
    // heap reuses pages a previous run touched). Untouched pages cost nothing.
    grow(std::min<std::uint64_t>(expected, kIdMask));
  }
  ~TriangleStore() {
    const std::uint64_t chunks = capacity_.load(std::memory_order_relaxed) >> kChunkBits;
    for (std::uint32_t c = 0; c < chunks; ++c) free_chunk(c, chunks_[c].load(std::memory_order_relaxed));
  }
  TriangleStore(const TriangleStore&) = delete;
  TriangleStore& operator=(const TriangleStore&) = delete;

  // relaxed: a thread holds an id only through a child link read with acquire, or under the
  // lock, and either orders the chunk's allocation before the read.
  Triangle& operator[](TriangleId t) {
    return chunks_[t >> kChunkBits].load(std::memory_order_relaxed)[t & (kChunkSize - 1)];
  }
  const Triangle& operator[](TriangleId t) const {
    return chunks_[t >> kChunkBits].load(std::memory_order_relaxed)[t & (kChunkSize - 1)];
  }

  /// Record t if its chunk exists, else null: for ids from a racy, possibly stale read.
  const Triangle* find(TriangleId t) const {
    if (t > kIdMask) return nullptr;
    const Triangle* chunk = chunks_[t >> kChunkBits].load(std::memory_order_acquire);
    return chunk == nullptr ? nullptr : chunk + (t & (kChunkSize - 1));
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
    // acquire: pairs with grow's release, so the chunks below capacity are seen.
    if (end > capacity_.load(std::memory_order_acquire)) grow(end);
    return static_cast<TriangleId>(first);
  }

  std::uint32_t size() const { return size_.load(std::memory_order_relaxed); }

  /// Frees chunk c (ids c * kChunkSize on), once no thread reads it again: the finish gives
  /// the records back as it copies them out, so the output does not come on top of them.
  void release_chunk(std::uint32_t c) {
    free_chunk(c, chunks_[c].exchange(nullptr, std::memory_order_relaxed));
  }

  /// Gives the pages that hold nothing but records [begin, end), all of one chunk, back to
  /// the kernel, once no thread reads them again (they would read as zeros). The finish does
  /// this behind its copy when all records fit in one chunk, which it frees only at the end.
  /// Not when the chunk is to be kept for the next call (memory.hpp): its pages would then
  /// have to be faulted in again.
  void release_pages(TriangleId begin, TriangleId end) {
#ifdef MADV_DONTNEED
    const std::uint32_t c = begin >> kChunkBits;
    const std::size_t kept_bytes = deleter(c).cacheable_bytes;
    if (kept_bytes != 0 && cache_has_room(kept_bytes)) return;
    constexpr std::uintptr_t kPage = 4096;
    const auto base = reinterpret_cast<std::uintptr_t>(chunks_[c].load(std::memory_order_relaxed));
    const std::uint64_t first = begin - (c << kChunkBits), last = end - (c << kChunkBits);
    const std::uintptr_t from = (base + first * sizeof(Triangle) + kPage - 1) & ~(kPage - 1);
    const std::uintptr_t to = (base + last * sizeof(Triangle)) & ~(kPage - 1);
    if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_DONTNEED);
#else
    (void)begin, (void)end;
#endif
  }

 private:
  void grow(std::uint64_t end) {
    const std::lock_guard<std::mutex> guard(grow_);
    std::uint64_t capacity = capacity_.load(std::memory_order_relaxed);
    while (capacity < end) {
      // A small run touches a few 4 KiB pages of its first chunk; huge pages would zero 2 MiB.
      auto chunk = allocate_huge<Triangle>(kChunkSize, capacity > 0 || expected_ >= kChunkSize / 4);
      deleter_[capacity > 0] = chunk.get_deleter();
      // release: pairs with find's racy load (the others are ordered as said above).
      chunks_[capacity >> kChunkBits].store(chunk.release(), std::memory_order_release);
      capacity += kChunkSize;
      capacity_.store(capacity, std::memory_order_release);
    }
  }

  // How chunk c goes back: only the first may be off huge pages, and so not kept.
  const BlockDeleter& deleter(std::uint32_t c) const { return deleter_[c > 0]; }
  void free_chunk(std::uint32_t c, Triangle* chunk) { deleter(c)(chunk); }

  std::uint64_t expected_;
  BlockDeleter deleter_[2];  // written under grow_, read once no thread grows the store
  std::unique_ptr<std::atomic<Triangle*>[]> chunks_;  // read by every thread at every step
  // Written at every allocation: a line of their own, or each write would evict the line
  // above from the other threads' caches.
  alignas(64) std::atomic<std::uint32_t> size_{0};
  std::atomic<std::uint64_t> capacity_{0};
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
