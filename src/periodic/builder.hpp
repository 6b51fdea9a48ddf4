// The periodic triangulation's builder (periodic/periodic.cpp): the Delaunay triangulation of
// some points and their copies near the domain, on the one mutable triangulation (tds/tds.hpp),
// and the triangles kept from it, one of each class of translates.
//
// A triangle of the copies' triangulation whose circle lies where the copies are complete (all
// copies there are in S) is empty of every copy, so it is a triangle of the periodic one. Of
// each class of translates one is kept: the one whose least corner (by input index, then
// offset) is a point as given (offset 0) — one of each class, since moving a triangle moves
// its least corner.
//
// Two uses. Whole: every point and the copies within a margin m of the domain; every circle kept
// must lie inside the domain grown by m, and their count be 2n (the torus's). Strip: the copies
// of some points within m of the line of one side of the domain (x = x0 or y = y0), along the
// whole side and m beyond its ends; kept is every triangle whose circle lies in the strip (where
// its copies are complete), moved so that its least corner is a point as given, unless its
// circle is inside the domain (`inside`: the caller has those).
//
// The predicates are those of the ordinary triangulation on the copies' true coordinates
// (predicates/shifted.hpp): the lexicographic order that keys the perturbation does not change
// when all points move together, so translates of a configuration get translated answers, and
// the kept triangles fit together.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "order/order.hpp"
#include "order/random.hpp"
#include "periodic/periodic.hpp"
#include "predicates/shifted.hpp"
#include "ridt/periodic.hpp"
#include "runtime/memory.hpp"
#include "runtime/parallel.hpp"
#include "tds/delaunay.hpp"
#include "tds/tds.hpp"

namespace ridt::detail {

/// Whether the circle of triangle (a, b, c) (points as given, exact) lies inside the domain,
/// clear of its sides by the rounding of the test. The same test decides for the Delaunay
/// triangles of the points and the strips' alike: the callers start a triangle at its corner
/// of least input index (a rotation: the answer does not depend on where a triangle starts,
/// and the output is written from that corner anyway).
///
/// Most triangles lie far from the sides, and for them a test without a division decides: the
/// circle lies within its diameter 2R of a, and (2R)^2 = |ab|^2 |ac|^2 |bc|^2 / det^2, so it is
/// inside where a is farther than that from every side; with room for the rounding of each
/// step (a relative 2^-40 on the lengths' product, the orientation filter's bound on det), and
/// only where no product can overflow or underflow. Else the circumcentre and radius decide.
inline bool circle_inside(const Point& a, const Point& b, const Point& c, const PeriodicDomain& d) {
  const double room = 4 * kEps * (std::max(std::fabs(d.origin.x), std::fabs(d.origin.y)) + d.width + d.height);
  const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y, ex = c.x - b.x, ey = c.y - b.y;
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy, e2 = ex * ex + ey * ey;
  const double l = bx * cy, r = by * cx, det = std::fabs(l - r) - 5 * kEps * (std::fabs(l) + std::fabs(r));
  const double side =
      std::min({a.x - d.origin.x, d.origin.x + d.width - a.x, a.y - d.origin.y, d.origin.y + d.height - a.y}) - room;
  constexpr double kLow = 0x1p-300, kHigh = 0x1p300;
  if (std::min({b2, c2, e2}) > kLow && std::max({b2, c2, e2}) < kHigh && side > 0x1p-150 && side < 0x1p150 &&
      det > 0x1p-600 && b2 * c2 * e2 * (1 + 0x1p-40) < side * side * det * det)
    return true;
  const Point o = circumcentre_bounded(a, b, c);
  auto squared = [](const Point& p, const Point& q) { return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y); };
  const double radius = (1 + 0x1p-30) * std::sqrt(std::max({squared(a, o), squared(b, o), squared(c, o)}));
  return o.x - radius > d.origin.x + room && o.x + radius < d.origin.x + d.width - room &&
      o.y - radius > d.origin.y + room && o.y + radius < d.origin.y + d.height - room;
}

