// The Delaunay triangulation on the sphere (ridt/sphere.hpp): the convex hull of the points,
// built by randomized incremental insertion on the one mutable triangulation (tds/tds.hpp),
// whose walk and cavity take the sphere's predicates.
//
// The hull is kept as a closed surface of triangles, counter-clockwise seen from outside,
// about an inner point o (the centroid of the first four points, strictly inside their
// tetrahedron, so inside every later hull: sphere/tetrahedron.hpp). Every decision is the
// exact orientation with its symbolic perturbation (predicates/orient3d.hpp), keyed on the
// points' lexicographic ranks, so that cocircular points (a cube's faces, a latitude circle)
// get one answer whatever the input's order. A point is located by walking through the cones
// from o over the triangles (its side of an edge a-b is its side of the plane through o, a and
// b, o perturbed least of all: the cones part space). It lies outside the hull exactly where
// it sees (lies above the plane of) the triangle whose cone holds it; then the triangles it
// sees make a disc, which is replaced by the fan of the point round its boundary, as a
// Delaunay cavity is. Else it is inside the hull: hidden. A disc with a vertex inside it (a
// point given a rounding below the sphere among close neighbours, now covered) makes that
// vertex hidden.
#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>
#include <numeric>
#include <random>
#include <string>

#include "order/order.hpp"
#include "order/runs.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/predicates.hpp"
#include "ridt/sphere.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"
#include "sphere/distinct.hpp"
#include "sphere/tetrahedron.hpp"
#include "tds/cover.hpp"
#include "tds/delaunay.hpp"
#include "tds/rounds.hpp"
#include "tds/tds.hpp"

namespace ridt {
namespace detail {
namespace {

// The key that sorts free slots after every triangle (a curve's key is below 6 * 2^29).
constexpr std::uint32_t kFreeSlot = ~std::uint32_t{0};

class Builder {
 public:
  Builder(const std::vector<Point3>& p, unsigned threads) : p_(p), threads_(threads) {}

  // Builds the hull; hidden_[v] marks the points inside it.
  // Vertex ids are places in the insertion order (the tetrahedron's four first), so that points
  // inserted one after another lie together in memory; rank_ maps them back.
  void run() {
    const VertexId n = static_cast<VertexId>(p_.size());
    // (every large array made present on the threads first: on huge pages, not faulted in one
    // small page at a time)
    resize_present(hidden_, n, threads_);
    const std::array<VertexId, 4> first = tetrahedron();
    const std::vector<VertexId> order = insertion_order(first);
    resize_present(rank_, n, threads_);
    std::copy(first.begin(), first.end(), rank_.begin());
    std::copy(order.begin(), order.end(), rank_.begin() + 4);
    resize_present(q_, n, threads_), resize_present(key_, n, threads_);
    parallel_for(n, threads_, 65536, [&](std::size_t from, std::size_t to) {
      for (std::size_t v = from; v < to; ++v) q_[v] = p_[rank_[v]], key_[v] = curve_[rank_[v]];
    });
    start();
    for (std::size_t r = 0; r + 1 < rounds_.size(); ++r) {
      const VertexId b = 4 + rounds_[r], e = 4 + rounds_[r + 1];
      if (shared_round(e - b, threads_)) {
        insert_round(b, e);
      } else {
        for (VertexId v = b; v < e; ++v) insert(v);
      }
    }
  }

  const Tds& tds() const { return tds_; }
  /// Per vertex id: its rank (the points' lexicographic order), whether it is hidden.
  const std::vector<VertexId>& rank() const { return rank_; }
  const std::vector<std::uint8_t>& hidden() const { return hidden_; }
  /// Per vertex id: its place along the curve insertion_order sorts by.
  const std::vector<std::uint32_t>& key() const { return key_; }

 private:
  // Four points far from coplanar (fat_tetrahedron), and the inner point inside them.
  std::array<VertexId, 4> tetrahedron() {
    const VertexId n = static_cast<VertexId>(p_.size());
    if (n < 4) throw InputError("triangulate_sphere: fewer than four distinct points");
    std::vector<VertexId> all;
    resize_present(all, n, threads_);
    std::iota(all.begin(), all.end(), VertexId{0});
    const Tetrahedron t = fat_tetrahedron(p_, all);
    if (t.flat != nullptr) throw InputError(std::string("triangulate_sphere: all points are ") + t.flat);
    if (!t.inside) throw InputError("triangulate_sphere: the points are too nearly coplanar");
    inner_ = t.inner;
    return t.v;
  }

