// Raw little-endian binary: points as float64 x, y pairs, triangles as uint32 triples.
#include "io_common.hpp"

namespace ridt::io::detail {

PointFile read_bin_points(const std::string& path, std::string_view data) {
  if (data.size() % 16 != 0) {
    fail_file(path, "size " + std::to_string(data.size()) +
                        " bytes is not a multiple of 16 (pairs of float64 x, y)");
  }
  PointFile out;
  const std::size_t n = data.size() / 16;
  out.points.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = load_f64_le(data.data() + 16 * i);
    const double y = load_f64_le(data.data() + 16 * i + 8);
    if (std::isnan(x) || std::isnan(y))
      fail_file(path, "point " + std::to_string(i) + " has a NaN coordinate");
    if (std::isinf(x) || std::isinf(y))
      fail_file(path, "point " + std::to_string(i) + " has an infinite coordinate");
    out.points[i] = {x, y};
  }
  return out;
}

std::vector<VertexId> read_bin_triangles(const std::string& path, std::string_view data) {
  if (data.size() % 12 != 0) {
    fail_file(path, "size " + std::to_string(data.size()) +
                        " bytes is not a multiple of 12 (triples of uint32 vertex indices)");
  }
  std::vector<VertexId> out(data.size() / 4);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = load_u32_le(data.data() + 4 * i);
  return out;
}

void write_bin_points(Writer& out, std::span<const Point> points) {
  for (const Point& p : points) {
    out.put_f64_le(p.x);
    out.put_f64_le(p.y);
  }
}

void write_bin_triangles(Writer& out, std::span<const VertexId> triangles) {
  for (const VertexId v : triangles) out.put_u32_le(v);
}

}  // namespace ridt::io::detail
