// The regular triangulation's hull, copies and hidden points, and its output (regular/settle.hpp).
#include "regular/settle.hpp"

#include <algorithm>
#include <bit>

#include "order/random.hpp"
#include "predicates/predicates.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"

namespace ridt::detail {

std::vector<VertexId> hull_of(const Tds& tds, VertexId infinite, std::span<const Point> points,
                              const std::vector<VertexId>& input) {
  std::vector<std::pair<VertexId, VertexId>> next;  // (q, p)
  for (TriangleId t = 0; t < tds.slots(); ++t)
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

namespace {

using Keyed = std::pair<std::uint64_t, VertexId>;  // (a hash of the weighted point, its input index)

// Sorts pairs whose hashes are uniform: placed by their hashes' first bits (a counting sort into
// about as many buckets as pairs), then each bucket, which holds one or two but where points
// are copies of each other (one hash), sorted on its own (835,000 hidden points: 10 ms where
// std::sort of them all took 80).
void sort_hashed(std::vector<Keyed>& keyed, unsigned threads) {
  const std::size_t n = keyed.size();
  if (n < 2) return;
  const int bits = std::clamp(static_cast<int>(std::bit_width(n)), 1, 24);
  std::vector<std::uint32_t> end((std::size_t{1} << bits) + 1, 0);  // of bucket b - 1, once placed
  for (const Keyed& k : keyed) ++end[(k.first >> (64 - bits)) + 1];
  for (std::size_t b = 1; b < end.size(); ++b) end[b] += end[b - 1];
  std::vector<Keyed> placed;
  resize_present(placed, n, threads);
  for (const Keyed& k : keyed) placed[end[k.first >> (64 - bits)]++] = k;
  for (std::size_t b = 0, from = 0; b + 1 < end.size(); from = end[b++])
    if (end[b] - from > 1) std::sort(placed.begin() + from, placed.begin() + end[b]);
  keyed.swap(placed);
}

}  // namespace

Settled settle(std::span<const Point> points, std::span<const double> weights, std::span<const Weighted> q,
               const std::vector<std::pair<VertexId, VertexId>>& copies, const std::vector<std::uint8_t>& is_hidden,
               std::vector<VertexId>& input, unsigned threads) {
  auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x == 0 ? 0.0 : x); };
  auto hash = [&](VertexId v) { return mix64(bits(q[v].p.x) ^ mix64(bits(q[v].p.y) ^ mix64(bits(q[v].w)))); };
  std::vector<std::uint8_t> hidden(points.size(), 0);  // by input index: the list comes out sorted
  std::vector<VertexId> of;  // the hidden points' vertex ids
  of.reserve(static_cast<std::size_t>(std::count(is_hidden.begin(), is_hidden.end(), std::uint8_t{1})));
  for (VertexId v = 0; v < is_hidden.size(); ++v)
    if (is_hidden[v]) of.push_back(v), hidden[input[v]] = 1;
  const std::size_t count = of.size();
  std::vector<Keyed> keyed;
  resize_present(keyed, 2 * copies.size() + count, threads);
  for (std::size_t k = 0; k < copies.size(); ++k) {
    const auto [c, w] = copies[k];
    keyed[2 * k] = {hash(c), input[c]}, keyed[2 * k + 1] = {hash(w), input[w]};
  }
  parallel_for(count, threads, 16384, [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) keyed[2 * copies.size() + k] = {hash(of[k]), input[of[k]]};
  });
  Settled out;
  sort_hashed(keyed, threads);
  keyed.erase(std::unique(keyed.begin(), keyed.end()), keyed.end());
  std::vector<std::pair<VertexId, VertexId>> least;  // (index, its group's least), where they differ
  auto same = [&](VertexId a, VertexId b) { return points[a] == points[b] && weights[a] == weights[b]; };
  std::vector<VertexId> firsts;
  for (std::size_t k = 0, g = 0; k < keyed.size(); k = g) {
    for (g = k; g < keyed.size() && keyed[g].first == keyed[k].first;) ++g;
    if (g == k + 1) continue;  // (most: no point of theirs read)
    // A run is one group but for a collision of the hash: each index (ascending in the run)
    // against the first of each distinct value met before it, its group's least.
    firsts.clear();
    for (std::size_t a = k; a < g; ++a) {
      const VertexId i = keyed[a].second;
      const auto f = std::find_if(firsts.begin(), firsts.end(), [&](VertexId low) { return same(low, i); });
      if (f == firsts.end())
        firsts.push_back(i);
      else
        least.emplace_back(i, *f), out.duplicates.push_back({i, *f});
    }
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
  out.hidden.reserve(count);
  for (VertexId i = 0; i < hidden.size(); ++i)
    if (hidden[i]) out.hidden.push_back(i);
  std::sort(out.duplicates.begin(), out.duplicates.end(),
            [](const Duplicate& a, const Duplicate& b) { return a.dropped < b.dropped; });
  return out;
}

}  // namespace ridt::detail
