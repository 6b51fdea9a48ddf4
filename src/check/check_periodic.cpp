// The validator of periodic triangulations (ridt/periodic.hpp), independent of the builder but
// for the exact predicates and the matching of each edge with its twin (periodic_twins).
//
// Why these checks suffice: triangles that are counter-clockwise where their offsets place
// them, glued edge to edge by their twins, with one cycle of triangles round each vertex, make
// a closed oriented surface that maps onto the torus, locally one to one except perhaps at
// vertices; with n vertices, 3n edges and 2n triangles its Euler characteristic is 0, so (by
// Riemann and Hurwitz) the map has no branch point and covers the torus some whole number of
// times — their areas say once (all positive, so even rounded their sum is far from 2 or 0
// domains). Their copies are then a triangulation of the plane whose vertices are all the
// copies of the points; every edge locally Delaunay makes it the Delaunay triangulation, and
// the perturbation the one triangulate_periodic decides.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "check/parts.hpp"
#include "periodic/periodic.hpp"
#include "predicates/shifted.hpp"
#include "ridt/periodic.hpp"
#include "runtime/parallel.hpp"
#include "tds/ids.hpp"

namespace ridt {
namespace {

using detail::next3;
using detail::prev3;
using detail::Shifted;

class PeriodicCheck {
 public:
  PeriodicCheck(std::span<const Point> pts, const PeriodicDomain& d, std::span<const VertexId> tris,
                std::span<const Offset> offs)
      : pts_(pts), d_(d), l_{d.width, d.height}, tris_(tris), offs_(offs) {}

  CheckResult run() {
    if (tris_.size() % 3 != 0 || offs_.size() != tris_.size()) return {false, "the arrays are not #T by 3 each", 1};
    for (std::size_t e = 0; e < tris_.size(); ++e)
      if (tris_[e] >= pts_.size()) return {false, "triangle " + std::to_string(e / 3) + " names no point", 1};
    for (const Offset& o : offs_)  // (their sums and differences must stay in range)
      if (std::abs(o.dx) > kMaxOffset || std::abs(o.dy) > kMaxOffset)
        return {false, "an offset is more than " + std::to_string(kMaxOffset) + " periods", 1};
    vertices();
    renumber();
    triangles();
    if (p_.problems() == 0) edges();
    if (p_.problems() == 0) fans();
    if (p_.problems() == 0) area();
    return p_.result("valid: " + std::to_string(tris_.size() / 3) +
                     " triangles, the periodic Delaunay triangulation of " + std::to_string(distinct_) +
                     " distinct points");
  }

 private:
  Shifted at(std::size_t e) const { return {near_[local_[e]], offs_[e].dx, offs_[e].dy}; }

  // The vertices numbered by first use, their points in that order: the triangles' corners are
  // then read from memory in order (the input's numbering may be any), and so are the edges'.
  void renumber() {
    std::vector<VertexId> id(pts_.size(), detail::kNoVertex);
    local_.resize(tris_.size());
    for (std::size_t e = 0; e < tris_.size(); ++e) {
      VertexId& v = id[tris_[e]];
      if (v == detail::kNoVertex)
        v = static_cast<VertexId>(near_.size()), near_.push_back(pts_[tris_[e]]), input_.push_back(tris_[e]);
      local_[e] = v;
    }
  }

  // Each group of equal points has exactly one of its members as a vertex; 2n triangles.
  void vertices() {
    std::vector<std::uint8_t> used(pts_.size(), 0);
    for (const VertexId v : tris_) used[v] = 1;
    std::vector<VertexId> order(pts_.size());
    std::iota(order.begin(), order.end(), VertexId{0});
    detail::parallel_sort(order.begin(), order.end(), 0, [&](VertexId a, VertexId b) {
      return detail::lex_less(pts_[a], pts_[b]) || (pts_[a] == pts_[b] && a < b);
    });
    for (std::size_t k = 0, g = 0; k < order.size(); k = g) {
      std::size_t standing = 0;
      for (g = k; g < order.size() && pts_[order[g]] == pts_[order[k]]; ++g) standing += used[order[g]];
      ++distinct_;
      if (standing != 1)
        p_.problem("point ", order[k],
                   standing == 0 ? " is no vertex" : " is a vertex more than once (a copy of it too)");
    }
    if (tris_.size() != 6 * distinct_)
      p_.problem(tris_.size() / 3, " triangles, where ", distinct_, " distinct points on the torus have ",
                 2 * distinct_);
  }

  void triangles() {
    std::vector<std::uint8_t> bad(tris_.size() / 3, 0);
    detail::parallel_for(bad.size(), 0, 16384, [&](std::size_t from, std::size_t to) {
      for (std::size_t t = from; t < to; ++t)
        bad[t] = detail::orient_shifted(at(3 * t), at(3 * t + 1), at(3 * t + 2), l_) <= 0;
    });
    for (std::size_t t = 0; t < bad.size(); ++t)
      if (bad[t]) p_.problem("triangle ", t, " is not counter-clockwise where its offsets place it");
  }

