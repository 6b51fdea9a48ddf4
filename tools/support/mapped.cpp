// Files mapped into memory that shrink while they are read (io_common.hpp's map_file): a page
// of a mapping that lies past the file's new end raises SIGBUS when it is touched. The handler
// here maps a page of zeros there instead and marks the mapping, so that the reader finishes (on
// zeros where the file's text was) and its caller throws IoError, saying the file changed while
// it was read, rather than the process dying of the signal. Only the faults in a mapping made
// here are taken; any other SIGBUS goes to the action there was before (a tool's message).
#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <mutex>

#include "io_common.hpp"

namespace ridt::io::detail {
namespace {

// A mapping watched: [begin, end) of the address space, and whether a fault was taken there.
// Written outside the handler only (taken with a compare-and-swap of `begin`), read by it.
struct Watched {
  std::atomic<std::uintptr_t> begin{0}, end{0};
  std::atomic<bool> shrank{false};
};
constexpr int kWatched = 64;  // a reader maps one file at a time; a run, a few
Watched watched[kWatched];
std::atomic<bool> any_shrank{false};
struct sigaction before {};  // the action this handler took the place of (a tool's, or the default)

void on_sigbus(int, siginfo_t* info, void*) {
  const auto at = reinterpret_cast<std::uintptr_t>(info->si_addr);
  for (Watched& w : watched) {
    const std::uintptr_t b = w.begin.load(std::memory_order_acquire), e = w.end.load(std::memory_order_acquire);
    if (b == 0 || at < b || at >= e) continue;
    const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    void* zeros = ::mmap(reinterpret_cast<void*>(at & ~(page - 1)), page, PROT_READ,
                         MAP_FIXED | MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (zeros == MAP_FAILED) break;
    w.shrank.store(true, std::memory_order_relaxed);
    any_shrank.store(true, std::memory_order_relaxed);
    return;
  }
  // Not a mapping of ours: the action there was before (the tool's message, or the default),
  // when the access is tried again.
  ::sigaction(SIGBUS, &before, nullptr);
}

void install() {
  static std::once_flag once;
  std::call_once(once, [] {
    struct sigaction sa {};
    sa.sa_sigaction = on_sigbus;
    sa.sa_flags = SA_SIGINFO | SA_RESTART;
    ::sigemptyset(&sa.sa_mask);
    ::sigaction(SIGBUS, &sa, &before);
  });
}

}  // namespace

int watch_mapping(const void* data, std::size_t bytes) {
  install();
  const auto b = reinterpret_cast<std::uintptr_t>(data);
  for (int k = 0; k < kWatched; ++k) {
    std::uintptr_t free = 0;
    // Taken with a marker first, so that the handler never sees a begin without its end.
    if (!watched[k].begin.compare_exchange_strong(free, 1)) continue;
    watched[k].shrank.store(false);
    watched[k].end.store(b + bytes, std::memory_order_release);
    watched[k].begin.store(b, std::memory_order_release);
    return k;
  }
  return -1;  // none free: the mapping is read without the watch
}

void unwatch_mapping(int k) {
  if (k < 0) return;
  watched[k].begin.store(1, std::memory_order_release);  // taken, and matching no address
  watched[k].end.store(0, std::memory_order_release);
  watched[k].begin.store(0, std::memory_order_release);
}

bool mapping_shrank(int k) { return k >= 0 && watched[k].shrank.load(); }

bool any_mapping_shrank() { return any_shrank.load(); }

void forget_shrunk_mappings() { any_shrank.store(false); }

}  // namespace ridt::io::detail
