// The Delaunay triangulation of a point file larger than memory (`ridt triangulate --out-of-core`,
// Python's ridt.triangulate_out_of_core).
//
// The points are bucketed on disk into cells: columns of about equal counts (cut at quantiles
// of a sample's x), each cut into rows (quantiles of y). Strips of a few columns are then
// triangulated one after another, each with a column on either side, by the library's walking
// kernel. A strip keeps the triangles whose smallest input index it owns, once it knows that
// each triangle at a point it owns is a triangle of the whole set: its circumcircle holds no
// point of a column not loaded (the exact in-circle test, on the cells that the widened circle
// meets), and no point lies strictly beyond a hull edge at a point it owns. Where either fails,
// the strip loads the columns out to the point that failed it and triangulates again. The
// predicates' symbolic perturbation depends on the coordinates alone, so every strip decides as
// one process would: the union of the kept triangles is the triangulation of the whole set,
// the same triangles as `ridt triangulate` (ridt-mpi's argument, docs/distributed.md).
//
// Output: the parts format that `ridt check` reads (ridt-mpi writes it too): OUT.parts naming
// OUT.k-of-S.bin, one part a strip (uint32 input indices, each triangle from its smallest).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace ridt {

struct OutOfCoreOptions {
  std::string input;  ///< a .bin point file
  std::string output;  ///< the index, OUT.parts
  std::size_t memory_limit = 0;  ///< bytes for the strips' work (0: a quarter of what is available)
  unsigned threads = 1;  ///< threads of each strip's triangulation (partition method)
  /// Points a column of cells holds (0: what the memory limit allows; a strip owns 8 columns
  /// and loads one more on either side).
  std::uint64_t column_points = 0;
  /// Called now and then with a phase ("bucketing", "triangulating") and the fraction done.
  std::function<void(const char*, double)> progress;
  /// Called with each file the run writes (each part and the index, under the temporary name
  /// each is written under as soon as that is there, and under its own name just before the
  /// rename puts it there): for a caller that removes them where a signal stops it. The run
  /// removes them itself where it fails.
  std::function<void(const std::string&)> wrote;
};

struct OutOfCoreStats {
  std::uint64_t points = 0;  ///< input points
  std::uint64_t triangles = 0;  ///< triangles written
  std::uint64_t columns = 0, rows = 0, strips = 0;
  std::uint64_t loaded = 0;  ///< points triangulated, summed over the strips' tries
  std::uint64_t retries = 0;  ///< strips triangulated again with more columns
  double time_bucket_s = 0, time_triangulate_s = 0, time_check_s = 0, time_write_s = 0;
};

/// Triangulates the points of `options.input` strip by strip within `options.memory_limit`
/// and writes the parts and their index; throws InputError or IoError with a message (and
/// leaves no part behind) on bad input, a full disk or a limit too small for a strip.
OutOfCoreStats triangulate_out_of_core(const OutOfCoreOptions& options);

}  // namespace ridt