// The least of a group of equal points: a union of input indices by their least.
VertexId root(std::vector<VertexId>& up, VertexId i) {
  while (up[i] != i) i = up[i] = up[up[i]];
  return i;
}

class Builder {
 public:
  /// The whole: every point; a strip: the points `subset` names.
  Builder(std::span<const Point> points, const PeriodicDomain& d, unsigned threads,
          std::span<const VertexId> subset = {})
      : points_(points), subset_(subset), d_(d), l_{d.width, d.height}, threads_(threads) {}

  // One attempt with margin m: true when the triangles kept are the whole periodic
  // triangulation; else `m` is what the next attempt should take.
  bool attempt(double& m) {
    copy({d_.origin.x - m, d_.origin.y - m}, {d_.origin.x + d_.width + m, d_.origin.y + d_.height + m}, m, true);
    insert_all();
    if (keep(m) && link() && (!verify_ || check_periodic(points_, d_, out_.triangles, out_.offsets).valid)) return true;
    if (!grown_) m *= 2;
    return false;
  }

  /// The strip of half-width m across the side x = x0 (`across_x`) or y = y0: its triangles in
  /// take()'s triangles and offsets (no neighbours), their least corner first at offset 0, and
  /// whether they want the exact validator in verify(). A triangle may come more than once.
  void strip(double m, bool across_x) {
    const Point o = d_.origin;
    const Point lo{o.x - m, o.y - m},
        hi{across_x ? o.x + m : o.x + d_.width + m, across_x ? o.y + d_.height + m : o.y + m};
    copy(lo, hi, m, false);
    insert_all();
    const double edge = 4 * kEps * (std::max(std::fabs(o.x), std::fabs(o.y)) + d_.width + d_.height + 2 * m);
    out_ = {}, verify_ = false;
    for (TriangleId t = 0; t < tds_.slots(); ++t) {
      const VertexId* c = tds_.corners(t);
      if (c[0] >= n_ || c[1] >= n_ || c[2] >= n_) continue;  // a free slot (kNoVertex) or bounding
      const Reach r = reach(c, lo, hi);
      if (!(r.bare < -edge)) continue;  // beyond the strip, or in doubt
      verify_ = verify_ || !(r.sure < -edge);
      const int low = least(c);
      check_reach(c, low);
      const Offset shift = make_offset(s_[c[low]].dx, s_[c[low]].dy);
      if (same_shift(s_[c[0]], s_[c[1]]) && same_shift(s_[c[0]], s_[c[2]]) &&
          circle_inside(s_[c[low]].p, s_[c[next3(low)]].p, s_[c[prev3(low)]].p, d_))
        continue;  // the caller's, from the points' triangulation
      for (int j = 0; j < 3; ++j) {
        const VertexId v = c[(low + j) % 3];
        out_.triangles.push_back(index(v)),
            out_.offsets.push_back(make_offset(s_[v].dx - shift.dx, s_[v].dy - shift.dy));
      }
    }
  }
  bool verify() const { return verify_; }

  PeriodicTriangulation take() {
    out_.domain = d_;
    if (duplicates_)
      for (VertexId i = 0; i < up_.size(); ++i)
        if (const VertexId r = root(up_, i); r != i) out_.duplicates.push_back({input_of(i), input_of(r)});
    return std::move(out_);
  }

