// Ties after a sort by key: the runs of equal keys put in an order of their own.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "runtime/parallel.hpp"

namespace ridt::detail {

/// The words (key << 32 | id), sorted by key (sort_by_key), with each run of one key sorted
/// by `less` of the ids, on up to `threads` threads: the parts start where a key does, cut
/// before any thread writes, and a run is sorted by the part it starts in.
template <class Less>
void sort_runs(std::vector<std::uint64_t>& words, unsigned threads, Less less) {
  const std::size_t n = words.size();
  auto within = [&](std::size_t k) { return k > 0 && k < n && words[k] >> 32 == words[k - 1] >> 32; };
  const auto parts = static_cast<unsigned>(std::clamp<std::size_t>(n / 65536, 1, std::max(threads, 1u)));
  std::vector<std::size_t> cut(parts + 1, n);
  for (unsigned p = 0; p < parts; ++p)
    for (cut[p] = std::max(n * p / parts, p > 0 ? cut[p - 1] : 0); within(cut[p]);) ++cut[p];
  parallel_for(parts, parts, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t k = cut[first], end; k < cut[last]; k = end) {
      for (end = k + 1; end < cut[last] && within(end);) ++end;
      if (end - k > 1)
        std::sort(words.begin() + static_cast<std::ptrdiff_t>(k), words.begin() + static_cast<std::ptrdiff_t>(end),
                  [&](std::uint64_t x, std::uint64_t y) {
                    return less(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
                  });
    }
  });
}

}  // namespace ridt::detail