  // The tetrahedron's four triangles, counter-clockwise seen from outside (d lies below
  // (a, b, c), and so on), linked; o inside it.
  void start() {
    const VertexId a = 0, b = 1, c = 2, d = 3;
    const VertexId faces[4][3] = {{a, b, c}, {a, d, b}, {a, c, d}, {b, d, c}};
    // Room for the 2n - 4 triangles of n points (a fan takes its cavity's slots and two more,
    // freed ones first; SlotArrays makes the pages present on the threads).
    SlotArrays arrays(p_.size(), threads_);
    std::vector<VertexId>& v = arrays.v;
    std::vector<Link>& link = arrays.link;
    for (int f = 0; f < 4; ++f)
      for (int i = 0; i < 3; ++i) v[3 * f + i] = faces[f][i];
    for (int f = 0; f < 4; ++f)
      for (int i = 0; i < 3; ++i) {
        const VertexId x = faces[f][next3(i)], y = faces[f][prev3(i)];
        for (int g = 0; g < 4; ++g)
          for (int j = 0; j < 3; ++j)
            if (faces[g][next3(j)] == y && faces[g][prev3(j)] == x) link[3 * f + i] = static_cast<Link>(3 * g + j);
      }
    tds_ = Tds(std::move(v), std::move(link), 4);
    resize_present(stamp_, 2 * p_.size() + 1, threads_);
  }

  // The points but the first four: a random permutation (seeded: the same every run) in rounds
  // of doubling size (a biased randomized insertion order), each round along a curve
  // over the directions from the middle (key, below).
  std::vector<VertexId> insertion_order(const std::array<VertexId, 4>& first) {
    std::vector<VertexId> order;
    resize_present(order, p_.size() - 4, threads_);
    for (VertexId v = 0, k = 0; v < p_.size(); ++v)
      if (std::find(first.begin(), first.end(), v) == first.end()) order[k++] = v;
    std::mt19937_64 random(0x5eed);
    std::shuffle(order.begin(), order.end(), random);
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (const Point3& p : p_) {
      const double c[3] = {p.x, p.y, p.z};
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
    }
    // Along a Hilbert curve on each face of a cube about the points' box's centre, the point's
    // direction from it projected onto the face it meets.
    const double mid[3] = {lo[0] / 2 + hi[0] / 2, lo[1] / 2 + hi[1] / 2, lo[2] / 2 + hi[2] / 2};
    auto key = [&](VertexId v) {
      const double d[3] = {p_[v].x - mid[0], p_[v].y - mid[1], p_[v].z - mid[2]};
      int axis = 0;
      for (int k = 1; k < 3; ++k)
        if (std::fabs(d[k]) > std::fabs(d[axis])) axis = k;
      // The other two coordinates over the largest's magnitude, in [-1, 1] at any scale (a factor
      // 32767.5 / |d| taken first is infinite for a difference below 2^-1009, and 0 times it NaN).
      const double m = std::fabs(d[axis]);
      auto cell = [&](double x) {
        return m > 0 ? static_cast<std::uint32_t>(std::clamp(x / m * 32767.5 + 32767.5, 0.0, 65535.0)) : 32767u;
      };
      // The face in the top three bits, the curve's place on it in 29 (cells 2^-14.5 of the
      // face wide): 32 bits, below 6 * 2^29.
      const std::uint32_t face = 2 * static_cast<std::uint32_t>(axis) + (d[axis] < 0);
      return face << 29 | hilbert_key(cell(d[(axis + 1) % 3]), cell(d[(axis + 2) % 3])) >> 3;
    };
    resize_present(curve_, p_.size(), threads_);
    parallel_for(p_.size(), threads_, 65536, [&](std::size_t from, std::size_t to) {
      for (std::size_t v = from; v < to; ++v) curve_[v] = key(static_cast<VertexId>(v));
    });
    // Each round sorted by key, stably (a radix sort): ties in the random order.
    const auto m = static_cast<std::uint32_t>(order.size());
    std::vector<std::uint64_t> words, sorted;
    resize_present(words, m, threads_), resize_present(sorted, m, threads_);
    parallel_for(m, threads_, 65536, [&](std::size_t from, std::size_t to) {
      for (std::size_t i = from; i < to; ++i) words[i] = std::uint64_t{curve_[order[i]]} << 32 | order[i];
    });
    std::uint32_t end = m;
    rounds_.assign(1, end);
    while (end > 0) {
      const std::uint32_t begin = end > 64 ? end / 2 : 0;
      sort_by_key(words.data() + begin, sorted.data() + begin, end - begin, threads_);
      rounds_.push_back(end = begin);
    }
    std::reverse(rounds_.begin(), rounds_.end());
    parallel_for(m, threads_, 65536, [&](std::size_t from, std::size_t to) {
      for (std::size_t i = from; i < to; ++i) order[i] = static_cast<VertexId>(sorted[i]);
    });
    return order;
  }

