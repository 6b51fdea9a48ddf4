// The validator of regular triangulations (ridt/regular.hpp), independent of
// src/regular/regular.cpp: its own ranks, edge table, hull (Andrew's monotone chain on exact
// orientations) and point location; it shares only the exact predicates.
//
// Locally regular everywhere (each interior edge's far vertex above its triangle's plane, lifted)
// makes a triangulation of the convex hull the lower hull of its lifted vertices; the points that
// are no vertex must lie above it, each above the triangle that holds it.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "predicates/power.hpp"
#include "predicates/predicates.hpp"
#include "ridt/regular.hpp"

namespace ridt {
namespace {

using detail::orient2d;
using detail::Weighted;

struct Problems {
  std::size_t count = 0;
  std::string first;
  template <class... Args>
  void add(const Args&... args) {
    if (count++ > 0) return;
    std::ostringstream s;
    (s << ... << args);
    first = s.str();
  }
};

// The convex hull's corners, counter-clockwise from the least point (collinear points left out).
std::vector<VertexId> corners_of(std::span<const Point> pts, const std::vector<VertexId>& sorted) {
  std::vector<VertexId> order;
  for (const VertexId v : sorted)
    if (order.empty() || pts[order.back()] != pts[v]) order.push_back(v);
  if (order.size() < 3) return {};
  std::vector<VertexId> h(2 * order.size());
  std::size_t k = 0;
  auto add = [&](VertexId p, std::size_t floor) {
    while (k >= floor && orient2d(pts[h[k - 2]], pts[h[k - 1]], pts[p]) <= 0) --k;
    h[k++] = p;
  };
  for (const VertexId p : order) add(p, 2);
  const std::size_t lower = k + 1;
  for (std::size_t n = order.size() - 1; n-- > 0;) add(order[n], lower);
  h.resize(k - 1);
  return h.size() >= 3 ? h : std::vector<VertexId>{};
}

class RegularCheck {
 public:
  RegularCheck(std::span<const Point> pts, std::span<const double> w, std::span<const VertexId> tris)
      : pts_(pts), w_(w), tris_(tris), count_(tris.size() / 3) {}

  CheckResult run() {
    if (tris_.size() % 3 != 0) throw InputError("check_regular: triangles must be #T by 3");
    if (w_.size() != pts_.size()) throw InputError("check_regular: one weight a point");
    for (const VertexId v : tris_)
      if (v >= pts_.size()) throw InputError("check_regular: a vertex is not one of the points");
    sort();
    for (std::size_t t = 0; t < count_; ++t)
      if (orient2d(pts_[tris_[3 * t]], pts_[tris_[3 * t + 1]], pts_[tris_[3 * t + 2]]) <= 0)
        problems_.add("triangle ", t, " is not counter-clockwise or is degenerate");
    if (problems_.count == 0) edges();
    if (problems_.count == 0) vertices();
    if (problems_.count == 0) boundary();
    if (problems_.count == 0) hidden();
    if (problems_.count > 0) {
      std::ostringstream s;
      s << "invalid: " << problems_.first << " (" << problems_.count << " problem" << (problems_.count == 1 ? "" : "s")
        << ")";
      return {false, s.str(), problems_.count};
    }
    std::ostringstream s;
    s << "valid: " << count_ << " triangles, " << used_ << " vertices of " << pts_.size() << " points (" << hidden_
      << " hidden), exactly regular";
    return {true, s.str(), 0};
  }

 private:
  Weighted at(VertexId v) const { return {pts_[v], w_[v]}; }

  // The points in weighted_less order, copies by index.
  void sort() {
    sorted_.resize(pts_.size());
    std::iota(sorted_.begin(), sorted_.end(), VertexId{0});
    std::sort(sorted_.begin(), sorted_.end(),
              [&](VertexId a, VertexId b) { return detail::weighted_less(at(a), at(b)) || (at(a) == at(b) && a < b); });
  }
  bool above(VertexId a, VertexId b, VertexId c, VertexId d) const {
    return detail::power_sos(at(a), at(b), at(c), at(d)) < 0;
  }

