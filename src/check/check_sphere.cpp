// check_sphere (ridt/sphere.hpp): a triangulation on the sphere checked to be the convex hull
// of its points, by other means than triangulate_sphere finds it. A closed surface (each
// directed edge once, its reverse once, one piece, Euler's V - E + F = 2) whose triangles all
// face away from an inner point and wrap round it once (one of their cones from it holds a
// probe) projects onto the directions from that point one to one: it is star-shaped. Star-shaped
// with every edge convex, it is convex, so it is the hull of its corners; every other point
// then lies below the triangle whose cone holds it. The inner point is strictly inside four
// corners (sphere/tetrahedron.hpp, which the triangulation starts from too), exactly.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "check/parts.hpp"
#include "predicates/orient3d.hpp"
#include "ridt/sphere.hpp"
#include "sphere/tetrahedron.hpp"
#include "tds/ids.hpp"

namespace ridt {

namespace {

using detail::kNoVertex;
using detail::next3;
using detail::orient3d;
using detail::prev3;

bool lex_less3(const Point3& a, const Point3& b) {
  return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
}

// The checks in turn, each adding to `report`; each needs the ones before it to have passed.
class SphereCheck {
 public:
  SphereCheck(std::span<const Point3> pts, std::span<const VertexId> tris)
      : pts_(pts), tris_(tris), n_(pts.size()), m_(tris.size() / 3) {}

  CheckResult run() {
    if (!arrays() || !corners() || !closed() || !sphere() || !convex() || !wrapped()) return report_.result();
    const std::size_t hidden = inside();
    return report_.result("valid: the convex hull of " + std::to_string(corners_) + " points, " + std::to_string(m_) +
                          " triangles" + (hidden > 0 ? ", " + std::to_string(hidden) + " inside it" : ""));
  }

 private:
  bool arrays() {
    if (tris_.size() % 3 != 0)
      report_.problem("the triangles' array holds ", tris_.size(), " numbers, not a multiple of three");
    for (std::size_t i = 0; i < n_ && report_.problems() == 0; ++i)
      if (!std::isfinite(pts_[i].x) || !std::isfinite(pts_[i].y) || !std::isfinite(pts_[i].z))
        report_.problem("point ", i, " is not finite");
    for (std::size_t k = 0; k < tris_.size() && report_.problems() == 0; ++k)
      if (tris_[k] >= n_) report_.problem("corner ", tris_[k], " is not a point's index (", n_, " points)");
    if (report_.problems() == 0 && m_ < 4) report_.problem(m_, " triangles: a closed surface has at least four");
    return report_.problems() == 0;
  }

  // Ranks (the points' lexicographic order, equal points one rank: the perturbation's key), and
  // the corners: distinct points, each used by one index.
  bool corners() {
    std::vector<VertexId> order(n_);
    std::iota(order.begin(), order.end(), VertexId{0});
    std::sort(order.begin(), order.end(), [&](VertexId a, VertexId b) { return lex_less3(pts_[a], pts_[b]); });
    rank_.resize(n_);
    for (std::size_t k = 0, r = 0; k < n_; ++k) {
      if (k > 0 && !(pts_[order[k - 1]] == pts_[order[k]])) ++r;
      rank_[order[k]] = static_cast<std::uint32_t>(r);
    }
    corner_.assign(n_, 0);
    for (const VertexId v : tris_) corner_[v] = 1;
    owner_.assign(n_, kNoVertex);
    for (std::size_t v = 0; v < n_; ++v) {
      if (!corner_[v]) continue;
      ++corners_;
      if (owner_[rank_[v]] != kNoVertex) {
        report_.problem("corners ", owner_[rank_[v]], " and ", v, " are the same point");
        return false;
      }
      owner_[rank_[v]] = static_cast<VertexId>(v);
    }
    return true;
  }

