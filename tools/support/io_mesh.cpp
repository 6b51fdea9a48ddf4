// Surface meshes for viewers: .off (0-based indices) and .obj (1-based), with z = 0.
#include "io_common.hpp"

namespace ridt::io::detail {

void write_off(Writer& out, std::span<const Point> points, std::span<const VertexId> tris) {
  out.put("OFF\n");
  out.put_int(static_cast<std::int64_t>(points.size()));
  out.put(' ');
  out.put_int(static_cast<std::int64_t>(tris.size() / 3));
  out.put(" 0\n");
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
