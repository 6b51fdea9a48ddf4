// Runs of keys: the ties after a sort by key put in an order of their own, and a sorted round
// cut among threads.
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

/// A stretch of a round and its keys [from, to).
struct Stretch {
  std::uint32_t a = 0, b = 0;
  std::uint64_t from = 0, to = 0;
};

/// The round [b, e) of ids whose keys (key[id], 32 bits) never decrease, cut into `parts`
/// stretches of about equal size where the key changes (equal keys stay in one), with their
/// keys: the first from 0, the last to 2^32, each the next one's from (an empty stretch at the
/// end from 2^32).
inline std::vector<Stretch> cut_round(const std::uint32_t* key, std::uint32_t b, std::uint32_t e, unsigned parts) {
  std::vector<Stretch> s(parts);
  for (unsigned i = 0; i < parts; ++i) {
    std::uint32_t c =
        i == 0 ? b : std::max(s[i - 1].a, b + static_cast<std::uint32_t>(std::uint64_t{e - b} * i / parts));
    while (c > b && c < e && key[c] == key[c - 1]) ++c;
    s[i].a = c;
    s[i].from = i == 0 ? 0 : c < e ? key[c] : std::uint64_t{1} << 32;
    if (i > 0) s[i - 1].b = c, s[i - 1].to = s[i].from;
  }
  s[parts - 1].b = e, s[parts - 1].to = std::uint64_t{1} << 32;
  return s;
}

}  // namespace ridt::detail
