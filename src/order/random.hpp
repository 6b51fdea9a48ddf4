// Seeded, counter-based randomness: the same numbers on every machine and standard library
// (the std:: distributions differ between implementations, so none is used).
#pragma once

#include <cstdint>

namespace ridt::detail {

/// SplitMix64 finalizer (Steele, Lea and Flood, "Fast splittable pseudorandom number
/// generators", 2014): a bijective mix of 64 bits with good avalanche.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// A stream of 64-bit values: value k is mix64(seed_key + k * golden ratio).
class Rng {
 public:
  explicit Rng(std::uint64_t seed, std::uint64_t stream = 0)
      : state_(mix64(seed ^ mix64(stream + 0x632be59bd9b4e019ULL))) {}

  std::uint64_t next() {
    state_ += kStep;
    return mix64(state_);
  }

  /// The k-th value from here (k = 1: what next() gives), without stepping: for threads that
  /// each take their part of one stream.
  std::uint64_t at(std::uint64_t k) const { return mix64(state_ + k * kStep); }

  /// Uniform in [0, bound), without modulo bias (Lemire, "Fast random integer generation in
  /// an interval", 2019).
  std::uint64_t below(std::uint64_t bound) {
    unsigned __int128 m = static_cast<unsigned __int128>(next()) * bound;
    auto low = static_cast<std::uint64_t>(m);
    if (low < bound) {
      const std::uint64_t threshold = (0 - bound) % bound;
      while (low < threshold) {
        m = static_cast<unsigned __int128>(next()) * bound;
        low = static_cast<std::uint64_t>(m);
      }
    }
    return static_cast<std::uint64_t>(m >> 64);
  }

  /// Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1p-53; }

 private:
  static constexpr std::uint64_t kStep = 0x9e3779b97f4a7c15ULL;  // 2^64 / golden ratio: SplitMix64's increment
  std::uint64_t state_;
};

}  // namespace ridt::detail
