// Insertion orders.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "predicates/predicates.hpp"
#include "ridt/ridt.hpp"

namespace ridt::detail {

/// A uniformly random permutation of 0 .. n-1 from `seed` (Fisher-Yates), the same on every
/// machine.
std::vector<std::uint32_t> random_permutation(std::uint32_t n, std::uint64_t seed);

/// Position of (x, y), both in [0, 2^16), along the Hilbert curve of order 16: a 32-bit key.
/// Points close on the curve are close in the plane.
std::uint32_t hilbert_key(std::uint32_t x, std::uint32_t y);

/// The points' extent (extent_of) in one pass on up to `threads` threads; throws InputError
/// naming the first point with a coordinate that is not finite.
Extent checked_extent(std::span<const Point> points, unsigned threads);

/// hilbert_key of each point, over the bounding box of the n points (one scale for both axes,
/// so the curve's cells are square), computed by up to `threads` threads.
std::vector<std::uint32_t> hilbert_keys(const Point* points, std::uint32_t n, unsigned threads = 1);
/// The same into key[0 .. n); `extent`, when given, is the points' (extent_of), whose box
/// spares a pass over them.
void hilbert_keys(const Point* points, std::uint32_t n, unsigned threads, std::uint32_t* key,
                  const Extent* extent = nullptr);

/// Sorts ids[0 .. count) along the Hilbert curve: by key[id], the hilbert_keys of `points`,
/// then every cell of the curve that holds more than a few of them again along a curve over
/// their own bounding box, and so on. No input makes the order coarse: one far outlier, or a
/// tight cluster, would otherwise leave nearly every point in one cell, in random order.
void hilbert_sort(const Point* points, const std::uint32_t* key, std::uint32_t* ids, std::uint32_t count);

/// Insertions come in rounds of doubling size: [0, kFirstRound), [kFirstRound, 2 kFirstRound),
/// [2 kFirstRound, 4 kFirstRound), ... Round sizes below kFirstRound are not worth sorting: the
/// mesh is small and stays in cache.
inline constexpr std::uint32_t kFirstRound = 1024;
/// The end of the round that starts at b (b < 2^31, so no overflow).
constexpr std::uint32_t round_end(std::uint32_t b) { return b < kFirstRound ? kFirstRound : 2 * b; }

/// Sorts each round of ids, [first[r], first[r + 1]), on its own with hilbert_sort (`key`: the
/// hilbert_keys of `points`). The rounds are shared among up to `threads` threads, the largest
/// first, each to the thread with the least work so far: with two threads the last round, half
/// of the points, against all the others.
void sort_rounds(const Point* points, const std::uint32_t* key, std::uint32_t* ids,
                 const std::vector<std::uint32_t>& first, unsigned threads);

/// A biased randomized insertion order (Amenta, Choi and Rote, "Incremental constructions con
/// BRIO", 2003): the points cut into the rounds above, each round a uniformly random sample
/// from `seed` (as from a uniformly random order, though not random_permutation's: one drawn
/// in the cache), each round sorted along the Hilbert curve. A point lands in the last round
/// with probability 1/2, in the one before with 1/4, ..., as a random sample should; within a
/// round, successive insertions are close in the plane and touch nearby memory. Up to
/// `threads` threads; the same order for any number.
/// `keys`, when given, receives each vertex's hilbert_keys value in the order's terms (keys[v]
/// is the key of point order[v]): along each round they never decrease.
/// `scratch`, when given, is memory at hand for its work: at least 2n words and n numbers;
/// `extent`, when given, the points' (as for hilbert_keys).
struct OrderScratch {
  std::span<std::uint64_t> words;
  std::span<std::uint32_t> numbers;
};
std::vector<std::uint32_t> brio_order(const Point* points, std::uint32_t n, std::uint64_t seed, unsigned threads = 1,
                                      std::vector<std::uint32_t>* keys = nullptr, OrderScratch scratch = {},
                                      const Extent* extent = nullptr);

/// Sorts the words (key << 32 | id) a[0 .. count) by key, stably, into b (a is overwritten): a
/// radix sort, least significant digit first, on up to `threads` threads; the same result on
/// any number.
void sort_by_key(std::uint64_t* a, std::uint64_t* b, std::uint32_t count, unsigned threads);

/// The indices 0 .. n-1 of `points` sorted along a Hilbert curve over their bounding box
/// (hilbert_sort).
std::vector<std::uint32_t> hilbert_order(const Point* points, std::uint32_t n);

/// Each key[i] (below `keys`) replaced by i's place when 0 .. n-1 are sorted by key, stably (ties
/// by index): a counting sort on up to `threads` threads, for keys of a small range (some
/// vertex of each triangle, say), in `keys` numbers of memory for each of up to four threads.
void places_by_key(std::uint32_t* key, std::size_t n, std::size_t keys, unsigned threads);

/// The indices 0 .. n-1 of `points` sorted by their cell of hilbert_keys' curve, the points of
/// a cell by x, then y, then index (so that the order of distinct points does not depend on
/// their numbering): coarser than hilbert_order where many points share a cell, and quicker
/// (the keys and a radix sort's passes on up to `threads` threads); enough to lay out in
/// memory points near in the plane.
std::vector<std::uint32_t> hilbert_cells_order(const Point* points, std::uint32_t n, unsigned threads);

}  // namespace ridt::detail
