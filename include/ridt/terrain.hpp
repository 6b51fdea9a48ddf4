// Terrain: heights carried as values on a triangulation's points, and a raster of them (a DEM)
// made row band by row band, so that the raster never has to lie in memory whole.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "ridt/interpolate.hpp"
#include "ridt/ridt.hpp"

namespace ridt {

/// What the height of points equal in x and y is: the triangulation keeps one of them (the
/// smallest index) and drops the others (Triangulation::duplicates).
enum class Merge { First, Last, Lowest, Highest, Mean };

/// Which returns of a LiDAR pulse a reader keeps (LAS's return number and number of returns).
enum class Returns { All, First, Last, Single };

/// How a DEM cell's value comes from the triangulation.
enum class Surface { Linear, Natural, Nearest };

template <>
struct OptionNames<Merge> {
  static constexpr std::string_view option = "duplicates";
  static constexpr Named<Merge> values[] = {
      {"first", Merge::First, "the height of the point that comes first in the input"},
      {"last", Merge::Last, "the height of the point that comes last"},
      {"lowest", Merge::Lowest, "the lowest height"},
      {"highest", Merge::Highest, "the highest height"},
      {"mean", Merge::Mean, "the mean of the heights"},
  };
};

template <>
struct OptionNames<Returns> {
  static constexpr std::string_view option = "returns";
  static constexpr Named<Returns> values[] = {
      {"all", Returns::All, "every return"},
      {"first", Returns::First, "the first return of each pulse (canopy and roofs)"},
      {"last", Returns::Last, "the last return of each pulse (nearest the ground)"},
      {"single", Returns::Single, "pulses that gave one return only"},
  };
};

template <>
struct OptionNames<Surface> {
  static constexpr std::string_view option = "interpolation";
  static constexpr Named<Surface> values[] = {
      {"linear", Surface::Linear, "the plane of the triangle that holds the cell's centre"},
      {"natural", Surface::Natural, "Sibson's natural-neighbour interpolation (smooth)"},
      {"nearest", Surface::Nearest, "the height of a nearest point"},
  };
};

/// Gives each kept point of `t` (a result of triangulate on n points) the height that `how`
/// makes of its group of equal points: z[kept] is replaced, z has n numbers (a dropped
/// point's own stays as it was). Throws InputError when z's size is not n.
void merge_heights(const Triangulation& t, std::span<double> z, Merge how);

/// A north-up raster: nx columns by ny rows of square cells `cell` wide, its top-left corner at
/// (x0, y1). Row 0 is the northernmost; cell (i, j) has its centre at (x(i), y(j)), the point
/// whose value it holds (GDAL's convention, and gdal_grid's).
struct RasterGrid {
  double x0 = 0, y1 = 0, cell = 1;
  std::size_t nx = 0, ny = 0;

  double x(std::size_t i) const { return x0 + (static_cast<double>(i) + 0.5) * cell; }
  double y(std::size_t j) const { return y1 - (static_cast<double>(j) + 0.5) * cell; }
  std::size_t size() const { return nx * ny; }

  /// The raster of cells `cell` wide over the box [x0, x1] x [y0, y1], its edges on multiples of
  /// `cell` (the box grown out to them; a box of zero width gets one cell). Throws InputError
  /// for a cell that is not positive and finite, a box that is not finite or is inverted, a
  /// raster of more than 2^40 cells, or cells too small for their coordinates (within a few
  /// units in the last place: the centres would not be distinct doubles).
  static RasterGrid around(double x0, double y0, double x1, double y1, double cell);
};

/// What a DEM takes beyond the heights.
struct DemOptions {
  Surface method = Surface::Linear;
  /// A cell whose centre lies in a triangle with a side longer than this gets `nodata`, so that
  /// lakes, gaps and the hull's long edges are not bridged (infinity: none killed); a centre on
  /// a side or corner of a shorter triangle too is that one's.
  double max_edge = std::numeric_limits<double>::infinity();
  /// The value of a cell outside the hull or in a killed triangle.
  double nodata = std::numeric_limits<double>::quiet_NaN();
  unsigned threads = 1;  ///< 0: the machine's hardware threads
  /// Rows a band (Dem::band): 0 for as many as some 64 MiB of doubles hold, a multiple of 64,
  /// so that a raster of up to 8 million cells is one band and needs no sorting of triangles.
  std::size_t band_rows = 0;
};

/// A triangulated terrain that answers a raster band by band: the triangles are sorted once
/// into the bands of rows they touch (4 bytes a triangle and band), and each band is then
/// found by the triangles over it, as interpolate_linear's grid form does (exact orientation
/// tests; a centre on an edge or at a vertex taken once). Every value is the library's
/// interpolation at the cell's centre: interpolate_linear, interpolate_natural_neighbor, or
/// the height of the point nearest_vertex finds. Copies the points, heights and triangles it
/// reads (renumbered for locality: some 48 bytes a point) and keeps a reference to t's
/// neighbours: t must outlive it. Thread-safe for concurrent calls of band().
class Dem {
 public:
  /// Throws InputError for sizes that do not match or a max_edge that is not positive.
  Dem(std::span<const Point> points, const Triangulation& t, std::span<const double> z, const RasterGrid& grid,
      const DemOptions& options = {});

  const RasterGrid& grid() const { return grid_; }
  const DemOptions& options() const { return options_; }

  /// The rows of a band, as the bands are cut (the last may be shorter): band b is rows
  /// [b * band_rows(), min(ny, (b + 1) * band_rows())).
  std::size_t band_rows() const { return band_rows_; }
  std::size_t bands() const { return bands_.empty() ? 0 : bands_.size() - 1; }

  /// Writes band b's values into out (its rows times nx numbers), row by row, west to east.
  void band(std::size_t b, std::span<double> out) const;

  /// All of it (grid().size() numbers, row by row): for rasters that fit in memory. The second
  /// form writes into `out`; throws InputError when its size is not grid().size().
  std::vector<double> all() const;
  void all(std::span<double> out) const;

 private:
  void renumber(std::span<const Point> points, std::span<const VertexId> triangles, std::span<const double> z);
  void bucket();
  VertexId nearest(std::size_t tri, const Point& q) const;

  std::span<const std::int32_t> neighbors_;
  std::vector<Point> points_;  // the triangles' corners, in the order they first meet them
  std::vector<VertexId> triangles_;
  std::vector<double> z_;
  RasterGrid grid_;
  DemOptions options_;
  std::size_t band_rows_ = 0;
  std::vector<std::uint64_t> bands_;  // triangles of band b: members_[bands_[b] .. bands_[b + 1])
  std::vector<std::uint32_t> members_;
  std::vector<std::int32_t> vertex_triangle_;  // nearest: a triangle at each vertex
};

/// A shaded relief of a DEM (nx by ny, row 0 north, cells `cell` wide): grey levels 1 to 255
/// for the light a surface takes from the sun at `azimuth` degrees clockwise from north and
/// `altitude` degrees above the horizon (Horn's slopes, heights times z_factor), 0 where a
/// cell or one of its eight neighbours is `nodata` (NaN matches NaN) or lies outside.
std::vector<std::uint8_t> hillshade(std::span<const double> dem, std::size_t nx, std::size_t ny, double cell,
                                    double nodata, double azimuth = 315, double altitude = 45, double z_factor = 1);

}  // namespace ridt
