#include "order/order.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <numeric>
#include <string>
#include <utility>

#include "order/random.hpp"
#include "predicates/predicates.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"

namespace ridt::detail {

std::vector<std::uint32_t> random_permutation(std::uint32_t n, std::uint64_t seed) {
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  Rng rng(seed, /*stream=*/1);
  for (std::uint32_t i = n; i > 1; --i) std::swap(order[i - 1], order[rng.below(i)]);
  return order;
}

namespace {

// The Hilbert curve as a state machine. Going down one level, the quadrant of (x, y) gives two
// bits of the key, and the curve inside that quadrant is the standard one after a swap of the
// axes and/or a reflection of both: two bits of state, and the two operations commute. The
// table takes four levels at a time: index (state, 4 bits of x, 4 bits of y), entry (8 bits of
// key, next state).
struct HilbertStep {
  std::uint8_t key, state;
};
constexpr std::array<HilbertStep, 1024> hilbert_table() {
  std::array<HilbertStep, 1024> table{};
  for (unsigned state = 0; state < 4; ++state)
    for (unsigned x = 0; x < 16; ++x)
      for (unsigned y = 0; y < 16; ++y) {
        unsigned s = state, key = 0;
        for (int bit = 3; bit >= 0; --bit) {
          unsigned right = (x >> bit) & 1, up = (y >> bit) & 1;
          if (s & 2) right ^= 1, up ^= 1;  // reflected
          if (s & 1) std::swap(right, up);  // axes swapped
          // Quadrants in curve order: 0 (0,0), 1 (0,1), 2 (1,1), 3 (1,0).
          key = key << 2 | ((3 * right) ^ up);
          if (up == 0) s ^= right == 1 ? 3 : 1;  // lower right: reflect and swap; lower left: swap
        }
        table[state << 8 | x << 4 | y] = {static_cast<std::uint8_t>(key), static_cast<std::uint8_t>(s)};
      }
  return table;
}
constexpr std::array<HilbertStep, 1024> kHilbert = hilbert_table();

// The keys of k points at once: each key is a chain of four table reads, each waiting for the
// last one's state; k independent chains, stepped together, keep the processor busy while they
// wait (one at a time took some 13 ns a point).
template <int k>
void hilbert_keys_of(const std::uint32_t* x, const std::uint32_t* y, std::uint32_t* key) {
  std::uint32_t state[k] = {};
  for (int j = 0; j < k; ++j) key[j] = 0;
  for (int shift = 12; shift >= 0; shift -= 4)
    for (int j = 0; j < k; ++j) {
      const HilbertStep step = kHilbert[state[j] << 8 | ((x[j] >> shift) & 15) << 4 | ((y[j] >> shift) & 15)];
      key[j] = key[j] << 8 | step.key;
      state[j] = step.state;
    }
}

}  // namespace

std::uint32_t hilbert_key(std::uint32_t x, std::uint32_t y) {
  std::uint32_t key;
  hilbert_keys_of<1>(&x, &y, &key);
  return key;
}

std::vector<std::uint32_t> hilbert_keys(const Point* points, std::uint32_t n, unsigned threads) {
  std::vector<std::uint32_t> key(n);
  hilbert_keys(points, n, threads, key.data());
  return key;
}

void hilbert_keys(const Point* points, std::uint32_t n, unsigned threads, std::uint32_t* key, const Extent* known) {
  if (n == 0) return;
  const Extent box = known != nullptr ? *known : extent_of({points, n});
  const double x0 = box.x0, x1 = box.x1, y0 = box.y0, y1 = box.y1;
  // Halving first keeps x1 - x0 finite for coordinates near the largest double; the offsets
  // below are halved the same way, so they run from 0 to `extent`.
  const double extent = std::max(x1 / 2 - x0 / 2, y1 / 2 - y0 / 2);
  if (!(extent > 0)) {  // all points equal: every key 0
    std::fill_n(key, n, 0u);
    return;
  }
  // Cells of 1/65535 of the longer side. When the extent is so small (subnormal) that this
  // scale overflows, divide by the extent instead of multiplying by the scale.
  const double scale = 65535.0 / extent;
  const bool divide = std::isinf(scale);
  const auto cell = [&](double v, double lo) {
    const double offset = v / 2 - lo / 2;
    const double c = divide ? offset / extent * 65535.0 : offset * scale;
    return static_cast<std::uint32_t>(std::clamp(c, 0.0, 65535.0));
  };
  auto part = [&](unsigned t, unsigned parts) {
    const auto begin = static_cast<std::uint32_t>(std::uint64_t{n} * t / parts);
    const auto end = static_cast<std::uint32_t>(std::uint64_t{n} * (t + 1) / parts);
    constexpr int kTogether = 4;
    std::uint32_t i = begin;
    for (; i + kTogether <= end; i += kTogether) {
      std::uint32_t x[kTogether], y[kTogether];
      for (int j = 0; j < kTogether; ++j) x[j] = cell(points[i + j].x, x0), y[j] = cell(points[i + j].y, y0);
      hilbert_keys_of<kTogether>(x, y, &key[i]);
    }
    for (; i < end; ++i) key[i] = hilbert_key(cell(points[i].x, x0), cell(points[i].y, y0));
  };
  const unsigned parts = std::max(1u, std::min(threads, n / 65536 + 1));
  on_threads(parts, [&](unsigned t) { part(t, parts); });
}

namespace {

// Sorts the (key << 32 | id) pairs a[0 .. count) by key, stably, into b (as long; a is
// overwritten): a radix sort, least significant digit first, 11 bits a pass, three stable
// counting passes. Each id travels with its key, so every pass reads its input in order.
void sort_by_key(std::uint64_t* a, std::uint64_t* b, std::uint32_t count) {
  constexpr int kBits = 11;
  constexpr std::uint64_t kMask = (1u << kBits) - 1;
  std::vector<std::uint32_t> at(std::size_t{1} << kBits);
  for (int shift = 32; shift < 64; shift += kBits) {
    std::fill(at.begin(), at.end(), 0u);
    for (std::uint32_t i = 0; i < count; ++i) ++at[(a[i] >> shift) & kMask];
    std::uint32_t sum = 0;
    for (std::uint32_t& c : at) sum += std::exchange(c, sum);
    for (std::uint32_t i = 0; i < count; ++i) b[at[(a[i] >> shift) & kMask]++] = a[i];
    std::swap(a, b);  // three passes: the last one wrote the caller's b
  }
}

}  // namespace

// The same on up to `threads` threads, for a large round: in each pass each thread counts the
// digits of its own stretch of the pairs, then writes its pairs after those of the same digit
// from the stretches before its own. The sort stays stable: the same result on any number of
// threads.
void sort_by_key(std::uint64_t* a, std::uint64_t* b, std::uint32_t count, unsigned threads) {
  const unsigned parts = std::max(1u, std::min(threads, count / 65536 + 1));
  if (parts == 1) return sort_by_key(a, b, count);
  constexpr int kBits = 11;
  constexpr std::size_t kBins = std::size_t{1} << kBits;
  std::vector<std::uint32_t> at(parts * kBins);  // at[t * kBins + digit]
  auto stretch = [&](unsigned t, auto&& visit) {
    const auto begin = static_cast<std::uint32_t>(std::uint64_t{count} * t / parts);
    const auto end = static_cast<std::uint32_t>(std::uint64_t{count} * (t + 1) / parts);
    for (std::uint32_t i = begin; i < end; ++i) visit(i);
  };
  for (int shift = 32; shift < 64; shift += kBits) {
    const auto digit = [shift](std::uint64_t pair) { return (pair >> shift) & (kBins - 1); };
    on_threads(parts, [&](unsigned t) {
      std::uint32_t* mine = &at[t * kBins];
      std::fill_n(mine, kBins, 0u);
      stretch(t, [&](std::uint32_t i) { ++mine[digit(a[i])]; });
    });
    std::uint32_t sum = 0;
    for (std::size_t d = 0; d < kBins; ++d)
      for (unsigned t = 0; t < parts; ++t) sum += std::exchange(at[t * kBins + d], sum);
    on_threads(parts, [&](unsigned t) {
      std::uint32_t* mine = &at[t * kBins];
      stretch(t, [&](std::uint32_t i) { b[mine[digit(a[i])]++] = a[i]; });
    });
    std::swap(a, b);  // three passes: the last one wrote the caller's b
  }
}

namespace {

// ids[0 .. count) sorted by key[id], stably, as pairs.
std::vector<std::uint64_t> sorted_pairs(const std::uint32_t* key, const std::uint32_t* ids, std::uint32_t count) {
  std::vector<std::uint64_t> a(count), b(count);
  for (std::uint32_t i = 0; i < count; ++i) a[i] = std::uint64_t{key[ids[i]]} << 32 | ids[i];
  sort_by_key(a.data(), b.data(), count);
  return b;
}

// The pairs (key[i] << 32 | i) of all n points cut into the rounds [first[r], first[r + 1]),
// each round a uniformly random sample from `seed`, as the rounds of a uniformly random
// permutation would be: each pair goes to one of 2^bits bins at random, the bins follow one
// another, and a bin is then shuffled on its own (Rao and Sandelius), where a bin fits in the
// cache; one shuffle of the whole array misses it at nearly every swap once the array outgrows
// it (at 10^7 points that shuffle took 180 ms, and reading the keys through the permutation
// some 200 more). Which round a pair lands in is all that matters, since each round is sorted
// by key after: a bin that lies within one round is left in input order, and one that a
// round's start cuts is shuffled only as far as its last cut (the first m of a forward
// Fisher-Yates are a uniform sample in uniform order). At 10^6 points that shuffles some 3 of
// 32 bins' worth of pairs, not all 32. Pair i's bin depends on (seed, i) alone and a bin's
// shuffle on (seed, bin) alone: the same order on any number of threads.
void shuffled_pairs(const std::uint32_t* key, std::uint32_t n, std::uint64_t seed,
                    const std::vector<std::uint32_t>& first, unsigned threads, std::uint64_t* pairs) {
  constexpr std::uint32_t kBinPoints = 1u << 15;  // 256 KiB of pairs
  int bits = 0;
  while ((std::uint64_t{n} >> bits) > kBinPoints) ++bits;
  const std::size_t bins = std::size_t{1} << bits;
  const Rng draw(seed, /*stream=*/1);
  auto bin_of = [&](std::uint32_t i) {
    return bits == 0 ? std::size_t{0} : static_cast<std::size_t>(draw.at(std::uint64_t{i} + 1) >> (64 - bits));
  };
  // Each part of the points counts its pairs a bin, then puts them in place: bin by bin, and
  // within a bin part by part, so the pairs of a bin come in input order whatever the parts.
  const unsigned parts = std::max(1u, std::min(threads, n / 65536 + 1));
  auto part_of = [&](unsigned t) {
    return std::pair<std::uint32_t, std::uint32_t>(static_cast<std::uint32_t>(std::uint64_t{n} * t / parts),
                                                   static_cast<std::uint32_t>(std::uint64_t{n} * (t + 1) / parts));
  };
  std::vector<std::uint32_t> at(parts * bins, 0u);  // at[t * bins + bin]
  on_threads(parts, [&](unsigned t) {
    const auto [begin, end] = part_of(t);
    for (std::uint32_t i = begin; i < end; ++i) ++at[t * bins + bin_of(i)];
  });
  std::vector<std::uint32_t> bin_start(bins + 1);
  std::uint32_t sum = 0;
  for (std::size_t b = 0; b < bins; ++b) {
    bin_start[b] = sum;
    for (unsigned t = 0; t < parts; ++t) sum += std::exchange(at[t * bins + b], sum);
  }
  bin_start[bins] = n;
  on_threads(parts, [&](unsigned t) {
    const auto [begin, end] = part_of(t);
    for (std::uint32_t i = begin; i < end; ++i) pairs[at[t * bins + bin_of(i)]++] = std::uint64_t{key[i]} << 32 | i;
  });
  // In each bin, Fisher-Yates as far as the last round start inside it (the bins that have
  // one shared among the threads).
  std::vector<std::pair<std::size_t, std::uint32_t>> cut;  // (bin, pairs to draw)
  for (std::size_t b = 0, r = 0; b < bins; ++b) {
    while (r < first.size() && first[r] <= bin_start[b]) ++r;
    std::uint32_t last = 0;
    for (std::size_t k = r; k < first.size() && first[k] < bin_start[b + 1]; ++k) last = first[k];
    if (last > bin_start[b]) cut.emplace_back(b, last - bin_start[b]);
  }
  std::atomic<std::size_t> next{0};
  on_threads(static_cast<unsigned>(std::min<std::size_t>(std::max(threads, 1u), std::max<std::size_t>(cut.size(), 1))),
             [&](unsigned) {
               // relaxed: the counter only hands out each bin once; the joins order the rest.
               for (std::size_t c; (c = next.fetch_add(1, std::memory_order_relaxed)) < cut.size();) {
                 const auto [b, draws] = cut[c];
                 Rng rng(seed, (std::uint64_t{1} << 32) | b);
                 std::uint64_t* bin = pairs + bin_start[b];
                 const std::uint32_t size = bin_start[b + 1] - bin_start[b];
                 for (std::uint32_t i = 0; i < draws && i + 1 < size; ++i)
                   std::swap(bin[i], bin[i + rng.below(size - i)]);
               }
             });
}

// A cell of the curve may hold at most this many points before it is sorted on its own.
constexpr std::uint32_t kCellPoints = 32;

// Writes the ids of the sorted pairs[0 .. count) to ids (and, when `keys` is given, their keys
// to keys), then sorts each run of more than kCellPoints pairs with one key (one cell) along a
// curve over the run's own bounding box, and so on within it. Each level puts a run into cells
// at least 2^15 times smaller than its box, and a run whose points the curve cannot tell apart
// (equal points) stays as it is: the recursion ends after some 140 levels at most, even for
// points that span every exponent of a double.
void refine(const Point* points, const std::uint64_t* pairs, std::uint32_t count, std::uint32_t* ids,
            std::uint32_t* keys = nullptr) {
  for (std::uint32_t i = 0; i < count; ++i) ids[i] = static_cast<std::uint32_t>(pairs[i]);
  if (keys != nullptr)
    for (std::uint32_t i = 0; i < count; ++i) keys[i] = static_cast<std::uint32_t>(pairs[i] >> 32);
  for (std::uint32_t b = 0, e; b < count; b = e) {
    for (e = b + 1; e < count && pairs[e] >> 32 == pairs[b] >> 32;) ++e;
    if (e - b <= kCellPoints) continue;
    std::vector<Point> cell(e - b);
    for (std::uint32_t i = b; i < e; ++i) cell[i - b] = points[ids[i]];
    const std::vector<std::uint32_t> key = hilbert_keys(cell.data(), e - b);
    if (std::all_of(key.begin(), key.end(), [&](std::uint32_t k) { return k == key[0]; })) continue;
    std::vector<std::uint32_t> local(e - b);
    std::iota(local.begin(), local.end(), 0u);
    std::vector<std::uint64_t> sorted = sorted_pairs(key.data(), local.data(), e - b);
    // Local positions back to point ids, keeping the keys.
    const std::vector<std::uint32_t> run(ids + b, ids + e);
    for (std::uint64_t& pair : sorted) pair = (pair >> 32) << 32 | run[static_cast<std::uint32_t>(pair)];
    refine(points, sorted.data(), e - b, ids + b);
  }
}

// refine on up to `threads` threads, for a large round: the pairs cut into stretches where the
// key changes, so that no cell is split, each refined on its own.
void refine(const Point* points, const std::uint64_t* pairs, std::uint32_t count, std::uint32_t* ids,
            std::uint32_t* keys, unsigned threads) {
  const unsigned parts = std::max(1u, std::min(threads, count / 65536 + 1));
  std::vector<std::uint32_t> cut(parts + 1, count);
  for (unsigned t = 0; t < parts; ++t) {
    auto c = static_cast<std::uint32_t>(std::uint64_t{count} * t / parts);
    while (c > 0 && c < count && pairs[c] >> 32 == pairs[c - 1] >> 32) ++c;
    cut[t] = c;
  }
  on_threads(parts, [&](unsigned t) {
    refine(points, pairs + cut[t], cut[t + 1] - cut[t], ids + cut[t], keys != nullptr ? keys + cut[t] : nullptr);
  });
}

// Runs sort(r) for each round r of `first` smaller than `large` points on up to `threads`
// threads: the rounds are shared out largest first, each to the thread with the least work so
// far (with two threads, the last round, half of the points, against all the others).
template <class Sort>
void share_rounds(const std::vector<std::uint32_t>& first, std::uint32_t large, unsigned threads, Sort&& sort) {
  std::vector<std::size_t> rounds;  // largest first
  std::uint64_t points = 0;
  for (std::size_t r = first.size() - 1; r-- > 0;)
    if (first[r + 1] - first[r] < large) rounds.push_back(r), points += first[r + 1] - first[r];
  const auto parts = static_cast<unsigned>(std::clamp<std::uint64_t>(points / 65536 + 1, 1, std::max(threads, 1u)));
  std::vector<std::vector<std::size_t>> share(parts);
  std::vector<std::uint64_t> load(parts, 0);
  for (const std::size_t r : rounds) {
    const auto least = static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());
    share[least].push_back(r);
    load[least] += first[r + 1] - first[r];
  }
  auto sort_share = [&](unsigned t) {
    for (const std::size_t r : share[t]) sort(r);
  };
  on_threads(parts, sort_share);
}

}  // namespace

