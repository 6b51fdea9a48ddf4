// Point and triangle files, chosen by extension.
//
// Points in:  .node (Triangle's format: "n 2 attributes markers" then "i x y ..."; its first
//             index, 0 or 1, is kept), .bin (raw little-endian float64 x, y pairs), anything
//             else text (one point a line, "x y" or "x,y", '#' starts a comment).
// Points out: .node, .bin, .ply, .csv ("x,y"), text ("x y" with the shortest exact decimal
//             form) for .txt, .xy, .pts, .dat or no extension; another extension is refused.
// Triangles:  .ele (Triangle's format, numbered from the input .node's first index, else 0),
//             .neigh (Triangle's neighbour file, -1 on the hull), .off, .obj, .svg (a drawing),
//             .bin (little-endian uint32 triples). Every file is written to a temporary
//             name beside the target and renamed, so a failure never leaves half a file; a
//             device or a pipe is written in place (Writer, writer.hpp).
#pragma once

#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "ridt/regions.hpp"
#include "ridt/ridt.hpp"
#include "ridt/size_field.hpp"
#include "ridt/voronoi.hpp"

namespace ridt::io::detail {

/// Mappings watched for a file that shrinks while it is read (mapped.cpp): a fault past its new
/// end reads zeros, and marks the mapping, where it would end the process with SIGBUS. The slot
/// of a watch, or -1 where none is free (the mapping is then read unwatched).
int watch_mapping(const void* data, std::size_t bytes);
void unwatch_mapping(int slot);
/// Whether a fault was taken in the watched mapping `slot`, or in any since the process began.
bool mapping_shrank(int slot);
bool any_mapping_shrank();
/// any_mapping_shrank false again (for tests, which go on in one process).
void forget_shrunk_mappings();

}  // namespace ridt::io::detail

namespace ridt::io {

/// A file that cannot be read or written, or malformed content; the message names the file
/// and, for text, the line. A kind of the library's IoError (ridt.hpp), which the library
/// throws for files it cannot read or write alone: Python raises this one as ValueError.
struct IoError : ridt::IoError {
  using ridt::IoError::IoError;
};

/// Points read from a file. A .bin file is mapped into memory as it lies (on a little-endian
/// machine; read only, no copy), other formats are parsed into memory the PointFile owns;
/// either way `points` stays valid while the PointFile lives. Movable, not copyable.
class PointFile {
 public:
  PointFile() = default;
  explicit PointFile(std::vector<Point> parsed, int first = 0)
      : points(parsed), first_index(first), parsed_(std::move(parsed)) {}
  /// Points that lie in memory that `owner` keeps (a mapping).
  PointFile(std::shared_ptr<const void> owner, std::span<const Point> mapped)
      : points(mapped), owner_(std::move(owner)) {}
  PointFile(PointFile&&) noexcept = default;
  PointFile& operator=(PointFile&&) noexcept = default;
  PointFile(const PointFile&) = delete;
  PointFile& operator=(const PointFile&) = delete;

  std::span<const Point> points;
  int first_index = 0;  ///< numbering of a .node file (0 or 1); 0 for other formats

  /// The points in a vector: the parsed one itself (`points` then empty), or a copy of a
  /// mapping's.
  std::vector<Point> vector() && {
    if (parsed_.empty() || parsed_.data() != points.data()) return {points.begin(), points.end()};
    points = {};
    return std::move(parsed_);
  }

