// The domain of a constrained triangulation: the triangles outside it removed, the regions
// within it marked.
#pragma once

#include <vector>

#include "constrained/cdt.hpp"
#include "ridt/constrained.hpp"

namespace ridt::detail {

/// Removes from m the triangles outside `domain` (holes and, without convex_hull, the
/// exterior: flooded across every edge that is not fixed), then marks each region's
/// triangles (m.region; left empty without regions). Seeds are in m's (scaled) coordinates.
/// Renumbers the triangles that stay in their order; returns whether any were removed.
bool carve(Cdt& m, const std::vector<Point>& holes, const std::vector<Region>& regions, bool convex_hull);

}  // namespace ridt::detail
