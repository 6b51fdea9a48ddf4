// A round of insertions shared among threads by regions of a curve, for the triangulations on
// the one mutable triangulation that insert this way (the sphere's, sphere/sphere.cpp; the
// regular one, regular/regular.cpp): the parts' stretches, keys, slots and stamps, and what
// they leave.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "order/runs.hpp"
#include "runtime/parallel.hpp"
#include "tds/tds.hpp"

namespace ridt::detail {

/// A round is shared among the threads where it has at least kMinCutRound points and each
/// thread gets at least kMinPart (a smaller one meets a triangulation so small that most of its
/// points would be put off); a thread tries up to kStartTries points for a face to start from.
inline constexpr VertexId kMinCutRound = 4096, kMinPart = 256, kStartTries = 64;
constexpr bool shared_round(VertexId points, unsigned threads) {
  return threads > 1 && points >= kMinCutRound && points >= std::uint64_t{kMinPart} * threads;
}

/// A part for each of `threads` threads of the round [b, e) of vertex ids, whose keys never
/// decrease: its stretch [a, b) and region of keys [from, to) (cut_round), two fresh slots for
/// each of its points in `pool`, and its stamps' epochs: epoch + i + 1, then steps of `threads`
/// (Part::epoch the one before its first). Part needs those members.
template <class Part>
std::vector<Part> round_parts(Tds& tds, std::span<const std::uint32_t> key, VertexId b, VertexId e, unsigned threads,
                              std::uint32_t epoch) {
  std::vector<Part> parts(threads);
  const std::vector<Stretch> cut = cut_round(key.data(), b, e, threads);
  const TriangleId base = tds.grow(2 * (e - b));
  for (unsigned i = 0; i < threads; ++i) {
    Part& p = parts[i];
    p.a = cut[i].a, p.b = cut[i].b, p.from = cut[i].from, p.to = cut[i].to;
    p.pool = {nullptr, 0, base + 2 * (p.a - b), base + 2 * (p.b - b)};
    p.epoch = epoch + i + 1 - threads;
  }
  return parts;
}

/// Runs insert(part, scratch) for each part on a thread of its own, each with a scratch of its
/// own (kept in `scratches` for the next round).
template <class Part, class Insert>
void run_parts(std::vector<Part>& parts, std::vector<CavityScratch>& scratches, Insert&& insert) {
  if (scratches.size() < parts.size()) scratches.resize(parts.size());
  const auto threads = static_cast<unsigned>(parts.size());
  parallel_for(parts.size(), threads, 1, [&](std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) insert(parts[i], scratches[i]);
  });
}

/// How many steps a walk may take before it gives up (a walk through cones or over faces that
/// are not a Delaunay triangulation's may cycle): a round's point is then put off, a point
/// inserted alone looked for by a scan.
inline std::size_t walk_limit(const Tds& tds) {
  return 256 + 4 * static_cast<std::size_t>(std::sqrt(static_cast<double>(tds.slots())));
}

/// After the round: the slots a part did not take made free, onto `free` (those at the top
/// dropped: no slots at all); the last epoch used.
template <class Part>
std::uint32_t round_left(Tds& tds, std::vector<Part>& parts, std::vector<TriangleId>& free, std::uint32_t epoch) {
  std::size_t left = free.size();
  for (const Part& p : parts) left += p.pool.end - p.pool.next;
  free.reserve(left);  // (once: grown by doubling into fresh pages it took some 8 ms a call)
  for (auto p = parts.rbegin(); p != parts.rend(); ++p) {
    epoch = std::max(epoch, p->epoch);
    if (p->pool.end == tds.slots()) tds.truncate(p->pool.next), p->pool.end = p->pool.next;
    for (; p->pool.next < p->pool.end; ++p->pool.next) tds.free_slot(p->pool.next), free.push_back(p->pool.next);
  }
  return epoch;
}

}  // namespace ridt::detail
