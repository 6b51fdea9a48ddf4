// The walking kernel's finish (tds/delaunay.hpp): its arrays become the output's, in place.
// The triangles of the bounding vertices and the free slots are dropped, the kept slots above
// the output's count move into the gaps below it, and links become neighbour ids. The regular
// triangulation's faces are written the same way (finish_in_place): there the dropped ones are
// the walls at the vertex at infinity, whose number n is the bounding vertices' first.
#include <algorithm>
#include <bit>
#include <numeric>

#include "output/output.hpp"
#include "runtime/parallel.hpp"
#include "tds/delaunay.hpp"

namespace ridt::detail {

namespace {

// The slots of the walking kernel that hold output triangles (no vertex numbered n or more: a
// bounding vertex, the vertex at infinity, a free slot's), a bit each, and where the output
// puts them: the output is the kernel's own arrays, so a kept slot below count() keeps its
// place, and the i-th kept slot at or above count() moves into the i-th gap below it (a
// dropped slot).
class KeptSlots {
 public:
  KeptSlots(const VertexId* v, std::uint32_t n, TriangleId slots, unsigned threads)
      : words_((std::size_t{slots} + 63) / 64),
        workers_(std::clamp<unsigned>(static_cast<unsigned>(words_ / 4096), 1, std::max(threads, 1u))),
        bits_(words_, 0) {
    std::vector<std::uint64_t> kept_in(workers_, 0);
    on_threads(workers_, [&, out = bits_.data()](unsigned w) {
      const auto [first, last] = share(w, words_);
      std::uint64_t count = 0;  // here, not in kept_in[w], whose line the other workers write
      for (std::size_t k = first; k < last; ++k) {
        std::uint64_t bits = 0;
        const std::size_t end = std::min<std::size_t>(64 * k + 64, slots);
        for (std::size_t t = 64 * k; t < end; ++t)
          if (v[3 * t] < n && v[3 * t + 1] < n && v[3 * t + 2] < n) bits |= std::uint64_t{1} << (t & 63);
        out[k] = bits;
        count += static_cast<std::uint64_t>(__builtin_popcountll(bits));
      }
      kept_in[w] = count;
    });
    count_ = static_cast<TriangleId>(std::accumulate(kept_in.begin(), kept_in.end(), std::uint64_t{0}));
    // Word by word: nearly every word below count() is all kept, and few above it are.
    for (std::size_t k = 0; 64 * k < count_; ++k)
      for (std::uint64_t gap = ~bits_[k]; gap != 0; gap &= gap - 1)
        if (const auto t = static_cast<TriangleId>(64 * k + std::countr_zero(gap)); t < count_) gaps_.push_back(t);
    for (std::size_t k = count_ / 64; k < words_; ++k)
      for (std::uint64_t kept = bits_[k]; kept != 0; kept &= kept - 1)
        if (const auto t = static_cast<TriangleId>(64 * k + std::countr_zero(kept)); t >= count_) movers_.push_back(t);
    to_.resize(slots - count_);
    for (std::size_t i = 0; i < movers_.size(); ++i) to_[movers_[i] - count_] = gaps_[i];
  }

  TriangleId count() const { return count_; }
  const std::uint64_t* bits() const { return bits_.data(); }
  unsigned workers() const { return workers_; }
  bool kept(TriangleId t) const { return kept(bits_.data(), t); }
  /// The same from a copy of bits().
  static bool kept(const std::uint64_t* bits, std::size_t t) { return (bits[t >> 6] >> (t & 63)) & 1; }
  // Kept slot u's output id.
  std::int32_t new_id(TriangleId u) const { return static_cast<std::int32_t>(u < count_ ? u : to_[u - count_]); }
  const std::vector<TriangleId>& gaps() const { return gaps_; }
  const std::vector<TriangleId>& movers() const { return movers_; }
  // Worker w's part of [0, total).
  std::pair<std::size_t, std::size_t> share(unsigned w, std::size_t total) const {
    return {total * w / workers_, total * (w + 1) / workers_};
  }

