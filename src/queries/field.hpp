// What every interpolation in a finished triangulation shares (queries/interpolate.cpp, queries/cubic.cpp):
// the field it reads (points, triangles, values), renumbered for cache locality when there are
// many queries, and the two ways of answering: queries located one by one (exact walks, on
// threads), or the nodes of a grid found by the triangles that hold them.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#include "order/order.hpp"
#include "predicates/predicates.hpp"
#include "queries/arrays.hpp"
#include "queries/near.hpp"
#include "ridt/interpolate.hpp"
#include "ridt/locate.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"
#include "tds/ids.hpp"

namespace ridt::detail {

inline constexpr std::size_t kGrain = 1 << 14;  // queries a thread takes at least

inline void check_values(const char* who, std::size_t n, const Values& values) {
  if (values.components == 0 || values.data.size() != n * values.components)
    throw InputError(std::string(who) + ": " + std::to_string(values.data.size()) + " values for " + std::to_string(n) +
                     " points of " + std::to_string(values.components) + " components");
}

// `out` holds `width` numbers for each of `count` answers (`what`: queries, nodes).
inline void check_room(const char* who, std::span<const double> out, std::size_t count, const char* what,
                       std::size_t width) {
  if (out.size() != count * width)
    throw InputError(std::string(who) + ": room for " + std::to_string(out.size()) + " numbers, not " +
                     std::to_string(count) + " " + what + " of " + std::to_string(width) + " components");
}

// Which triangles answer at the nodes of a grid: all of them, but for the DEM (its longest
// side).
struct EveryTriangle {
  bool operator()(std::size_t) const { return true; }
};

// What interpolation reads: the points, the triangulation, the values (`components` numbers a
// point: for the cubic, the values and then their gradients).
struct Field {
  std::span<const Point> points;
  std::span<const VertexId> triangles;
  std::span<const std::int32_t> neighbors;
  Values values;
  bool from_least = false;  // every triangle stored from its least point (Renumbered's)

  const Point& corner(std::size_t tri, int i) const { return points[triangles[3 * tri + i]]; }
  VertexId vertex(std::size_t tri, int i) const { return triangles[3 * tri + i]; }
  std::int32_t neighbor(std::size_t tri, int i) const { return neighbors[3 * tri + i]; }
  const double* value(VertexId v) const { return values.data.data() + v * values.components; }

  // The corner every answer reads triangle tri from: its least point (x, then y). Weights and
  // corners in this rotation make the answers a function of the triangles as a set of
  // points: the same bits whatever corner a triangle is stored from, wherever it lies in the
  // array (which a threaded triangulation's run decides) and however the points are numbered.
  // Inlined (a call per triangle costs more than the comparisons), without branches (which
  // way each comparison goes is a coin's toss).
  [[gnu::always_inline]] int first(std::size_t tri) const {
    return from_least ? 0 : least(corner(tri, 0), corner(tri, 1), corner(tri, 2));
  }
  // Which of three distinct points is the least.
  [[gnu::always_inline]] static int least(const Point& a, const Point& b, const Point& c) {
    const int ab = (a.x < b.x) | ((a.x == b.x) & (a.y < b.y)), ac = (a.x < c.x) | ((a.x == c.x) & (a.y < c.y)),
              bc = (b.x < c.x) | ((b.x == c.x) & (b.y < c.y));
    return ab & ac ? 0 : (1 - ab) & bc ? 1 : 2;
  }
  // Of two triangles with a common side, the one that answers at a point on it: the one whose
  // corner across from it is the lesser point, or the one `eligible` takes. `side` is tri's
  // stored corner across from it.
  template <class Eligible = EveryTriangle>
  bool answers_on_side(std::size_t tri, int side, const Eligible& eligible = {}) const {
    const std::int32_t u = neighbor(tri, side);
    if (u < 0 || !eligible(static_cast<std::size_t>(u))) return true;
    const auto other = static_cast<std::size_t>(u);
    const VertexId a = vertex(tri, next3(side)), b = vertex(tri, prev3(side));
    for (int i = 0; i < 3; ++i)
      if (const VertexId w = vertex(other, i); w != a && w != b) return lex_less(corner(tri, side), points[w]);
    return true;  // not reached: a neighbour has a third corner
  }