  // Each directed edge once; each interior edge locally regular; the neighbours found.
  void edges() {
    std::vector<std::tuple<VertexId, VertexId, std::uint32_t>> e;  // (from, to, 3 t + corner across)
    e.reserve(3 * count_);
    for (std::size_t t = 0; t < count_; ++t)
      for (int i = 0; i < 3; ++i)
        e.emplace_back(tris_[3 * t + (i + 1) % 3], tris_[3 * t + (i + 2) % 3], static_cast<std::uint32_t>(3 * t + i));
    std::sort(e.begin(), e.end());
    neighbour_.assign(3 * count_, -1);
    for (std::size_t k = 0; k < e.size(); ++k) {
      const auto& [a, b, side] = e[k];
      if (k > 0 && std::get<0>(e[k - 1]) == a && std::get<1>(e[k - 1]) == b)
        problems_.add("edge ", a, "-", b, " is used twice in one direction");
      const auto twin = std::lower_bound(e.begin(), e.end(), std::make_tuple(b, a, std::uint32_t{0}));
      if (twin == e.end() || std::get<0>(*twin) != b || std::get<1>(*twin) != a) {
        boundary_.emplace_back(a, b);
        continue;
      }
      const std::uint32_t other = std::get<2>(*twin);
      neighbour_[side] = static_cast<std::int32_t>(other / 3);
      const VertexId* v = &tris_[3 * (side / 3)];
      const VertexId d = tris_[other];
      if (!above(v[0], v[1], v[2], d))
        problems_.add("edge ", a, "-", b, " is not locally regular (point ", d, " lies below the plane of triangle ",
                      side / 3, ", lifted)");
    }
  }

  // Each distinct weighted point a vertex at most once, no two vertices at one place.
  void vertices() {
    is_vertex_.assign(pts_.size(), 0);
    for (const VertexId v : tris_) is_vertex_[v] = 1;
    std::vector<VertexId> used;
    for (const VertexId v : sorted_)
      if (is_vertex_[v]) used.push_back(v);
    used_ = used.size();
    for (std::size_t k = 1; k < used.size(); ++k)
      if (pts_[used[k - 1]] == pts_[used[k]])
        problems_.add(w_[used[k - 1]] == w_[used[k]] ? "points " : "vertices ", used[k - 1], " and ", used[k],
                      " lie at one place");
  }

  // The boundary: the hull's corners in order, each side a chain of vertices on it, once round;
  // and Euler's count.
  void boundary() {
    const std::vector<VertexId> corners = corners_of(pts_, sorted_);
    if (corners.empty()) {
      if (count_ > 0)
        problems_.add("the points are collinear or fewer than three, but there are triangles");
      else
        problems_.add("no triangle");
      return;
    }
    std::sort(boundary_.begin(), boundary_.end());
    for (std::size_t k = 1; k < boundary_.size(); ++k)
      if (boundary_[k].first == boundary_[k - 1].first)
        return problems_.add("vertex ", boundary_[k].first, " begins two boundary edges");
    auto next = [&](VertexId v) -> std::int64_t {
      const auto it = std::lower_bound(boundary_.begin(), boundary_.end(), std::make_pair(v, VertexId{0}));
      return it != boundary_.end() && it->first == v ? it->second : -1;
    };
    // The corners by place: a vertex at a corner's place stands for it.
    std::size_t walked = 0;
    for (std::size_t k = 0; k < corners.size(); ++k) {
      const Point from = pts_[corners[k]], to = pts_[corners[(k + 1) % corners.size()]];
      std::int64_t v = k == 0 ? vertex_at(from) : current_;
      if (v < 0) return problems_.add("the hull's corner ", corners[k], " is not a vertex");
      Point last = from;
      for (;;) {
        const std::int64_t u = next(static_cast<VertexId>(v));
        if (u < 0 || ++walked > boundary_.size()) return problems_.add("the boundary is not the convex hull");
        const Point& q = pts_[static_cast<VertexId>(u)];
        if (orient2d(from, to, q) != 0 ||
            !(detail::lex_less(from, to) ? detail::lex_less(last, q) : detail::lex_less(q, last)))
          return problems_.add("boundary edge ", v, "-", u, " is not on the convex hull");
        v = u, last = q;
        if (q == to) break;
      }
      current_ = v;
    }
    if (walked != boundary_.size()) problems_.add("the boundary has edges off the convex hull");
    if (count_ != 2 * used_ - 2 - boundary_.size())
      problems_.add(count_, " triangles, not 2V - 2 - H = ", 2 * used_ - 2 - boundary_.size(), " (V = ", used_,
                    ", H = ", boundary_.size(), ")");
  }
  std::int64_t vertex_at(const Point& p) const {
    for (const VertexId v : sorted_)
      if (pts_[v] == p && is_vertex_[v]) return v;
    return -1;
  }

