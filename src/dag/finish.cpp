// The history DAG's finish (the paper's Fig. 4, line 24): remove the bounding vertices and
// everything incident to them; then number the remaining triangles compactly, give neighbours
// across the hull as -1, trace the hull and resolve duplicates so the output names the smallest
// input index of each group of equal points.
#include <algorithm>
#include <atomic>
#include <numeric>
#include <thread>
#include <type_traits>

#include "dag/kernel.hpp"
#include "output/output.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"

namespace ridt::detail {
namespace {

// The bits set in x. std::popcount is a library call without the POPCNT instruction, which
// the baseline x86-64 target lacks; this is a dozen inline operations.
constexpr int ones(std::uint64_t x) {
  x -= (x >> 1) & 0x5555555555555555u;
  x = (x & 0x3333333333333333u) + ((x >> 2) & 0x3333333333333333u);
  x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0fu;
  return static_cast<int>((x * 0x0101010101010101u) >> 56);
}
static_assert(ones(0) == 0 && ones(~std::uint64_t{0}) == 64 && ones(0x8000000000000001u) == 2);

}  // namespace

namespace {

// The records of the history DAG that are output triangles (leaves without a bounding vertex):
// a bit for each record and, for each word of 64 records, how many kept records come before
// it. A kept record's new id is its rank among the kept ones: the kept records before its word
// and those before it in the word (a popcount). The bits and ranks take 12 bytes for 64
// records and stay in cache, where reading the neighbours' records for their ids would miss
// it at every read.
//
// The work is shared in blocks of 1024 words (65,536 records) taken in turn from a counter:
// the kept records crowd the later blocks, the last insertions' records, so equal shares of the
// records would be unequal work. A run that fits in one block runs on the caller alone.
class KeptRecords {
 public:
  KeptRecords(TriangleId records, unsigned threads)
      : records_(records),
        words_((std::size_t{records} + 63) / 64),
        blocks_((words_ + kBlockWords - 1) / kBlockWords),
        workers_(static_cast<unsigned>(std::clamp<std::size_t>(blocks_, 1, std::max(threads, 1u)))),
        bits_(words_),
        rank_before_(words_ + 1, 0) {}

  // Pass 1: marks the kept records and moves each block's kept records to its front, in order,
  // with the input indices that stand for their vertices. A record moves only down and is read
  // before anything is written over it. Returns how many records are triangles (DAG nodes).
  std::uint64_t compact(TriangleStore& tris, std::uint32_t n, const Standing& standing) {
    // Ids 1 .. kMaxOwner are never written (dag/records.hpp).
    auto unused = [](TriangleId t) { return t != 0 && t < kFirstChild; };
    auto kept = [&](const Triangle& r) { return is_leaf(r.child) && r.v[0] < n && r.v[1] < n && r.v[2] < n; };
    std::vector<std::uint64_t> made(workers_, 0);
    for_each_block([&](unsigned w, std::size_t b) {
      const auto [begin, end] = range(b);
      TriangleId to = begin;
      std::uint64_t count = 0;  // (here, not in made[w], whose line the other workers write)
      // The input indices of the vertices are read at random: those of a record kAhead on are
      // prefetched, so the misses overlap.
      constexpr TriangleId kAhead = 16;
      for (std::size_t k = first_word(b); k < first_word(b + 1); ++k) {
        std::uint64_t bits = 0;
        const auto stop = static_cast<TriangleId>(std::min<std::size_t>(64 * k + 64, records_));
        for (auto t = static_cast<TriangleId>(64 * k); t < stop; ++t) {
          if (t + kAhead < end && !unused(t + kAhead) && kept(tris[t + kAhead]))
            for (const VertexId v : tris[t + kAhead].v) __builtin_prefetch(&standing.input_index[v]);
          if (unused(t)) continue;
          const Triangle& r = tris[t];
          count += r.v[0] != kNoVertex;
          if (!kept(r)) continue;
          bits |= std::uint64_t{1} << (t & 63);
          tris[to++] = Triangle{{standing(r.v[0]), standing(r.v[1]), standing(r.v[2])}, {r.n[0], r.n[1], r.n[2]}, 0};
        }
        bits_[k] = bits;
        rank_before_[k + 1] = static_cast<std::uint32_t>(ones(bits));
      }
      made[w] += count;
    });
    std::partial_sum(rank_before_.begin(), rank_before_.end(), rank_before_.begin());
    return std::accumulate(made.begin(), made.end(), std::uint64_t{0});
  }

  // After compact(): the moved records' neighbours given as their new ids (-1 across the hull).
  void renumber_neighbors(TriangleStore& tris) {
    for_each_block([&](unsigned, std::size_t b) {
      for (TriangleId t = range(b).first, stop = t + moved(b); t < stop; ++t)
        for (TriangleId& u : tris[t].n) u = static_cast<TriangleId>(neighbor_id(u));
    });
  }

  // body(worker, block) for every block, on workers() threads.
  template <class Body>
  void for_each_block(Body&& body) {
    std::atomic<std::size_t> next{0};
    on_threads(workers_, [&](unsigned w) {
      // relaxed: the blocks need only be distinct; the joins order the results.
      for (std::size_t b; (b = next.fetch_add(1, std::memory_order_relaxed)) < blocks_;) body(w, b);
    });
  }