void hilbert_sort(const Point* points, const std::uint32_t* key, std::uint32_t* ids, std::uint32_t count) {
  const std::vector<std::uint64_t> pairs = sorted_pairs(key, ids, count);
  refine(points, pairs.data(), count, ids);
}

void sort_rounds(const Point* points, const std::uint32_t* key, std::uint32_t* ids,
                 const std::vector<std::uint32_t>& first, unsigned threads) {
  share_rounds(first, UINT32_MAX, threads,
               [&](std::size_t r) { hilbert_sort(points, key, ids + first[r], first[r + 1] - first[r]); });
}

std::vector<std::uint32_t> brio_order(const Point* points, std::uint32_t n, std::uint64_t seed, unsigned threads,
                                      std::vector<std::uint32_t>* keys, OrderScratch scratch, const Extent* extent) {
  std::vector<std::uint32_t> first;
  for (std::uint32_t b = 0; b < n; b = round_end(b)) first.push_back(b);
  first.push_back(n);
  // The (key, index) pairs, each round a random sample, in words [0, n); each round's sorted
  // pairs in words [n, 2n); the Hilbert keys in numbers [0, n).
  std::vector<std::uint64_t> own_words;
  std::vector<std::uint32_t> own_numbers;
  if (scratch.words.size() < 2 * std::size_t{n}) own_words.resize(2 * std::size_t{n}), scratch.words = own_words;
  if (scratch.numbers.size() < n) own_numbers.resize(n), scratch.numbers = own_numbers;
  std::uint64_t* pairs = scratch.words.data();
  std::uint64_t* sorted = pairs + n;
  hilbert_keys(points, n, threads, scratch.numbers.data(), extent);
  shuffled_pairs(scratch.numbers.data(), n, seed, first, threads, pairs);
  std::vector<std::uint32_t> order;
  resize_present(order, n, threads);
  if (keys != nullptr) resize_present(*keys, n, threads);
  std::uint32_t* key_out = keys != nullptr ? keys->data() : nullptr;
  // The rounds of at least a thread's share of the points (the last few, half of them and
  // more), one after another, each on all threads; the others shared out whole. With many
  // threads, one thread sorting the last round alone was most of the order's time.
  const std::uint32_t large = threads > 1 ? std::max<std::uint32_t>(n / threads, 1u << 18) : UINT32_MAX;
  auto sort_round = [&](std::size_t r, unsigned on) {
    const std::uint32_t b = first[r], count = first[r + 1] - b;
    detail::sort_by_key(pairs + b, sorted + b, count, on);
    refine(points, sorted + b, count, order.data() + b, key_out != nullptr ? key_out + b : nullptr, on);
  };
  for (std::size_t r = 0; r + 1 < first.size(); ++r)
    if (first[r + 1] - first[r] >= large) sort_round(r, threads);
  share_rounds(first, large, threads, [&](std::size_t r) { sort_round(r, 1); });
  return order;
}

