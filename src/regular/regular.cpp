// The regular triangulation (ridt/regular.hpp): randomized incremental insertion on the one
// mutable triangulation (tds/tds.hpp), closed by a vertex at infinity.
//
// Lifted, the weighted points are points in space and the regular triangulation the lower
// hull of theirs; add a point infinitely far above and the hull is closed: the lower faces,
// and a vertical "wall" (p, q, infinity) over each edge of the convex hull. The structure holds
// exactly that closed surface, as the sphere's (sphere/sphere.cpp) holds its hull: every
// triangle has three neighbours, and a point is inserted by replacing the faces its lift sees
// (the cavity) by the fan of faces round their boundary. A finite face sees the point where the
// power test puts its lift below the face's plane (perturbed: never on it); a wall sees it
// where it lies beyond the hull edge, or on the edge's line with its lift below the edge's
// (then the wall answers as the finite face beside it, whose plane holds that edge: so no
// horizon edge has the point on its line, and no new face is flat). A point whose lift lies
// above the triangle that holds it is hidden; one whose lift hides vertices surrounds them
// with its cavity (the traversal meets a face twice): they are made hidden and their faces
// dropped (cover).
//
// Points are located by a visibility walk over the finite faces (which cannot cycle in a
// regular triangulation: Edelsbrunner's acyclicity theorem), stopped where it would enter a
// wall: the point lies beyond that hull edge.
#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <random>
#include <string>

#include "order/order.hpp"
#include "predicates/power.hpp"
#include "predicates/predicates.hpp"
#include "ridt/regular.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"
#include "tds/delaunay.hpp"
#include "tds/tds.hpp"

namespace ridt {
namespace detail {
namespace {

// The distinct weighted points in weighted_less order (their ranks), the input index of each,
// and the copies dropped.
struct Distinct {
  std::vector<Weighted> points;
  std::vector<VertexId> input;
  std::vector<Duplicate> duplicates;
};

Distinct distinct_points(std::span<const Point> points, std::span<const double> weights, unsigned threads) {
  if (points.size() >= kMaxSlotPoints) throw InputError("triangulate_regular: too many points");
  if (weights.size() != points.size())
    throw InputError("triangulate_regular: " + std::to_string(weights.size()) + " weights for " +
                     std::to_string(points.size()) + " points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
      throw InputError("triangulate_regular: point " + std::to_string(i) + " is not finite");
    if (!std::isfinite(weights[i]))
      throw InputError("triangulate_regular: the weight of point " + std::to_string(i) + " is not finite");
  }
  struct Indexed {
    Weighted p;
    VertexId i;
  };
  std::vector<Indexed> sorted(points.size());
  parallel_for(points.size(), threads, 65536, [&](std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) sorted[i] = {{points[i], weights[i]}, static_cast<VertexId>(i)};
  });
  parallel_sort(sorted.begin(), sorted.end(), threads, [](const Indexed& a, const Indexed& b) {
    return weighted_less(a.p, b.p) || (a.p == b.p && a.i < b.i);
  });
  Distinct d;
  d.points.reserve(points.size()), d.input.reserve(points.size());
  for (const Indexed& e : sorted) {
    if (!d.input.empty() && d.points.back() == e.p) {
      d.duplicates.push_back({e.i, d.input.back()});
      continue;
    }
    d.input.push_back(e.i);
    d.points.push_back(e.p);
  }
  std::sort(d.duplicates.begin(), d.duplicates.end(),
            [](const Duplicate& a, const Duplicate& b) { return a.dropped < b.dropped; });
  return d;
}

class Builder {
 public:
  Builder(const std::vector<Weighted>& p, unsigned threads)
      : p_(p), n_(static_cast<VertexId>(p.size())), infinite_(n_), threads_(threads) {}

