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

/// The slots of a round's insertions. A point inserted takes two slots besides its cavity's,
/// but many take none (hidden points, copies, points put off). Each part's pool lists first a
/// share of the free slots the rounds before left, then two fresh slots for each of its points
/// (a range of its own past the slots in use, so that which slot each face takes is the same
/// from run to run). What the pools did not hand out becomes the free slots the next round
/// shares out (at the top, no slots at all): so the free slots, which the finish must fill,
/// are only those of the last round.
class RoundSlots {
 public:
  /// For the round [b, e) of vertex ids; `free` the free slots.
  RoundSlots(Tds& tds, std::vector<TriangleId>& free, VertexId b, VertexId e, unsigned parts)
      : tds_(tds), free_(free), b_(b), parts_(parts), base_(tds.grow(2 * (e - b))) {}

  /// The pool of part i, of `parts`, whose points are [a, b).
  SlotPool pool(unsigned i, VertexId a, VertexId b) const {
    const std::size_t n = free_.size();
    const std::size_t first = n * i / parts_, last = n * (i + 1) / parts_;
    return {free_.data() + first, last - first, base_ + 2 * (a - b_), base_ + 2 * (b - b_)};
  }
  /// After the round: what the pools did not hand out, and the slots in `freed`, the free
  /// slots; fresh ones at the top dropped.
  void close(std::span<SlotPool* const> pools, std::span<std::vector<TriangleId>* const> freed) {
    std::vector<TriangleId> left;
    std::size_t size = 0;
    for (const SlotPool* p : pools) size += p->size();
    for (const std::vector<TriangleId>* f : freed) size += f->size();
    left.reserve(size);
    for (auto pool = pools.rbegin(); pool != pools.rend(); ++pool) {
      SlotPool& p = **pool;
      left.insert(left.end(), p.list, p.list + p.listed);
      if (p.end == tds_.slots()) {
        tds_.truncate(p.next);
      } else {
        for (; p.next < p.end; ++p.next) tds_.free_slot(p.next), left.push_back(p.next);
      }
      p = SlotPool{};
    }
    for (const std::vector<TriangleId>* f : freed) left.insert(left.end(), f->begin(), f->end());
    free_ = std::move(left);
  }

 private:
  Tds& tds_;
  std::vector<TriangleId>& free_;
  VertexId b_;
  unsigned parts_;
  TriangleId base_;
};

/// A part for each of `threads` threads of the round [b, e) of vertex ids, whose keys never
/// decrease: its stretch [a, b) and region of keys [from, to) (cut_round), its share of the
/// round's slots (`slots`), and its stamps' epochs: epoch + i + 1, then steps of `threads`
/// (Part::epoch the one before its first). Part needs those members.
template <class Part>
std::vector<Part> round_parts(std::span<const std::uint32_t> key, VertexId b, VertexId e, unsigned threads,
                              std::uint32_t epoch, const RoundSlots& slots) {
  std::vector<Part> parts(threads);
  const std::vector<Stretch> cut = cut_round(key.data(), b, e, threads);
  for (unsigned i = 0; i < threads; ++i) {
    Part& p = parts[i];
    p.a = cut[i].a, p.b = cut[i].b, p.from = cut[i].from, p.to = cut[i].to;
    p.pool = slots.pool(i, p.a, p.b);
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

/// After the round: the slots the parts did not take, and those in their `freed` lists, made the
/// free slots (RoundSlots::close); the last epoch used.
template <class Part>
std::uint32_t round_left(RoundSlots& slots, std::vector<Part>& parts, std::uint32_t epoch) {
  std::vector<SlotPool*> pools;
  std::vector<std::vector<TriangleId>*> freed;
  for (Part& p : parts) epoch = std::max(epoch, p.epoch), pools.push_back(&p.pool), freed.push_back(&p.freed);
  slots.close(pools, freed);
  return epoch;
}

}  // namespace ridt::detail
