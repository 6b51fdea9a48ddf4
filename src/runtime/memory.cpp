#include "runtime/memory.hpp"

#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <new>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ridt/ridt.hpp"
#include "runtime/parallel.hpp"

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

// Whether the process has a limit on its address space (ulimit -v): what the cache keeps, the
// reserved ranges' address space above all, would then count against it.
bool address_space_limited() {
  rlimit r{};
  return getrlimit(RLIMIT_AS, &r) == 0 && r.rlim_cur != RLIM_INFINITY;
}

struct Cache {
  // A kept block (from allocate_huge) or range (from a Reservation, when `block` is null),
  // counted as `bytes`: a range's committed bytes.
  struct Entry {
    std::size_t bytes;
    void* block;
    Reservation::Mapping range;
  };
  std::mutex mutex;
  std::vector<Entry> kept;  // the last given back last
  std::size_t held = 0;  // bytes in `kept`
  std::size_t limit = kDefaultLimit;
  std::size_t lent = 0;  // more room while MemoryReuse objects live (their bytes)

  std::size_t room() const { return limit + lent > held && !address_space_limited() ? limit + lent - held : 0; }
  // What of a range with `committed` bytes would be kept now: its start, in whole huge pages.
  std::size_t keepable(std::size_t committed) const { return std::min(committed, room() / kHugePage * kHugePage); }
  // Removes and returns the most recently kept entry that `match` accepts (its pages are the
  // likeliest to be in the TLB and cache), if any. Under the mutex.
  template <class Match>
  bool take(Match&& match, Entry& out) {
    for (auto it = kept.rbegin(); it != kept.rend(); ++it) {
      if (!match(*it)) continue;
      out = *it;
      held -= it->bytes;
      kept.erase(std::next(it).base());
      return true;
    }
    return false;
  }
  // Frees the oldest entries until at most `keep` bytes are held. Under the mutex.
  void shrink(std::size_t keep) {
    std::size_t i = 0;
    for (; i < kept.size() && held > keep; ++i) {
      held -= kept[i].bytes;
      free_entry(kept[i]);
    }
    kept.erase(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(i));
  }
  static void free_entry(const Entry& e) {
    if (e.block != nullptr)
      std::free(e.block);
    else
      munmap(e.range.map, e.range.map_bytes);
  }
  ~Cache() { shrink(0); }
};

Cache& cache() {
  static Cache c;
  return c;
}

std::size_t round_up(std::size_t x, std::size_t to) { return (x + to - 1) / to * to; }

}  // namespace

void* take_cached_block(std::size_t bytes) {
  Cache& c = cache();
  const std::lock_guard<std::mutex> guard(c.mutex);
  Cache::Entry e;
  return c.take([&](const Cache::Entry& k) { return k.block != nullptr && k.bytes == bytes; }, e) ? e.block : nullptr;
}

void release_block(void* p, std::size_t bytes) {
  Cache& c = cache();
  {
    const std::lock_guard<std::mutex> guard(c.mutex);
    if (bytes != 0 && bytes <= c.room()) {
      try {
        c.kept.push_back({bytes, p, {}});
        c.held += bytes;
        return;
      } catch (const std::bad_alloc&) {
        // no room for the entry: the block is freed instead
      }
    }
  }
  std::free(p);
}