  // Vertex ids are places in the insertion order (the first triangle's three first), so that
  // points inserted one after another lie together in memory; rank_ maps them back, and the
  // vertex at infinity is n_.
  void run() {
    hidden_.assign(n_, 0);
    const std::array<VertexId, 3> first = first_triangle();
    const std::vector<VertexId> order = insertion_order(first);
    rank_.assign(first.begin(), first.end());
    rank_.insert(rank_.end(), order.begin(), order.end());
    q_.resize(n_);
    for (VertexId v = 0; v < n_; ++v) q_[v] = p_[rank_[v]];
    start();
    for (VertexId v = 3; v < n_; ++v) insert(v);
  }

  const Tds& tds() const { return tds_; }
  VertexId infinite() const { return infinite_; }
  const std::vector<VertexId>& rank() const { return rank_; }
  const std::vector<std::uint8_t>& hidden() const { return hidden_; }
  const std::vector<std::uint32_t>& curve() const { return curve_; }

 private:
  // Three points far from collinear: the first, the farthest from it, the farthest from their
  // line (scored in double precision on the points scaled by a power of two, confirmed exactly;
  // found by an exact search where the scores miss).
  std::array<VertexId, 3> first_triangle() const {
    if (n_ < 3) throw InputError("triangulate_regular: fewer than three distinct points");
    double largest = 0;
    for (const Weighted& q : p_) largest = std::max({largest, std::fabs(q.p.x), std::fabs(q.p.y)});
    const int e = largest > 0 ? std::ilogb(largest) : 0;
    auto at = [&](VertexId v) { return Point{std::ldexp(p_[v].p.x, -e), std::ldexp(p_[v].p.y, -e)}; };
    auto best = [&](auto&& score) {
      VertexId arg = 0;
      double top = -1;
      for (VertexId v = 0; v < n_; ++v)
        if (const double s = score(v); s > top) top = s, arg = v;
      return arg;
    };
    const VertexId a = 0;
    const Point pa = at(a);
    const VertexId b = best([&](VertexId v) { return std::hypot(at(v).x - pa.x, at(v).y - pa.y); });
    const Point pb = at(b);
    VertexId c = best(
        [&](VertexId v) { return std::fabs((pb.x - pa.x) * (at(v).y - pa.y) - (pb.y - pa.y) * (at(v).x - pa.x)); });
    if (orient2d(p_[a].p, p_[b].p, p_[c].p) == 0) {
      c = n_;
      for (VertexId v = 0; v < n_ && c == n_; ++v)
        if (orient2d(p_[a].p, p_[b].p, p_[v].p) != 0) c = v;
      if (c == n_)
        throw InputError(p_[a].p == p_[b].p ? "triangulate_regular: fewer than three distinct points"
                                            : "triangulate_regular: all points are collinear");
    }
    return orient2d(p_[a].p, p_[b].p, p_[c].p) > 0 ? std::array{a, b, c} : std::array{a, c, b};
  }

  // The first triangle (0, 1, 2) and its three walls, linked, in arrays with room for every
  // face of n points (at most 2n - 2; a fan takes its cavity's slots and two more, freed ones
  // first).
  void start() {
    const VertexId inf = infinite_;
    const VertexId faces[4][3] = {{0, 1, 2}, {1, 0, inf}, {2, 1, inf}, {0, 2, inf}};
    SlotArrays arrays(n_, threads_);
    for (int f = 0; f < 4; ++f)
      for (int i = 0; i < 3; ++i) arrays.v[3 * f + i] = faces[f][i];
    for (int f = 0; f < 4; ++f)
      for (int i = 0; i < 3; ++i)
        for (int g = 0; g < 4; ++g)
          for (int j = 0; j < 3; ++j)
            if (faces[g][next3(j)] == faces[f][prev3(i)] && faces[g][prev3(j)] == faces[f][next3(i)])
              arrays.link[3 * f + i] = static_cast<Link>(3 * g + j);
    tds_ = Tds(std::move(arrays.v), std::move(arrays.link), 4);
    stamp_.assign(2 * std::size_t{n_} + 2, 0);
  }

