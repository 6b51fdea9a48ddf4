// Segments made edges of the constrained triangulation, split where they pass through a
// vertex or cross another segment.
#pragma once

#include <span>
#include <vector>

#include "constrained/cdt.hpp"

namespace ridt::detail {

/// Each segment (pairs of indices, flat; `kept` maps a duplicate point to the one kept) made a
/// chain of fixed edges of m, each edge's constraint the segment's number (k for the pair at
/// 2k). Where two segments cross, the exact crossing rounded to doubles is added as a point
/// (m.pts grows by one a crossing), on both; a segment given twice, or two that overlap, leave
/// the later one's number on their shared pieces.
void insert_segments(Cdt& m, std::span<const VertexId> segments, std::span<const VertexId> kept);

}  // namespace ridt::detail