Reservation::Reservation(std::size_t bytes, bool huge, std::size_t likely) {
  Cache& c = cache();
  {
    const std::lock_guard<std::mutex> guard(c.mutex);
    Cache::Entry e;
    const std::size_t enough = likely > 0 ? std::min(bytes, likely) : bytes;
    if (c.take([&](const Cache::Entry& k) { return k.block == nullptr && k.range.reserved >= enough; }, e))
      m_ = e.range;
  }
  if (m_.map == nullptr) {
    // Address space only: PROT_NONE is neither usable nor charged to the commit limit, and
    // most systems grant tens of GiB. Where a limit on address space refuses, ask for less:
    // half as much each time, but what is likely needed before anything below it.
    const std::size_t align = huge ? kHugePage : 4096;
    const std::size_t need = round_up(std::max<std::size_t>(likely, 1), align);
    for (bytes = round_up(std::max<std::size_t>(bytes, 1), align);;) {
      void* p = mmap(nullptr, bytes + align, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
      if (p != MAP_FAILED) {
        const auto at = reinterpret_cast<std::uintptr_t>(p);
        m_ = {p, bytes + align, reinterpret_cast<std::byte*>(round_up(at, align)), bytes, 0, false};
        break;
      }
      if (bytes <= kHugePage) throw std::bad_alloc();
      const std::size_t half = round_up(bytes / 2, align);
      bytes = likely > 0 && half < need && need < bytes ? need : half;
    }
  }
#ifdef MADV_HUGEPAGE
  // A kept range may have been made without: what is faulted in from now on is huge.
  if (huge && !m_.huge) m_.huge = madvise(m_.base, m_.reserved, MADV_HUGEPAGE) == 0;
#endif
}

Reservation& Reservation::operator=(Reservation&& other) noexcept {
  if (this != &other) {
    this->~Reservation();
    m_ = std::exchange(other.m_, {});
  }
  return *this;
}

Reservation::~Reservation() {
  if (m_.map == nullptr) return;
  Cache& c = cache();
  std::size_t keep = 0;
  {
    const std::lock_guard<std::mutex> guard(c.mutex);
    keep = c.keepable(m_.committed);
    if (keep > 0 && keep < m_.committed) {
      // What is over the limit goes back, before another thread can take the range: mapped
      // afresh, its pages are freed and it is reserved address space again, unmarked.
      if (mmap(m_.base + keep, m_.committed - keep, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE | MAP_FIXED,
               -1, 0) == MAP_FAILED) {
        keep = 0;
      } else {
        m_.committed = keep;
        m_.huge = false;  // marked again when taken for huge pages
      }
    }
    if (keep > 0) {
      try {
        c.kept.push_back({keep, nullptr, m_});
        c.held += keep;
      } catch (const std::bad_alloc&) {
        keep = 0;  // no room for the entry: the range is unmapped instead
      }
    }
  }
  if (keep == 0) munmap(m_.map, m_.map_bytes);
  m_ = {};
}

void Reservation::commit(std::size_t bytes, std::size_t step) {
  if (bytes <= m_.committed) return;
  if (bytes > m_.reserved) throw std::bad_alloc();
  const std::size_t target = std::min(round_up(bytes, step), m_.reserved);
  if (mprotect(m_.base + m_.committed, target - m_.committed, PROT_READ | PROT_WRITE) != 0) throw std::bad_alloc();
  m_.committed = target;
}

std::size_t Reservation::keepable() const {
  Cache& c = cache();
  const std::lock_guard<std::mutex> guard(c.mutex);
  return c.keepable(m_.committed);
}

void Reservation::discard(std::size_t from, std::size_t to) {
#ifdef MADV_DONTNEED
  const std::size_t kPage = m_.huge ? kHugePage : 4096;
  from = round_up(from, kPage);
  to = std::min(to, m_.committed) / kPage * kPage;
  if (to > from) madvise(m_.base + from, to - from, MADV_DONTNEED);
#else
  (void)from, (void)to;
#endif
}

void make_present(void* data, std::size_t bytes, unsigned threads) {
#ifdef MADV_POPULATE_WRITE
  constexpr std::uintptr_t kPage = 4096;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kPage - 1) & ~(kPage - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kPage - 1);
  if (end <= begin || end - begin < (std::uintptr_t{1} << 20)) return;
#ifdef MADV_HUGEPAGE
  // Marked for transparent huge pages first, where the range holds some: the kernel then
  // faults and zeroes 2 MiB at a time, and random reads later miss the TLB far less.
  const std::uintptr_t huge_begin = (begin + kHugePage - 1) & ~(kHugePage - 1), huge_end = end & ~(kHugePage - 1);
  if (huge_end > huge_begin) madvise(reinterpret_cast<void*>(huge_begin), huge_end - huge_begin, MADV_HUGEPAGE);
#endif
  const std::uintptr_t pages = (end - begin) / kPage;
  threads = static_cast<unsigned>(std::clamp<std::uintptr_t>(pages / 256, 1, std::max(threads, 1u)));
  on_threads(threads, [=](unsigned t) {
    const std::uintptr_t from = begin + pages * t / threads * kPage, to = begin + pages * (t + 1) / threads * kPage;
    madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);
  });
#else
  (void)data, (void)bytes, (void)threads;
#endif
}

}  // namespace ridt::detail

