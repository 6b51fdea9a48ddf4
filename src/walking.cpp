// The walking kernel's mesh, its serial driver and its finish (cavity.hpp).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include <sys/mman.h>

#include "cavity.hpp"
#include "driver.hpp"

namespace ridt::detail {

namespace {

// Makes the pages of vector a's storage, reserved and not yet touched, present, `threads` parts
// at once: the kernel's faulting and zeroing of fresh pages then runs on every thread, where
// the vector's own filling would fault them in one by one on one thread. Only a request:
// without MADV_POPULATE_WRITE (Linux 5.14) the filling faults them in as before.
template <class T>
void populate(std::vector<T>& a, unsigned threads) {
#ifdef MADV_POPULATE_WRITE
  constexpr std::uintptr_t kPage = 4096;
  const auto begin = (reinterpret_cast<std::uintptr_t>(a.data()) + kPage - 1) & ~(kPage - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(a.data() + a.capacity())) & ~(kPage - 1);
  if (end <= begin || end - begin < (std::uintptr_t{1} << 22) || threads < 2) return;
  const std::uintptr_t pages = (end - begin) / kPage;
  std::vector<std::jthread> pool;
  for (unsigned t = 0; t < threads; ++t)
    pool.emplace_back([=] {
      const std::uintptr_t from = begin + pages * t / threads * kPage, to = begin + pages * (t + 1) / threads * kPage;
      madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);
    });
#else
  (void)a, (void)threads;
#endif
}

}  // namespace

Mesh::Mesh(const Vertices& vertices, unsigned threads) : vertices_(vertices) {
  const std::uint64_t n = vertices.n();
  if (n > kMaxWalkingPoints) throw InputError("too many points for the walking kernel (at most " +
                                              std::to_string(kMaxWalkingPoints) + ")");
  // 2k + 1 triangles for k points, at every step.
  const std::size_t slots = 2 * n + 1;
  vertex_store_.reserve(3 * slots);
  link_store_.reserve(3 * slots);
  populate(vertex_store_, threads);
  populate(link_store_, threads);
  vertex_store_.resize(3 * slots);
  link_store_.resize(3 * slots);
  v_ = vertex_store_.data();
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
constexpr auto kAnyTriangle = [](TriangleId) { return true; };

}  // namespace

