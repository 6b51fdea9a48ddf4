// Stanford PLY (binary, little-endian) for mesh viewers and GIS tools: each vertex x, y, z
// (z = 0) as float64, each face a count of 3 and three uint32 indices from 0.
#include "formats.hpp"

namespace ridt::io::detail {

void write_ply(const std::string& path, const TriangulationOut& o) {
  const std::span<const VertexId> tris = o.triangles();
  check_indices(path, tris, o.points.size(), "a triangle");
  Writer out(path);
  out.put("ply\nformat binary_little_endian 1.0\ncomment ridt: the Delaunay triangulation\nelement vertex ");
  out.put_int(static_cast<std::int64_t>(o.points.size()));
  out.put("\nproperty double x\nproperty double y\nproperty double z\nelement face ");
  out.put_int(static_cast<std::int64_t>(tris.size() / 3));
  out.put("\nproperty list uchar uint vertex_indices\nend_header\n");
  for (const Point& p : o.points) out.put_f64_le(p.x), out.put_f64_le(p.y), out.put_f64_le(0.0);
  for (std::size_t k = 0; k < tris.size(); k += 3) {
    out.put('\3');
    for (int i = 0; i < 3; ++i) out.put_u32_le(tris[k + i]);
  }
  out.commit();
}

// Points alone: the vertices, and no face.
void write_ply_points(Writer& out, std::span<const Point> points, int /*first_index*/, unsigned /*threads*/) {
  out.put("ply\nformat binary_little_endian 1.0\ncomment ridt: points\nelement vertex ");
  out.put_int(static_cast<std::int64_t>(points.size()));
  out.put("\nproperty double x\nproperty double y\nproperty double z\nend_header\n");
  for (const Point& p : points) out.put_f64_le(p.x), out.put_f64_le(p.y), out.put_f64_le(0.0);
}

}  // namespace ridt::io::detail
