// The library's two parallel loops: a body on each of a few threads, and a range cut into
// parts, one a thread. The caller's thread always takes part 0.
#pragma once

#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace ridt::detail {

/// The threads to use: `threads`, or the machine's hardware threads for 0.
inline unsigned thread_count(unsigned threads) {
  return threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
}

/// Runs body(w) for w in [0, count), each on its own thread, the caller taking w = 0; returns
/// once all have ended. The body must not throw (parallel_for catches for its parts).
template <class Body>
void on_threads(unsigned count, Body&& body) {
  std::vector<std::jthread> pool;
  for (unsigned w = 1; w < count; ++w) pool.emplace_back(body, w);
  body(0u);
}  // the pool joins on leaving

/// Runs body(first, last) over [0, count) in up to `threads` parts (0: the hardware's threads)
/// of at least `grain` each; the first exception of any part is rethrown once all ended.
template <class Body>
void parallel_for(std::size_t count, unsigned threads, std::size_t grain, Body&& body) {
  const auto parts =
      static_cast<unsigned>(std::clamp<std::size_t>(count / std::max<std::size_t>(grain, 1), 1, thread_count(threads)));
  std::vector<std::exception_ptr> failed(parts);
  on_threads(parts, [&](unsigned p) {
    try {
      body(count * p / parts, count * (p + 1) / parts);
    } catch (...) {
      failed[p] = std::current_exception();
    }
  });
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace ridt::detail
