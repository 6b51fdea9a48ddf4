// Insertion orders.
#pragma once

#include <cstdint>
#include <vector>

namespace ridt::detail {

/// A uniformly random permutation of 0 .. n-1 from `seed` (Fisher-Yates), the same on every
/// machine.
std::vector<std::uint32_t> random_permutation(std::uint32_t n, std::uint64_t seed);

}  // namespace ridt::detail
