// The one registry of file formats, keyed by extension (formats.cpp): for each format, each
// role it plays (points in, a triangulation out, a TIN out, ...), with its reader or writer and
// what a file of it holds in that role. Every reader and writer of the tool is found here; the
// help texts, the messages that name the formats and the tables of formats in the README and
// docs/cli.md (`ridt formats --markdown`) are made from it. A new format is its io_*.cpp and
// its row in formats.cpp.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "io_common.hpp"
#include "terrain_io.hpp"

namespace ridt::io::detail {

/// What a triangulation writer is given.
struct TriangulationOut {
  std::span<const Point> points;
  const Triangulation& t;
  int first_index;  ///< of the input .node, for formats numbered as Triangle's
  unsigned threads = 1;  ///< that text formats may format on
  std::span<const VertexId> triangles() const { return std::span(t.triangles).first(3 * t.size()); }
};

/// What a Voronoi writer is given (`box`: what drawings and faces are clipped to).
struct VoronoiOut {
  const std::string& path;
  std::span<const Point> points;
  const Triangulation& t;
  const Voronoi& vd;
  const Box& box;
};

/// What a writer of interpolated values is given: `components` values a query, and for a grid
/// its size (nx by ny, row by row; 0 for scattered queries).
struct ValuesOut {
  const std::string& path;
  std::span<const Point> queries;
  std::span<const double> values;
  std::size_t components, nx, ny;
};

/// One role of a format: its reader or writer (null: the format has not this role), what a file
/// of it holds in this role (for the tables), and whether GDAL's module reads or writes it.
template <class Fn>
struct Role {
  Fn fn{};
  std::string_view holds;
  bool through_gdal = false;
};

// The readers' and writers' calls, a role each. Text is parsed and formatted on `threads`.
using ReadPoints = PointFile (*)(const std::string& path, std::string_view data, unsigned threads);
using WritePoints = void (*)(Writer& out, std::span<const Point> points, int first_index, unsigned threads);
using ReadTriangles = std::vector<VertexId> (*)(const std::string& path, std::string_view data, int first_index,
                                                unsigned threads);
using WriteTriangulation = void (*)(const std::string& path, const TriangulationOut& out);
using WriteVoronoi = void (*)(Writer& out, const VoronoiOut& v);
using WriteValues = void (*)(Writer& out, const ValuesOut& v);
using ReadGraph = Pslg (*)(const std::string& path, std::string_view data, unsigned threads);
using ReadTerrain = Terrain (*)(const std::string& path, const PointFilter& filter, const Columns& columns);
using WriteTin = void (*)(const std::string& path, const Terrain& terrain, const Triangulation& t);
using WriteDem = void (*)(const std::string& path, const Dem& dem, const DemFile& file);
using ReadSize = SizeField (*)(const std::string& path, unsigned threads, double gradation);
/// A role that `ridt mesh` or `ridt check` reads or writes itself, as a family of files named
/// by Triangle's conventions rather than chosen by extension: described, not dispatched.
using Described = bool;

/// A format: its extension ("" stands for any other: text) and its roles.
struct Format {
  std::string_view extension;
  std::string_view name;
  Role<ReadPoints> points_in;
  Role<WritePoints> points_out;
  Role<ReadTriangles> triangles_in;
  Role<WriteTriangulation> triangulation_out;
  Role<WriteVoronoi> voronoi_out;
  Role<WriteValues> values_out;
  Role<ReadGraph> graph_in;  ///< points, segments, holes, regions
  Role<ReadSize> size_in;  ///< a size field for quality meshes
  Role<Described> mesh_files;  ///< read or written by `ridt mesh` (Triangle's files)
  Role<ReadTerrain> terrain_in;
  Role<WriteTin> tin_out;
  Role<WriteDem> dem_out;
  std::string_view gdal_driver;  ///< GDAL's name of the format, for its roles through GDAL
  bool writes_neighbors = false;  ///< triangulation_out reads Triangulation::neighbors
  /// Writes a stretch of the canonically sorted triangles at its place (Options::on_sorted),
  /// `first` its first triangle: for a format whose file is the triangles as they lie, which
  /// the writer then fills while the rest are sorted.
  void (*put_sorted)(Writer& out, std::size_t first, std::span<const VertexId> triangles) = nullptr;
};

/// A role's member and its names: `title` for the tables ("points in"), `what` for messages
/// ("point input"), `commands` the subcommands that take it. With `any_extension` false, text
/// (the format of extension "") is only for a path without an extension: an output whose
/// extension names another format is not written as text.
template <class Fn>
struct RoleName {
  Role<Fn> Format::*role;
  const char* title;
  const char* what;
  const char* commands;
  bool any_extension = true;
};

/// The registered formats.
std::span<const Format> formats();

/// The format of `path` that has `role`; else throws IoError naming the extensions that have it
/// ("unknown point input extension '.x' (use ...)").
template <class Fn>
const Format& format_of(const std::string& path, const RoleName<Fn>& role);

/// "a, b or c": the extensions of the formats with `role` (" or text" where any other is, " or
/// none (text)" where only a path without an extension is); GDAL's formats only where the
/// build has GDAL.
template <class Fn>
std::string extensions_with(const RoleName<Fn>& role) {
  std::vector<std::string> found;
  std::string text;
  for (const Format& f : formats()) {
    const Role<Fn>& r = f.*role.role;
    if (!r.fn || (r.through_gdal && !have_gdal())) continue;
    if (f.extension.empty()) {
      text = role.any_extension ? "text" : "none (text)";
      continue;
    }
    found.emplace_back(f.extension);
  }
  if (!text.empty()) found.push_back(text);
  std::string list;
  for (std::size_t i = 0; i < found.size(); ++i)
    list += (i == 0 ? "" : i + 1 == found.size() ? " or " : ", ") + found[i];
  return list;
}

template <class Fn>
const Format& format_of(const std::string& path, const RoleName<Fn>& role) {
  const std::string ext = extension_of(path);
  for (const Format& f : formats())
    if (f.extension == ext && (f.*role.role).fn) return f;
  for (const Format& f : formats())
    if (role.any_extension && f.extension.empty() && (f.*role.role).fn) return f;
  throw IoError("unknown " + std::string(role.what) + " extension '" + fs::path(path).extension().string() + "' (use " +
                extensions_with(role) + ")");
}

// The roles.
inline constexpr RoleName<ReadPoints> kPointsIn{&Format::points_in, "points in", "point input",
                                                "triangulate, voronoi, interpolate, check"};
inline constexpr RoleName<WritePoints> kPointsOut{&Format::points_out, "points out", "point output", "generate", false};
inline constexpr RoleName<ReadTriangles> kTrianglesIn{&Format::triangles_in, "triangles in", "triangle input",
                                                      "check, interpolate"};
inline constexpr RoleName<WriteTriangulation> kTriangulationOut{&Format::triangulation_out, "triangulation out",
                                                                "output", "triangulate"};
inline constexpr RoleName<WriteVoronoi> kVoronoiOut{&Format::voronoi_out, "Voronoi out", "Voronoi output", "voronoi"};
inline constexpr RoleName<WriteValues> kValuesOut{&Format::values_out, "values out", "values output", "interpolate"};
inline constexpr RoleName<ReadGraph> kGraphIn{&Format::graph_in, "graph in", "planar straight-line graph input",
                                              "mesh"};
inline constexpr RoleName<ReadSize> kSizeIn{&Format::size_in, "size in", "size field input", "mesh"};
inline constexpr RoleName<Described> kMeshFiles{&Format::mesh_files, "mesh files", "mesh file", "mesh, check"};
inline constexpr RoleName<ReadTerrain> kTerrainIn{&Format::terrain_in, "terrain in", "terrain input", "tin, dem"};
inline constexpr RoleName<WriteTin> kTinOut{&Format::tin_out, "TIN out", "TIN", "tin"};
inline constexpr RoleName<WriteDem> kDemOut{&Format::dem_out, "DEM out", "DEM", "dem"};

// Readers and writers of more than one file's code, named in formats.cpp's rows.
void write_ply(const std::string& path, const TriangulationOut& o);  // io_ply.cpp
void write_ply_points(Writer& out, std::span<const Point> points, int first_index, unsigned threads);
Pslg read_poly(const std::string& path, std::string_view text, unsigned threads);  // io_poly.cpp
PointFile read_poly_points(const std::string& path, std::string_view text, unsigned threads);
Pslg read_node_graph(const std::string& path, std::string_view text, unsigned threads);
void write_tin_ply(const std::string& path, const Terrain& terrain, const Triangulation& t);  // io_terrain.cpp
void write_tin_obj(const std::string& path, const Terrain& terrain, const Triangulation& t);
void write_dem_png(const std::string& path, const Dem& dem, const DemFile& file);
SizeField read_size_node(const std::string& path, unsigned threads, double gradation);  // io_size.cpp
SizeField read_size_mesh(const std::string& path, unsigned threads, double gradation);
SizeField read_size_ascii_grid(const std::string& path, unsigned threads, double gradation);
SizeField read_size_gdal(const std::string& path, unsigned threads, double gradation);
Terrain read_las_terrain(const std::string& path, const PointFilter& filter, const Columns& columns);  // io_las.cpp
Terrain read_laz(const std::string& path, const PointFilter& filter, const Columns& columns);
Terrain read_table(const std::string& path, const PointFilter& filter, const Columns& columns);  // io_table.cpp
std::vector<VertexId> read_parts_index(const std::string& path, std::string_view index, int first_index,
                                       unsigned threads);  // io.cpp

}  // namespace ridt::io::detail