 private:
  std::vector<Point> parsed_;  // moving a vector keeps its storage: `points` stays valid
  std::shared_ptr<const void> owner_;
};

/// A planar straight-line graph (Triangle's .poly): points, segments between them (pairs of
/// 0-based indices), seeds of holes, regions (x, y, attribute, maximum area) as read.
struct Pslg {
  std::vector<Point> points;
  std::vector<VertexId> segments;
  std::vector<Point> holes;
  std::vector<std::array<double, 4>> regions;
  int first_index = 0;  ///< the file's numbering (0 or 1), for the files written from it
  std::string node_file;  ///< the .node file beside it that the points came from, where it lists none
  std::vector<std::int64_t> segment_markers;  ///< one a segment where the file gives them, else none
  /// The vertices' attributes (`vertex_attributes` a point, row by row) and boundary markers
  /// where the file gives them (else none).
  std::size_t vertex_attributes = 0;
  std::vector<double> point_attributes;
  std::vector<std::int64_t> point_markers;
};

/// Reads a .poly file (its points from the .node file beside it where it lists none); throws
/// IoError on malformed content, an index out of range, a count that does not match. Its lines
/// are parsed on `threads` threads, as every text reader's here are: the same result, and the
/// same first error, as on one.
Pslg read_pslg(const std::string& path, unsigned threads = 1);

/// A size field for quality meshes (`ridt mesh --size`), by extension: a .node's points with
/// the size their first attribute; a .ele and the .node beside it (a background mesh); an ESRI
/// ASCII grid (.asc); a GDAL raster (.tif, .tiff, .img) where the build has GDAL; its values
/// graded to `gradation` (SizeField::on_grid). Throws IoError.
SizeField read_size_field(const std::string& path, unsigned threads = 1, double gradation = 0);
/// The extensions read_size_field reads ("a, b or c").
std::string size_formats();

/// The same for a file's content already in memory; `name` picks the format by its extension.
Pslg parse_pslg(std::string_view data, const std::string& name, unsigned threads = 1);

/// Draws a constrained triangulation or mesh as .svg, its segments' edges (pairs of indices)
/// thick and red apart from the other edges; throws IoError past kSvgMaxTriangles.
void write_mesh_svg(const std::string& path, std::span<const Point> points, const Triangulation& t,
                    std::span<const VertexId> edges);

/// Reads Triangle's .edge file ("edges [markers]", then "i a b [marker]" numbered from
/// `first_index`, each end one of `points`) as pairs of 0-based indices, and where `markers`
/// is not null each edge's marker into it (none where the file has no markers); throws IoError.
std::vector<VertexId> read_edge_file(const std::string& path, std::size_t points, int first_index,
                                     std::vector<std::int64_t>* markers = nullptr);

/// Reads Triangle's .area file ("triangles", then "i max_area" numbered from `first_index`, a
/// bound of 0 or below meaning none) for a mesh of `triangles`; throws IoError.
std::vector<double> read_area_file(const std::string& path, std::size_t triangles, int first_index);

/// Triangle's .area text (`name` stands for it in messages) as read_area_file reads a file; with
/// `triangles` none, for a mesh of any number of triangles; with `first_index` -1, its records
/// numbered from the first's index (0 or 1).
std::vector<double> parse_area_text(std::string_view text, const std::string& name,
                                    std::optional<std::size_t> triangles, int first_index);

/// The edges and rays of an .edge file (parse_edge_text).
struct EdgeText {
  std::vector<VertexId> edges;  ///< pairs of 0-based indices
  std::vector<std::int64_t> markers;  ///< one an edge where the header declares markers, else none
  std::vector<VertexId> ray_origins;  ///< one a ray, 0-based
  std::vector<Point> ray_directions;  ///< one a ray
};

/// Triangle's .edge text (`name` stands for it in messages): "edges [markers]", then records
/// "i a b [marker]" or, as a Voronoi diagram's .v.edge has them, rays "i a -1 dx dy [marker]"
/// (from vertex a along (dx, dy)). The records are numbered from the first's index (0 or 1),
/// their ends from `first_index`, each end one of `points`; a ray's marker is read and not
/// kept. Throws IoError.
EdgeText parse_edge_text(std::string_view text, const std::string& name, std::size_t points, int first_index);

/// Triangle's .poly text (`name` stands for it in messages) as read_pslg reads a .poly file,
/// except that where it lists no vertices they come from `node`, the text of its .node file
/// (`node_name` in messages), not from a file beside it; IoError where `node` is none then.
Pslg parse_poly_text(std::string_view text, const std::string& name, std::optional<std::string_view> node,
                     const std::string& node_name, unsigned threads = 1);

/// Triangle's .node text (`name` stands for it in messages) as read_pslg reads a .node file: a
/// graph of its points alone, with their attributes and markers.
Pslg parse_node_text(std::string_view text, const std::string& name, unsigned threads = 1);

/// Triangle's .ele text (`name` stands for it in messages) as read_elements reads a file, with
/// every attribute of each triangle into `attributes` (`attribute_count` a triangle, the number
/// its header declares, row by row).
std::vector<VertexId> parse_elements(std::string_view text, const std::string& name, int first_index,
                                     std::vector<double>& attributes, std::size_t& attribute_count,
                                     std::vector<VertexId>& middles, unsigned threads = 1);

/// Triangle's .neigh text (`name` stands for it in messages): "triangles 3", then records
/// "i n1 n2 n3" numbered from the first's index (0 or 1), each neighbour -1 (none) or a triangle
/// numbered from `first_index` (-1: as the records are); returns the neighbours, three a
/// triangle, 0-based, -1 for none. Throws IoError.
std::vector<std::int32_t> parse_neighbors(std::string_view text, const std::string& name, int first_index,
                                          unsigned threads = 1);

/// Reads Triangle's .ele file as read_triangles does, each triangle's first attribute into
/// `attributes` (left empty where the file has none), and, from a six-node file (-o2), each
/// triangle's corners returned and its other three nodes (the middles of the edges across from
/// its corners) into `middles` (left empty for a three-node file).
std::vector<VertexId> read_elements(const std::string& path, int first_index, std::vector<double>& attributes,
                                    std::vector<VertexId>& middles, unsigned threads = 1);

/// Writes edges (pairs of 0-based indices) as Triangle's .edge file, numbered from
/// `first_index`, each with boundary marker 1 (they are segments); formatted on `threads` threads.
void write_edges(const std::string& path, std::span<const VertexId> edges, int first_index, unsigned threads = 1);

/// Which of a mesh's files ridt mesh writes beside OUT.ele (Triangle's switches in brackets).
struct MeshFileSet {
  bool ele = true, node = true;  ///< OUT.ele, OUT.node (-E, -N: not written)
  bool neighbors = false;  ///< OUT.neigh (-n)
  bool off = false;  ///< OUT.off, the triangles for a viewer (-g)
  bool voronoi = false;  ///< OUT.v.node and OUT.v.edge, the mesh's dual (-v)
};

/// A mesh as Triangle writes it (ridt mesh).
struct MeshFiles {
  MeshFileSet files;
  std::span<const Point> points;  ///< every vertex: OUT.node
  std::span<const VertexId> triangles;  ///< OUT.ele: `nodes` a triangle
  int nodes = 3;  ///< 3, or 6 (Triangle's -o2: second_order's triangles)
  std::span<const double> attributes;  ///< one a triangle (Triangle's -A), or none
  std::span<const VertexId> edges;  ///< the segments' edges, pairs of indices: OUT.edge
  std::span<const std::int64_t> edge_markers;  ///< one an edge (none: 1 each)
  std::span<const std::int64_t> point_markers;  ///< one a point, or none (no marker column)
  std::span<const double> point_attributes;  ///< `point_attribute_count` a point, row by row
  std::size_t point_attribute_count = 0;
  std::span<const std::int32_t> neighbors;  ///< three a triangle: OUT.neigh (files.neighbors)
  /// OUT.v.node and OUT.v.edge (files.voronoi): vertex t the circumcentre of triangle t; an edge
  /// (u, v) joins two of them, or where v is -1 is a ray from u along its direction.
  std::span<const Point> voronoi_vertices;
  std::span<const std::int32_t> voronoi_edges;  ///< pairs
  std::span<const Point> voronoi_directions;  ///< one an edge ((0, 0) for a segment)
  std::span<const double> voronoi_attributes;  ///< `point_attribute_count` a vertex, row by row
  std::size_t edge_count = 0;  ///< the mesh's edges, for OUT.off's header
  int first_index = 0;  ///< the numbering of every file but OUT.off (which counts from 0)
  bool markers = true;  ///< boundary markers in OUT.node and OUT.edge (Triangle's -B: none)
};

/// The files write_mesh_files writes for OUT.ele `ele`: it (unless not `set.ele`), then
/// OUT.node (unless not `set.node`), OUT.edge, and as `set` asks OUT.neigh, OUT.off, OUT.v.node
/// and OUT.v.edge.
std::vector<std::string> mesh_file_paths(const std::string& ele, const MeshFileSet& set);

/// Writes the mesh's files (mesh_file_paths), all or none: each is written under a temporary
/// name and all are renamed once all are written; IoError where one cannot be (a directory in
/// its place, among others), and then no file that was not there is left.
void write_mesh_files(const std::string& ele, const MeshFiles& m, unsigned threads = 1);

/// Writes triangles as Triangle's .ele file, numbered from `first_index`, with one attribute a
/// triangle where `attributes` is not empty (Triangle's -A); formatted on `threads` threads.
void write_elements(const std::string& path, std::span<const VertexId> triangles, std::span<const double> attributes,
                    int first_index, unsigned threads = 1);

/// The extensions of each kind of file, for a help text ("a, b or text"), from the registry
/// (formats.cpp).
std::string point_formats();
std::string point_output_formats();
std::string triangle_formats();
std::string triangulation_formats();
std::string voronoi_formats();
std::string values_formats();

/// Every format and what it holds in each role, from the registry: as text for a terminal, or
/// as the Markdown table of docs/cli.md; `summary`: a line a role (the README's table).
std::string formats_table(bool markdown, bool summary);

/// Reads points; throws IoError on a missing file, a malformed line, a NaN or infinite
/// coordinate, or a .node count that does not match. Text is parsed on `threads` threads.
PointFile read_points(const std::string& path, unsigned threads = 1);

/// The same for a file's content already in memory; `name` picks the format by its extension
/// and stands for the file in messages.
PointFile parse_points(std::string_view data, const std::string& name, unsigned threads = 1);

/// Writes points (format by extension: .node, .bin, .ply (vertices alone), .csv ("x,y" lines),
/// text for .txt, .xy, .pts, .dat and no extension; IoError naming these for another one);
/// text is formatted on `threads` threads.
void write_points(const std::string& path, std::span<const Point> points, int first_index = 0, unsigned threads = 1);

/// Reads triangles (.ele, .bin, or text with three indices a line) as 0-based indices;
/// `first_index` is the numbering of .ele and text files. Text is parsed on `threads` threads.
/// An index of a distributed or out-of-core run's parts (.parts: "ridt parts N", then the N
/// part files, .ele (0-based) or .bin, named relative to the index) gives the parts' triangles
/// one after another.
std::vector<VertexId> read_triangles(const std::string& path, int first_index, unsigned threads = 1);
/// A file's extension in lower case, as the formats are chosen (".tif" for "dem.TIF").
std::string extension(const std::string& path);
/// Whether `path` names an index of parts (.parts).
bool is_parts_index(const std::string& path);
/// The part files that a .parts index names, in its order, each checked to be .ele or .bin.
std::vector<std::string> part_files(const std::string& path);

/// The same for content in memory (`name` as for parse_points).
std::vector<VertexId> parse_triangles(std::string_view data, const std::string& name, int first_index,
                                      unsigned threads = 1);

/// Whether the triangulation format of `path` writes the neighbours (else the triangulation
/// need not find them: Options::neighbors); throws IoError unless write_triangulation knows
/// its extension.
bool triangulation_needs_neighbors(const std::string& path);

/// Writes a triangulation (format by extension); indices start at `first_index` in .ele,
/// .neigh and .off/.obj keep their own conventions (0-based and 1-based). Text is formatted on
/// `threads` threads.
void write_triangulation(const std::string& path, std::span<const Point> points, const Triangulation& t,
                         int first_index, unsigned threads = 1);

class Writer;

/// A triangulation file written while the canonical sort puts the triangles in place
/// (Options::on_sorted), where its format is the triangles as they lie (.bin): opened before
/// the triangulation, its writing overlapped with the sort's, renamed onto `path` by commit.
/// Left uncommitted (an error, an exception), the temporary file is removed.
class SortedOutput {
 public:
  /// For `path`, where its format can be so written; else nothing (active() false).
  explicit SortedOutput(const std::string& path);
  SortedOutput(const SortedOutput&) = delete;
  SortedOutput& operator=(const SortedOutput&) = delete;
  ~SortedOutput();