void insert_walking(Mesh& mesh, bool profile, std::vector<DuplicateHit>& duplicates, Stats& stats,
                    Progress& progress) {
  const std::uint32_t n = mesh.vertices().n();
  CavityScratch s;
  SlotPool pool;
  pool.next = mesh.grow(2 * n);
  pool.end = pool.next + 2 * n;
  TriangleId last = 0;
  if (!profile) {
    for (VertexId p = 0; p < n; ++p) {
      progress(p);
      if (const VertexId hit = mesh.insert(p, last, s, pool); hit != kNoVertex) duplicates.push_back({p, hit});
    }
  } else {
    // Fig. 8's phases: location is the walk, legalization finding the cavity (the triangles
    // Lawson's flips would replace), subdivision writing the new triangles over it.
    for (VertexId p = 0; p < n; ++p) {
      progress(p);
      const auto t0 = Clock::now();
      const TriangleId t = mesh.walk(last, p);
      const VertexId hit = mesh.coincident(t, p);
      const auto t1 = Clock::now();
      stats.time_locate_s += seconds(t1 - t0);
      if (hit != kNoVertex) {
        duplicates.push_back({p, hit});
        last = t;
        continue;
      }
      mesh.find_cavity(t, p, s, kAnyTriangle);
      const auto t2 = Clock::now();
      stats.time_legalize_s += seconds(t2 - t1);
      last = mesh.fill_cavity(p, s, pool);
      stats.time_split_s += seconds(Clock::now() - t2);
    }
  }
  mesh.give_back(pool);
  stats.flips += s.replaced;
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

Triangulation finish_walking(Mesh& mesh, const std::vector<std::uint32_t>& input_index,
                             const std::vector<DuplicateHit>& duplicates, const Options& options,
                             unsigned threads) {
  Triangulation out;
  const std::uint32_t n = mesh.vertices().n();
  const TriangleId slots = mesh.slots();
  std::vector<VertexId>& v = mesh.vertex_array();
  std::vector<Link>& link = mesh.link_array();
  const Standing standing = resolve_duplicates(input_index, duplicates, out.duplicates);

  // The output is the mesh's own arrays: the triangles of real vertices keep their slots,
  // and those past the end are moved into the gaps that the others (bounding vertices, free
  // slots) leave below it. A bit for each kept slot first.
  const std::size_t words = (std::size_t{slots} + 63) / 64;
  std::vector<std::uint64_t> kept(words, 0);
  const unsigned workers = std::clamp<unsigned>(static_cast<unsigned>(words / 4096), 1, std::max(threads, 1u));
  auto in_parallel = [&](auto&& body) {
    std::vector<std::jthread> pool;
    for (unsigned w = 1; w < workers; ++w) pool.emplace_back(body, w);
    body(0u);
  };
  auto share = [&](unsigned w, std::size_t total) {
    return std::pair(total * w / workers, total * (w + 1) / workers);
  };
  std::vector<std::uint64_t> kept_in(workers, 0);
  in_parallel([&](unsigned w) {
    const auto [first, last] = share(w, words);
    std::uint64_t count = 0;
    for (std::size_t k = first; k < last; ++k) {
      std::uint64_t bits = 0;
      const std::size_t end = std::min<std::size_t>(64 * k + 64, slots);
      for (std::size_t t = 64 * k; t < end; ++t)
        if (v[3 * t] < n && v[3 * t + 1] < n && v[3 * t + 2] < n) bits |= std::uint64_t{1} << (t & 63);
      kept[k] = bits;
      count += static_cast<std::uint64_t>(__builtin_popcountll(bits));
    }
    kept_in[w] = count;
  });
  std::uint64_t total = 0;
  for (const std::uint64_t c : kept_in) total += c;
  const auto count = static_cast<TriangleId>(total);
  auto is_kept = [&](TriangleId t) { return (kept[t >> 6] >> (t & 63)) & 1; };
  // The gaps below `count` and the kept slots at or above it, as many of each, in order: the
  // i-th of the latter moves into the i-th gap.
  std::vector<TriangleId> gaps, movers;
  for (TriangleId t = 0; t < count; ++t)
    if (!is_kept(t)) gaps.push_back(t);
  for (TriangleId t = count; t < slots; ++t)
    if (is_kept(t)) movers.push_back(t);
  auto new_id = [&](TriangleId u) -> std::int32_t {
    if (u < count) return static_cast<std::int32_t>(u);
    const auto it = std::lower_bound(movers.begin(), movers.end(), u);
    return static_cast<std::int32_t>(gaps[static_cast<std::size_t>(it - movers.begin())]);
  };
  // Slot t in output terms: input indices, neighbours' new ids (-1 across the hull), and the
  // hull's edges found on the way.
  auto convert = [&](TriangleId t, VertexId* tv, Link* tl, std::vector<std::pair<VertexId, VertexId>>& hull) {
    VertexId w[3];
    std::int32_t nb[3];
    for (int i = 0; i < 3; ++i) {
      w[i] = standing(v[3 * std::size_t{t} + i]);
      const Link l = link[3 * std::size_t{t} + i];
      const auto u = static_cast<TriangleId>(l / 3);
      nb[i] = l != kNoLink && is_kept(u) ? new_id(u) : kNoNeighbor;
    }
    for (int i = 0; i < 3; ++i) {
      tv[i] = w[i], tl[i] = nb[i];
      if (nb[i] == kNoNeighbor) hull.emplace_back(w[next3(i)], w[prev3(i)]);
    }
  };
  std::vector<std::vector<std::pair<VertexId, VertexId>>> hull_parts(workers);
  in_parallel([&](unsigned w) {
    const auto [first, last] = share(w, count);
    // The input indices of the vertices are read at random: those of a triangle some way on
    // are asked for ahead, so that the misses overlap.
    constexpr std::size_t kAhead = 16;
    for (std::size_t t = first; t < last; ++t) {
      if (t + kAhead < last)
        for (int i = 0; i < 3; ++i) {
          const VertexId u = v[3 * (t + kAhead) + i];
          if (u < n) __builtin_prefetch(&input_index[u]);
        }
      if (is_kept(static_cast<TriangleId>(t)))
        convert(static_cast<TriangleId>(t), &v[3 * t], &link[3 * t], hull_parts[w]);
    }
  });
  for (std::size_t i = 0; i < movers.size(); ++i)
    convert(movers[i], &v[3 * std::size_t{gaps[i]}], &link[3 * std::size_t{gaps[i]}], hull_parts[0]);
  std::vector<std::pair<VertexId, VertexId>> hull_edges;
  for (auto& part : hull_parts) hull_edges.insert(hull_edges.end(), part.begin(), part.end());

  v.resize(3 * std::size_t{count});
  link.resize(3 * std::size_t{count});
  out.triangles = std::move(v);
  out.neighbors = std::move(link);
  out.hull = trace_hull(hull_edges);
  set_warnings(out, n, count, hull_edges.size(), options, [&](std::vector<Point>& pts) {
    for (VertexId u = 0; u < n; ++u) pts[input_index[u]] = mesh.vertices()[u];
  });
  return out;
}

}  // namespace ridt::detail
