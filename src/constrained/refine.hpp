// Delaunay refinement of a constrained triangulation to a minimum angle and maximum areas.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "constrained/cdt.hpp"
#include "constrained/given_mesh.hpp"
#include "ridt/constrained.hpp"

namespace ridt::detail {

/// What refinement is asked, in m's (scaled) coordinates.
struct Refinement {
  double min_angle = 0;  ///< degrees
  double max_area = 0;  ///< 0: none
  std::vector<double> region_area;  ///< per region of m.region, 0: none
  bool split_boundary = true;
  bool split_segments = true;  ///< false: no subsegment split (-YY)
  bool conforming = false;  ///< a point on one subsegment splits another whose circle holds it
  std::size_t max_steiner = 0;
  VertexId corners = 0;  ///< vertices below this id are corners (input points and crossings)
  std::size_t memory = 0;  ///< the bytes refinement may take; 0: what the process has left
  /// refine_mesh's given mesh: where set, m.region numbers its triangles, and each triangle's
  /// region is located again (by its centroid) before its area bound is read.
  const GivenMesh* given = nullptr;
  /// Quality::unsuitable, given m's (scaled) corners and twice the area; empty: none.
  std::function<bool(const Point&, const Point&, const Point&, double)> unsuitable;
  /// Quality::size at many points of m (scaled), in m's lengths; empty: none.
  std::function<void(std::span<const Point>, std::span<double>)> sizes;
  /// Threads for the tiles of a large mesh (constrained/tiles.cpp); the mesh is the same for any.
  unsigned threads = 1;
  /// Only triangles with an edge longer than this are mended (tiles.cpp's first step); 0: all.
  double longer_than = 0;
  /// The points added before this run (by tiles) are those from here on, counted in a message
  /// on the points added; 0: none.
  std::size_t added_from = 0;
  /// Free vertices near a subsegment split for a point refused beside it taken out first
  /// (Refiner::clear_circle): the last, whole-mesh run's (refine() sets it), whose mesh is
  /// then compacted.
  bool clear = false;
};

/// Refines m (Ruppert's algorithm with Shewchuk's concentric shells and Üngör's
/// off-centres): encroached subsegments split first, then bad triangles, each at its
/// off-centre unless that point would encroach a subsegment (then the subsegment is split).
/// Every boundary edge becomes fixed. A large mesh is refined first tile by tile, on
/// r.threads (constrained/tiles.cpp), then as a whole. Returns a warning where it stopped
/// early, else "".
std::string refine(Cdt& m, const Refinement& r);

/// What refinement carries from one stage to the next: per vertex, the corners at the ends of
/// the chain of subsegments it was added on (kNoVertex, kNoVertex for a corner or a vertex on no
/// chain); per corner, whether two segments meet there below 60 degrees (empty: not yet found).
struct Chains {
  std::vector<std::pair<VertexId, VertexId>> ends;
  std::vector<std::uint8_t> small;
};

/// The first stage of refine for a large mesh: each tile of a grid over m refined on its own,
/// on threads, wherever that leaves the tiles' ghosts alone. Returns the chains, which the
/// whole mesh's refinement goes on from; none where the mesh is too small for tiles.
Chains refine_tiles(Cdt& m, const Refinement& r);

}  // namespace ridt::detail
