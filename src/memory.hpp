// Large arrays on transparent huge pages: the DAG is read at random, and with 4 KiB pages
// nearly every access would also miss the TLB.
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

struct FreeDeleter {
  void operator()(void* p) const { std::free(p); }
};

/// Uninitialized storage for `count` objects of an implicit-lifetime type (created by the
/// allocation itself, C++20), aligned to a huge page and marked for transparent huge pages (a
/// hint: without them it works the same).
template <typename T>
std::unique_ptr<T[], FreeDeleter> allocate_huge(std::size_t count, bool huge = true) {
  static_assert(std::is_aggregate_v<T> && std::is_trivially_copyable_v<T> &&
                std::is_trivially_destructible_v<T>);
  huge = huge && count * sizeof(T) >= 4 * kHugePage;  // else 2 MiB of zeroing for little
  const std::size_t align = huge ? kHugePage : alignof(std::max_align_t);
  const std::size_t bytes = std::max<std::size_t>((count * sizeof(T) + align - 1) / align * align, align);
  void* p = std::aligned_alloc(align, bytes);
  if (p == nullptr) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
  if (huge) madvise(p, bytes, MADV_HUGEPAGE);
#endif
  return std::unique_ptr<T[], FreeDeleter>(static_cast<T*>(p));
}

}  // namespace ridt::detail
