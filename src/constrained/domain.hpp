// The domain of a constrained triangulation: the triangles outside it removed, the regions
// within it marked.
#pragma once

#include <vector>

#include "constrained/cdt.hpp"
#include "ridt/constrained.hpp"

namespace ridt::detail {

/// Marks the triangles of m outside `domain` (holes and, without convex_hull, the exterior:
/// flooded across every edge that is not fixed), then each region's triangles (m.region; left
/// empty without regions). Seeds are in m's (scaled) coordinates. With `compact` (what follows
/// works on m: refinement), the marked triangles are removed now, those that stay renumbered
/// in their order, and the vertices' corners set again; returns nothing then. Else they stay
/// (no kept triangle's free edge leads to one) and their marks are returned, for the output to
/// leave them out in its own pass (empty where none is marked).
std::vector<std::uint8_t> carve(Cdt& m, const std::vector<Point>& holes, const std::vector<Region>& regions,
                                bool convex_hull, bool compact);

/// Where the domain touches itself at a vertex (two holes, or a hole and the outline, meeting
/// at a corner), the triangles about it make fans that no edge joins, and a walk round it
/// (Cdt::around) sees one. Each such fan but one is given a vertex of its own at the same point,
/// added after m's points; returns, for each added vertex in turn, the vertex it stands for.
std::vector<VertexId> split_pinches(Cdt& m);

/// Undoes split_pinches, whose first added vertex was `first`: each one replaced in m's triangles
/// by the vertex it stands for, the vertices after them numbered down, their points removed.
void merge_pinches(Cdt& m, VertexId first, const std::vector<VertexId>& stands_for);

}  // namespace ridt::detail
