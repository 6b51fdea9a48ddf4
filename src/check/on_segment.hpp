// What check_mesh follows an input segment by: where a point lies along it, whether a point
// lies on it as far as its chain goes (OnSegment), and, for a mesh given without its segment
// edges, the mesh's edges along the segments (segment_edges.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "check/mesh_angles.hpp"
#include "predicates/predicates.hpp"
#include "ridt/check.hpp"

namespace ridt::detail {

// Where p lies along a -> b, exactly: its coordinate on the axis a -> b moves most along (x
// where it moves at least as much in x), signed so that it grows from a to b.
inline double along_key(const Point& a, const Point& b, const Point& p) {
  const bool by_x = std::fabs(b.x - a.x) >= std::fabs(b.y - a.y);
  const double from = by_x ? a.x : a.y, to = by_x ? b.x : b.y, at = by_x ? p.x : p.y;
  return to >= from ? at : -at;
}

// Where p lies along a -> b, in order: along_key, then, where that ties, the coordinate on the
// other axis, signed the same way (a point a rounding beside an end of a steep segment lies at
// that end's along_key, yet ahead of it or behind).
inline std::pair<double, double> along_keys(const Point& a, const Point& b, const Point& p) {
  const bool by_x = std::fabs(b.x - a.x) >= std::fabs(b.y - a.y);
  const double from = by_x ? a.y : a.x, to = by_x ? b.y : b.x, at = by_x ? p.y : p.x;
  return {along_key(a, b, p), to >= from ? at : -at};
}

// Whether a point lies on input segment a-b, as far as its chain goes: between its ends along
// it (up to 2^-40 of each end's coordinate: a crossing rounded past an end; a point beside a
// very long segment's end, within that segment's rounding of its line, is not on it), within
// its box grown by 10^-6 of its length, and off its line by no more than an added point's
// roundings upon roundings (2^-40 of the coordinates: a point on another segment is farther)
// or an input point's where a crossing within a few units in the last place of its
// coordinates was merged into it (2^-49: the merge's 4 units, the crossing's rounding).
struct OnSegment {
  OnSegment(std::span<const Point> points, VertexId from_a, VertexId to_b, std::size_t input_points, long double floor)
      : pts(points), a(from_a), b(to_b), input(input_points), least(floor) {
    const Point &pa = pts[a], &pb = pts[b];
    const double grow = 1e-6 * std::max(std::fabs(pa.x - pb.x), std::fabs(pa.y - pb.y));
    x0 = std::min(pa.x, pb.x) - grow, x1 = std::max(pa.x, pb.x) + grow;
    y0 = std::min(pa.y, pb.y) - grow, y1 = std::max(pa.y, pb.y) + grow;
    from = along_key(pa, pb, pa), to = along_key(pa, pb, pb);
  }

  bool operator()(VertexId v) const {
    const Point& p = pts[v];
    if (v == b) return true;
    if (!(p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1)) return false;
    const double at = along_key(pts[a], pts[b], p);
    if (!(at > from - 0x1p-40 * std::fabs(from) && at < to + 0x1p-40 * std::fabs(to))) return false;
    return orient2d(pts[a], pts[b], p) == 0 ||
        (v >= input ? off_line(pts[a], pts[b], p, least, true) <= 0x1p-40
                    : off_line(pts[a], pts[b], p, least, false) <= 0x1p-49);
  }

  std::span<const Point> pts;
  VertexId a, b;
  std::size_t input;
  long double least;
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0, from = 0, to = 0;
};

/// For a segment's end, the vertex it stands for: itself where it is a vertex (`used`), else
/// a vertex equal to it where there is one (the mesh kept another of a group of equal points).
/// The vertices are sorted by place only where some input point is no vertex.
class Standing {
 public:
  Standing(std::span<const Point> pts, const std::vector<std::uint8_t>& used, std::size_t input_points)
      : pts_(pts), used_(used) {
    if (std::all_of(used.begin(), used.begin() + static_cast<std::ptrdiff_t>(input_points), [](auto u) { return u; }))
      return;
    for (VertexId v = 0; v < pts.size(); ++v)
      if (used[v]) by_place_.push_back(v);
    std::sort(by_place_.begin(), by_place_.end(), [&](VertexId a, VertexId b) { return lex_less(pts[a], pts[b]); });
  }
  VertexId operator()(VertexId v) const {
    if (used_[v]) return v;
    const auto it = std::lower_bound(by_place_.begin(), by_place_.end(), v,
                                     [&](VertexId a, VertexId b) { return lex_less(pts_[a], pts_[b]); });
    return it != by_place_.end() && pts_[*it] == pts_[v] ? *it : v;
  }

 private:
  std::span<const Point> pts_;
  const std::vector<std::uint8_t>& used_;
  std::vector<VertexId> by_place_;  // the vertices, lexicographically
};

/// The edges of the mesh (its triangles' `sides`) that lie along the input's segments (pairs, each edge once):
/// for a mesh given without its segment edges (Triangle's files, or ridt mesh's without
/// OUT.edge), what they must be. Each segment a-b is followed from a along edges through the
/// points on it (OnSegment); where that does not reach b (the segment runs through a hole or
/// the exterior), from b and from every boundary vertex on it as well. A segment that the mesh
/// does not follow gives no edge, and check_mesh then reports it. The segments from the
/// `whole`-th on are followed from their ends only (the edges of the input's hull, which a mesh
/// of the hull keeps whole). `used`: the vertices of a triangle; `stand`: the vertex a
/// segment's end stands for. On `threads`.
std::vector<VertexId> edges_along_segments(std::span<const Point> pts, const Adjacency& sides,
                                           std::span<const VertexId> segments, std::size_t whole,
                                           std::size_t input_points, const std::vector<std::uint8_t>& used,
                                           const Standing& stand, long double least, unsigned threads);

}  // namespace ridt::detail