  // The points but the first three: a random permutation (seeded: the same every run) in rounds
  // of doubling size, each round along a Hilbert curve over the points' bounding square.
  std::vector<VertexId> insertion_order(const std::array<VertexId, 3>& first) {
    std::vector<Point> where(n_);
    for (VertexId v = 0; v < n_; ++v) where[v] = p_[v].p;
    curve_ = hilbert_keys(where.data(), n_, threads_);
    std::vector<VertexId> order;
    order.reserve(n_);
    for (VertexId v = 0; v < n_; ++v)
      if (std::find(first.begin(), first.end(), v) == first.end()) order.push_back(v);
    std::mt19937_64 random(0x5eed);
    std::shuffle(order.begin(), order.end(), random);
    std::vector<std::pair<std::uint32_t, VertexId>> keyed(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) keyed[i] = {curve_[order[i]], order[i]};
    std::size_t end = keyed.size();
    while (end > 0) {
      const std::size_t begin = end > 64 ? end / 2 : 0;
      parallel_sort(keyed.begin() + static_cast<std::ptrdiff_t>(begin),
                    keyed.begin() + static_cast<std::ptrdiff_t>(end), threads_, std::less<>());
      end = begin;
    }
    for (std::size_t i = 0; i < keyed.size(); ++i) order[i] = keyed[i].second;
    return order;
  }

  // The corner of face w that is the vertex at infinity, or -1.
  int infinite_corner(const VertexId* w) const {
    return w[0] == infinite_ ? 0 : w[1] == infinite_ ? 1 : w[2] == infinite_ ? 2 : -1;
  }
  bool power_sees(VertexId a, VertexId b, VertexId c, VertexId v) const {
    return power_sos(q_[a], q_[b], q_[c], q_[v], rank_[a], rank_[b], rank_[c], rank_[v]) > 0;
  }
  // Whether face w (a slot's corners) sees point v: see the file's comment.
  bool sees(const VertexId* w, VertexId v) const {
    const int k = infinite_corner(w);
    if (k < 0) return power_sees(w[0], w[1], w[2], v);
    const VertexId p = w[next3(k)], q = w[prev3(k)];
    const int o = orient2d(q_[p].p, q_[q].p, q_[v].p);
    if (o != 0) return o > 0;
    const auto t = static_cast<TriangleId>((w - tds_.corners(0)) / 3);
    return power_sees(q, p, tds_.opposite(tds_.link(t, k)), v);
  }

  // Where v lies: a finite face whose closure holds it (outside = false), or a wall beyond whose
  // edge it lies (outside = true). A walk from last_; where it goes on too long (it cannot in a
  // regular triangulation, but the perturbation's is the one it is proven for), every face.
  TriangleId locate(VertexId v, bool& outside) {
    TriangleId t = last_;
    if (const int k = infinite_corner(tds_.corners(t)); k >= 0) t = triangle_of(tds_.link(t, k));
    const Point q = q_[v].p;
    std::size_t steps = 0;
    const std::size_t limit = 256 + 4 * static_cast<std::size_t>(std::sqrt(static_cast<double>(tds_.slots())));
    bool wall = false;
    const Walked w = tds_.walk(
        t, [&](VertexId a, VertexId b) { return orient2d(q_[a].p, q_[b].p, q); },
        [&](Link l) {
          wall = infinite_corner(tds_.corners(triangle_of(l))) >= 0;
          return !wall && ++steps < limit ? Step::Cross : Step::Stop;
        });
    outside = !w && wall;
    if (w) return t;
    if (wall) return triangle_of(tds_.link(t, w.edge));
    for (TriangleId u = 0; u < tds_.slots(); ++u) {
      const VertexId* c = tds_.corners(u);
      if (c[0] == kNoVertex || infinite_corner(c) >= 0) continue;
      if (orient2d(q_[c[0]].p, q_[c[1]].p, q) >= 0 && orient2d(q_[c[1]].p, q_[c[2]].p, q) >= 0 &&
          orient2d(q_[c[2]].p, q_[c[0]].p, q) >= 0)
        return u;
    }
    for (TriangleId u = 0; u < tds_.slots(); ++u)
      if (const VertexId* c = tds_.corners(u); c[0] != kNoVertex && infinite_corner(c) >= 0 && sees(c, v))
        return outside = true, u;
    return last_;  // unreachable: the faces cover the plane
  }