  // v's side of the plane through o, a and b (+1: the side of the triangles left of a -> b),
  // perturbed as the points are, o least of all (its rank past every point's): never 0, so
  // that the cones from o over the triangles part space, a triangle of three collinear points
  // (a sliver of the perturbed hull) too.
  int side(VertexId a, VertexId b, VertexId v) const {
    return -orient3d_sos(inner_, q_[a], q_[b], q_[v], static_cast<std::uint32_t>(q_.size()), rank_[a], rank_[b],
                         rank_[v]);
  }
  // Whether point v lies above the plane of triangle t (perturbed: never on it).
  bool sees(const VertexId* w, VertexId v) const {
    return orient3d_sos(q_[w[0]], q_[w[1]], q_[w[2]], q_[v], rank_[w[0]], rank_[w[1]], rank_[w[2]], rank_[v]) < 0;
  }
  bool holds(TriangleId t, VertexId v) const {
    const VertexId* w = tds_.corners(t);
    return side(w[0], w[1], v) > 0 && side(w[1], w[2], v) > 0 && side(w[2], w[0], v) > 0;
  }

  // The triangle whose cone from o holds v: by walking from last_, or, where the walk goes on
  // too long (the cones are not a Delaunay triangulation's, whose walks cannot cycle), by
  // looking at every triangle. v lies outside the hull exactly where it sees that triangle.
  TriangleId locate(VertexId v) {
    TriangleId t = last_;
    std::size_t steps = 0;
    const std::size_t limit = walk_limit(tds_);
    const Walked w = tds_.walk(
        t, [&](VertexId a, VertexId b) { return side(a, b, v); },
        [&](Link) { return ++steps < limit ? Step::Cross : Step::Stop; });
    if (w) return t;
    for (TriangleId u = 0; u < tds_.slots(); ++u)
      if (tds_.live(u) && holds(u, v)) return u;
    return last_;  // unreachable: the cones part space
  }

  void insert(VertexId v) {
    const TriangleId t = locate(v);
    if (!sees(tds_.corners(t), v)) {
      hidden_[v] = 1;
      return;
    }
    ++epoch_;
    stamp_[t] = epoch_;
    tds_.find_cavity(
        t, scratch_, [&](const VertexId* w) { return sees(w, v); }, Tds::kAnywhere, Tds::kNoWall,
        stamped(stamp_, epoch_));
    if (scratch_.revisited) {
      cover_at_.resize(p_.size());  // (made at the first: few sets have points inside their hull)
      cover_cavity(
          tds_, scratch_, [&](TriangleId u) { return stamp_[u] == epoch_; }, [&](VertexId u) { hidden_[u] = 1; }, free_,
          cover_, cover_at_);
    }
    SlotPool pool;
    if (free_.size() >= 2) {
      pool.list = free_.data(), pool.listed = free_.size();
    } else {
      pool = tds_.fresh(2);
    }
    last_ = tds_.fill_cavity(v, scratch_, pool);
    free_.resize(pool.listed);
  }

  // The threads' share of a round. Its points are sorted along the curve: each thread takes a
  // stretch of them, and the stretch's keys make its region, which every vertex whose key lies
  // in it (old or new) belongs to. A thread inserts a point only where the triangle its walk
  // ends in and every triangle of the cavity have all three corners in its region, and puts it
  // off else (inserted afterwards on one thread). Its walk crosses only edges with an end in its
  // region, and its cavity grows only by triangles that share an edge with one of its own:
  //   - a triangle a thread replaces is its own, and so are the new ones (the point and the
  //     cavity's boundary), so no two threads write one triangle;
  //   - a triangle with a corner in a thread's region is that thread's, or has corners in two
  //     regions and none changes it: that thread reads it racing with nothing;
  //   - the links a thread rewrites are those of edges with both ends in its region, which
  //     only it reads.
  // (methods/partition.hpp shares the plane's rounds the same way.) The hull is unique, so the
  // triangles are the same whichever thread inserted which point.
  struct alignas(64) Part {  // (a line of its own: its thread writes it at each point)
    VertexId a = 0, b = 0;  // its points
    std::uint64_t from = 0, to = 0;  // its region: the keys in [from, to)
    // Where its walks start: at the first point of each face of the cube (the curve jumps
    // between faces), a triangle with a corner in its region found before the threads start
    // (kNoTriangle where none was).
    std::vector<std::pair<VertexId, TriangleId>> starts;
    TriangleId last = kNoTriangle;  // where its last walk ended
    SlotPool pool;  // two slots a point
    std::vector<VertexId> put_off;
    std::uint32_t epoch = 0;  // its stamps: each insertion's epoch its last plus the thread count
  };