std::vector<std::uint32_t> hilbert_order(const Point* points, std::uint32_t n) {
  const std::vector<std::uint32_t> key = hilbert_keys(points, n);
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  hilbert_sort(points, key.data(), order.data(), n);
  return order;
}

namespace {

// Each index i as key[i] << 32 | i, sorted (radix passes on up to `threads` threads).
Block<std::uint64_t> sorted_words(const std::uint32_t* key, std::uint32_t n, unsigned threads) {
  Block<std::uint64_t> a = allocate_huge<std::uint64_t>(n), b = allocate_huge<std::uint64_t>(n);
  parallel_for(n, threads, 1 << 16, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) a[i] = std::uint64_t{key[i]} << 32 | i;
  });
  detail::sort_by_key(a.get(), b.get(), n, threads);
  return b;
}

}  // namespace

void places_by_key(std::uint32_t* key, std::size_t n, std::size_t keys, unsigned threads) {
  // Each part of the items (at most four: each holds a count a key) counts its own a key, then
  // places its items after those of the same key in the parts before it.
  const auto parts = static_cast<unsigned>(std::clamp<std::size_t>(n >> 16, 1, std::clamp(threads, 1u, 4u)));
  auto each = [&](unsigned p, auto&& visit) {
    for (std::size_t i = n * p / parts; i < n * (p + 1) / parts; ++i) visit(i);
  };
  const Block<std::uint32_t> at = allocate_huge<std::uint32_t>(parts * keys);  // at[p * keys + key]
  parallel_for(parts * keys, threads, 1 << 16,
               [&](std::size_t first, std::size_t last) { std::fill(&at[first], &at[0] + last, 0u); });
  on_threads(parts, [&](unsigned p) { each(p, [&](std::size_t i) { ++at[p * keys + key[i]]; }); });
  std::uint32_t sum = 0;
  for (std::size_t k = 0; k < keys; ++k)
    for (unsigned p = 0; p < parts; ++p) sum += std::exchange(at[p * keys + k], sum);
  on_threads(parts, [&](unsigned p) { each(p, [&](std::size_t i) { key[i] = at[p * keys + key[i]]++; }); });
}