  // Every directed edge once, its reverse once: the triangle across each edge.
  bool closed() {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> edges(3 * m_);  // (tail, head), slot 3f + i
    for (std::size_t f = 0; f < m_; ++f)
      for (int i = 0; i < 3; ++i) {
        const std::uint64_t a = tris_[3 * f + next3(i)], b = tris_[3 * f + prev3(i)];
        if (a == b || tris_[3 * f + i] == a) {
          report_.problem("triangle ", f, " repeats a corner");
          return false;
        }
        edges[3 * f + i] = {a << 32 | b, static_cast<std::uint32_t>(3 * f + i)};
      }
    std::sort(edges.begin(), edges.end());
    for (std::size_t k = 1; k < edges.size(); ++k)
      if (edges[k].first == edges[k - 1].first) {
        report_.problem("edge ", edges[k].first >> 32, "-", edges[k].first & 0xffffffffu,
                        " is used twice the same way");
        return false;
      }
    across_.resize(3 * m_);
    for (const auto& [key, slot] : edges) {
      const std::uint64_t reverse = (key & 0xffffffffu) << 32 | key >> 32;
      const auto at = std::lower_bound(edges.begin(), edges.end(), std::pair{reverse, std::uint32_t{0}});
      if (at == edges.end() || at->first != reverse) {
        report_.problem("edge ", key >> 32, "-", key & 0xffffffffu, " has no triangle on its other side");
        return false;
      }
      across_[slot] = at->second;
    }
    return true;
  }

  // One piece, and a sphere: V - E + F = 2.
  bool sphere() {
    std::vector<std::uint8_t> reached(m_, 0);
    std::vector<std::uint32_t> todo{0};
    reached[0] = 1;
    std::size_t count = 1;
    while (!todo.empty()) {
      const std::uint32_t f = todo.back();
      todo.pop_back();
      for (int i = 0; i < 3; ++i)
        if (const std::uint32_t g = across_[3 * f + i] / 3; !reached[g]) reached[g] = 1, ++count, todo.push_back(g);
    }
    if (count != m_)
      report_.problem("the triangles make more than one surface");
    else if (corners_ + m_ != 3 * m_ / 2 + 2)
      report_.problem("the surface is not a sphere (", corners_, " corners, ", m_, " triangles)");
    return report_.problems() == 0;
  }

  // Every edge convex: the apex across below the triangle's plane (perturbed as the
  // triangulation is).
  bool convex() {
    for (std::size_t f = 0; f < m_ && report_.problems() < 100; ++f)
      for (int i = 0; i < 3; ++i)
        if (const std::uint32_t l = across_[3 * f + i]; l > 3 * f && !below(f, tris_[l]))
          report_.problem("edge ", tris_[3 * f + next3(i)], "-", tris_[3 * f + prev3(i)], " is not convex");
    return report_.problems() == 0;
  }
  bool below(std::size_t f, VertexId q) const {
    const VertexId a = tris_[3 * f], b = tris_[3 * f + 1], c = tris_[3 * f + 2];
    return detail::orient3d_sos(pts_[a], pts_[b], pts_[c], pts_[q], rank_[a], rank_[b], rank_[c], rank_[q]) > 0;
  }