  // Every point that is no vertex, nor a copy of one, lies above the triangle that holds it:
  // each group of equal weighted points none of which is a vertex, its first tested.
  void hidden() {
    std::size_t t = 0;
    for (std::size_t k = 0, g = 0; k < sorted_.size(); k = g) {
      bool vertex = false;
      for (g = k; g < sorted_.size() && at(sorted_[g]) == at(sorted_[k]); ++g) vertex |= is_vertex_[sorted_[g]] != 0;
      if (vertex) continue;
      const VertexId p = sorted_[k];
      ++hidden_;
      if (!locate(p, t)) return problems_.add("point ", p, " is no vertex and lies in no triangle");
      const VertexId* v = &tris_[3 * t];
      if (!above(v[0], v[1], v[2], p))
        problems_.add("point ", p, " is no vertex but lies below triangle ", t, ", lifted (its cell is not empty)");
    }
  }
  bool holds(std::size_t t, const Point& q) const {
    const VertexId* v = &tris_[3 * t];
    return orient2d(pts_[v[0]], pts_[v[1]], q) >= 0 && orient2d(pts_[v[1]], pts_[v[2]], q) >= 0 &&
        orient2d(pts_[v[2]], pts_[v[0]], q) >= 0;
  }
  // A walk from triangle t to one whose closure holds point p; every triangle where it fails.
  bool locate(VertexId p, std::size_t& t) const {
    const Point& q = pts_[p];
    const std::size_t limit = 64 + 8 * static_cast<std::size_t>(std::sqrt(static_cast<double>(count_)));
    for (std::size_t steps = 0; steps < limit; ++steps) {
      const VertexId* v = &tris_[3 * t];
      int across = -1;
      for (int i = 0; i < 3 && across < 0; ++i)
        if (orient2d(pts_[v[(i + 1) % 3]], pts_[v[(i + 2) % 3]], q) < 0) across = i;
      if (across < 0) return true;
      const std::int32_t u = neighbour_[3 * t + static_cast<std::size_t>(across)];
      if (u < 0) break;
      t = static_cast<std::size_t>(u);
    }
    for (t = 0; t < count_; ++t)
      if (holds(t, q)) return true;
    t = 0;
    return false;
  }

  std::span<const Point> pts_;
  std::span<const double> w_;
  std::span<const VertexId> tris_;
  std::size_t count_;
  std::vector<VertexId> sorted_;
  std::vector<std::int32_t> neighbour_;
  std::vector<std::pair<VertexId, VertexId>> boundary_;
  std::vector<std::uint8_t> is_vertex_;
  std::size_t used_ = 0, hidden_ = 0;
  std::int64_t current_ = -1;
  Problems problems_;
};

}  // namespace

CheckResult check_regular(std::span<const Point> points, std::span<const double> weights,
                          std::span<const VertexId> triangles) {
  return RegularCheck(points, weights, triangles).run();
}

}  // namespace ridt
