// Large arrays on transparent huge pages: the DAG is read at random, and with 4 KiB pages
// nearly every access would also miss the TLB.
//
// Blocks on huge pages are kept for the next triangulation in the process when they are given
// back (up to ridt::set_memory_cache_limit; memory.cpp): a fresh block's pages are each
// faulted in and zeroed by the kernel on first touch, which for 10^6 points is some 250 MB,
// and on a virtual machine whose host has reclaimed the guest's free memory that can cost as
// much as the insertion itself.
#pragma once

#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>

namespace ridt::detail {

inline constexpr std::size_t kHugePage = std::size_t{1} << 21;

/// A kept block of exactly `bytes`, or null when the cache has none.
void* take_cached_block(std::size_t bytes);
/// Gives block p back: kept for reuse when `bytes` (its size) is non-zero and the cache has
/// room, else freed.
void release_block(void* p, std::size_t bytes);

/// Whether a block of `bytes` given back now would be kept.
bool cache_has_room(std::size_t bytes);

/// Frees a block made by allocate_huge, through the cache when it may be kept.
struct BlockDeleter {
  std::size_t cacheable_bytes = 0;  // the block's size if it is on huge pages, else 0
  void operator()(void* p) const {
    if (p != nullptr) release_block(p, cacheable_bytes);
  }
};
template <typename T>
using Block = std::unique_ptr<T[], BlockDeleter>;

/// Uninitialized storage for `count` objects of an implicit-lifetime type (created by the
/// allocation itself, C++20), aligned to a huge page and marked for transparent huge pages (a
/// hint: without them it works the same). A kept block may hold anything.
template <typename T>
Block<T> allocate_huge(std::size_t count, bool huge = true) {
  static_assert(std::is_aggregate_v<T> && std::is_trivially_copyable_v<T> &&
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

}  // namespace ridt::detail
