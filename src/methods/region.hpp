// A partition thread's region (methods/partition.cpp): the vertices whose Hilbert keys lie in one
// interval round the circle of 32-bit keys, tested by vertex id alone.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>

#include "order/order.hpp"

namespace ridt::detail {

/// The vertices v < n whose keys key[v] lie in [lo, lo + len) round the circle of 32-bit keys
/// (len up to 2^32: the whole circle). The vertices come in BRIO rounds (round_end), each
/// sorted by key, so a round's vertices in the region are one interval of its ids, or, where
/// the region wraps past key 0, its first ids and its last: one interval round the circle of
/// 32-bit ids. holds() reads that round's entry, which stays in cache, and not the vertex's
/// key, which would be a miss of its own. Made before any thread reads it.
struct Region {
  // Read only: a region that changes is made again (the ids follow from these).
  std::uint32_t lo = 0;
  std::uint64_t len = 0;
  struct Ids {
    std::uint32_t first = 0, count = 0;  // ids [first, first + count) round the circle of ids
  };
  std::array<Ids, 32> ids{};  // by round_of(); past the last round: none

  Region() = default;
  Region(const std::uint32_t* key, std::uint32_t n, std::uint32_t lo_key, std::uint64_t length)
      : lo(lo_key), len(length) {
    constexpr std::uint64_t kCircle = std::uint64_t{1} << 32;
    for (std::uint32_t b = 0; b < n; b = round_end(b)) {
      const std::uint32_t e = std::min(round_end(b), n);
      // The round's first id whose key is at least k (e for 2^32).
      auto at = [&](std::uint64_t k) {
        if (k >= kCircle) return e;
        return static_cast<std::uint32_t>(std::lower_bound(key + b, key + e, static_cast<std::uint32_t>(k)) - key);
      };
      Ids& r = ids[round_of(b)];
      if (len >= kCircle) {
        r = {b, e - b};
      } else if (lo + len <= kCircle) {
        const std::uint32_t first = at(lo);
        r = {first, at(lo + len) - first};
      } else {  // keys [lo, 2^32) and [0, lo + len - 2^32): ids [first, e) and [b, end)
        const std::uint32_t end = at(lo + len - kCircle), first = at(lo);
        r = end == first ? Ids{b, e - b} : Ids{first, end - first};  // end - first wraps round
      }
    }
  }

  /// Vertex v's entry: b's for every v of the round that starts at b. kFirstRound - 1 | v is
  /// never 0, so the count of leading zeros needs no test.
  static unsigned round_of(std::uint32_t v) {
    static_assert(std::has_single_bit(kFirstRound));
    return 31 - static_cast<unsigned>(std::countl_zero(v | (kFirstRound - 1)));
  }
  /// Whether vertex v < n is in the region (for an id past the points, the answer means nothing).
  bool holds(std::uint32_t v) const {
    const Ids& r = ids[round_of(v)];
    return static_cast<std::uint32_t>(v - r.first) < r.count;
  }
};

}  // namespace ridt::detail