  // Every edge has one twin, the twin's twin is the edge, and the vertex across the twin lies
  // outside the triangle's circle (placed beside it).
  void edges() {
    twin_ = detail::periodic_twins(local_, offs_, near_.size());
    // 1: no twin or not the twin's; 2: not locally Delaunay.
    std::vector<std::uint8_t> bad(twin_.size(), 0);
    detail::parallel_for(twin_.size(), 0, 16384, [&](std::size_t from, std::size_t to) {
      for (std::size_t e = from; e < to; ++e) {
        if (twin_[e] < 0 || twin_[static_cast<std::size_t>(twin_[e])] != static_cast<std::int64_t>(e)) {
          bad[e] = 1;
          continue;
        }
        const auto f = static_cast<std::size_t>(twin_[e]);
        if (f < e) continue;
        const std::size_t here = e - e % 3 + prev3(static_cast<int>(e % 3));
        const std::size_t there = f - f % 3 + next3(static_cast<int>(f % 3));
        Shifted far = at(f);
        far.dx += offs_[here].dx - offs_[there].dx, far.dy += offs_[here].dy - offs_[there].dy;
        const std::size_t b = e - e % 3;
        bad[e] = detail::incircle_shifted(at(b), at(b + 1), at(b + 2), far, l_) > 0 ? 2 : 0;
      }
    });
    for (std::size_t e = 0; e < bad.size(); ++e) {
      if (bad[e] == 1)
        p_.problem("edge ", e % 3, " of triangle ", e / 3, twin_[e] == -2 ? " has several twins" : " has no twin");
      if (bad[e] == 2) p_.problem("edge ", e % 3, " of triangle ", e / 3, " is not locally Delaunay");
    }
  }

  // The triangles round each vertex make one cycle: from one corner of it, across the edge
  // after it, as many steps as it has corners.
  void fans() {
    std::vector<std::uint32_t> corners(near_.size(), 0);
    std::vector<std::int64_t> first(near_.size(), -1);
    for (std::size_t e = 0; e < local_.size(); ++e) {
      ++corners[local_[e]];
      if (first[local_[e]] < 0) first[local_[e]] = static_cast<std::int64_t>(e);
    }
    for (std::size_t v = 0; v < near_.size(); ++v) {
      if (first[v] < 0) continue;
      auto e = static_cast<std::size_t>(first[v]);
      std::uint32_t steps = 0;
      do {
        // The edge across from the next corner runs from the one after it back to this one:
        // its twin starts here, so the twin's triangle has this vertex at the twin's end.
        const std::size_t across = e - e % 3 + next3(static_cast<int>(e % 3));
        const auto f = static_cast<std::size_t>(twin_[across]);
        e = f - f % 3 + next3(static_cast<int>(f % 3));
        ++steps;
      } while (e != static_cast<std::size_t>(first[v]) && steps <= corners[v]);
      if (steps != corners[v]) p_.problem("the triangles round point ", input_[v], " make more than one cycle");
    }
  }

  // The areas add up to the domain's once (rounded: all are positive, and they could only add
  // up to a whole number of domains).
  void area() {
    double sum = 0;
    for (std::size_t b = 0; b < tris_.size(); b += 3) {
      const Point a = rounded(at(b), l_), p = rounded(at(b + 1), l_), q = rounded(at(b + 2), l_);
      sum += 0.5 * ((p.x - a.x) * (q.y - a.y) - (p.y - a.y) * (q.x - a.x));
    }
    const double domain = d_.width * d_.height;
    if (!(std::fabs(sum - domain) < 0.5 * domain))
      p_.problem("the triangles cover the torus ", std::lround(sum / domain), " times, not once");
  }

  static Point rounded(const Shifted& s, const detail::Periods& l) { return detail::rounded(s, l); }

  std::span<const Point> pts_;
  PeriodicDomain d_;
  detail::Periods l_;
  std::span<const VertexId> tris_;
  std::span<const Offset> offs_;
  std::vector<std::int64_t> twin_;
  std::vector<VertexId> local_;  // by corner: its vertex's number by first use
  std::vector<Point> near_;  // by that number: the point
  std::vector<VertexId> input_;  // and its input index
  std::size_t distinct_ = 0;
  detail::Report p_;
};

}  // namespace

CheckResult check_periodic(std::span<const Point> points, const PeriodicDomain& domain,
                           std::span<const VertexId> triangles, std::span<const Offset> offsets) {
  if (!(std::isfinite(domain.width) && domain.width > 0 && std::isfinite(domain.height) && domain.height > 0))
    return {false, "the domain's width and height must be positive and finite", 1};
  return PeriodicCheck(points, domain, triangles, offsets).run();
}

}  // namespace ridt
