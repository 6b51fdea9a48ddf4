// Meshes to files: for viewers .off (0-based indices) and .obj (1-based), with z = 0; and
// Triangle's group of files for one mesh (ridt mesh): .ele, .node, .edge, .neigh, .off and the
// dual's .v.node and .v.edge, written whole or not at all.
#include "io_common.hpp"

#include <functional>

#include "lines.hpp"

namespace ridt::io::detail {

void write_off(Writer& out, std::span<const Point> points, std::span<const VertexId> tris, std::size_t edges) {
  out.put("OFF\n");
  out.put_int(static_cast<std::int64_t>(points.size()));
  out.put(' ');
  out.put_int(static_cast<std::int64_t>(tris.size() / 3));
  out.put(' ');
  out.put_int(static_cast<std::int64_t>(edges));
  out.put('\n');
  for (const Point& p : points) {
    out.put_double(p.x);
    out.put(' ');
    out.put_double(p.y);
    out.put(" 0\n");
  }
  for (std::size_t k = 0; k < tris.size() / 3; ++k) {
    out.put('3');
    for (int i = 0; i < 3; ++i) {
      out.put(' ');
      out.put_int(tris[3 * k + i]);
    }
    out.put('\n');
  }
}

void write_obj(Writer& out, std::span<const Point> points, std::span<const VertexId> tris) {
  for (const Point& p : points) {
    out.put("v ");
    out.put_double(p.x);
    out.put(' ');
    out.put_double(p.y);
    out.put(" 0\n");
  }
  for (std::size_t k = 0; k < tris.size() / 3; ++k) {
    out.put('f');
    for (int i = 0; i < 3; ++i) {
      out.put(' ');
      out.put_int(static_cast<std::int64_t>(tris[3 * k + i]) + 1);
    }
    out.put('\n');
  }
}

}  // namespace ridt::io::detail