  // out = the barycentric interpolant of triangle tri at q, its weights within 2^-44 of the
  // exact ones (barycentric from first(tri), or `weights` when the caller has them so): at a
  // corner the corner's value, on a side the side's linear interpolant, bounded for the
  // thinnest sliver. `from`: first(tri) where the caller has it, else -1.
  [[gnu::always_inline]] void linear(std::size_t tri, const Point& q, double* out, const double* weights = nullptr,
                                     int from = -1) const {
    const int s = from >= 0 ? from : first(tri);
    const VertexId v[3] = {vertex(tri, s), vertex(tri, next3(s)), vertex(tri, prev3(s))};
    double w[3];
    if (weights != nullptr)
      std::copy_n(weights, 3, w);
    else
      barycentric(points[v[0]], points[v[1]], points[v[2]], q, w);
    const double *va = value(v[0]), *vb = value(v[1]), *vc = value(v[2]);
    for (int i = 0; i < 3; ++i)
      if (w[i] == 1) {  // at a corner: its values themselves (whatever the others', infinite or -0)
        std::copy_n(value(v[i]), values.components, out);
        return;
      }
    for (std::size_t k = 0; k < values.components; ++k) out[k] = w[0] * va[k] + w[1] * vb[k] + w[2] * vc[k];
  }
};

// The field renumbered for many queries: the points along the Hilbert curve, their points and
// values copied in that order, and the triangles sorted by their least point's new number (the
// point they are read from, Field::first, stored first, neighbours turned and renumbered with
// them). The caller's points and values come in its order, often a random one, and a threaded
// triangulation's triangles in the order its run made them, so that a triangle's neighbours
// and corners lie anywhere in memory. Renumbered, walks, sweeps and answers read points,
// values and triangles near in memory instead of missing the cache at every corner, which
// more than pays for the copy once there are about as many queries as triangles. Every step
// on threads.
struct Renumbered {
  std::size_t count, components, triangle_count;
  std::vector<VertexId> input;  // number -> the caller's
  Block<Point> points;
  Block<double> values;
  Block<VertexId> triangles;
  Block<std::int32_t> neighbors;

  Renumbered(const Field& f, unsigned threads)
      : count(f.points.size()),
        components(f.values.components),
        triangle_count(f.triangles.size() / 3),
        input(hilbert_cells_order(f.points.data(), static_cast<std::uint32_t>(count), threads)) {
    const Block<VertexId> id = allocate_huge<VertexId>(count);
    copy_points(f.points, f.values, threads, id.get());
    take_triangles(f, id.get(), threads);
  }

  // The points' own Delaunay triangulation (with `options`, on its threads), made in the new
  // numbering: the points and values copied along the curve first and triangulated there, so
  // that no number is mapped and the triangulation's arrays, once sorted, are given back before
  // the caller's next blocks (the same field as triangulating first and renumbering: the
  // triangulation does not depend on the numbering, and equal points keep their input order,
  // the least input number standing for them).
  Renumbered(std::span<const Point> caller_points, Values caller_values, const Options& options)
      : count(caller_points.size()),
        components(caller_values.components),
        triangle_count(0),
        input(hilbert_cells_order(caller_points.data(), static_cast<std::uint32_t>(count), options.threads)) {
    const unsigned threads = options.threads;
    copy_points(caller_points, caller_values, threads, nullptr);
    Triangulation t = triangulate(std::span<const Point>(points_view()), options);
    triangle_count = t.size();
    take_triangles({points_view(), t.triangles, t.neighbors, {{values.get(), count * components}, components}}, nullptr,
                   threads);
  }

  // The renumbered field; with `other`, other values (`other_components` a point, in the
  // new numbering) in place of the caller's.
  Field field(std::span<const double> other = {}, std::size_t other_components = 0) const {
    const Values v =
        other.empty() ? Values{{values.get(), count * components}, components} : Values{other, other_components};
    const std::size_t corners = 3 * triangle_count;
    return {{points.get(), count}, {triangles.get(), corners}, {neighbors.get(), corners}, v, true};
  }

