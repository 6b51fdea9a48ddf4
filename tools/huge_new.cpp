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
// The memory comes from aligned_alloc, so every operator delete (the standard library's: free)
// gives it back; the other forms of operator new call this one (new[], nothrow) or keep their own
// (aligned). Sanitizers' builds leave it out (CMakeLists.txt): they count on their own.
#include <sys/mman.h>

#include <cstddef>
#include <cstdlib>
#include <new>

namespace {

constexpr std::size_t kHugePage = std::size_t{1} << 21;
constexpr std::size_t kLarge = 2 * kHugePage;  // smaller ones as malloc gives them

void* allocate(std::size_t bytes) {
  if (bytes < kLarge) return std::malloc(bytes != 0 ? bytes : 1);
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
