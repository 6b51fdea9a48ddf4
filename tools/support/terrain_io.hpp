// Terrain files: points with heights in (LAS, tables with a header, GDAL's vector layers), a
// TIN with heights and a DEM raster out. LAS and tables are read here; GDAL's formats where the
// build has GDAL, through its module (tools/gdal/, loaded by io_gdal.cpp; have_gdal() says).
//
// LAS:    1.0 to 1.4, point formats 0 to 10, scale and offset applied, the 1.4 header's 64-bit
//         count, the CRS from the OGC WKT record or the GeoTIFF keys' EPSG code (VLR or EVLR);
//         filtered by classification and return. LAZ (compressed) is refused with a message.
// Tables: .csv, .txt, .xyz (and any other text): one point a line, fields apart by commas,
//         semicolons, tabs or spaces (the first line decides), an optional header naming the
//         columns; x, y, z found by name or given by name or 1-based number.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "io.hpp"
#include "ridt/terrain.hpp"

namespace ridt::io {

/// Points with heights, and their coordinate reference system: WKT, "EPSG:n", or empty when
/// the file says none.
struct Terrain {
  std::vector<Point> points;
  std::vector<double> z;
  std::string crs;
};

/// Which LAS points are read: those whose classification is one of `classes` (all when empty;
/// 2 is ground) and whose return `returns` keeps; withheld points only when `withheld`.
struct PointFilter {
  std::vector<int> classes;
  Returns returns = Returns::All;
  bool withheld = false;
};

/// The columns of a table that hold x, y and z: each a header's name (any case) or a 1-based
/// column number; empty: recognised by name (x/easting/lon, y/northing/lat,
/// z/elevation/height/alt), else the first three.
struct Columns {
  std::string x, y, z;
};

/// What a LAS file's header says.
struct LasHeader {
  int major = 1, minor = 0, format = 0;
  std::size_t record_length = 0, data_offset = 0;
  std::uint64_t count = 0;
  double scale[3] = {1, 1, 1}, offset[3] = {0, 0, 0};
  std::string crs;
};

/// The header of a LAS file in memory; throws IoError for anything that is not a LAS 1.0-1.4
/// file whose points lie within `data` (naming what is wrong: truncated, compressed, ...).
LasHeader parse_las_header(std::string_view data, const std::string& name);

/// The points of a LAS file in memory that `filter` keeps; throws as parse_las_header.
Terrain parse_las(std::string_view data, const std::string& name, const PointFilter& filter = {});

/// The same from a file (mapped into memory, not copied).
Terrain read_las(const std::string& path, const PointFilter& filter = {});

/// A table's points (see the file's head). The first line is a header (the columns' names) when
/// none of its coordinate fields (those --columns numbers, else the first three) is a number, or
/// when `columns` names a column; a row when all are. Every line has as many fields as the
/// first. Throws IoError naming the line of a bad field, of a row of another width, of a first
/// line that is neither, a column that is not there, or a table without a z column.
Terrain parse_table(std::string_view text, const std::string& name, const Columns& columns = {});

/// Points with heights from any of the formats, chosen by extension: .las, .laz (refused),
/// GDAL's vector formats (.gpkg, .shp, .geojson, .json, .fgb, .gml, .kml, .sqlite) where the
/// build has GDAL, else a table. `columns.z` names a field of a GDAL layer whose points have
/// no z.
Terrain read_terrain(const std::string& path, const PointFilter& filter = {}, const Columns& columns = {});

/// True where the build reads and writes GDAL's formats.
bool have_gdal();

/// The extensions read_terrain reads, those write_tin writes and those write_dem writes, for a
/// help text.
std::string terrain_formats();
std::string tin_formats();
std::string dem_formats();

/// Writes a TIN: .ply and .obj with z (here); a GDAL vector layer (.gpkg, .shp, .geojson, .fgb,
/// ...) of triangles as PolygonZ with the CRS, where the build has GDAL. Throws IoError.
void write_tin(const std::string& path, const Terrain& terrain, const Triangulation& t);

/// What write_dem writes besides the heights.
struct DemFile {
  std::string crs;
  bool float32 = false;  ///< Float32 cells (else Float64)
  std::function<void(double)> progress;  ///< told the fraction written, band by band
};

/// Writes a DEM band by band as it is interpolated: GeoTIFF (tiled, DEFLATE-compressed,
/// BigTIFF when large) or any GDAL raster format by extension, the CRS and nodata set; where
/// the build has GDAL. A .png is a hillshade (quick look, no GDAL needed; the whole raster in
/// memory). Nothing is left at `path` on failure. Throws IoError.
void write_dem(const std::string& path, const Dem& dem, const DemFile& file);

/// Writes the DEM's hillshade (sun in the north-west, 45 degrees high) as a grey .png, transparent
/// where there is no height; IoError for another extension. Nothing is left at `path` on failure.
void write_hillshade(const std::string& path, const Dem& dem);

namespace detail {

/// What GDAL does for the terrain formats, from a module of its own (libridt_gdal.so, built
/// from tools/gdal/): loaded on first use, so that the tool starts without loading GDAL's
/// hundred-odd libraries (some 40 ms) when it writes no GIS format. `driver` is GDAL's name of
/// the format (io_gdal.cpp picks it by extension).
/// A raster's first band and where its cells' centres lie: (x0, y0) the first cell's (the top
/// left of a north-up raster), (x1, y1) the last's, rows of nx cells, ny of them.
struct RasterIn {
  std::vector<double> values;
  std::size_t nx = 0, ny = 0;
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct GdalModule {
  Terrain (*read_ogr)(const std::string& path, const Columns& columns);
  void (*write_tin)(const std::string& path, const char* driver, const Terrain& terrain, const Triangulation& t);
  /// The raster of `grid` whose band b (rows [b * band_rows, ...)) `band` fills.
  void (*write_dem)(const std::string& path, const char* driver, const RasterGrid& grid, double nodata,
                    const DemFile& file, std::size_t band_rows,
                    const std::function<void(std::size_t, std::span<double>)>& band);
  /// A north-up raster's first band; IoError where a cell has the band's nodata value.
  void (*read_raster)(const std::string& path, RasterIn& out);
  /// The module's own list of temporary files (temporaries.hpp), emptied: async-signal-safe.
  void (*remove_temporaries)() noexcept;
};

/// The module, loaded once; IoError naming `path` where the build has none or it cannot be
/// loaded (the message says why).
const GdalModule& gdal_module(const std::string& path);

Terrain read_ogr(const std::string& path, const Columns& columns);
void write_tin_ogr(const std::string& path, const Terrain& terrain, const Triangulation& t);
void write_dem_gdal(const std::string& path, const Dem& dem, const DemFile& file);

}  // namespace detail

}  // namespace ridt::io
