// What every kernel's finish shares (output/output.hpp): the duplicates resolved, the hull
// traced, the warnings, and the canonical order of the output's triangles.
#include <algorithm>
#include <atomic>
#include <numeric>
#include <thread>
#include <type_traits>
#include <unordered_map>

#include "output/output.hpp"
#include "predicates/predicates.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"
#include "tds/ids.hpp"

namespace ridt::detail {
namespace {

// (x0, x1, x2) rotated to start at x[s].
template <class T>
void rotate3(T* x, int s) {
  const T a = x[0], b = x[1], c = x[2];
  if (s == 1) x[0] = b, x[1] = c, x[2] = a;
  if (s == 2) x[0] = c, x[1] = a, x[2] = b;
}

}  // namespace

namespace {

// A triangle on its way to its canonical place: its vertices, rotated to start at the
// smallest; Placed adds its number before, for its neighbours'.
struct Triple {
  VertexId first, second, third;
  bool operator<(const Triple& o) const {
    return first < o.first || (first == o.first && (second < o.second || (second == o.second && third < o.third)));
  }
};
struct Placed : Triple {
  std::uint32_t from;
};

// The triangles, each rotated to start at its smallest vertex, sorted into buckets of first
// vertices (bucket b: first vertices from b << shift), each bucket a run of `bucket_start`,
// in `placed` (room for every triangle): each part of the triangles counts its own a bucket,
// then puts them in place after those of the parts before it. Some two thousand buckets: each
// is small enough to sort in the cache, and a thread writes to few enough places at once to
// keep them there. Placed turns the neighbours with their triangles.
template <class T>
void into_buckets(Triangulation& out, unsigned threads, std::vector<std::uint32_t>& bucket_start, int& shift,
                  T* placed) {
  const std::size_t count = out.size();
  auto& tv = out.triangles;
  auto& tn = out.neighbors;
  const auto parts = static_cast<unsigned>(std::clamp<std::size_t>(count / 65536, 1, threads));
  auto each = [&](unsigned k, auto&& visit) {
    for (std::size_t t = count * k / parts; t < count * (k + 1) / parts; ++t) visit(t);
  };
  // Which corner is the least: the triangles are read from it. Placed turns them where they
  // lie, with their neighbours; Triple leaves them, turning each as it is copied.
  auto least = [&](std::size_t t) {
    const VertexId* v = &tv[3 * t];
    return v[0] < v[1] ? (v[0] < v[2] ? 0 : 2) : (v[1] < v[2] ? 1 : 2);
  };
  auto first = [&](std::size_t t) {
    if constexpr (std::is_same_v<T, Placed>) return tv[3 * t];
    return std::min(std::min(tv[3 * t], tv[3 * t + 1]), tv[3 * t + 2]);  // without branches
  };
  std::vector<VertexId> part_max(parts, 0);
  on_threads(parts, [&](unsigned k) {
    VertexId high = 0;
    each(k, [&](std::size_t t) {
      if constexpr (std::is_same_v<T, Placed>) {
        const int s = least(t);
        rotate3(&tv[3 * t], s);
        rotate3(&tn[3 * t], s);
      }
      high = std::max(high, first(t));
    });
    part_max[k] = high;
  });
  const std::uint64_t groups = count > 0 ? std::uint64_t{*std::max_element(part_max.begin(), part_max.end())} + 1 : 1;
  shift = 0;
  while ((groups >> shift) > 2048) ++shift;
  const std::size_t buckets = static_cast<std::size_t>(((groups - 1) >> shift) + 1);
  std::vector<std::uint32_t> at(parts * buckets, 0);  // at[k * buckets + bucket]
  on_threads(parts, [&](unsigned k) { each(k, [&](std::size_t t) { ++at[k * buckets + (first(t) >> shift)]; }); });
  bucket_start.assign(buckets + 1, 0);
  std::uint32_t sum = 0;
  for (std::size_t b = 0; b < buckets; ++b) {
    bucket_start[b] = sum;
    for (unsigned k = 0; k < parts; ++k) sum += std::exchange(at[k * buckets + b], sum);
  }
  bucket_start[buckets] = sum;
  on_threads(parts, [&](unsigned k) {
    each(k, [&](std::size_t t) {
      const VertexId* v = &tv[3 * t];
      const VertexId m = first(t);
      const int s = v[1] == m ? 1 : v[2] == m ? 2 : 0;  // 0 for Placed
      T& to = placed[at[k * buckets + (m >> shift)]++];
      to.first = m, to.second = v[s == 2 ? 0 : s + 1], to.third = v[s == 0 ? 2 : s - 1];
      if constexpr (std::is_same_v<T, Placed>) to.from = static_cast<std::uint32_t>(t);
    });
  });
}

// The triangles sorted: into buckets, then each bucket on its own, by first vertex (a counting
// sort) and each group of one first vertex (some two triangles, no two with the same second
// vertex) by its second, back into out.triangles; `moved(p, i)` is called for each triangle p
// placed at i, and `sorted` (where set) with each bucket's stretch once it is in place. A
// small group's triangles go straight to their places, each's place its rank among the
// group's second vertices: comparisons without branches, where the moves of an insertion sort
// would go one way or the other at random.
template <class T, class Moved>
void sort_triangles(Triangulation& out, unsigned threads, T* placed, Moved&& moved, const Sorted& sorted) {
  std::vector<std::uint32_t> bucket_start;
  int shift = 0;
  into_buckets(out, threads, bucket_start, shift, placed);
  auto& tv = out.triangles;
  auto put = [&](const T& p, std::uint32_t i) {
    tv[3 * i] = p.first, tv[3 * i + 1] = p.second, tv[3 * i + 2] = p.third;
    moved(p, i);
  };
  parallel_for(bucket_start.size() - 1, threads, 16, [&](std::size_t first, std::size_t last) {
    std::vector<std::uint32_t> at((std::size_t{1} << shift) + 1);
    std::vector<T> run;
    for (std::size_t b = first; b < last; ++b) {
      const std::uint32_t lo = bucket_start[b], hi = bucket_start[b + 1];
      const VertexId base = static_cast<VertexId>(b << shift);
      std::fill(at.begin(), at.end(), 0u);
      for (std::uint32_t i = lo; i < hi; ++i) ++at[placed[i].first - base + 1];
      std::partial_sum(at.begin(), at.end(), at.begin());
      run.resize(hi - lo);
      for (std::uint32_t i = lo; i < hi; ++i) run[at[placed[i].first - base]++] = placed[i];
      // at[v - base] is now where v's group ends, the next one's start.
      for (std::size_t v = 0, begin = 0; v + 1 < at.size() && begin < run.size(); begin = at[v++]) {
        T* const group = run.data() + begin;
        const std::size_t size = at[v] - begin;
        // Distinct ranks sum to 0 + 1 + ... + (size - 1); a tie (two triangles on one directed
        // edge, not in a triangulation) sums to less and would leave a place unwritten: such a
        // group, and the many of a fan's centre, are sorted whole instead.
        bool whole = size > 16;
        if (!whole) {
          std::size_t ranks = 0;
          for (std::size_t k = 0; k < size; ++k) {
            std::size_t rank = 0;
            for (std::size_t j = 0; j < size; ++j) rank += group[j].second < group[k].second;
            put(group[k], static_cast<std::uint32_t>(lo + begin + rank));
            ranks += rank;
          }
          whole = 2 * ranks != size * (size - 1);
        }
        if (whole) {
          std::sort(group, group + size);
          for (std::size_t k = 0; k < size; ++k) put(group[k], static_cast<std::uint32_t>(lo + begin + k));
        }
      }
      if (sorted) sorted(lo, std::span<const VertexId>(&tv[3 * std::size_t{lo}], 3 * std::size_t{hi - lo}));
    }
  });
}

}  // namespace

// Each triangle rotated to start at its smallest vertex, then the triangles sorted (no two
// triangles share a first and a second vertex: the edge between them is directed
// counter-clockwise in one triangle only; the order is the same on any number of threads).
// The triangles travel with their vertices, so nothing is looked up at random but the
// neighbours: renumbered where they are, then moved to their triangles' new places in the
// buckets' memory (no longer needed by then) and copied back. Fresh memory costs more than a
// pass over it (each page faulted in and zeroed), so the sort takes 20 bytes a triangle beyond
// the result, and none of it is zeroed twice; without the neighbours, none: their memory holds
// the buckets, and is given back after.
void canonicalize(Triangulation& out, unsigned threads, bool neighbors, const Sorted& sorted) {
  threads = std::max(threads, 1u);
  const std::size_t count = out.size();
  auto& tn = out.neighbors;
  if (!neighbors) {
    if (tn.size() < 3 * count) tn.resize(3 * count);
    // Triples of unsigned numbers where the signed ones were: an allowed alias.
    static_assert(sizeof(Triple) == 3 * sizeof(std::int32_t) && alignof(Triple) == alignof(std::int32_t));
    sort_triangles(
        out, threads, reinterpret_cast<Triple*>(tn.data()), [](const Triple&, std::uint32_t) {}, sorted);
    std::vector<std::int32_t>().swap(tn);
    return;
  }
  const Block<Placed> placed = allocate_huge<Placed>(count);
  make_present(placed.get(), count * sizeof(Placed), threads);
  const Block<std::int32_t> rank = allocate_huge<std::int32_t>(count);  // a triangle's new number
  make_present(rank.get(), count * sizeof(std::int32_t), threads);
  sort_triangles(
      out, threads, placed.get(),
      [&](const Placed& p, std::uint32_t i) { rank[p.from] = static_cast<std::int32_t>(i); }, sorted);
  // Each triangle's neighbours renumbered in its old place, then the three moved to its new
  // place: in the buckets' memory (12 of its 16 bytes a triangle; int32 may alias the unsigned
  // numbers there), from where they are copied back in order.
  auto* moved = reinterpret_cast<std::int32_t*>(placed.get());
  parallel_for(count, threads, 65536, [&](std::size_t first, std::size_t last) {
    for (std::size_t t = first; t < last; ++t) {
      std::int32_t* n = &tn[3 * t];
      std::int32_t* to = &moved[3 * std::size_t{static_cast<std::uint32_t>(rank[t])}];
      for (int k = 0; k < 3; ++k) to[k] = n[k] < 0 ? kNoNeighbor : rank[n[k]];
    }
  });
  parallel_for(tn.size(), threads, 1 << 18, [&](std::size_t first, std::size_t last) {
    std::copy(moved + first, moved + last, tn.begin() + static_cast<std::ptrdiff_t>(first));
  });
}

void apply_output_options(Triangulation& out, const Options& options, unsigned threads) {
  if (options.canonical_order)
    canonicalize(out, threads, options.neighbors, options.on_sorted);
  else if (!options.neighbors)
    std::vector<std::int32_t>().swap(out.neighbors);
}

Standing resolve_duplicates(const std::vector<std::uint32_t>& input_index, const std::vector<DuplicateHit>& duplicates,
                            std::vector<Duplicate>& out) {
  Standing standing(input_index);
  // The smallest input index of each group stands for all of them.
  auto& keep = standing.keep;  // input index of a mesh vertex -> standing index
  for (const DuplicateHit& d : duplicates) {
    const VertexId v = input_index[d.vertex];
    auto [it, fresh] = keep.try_emplace(v, v);
    it->second = std::min(it->second, input_index[d.dropped]);
  }
  for (const DuplicateHit& d : duplicates) {
    const VertexId v = input_index[d.vertex], dropped = input_index[d.dropped];
    const VertexId kept = keep[v];
    if (dropped != kept) out.push_back({dropped, kept});
    if (v != kept) out.push_back({v, kept});
  }
  std::sort(out.begin(), out.end(), [](const Duplicate& a, const Duplicate& b) { return a.dropped < b.dropped; });
  out.erase(std::unique(out.begin(), out.end(),
                        [](const Duplicate& a, const Duplicate& b) { return a.dropped == b.dropped; }),
            out.end());
  for (auto it = keep.begin(); it != keep.end();) it = it->first == it->second ? keep.erase(it) : std::next(it);
  return standing;
}

std::vector<VertexId> trace_hull(std::vector<std::pair<VertexId, VertexId>>& edges) {
  // Follow the boundary edges (counter-clockwise: the interior is on their left) from the
  // smallest vertex index.
  std::vector<VertexId> hull;
  if (edges.empty()) return hull;
  std::sort(edges.begin(), edges.end());
  auto from = [&](VertexId v) {
    auto it = std::lower_bound(edges.begin(), edges.end(), std::pair{v, VertexId{0}});
    return it != edges.end() && it->first == v ? it->second : kNoVertex;
  };
  const VertexId start = edges.front().first;
  VertexId v = start;
  do {
    hull.push_back(v);
    v = from(v);
  } while (v != kNoVertex && v != start && hull.size() <= edges.size());
  return hull;
}

void set_warnings(Triangulation& out, std::uint32_t n, std::uint32_t count, std::size_t hull_edges,
                  const Options& options, const std::function<void(std::vector<Point>&)>& input_points) {
  Stats& s = out.stats;
  s.points = n;
  s.duplicates = out.duplicates.size();
  s.distinct = n - s.duplicates;
  if (s.distinct < 3) {
    out.warning = "fewer than three distinct points: no triangle";
  } else if (count == 0 && options.experiment.bounding == Bounding::Symbolic) {
    out.warning = "all points are collinear: no triangle";  // else there would be a triangle
  } else if (options.experiment.bounding == Bounding::Finite) {
    // The paper's finite bounding triangle can leave a reflex boundary or drop points, or
    // every triangle, when the circle of a thin one holds a bounding vertex.
    std::vector<Point> pts(n);
    input_points(pts);
    const std::size_t h = out.hull.size();
    if (count == 0) {
      VertexId far = 0;  // a point other than pts[0]
      while (far < n && pts[far] == pts[0]) ++far;
      bool collinear = true;
      for (VertexId v = 0; collinear && v < n; ++v) collinear = orient2d(pts[0], pts[far], pts[v]) == 0;
      if (collinear) {
        out.warning = "all points are collinear: no triangle";
        return;
      }
    }
    bool convex = h == hull_edges;
    for (std::size_t i = 0; convex && i < h; ++i)
      convex = orient2d(pts[out.hull[i]], pts[out.hull[(i + 1) % h]], pts[out.hull[(i + 2) % h]]) >= 0;
    // Euler: a triangulation of all distinct points with h boundary vertices has 2d - 2 - h.
    const bool complete = count == 2 * s.distinct - 2 - h;
    if (!convex || !complete)
      out.warning = "finite bounding triangle (k = " + std::to_string(options.experiment.k) +
          ") lost convex hull edges: the result is not the Delaunay triangulation of the "
          "points; use the symbolic bounding triangle";
  }
}

}  // namespace ridt::detail