  // An inner point: the centroid of four corners far from flat, strictly inside them, so inside
  // their hull (sphere/tetrahedron.hpp); every triangle faces away from it, and their solid
  // angles from it make one turn of the sphere.
  bool wrapped() {
    // The corners in lexicographic order; where the fattest tetrahedron from the least is too
    // thin for a double inside it, from each of the next few.
    std::vector<VertexId> corners;
    for (std::size_t v = 0; v < n_; ++v)
      if (corner_[v]) corners.push_back(static_cast<VertexId>(v));
    std::sort(corners.begin(), corners.end(), [&](VertexId a, VertexId b) { return rank_[a] < rank_[b]; });
    detail::Tetrahedron t = detail::fat_tetrahedron(pts_, corners);
    for (std::size_t k = 1; k < std::min<std::size_t>(corners.size(), 8) && t.flat == nullptr && !t.inside; ++k) {
      std::swap(corners[0], corners[k]);
      t = detail::fat_tetrahedron(pts_, corners);
    }
    if (t.flat != nullptr || !t.inside) {
      report_.problem("the corners are ", t.flat != nullptr ? t.flat : "too nearly coplanar", ": they have no inside");
      return false;
    }
    o_ = t.inner;
    const std::uint32_t* r = rank_.data();
    for (std::size_t f = 0; f < m_; ++f) {
      // (perturbed as the triangulation is, the inner point least of all: a face of three
      // collinear points is a sliver of the perturbed hull, with the inner point below it)
      const VertexId* c = tris_.data() + 3 * f;
      if (detail::orient3d_sos(pts_[c[0]], pts_[c[1]], pts_[c[2]], o_, r[c[0]], r[c[1]], r[c[2]], inner_rank()) <= 0) {
        report_.problem("triangle ", f, " does not face away from the inner point");
        return false;
      }
    }
    // Facing away, the triangles cover every direction from o the same number of times: as
    // many as hold one probe in their cones (perturbed, so that exactly that many do).
    const Point3& a = pts_[tris_[0]];
    const Point3 probe{a.x / 2 + o_.x / 2, a.y / 2 + o_.y / 2, a.z / 2 + o_.z / 2};
    std::size_t turns = 0;
    for (std::size_t f = 0; f < m_; ++f) turns += holds(f, probe, inner_rank() + 1);
    if (turns != 1) report_.problem("the triangles wrap round the inner point ", turns, " times, not once");
    return report_.problems() == 0;
  }
  std::uint32_t inner_rank() const { return static_cast<std::uint32_t>(n_); }

  // Every point not a corner: a copy of one, or below the triangle whose cone from o holds it
  // (found by walking; the sides perturbed, o least of all, so that the cones part space).
  // Returns how many lie inside.
  std::size_t inside() {
    std::size_t last = 0, hidden = 0;
    for (std::size_t q = 0; q < n_ && report_.problems() < 100; ++q) {
      if (corner_[q] || owner_[rank_[q]] != kNoVertex) continue;  // a corner, or a copy of one
      ++hidden;
      last = cone(last, static_cast<VertexId>(q));
      if (!below(last, static_cast<VertexId>(q)))
        report_.problem("point ", q, " is outside the hull (above triangle ", last, ")");
    }
    return hidden;
  }
  // q's side of the plane through o, a and b (+1: the side of the triangles left of a -> b),
  // perturbed, o least of all but a probe (rank r): never 0, so that the cones part space.
  int side(VertexId a, VertexId b, const Point3& q, std::uint32_t r) const {
    return -detail::orient3d_sos(o_, pts_[a], pts_[b], q, inner_rank(), rank_[a], rank_[b], r);
  }
  bool holds(std::size_t f, const Point3& q, std::uint32_t r) const {
    const VertexId* t = tris_.data() + 3 * f;
    return side(t[0], t[1], q, r) > 0 && side(t[1], t[2], q, r) > 0 && side(t[2], t[0], q, r) > 0;
  }
  // The triangle whose cone holds q: by walking from f, else by looking at each.
  std::size_t cone(std::size_t f, VertexId q) const {
    const Point3& x = pts_[q];
    for (std::size_t steps = 0, moved = 1; moved && steps < 4 * m_; ++steps) {
      moved = 0;
      for (int i = 0; i < 3 && !moved; ++i)
        if (side(tris_[3 * f + next3(i)], tris_[3 * f + prev3(i)], x, rank_[q]) < 0)
          f = across_[3 * f + i] / 3, moved = 1;
    }
    for (std::size_t g = 0; g < m_ && !holds(f, x, rank_[q]); ++g) f = g;
    return f;
  }

  std::span<const Point3> pts_;
  std::span<const VertexId> tris_;
  std::size_t n_, m_, corners_ = 0;
  detail::Report report_;
  std::vector<std::uint32_t> rank_, across_;
  std::vector<std::uint8_t> corner_;
  std::vector<VertexId> owner_;
  Point3 o_;
};

}  // namespace

CheckResult check_sphere(std::span<const Point3> pts, std::span<const VertexId> tris) {
  return SphereCheck(pts, tris).run();
}

}  // namespace ridt
