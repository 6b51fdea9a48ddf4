// ridt mesh's files (mesh_files.hpp).
#include "mesh_files.hpp"

#include <algorithm>

#include "command.hpp"

namespace ridt::tool {

void write_mesh(const std::string& path, const triangle::Output& m, const io::MeshFileSet& files, int first_index,
                unsigned threads) {
  if (io::extension(path) == ".svg") {
    Triangulation t;
    t.triangles = m.triangles;
    return io::write_mesh_svg(path, m.vertices, t, m.segments);
  }
  io::MeshFiles f;
  f.files = files;
  f.points = m.vertices;
  f.triangles = m.triangles;
  f.nodes = m.nodes;
  f.attributes = m.triangle_attributes;
  const bool every = !m.edges.empty() || !m.edge_markers.empty();
  f.edges = every ? m.edges : m.segments;
  f.edge_markers = every ? m.edge_markers : m.segment_markers;
  f.point_markers = m.vertex_markers;
  f.point_attributes = m.vertex_attributes;
  f.point_attribute_count = m.attribute_count;
  f.neighbors = m.neighbors;
  f.voronoi_vertices = m.voronoi_vertices, f.voronoi_edges = m.voronoi_edges;
  f.voronoi_directions = m.voronoi_directions, f.voronoi_attributes = m.voronoi_attributes;
  if (files.off) {  // each edge inside is two triangles' side, each on the boundary one's
    const std::size_t corners = m.triangles.size() / static_cast<std::size_t>(m.nodes) * 3;
    std::size_t boundary = 0;
    for (std::size_t k = 0; k < m.triangles.size() / static_cast<std::size_t>(m.nodes); ++k)
      for (int i = 0; i < 3; ++i) boundary += m.neighbors.empty() ? 0 : m.neighbors[3 * k + i] < 0;
    f.edge_count = boundary + (corners - boundary) / 2;
  }
  f.first_index = first_index;
  f.markers = !m.vertex_markers.empty() || m.vertices.empty();
  io::write_mesh_files(path, f, thread_count(threads));
}

}  // namespace ridt::tool
