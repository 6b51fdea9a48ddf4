// The registry of file formats, keyed by extension (formats.cpp): what each format reads and
// writes. io.cpp asks it for the format of a path; a new format is its io_*.cpp and one line in
// formats.cpp.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "io_common.hpp"

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

/// A format: its extension ("" stands for any other: text) and what it can do (null: not).
struct Format {
  std::string_view extension;
  std::string_view description;
  /// Readers of text parse on `threads` threads.
  PointFile (*read_points)(const std::string& path, std::string_view data, unsigned threads);
  std::vector<VertexId> (*read_triangles)(const std::string& path, std::string_view data, int first_index,
                                          unsigned threads);
  /// Text formats format on `threads` threads.
  void (*write_points)(Writer& out, std::span<const Point> points, int first_index, unsigned threads);
  void (*write_triangulation)(const std::string& path, const TriangulationOut& out);
  void (*write_voronoi)(Writer& out, const VoronoiOut& v);
  void (*write_values)(Writer& out, const ValuesOut& v);
  Pslg (*read_pslg)(const std::string& path, std::string_view data, unsigned threads);  ///< points, segments, holes
  bool writes_neighbors = false;  ///< write_triangulation reads Triangulation::neighbors
  /// Writes a stretch of the canonically sorted triangles at its place (Options::on_sorted),
  /// `first` its first triangle: for a format whose file is the triangles as they lie, which
  /// the writer then fills while the rest are sorted.
  void (*put_sorted)(Writer& out, std::size_t first, std::span<const VertexId> triangles) = nullptr;
};

/// The format of `path` that has `role` (a member: &Format::read_points, ...); else throws
/// IoError naming the extensions that have it, `what` naming the role. With `any_extension`
/// false, text (the format of extension "") is only for a path without an extension: an output
/// whose extension names another format is not written as text.
template <class Role>
const Format& format_of(const std::string& path, Role Format::*role, const char* what, bool any_extension = true);

/// The registered formats.
std::span<const Format> formats();

/// "a, b or c": the extensions of the formats with `role` (" or text" where any other is, " or
/// none (text)" where only a path without an extension is: `any_extension` false).
template <class Role>
std::string extensions_with(Role Format::*role, bool any_extension = true) {
  std::string list;
  bool text = false;
  std::vector<std::string_view> found;
  for (const Format& f : formats())
    if (f.*role != nullptr) f.extension.empty() ? void(text = true) : found.push_back(f.extension);
  for (std::size_t i = 0; i < found.size(); ++i)
    list += std::string(i == 0 ? "" : i + 1 == found.size() && !text ? " or " : ", ") + std::string(found[i]);
  return !text ? list : any_extension ? list + " or text" : list + " or none (text)";
}

template <class Role>
const Format& format_of(const std::string& path, Role Format::*role, const char* what, bool any_extension) {
  const std::string ext = extension_of(path);
  for (const Format& f : formats())
    if (f.extension == ext && f.*role != nullptr) return f;
  for (const Format& f : formats())
    if (any_extension && f.extension.empty() && f.*role != nullptr) return f;
  throw IoError("unknown " + std::string(what) + " extension '" + fs::path(path).extension().string() + "' (use " +
                extensions_with(role, any_extension) + ")");
}

}  // namespace ridt::io::detail