 private:
  std::size_t words_;
  unsigned workers_;
  std::vector<std::uint64_t> bits_;
  TriangleId count_ = 0;
  std::vector<TriangleId> gaps_, movers_;
  std::vector<TriangleId> to_;  // slot count() + i's output id, where it is a mover
};

// Unlinks the kept triangles from the dropped ones (the gaps below count(), and the slots at
// or above it that are not movers: as many as there are bounding triangles, walls and free
// slots): a kept triangle's edge that a dropped one shares becomes a hull edge (kNoLink), so the
// conversion needs no test of a neighbour's slot. Free slots link nowhere.
void unlink_dropped(Tds& tds, const KeptSlots& kept) {
  Link* link = tds.link_array().data();
  auto unlink = [link](TriangleId u) {
    for (int j = 0; j < 3; ++j)
      if (const Link l = link[3 * std::size_t{u} + j]; l != kNoLink) link[l] = kNoLink;
  };
  for (const TriangleId u : kept.gaps()) unlink(u);
  for (TriangleId u = kept.count(); u < tds.slots(); ++u)
    if (!kept.kept(u)) unlink(u);
}

// Rewrites a kept slot in output terms, in place or into its gap: input indices for the
// vertices, the neighbours' new ids (-1 across the hull); collects the hull's edges. Each
// thread works with its own copy: what every triangle reads (the arrays' addresses, the kept
// bits, the count), read through references into the caller's frame, shared cache lines with
// the locals the caller's own thread kept writing, and had to be read again after each store
// into the arrays. So on two threads each half took longer than the whole on one (40 ms
// against 28 at 10^6 points); with copies the finish takes 13 ms on two threads and 24 on one
// (31 before).
class Converter {
 public:
  Converter(Tds& tds, const KeptSlots& kept, const Standing& standing, bool links)
      : v_(tds.vertex_array().data()),
        link_(tds.link_array().data()),
        bits_(kept.bits()),
        count_(kept.count()),
        index_(standing.input_index.data()),
        plain_(standing.keep.empty()),
        links_(links),
        kept_(&kept),
        standing_(&standing) {}

  void operator()(TriangleId t, TriangleId to) {
    VertexId w[3];
    std::int32_t nb[3];
    for (int i = 0; i < 3; ++i) {
      const VertexId u = v_[3 * std::size_t{t} + i];
      w[i] = plain_ ? index_[u] : (*standing_)(u);
      const Link l = link_[3 * std::size_t{t} + i];
      // A dropped one is unlinked; kept as links, the neighbour's edge goes with its new id.
      nb[i] = l == kNoLink ? kNoNeighbor : links_ ? 3 * new_id(triangle_of(l)) + edge_of(l) : new_id(triangle_of(l));
    }
    for (int i = 0; i < 3; ++i) {
      v_[3 * std::size_t{to} + i] = w[i], link_[3 * std::size_t{to} + i] = static_cast<Link>(nb[i]);
      if (nb[i] == kNoNeighbor) hull.emplace_back(w[next3(i)], w[prev3(i)]);
    }
  }

  bool kept(std::size_t t) const { return KeptSlots::kept(bits_, t); }
  /// Asks for the input index of the vertices of triangle t.
  void prefetch(std::size_t t, std::uint32_t n) const {
    for (int i = 0; i < 3; ++i)
      if (const VertexId u = v_[3 * t + i]; u < n) __builtin_prefetch(&index_[u]);
  }

  std::vector<std::pair<VertexId, VertexId>> hull;

 private:
  std::int32_t new_id(TriangleId u) const { return u < count_ ? static_cast<std::int32_t>(u) : kept_->new_id(u); }

