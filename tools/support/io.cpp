// Point and triangle files: a .bin point file is mapped into memory and used where it lies;
// other files are read whole into memory and parsed in place with std::from_chars. Output is
// formatted with std::to_chars into a large buffer and written to a temporary file beside the
// target, which is renamed onto the target only when complete.
//
// The format comes from the file's extension, through the registry (formats.cpp); each format
// lives in its own io_*.cpp.
#include "io.hpp"

#include "formats.hpp"
#include "io_common.hpp"

namespace ridt::io {

using namespace detail;

PointFile read_points(const std::string& path, unsigned threads) {
  if (extension_of(path) == ".bin")
    if (std::optional<PointFile> mapped = map_bin_points(path)) return std::move(*mapped);
  return FileText(path).parse([&](std::string_view text) { return parse_points(text, path, threads); });
}

PointFile parse_points(std::string_view data, const std::string& name, unsigned threads) {
  return format_of(name, kPointsIn).points_in.fn(name, data, threads);
}

void write_points(const std::string& path, std::span<const Point> points, int first_index, unsigned threads) {
  const Format& f = format_of(path, kPointsOut);
  Writer out(path);
  f.points_out.fn(out, points, first_index, threads);
  out.commit();
}

std::vector<VertexId> read_triangles(const std::string& path, int first_index, unsigned threads) {
  return FileText(path).parse([&](std::string_view text) { return parse_triangles(text, path, first_index, threads); });
}

std::string extension(const std::string& path) { return extension_of(path); }

bool is_parts_index(const std::string& path) { return extension_of(path) == ".parts"; }

namespace {

// The part files that the index `text` at `path` names: "ridt parts N", then N part files (.ele,
// indices from 0, or .bin), named relative to the index.
std::vector<std::string> parts_named(const std::string& path, std::string_view text) {
  std::vector<std::string> lines;
  for_each_line(text, [&](std::size_t, std::string_view line) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.remove_suffix(1);
    if (!line.empty()) lines.emplace_back(line);
  });
  const std::string head = "ridt parts ";
  if (lines.empty() || lines[0].rfind(head, 0) != 0)
    fail_file(path, "not an index of parts (its first line must be \"ridt parts N\")");
  const std::string count = lines[0].substr(head.size());
  if (count.empty() || count.size() > 9 || count.find_first_not_of("0123456789") != std::string::npos ||
      std::stoul(count) != lines.size() - 1)
    fail_file(path, "the index says " + count + " parts but names " + std::to_string(lines.size() - 1));
  const fs::path dir = fs::path(path).parent_path();
  std::vector<std::string> parts;
  for (std::size_t k = 1; k < lines.size(); ++k) {
    parts.push_back((dir / lines[k]).string());
    if (extension_of(parts.back()) != ".ele" && extension_of(parts.back()) != ".bin")
      fail_file(path, "part " + lines[k] + " is neither an .ele nor a .bin file");
  }
  return parts;
}

}  // namespace

std::vector<std::string> part_files(const std::string& path) { return parts_named(path, read_file_whole(path)); }

std::vector<VertexId> detail::read_parts_index(const std::string& path, std::string_view index, int /*first_index*/,
                                               unsigned threads) {
  std::vector<VertexId> out;
  for (const std::string& part : parts_named(path, index)) {
    const std::vector<VertexId> t = read_triangles(part, 0, threads);
    out.insert(out.end(), t.begin(), t.end());
  }
  return out;
}

std::vector<VertexId> parse_triangles(std::string_view data, const std::string& name, int first_index,
                                      unsigned threads) {
  return format_of(name, kTrianglesIn).triangles_in.fn(name, data, first_index, threads);
}

bool triangulation_needs_neighbors(const std::string& path) {
  return format_of(path, kTriangulationOut).writes_neighbors;
}

void write_triangulation(const std::string& path, std::span<const Point> points, const Triangulation& t,
                         int first_index, unsigned threads) {
  format_of(path, kTriangulationOut).triangulation_out.fn(path, {points, t, first_index, threads});
}

SortedOutput::SortedOutput(const std::string& path) : path_(path) {
  const Format& f = format_of(path, kTriangulationOut);
  // A device or a pipe takes its bytes in order only: the file is written after the sort.
  if (f.put_sorted == nullptr || output_target(path).in_place) return;
  writer_ = std::make_unique<Writer>(path);
  put_ = f.put_sorted;
}

SortedOutput::~SortedOutput() = default;

void SortedOutput::put(std::size_t first, std::span<const VertexId> triangles) {
  put_(*writer_, first, triangles);
  triangles_ += triangles.size() / 3;
}

void SortedOutput::commit(const Triangulation& t) {
  if (triangles_ != t.size())
    throw IoError("cannot write " + path_ + ": " + std::to_string(triangles_.load()) + " of " +
                  std::to_string(t.size()) + " triangles came sorted");
  writer_->commit();
}

Pslg read_pslg(const std::string& path, unsigned threads) {
  format_of(path, kGraphIn);  // before reading it
  return FileText(path).parse([&](std::string_view text) { return parse_pslg(text, path, threads); });
}

Pslg parse_pslg(std::string_view data, const std::string& name, unsigned threads) {
  return format_of(name, kGraphIn).graph_in.fn(name, data, threads);
}

void write_voronoi(const std::string& path, std::span<const Point> points, const Triangulation& t, const Voronoi& vd,
                   const Box& box) {
  const Format& f = format_of(path, kVoronoiOut);
  Writer out(path);
  f.voronoi_out.fn(out, {path, points, t, vd, box});
  out.commit();
}

void write_values(const std::string& path, std::span<const Point> queries, std::span<const double> values,
                  std::size_t components, std::size_t nx, std::size_t ny) {
  const Format& f = format_of(path, kValuesOut);
  Writer out(path);
  f.values_out.fn(out, {path, queries, values, components, nx, ny});
  out.commit();
}

}  // namespace ridt::io
