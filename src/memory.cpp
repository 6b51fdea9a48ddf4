#include "memory.hpp"

#include <mutex>
#include <new>
#include <utility>
#include <vector>

#include "ridt/ridt.hpp"

namespace ridt::detail {
namespace {

// The sanitizers' builds keep nothing by default: a block reused by the next run would hide
// a read after its release from them.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr std::size_t kDefaultLimit = 0;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr std::size_t kDefaultLimit = 0;
#else
constexpr std::size_t kDefaultLimit = std::size_t{512} << 20;
#endif
#else
constexpr std::size_t kDefaultLimit = std::size_t{512} << 20;
#endif

struct Cache {
  std::mutex mutex;
  std::vector<std::pair<std::size_t, void*>> blocks;  // (size, block), the last given back last
  std::size_t held = 0;                               // bytes in `blocks`
  std::size_t limit = kDefaultLimit;

  // Frees the oldest blocks until at most `keep` bytes are held. Under the mutex.
  void shrink(std::size_t keep) {
    std::size_t i = 0;
    for (; i < blocks.size() && held > keep; ++i) {
      held -= blocks[i].first;
      std::free(blocks[i].second);
    }
    blocks.erase(blocks.begin(), blocks.begin() + static_cast<std::ptrdiff_t>(i));
  }
  ~Cache() { shrink(0); }
};

Cache& cache() {
  static Cache c;
  return c;
}

}  // namespace

void* take_cached_block(std::size_t bytes) {
  Cache& c = cache();
  const std::lock_guard<std::mutex> guard(c.mutex);
  // The most recently given back first: its pages are the likeliest to be in the TLB and cache.
  for (auto it = c.blocks.rbegin(); it != c.blocks.rend(); ++it) {
    if (it->first != bytes) continue;
    void* p = it->second;
    c.held -= bytes;
    c.blocks.erase(std::next(it).base());
    return p;
  }
  return nullptr;
}

bool cache_has_room(std::size_t bytes) {
  Cache& c = cache();
  const std::lock_guard<std::mutex> guard(c.mutex);
  return c.held + bytes <= c.limit;
}

void release_block(void* p, std::size_t bytes) {
  Cache& c = cache();
  {
    const std::lock_guard<std::mutex> guard(c.mutex);
    if (bytes != 0 && c.held + bytes <= c.limit) {
      try {
        c.blocks.emplace_back(bytes, p);
        c.held += bytes;
        return;
      } catch (const std::bad_alloc&) {
        // no room for the entry: the block is freed instead
      }
    }
  }
  std::free(p);
}

}  // namespace ridt::detail

namespace ridt {

std::size_t set_memory_cache_limit(std::size_t bytes) {
  detail::Cache& c = detail::cache();
  const std::lock_guard<std::mutex> guard(c.mutex);
  const std::size_t previous = c.limit;
  c.limit = bytes;
  c.shrink(bytes);
  return previous;
}

std::size_t cached_memory() {
  detail::Cache& c = detail::cache();
  const std::lock_guard<std::mutex> guard(c.mutex);
  return c.held;
}

}  // namespace ridt
