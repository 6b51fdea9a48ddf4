// The walking kernel's mesh, its serial driver and its finish (walk/mesh.hpp).
#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <memory>
#include <new>
#include <numeric>
#include <stdexcept>
#include <thread>

#include "finish/finish.hpp"
#include "methods/method.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"
#include "walk/mesh.hpp"

namespace ridt::detail {

MeshArrays::MeshArrays(std::uint64_t n, unsigned threads) {
  if (n > kMaxWalkingPoints)
    throw InputError("too many points for the walking kernel (at most " + std::to_string(kMaxWalkingPoints) + ")");
  // 2k + 1 triangles for k points, at every step.
  const std::size_t size = 3 * (2 * n + 1);
  v.reserve(size), link.reserve(size);
  make_present(v.data(), size * sizeof(VertexId), threads);
  make_present(link.data(), size * sizeof(Link), threads);
  // A vector's new elements are zeroed, on one thread: each array on its own, side by side.
  on_threads(threads >= 2 ? 2 : 1, [&](unsigned w) {
    if (w == 0) v.resize(size);
    if (w == 1 || threads < 2) link.resize(size);
  });
}

std::span<std::uint64_t> MeshArrays::words() {
  // Words begin their lifetime where the vertex numbers were (trivial types: nothing is
  // written); the mesh begins theirs again (Mesh::Mesh).
  const std::size_t count = v.size() * sizeof(VertexId) / sizeof(std::uint64_t);
  std::uninitialized_default_construct_n(reinterpret_cast<std::uint64_t*>(v.data()), count);
  return {std::launder(reinterpret_cast<std::uint64_t*>(v.data())), count};
}

Mesh::Mesh(const Vertices& vertices, MeshArrays arrays)
    : vertices_(vertices), vertex_store_(std::move(arrays.v)), link_store_(std::move(arrays.link)) {
  if (vertex_store_.size() != 3 * (2 * std::size_t{vertices.n()} + 1) || link_store_.size() != vertex_store_.size())
    throw std::logic_error("ridt: mesh arrays made for another number of points");
  std::uninitialized_default_construct_n(vertex_store_.data(), vertex_store_.size());  // after words()
  v_ = std::launder(vertex_store_.data());
  link_ = link_store_.data();
  top_ = 1;
  v_[0] = vertices.n(), v_[1] = vertices.n() + 1, v_[2] = vertices.n() + 2;
  link_[0] = link_[1] = link_[2] = kNoLink;
}

void Mesh::check_room(TriangleId end) const {
  if (3 * std::size_t{end} > vertex_store_.size()) throw std::logic_error("ridt: the walking mesh ran out of slots");
}

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// insert_walking with the predicates' lattice forms (kLattice) or the general ones.
template <bool kLattice>
void insert_all(Mesh& mesh, bool profile, std::vector<DuplicateHit>& duplicates, Stats& stats, Progress& progress) {
  const std::uint32_t n = mesh.vertices().n();
  CavityScratch s;
  SlotPool pool;
  pool.next = mesh.grow(2 * n);
  pool.end = pool.next + 2 * n;
  TriangleId last = 0;
  if (!profile) {
    for (VertexId p = 0; p < n; ++p) {
      progress(p);
      if (const VertexId hit = mesh.insert<kLattice>(p, last, s, pool); hit != kNoVertex)
        duplicates.push_back({p, hit});
    }
  } else {
    // Fig. 8's phases: location is the walk, legalization finding the cavity (the triangles
    // Lawson's flips would replace), subdivision writing the new triangles over it.
    for (VertexId p = 0; p < n; ++p) {
      progress(p);
      const auto t0 = Clock::now();
      TriangleId t = last;
      mesh.walk<kLattice>(t, p, Mesh::kAnywhere);
      const VertexId hit = mesh.coincident(t, p);
      const auto t1 = Clock::now();
      stats.time_locate_s += seconds(t1 - t0);
      if (hit != kNoVertex) {
        duplicates.push_back({p, hit});
        last = t;
        continue;
      }
      mesh.find_cavity<kLattice>(t, p, s, Mesh::kAnywhere);
      const auto t2 = Clock::now();
      stats.time_legalize_s += seconds(t2 - t1);
      last = mesh.fill_cavity(p, s, pool);
      stats.time_split_s += seconds(Clock::now() - t2);
    }
  }
  mesh.give_back(pool);
  stats.flips += s.replaced;
}

}  // namespace

void insert_walking(Mesh& mesh, const Insertion& run) {
  const bool profile = run.experiment.profile;
  if (mesh.vertices().lattice())
    insert_all<true>(mesh, profile, run.duplicates, run.stats, run.progress);
  else
    insert_all<false>(mesh, profile, run.duplicates, run.stats, run.progress);
}

void Mesh::give_back(SlotPool& pool) {
  for (; pool.listed > 0; --pool.listed) free_slot(pool.list[pool.listed - 1]);
  if (pool.end == top_) {
    top_ = pool.next;
  } else {
    for (; pool.next < pool.end; ++pool.next) free_slot(pool.next);
  }
  pool.next = pool.end;
}

