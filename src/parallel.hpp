// A parallel loop for the steps after the triangulation (Voronoi, interpolation).
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

/// Runs body(first, last) over [0, count) in up to `threads` parts of at least `grain` each,
/// the caller running the first; the first exception of any part is rethrown once all ended.
template <class Body>
void parallel_for(std::size_t count, unsigned threads, std::size_t grain, Body&& body) {
  const auto parts =
      static_cast<unsigned>(std::clamp<std::size_t>(count / std::max<std::size_t>(grain, 1), 1, thread_count(threads)));
  std::vector<std::exception_ptr> failed(parts);
  auto part = [&](unsigned p) {
    try {
      body(count * p / parts, count * (p + 1) / parts);
    } catch (...) {
      failed[p] = std::current_exception();
    }
  };
  {
    std::vector<std::jthread> pool;
    for (unsigned p = 1; p < parts; ++p) pool.emplace_back(part, p);
    part(0);
  }
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace ridt::detail
