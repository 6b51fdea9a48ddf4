// The global operator new of the programs that link this file (the tool, the Python module; never
// the library itself, whose users choose their own allocator): an allocation of 4 MiB or more
// starts on a 2 MiB boundary, is rounded up to whole 2 MiB pages and is marked for transparent
// huge pages (madvise; Debian's default lets a process ask for them so). The kernel then faults
// it in and zeroes it 2 MiB at a time, where it would take one fault each 4 KiB: on a virtual
// machine a fault costs some 10 microseconds, and the 10^7-triangle quality mesh's 1.6 GB took
// 470,000 of them, 5.8 s of its 20.8 s on one thread (docs/constrained.md). Random reads of the
// large arrays miss the TLB less too. Where the system gives no huge pages, nothing changes but
// the rounding.
//
// Under a limit on address space (ulimit -v, as batch systems set it) allocations are malloc's
// as they were: the alignment and the rounding map up to 4 MiB more an array, and what the
// limit leaves is the room the library counts on (for a refinement's growth, for the threads'
// stacks).
//
// The memory comes from aligned_alloc, so every operator delete (the standard library's: free)
// gives it back; the other forms of operator new call this one (new[], nothrow) or keep their own
// (aligned). Sanitizers' builds leave it out (CMakeLists.txt): they count on their own.
#include <sys/mman.h>
#include <sys/resource.h>

#include <cstddef>
#include <cstdlib>
#include <new>

namespace {

constexpr std::size_t kHugePage = std::size_t{1} << 21;
constexpr std::size_t kLarge = 2 * kHugePage;  // smaller ones as malloc gives them

// (Asked at each large allocation, a system call: the limit may be set at any time.)
bool address_space_limited() {
  rlimit r{};
  return getrlimit(RLIMIT_AS, &r) == 0 && r.rlim_cur != RLIM_INFINITY;
}

void* allocate(std::size_t bytes) {
  if (bytes < kLarge || address_space_limited()) return std::malloc(bytes != 0 ? bytes : 1);
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  if (rounded < bytes) return nullptr;  // (a size near the largest: refused, as malloc would)
  void* p = std::aligned_alloc(kHugePage, rounded);
#ifdef MADV_HUGEPAGE
  if (p != nullptr) madvise(p, rounded, MADV_HUGEPAGE);
#endif
  return p;
}

}  // namespace

void* operator new(std::size_t bytes) {
  while (true) {
    if (void* p = allocate(bytes)) return p;
    const std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) throw std::bad_alloc();
    handler();
  }
}
