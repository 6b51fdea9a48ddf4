// The library's two parallel loops: a body on each of a few threads, and a range cut into
// parts, one a thread (the caller's thread always takes part 0); and the indices of a range that
// a test keeps, found on threads.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <new>
#include <system_error>
#include <thread>
#include <type_traits>
#include <vector>

namespace ridt::detail {

/// Tells the core we are spinning (frees resources for the other hardware thread).
inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

/// The threads to use: `threads`, or the machine's hardware threads for 0.
inline unsigned thread_count(unsigned threads) {
  return threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
}

/// A body to run on several threads, by reference: body(w) for the w-th thread.
struct TaskRef {
  void* body;
  void (*call)(void*, unsigned);
  void operator()(unsigned w) const { call(body, w); }
};

/// Runs task(w) for w in [0, count), w = 0 on the calling thread and the rest on threads that
/// the process keeps parked between calls (runtime/parallel.cpp), and returns once all have ended; or
/// runs nothing and returns false when they are busy with another call, or the caller is one
/// of them. A thread started for each part costs some 0.5 ms on a virtual machine, before it
/// runs and on the thread that starts it, against some 0.05 ms to wake a parked one; a
/// triangulation runs some thirty such parts.
bool run_parked(unsigned count, TaskRef task);

/// Runs body(w) for w in [0, count), each on its own thread, the caller taking w = 0; returns
/// once all have ended. The body must not throw (parallel_for catches for its parts).
template <class Body>
void on_threads(unsigned count, Body&& body) {
  if (count > 1) {
    using B = std::remove_reference_t<Body>;
    void* at = const_cast<std::remove_const_t<B>*>(std::addressof(body));
    if (run_parked(count, {at, [](void* b, unsigned w) { (*static_cast<B*>(b))(w); }})) return;
  }
  std::vector<std::jthread> pool;
  for (unsigned w = 1; w < count; ++w) pool.emplace_back(body, w);
  body(0u);
}  // the pool joins on leaving

/// Runs body(first, last) over [0, count) in up to `threads` parts (0: the hardware's threads)
/// of at least `grain` each; the first exception of any part is rethrown once all ended. The
/// parts are independent: where a thread cannot be started (the process's limit on threads or
/// on address space, which its stack must fit in), the caller runs the parts no thread ran.
template <class Body>
void parallel_for(std::size_t count, unsigned threads, std::size_t grain, Body&& body) {
  const auto parts =
      static_cast<unsigned>(std::clamp<std::size_t>(count / std::max<std::size_t>(grain, 1), 1, thread_count(threads)));
  std::vector<std::exception_ptr> failed(parts);
  std::vector<std::uint8_t> ran(parts, 0);  // (each part's own byte)
  auto part = [&](unsigned p) {
    ran[p] = 1;
    try {
      body(count * p / parts, count * (p + 1) / parts);
    } catch (...) {
      failed[p] = std::current_exception();
    }
  };
  try {
    on_threads(parts, part);
  } catch (const std::system_error&) {  // (the threads started have ended: joined on the way)
    for (unsigned p = 0; p < parts; ++p)
      if (!ran[p]) part(p);
  } catch (const std::bad_alloc&) {
    for (unsigned p = 0; p < parts; ++p)
      if (!ran[p]) part(p);
  }
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

/// Sorts [first, last) by `less`: in up to `threads` parts (0: the hardware's threads) sorted
/// side by side, then merged.
template <class It, class Less>
void parallel_sort(It first, It last, unsigned threads, Less less) {
  const auto n = static_cast<std::size_t>(last - first);
  const auto parts = static_cast<unsigned>(std::clamp<std::size_t>(n / 65536, 1, thread_count(threads)));
  auto at = [&](std::size_t p) { return first + static_cast<std::ptrdiff_t>(n * p / parts); };
  parallel_for(parts, parts, 1, [&](std::size_t from, std::size_t to) {
    for (std::size_t p = from; p < to; ++p) std::sort(at(p), at(p + 1), less);
  });
  for (unsigned width = 1; width < parts; width *= 2)
    for (unsigned p = 0; p + width < parts; p += 2 * width)
      std::inplace_merge(at(p), at(p + width), at(std::min(p + 2 * width, parts)), less);
}

/// The indices i in [0, count) (below 2^32) where keep(i), in order: the parts on threads, then
/// joined. For few indices among many.
template <class Keep>
std::vector<std::uint32_t> indices_where(std::size_t count, unsigned threads, Keep&& keep) {
  const auto parts = static_cast<unsigned>(std::clamp<std::size_t>(count / 65536, 1, thread_count(threads)));
  std::vector<std::vector<std::uint32_t>> found(parts);
  parallel_for(parts, parts, 1, [&](std::size_t from, std::size_t to) {
    for (std::size_t p = from; p < to; ++p)
      for (std::size_t i = count * p / parts; i < count * (p + 1) / parts; ++i)
        if (keep(i)) found[p].push_back(static_cast<std::uint32_t>(i));
  });
  std::size_t total = 0;
  for (const auto& f : found) total += f.size();
  std::vector<std::uint32_t> all;
  all.reserve(total);
  for (const auto& f : found) all.insert(all.end(), f.begin(), f.end());
  return all;
}

}  // namespace ridt::detail