 private:
  std::span<const Point> points_view() const { return {points.get(), count}; }

  // The points and values copied in the new order; `id`, when given, each input number's new one.
  void copy_points(std::span<const Point> from, Values from_values, unsigned threads, VertexId* id) {
    points = allocate_huge<Point>(count);
    values = allocate_huge<double>(count * components);
    const std::size_t m = components;
    parallel_for(count, threads, kGrain, [&](std::size_t first, std::size_t last) {
      for (std::size_t k = first; k < last; ++k) {
        if (id != nullptr) id[input[k]] = static_cast<VertexId>(k);
        points[k] = from[input[k]];
        std::copy_n(&from_values.data[input[k] * m], m, &values[k * m]);
      }
    });
  }

  // f's triangles (its points numbered `id`, or already in the new numbering where id is null)
  // sorted by their least point's new number, each stored from that point.
  void take_triangles(const Field& f, const VertexId* id, unsigned threads) {
    const std::size_t t = triangle_count;
    triangles = allocate_huge<VertexId>(3 * t);
    neighbors = allocate_huge<std::int32_t>(3 * t);
    auto renumber = [id](VertexId v) { return id != nullptr ? id[v] : v; };
    // Each triangle's first corner, found among the copied points (near one another in memory),
    // and that corner's new number: the key the triangles are sorted by. `place` then becomes
    // each triangle's new place, which its neighbours are renumbered to.
    const Block<std::uint32_t> place = allocate_huge<std::uint32_t>(t);
    const Block<std::uint8_t> turn = allocate_huge<std::uint8_t>(t);
    parallel_for(t, threads, kGrain, [&](std::size_t first, std::size_t last) {
      for (std::size_t k = first; k < last; ++k) {
        const VertexId v[3] = {renumber(f.vertex(k, 0)), renumber(f.vertex(k, 1)), renumber(f.vertex(k, 2))};
        const int s = Field::least(points[v[0]], points[v[1]], points[v[2]]);
        place[k] = v[s];
        turn[k] = static_cast<std::uint8_t>(s);
      }
    });
    places_by_key(place.get(), t, count, threads);
    parallel_for(t, threads, kGrain, [&](std::size_t first, std::size_t last) {
      for (std::size_t k = first; k < last; ++k) {
        const std::size_t to = place[k];
        const int s = turn[k];
        for (int i = 0; i < 3; ++i) {
          triangles[3 * to + i] = renumber(f.vertex(k, (s + i) % 3));
          const std::int32_t u = f.neighbor(k, (s + i) % 3);
          neighbors[3 * to + i] = u < 0 ? u : static_cast<std::int32_t>(place[static_cast<std::size_t>(u)]);
        }
      }
    });
  }
};

// What both kinds of call read, checked: the field, renumbered when there are about as many
// answers (`count` of `what`, queries or nodes) as triangles.
class Input {
 public:
  Input(const char* who, std::span<const Point> points, const Triangulation& t, Values values, std::size_t width,
        std::size_t count, const char* what, std::span<double> out, unsigned threads)
      : field_{points, t.triangles, t.neighbors, values} {
    check_arrays(who, points.size(), t.triangles, t.neighbors);
    check_values(who, points.size(), values);
    check_room(who, out, count, what, width);
    if (count >= t.size()) {
      renumbered_.emplace(field_, threads);
      field_ = renumbered_->field();
    }
  }
  Input(const Input&) = delete;
  Input& operator=(const Input&) = delete;

  const Field& field() const { return field_; }

