// Large arrays on transparent huge pages: the DAG is read at random, and with 4 KiB pages
// nearly every access would also miss the TLB.
//
// Blocks on huge pages, and reserved ranges with their pages, are kept for the next
// triangulation in the process when they are given back (up to ridt::set_memory_cache_limit;
// runtime/memory.cpp): a fresh block's pages are each faulted in and zeroed by the kernel on first
// touch, which for 10^6 points is some 250 MB, and on a virtual machine whose host has
// reclaimed the guest's free memory that can cost as much as the insertion itself.
#pragma once

#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "ridt/ridt.hpp"

namespace ridt::detail {

inline constexpr std::size_t kHugePage = std::size_t{1} << 21;

/// A kept block of exactly `bytes`, or null when the cache has none.
void* take_cached_block(std::size_t bytes);
/// Gives block p back: kept for reuse when `bytes` (its size) is non-zero and the cache has
/// room, else freed.
void release_block(void* p, std::size_t bytes);

/// Frees a block made by allocate_huge, through the cache when it may be kept.
struct BlockDeleter {
  std::size_t cacheable_bytes = 0;  // the block's size if it is on huge pages, else 0
  void operator()(void* p) const {
    if (p != nullptr) release_block(p, cacheable_bytes);
  }
};
template <typename T>
using Block = std::unique_ptr<T[], BlockDeleter>;

/// Address space for one array that grows in place: reserved up to a maximum (neither usable
/// nor counted against the system's commit limit), made usable from its start as the array
/// grows (commit), and never moved. An index thus stays valid while the array grows, under
/// threads too, and finding an element is one addition to the base, with no table of pieces
/// to read first. Given back through the cache (runtime/memory.cpp), which keeps the range with its
/// pages for the next one.
class Reservation {
 public:
  Reservation() = default;
  /// At most `bytes` of address space, fewer when the system refuses that much (commit then
  /// fails past what was granted); a kept range when the cache has one. With `huge`, the range is aligned
  /// to a huge page and marked for transparent huge pages. `likely`: what the caller expects to
  /// use; under a limit on address space (ulimit -v) that refuses `bytes`, that much is asked
  /// for before less, rather than the largest halving of `bytes` that fits (which can take the
  /// whole room, or fall short of the need), and a kept range that holds it will do.
  Reservation(std::size_t bytes, bool huge, std::size_t likely = 0);
  Reservation(Reservation&& other) noexcept { *this = std::move(other); }
  Reservation& operator=(Reservation&& other) noexcept;
  ~Reservation();

  std::byte* data() const { return m_.base; }
  /// The bytes made usable so far.
  std::size_t committed() const { return m_.committed; }
  /// Whether the range is marked for huge pages.
  bool huge() const { return m_.huge; }
  /// Makes at least the first `bytes` usable: in steps of `step` bytes (a multiple of the page
  /// size), so that the range's use is counted in those steps. Throws std::bad_alloc past the
  /// reserved bytes or when the system refuses. One thread at a time.
  void commit(std::size_t bytes, std::size_t step);
  /// Bytes from the start that the cache would keep if the range were given back now (all of
  /// the committed ones when it has room).
  std::size_t keepable() const;
  /// Gives the pages that lie wholly within [from, to) back to the system (the huge pages, on
  /// huge pages: a part of one would split it); they read as zeros after. Once nothing reads
  /// them.
  void discard(std::size_t from, std::size_t to);

  /// What the cache keeps of a range (runtime/memory.cpp).
  struct Mapping {
    void* map = nullptr;  // as mmap returned it, for munmap
    std::size_t map_bytes = 0;
    std::byte* base = nullptr;  // the start used, aligned
    std::size_t reserved = 0, committed = 0;
    bool huge = false;
  };

 private:
  Mapping m_;
};

/// Asks for the pages wholly within [data, data + bytes), reserved and not yet touched, to be
/// made present, by up to `threads` threads at once: the kernel's faulting and zeroing of fresh
/// pages then runs on every thread, where the first writes would fault them in one by one on
/// one; on one thread, one call in place of a fault a page is still some 15 % quicker. Only a
/// request: without MADV_POPULATE_WRITE (Linux 5.14) the first writes fault them in as before.
/// The whole huge pages within the range are marked for transparent huge pages. Below 1 MiB it
/// does nothing.
void make_present(void* data, std::size_t bytes, unsigned threads);

/// The most a call may take: `memory_limit` (Options::memory_limit) where it is not 0, else
/// what the process can take now (available_memory(); 0 where that cannot be read).
inline std::size_t memory_room(std::size_t memory_limit) {
  return memory_limit != 0 ? memory_limit : available_memory();
}

/// Bytes as "1.2 GB", for the messages that say what a run needs and what there is.
std::string gigabytes(std::size_t bytes);

/// `a` resized to n (new elements zero), the storage of the new elements made present by up
/// to `threads` threads first.
template <typename T>
void resize_present(std::vector<T>& a, std::size_t n, unsigned threads) {
  if (n <= a.size()) {
    a.resize(n);
    return;
  }
  a.reserve(n);
  make_present(a.data() + a.size(), (n - a.size()) * sizeof(T), threads);
  a.resize(n);
}

/// Uninitialized storage for `count` objects of an implicit-lifetime type (created by the
/// allocation itself, C++20), aligned to a huge page and marked for transparent huge pages (a
/// hint: without them it works the same). A kept block may hold anything.
template <typename T>
Block<T> allocate_huge(std::size_t count, bool huge = true) {
  static_assert((std::is_scalar_v<T> || std::is_aggregate_v<T>)&&std::is_trivially_copyable_v<T> &&
                std::is_trivially_destructible_v<T>);
  huge = huge && count * sizeof(T) >= 4 * kHugePage;  // else 2 MiB of zeroing for little
  const std::size_t align = huge ? kHugePage : alignof(std::max_align_t);
  const std::size_t bytes = std::max<std::size_t>((count * sizeof(T) + align - 1) / align * align, align);
  void* p = huge ? take_cached_block(bytes) : nullptr;
  if (p == nullptr) {
    p = std::aligned_alloc(align, bytes);
    if (p == nullptr) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    if (huge) madvise(p, bytes, MADV_HUGEPAGE);
#endif
  }
  return Block<T>(static_cast<T*>(p), BlockDeleter{huge ? bytes : 0});
}

/// An array of `size` objects in a block of allocate_huge's, its pages made present by up to
/// `threads` threads: a triangulation made again in the process takes the block kept from the
/// one before, where a std::vector's storage of some megabytes goes back to the system when it
/// is freed (the C library trims its heap) and comes back as fresh pages, each faulted in and
/// zeroed (a sixth of a regular triangulation's time in process). The values are unspecified
/// until written: a kept block holds what it held.
template <typename T>
class HugeArray {
 public:
  HugeArray() = default;
  HugeArray(std::size_t size, unsigned threads) : block_(allocate_huge<T>(size)), size_(size) {
    make_present(block_.get(), size * sizeof(T), threads);
  }
  T* data() const { return block_.get(); }
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) const { return block_[i]; }
  operator std::span<T>() const { return {block_.get(), size_}; }  // NOLINT: an array's views
  operator std::span<const T>() const { return {block_.get(), size_}; }  // NOLINT

 private:
  Block<T> block_;
  std::size_t size_ = 0;
};

}  // namespace ridt::detail