namespace {

// The slots of the walking mesh that hold output triangles (no bounding vertex), a bit each,
// and where the output puts them: the output is the mesh's own arrays, so a kept slot below
// count() keeps its place, and the i-th kept slot at or above count() moves into the i-th gap
// below it (a slot of the bounding vertices, or a free one).
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
  }

  TriangleId count() const { return count_; }
  const std::uint64_t* bits() const { return bits_.data(); }
  unsigned workers() const { return workers_; }
  bool kept(TriangleId t) const { return kept(bits_.data(), t); }
  /// The same from a copy of bits().
  static bool kept(const std::uint64_t* bits, std::size_t t) { return (bits[t >> 6] >> (t & 63)) & 1; }
  // Kept slot u's output id.
  std::int32_t new_id(TriangleId u) const {
    if (u < count_) return static_cast<std::int32_t>(u);
    const auto it = std::lower_bound(movers_.begin(), movers_.end(), u);
    return static_cast<std::int32_t>(gaps_[static_cast<std::size_t>(it - movers_.begin())]);
  }
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
};

// Unlinks the kept triangles from the dropped ones (the gaps below count(), and the slots at
// or above it that are not movers: as many as there are bounding triangles and free slots): a
// kept triangle's edge that a dropped one shares becomes a hull edge (kNoLink), so the
// conversion needs no test of a neighbour's slot. Free slots link nowhere.
void unlink_dropped(Mesh& mesh, const KeptSlots& kept) {
  Link* link = mesh.link_array().data();
  auto unlink = [link](TriangleId u) {
    for (int j = 0; j < 3; ++j)
      if (const Link l = link[3 * std::size_t{u} + j]; l != kNoLink) link[l] = kNoLink;
  };
  for (const TriangleId u : kept.gaps()) unlink(u);
  for (TriangleId u = kept.count(); u < mesh.slots(); ++u)
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
  Converter(Mesh& mesh, const KeptSlots& kept, const Standing& standing)
      : v_(mesh.vertex_array().data()),
        link_(mesh.link_array().data()),
        bits_(kept.bits()),
        count_(kept.count()),
        index_(standing.input_index.data()),
        plain_(standing.keep.empty()),
        kept_(&kept),
        standing_(&standing) {}

  void operator()(TriangleId t, TriangleId to) {
    VertexId w[3];
    std::int32_t nb[3];
    for (int i = 0; i < 3; ++i) {
      const VertexId u = v_[3 * std::size_t{t} + i];
      w[i] = plain_ ? index_[u] : (*standing_)(u);
      const Link l = link_[3 * std::size_t{t} + i];
      nb[i] = l != kNoLink ? new_id(triangle_of(l)) : kNoNeighbor;  // a dropped one is unlinked
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
  const KeptSlots* kept_;
  const Standing* standing_;
};

// Converts every kept slot, on the kept slots' workers. Returns the hull's edges.
std::vector<std::pair<VertexId, VertexId>> convert_in_place(Mesh& mesh, const KeptSlots& kept,
                                                            const Standing& standing) {
  const Converter proto(mesh, kept, standing);
  const std::uint32_t n = mesh.vertices().n();
  std::vector<std::vector<std::pair<VertexId, VertexId>>> hull_parts(kept.workers());
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
  // The movers last: their slots lie at or above count(), which no worker wrote.
  Converter convert = proto;
  for (std::size_t i = 0; i < kept.movers().size(); ++i) convert(kept.movers()[i], kept.gaps()[i]);
  std::vector<std::pair<VertexId, VertexId>> hull_edges = std::move(convert.hull);
  for (auto& part : hull_parts) hull_edges.insert(hull_edges.end(), part.begin(), part.end());
  return hull_edges;
}

}  // namespace

Triangulation finish_walking(Mesh& mesh, const std::vector<std::uint32_t>& input_index,
                             const std::vector<DuplicateHit>& duplicates, const Options& options, unsigned threads) {
  Triangulation out;
  const std::uint32_t n = mesh.vertices().n();
  const Standing standing = resolve_duplicates(input_index, duplicates, out.duplicates);
  const KeptSlots kept(mesh.vertex_array().data(), n, mesh.slots(), threads);
  unlink_dropped(mesh, kept);
  std::vector<std::pair<VertexId, VertexId>> hull_edges = convert_in_place(mesh, kept, standing);
  mesh.vertex_array().resize(3 * std::size_t{kept.count()});
  mesh.link_array().resize(3 * std::size_t{kept.count()});
  out.triangles = std::move(mesh.vertex_array());
  out.neighbors = std::move(mesh.link_array());
  out.hull = trace_hull(hull_edges);
  set_warnings(out, n, kept.count(), hull_edges.size(), options, [&](std::vector<Point>& pts) {
    for (VertexId u = 0; u < n; ++u) pts[input_index[u]] = mesh.vertices()[u];
  });
  return out;
}

}  // namespace ridt::detail