namespace ridt::io {

namespace {

// `markers` one an edge (none: 1 each); without `column`, no marker column at all.
void put_edges(detail::Writer& out, std::span<const VertexId> edges, int first_index, unsigned threads,
               std::span<const std::int64_t> markers = {}, bool column = true) {
  out.put_int(static_cast<std::int64_t>(edges.size() / 2));
  out.put(column ? " 1\n" : " 0\n");
  out.put_lines(edges.size() / 2, threads, [&](std::size_t k, TextPart& line) {
    line.put_int(static_cast<std::int64_t>(k) + first_index);
    for (int e = 0; e < 2; ++e) line.put(' '), line.put_int(static_cast<std::int64_t>(edges[2 * k + e]) + first_index);
    if (column) line.put(' '), line.put_int(markers.empty() ? 1 : markers[k]);
    line.put('\n');
  });
}

// Renames the closed writers' files onto their targets; where one fails, the files that this
// call has put where there was none are removed again.
void commit_all(std::vector<std::unique_ptr<detail::Writer>>& out) {
  std::vector<std::string> made;
  try {
    for (const auto& w : out) {
      struct stat st {};
      const bool there = ::stat(w->target().c_str(), &st) == 0;
      w->commit();
      if (!there && !w->in_place()) made.push_back(w->target());
    }
  } catch (...) {
    for (const std::string& f : made) std::remove(f.c_str());
    throw;
  }
}

// The dual's edges as Triangle writes a Voronoi diagram's .v.edge: "i u v", or for a ray
// "i u -1 dx dy"; no marker column.
void put_dual_edges(detail::Writer& out, std::span<const std::int32_t> edges, std::span<const Point> directions,
                    int first_index, unsigned threads) {
  out.put_int(static_cast<std::int64_t>(edges.size() / 2));
  out.put(" 0\n");
  out.put_lines(edges.size() / 2, threads, [&](std::size_t k, TextPart& line) {
    line.put_int(static_cast<std::int64_t>(k) + first_index);
    line.put(' '), line.put_int(std::int64_t{edges[2 * k]} + first_index);
    if (edges[2 * k + 1] >= 0) {
      line.put(' '), line.put_int(std::int64_t{edges[2 * k + 1]} + first_index);
    } else {
      line.put(" -1 "), line.put_double(directions[k].x), line.put(' '), line.put_double(directions[k].y);
    }
    line.put('\n');
  });
}

// The corners of each triangle: the triangles themselves, or the first three of each six-node one.
std::vector<VertexId> corners(std::span<const VertexId> triangles, int nodes) {
  std::vector<VertexId> out;
  out.reserve(triangles.size() / static_cast<std::size_t>(nodes) * 3);
  for (std::size_t k = 0; k < triangles.size(); k += static_cast<std::size_t>(nodes))
    out.insert(out.end(), triangles.begin() + static_cast<std::ptrdiff_t>(k),
               triangles.begin() + static_cast<std::ptrdiff_t>(k + 3));
  return out;
}

}  // namespace

void write_edges(const std::string& path, std::span<const VertexId> edges, int first_index, unsigned threads) {
  detail::Writer out(path);
  put_edges(out, edges, first_index, threads);
  out.commit();
}

void write_elements(const std::string& path, std::span<const VertexId> triangles, std::span<const double> attributes,
                    int first_index, unsigned threads) {
  detail::Writer out(path);
  detail::write_ele(out, triangles, first_index, attributes, threads);
  out.commit();
}

std::vector<std::string> mesh_file_paths(const std::string& ele, const MeshFileSet& set) {
  const std::string base = detail::fs::path(ele).replace_extension().string();
  std::vector<std::string> paths;
  if (set.ele) paths.push_back(ele);
  if (set.node) paths.push_back(base + ".node");
  paths.push_back(base + ".edge");
  if (set.neighbors) paths.push_back(base + ".neigh");
  if (set.off) paths.push_back(base + ".off");
  if (set.voronoi) paths.push_back(base + ".v.node"), paths.push_back(base + ".v.edge");
  return paths;
}

void write_mesh_files(const std::string& ele, const MeshFiles& m, unsigned threads) {
  const MeshFileSet& set = m.files;
  if (set.neighbors && 3 * m.triangles.size() != m.neighbors.size() * static_cast<std::size_t>(m.nodes))
    detail::fail_file(ele,
                      std::to_string(m.neighbors.size()) + " neighbour entries for " +
                          std::to_string(m.triangles.size() / static_cast<std::size_t>(m.nodes)) + " triangles");
  if (set.voronoi && 2 * m.voronoi_directions.size() != m.voronoi_edges.size())
    detail::fail_file(ele, "the dual's edges and their directions differ in number");
  // Every file opened first (a directory in the way is refused before any is written), all
  // written and closed, then renamed together.
  std::vector<std::unique_ptr<detail::Writer>> out;
  for (const std::string& path : mesh_file_paths(ele, set)) out.push_back(std::make_unique<detail::Writer>(path));
  // Two lanes of files written side by side where there are threads: the kernel takes one
  // file's writes at a time (its copy into the page cache, a third of a second for the .ele of
  // 10^7 triangles), so the triangles' file goes on its own while the points' is formatted and
  // written beside it. Each lane formats on the threads given.
  std::size_t next = 0;
  std::vector<std::function<void()>> lanes[2];  // the triangles', the others'
  if (set.ele)
    lanes[0].push_back([&, w = out[next++].get()] {
      detail::write_ele(*w, m.triangles, m.first_index, m.attributes, threads, m.nodes);
    });
  if (set.node)
    lanes[1].push_back([&, w = out[next++].get()] {
      detail::write_node(*w, m.points, m.first_index, threads,
                         m.markers ? m.point_markers : std::span<const std::int64_t>{},
                         {m.point_attributes, m.point_attribute_count});
    });
  lanes[1].push_back(
      [&, w = out[next++].get()] { put_edges(*w, m.edges, m.first_index, threads, m.edge_markers, m.markers); });
  if (set.neighbors)
    lanes[0].push_back([&, w = out[next++].get()] { detail::write_neigh(*w, m.neighbors, m.first_index, threads); });
  if (set.off)
    lanes[1].push_back(
        [&, w = out[next++].get()] { detail::write_off(*w, m.points, corners(m.triangles, m.nodes), m.edge_count); });
  if (set.voronoi) {
    lanes[1].push_back([&, w = out[next++].get()] {
      detail::write_node(*w, m.voronoi_vertices, m.first_index, threads, {},
                         {m.voronoi_attributes, m.point_attribute_count});
    });
    lanes[1].push_back([&, w = out[next++].get()] {
      put_dual_edges(*w, m.voronoi_edges, m.voronoi_directions, m.first_index, threads);
    });
  }
  auto lane = [&](std::size_t k) {
    for (const auto& task : lanes[k]) task();
  };
  if (threads > 1)
    detail::on_pieces(2, lane);
  else
    lane(0), lane(1);
  for (const auto& w : out) w->close();
  commit_all(out);
}

}  // namespace ridt::io