namespace ridt {

MemoryReuse::MemoryReuse(std::size_t bytes) {
  if (detail::kDefaultLimit == 0) return;  // sanitizers: reuse would hide a read after release
  detail::Cache& c = detail::cache();
  const std::lock_guard<std::mutex> guard(c.mutex);
  c.lent += bytes;
  bytes_ = bytes;
}

MemoryReuse::~MemoryReuse() {
  if (bytes_ == 0) return;
  detail::Cache& c = detail::cache();
  const std::lock_guard<std::mutex> guard(c.mutex);
  c.lent -= bytes_;
  c.shrink(c.limit + c.lent);
}

std::size_t set_memory_cache_limit(std::size_t bytes) {
  detail::Cache& c = detail::cache();
  const std::lock_guard<std::mutex> guard(c.mutex);
  const std::size_t previous = c.limit;
  c.limit = bytes;
  c.shrink(bytes + c.lent);
  return previous;
}

namespace {

// A number from the first line of a file ("max" and unreadable files: none).
std::optional<std::size_t> number_in(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "r");
  if (f == nullptr) return std::nullopt;
  unsigned long long v = 0;
  const bool ok = std::fscanf(f, "%llu", &v) == 1;
  std::fclose(f);
  return ok ? std::optional<std::size_t>(static_cast<std::size_t>(v)) : std::nullopt;
}

// The room left under this process's cgroup's memory limit (cgroup v2's memory.max, else v1's
// memory.limit_in_bytes), or none where there is no limit.
std::optional<std::size_t> cgroup_room() {
  std::FILE* f = std::fopen("/proc/self/cgroup", "r");
  if (f == nullptr) return std::nullopt;
  char line[4096];
  std::string v2;
  while (std::fgets(line, sizeof line, f))
    if (std::strncmp(line, "0::", 3) == 0) v2 = std::string(line + 3, std::strcspn(line + 3, "\n"));
  std::fclose(f);
  std::optional<std::size_t> limit, used;
  if (!v2.empty()) {
    limit = number_in("/sys/fs/cgroup" + v2 + "/memory.max");
    used = number_in("/sys/fs/cgroup" + v2 + "/memory.current");
  } else {
    limit = number_in("/sys/fs/cgroup/memory/memory.limit_in_bytes");
    used = number_in("/sys/fs/cgroup/memory/memory.usage_in_bytes");
  }
  if (!limit || *limit >= (std::size_t{1} << 60)) return std::nullopt;  // v1 writes "no limit" as a huge number
  return *limit - std::min(*limit, used.value_or(0));
}

// The room left under this process's limits on its address space and its data (ulimit -v and
// -d: batch systems set them), against what it maps now (/proc/self/statm: the whole size, and
// the data and stack), or none where neither is set.
std::optional<std::size_t> rlimit_room() {
  unsigned long long pages = 0, resident = 0, shared = 0, text = 0, lib = 0, data = 0;
  if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%llu %llu %llu %llu %llu %llu", &pages, &resident, &shared, &text, &lib, &data) != 6)
      pages = data = 0;
    std::fclose(f);
  }
  const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  std::optional<std::size_t> room;
  auto under = [&](int resource, unsigned long long used) {
    rlimit r{};
    if (getrlimit(resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return;
    const std::size_t limit = r.rlim_cur, taken = static_cast<std::size_t>(used) * page;
    room = std::min(room.value_or(limit), limit - std::min(limit, taken));
  };
  under(RLIMIT_AS, pages);
  under(RLIMIT_DATA, data);
  return room;
}

}  // namespace

namespace detail {

std::string gigabytes(std::size_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GB", static_cast<double>(bytes) / 1e9);
  return text;
}

}  // namespace detail

std::size_t available_memory() {
  std::size_t bytes = 0;
  if (std::FILE* f = std::fopen("/proc/meminfo", "r")) {
    char line[256];
    unsigned long long kib = 0;
    while (std::fgets(line, sizeof line, f))
      if (std::sscanf(line, "MemAvailable: %llu kB", &kib) == 1) break;
    std::fclose(f);
    bytes = static_cast<std::size_t>(kib) * 1024;
  }
  // A limit that leaves no room gives 1, not 0: 0 says that nothing could be read.
  for (const std::optional<std::size_t> room : {cgroup_room(), rlimit_room()})
    if (room) bytes = std::max<std::size_t>(bytes == 0 ? *room : std::min(bytes, *room), 1);
  return bytes;
}

std::size_t cached_memory() {
  detail::Cache& c = detail::cache();
  const std::lock_guard<std::mutex> guard(c.mutex);
  return c.held;
}

}  // namespace ridt