 private:
  // S: every copy of the points that lies in [lo, hi] (by its rounded place: the circles kept
  // stay clear of the edge by more than that rounding), every point as given too where `given`,
  // then the three bounding vertices; vertex ids in a biased randomized order along the Hilbert
  // curve. [lo, hi] reaches at most m beyond the domain.
  void copy(Point lo, Point hi, double m, bool given) {
    const auto all = static_cast<VertexId>(subset_.empty() ? points_.size() : subset_.size());
    auto point = [&](VertexId k) { return subset_.empty() ? k : subset_[k]; };  // copy k < n's input index
    const auto kx = static_cast<std::int32_t>(std::ceil(m / d_.width)),
               ky = static_cast<std::int32_t>(std::ceil(m / d_.height));
    lo_ = lo, hi_ = hi;
    // Copy k < n is point k (of the subset) as given; the others follow.
    const VertexId n = given ? all : 0;
    std::vector<Shifted> more;
    std::vector<VertexId> of;
    for (VertexId k = 0; k < all; ++k)
      for (std::int32_t dy = -ky; dy <= ky; ++dy)
        for (std::int32_t dx = -kx; dx <= kx; ++dx) {
          const Shifted c{points_[point(k)], dx, dy};
          const Point q = rounded(c, l_);
          if ((dx != 0 || dy != 0 || !given) && q.x >= lo_.x && q.x <= hi_.x && q.y >= lo_.y && q.y <= hi_.y)
            more.push_back(c), of.push_back(point(k));
        }
    n_ = n + static_cast<VertexId>(more.size());
    std::vector<Point> at;
    resize_present(at, n_, threads_);
    for (VertexId k = 0; k < n; ++k) at[k] = points_[point(k)];
    for (std::size_t k = 0; k < more.size(); ++k) at[n + k] = rounded(more[k], l_);
    const std::vector<std::uint32_t> order = brio_order(at.data(), n_, 0x5eed, threads_);
    resize_present(s_, n_ + 3, threads_), resize_present(input_, n_, threads_);
    parallel_for(n_, threads_, 65536, [&](std::size_t from, std::size_t to) {
      for (std::size_t v = from; v < to; ++v) {
        const std::uint32_t k = order[v];
        s_[v] = k < n ? Shifted{points_[point(k)], 0, 0} : more[k - n];
        input_[v] = k < n ? point(k) : of[k - n];
      }
    });
    // Far outside: every circle through one of them reaches beyond the margin, so no triangle
    // with one is kept, and none kept is changed by them.
    const double r = 8 * (std::max(d_.width, d_.height) + m);
    const Point c{d_.origin.x + d_.width / 2, d_.origin.y + d_.height / 2};
    s_[n_] = {{c.x - r, c.y - r}, 0, 0};
    s_[n_ + 1] = {{c.x + 2 * r, c.y - r}, 0, 0};
    s_[n_ + 2] = {{c.x - r, c.y + 2 * r}, 0, 0};
  }

  int orient(VertexId a, VertexId b, VertexId c) const { return orient_shifted(s_[a], s_[b], s_[c], l_); }
  bool in_circle(const VertexId* w, VertexId p) const {
    return incircle_shifted(s_[w[0]], s_[w[1]], s_[w[2]], s_[p], l_) > 0;
  }

  // Bowyer-Watson insertion of every vertex in id order, walking from the last fan. A copy at a
  // vertex's place (the same point given twice: copies with the same offset) is left out and
  // its input joined to the vertex's.
  void insert_all() {
    SlotArrays arrays(n_, threads_);
    arrays.v[0] = n_, arrays.v[1] = n_ + 1, arrays.v[2] = n_ + 2;
    arrays.link[0] = arrays.link[1] = arrays.link[2] = kNoLink;
    tds_ = Tds(std::move(arrays.v), std::move(arrays.link), 1);
    // (by place among the points copied: a strip's few, not every point's)
    const std::size_t places = subset_.empty() ? points_.size() : subset_.size();
    up_.resize(places);
    given_.assign(places, kNoVertex);
    duplicates_ = false;
    std::iota(up_.begin(), up_.end(), VertexId{0});
    TriangleId last = 0;
    CavityScratch scratch;
    for (VertexId v = 0; v < n_; ++v) {
      tds_.walk(
          last, [&](VertexId a, VertexId b) { return orient(a, b, v); }, Tds::kAnywhere);
      bool equal = false;
      VertexId kept = kNoVertex;
      for (int i = 0; i < 3 && !equal; ++i) {
        const VertexId w = tds_.vertex(last, i);
        if (w < n_ && same_shift(s_[w], s_[v]) && s_[w].p == s_[v].p) {
          kept = w;
          const VertexId a = root(up_, place(input_[w])), b = root(up_, place(input_[v]));
          up_[std::max(a, b)] = std::min(a, b);
          equal = duplicates_ = true;
        }
      }
      if (s_[v].dx == 0 && s_[v].dy == 0) given_[place(input_[v])] = equal ? kept : v;
      if (equal) continue;
      tds_.find_cavity(
          last, scratch, [&](const VertexId* w) { return in_circle(w, v); }, Tds::kAnywhere, Tds::kNoWall,
          Tds::kNotSeen);
      SlotPool pool = tds_.fresh(2);
      last = tds_.fill_cavity(v, scratch, pool);
    }
  }

