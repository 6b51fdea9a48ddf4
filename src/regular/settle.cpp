// The regular triangulation's hull, copies and hidden points, and its output (regular/settle.hpp).
#include "regular/settle.hpp"

#include <algorithm>
#include <bit>

#include "order/order.hpp"
#include "order/random.hpp"
#include "predicates/predicates.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"

namespace ridt::detail {

namespace {

// value(i) for each i in [0, count) where keep(i), in order: on threads, the kept counted in
// each part, then each part's values written after those of the parts before (no list grown
// and copied). value(i) is called once for each kept i.
template <class T, class Keep, class Value>
std::vector<T> gathered(std::size_t count, unsigned threads, Keep&& keep, Value&& value) {
  const auto parts = static_cast<unsigned>(std::clamp<std::size_t>(count / 65536, 1, std::max(threads, 1u)));
  std::vector<std::size_t> at(parts + 1, 0);
  parallel_for(parts, parts, 1, [&](std::size_t from, std::size_t to) {
    for (std::size_t p = from; p < to; ++p) {
      std::size_t k = 0;  // (here, not in at[p + 1], whose line the other parts write)
      for (std::size_t i = count * p / parts; i < count * (p + 1) / parts; ++i) k += keep(i) ? 1 : 0;
      at[p + 1] = k;
    }
  });
  for (unsigned p = 0; p < parts; ++p) at[p + 1] += at[p];
  std::vector<T> all;
  resize_present(all, at[parts], threads);
  parallel_for(parts, parts, 1, [&](std::size_t from, std::size_t to) {
    for (std::size_t p = from; p < to; ++p) {
      T* out = all.data() + at[p];
      for (std::size_t i = count * p / parts; i < count * (p + 1) / parts; ++i)
        if (keep(i)) *out++ = value(i);
    }
  });
  return all;
}

// Of the words (hash << 32 | anything), those whose hash's top bits another word's share: the
// only ones that can be copies of another. The top bits (at least three more than the words
// need) mark a table of bits, `twice` where two words mark one; each thread marks its own stretch
// of the table, reading every word (so no two threads write one table word).
std::vector<std::uint64_t> meeting(const std::vector<std::uint64_t>& words, unsigned threads) {
  const int bits = std::min(32, std::countr_zero(std::bit_ceil(std::max<std::size_t>(8 * words.size(), 64))));
  const std::size_t size = std::size_t{1} << (bits - 6);  // 64-bit table words
  std::vector<std::uint64_t> once(size, 0), twice(size, 0);
  auto slot = [&](std::uint64_t word) { return word >> (64 - bits); };
  const auto parts = static_cast<unsigned>(std::clamp<std::size_t>(words.size() / 65536, 1, std::max(threads, 1u)));
  parallel_for(parts, parts, 1, [&](std::size_t from, std::size_t to) {
    // (whole table words: a word cut between two threads would be written by both)
    const std::uint64_t low = 64 * (size * from / parts), high = 64 * (size * to / parts);
    for (const std::uint64_t word : words)
      if (const std::uint64_t h = slot(word); h >= low && h < high) {
        const std::uint64_t bit = std::uint64_t{1} << (h & 63);
        twice[h >> 6] |= once[h >> 6] & bit;
        once[h >> 6] |= bit;
      }
  });
  return gathered<std::uint64_t>(
      words.size(), threads,
      [&](std::size_t k) {
        const std::uint64_t h = slot(words[k]);
        return (twice[h >> 6] >> (h & 63) & 1) != 0;
      },
      [&](std::size_t k) { return words[k]; });
}

// The words (a hash's top 32 bits << 32 | an input index) sorted by the hash (the insertion
// order's radix sort, on threads); each run of one hash, which holds one word but where points
// are copies of each other (or their hashes meet), then sorted by the points' values and
// indices, so that each group of equal weighted points lies together, its least index first.
// Reads the points at random only in those runs.
template <class Less>
std::vector<std::uint64_t> grouped(std::vector<std::uint64_t> a, Less&& less, unsigned threads) {
  const std::size_t m = a.size();
  std::vector<std::uint64_t> b;
  resize_present(b, m, threads);
  sort_by_key(a.data(), b.data(), static_cast<std::uint32_t>(m), threads);
  for (std::size_t k = 0, g = 0; k < m; k = g) {
    for (g = k + 1; g < m && b[g] >> 32 == b[k] >> 32;) ++g;
    if (g > k + 1)
      std::sort(b.begin() + static_cast<std::ptrdiff_t>(k), b.begin() + static_cast<std::ptrdiff_t>(g),
                [&](std::uint64_t x, std::uint64_t y) {
                  const auto i = static_cast<VertexId>(x), j = static_cast<VertexId>(y);
                  return less(i, j) || (!less(j, i) && i < j);
                });
  }
  b.erase(std::unique(b.begin(), b.end()), b.end());  // (an index met twice: a copy's vertex)
  return b;
}

}  // namespace

std::vector<VertexId> hull_of(const Tds& tds, VertexId infinite, std::span<const Point> points,
                              const std::vector<VertexId>& input, unsigned threads) {
  const std::vector<VertexId> walls = indices_where(tds.slots(), threads, [&](std::size_t t) {
    const VertexId* c = tds.corners(static_cast<TriangleId>(t));
    return c[0] == infinite || c[1] == infinite || c[2] == infinite;
  });
  std::vector<std::pair<VertexId, VertexId>> next;  // (q, p)
  next.reserve(walls.size());
  for (const TriangleId t : walls)
    for (int k = 0; k < 3; ++k)
      if (tds.vertex(t, k) == infinite) next.emplace_back(tds.vertex(t, prev3(k)), tds.vertex(t, next3(k)));
  std::sort(next.begin(), next.end());
  VertexId from = next[0].first;
  for (const auto& e : next)
    if (lex_less(points[input[e.first]], points[input[from]])) from = e.first;
  std::vector<VertexId> hull;
  for (VertexId v = from; hull.size() < next.size();) {
    hull.push_back(input[v]);
    v = std::lower_bound(next.begin(), next.end(), std::make_pair(v, VertexId{0}))->second;
    if (v == from) break;
  }
  return hull;
}

Settled settle(std::span<const Point> points, std::span<const double> weights, std::span<const Weighted> q,
               const std::vector<std::pair<VertexId, VertexId>>& copies, const std::vector<std::uint8_t>& is_hidden,
               std::vector<VertexId>& input, unsigned threads) {
  auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x == 0 ? 0.0 : x); };
  auto hash = [&](VertexId v) { return mix64(bits(q[v].p.x) ^ mix64(bits(q[v].p.y) ^ std::rotl(bits(q[v].w), 32))); };
  // Each hidden point marked at its input index (input: one vertex each), and its word (its
  // hash's top 32 bits << 32 | its input index) made.
  std::vector<std::uint8_t> hidden;  // by input index: the list comes out sorted
  resize_present(hidden, points.size(), threads);
  auto word = [&](VertexId v) { return hash(v) >> 32 << 32 | input[v]; };
  std::vector<std::uint64_t> words = gathered<std::uint64_t>(
      is_hidden.size(), threads, [&](std::size_t v) { return is_hidden[v] != 0; },
      [&](std::size_t v) {
        hidden[input[v]] = 1;
        return word(static_cast<VertexId>(v));
      });
  // The copies found at insertion with them; of all, those that may be copies of another (the
  // copies found at insertion among them: each meets its vertex), grouped.
  for (const auto& [c, w] : copies) words.push_back(word(c)), words.push_back(word(w));
  words = meeting(words, threads);
  auto less = [&](VertexId i, VertexId j) {  // (0 and -0 equal, as the hash has them)
    const Point &p = points[i], &r = points[j];
    return p.x < r.x || (p.x == r.x && (p.y < r.y || (p.y == r.y && weights[i] < weights[j])));
  };
  words = grouped(std::move(words), less, threads);
  Settled out;
  std::vector<std::pair<VertexId, VertexId>> least;  // (index, its group's least), where they differ
  for (std::size_t k = 1, low = 0; k < words.size(); ++k) {
    const auto i = static_cast<VertexId>(words[k]), first = static_cast<VertexId>(words[low]);
    if (words[k] >> 32 == words[low] >> 32 && !less(first, i))
      least.emplace_back(i, first), out.duplicates.push_back({i, first});
    else
      low = k;
  }
  std::sort(least.begin(), least.end());
  auto dropped = [&](VertexId i) {
    const auto it = std::lower_bound(least.begin(), least.end(), std::make_pair(i, VertexId{0}));
    return it != least.end() && it->first == i ? it->second : i;
  };
  for (const auto& [c, w] : copies) input[w] = dropped(input[w]);
  // A group with a hidden member is hidden (a vertex hidden after its copies came), as its least.
  for (const auto& [i, low] : least)
    if (hidden[i]) hidden[i] = 0, hidden[low] = 1;
  out.hidden = gathered<VertexId>(
      hidden.size(), threads, [&](std::size_t i) { return hidden[i] != 0; },
      [](std::size_t i) { return static_cast<VertexId>(i); });
  std::sort(out.duplicates.begin(), out.duplicates.end(),
            [](const Duplicate& a, const Duplicate& b) { return a.dropped < b.dropped; });
  return out;
}

}  // namespace ridt::detail