  void insert(VertexId v) {
    bool outside = false;
    const TriangleId t = locate(v, outside);
    if (!outside && !sees(tds_.corners(t), v)) {
      hidden_[v] = 1;
      return;
    }
    ++epoch_;
    stamp_[t] = epoch_;
    tds_.find_cavity(
        t, scratch_, [&](const VertexId* w) { return sees(w, v); }, Tds::kAnywhere, Tds::kNoWall,
        [&](TriangleId u, const TriangleId*, std::size_t) {
          if (stamp_[u] == epoch_) return true;
          stamp_[u] = epoch_;
          return false;
        });
    if (scratch_.revisited) cover();
    SlotPool pool;
    if (free_.size() >= 2) {
      pool.list = free_.data(), pool.listed = free_.size();
    } else {
      pool = tds_.fresh(2);
    }
    last_ = tds_.fill_cavity(v, scratch_, pool);
    free_.resize(pool.listed);
  }

  static VertexId key(VertexId v) { return v; }
  static VertexId key(const CavityScratch::Boundary& e) { return e.a; }

  // The faces v sees surround vertices (the traversal met one of them again): their boundary
  // found and ordered anew, the vertices inside made hidden, the slots beyond the fan's freed.
  void cover() {
    CavityScratch& s = scratch_;
    const std::size_t m = s.size;
    std::vector<CavityScratch::Boundary>& edges = edges_;
    edges.clear();
    std::vector<VertexId>& inside = inside_;
    inside.clear();
    for (std::size_t k = 0; k < m; ++k) {
      const TriangleId t = s.cavity[k];
      for (int i = 0; i < 3; ++i) {
        const Link l = tds_.link(t, i);
        inside.push_back(tds_.vertex(t, i));
        if (stamp_[triangle_of(l)] != epoch_) edges.push_back({tds_.vertex(t, next3(i)), l, link_to(t, i)});
      }
    }
    // Round the boundary: each edge a -> b is followed by the one from b.
    std::sort(edges.begin(), edges.end(), [](const auto& x, const auto& y) { return x.a < y.a; });
    s.make_room(edges.size() + 2);
    s.boundary[0] = edges[0];
    for (std::size_t k = 1; k < edges.size(); ++k) {
      const VertexId b = tds_.head(s.boundary[k - 1].inside);
      s.boundary[k] = *std::lower_bound(edges.begin(), edges.end(), b,
                                        [](const CavityScratch::Boundary& e, VertexId x) { return e.a < x; });
    }
    // (edges is sorted by a: a vertex of the cavity's faces not on its boundary is inside)
    for (const VertexId u : inside)
      if (u < n_ && !std::binary_search(edges.begin(), edges.end(), u, [](const auto& x, const auto& y) {
            return key(x) < key(y);
          }))
        hidden_[u] = 1;
    const std::size_t k = edges.size();
    for (std::size_t i = k - 2; i < m; ++i) {
      tds_.free_slot(s.cavity[i]);
      free_.push_back(s.cavity[i]);
    }
    s.size = k - 2, s.edges = k;
  }