  bool owns(const Part& p, VertexId v) const { return key_[v] >= p.from && key_[v] < p.to; }

  void insert_round(VertexId b, VertexId e) {
    std::vector<Part> parts = round_parts<Part>(tds_, key_, b, e, threads_, epoch_);
    for (Part& p : parts) find_starts(p);
    walk_limit_ = walk_limit(tds_);
    run_parts(parts, scratches_, [&](Part& p, CavityScratch& s) { insert_part(p, s); });
    epoch_ = round_left(tds_, parts, free_, epoch_);
    for (Part& p : parts) {  // what the parts found; then the points put off
      if (p.last != kNoTriangle) last_ = p.last;
    }
    for (const Part& p : parts)
      for (const VertexId v : p.put_off) insert(v);
  }

  // The part's starts, with the hull at rest.
  void find_starts(Part& p) {
    for (VertexId v = p.a; v < p.b; ++v) {
      if (v > p.a && key_[v] >> 29 == key_[v - 1] >> 29) continue;
      TriangleId start = kNoTriangle;
      for (VertexId u = v; u < p.b && u < v + kStartTries && start == kNoTriangle; ++u)
        if (const TriangleId t = locate(u); has_corner_in(t, p)) start = t;
      p.starts.push_back({v, start});
    }
  }

  bool has_corner_in(TriangleId t, const Part& p) const {
    const VertexId* c = tds_.corners(t);
    return owns(p, c[0]) || owns(p, c[1]) || owns(p, c[2]);
  }

  void insert_part(Part& p, CavityScratch& s) {
    TriangleId t = kNoTriangle;
    std::size_t next = 0;
    for (VertexId v = p.a; v < p.b; ++v) {
      if (next < p.starts.size() && p.starts[next].first == v) t = p.starts[next++].second;
      if (t == kNoTriangle || !insert_in(p, s, v, t)) p.put_off.push_back(v);
    }
    p.last = t;
  }

  // insert() on a thread of a round, from triangle t (left where the walk ended, or at the
  // new fan); false, with nothing changed, where the point is put off.
  bool insert_in(Part& p, CavityScratch& s, VertexId v, TriangleId& t) {
    std::size_t steps = 0;
    TriangleId at = t;
    const Walked w = tds_.walk(
        at, [&](VertexId a, VertexId b) { return side(a, b, v); },
        [&](VertexId a, VertexId b) {
          return (owns(p, a) || owns(p, b)) && ++steps < walk_limit_ ? Step::Cross : Step::Stop;
        });
    if (!w) return false;
    t = at;
    const VertexId* c = tds_.corners(at);
    if (!sees(c, v)) return hidden_[v] = 1, true;
    if (!owns(p, c[0]) || !owns(p, c[1]) || !owns(p, c[2]) || p.pool.size() < 2) return false;
    const std::uint32_t epoch = p.epoch += threads_;
    stamp_[at] = epoch;
    const bool whole = tds_.find_cavity(
        at, s, [&](const VertexId* u) { return sees(u, v); }, [&](Link l) { return owns(p, tds_.opposite(l)); },
        Tds::kNoWall, stamped(stamp_, epoch));
    if (!whole || s.revisited) return false;  // a vertex covered: left to insert()
    t = tds_.fill_cavity(v, s, p.pool);
    return true;
  }