  // The triangles whose least corner is a point as given, in their slots' order (the fans of
  // successive insertions, near each other), that corner first; false (and the next margin in
  // m) when a circle reaches too far or their count is not 2n.
  bool keep(double& m) {
    // Where a copy near the margin's edge is taken or left by its rounded place: two units in
    // the last place of the largest coordinate.
    const double edge =
        4 * kEps * (std::max(std::fabs(d_.origin.x), std::fabs(d_.origin.y)) + d_.width + d_.height + 2 * m);
    Reach need{0, 0};
    grown_ = verify_ = false;
    id_.clear(), around_.clear();
    resize_present(id_, tds_.slots(), threads_), resize_present(around_, n_, threads_);
    std::fill(around_.begin(), around_.end(), kNoTriangle);
    slot_.clear(), first_.clear();
    const Point end{d_.origin.x + d_.width, d_.origin.y + d_.height};
    for (TriangleId t = 0; t < tds_.slots(); ++t) {
      const VertexId* c = tds_.corners(t);
      id_[t] = -1;
      if (c[0] >= n_ || c[1] >= n_ || c[2] >= n_) continue;  // a free slot (kNoVertex) or bounding
      around_[c[0]] = around_[c[1]] = around_[c[2]] = t;
      const int low = least(c);
      if (s_[c[low]].dx != 0 || s_[c[low]].dy != 0) continue;
      check_reach(c, low);
      const Reach r = reach(c, d_.origin, end);
      need = {std::max(need.bare, r.bare + edge), std::max(need.sure, r.sure + edge)};
      id_[t] = static_cast<std::int32_t>(slot_.size());
      slot_.push_back(t), first_.push_back(static_cast<std::uint8_t>(low));
    }
    std::size_t distinct = 0;
    for (VertexId i = 0; i < up_.size(); ++i) distinct += root(up_, i) == i;
    if (need.bare <= m && slot_.size() > 2 * distinct)
      throw std::logic_error("ridt: periodic triangulation: more triangles than the torus holds");
    if (need.sure <= m && slot_.size() == 2 * distinct) return true;
    // Circles whose rounding alone leaves them in doubt (slivers with corners at copies whose
    // coordinates are no doubles): the result is checked exactly instead of the margin grown.
    if (need.bare <= m && slot_.size() == 2 * distinct) return verify_ = true;
    m = std::max(2 * m, 1.25 * need.bare);
    return !(grown_ = true);
  }

