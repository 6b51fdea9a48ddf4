// What the methods share: the set-up of a run and its finish.
#pragma once

#include <cstdint>
#include <vector>

#include "kernel.hpp"
#include "ridt/ridt.hpp"

namespace ridt::detail {

/// A point dropped during insertion and the mesh vertex it coincides with.
struct DuplicateHit {
  VertexId dropped;
  VertexId vertex;
};

/// Serial insertion of vertices 0 .. n-1 in that order (the paper's Fig. 4, lines 5-23).
void insert_serial(Kernel& kernel, bool profile, std::vector<DuplicateHit>& duplicates,
                   Stats& stats);

/// The paper's Fig. 10 with `threads` workers (pessimistic.cpp).
void insert_pessimistic(Kernel& kernel, unsigned threads, bool paper, bool timed,
                        std::vector<DuplicateHit>& duplicates, Stats& stats);

/// The optimistic method with `threads` workers (optimistic.cpp).
void insert_optimistic(Kernel& kernel, unsigned threads, bool timed,
                       std::vector<DuplicateHit>& duplicates, Stats& stats);

/// The batch method: threads - 1 locators and one modifier (batch.cpp).
void insert_batch(Kernel& kernel, unsigned threads, std::vector<DuplicateHit>& duplicates,
                  Stats& stats);

/// Removes the bounding vertices, numbers the remaining triangles compactly, finds the
/// neighbours and the hull, and resolves duplicates (Fig. 4, line 24). Mesh vertex v is input
/// point input_index[v]. Uses up to `threads` threads.
Triangulation finish(Kernel& kernel, const std::vector<std::uint32_t>& input_index,
                     const std::vector<DuplicateHit>& duplicates, const Options& options,
                     unsigned threads);

/// Rotates each triangle to start at its smallest vertex, then sorts the triangles, renumbering
/// neighbours: the output no longer depends on the order of insertion.
void canonicalize(Triangulation& out);

}  // namespace ridt::detail