 private:
  Field field_;
  std::optional<Renumbered> renumbered_;
};

// The triangle that answers at q, which triangle tri holds (as the walk found it): the other
// one across a side that q lies on where answers_on_side gives it that side, so that the
// answer is the same whichever of the two the walk reached. A q outside the hull that a
// tolerance gave tri stays with tri, the triangle it is near.
inline std::size_t settled(const Field& f, std::size_t tri, const Point& q) {
  const Point &a = f.corner(tri, 0), &b = f.corner(tri, 1), &c = f.corner(tri, 2);
  const int o[3] = {orient2d(b, c, q), orient2d(c, a, q), orient2d(a, b, q)};
  if (o[0] < 0 || o[1] < 0 || o[2] < 0) return tri;
  if ((o[0] == 0) + (o[1] == 0) + (o[2] == 0) != 1) return tri;  // inside, or at a corner (its value)
  const int side = o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2;
  return f.answers_on_side(tri, side) ? tri : static_cast<std::size_t>(f.neighbor(tri, side));
}

// Answers each query with Answer, a class built on each thread from the field (so that its
// scratch space is reused between queries) whose operator()(tri, q, out) writes `width`
// numbers for q in triangle tri; `fill` outside the hull, but for a query that
// `hull_tolerance` gives a hull triangle (ridt/locate.hpp's tolerance): Answer then
// extrapolates from that triangle, its q just outside.
template <class Answer>
void interpolate(const char* who, std::span<const Point> points, const Triangulation& t, Values values,
                 std::size_t width, std::span<const Point> queries, std::span<double> out, double fill,
                 unsigned threads, double hull_tolerance = 0) {
  const Input input(who, points, t, values, width, queries.size(), "queries", out, threads);
  const Field& field = input.field();
  std::vector<std::int32_t> where(queries.size());
  locate(field.points, field.triangles, field.neighbors, queries, where, threads, hull_tolerance);
  parallel_for(queries.size(), threads, kGrain, [&](std::size_t first, std::size_t last) {
    Answer answer(field);
    for (std::size_t k = first; k < last; ++k) {
      if (where[k] >= 0)
        answer(settled(field, static_cast<std::size_t>(where[k]), queries[k]), queries[k], &out[k * width]);
      else
        std::fill_n(&out[k * width], width, fill);
    }
  });
}

class Axis {
 public:
  Axis(const char* who, const char* name, std::span<const double> v) : v_(v), n_(v.size()) {
    bool up = true, down = true;
    for (std::size_t k = 0; k < n_; ++k) {
      if (!std::isfinite(v[k]))
        throw InputError(std::string(who) + ": grid " + name + "[" + std::to_string(k) + "] is not finite");
      if (k > 0) up = up && v[k] > v[k - 1], down = down && v[k] < v[k - 1];
    }
    if (!up && !down)
      throw InputError(std::string(who) + ": the grid's " + name + " must be strictly increasing or decreasing");
    reversed_ = n_ > 1 && down;
    if (n_ > 1) lowest_ = value(0), per_step_ = static_cast<double>(n_ - 1) / (value(n_ - 1) - lowest_);
  }

  double value(std::size_t k) const { return v_[index(k)]; }
  std::size_t index(std::size_t k) const { return reversed_ ? n_ - 1 - k : k; }

  // The nodes with lo <= value <= hi: [first, last). A guess from the mean step, then steps to
  // the exact ends, so uneven axes are right too, only slower.
  std::pair<std::size_t, std::size_t> within(double lo, double hi) const {
    std::size_t first = guess(lo), last = guess(hi);
    while (first > 0 && value(first - 1) >= lo) --first;
    while (first < n_ && value(first) < lo) ++first;
    while (last < n_ && value(last) <= hi) ++last;
    while (last > first && value(last - 1) > hi) --last;
    return {first, std::max(first, last)};
  }

 private:
  std::size_t guess(double x) const {
    if (!(per_step_ > 0)) return 0;
    const double k = std::floor((x - lowest_) * per_step_);
    return k <= 0 ? 0 : k >= static_cast<double>(n_) ? n_ : static_cast<std::size_t>(k);
  }

