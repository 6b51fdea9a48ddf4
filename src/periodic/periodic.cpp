// The periodic Delaunay triangulation (ridt/periodic.hpp): the Delaunay triangulation of the
// points and their copies near the domain, on the one mutable triangulation (tds/tds.hpp),
// from which one triangle of each class of translates is kept.
//
// The copies of the points tile the plane, and their Delaunay triangulation repeats with the
// domain. Take the copies that lie within a margin m of the domain, S, and triangulate them
// (inside a finite bounding triangle far away). A triangle of that triangulation whose circle
// lies inside the domain grown by m is empty of every copy (all copies there are in S), so it
// is a triangle of the periodic one; and with m at least the largest circle's diameter, every
// periodic triangle has a copy whose least corner lies in the domain, all of whose corners are
// in S. So: keep the triangles whose least corner (by input index, then offset) is a point as
// given (offset 0) — one of each class, since moving a triangle moves its least corner — and
// check them: when every kept circle lies inside and there are 2n of them (the torus's count),
// they are the whole periodic triangulation. Otherwise the margin grows and all is built again
// (uniform points rarely need it: the first margin is some 2.4 times the expected largest
// empty circle's diameter).
//
// The predicates are those of the ordinary triangulation on the copies' true coordinates
// (predicates/shifted.hpp): the lexicographic order that keys the perturbation does not change
// when all points move together, so translates of a configuration get translated answers, and
// the kept triangles fit together.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "order/order.hpp"
#include "periodic/periodic.hpp"
#include "predicates/shifted.hpp"
#include "ridt/periodic.hpp"
#include "runtime/parallel.hpp"
#include "tds/delaunay.hpp"
#include "tds/tds.hpp"

namespace ridt {
namespace detail {
namespace {

// Whether x0 <= x < x0 + width, exactly: x - x0 = s + e (two_diff), compared with width.
bool within(double x, double x0, double width) {
  if (!(x >= x0)) return false;
  const double s = x - x0, bv = x - s, av = s + bv, e = (x - av) + (bv - x0);
  return s < width || (s == width && e < 0);
}

void check_input(std::span<const Point> points, const PeriodicDomain& d) {
  if (!(std::isfinite(d.width) && d.width > 0 && std::isfinite(d.height) && d.height > 0))
    throw InputError("triangulate_periodic: the domain's width and height must be positive and finite");
  if (!std::isfinite(d.origin.x) || !std::isfinite(d.origin.y))
    throw InputError("triangulate_periodic: the domain's origin is not finite");
  if (points.empty()) throw InputError("triangulate_periodic: no points");
  if (points.size() >= kMaxSlotPoints / 16) throw InputError("triangulate_periodic: too many points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw InputError("triangulate_periodic: point " + std::to_string(i) + " is not finite");
    if (!within(p.x, d.origin.x, d.width) || !within(p.y, d.origin.y, d.height))
      throw InputError("triangulate_periodic: point " + std::to_string(i) +
                       " lies outside the domain [x0, x0 + width) x [y0, y0 + height)");
  }
}

// The least of a group of equal points: a union of input indices by their least.
VertexId root(std::vector<VertexId>& up, VertexId i) {
  while (up[i] != i) i = up[i] = up[up[i]];
  return i;
}

class Builder {
 public:
  Builder(std::span<const Point> points, const PeriodicDomain& d, unsigned threads)
      : points_(points), d_(d), l_{d.width, d.height}, threads_(threads) {}

  // One attempt with margin m: true when the triangles kept are the whole periodic
  // triangulation; else `m` is what the next attempt should take.
  // The circles are measured in rounded arithmetic, so the kept triangles are then checked
  // exactly: linked edge to edge and every edge locally Delaunay.
  bool attempt(double& m) {
    copy(m);
    insert_all();
    if (!keep(m)) return false;
    out_ = {};
    out_.domain = d_;
    out_.triangles = std::move(kept_);
    out_.offsets = std::move(kept_offsets_);
    if (link_periodic(out_) && locally_delaunay(points_, out_)) return true;
    m *= 2;
    return false;
  }

  PeriodicTriangulation take() {
    for (VertexId i = 0; i < up_.size(); ++i)
      if (const VertexId r = root(up_, i); r != i) out_.duplicates.push_back({i, r});
    return std::move(out_);
  }

 private:
  // S: every copy of every point that lies within m of the domain (by its rounded place: the
  // circles kept stay clear of the margin's edge by more than that rounding), then the three
  // bounding vertices; vertex ids in a biased randomized order along the Hilbert curve.
  void copy(double m) {
    const auto n = static_cast<VertexId>(points_.size());
    const auto kx = static_cast<std::int32_t>(std::ceil(m / d_.width)),
               ky = static_cast<std::int32_t>(std::ceil(m / d_.height));
    lo_ = {d_.origin.x - m, d_.origin.y - m};
    hi_ = {d_.origin.x + d_.width + m, d_.origin.y + d_.height + m};
    std::vector<Shifted> s;
    std::vector<VertexId> input;
    std::vector<Point> at;
    s.reserve(n + n / 8), input.reserve(n + n / 8), at.reserve(n + n / 8);
    for (VertexId i = 0; i < n; ++i)
      for (std::int32_t dy = -ky; dy <= ky; ++dy)
        for (std::int32_t dx = -kx; dx <= kx; ++dx) {
          const Shifted c{points_[i], dx, dy};
          const Point q = rounded(c, l_);
          if ((dx != 0 || dy != 0) && (q.x < lo_.x || q.x > hi_.x || q.y < lo_.y || q.y > hi_.y)) continue;
          s.push_back(c), input.push_back(i), at.push_back(q);
        }
    n_ = static_cast<VertexId>(s.size());
    const std::vector<std::uint32_t> order = brio_order(at.data(), n_, 0x5eed, threads_);
    s_.resize(n_ + 3), input_.resize(n_);
    for (VertexId v = 0; v < n_; ++v) s_[v] = s[order[v]], input_[v] = input[order[v]];
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
    up_.resize(points_.size());
    std::iota(up_.begin(), up_.end(), VertexId{0});
    TriangleId last = 0;
    CavityScratch scratch;
    for (VertexId v = 0; v < n_; ++v) {
      tds_.walk(
          last, [&](VertexId a, VertexId b) { return orient(a, b, v); }, Tds::kAnywhere);
      bool equal = false;
      for (int i = 0; i < 3 && !equal; ++i) {
        const VertexId w = tds_.vertex(last, i);
        if (w < n_ && same_shift(s_[w], s_[v]) && s_[w].p == s_[v].p) {
          const VertexId a = root(up_, input_[w]), b = root(up_, input_[v]);
          up_[std::max(a, b)] = std::min(a, b);
          equal = true;
        }
      }
      if (equal) continue;
      tds_.find_cavity(
          last, scratch, [&](const VertexId* w) { return in_circle(w, v); }, Tds::kAnywhere, Tds::kNoWall,
          Tds::kNotSeen);
      SlotPool pool = tds_.fresh(2);
      last = tds_.fill_cavity(v, scratch, pool);
    }
  }

