// What check_mesh (check_mesh.cpp) measures beside its chains and gaps: how far a point lies
// off a segment's line, and the angles and areas of the triangles, with the triangles below the
// angle that refinement leaves (beside small input angles) counted apart.
#pragma once

#include <span>
#include <vector>

#include "check/parts.hpp"
#include "ridt/check.hpp"

namespace ridt::detail {

/// How far p lies off the line a-b, in units of the roundings of a point on it (see the
/// definition); `least`: the least scale, `computed`: p computed from a and b.
double off_line(const Point& a, const Point& b, const Point& p, long double least, bool computed);

/// The segment edges as each point's neighbours (adjacency), and per point whether it is an
/// added one found on an input segment between its two segment edges' other ends (`straight`:
/// no corner of the segments' chains, however its neighbours measure the turn).
struct SegmentEdges {
  Adjacency adj;
  std::vector<std::uint8_t> straight;
};

struct MeshShape {
  long double smallest = 180, largest_area = 0;
  std::size_t excused = 0;  ///< triangles below the angle beside small input angles
};

/// The triangles' angles and areas against spec's bounds, each that breaks one reported; `input`
/// the points as given, `pts` as the predicates see them (scaled), the first `input_points` the
/// input's, `least` as for off_line, `edges` spec's segment edges.
MeshShape check_mesh_shape(std::span<const Point> input, std::span<const Point> pts, std::span<const VertexId> tris,
                           const MeshSpec& spec, std::size_t input_points, long double least, const SegmentEdges& edges,
                           Report& report);

}  // namespace ridt::detail