  std::span<const double> v_;
  std::size_t n_;
  bool reversed_ = false;
  double lowest_ = 0, per_step_ = 0;  // nodes a unit, on average
};

// The lowest-numbered triangle that `eligible` takes around the vertex at corner i of triangle
// tri (which it takes).
template <class Eligible = EveryTriangle>
std::size_t lowest_around(const Field& f, std::size_t tri, int i, const Eligible& eligible = {}) {
  const VertexId v = f.vertex(tri, i);
  std::size_t lowest = tri;
  // Counter-clockwise (across the side v -> next, across from the previous corner), then, if
  // that reaches the hull, clockwise from tri.
  for (int turn = 0; turn < 2; ++turn) {
    std::size_t at = tri;
    int corner = i;
    for (std::size_t steps = 0; steps <= f.triangles.size(); ++steps) {
      const std::int32_t u = f.neighbor(at, turn == 0 ? prev3(corner) : next3(corner));
      if (u < 0) break;
      at = static_cast<std::size_t>(u);
      if (at == tri) return lowest;
      corner = f.vertex(at, 0) == v ? 0 : f.vertex(at, 1) == v ? 1 : 2;
      if (eligible(at)) lowest = std::min(lowest, at);
    }
  }
  return lowest;
}

// Calls take(tri, node, p, w, f.first(tri)) for every node p of `grid` that triangle tri holds
// and takes, where `eligible` takes tri: those strictly inside, those on a hull side, those on
// an inner side that answers_on_side gives it, and a vertex when tri is the lowest-numbered
// eligible triangle around it (at a vertex every triangle answers its value). So every node in
// the closed union of the eligible triangles is taken exactly once, by one triangle. w is p's
// barycentric weights from f.first(tri) where the filter already gave them (as barycentric
// would), else null.
template <class Take, class Eligible = EveryTriangle>
void cover_triangle(const Field& f, const Axis& ax, const Axis& ay, const Grid& grid, std::size_t tri, Take& take,
                    const Eligible& eligible = {}) {
  if (!eligible(tri)) return;
  const std::size_t nx = grid.x.size(), ny = grid.y.size();
  const int s = f.first(tri);
  const Point& a = f.corner(tri, s);
  const Point& b = f.corner(tri, next3(s));
  const Point& c = f.corner(tri, prev3(s));
  const auto [i0, i1] = ax.within(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}));
  if (i0 == i1) return;
  const auto [j0, j1] = ay.within(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}));
  const BoundedArea whole = bounded_area(a, b, c);
  for (std::size_t j = j0; j < j1; ++j) {
    const double y = ay.value(j);
    for (std::size_t i = i0; i < i1; ++i) {
      const Point p{ax.value(i), y};
      const std::size_t node = grid.x_major ? ax.index(i) * ny + ay.index(j) : ay.index(j) * nx + ax.index(i);
      // The signs of the areas with p in place of each corner, where the filter decides them:
      // all positive, p is strictly inside, and the areas give its barycentric weights when
      // they are precise enough.
      const BoundedArea part[3] = {bounded_area(p, b, c), bounded_area(a, p, c), bounded_area(a, b, p)};
      bool certain = true, outside = false;
      for (const BoundedArea& area : part) {
        if (std::fabs(area.value) > area.bound)
          outside = outside || area.value < 0;
        else
          certain = false;
      }
      if (outside) continue;
      if (certain) {
        double w[3];
        take(tri, node, p, barycentric_quick(whole, part, w) ? w : nullptr, s);
        continue;
      }
      const int o[3] = {orient2d(b, c, p), orient2d(c, a, p), orient2d(a, b, p)};
      if (o[0] < 0 || o[1] < 0 || o[2] < 0) continue;
      const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
      if (zeros == 1) {
        const int e = o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2;
        if (!f.answers_on_side(tri, (s + e) % 3, eligible)) continue;
      } else if (zeros == 2) {
        const int corner = o[0] != 0 ? 0 : o[1] != 0 ? 1 : 2;  // p is this vertex
        if (lowest_around(f, tri, (s + corner) % 3, eligible) != tri) continue;
      }
      take(tri, node, p, nullptr, s);
    }
  }
}

// cover_triangle for every triangle, with take = make_take() on each thread (its own scratch
// space): threads that take stretches of the triangles never write the same node.
template <class MakeTake>
void cover(const Field& f, const Axis& ax, const Axis& ay, const Grid& grid, unsigned threads, MakeTake&& make_take) {
  parallel_for(f.triangles.size() / 3, threads, kGrain, [&](std::size_t first, std::size_t last) {
    auto take = make_take();
    for (std::size_t tri = first; tri < last; ++tri) cover_triangle(f, ax, ay, grid, tri, take);
  });
}