  // The least corner of a triangle: by (group's least input index, dx, dy).
  struct Key {
    VertexId index;
    std::int32_t dx, dy;
    friend auto operator<=>(const Key&, const Key&) = default;
  };
  Key key(VertexId v) { return {root(up_, input_[v]), s_[v].dx, s_[v].dy}; }

  // Whether the circle of triangle (a, b, c) lies inside the grown domain with room for the
  // rounding of its computation; else how far it would need the margin to reach.
  double reach(VertexId a, VertexId b, VertexId c) const {
    const Point pa = rounded(s_[a], l_), pb = rounded(s_[b], l_), pc = rounded(s_[c], l_);
    const Point o = circumcentre_bounded(pa, pb, pc);
    const double r = (1 + 0x1p-30) *
        std::max({std::hypot(pa.x - o.x, pa.y - o.y), std::hypot(pb.x - o.x, pb.y - o.y),
                  std::hypot(pc.x - o.x, pc.y - o.y)});
    const double x0 = d_.origin.x, y0 = d_.origin.y;
    const double out =
        std::max({x0 - (o.x - r), (o.x + r) - (x0 + d_.width), y0 - (o.y - r), (o.y + r) - (y0 + d_.height)});
    return std::isfinite(out) ? out : std::numeric_limits<double>::infinity();
  }

  // The triangles whose least corner is a point as given; false (and the next margin in m)
  // when a circle reaches too far or their count is not 2n.
  bool keep(double& m) {
    // The copies' rounding (a few units in the last place of the largest coordinate).
    const double room = 16 * kEps * (std::fabs(d_.origin.x) + std::fabs(d_.origin.y) + 2 * (d_.width + d_.height + m));
    double need = 0;
    kept_.clear(), kept_offsets_.clear();
    for (TriangleId t = 0; t < tds_.slots(); ++t) {
      const VertexId* c = tds_.corners(t);
      if (c[0] >= n_ || c[1] >= n_ || c[2] >= n_) continue;  // a free slot (kNoVertex) or bounding
      const Key k[3] = {key(c[0]), key(c[1]), key(c[2])};
      const int low = k[0] < k[1] ? (k[0] < k[2] ? 0 : 2) : (k[1] < k[2] ? 1 : 2);
      if (k[low].dx != 0 || k[low].dy != 0) continue;
      need = std::max(need, reach(c[0], c[1], c[2]) + 2 * room);
      for (int j = 0; j < 3; ++j) {
        const int i = (low + j) % 3;
        kept_.push_back(k[i].index), kept_offsets_.push_back({k[i].dx, k[i].dy});
      }
    }
    std::size_t distinct = 0;
    for (VertexId i = 0; i < up_.size(); ++i) distinct += root(up_, i) == i;
    if (need <= m && kept_.size() == 6 * distinct) return true;
    if (need <= m && kept_.size() > 6 * distinct)
      throw std::logic_error("ridt: periodic triangulation: more triangles than the torus holds");
    m = std::max(2 * m, 1.25 * need);
    return false;
  }

  std::span<const Point> points_;
  PeriodicDomain d_;
  Periods l_;
  unsigned threads_;
  Point lo_, hi_;
  VertexId n_ = 0;  // copies in S
  std::vector<Shifted> s_;  // by vertex id: the copy, then the bounding vertices
  std::vector<VertexId> input_;  // by vertex id: its point's input index
  std::vector<VertexId> up_;  // by input index: the union of equal points
  Tds tds_;
  std::vector<VertexId> kept_;
  std::vector<Offset> kept_offsets_;
  PeriodicTriangulation out_;
};

}  // namespace
}  // namespace detail

PeriodicTriangulation triangulate_periodic(std::span<const Point> points, const PeriodicDomain& domain,
                                           unsigned threads) {
  using namespace detail;
  threads = thread_count(threads);
  check_input(points, domain);
  const double n = static_cast<double>(points.size());
  // Some 2.4 times the diameter of the largest empty circle among n uniform points.
  double m = 2.4 * std::sqrt(domain.width * domain.height * std::log(n + 2) / (3.14159 * n));
  const double limit = 64 * std::max(domain.width, domain.height);
  Builder builder(points, domain, threads);
  while (!builder.attempt(m))
    if (m > limit) throw std::logic_error("ridt: periodic triangulation: the margin grew past 64 periods");
  return builder.take();
}

}  // namespace ridt
