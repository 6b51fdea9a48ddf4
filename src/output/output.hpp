// What every kernel's finish shares: each kernel turns what it inserted into the output's
// arrays (dag/finish.cpp, tds/delaunay_finish.cpp) with these steps, and the output's options
// are applied the same way to every result.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ridt/ridt.hpp"

namespace ridt::detail {

/// A point dropped during insertion and the vertex it coincides with.
struct DuplicateHit {
  VertexId dropped;
  VertexId vertex;
};

/// The input index that stands for a mesh vertex: its own, or for a group of equal points the
/// smallest among them.
struct Standing {
  explicit Standing(const std::vector<std::uint32_t>& input_index) : input_index(input_index) {}
  VertexId operator()(VertexId mesh_vertex) const {
    const VertexId v = input_index[mesh_vertex];
    if (keep.empty()) return v;
    const auto it = keep.find(v);
    return it == keep.end() ? v : it->second;
  }
  const std::vector<std::uint32_t>& input_index;
  std::unordered_map<VertexId, VertexId> keep;  // only the input indices that another stands for
};

/// The finish's steps that every mesh shares. Groups the duplicates (input indices, sorted by
/// the dropped one) and says who stands for whom.
Standing resolve_duplicates(const std::vector<std::uint32_t>& input_index, const std::vector<DuplicateHit>& duplicates,
                            std::vector<Duplicate>& out);
/// The hull, counter-clockwise from its smallest vertex, from its edges (sorted here).
std::vector<VertexId> trace_hull(std::vector<std::pair<VertexId, VertexId>>& edges);
/// The counts of the points and the warning of an empty or (finite bounding triangle) broken
/// result. `input_points` fills the points in input order when they are needed.
void set_warnings(Triangulation& out, std::uint32_t n, std::uint32_t count, std::size_t hull_edges,
                  const Options& options, const std::function<void(std::vector<Point>&)>& input_points);

/// Options::on_sorted's type.
using Sorted = decltype(Options::on_sorted);

/// Rotates each triangle to start at its smallest vertex, then sorts the triangles, renumbering
/// the neighbours: the output no longer depends on the order of insertion. Up to `threads`
/// threads. Without `neighbors`, their memory serves the sort and the result has none.
/// `sorted`, where set, is called with each stretch as soon as its triangles are in place.
void canonicalize(Triangulation& out, unsigned threads = 1, bool neighbors = true, const Sorted& sorted = {});
/// What options ask of a finished result: the canonical order (canonicalize), the neighbours
/// given back where they are not wanted.
void apply_output_options(Triangulation& out, const Options& options, unsigned threads);

}  // namespace ridt::detail