  VertexId* v_;
  Link* link_;
  const std::uint64_t* bits_;
  TriangleId count_;
  const std::uint32_t* index_;
  bool plain_;
  bool links_;
  const KeptSlots* kept_;
  const Standing* standing_;
};

// Converts every kept slot, on the kept slots' workers. Returns the hull's edges.
std::vector<std::pair<VertexId, VertexId>> convert_in_place(Tds& tds, std::uint32_t n, const KeptSlots& kept,
                                                            const Standing& standing, bool links) {
  const Converter proto(tds, kept, standing, links);
  std::vector<std::vector<std::pair<VertexId, VertexId>>> hull_parts(kept.workers());
  std::vector<std::vector<std::pair<VertexId, VertexId>>> mover_parts(kept.workers());
  on_threads(kept.workers(), [&hull_parts, &kept, proto, n](unsigned w) {
    Converter convert = proto;
    const auto [first, last] = kept.share(w, kept.count());
    // The input indices of the vertices are read at random: those of a triangle some way on
    // are asked for ahead, so that the misses overlap.
    constexpr std::size_t kAhead = 16;
    for (std::size_t t = first; t < last; ++t) {
      if (t + kAhead < last) convert.prefetch(t + kAhead, n);
      if (convert.kept(t)) convert(static_cast<TriangleId>(t), static_cast<TriangleId>(t));
    }
    hull_parts[w] = std::move(convert.hull);
  });
  // The movers after: their slots lie at or above count(), which no worker wrote, and each
  // goes to a gap of its own.
  on_threads(kept.workers(), [&mover_parts, &kept, proto, n](unsigned w) {
    Converter convert = proto;
    const auto [first, last] = kept.share(w, kept.movers().size());
    constexpr std::size_t kAhead = 16;  // (as above)
    for (std::size_t i = first; i < last; ++i) {
      if (i + kAhead < last) convert.prefetch(kept.movers()[i + kAhead], n);
      convert(kept.movers()[i], kept.gaps()[i]);
    }
    mover_parts[w] = std::move(convert.hull);
  });
  std::vector<std::pair<VertexId, VertexId>> hull_edges;
  for (auto& part : mover_parts) hull_edges.insert(hull_edges.end(), part.begin(), part.end());
  for (auto& part : hull_parts) hull_edges.insert(hull_edges.end(), part.begin(), part.end());
  return hull_edges;
}

}  // namespace

Triangulation finish_walking(DelaunayTds& tds, const std::vector<std::uint32_t>& input_index,
                             const std::vector<DuplicateHit>& duplicates, const Options& options, unsigned threads,
                             bool links) {
  Triangulation out;
  const std::uint32_t n = tds.vertices().n();
  const Standing standing = resolve_duplicates(input_index, duplicates, out.duplicates);
  const KeptSlots kept(tds.vertex_array().data(), n, tds.slots(), threads);
  unlink_dropped(tds, kept);
  std::vector<std::pair<VertexId, VertexId>> hull_edges = convert_in_place(tds, n, kept, standing, links);
  tds.vertex_array().resize(3 * std::size_t{kept.count()});
  tds.link_array().resize(3 * std::size_t{kept.count()});
  out.triangles = std::move(tds.vertex_array());
  out.neighbors = std::move(tds.link_array());
  out.hull = trace_hull(hull_edges);
  set_warnings(out, n, kept.count(), hull_edges.size(), options, [&](std::vector<Point>& pts) {
    for (VertexId u = 0; u < n; ++u) pts[input_index[u]] = tds.vertices()[u];
  });
  return out;
}

void finish_in_place(Tds& tds, std::uint32_t n, const std::vector<std::uint32_t>& input_index, unsigned threads,
                     std::vector<VertexId>& triangles, std::vector<std::int32_t>& neighbors) {
  const Standing standing(input_index);
  const KeptSlots kept(tds.vertex_array().data(), n, tds.slots(), threads);
  unlink_dropped(tds, kept);
  convert_in_place(tds, n, kept, standing, false);
  tds.vertex_array().resize(3 * std::size_t{kept.count()});
  tds.link_array().resize(3 * std::size_t{kept.count()});
  triangles = std::move(tds.vertex_array());
  neighbors = std::move(tds.link_array());
}

}  // namespace ridt::detail