  const std::vector<Weighted>& p_;  // by rank
  VertexId n_, infinite_;
  unsigned threads_;
  std::vector<Weighted> q_;  // by vertex id
  std::vector<VertexId> rank_;
  Tds tds_;
  TriangleId last_ = 0;
  CavityScratch scratch_;
  std::vector<TriangleId> free_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t epoch_ = 0;
  std::vector<std::uint8_t> hidden_;
  std::vector<CavityScratch::Boundary> edges_;
  std::vector<VertexId> inside_;
  std::vector<std::uint32_t> curve_;
};

// The hull, counter-clockwise from its lexicographically least vertex: each wall (p, q, inf)
// runs p -> q, so the hull runs q -> p.
std::vector<VertexId> hull_of(const Tds& tds, VertexId infinite, const std::vector<VertexId>& rank,
                              const std::vector<VertexId>& input) {
  std::vector<std::pair<VertexId, VertexId>> next;  // (q, p)
  for (TriangleId t = 0; t < tds.slots(); ++t)
    for (int k = 0; k < 3; ++k)
      if (tds.vertex(t, k) == infinite) next.emplace_back(tds.vertex(t, prev3(k)), tds.vertex(t, next3(k)));
  std::sort(next.begin(), next.end());
  VertexId from = next[0].first;
  for (const auto& e : next)
    if (rank[e.first] < rank[from]) from = e.first;
  std::vector<VertexId> hull;
  for (VertexId v = from; hull.size() < next.size();) {
    hull.push_back(input[rank[v]]);
    v = std::lower_bound(next.begin(), next.end(), std::make_pair(v, VertexId{0}))->second;
    if (v == from) break;
  }
  return hull;
}

}  // namespace
}  // namespace detail

RegularTriangulation triangulate_regular(std::span<const Point> points, std::span<const double> weights,
                                         unsigned threads) {
  using namespace detail;
  threads = thread_count(threads);
  Distinct d = distinct_points(points, weights, threads);
  Builder builder(d.points, threads);
  builder.run();
  const Tds& tds = builder.tds();
  const VertexId inf = builder.infinite();
  const std::vector<VertexId>& rank = builder.rank();
  // The finite faces in the curve's order of their least corner: a point's triangles lie close
  // together in the arrays.
  std::vector<std::pair<std::uint32_t, TriangleId>> live;
  live.reserve(tds.slots());
  const std::vector<std::uint32_t>& key = builder.curve();
  for (TriangleId t = 0; t < tds.slots(); ++t) {
    const VertexId* c = tds.corners(t);
    if (c[0] != kNoVertex && c[0] != inf && c[1] != inf && c[2] != inf)
      live.push_back({std::min({key[rank[c[0]]], key[rank[c[1]]], key[rank[c[2]]]}), t});
  }
  parallel_sort(live.begin(), live.end(), threads, std::less<>());
  RegularTriangulation out;
  std::vector<std::int32_t> id(tds.slots(), -1);
  for (std::size_t k = 0; k < live.size(); ++k) id[live[k].second] = static_cast<std::int32_t>(k);
  resize_present(out.triangles, 3 * live.size(), threads);
  resize_present(out.neighbors, 3 * live.size(), threads);
  parallel_for(live.size(), threads, 65536, [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k)
      for (int i = 0; i < 3; ++i) {
        out.triangles[3 * k + i] = d.input[rank[tds.vertex(live[k].second, i)]];
        out.neighbors[3 * k + i] = id[triangle_of(tds.link(live[k].second, i))];
      }
  });
  out.hull = hull_of(tds, inf, rank, d.input);
  for (VertexId v = 0; v < d.points.size(); ++v)
    if (builder.hidden()[v]) out.hidden.push_back(d.input[rank[v]]);
  std::sort(out.hidden.begin(), out.hidden.end());
  out.duplicates = std::move(d.duplicates);
  out.stats.threads = 1;
  out.stats.points = points.size();
  out.stats.distinct = d.points.size();
  out.stats.duplicates = out.duplicates.size();
  return out;
}

}  // namespace ridt