Extent checked_extent(std::span<const Point> points, unsigned threads) {
  constexpr std::size_t kGrain = std::size_t{1} << 16;
  const auto parts = static_cast<unsigned>(std::clamp<std::size_t>(points.size() / kGrain, 1, threads));
  std::vector<Extent> part(parts);
  on_threads(parts, [&](unsigned t) {
    part[t] = extent_of(
        points.subspan(points.size() * t / parts, points.size() * (t + 1) / parts - points.size() * t / parts));
  });
  Extent e;
  for (const Extent& x : part) e.add(x);
  if (!e.finite)
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Point& p = points[i];
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw InputError("point " + std::to_string(i) + " has " +
                         (std::isnan(p.x) || std::isnan(p.y) ? "a NaN" : "an infinite") + " coordinate");
    }
  return e;
}

std::vector<std::uint32_t> hilbert_cells_order(const Point* points, std::uint32_t n, unsigned threads) {
  std::vector<std::uint32_t> key(n);
  hilbert_keys(points, n, threads, key.data());
  const Block<std::uint64_t> words = sorted_words(key.data(), n, threads);
  std::vector<std::uint32_t> order(n);
  // Each part of the order takes the runs of one cell that start in it, and sorts each by the
  // points (stable: equal points by index).
  parallel_for(n, threads, 1 << 16, [&](std::size_t first, std::size_t last) {
    auto starts = [&](std::size_t k) { return k == 0 || k == n || words[k - 1] >> 32 != words[k] >> 32; };
    while (first < last && !starts(first)) ++first;
    for (std::size_t begin = first; begin < last;) {
      std::size_t end = begin + 1;
      while (!starts(end)) ++end;
      for (std::size_t k = begin; k < end; ++k) order[k] = static_cast<std::uint32_t>(words[k]);
      if (end - begin > 1)
        std::stable_sort(order.begin() + static_cast<std::ptrdiff_t>(begin),
                         order.begin() + static_cast<std::ptrdiff_t>(end),
                         [&](std::uint32_t a, std::uint32_t b) { return lex_less(points[a], points[b]); });
      begin = end;
    }
  });
  return order;
}

}  // namespace ridt::detail