// Calls take(tri, node, p, nullptr, f.first(tri)) for every node p of `grid` outside the hull
// that `near` gives a hull triangle tri: p strictly beyond a hull side of tri (so that cover
// took no triangle for it) and near tri, as location with that tolerance finds it. A node
// beside a hull corner, near two triangles, goes to the first in the triangles' order. One
// thread: the hull's triangles are few, and the nodes near them fewer.
template <class Take>
void cover_rim(const Field& f, const Axis& ax, const Axis& ay, const Grid& grid, const NearHull& near, Take& take) {
  const std::size_t nx = grid.x.size(), ny = grid.y.size();
  std::unordered_set<std::size_t> taken;
  for (std::size_t tri = 0; tri < f.triangles.size() / 3; ++tri) {
    int side = -1;
    for (int i = 0; i < 3; ++i)
      if (f.neighbor(tri, i) < 0) side = i;
    if (side < 0) continue;
    const int s = f.first(tri);
    const Point &a = f.corner(tri, 0), &b = f.corner(tri, 1), &c = f.corner(tri, 2);
    const double x0 = std::min({a.x, b.x, c.x}), x1 = std::max({a.x, b.x, c.x});
    const double y0 = std::min({a.y, b.y, c.y}), y1 = std::max({a.y, b.y, c.y});
    const auto [i0, i1] = ax.within(x0 - near.margin(x1 - x0), x1 + near.margin(x1 - x0));
    const auto [j0, j1] = ay.within(y0 - near.margin(y1 - y0), y1 + near.margin(y1 - y0));
    for (std::size_t j = j0; j < j1; ++j) {
      for (std::size_t i = i0; i < i1; ++i) {
        const Point p{ax.value(i), ay.value(j)};
        bool outside = false;
        for (int e = 0; e < 3; ++e)
          outside =
              outside || (f.neighbor(tri, e) < 0 && orient2d(f.corner(tri, next3(e)), f.corner(tri, prev3(e)), p) < 0);
        if (!outside || !near(a, b, c, p)) continue;
        const std::size_t node = grid.x_major ? ax.index(i) * ny + ay.index(j) : ay.index(j) * nx + ax.index(i);
        if (taken.insert(node).second) take(tri, node, p, nullptr, s);
      }
    }
  }
}

// Answer at every node of a grid (see cover), from a field already checked; `fill` outside
// the hull, but at a node that `hull_tolerance` gives a hull triangle (see cover_rim).
template <class Answer>
void answer_grid(const Field& field, const Axis& ax, const Axis& ay, const Grid& grid, std::size_t width,
                 std::span<double> out, double fill, unsigned threads, double hull_tolerance = 0) {
  parallel_for(out.size(), threads, kGrain, [&](std::size_t first, std::size_t last) {
    std::fill(out.begin() + static_cast<std::ptrdiff_t>(first), out.begin() + static_cast<std::ptrdiff_t>(last), fill);
  });
  auto make_take = [&] {
    return [&, answer = Answer(field)](std::size_t tri, std::size_t node, const Point& p, const double* w,
                                       int from) mutable { answer(tri, p, &out[node * width], w, from); };
  };
  cover(field, ax, ay, grid, threads, make_take);
  if (const NearHull near(field.points, hull_tolerance); near.active()) {
    auto take = make_take();
    cover_rim(field, ax, ay, grid, near, take);
  }
}

// The same from the caller's arrays, checked, and renumbered when there are many nodes.
template <class Answer>
void interpolate_grid(const char* who, std::span<const Point> points, const Triangulation& t, Values values,
                      std::size_t width, const Grid& grid, std::span<double> out, double fill, unsigned threads,
                      double hull_tolerance = 0) {
  const Axis ax(who, "x", grid.x), ay(who, "y", grid.y);
  const Input input(who, points, t, values, width, grid.size(), "nodes", out, threads);
  answer_grid<Answer>(input.field(), ax, ay, grid, width, out, fill, threads, hull_tolerance);
}

}  // namespace ridt::detail
