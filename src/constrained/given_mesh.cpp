// A mesh given to be refined (constrained/given_mesh.hpp).
#include "constrained/given_mesh.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "predicates/predicates.hpp"

namespace ridt::detail {

std::vector<std::int32_t> neighbours_of(std::span<const Point> points, std::span<const VertexId> triangles) {
  const std::size_t count = triangles.size() / 3;
  for (std::size_t t = 0; t < count; ++t)
    if (orient2d(points[triangles[3 * t]], points[triangles[3 * t + 1]], points[triangles[3 * t + 2]]) <= 0)
      throw InputError("triangle " + std::to_string(t) + " (" + std::to_string(triangles[3 * t]) + ", " +
                       std::to_string(triangles[3 * t + 1]) + ", " + std::to_string(triangles[3 * t + 2]) +
                       ") is clockwise or has no area: a mesh's triangles go counter-clockwise");
  // Edge k of triangle t runs from its corner k + 1 to corner k + 2. The edge slots listed by
  // their first end (counted, then placed), each end's by their second: two running the same
  // way are then side by side, and the one running back along an edge is found in its second
  // end's list.
  auto from = [&](std::size_t s) { return triangles[s - s % 3 + (s + 1) % 3]; };
  auto to = [&](std::size_t s) { return triangles[s - s % 3 + (s + 2) % 3]; };
  std::vector<std::uint32_t> start(points.size() + 1, 0);
  for (std::size_t s = 0; s < triangles.size(); ++s) ++start[from(s) + 1];
  for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<std::uint32_t> slots(triangles.size()), at(start.begin(), start.end() - 1);
  for (std::size_t s = 0; s < triangles.size(); ++s) slots[at[from(s)]++] = static_cast<std::uint32_t>(s);
  const auto by_end = [&](std::uint32_t s, std::uint32_t u) { return to(s) < to(u); };
  for (std::size_t v = 0; v + 1 < start.size(); ++v) {
    const auto first = slots.begin() + start[v], last = slots.begin() + start[v + 1];
    std::sort(first, last, by_end);
    if (const auto twice = std::adjacent_find(first, last, [&](auto s, auto u) { return to(s) == to(u); });
        twice != last)
      throw InputError("triangles " + std::to_string(*twice / 3) + " and " + std::to_string(twice[1] / 3) +
                       " both run from vertex " + std::to_string(v) + " to " + std::to_string(to(*twice)) +
                       ": they overlap");
  }
  std::vector<std::int32_t> out(triangles.size(), -1);
  for (std::size_t s = 0; s < triangles.size(); ++s) {
    const VertexId a = from(s), b = to(s);
    const auto last = slots.begin() + start[b + 1];
    const auto back = std::partition_point(slots.begin() + start[b], last, [&](std::uint32_t u) { return to(u) < a; });
    if (back != last && to(*back) == a) out[s] = static_cast<std::int32_t>(*back / 3);
  }
  return out;
}

std::uint32_t GivenMesh::locate(const Point& p, std::uint32_t hint) const {
  const std::size_t count = tris_.size() / 3;
  auto outside = [&](std::uint32_t t, int k) {
    return orient2d(pts_[tris_[3 * t + (k + 1) % 3]], pts_[tris_[3 * t + (k + 2) % 3]], p) < 0;
  };
  std::uint32_t t = hint < count ? hint : 0;
  for (std::size_t steps = 0, turn = 0; steps < 64 + count / 8; ++steps, turn += 7) {
    int out = -1;
    for (int r = 0; r < 3 && out < 0; ++r)
      if (const int k = static_cast<int>((r + turn) % 3); outside(t, k) && nbrs_[3 * t + k] >= 0) out = k;
    if (out < 0) {
      if (!outside(t, 0) && !outside(t, 1) && !outside(t, 2)) return t;
      break;  // beyond the boundary from here
    }
    t = static_cast<std::uint32_t>(nbrs_[3 * t + out]);
  }
  for (std::uint32_t u = 0; u < count; ++u)
    if (!outside(u, 0) && !outside(u, 1) && !outside(u, 2)) return u;
  return hint;
}

std::int32_t GivenMesh::region_of(const Cdt& m, std::uint32_t t) const {
  const Point &a = m.pts[m.tris[3 * t]], &b = m.pts[m.tris[3 * t + 1]], &c = m.pts[m.tris[3 * t + 2]];
  const Point centroid{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
  return static_cast<std::int32_t>(locate(centroid, static_cast<std::uint32_t>(std::max(m.region[t], 0))));
}

namespace {

// Whether direction v -> u comes before v -> w counter-clockwise from the direction of +x
// (which comes first of all): by half-plane, then by orientation, exactly.
bool before(const Point& v, const Point& u, const Point& w) {
  auto lower = [&v](const Point& p) { return !(p.y > v.y || (p.y == v.y && p.x > v.x)); };
  if (lower(u) != lower(w)) return lower(w);
  return orient2d(v, u, w) > 0;
}

}  // namespace

void check_fans(const Cdt& m) {
  std::vector<std::uint8_t> seen(m.tris.size(), 0);
  for (std::size_t s = 0; s < m.tris.size(); ++s) {
    if (seen[s]) continue;
    const VertexId v = m.tris[s];
    const Point& pv = m.pts[v];
    const auto t0 = static_cast<std::uint32_t>(s / 3);
    // Each triangle a wedge at v from its next corner to its last; one that ends before it
    // starts (from +x, counter-clockwise) passes +x. Counter-clockwise from t0 (across the edge
    // from the last corner to v) to the boundary or round to t0, then clockwise from t0 where
    // the fan is open.
    int wraps = 0;
    auto wedge = [&](std::uint32_t t) {
      const int i = m.corner_of(t, v);
      seen[3 * t + i] = 1;
      wraps += before(pv, m.pts[m.at(t, i + 2)], m.pts[m.at(t, i + 1)]);
      return i;
    };
    bool closed = false;
    VertexId first = m.at(t0, m.corner_of(t0, v) + 1), last = Cdt::kNone;
    for (std::uint32_t t = t0;;) {
      const int i = wedge(t);
      const std::int32_t n = m.nbrs[3 * t + (i + 1) % 3];
      if (n < 0) {
        last = m.at(t, i + 2);
        break;
      }
      t = static_cast<std::uint32_t>(n);
      if (t == t0) {
        closed = true;
        break;
      }
    }
    for (std::uint32_t t = t0; !closed;) {
      const std::int32_t n = m.nbrs[3 * t + (m.corner_of(t, v) + 2) % 3];
      if (n < 0) break;
      t = static_cast<std::uint32_t>(n);
      first = m.at(t, wedge(t) + 1);
    }
    const bool once = closed ? wraps == 1 : wraps == 0 || (wraps == 1 && before(pv, m.pts[last], m.pts[first]));
    if (!once)
      throw InputError("the triangles about vertex " + std::to_string(v) + " turn round it " +
                       (closed ? std::to_string(wraps) + " times" : "more than once") + ": they overlap");
  }
}

}  // namespace ridt::detail
