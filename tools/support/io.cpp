// Point and triangle files: a .bin point file is mapped into memory and used where it lies;
// other files are read whole into memory and parsed in place with std::from_chars. Output is
// formatted with std::to_chars into a large buffer and written to a temporary file beside the
// target, which is renamed onto the target only when complete.
//
// This file picks the format by the file's extension; each format lives in its own io_*.cpp.
#include "io.hpp"

#include "io_common.hpp"

namespace ridt::io {

using namespace detail;

PointFile read_points(const std::string& path) {
  if (extension_of(path) == ".bin")
    if (std::optional<PointFile> mapped = map_bin_points(path)) return std::move(*mapped);
  return parse_points(read_file_whole(path), path);
}

PointFile parse_points(std::string_view data, const std::string& name) {
  const std::string ext = extension_of(name);
  if (ext == ".node") return read_node(name, data);
  if (ext == ".bin") return read_bin_points(name, data);
  return read_text_points(name, data);
}

void write_points(const std::string& path, std::span<const Point> points) {
  const std::string ext = extension_of(path);
  Writer out(path);
  if (ext == ".bin") {
    write_bin_points(out, points);
  } else if (ext == ".node") {
    write_node(out, points);
  } else {
    write_text_points(out, points);
  }
  out.commit();
}

std::vector<VertexId> read_triangles(const std::string& path, int first_index) {
  if (extension_of(path) == ".parts") return read_parts(path);
  return parse_triangles(read_file_whole(path), path, first_index);
}

std::vector<VertexId> read_parts(const std::string& path) {
  // "ridt parts N", then N part files (.ele, indices from 0), named relative to the index.
  const std::string text = read_file_whole(path);
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
  std::vector<VertexId> out;
  for (std::size_t k = 1; k < lines.size(); ++k) {
    const std::string part = (dir / lines[k]).string();
    if (extension_of(part) != ".ele") fail_file(path, "part " + lines[k] + " is not an .ele file");
    const std::vector<VertexId> t = read_triangles(part, 0);
    out.insert(out.end(), t.begin(), t.end());
  }
  return out;
}

std::vector<VertexId> parse_triangles(std::string_view data, const std::string& name,
                                      int first_index) {
  const std::string ext = extension_of(name);
  if (ext == ".ele") return read_ele(name, data, first_index);
  if (ext == ".bin") return read_bin_triangles(name, data);
  return read_text_triangles(name, data, first_index);
}

void check_triangulation_extension(const std::string& path) {
  const std::string ext = extension_of(path);
  for (const char* known : {".ele", ".neigh", ".off", ".obj", ".svg", ".bin"})
    if (ext == known) return;
  throw IoError("unknown output extension '" + ext +
                "' (use .ele, .neigh, .off, .obj, .svg or .bin)");
}

void write_triangulation(const std::string& path, std::span<const Point> points,
                         const Triangulation& t, int first_index) {
  check_triangulation_extension(path);
  const std::string ext = extension_of(path);
  const std::size_t nt = t.size();
  const std::span<const VertexId> tris = std::span(t.triangles).first(3 * nt);
  if (ext == ".svg") {
    write_svg(path, points, t);
    return;
  }
  if (ext == ".neigh" && t.neighbors.size() < 3 * nt) {
    fail_file(path, "the triangulation has " + std::to_string(t.neighbors.size()) +
                        " neighbour entries for " + std::to_string(nt) + " triangles");
  }
  if (ext == ".off" || ext == ".obj") check_indices(path, tris, points.size(), "a triangle");

  Writer out(path);
  if (ext == ".ele") {
    write_ele(out, tris, first_index);
  } else if (ext == ".neigh") {
    write_neigh(out, std::span(t.neighbors).first(3 * nt), first_index);
  } else if (ext == ".off") {
    write_off(out, points, tris);
  } else if (ext == ".obj") {
    write_obj(out, points, tris);
  } else {  // .bin
    write_bin_triangles(out, tris);
  }
  out.commit();
}

}  // namespace ridt::io