  // How far beyond the rectangle [lo, hi] a triangle's circle reaches: as computed (bare), and with
  // room for the rounding of the corners at copies (sure). A corner moved by delta moves the
  // centre by up to some delta R / h (circumradius over the corner's height; first order, with
  // a factor 2 to spare); a corner at a point as given is exact.
  struct Reach {
    double bare, sure;
  };
  Reach reach(const VertexId* c, Point lo, Point hi) const {
    Point p[3];
    for (int i = 0; i < 3; ++i) p[i] = rounded(s_[c[i]], l_);
    const Point o = circumcentre_bounded(p[0], p[1], p[2]);
    auto squared = [](const Point& a, const Point& b) { return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y); };
    const double r = (1 + 0x1p-30) * std::sqrt(std::max({squared(p[0], o), squared(p[1], o), squared(p[2], o)}));
    const double twice_area = std::fabs((p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x));
    double slack = 0;
    for (int i = 0; i < 3; ++i) {
      const Shifted& q = s_[c[i]];
      if (q.dx == 0 && q.dy == 0) continue;
      const double delta =
          2 * kEps * (std::fabs(q.dx * l_.width) + std::fabs(q.dy * l_.height) + std::fabs(p[i].x) + std::fabs(p[i].y));
      slack += delta * (1 + 2 * r * std::sqrt(squared(p[(i + 1) % 3], p[(i + 2) % 3])) / twice_area);
    }
    const double out = std::max({lo.x - (o.x - r), (o.x + r) - hi.x, lo.y - (o.y - r), (o.y + r) - hi.y});
    if (!std::isfinite(out + slack))
      return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    return {out, out + slack};
  }

  // The kept triangles written out, each with its neighbours: the triangle beside it in the
  // structure where that one is kept too (then placed by its own offsets it lies there), else
  // the kept one of that triangle's class, found by its corners (the few that cross the
  // domain's sides), moved by its least corner's offset. False where a neighbour's class has
  // no kept triangle (the margin was too narrow after all). The triangles and neighbours are
  // written over the structure's own arrays (kept triangle k's slot is k or later).
  bool link() {
    struct Across {
      std::size_t edge;
      std::int32_t triangle;
      Offset shift;
    };
    std::vector<Across> across;  // the neighbours found by their corners, in edge order
    std::unordered_map<Corners, std::int32_t, CornersHash> crossing;
    const std::size_t count = slot_.size();
    for (std::size_t k = 0; k < count; ++k) {
      const VertexId* c = tds_.corners(slot_[k]);
      if (!same_shift(s_[c[0]], s_[c[1]]) || !same_shift(s_[c[0]], s_[c[2]]))
        crossing.emplace(corners(c, first_[k], {0, 0}), static_cast<std::int32_t>(k));
    }
    for (std::size_t k = 0; k < count; ++k)
      for (int j = 0; j < 3; ++j) {
        const TriangleId u = tds_.neighbour(slot_[k], (first_[k] + j) % 3);
        if (u == kNoTriangle) return false;
        if (id_[u] >= 0) continue;
        const VertexId* c = tds_.corners(u);
        if (c[0] >= n_ || c[1] >= n_ || c[2] >= n_) return false;
        const int low = least(c);
        const Offset shift = make_offset(s_[c[low]].dx, s_[c[low]].dy);
        const auto found = crossing.find(corners(c, low, shift));
        const std::int32_t at = found != crossing.end() ? found->second : unmoved(c, shift);
        if (at < 0) return false;
        across.push_back({3 * k + j, at, shift});
      }
    out_ = {};
    resize_present(out_.offsets, 3 * count, threads_);
    resize_present(out_.neighbor_offsets, 3 * count, threads_);
    VertexId* v = tds_.vertex_array().data();
    Link* l = tds_.link_array().data();
    std::size_t next = 0;  // in `across`
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t t = slot_[k];
      VertexId w[3];
      TriangleId u[3];
      for (int j = 0; j < 3; ++j) {
        const int i = (first_[k] + j) % 3;
        w[j] = v[3 * t + i], u[j] = triangle_of(l[3 * t + i]);
      }
      for (std::size_t j = 0; j < 3; ++j) {
        v[3 * k + j] = index(w[j]), out_.offsets[3 * k + j] = make_offset(s_[w[j]].dx, s_[w[j]].dy);
        if (next < across.size() && across[next].edge == 3 * k + j) {
          l[3 * k + j] = across[next].triangle, out_.neighbor_offsets[3 * k + j] = across[next].shift;
          ++next;
        } else {
          l[3 * k + j] = id_[u[j]];
        }
      }
    }
    out_.triangles = std::move(tds_.vertex_array());
    out_.neighbors = std::move(tds_.link_array());
    out_.triangles.resize(3 * count), out_.neighbors.resize(3 * count);
    return true;
  }

  // The kept triangle of the class of triangle c (all of whose corners have offset `shift`)
  // whose corners are points as given: found round the first one's vertex; or -1.
  std::int32_t unmoved(const VertexId* c, Offset shift) const {
    VertexId w[3];
    for (int j = 0; j < 3; ++j) {
      if (s_[c[j]].dx != shift.dx || s_[c[j]].dy != shift.dy) return -1;
      w[j] = given_[place(input_[c[j]])];
    }
    const TriangleId start = around_[w[0]];
    if (start == kNoTriangle) return -1;
    TriangleId t = start;
    do {  // counter-clockwise round w[0]: across the edge after it
      const int i = tds_.corner_of(t, w[0]);
      if (tds_.vertex(t, next3(i)) == w[1] && tds_.vertex(t, prev3(i)) == w[2]) return id_[t];
      t = tds_.neighbour(t, next3(i));
    } while (t != start && t != kNoTriangle);
    return -1;
  }

  // A triangle by its corners' input indices and offsets, from corner `first`, moved back by
  // `shift`: the key of its class's kept triangle.
  using Corners = std::array<std::int64_t, 3>;
  struct CornersHash {
    std::size_t operator()(const Corners& c) const {
      return mix64(static_cast<std::uint64_t>(c[0]) ^ mix64(static_cast<std::uint64_t>(c[1]) ^ mix64(c[2])));
    }
  };
  Corners corners(const VertexId* c, int first, Offset shift) {
    Corners out;
    for (int j = 0; j < 3; ++j) {
      const VertexId v = c[(first + j) % 3];
      out[j] = static_cast<std::int64_t>(index(v)) << 24 ^ std::int64_t{(s_[v].dx - shift.dx) & 0xfff} << 12 ^
          ((s_[v].dy - shift.dy) & 0xfff);
    }
    return out;
  }

  // Refuses a triangle kept with a corner more than kMaxOffset periods from its least one (few
  // points in a long, narrow domain), which Offset cannot hold.
  void check_reach(const VertexId* c, int low) const {
    for (int j = 0; j < 3; ++j)
      if (std::abs(s_[c[j]].dx - s_[c[low]].dx) > kMaxOffset || std::abs(s_[c[j]].dy - s_[c[low]].dy) > kMaxOffset)
        throw InputError(
            "triangulate_periodic: too few points for a domain this long and narrow (a triangle spans "
            "more than " +
            std::to_string(kMaxOffset) + " periods)");
  }

  // A vertex's input index: its group's least where the same point was given more than once.
  VertexId index(VertexId v) { return duplicates_ ? input_of(root(up_, place(input_[v]))) : input_[v]; }

  // Input index k's place among the points copied (subset_, ascending; k itself where every
  // point is), and back.
  VertexId place(VertexId k) const {
    return subset_.empty()
        ? k
        : static_cast<VertexId>(std::lower_bound(subset_.begin(), subset_.end(), k) - subset_.begin());
  }
  VertexId input_of(VertexId place) const { return subset_.empty() ? place : subset_[place]; }

  // The least corner of a triangle, by (input index, dx, dy).
  int least(const VertexId* c) {
    auto key = [&](VertexId v) { return std::tuple{index(v), s_[v].dx, s_[v].dy}; };
    const auto k0 = key(c[0]), k1 = key(c[1]), k2 = key(c[2]);
    return k0 < k1 ? (k0 < k2 ? 0 : 2) : (k1 < k2 ? 1 : 2);
  }

  std::span<const Point> points_;
  std::span<const VertexId> subset_;
  PeriodicDomain d_;
  Periods l_;
  unsigned threads_;
  Point lo_, hi_;
  VertexId n_ = 0;  // copies in S
  std::vector<Shifted> s_;  // by vertex id: the copy, then the bounding vertices
  std::vector<VertexId> input_;  // by vertex id: its point's input index
  std::vector<VertexId> up_;  // by place (below): the union of equal points
  std::vector<VertexId> given_;  // by place: the vertex at its point as given (offset 0)
  std::vector<TriangleId> around_;  // by vertex id: a triangle that has it
  bool grown_ = false;  // keep() has set the next margin
  bool verify_ = false;  // keep() asks for the exact validator
  bool duplicates_ = false;
  Tds tds_;
  std::vector<std::int32_t> id_;  // by slot: its kept triangle, or -1
  std::vector<TriangleId> slot_;  // by kept triangle: its slot
  std::vector<std::uint8_t> first_;  // and the slot's corner that comes first
  PeriodicTriangulation out_;
};

}  // namespace ridt::detail