  const std::vector<Point3>& p_;  // by rank
  unsigned threads_;
  std::vector<Point3> q_;  // by vertex id
  std::vector<VertexId> rank_;
  Tds tds_;
  Point3 inner_;
  TriangleId last_ = 0;
  CavityScratch scratch_;
  std::vector<TriangleId> free_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t epoch_ = 0;
  std::vector<std::uint8_t> hidden_;
  CoverScratch cover_;
  std::vector<std::uint32_t> cover_at_;  // cover_cavity's, by vertex id
  std::vector<std::uint32_t> curve_;
  std::vector<std::uint32_t> key_;  // by vertex id: curve_ of its rank
  std::vector<VertexId> rounds_;  // the insertion order's rounds: [rounds_[r], rounds_[r + 1])
  std::vector<CavityScratch> scratches_;  // a thread's each
  std::size_t walk_limit_ = 0;
};

// The corner of t with the least vertex id (its place in the insertion order), where the output
// starts the triangle.
int least_corner(const Tds& tds, TriangleId t) {
  const VertexId* c = tds.corners(t);
  return c[0] < c[1] ? (c[0] < c[2] ? 0 : 2) : (c[1] < c[2] ? 1 : 2);
}

// The triangles of one key (round one vertex, or the vertices of one cell of the curve) put in
// the order of their corners' vertex ids, each from its least: their slots depend on which
// thread inserted which point, the ids do not, so that the output is the same on any number of
// threads.
void in_own_order(const Tds& tds, std::vector<std::uint64_t>& live, unsigned threads) {
  auto corners = [&](TriangleId t) {
    const int c = least_corner(tds, t);
    return std::array<VertexId, 3>{tds.vertex(t, c), tds.vertex(t, next3(c)), tds.vertex(t, prev3(c))};
  };
  sort_runs(live, threads, [&](TriangleId x, TriangleId y) { return corners(x) < corners(y); });
}

// The output: the triangles in the order of `live`, each from its least corner, with their
// neighbours, as input indices; the hidden points and the copies.
SphericalTriangulation written(const Tds& tds, const std::vector<std::uint64_t>& live, const Builder& builder,
                               Distinct& d, unsigned threads) {
  const std::vector<VertexId>& rank = builder.rank();
  std::vector<VertexId> input;  // by vertex id
  std::vector<std::int32_t> id;  // by slot: its place in the output (every face's neighbours are faces)
  resize_present(input, rank.size(), threads), resize_present(id, tds.slots(), threads);
  parallel_for(rank.size(), threads, 65536, [&](std::size_t from, std::size_t to) {
    for (std::size_t v = from; v < to; ++v) input[v] = d.input[rank[v]];
  });
  parallel_for(live.size(), threads, 65536, [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) id[static_cast<TriangleId>(live[k])] = static_cast<std::int32_t>(k);
  });
  SphericalTriangulation out;
  resize_present(out.triangles, 3 * live.size(), threads);
  resize_present(out.neighbors, 3 * live.size(), threads);
  parallel_for(live.size(), threads, 65536, [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) {
      const auto t = static_cast<TriangleId>(live[k]);
      const int first = least_corner(tds, t);
      for (int i = 0, c = first; i < 3; ++i, c = next3(c)) {
        out.triangles[3 * k + i] = input[tds.vertex(t, c)];
        out.neighbors[3 * k + i] = id[triangle_of(tds.link(t, c))];
      }
    }
  });
  for (VertexId v = 0; v < rank.size(); ++v)
    if (builder.hidden()[v]) out.hidden.push_back(input[v]);
  std::sort(out.hidden.begin(), out.hidden.end());
  out.duplicates = std::move(d.duplicates);
  return out;
}

}  // namespace
}  // namespace detail

SphericalTriangulation triangulate_sphere(std::span<const Point3> points, unsigned threads) {
  using namespace detail;
  threads = thread_count(threads);
  Distinct d = distinct_points(points, threads);
  Builder builder(d.points, threads);
  builder.run();
  const Tds& tds = builder.tds();
  // The triangles in the curve's order of their least corner: a point's triangles then lie close
  // together in the arrays, and a walk round each (its Voronoi cell) stays in the cache. (Free
  // slots sort last, and are cut off.)
  const std::vector<std::uint32_t>& key = builder.key();
  const TriangleId slots = tds.slots();
  std::vector<std::uint64_t> words, live;  // (key << 32 | slot), then sorted
  resize_present(words, slots, threads), resize_present(live, slots, threads);
  parallel_for(slots, threads, 65536, [&](std::size_t from, std::size_t to) {
    for (std::size_t t = from; t < to; ++t) {
      const VertexId* c = tds.corners(static_cast<TriangleId>(t));
      const std::uint32_t least = c[0] == kNoVertex ? kFreeSlot : std::min({key[c[0]], key[c[1]], key[c[2]]});
      words[t] = std::uint64_t{least} << 32 | t;
    }
  });
  sort_by_key(words.data(), live.data(), slots, threads);
  live.erase(std::lower_bound(live.begin(), live.end(), std::uint64_t{kFreeSlot} << 32), live.end());
  in_own_order(tds, live, threads);
  return written(tds, live, builder, d, threads);
}

}  // namespace ridt