  bool active() const { return writer_ != nullptr; }
  /// What Options::on_sorted calls; the SortedOutput must outlive the triangulation.
  void put(std::size_t first, std::span<const VertexId> triangles);
  /// Checks that every one of t's triangles came, and renames the file onto its path.
  void commit(const Triangulation& t);

 private:
  std::string path_;
  std::unique_ptr<Writer> writer_;
  void (*put_)(Writer&, std::size_t, std::span<const VertexId>) = nullptr;
  std::atomic<std::size_t> triangles_{0};
};

/// An axis-parallel box (the library's, ridt/regions.hpp).
using Box = ridt::regions::Box;

/// The points' bounding box grown by `margin` of its size on every side (a box of one point
/// or a line grows by 1 where it is flat).
Box box_around(std::span<const Point> points, double margin);

/// Cell c of `vd` clipped to `box`, counter-clockwise (empty when it misses the box);
/// `t` is the triangulation the diagram came from (its hull edges carry the rays).
std::vector<Point> clipped_cell(std::span<const Point> points, const Triangulation& t, const Voronoi& vd, std::size_t c,
                                const Box& box);

/// Writes a Voronoi diagram: .svg (the cells clipped to `box`, and the sites), .off (each cell
/// clipped to `box` a face) or .json (vertices, cells with -1 at infinity, each point's cell,
/// ridges as [a, b, u, v]).
void write_voronoi(const std::string& path, std::span<const Point> points, const Triangulation& t, const Voronoi& vd,
                   const Box& box);

/// Reads values, one row of `components` numbers a point: text (numbers apart by white space or
/// a comma, '#' comments) or .bin (little-endian float64); `components` 0 means one row a line
/// decides it (text) or 1 (.bin). Returns the numbers and sets `components`.
std::vector<double> read_values(const std::string& path, std::size_t& components);

/// Reads weighted points, rows x y w as read_values reads them, into `points` and `weights`
/// (IoError where a row has not three numbers).
void read_weighted(const std::string& path, std::vector<Point>& points, std::vector<double>& weights);

/// Writes values at queries: .csv ("x,y,v1,...", a header line first), .bin (float64 values,
/// row by row) or, for a grid of nx by ny (nx, ny > 0) of one component, .png (a colour map
/// from the smallest to the largest finite value, transparent where there is none).
void write_values(const std::string& path, std::span<const Point> queries, std::span<const double> values,
                  std::size_t components, std::size_t nx = 0, std::size_t ny = 0);

/// The largest triangulation that write_triangulation draws as .svg.
inline constexpr std::size_t kSvgMaxTriangles = 200000;

}  // namespace ridt::io