  std::uint32_t count() const { return rank_before_[words_]; }
  unsigned workers() const { return workers_; }
  std::size_t blocks() const { return blocks_; }
  // Block b's records; after compact(), its kept ones are [first, first + moved(b)).
  std::pair<TriangleId, TriangleId> range(std::size_t b) const {
    return {static_cast<TriangleId>(std::min<std::size_t>(64 * first_word(b), records_)),
            static_cast<TriangleId>(std::min<std::size_t>(64 * first_word(b + 1), records_))};
  }
  TriangleId moved(std::size_t b) const { return rank_before_[first_word(b + 1)] - rank_before_[first_word(b)]; }
  // Record u's output id as a neighbour: -1 for none or a record that is not kept.
  std::int32_t neighbor_id(TriangleId u) const {
    if (u == kNoTriangle || !((bits_[u >> 6] >> (u & 63)) & 1)) return kNoNeighbor;
    const std::uint64_t below = bits_[u >> 6] & ((std::uint64_t{1} << (u & 63)) - 1);
    return static_cast<std::int32_t>(rank_before_[u >> 6] + ones(below));
  }

 private:
  static constexpr std::size_t kBlockWords = 1024;
  std::size_t first_word(std::size_t b) const { return std::min(b * kBlockWords, words_); }

  TriangleId records_;
  std::size_t words_, blocks_;
  unsigned workers_;
  std::vector<std::uint64_t> bits_;
  std::vector<std::uint32_t> rank_before_;
};

// Pass 2: the moved records copied out, block after block, into the output's triangles and
// neighbours, and the records' pages given back behind the copy. The output is reserved, not
// filled, so its pages are first touched as it grows: with the records' pages given back
// meanwhile, the peak is that of the records and not of the records and the output together.
// With two workers or more, one copies the vertices and another the neighbours (already
// renumbered), and a page goes once both are past it. Returns the hull's edges.
std::vector<std::pair<VertexId, VertexId>> copy_out(TriangleStore& tris, const KeptRecords& kept, bool renumbered,
                                                    Triangulation& out) {
  const unsigned copiers = renumbered ? 2 : 1;
  std::atomic<std::uint64_t> copied[2] = {0, 0};  // each copier's progress, in records
  const std::uint64_t step = tris.release_step();
  std::atomic<std::uint64_t> released{0};  // records whose pages are given back
  auto release_behind = [&]() {
    std::uint64_t done = copied[0].load(std::memory_order_acquire);
    if (copiers == 2) done = std::min(done, copied[1].load(std::memory_order_acquire));
    std::uint64_t p = released.load(std::memory_order_relaxed);
    if (done >= p + step && released.compare_exchange_strong(p, done, std::memory_order_relaxed))
      tris.release_pages(static_cast<TriangleId>(p), static_cast<TriangleId>(done));
  };
  // Copier c writes the vertices (c = 0, and the neighbours too when alone) or the neighbours,
  // and the one that writes the neighbours finds the hull's edges.
  std::vector<std::pair<VertexId, VertexId>> hull_edges;
  on_threads(copiers, [&](unsigned c) {
    const bool vertices = c == 0, neighbors = c == 1 || copiers == 1;
    if (vertices) out.triangles.reserve(3 * std::size_t{kept.count()});
    if (neighbors) out.neighbors.reserve(3 * std::size_t{kept.count()});
    constexpr std::size_t kBlock = 4096;  // triangles copied out at once
    std::vector<VertexId> vs(vertices ? 3 * kBlock : 0);
    std::vector<std::int32_t> ns(neighbors ? 3 * kBlock : 0);
    std::size_t k = 0;  // entries in the block
    // Copies what the block holds; every record below `done` is then copied.
    auto flush = [&](std::uint64_t done) {
      if (vertices) out.triangles.insert(out.triangles.end(), vs.begin(), vs.begin() + k);
      if (neighbors) out.neighbors.insert(out.neighbors.end(), ns.begin(), ns.begin() + k);
      k = 0;
      copied[c].store(done, std::memory_order_release);
      release_behind();
    };
    for (std::size_t b = 0; b < kept.blocks(); ++b) {
      const auto [begin, end] = kept.range(b);
      for (TriangleId t = begin; t < begin + kept.moved(b); ++t) {
        const Triangle& r = tris[t];
        for (int i = 0; i < 3; ++i, ++k) {
          if (vertices) vs[k] = r.v[i];
          if (!neighbors) continue;
          ns[k] = renumbered ? static_cast<std::int32_t>(r.n[i]) : kept.neighbor_id(r.n[i]);
          if (ns[k] == kNoNeighbor) hull_edges.emplace_back(r.v[next3(i)], r.v[prev3(i)]);
        }
        if (k == 3 * kBlock) flush(t + 1);
      }
      flush(end);
    }
  });
  return hull_edges;
}

}  // namespace

Triangulation finish(Kernel& kernel, const std::vector<std::uint32_t>& input_index,
                     const std::vector<DuplicateHit>& duplicates, const Options& options, unsigned threads) {
  Triangulation out;
  const Standing standing = resolve_duplicates(input_index, duplicates, out.duplicates);
  TriangleStore& tris = kernel.triangles_for_finish();
  KeptRecords kept(tris.size(), threads);
  out.stats.dag_nodes = kept.compact(tris, kernel.n(), standing);
  // The points are no longer needed (but for the finite bounding triangle's check below).
  if (options.experiment.bounding == Bounding::Symbolic) kernel.release_points();
  // With two copiers, the neighbours' new ids would make the neighbour copier's work twice the
  // vertex copier's: they are written into the moved records first, on every worker.
  const bool renumber = kept.workers() > 1;
  if (renumber) kept.renumber_neighbors(tris);
  std::vector<std::pair<VertexId, VertexId>> hull_edges = copy_out(tris, kept, renumber, out);
  out.hull = trace_hull(hull_edges);
  set_warnings(out, kernel.n(), kept.count(), hull_edges.size(), options, [&](std::vector<Point>& pts) {
    for (VertexId v = 0; v < kernel.n(); ++v) pts[input_index[v]] = kernel.point(v);
  });
  return out;
}

}  // namespace ridt::detail
