// A drawing of a triangulation: its triangles, hull and points, scaled to a 1000-unit box.
#include "io_common.hpp"

namespace ridt::io::detail {

void write_svg(const std::string& path, std::span<const Point> points, const Triangulation& t) {
  const std::size_t nt = t.size();
  if (nt > kSvgMaxTriangles) {
    fail_file(path,
              std::to_string(nt) + " triangles are too many to draw usefully (at most " +
                  std::to_string(kSvgMaxTriangles) + "); write .off or .ele instead");
  }
  check_indices(path, std::span(t.triangles).first(3 * nt), points.size(), "a triangle");
  check_indices(path, t.hull, points.size(), "the hull");

  // Box of the points, mapped to [0, 1000] along its longer side, y flipped so up is up.
  // Halved coordinates keep the differences finite even for a box wider than the largest double.
  double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
  if (!points.empty()) {
    min_x = max_x = points[0].x;
    min_y = max_y = points[0].y;
    for (const Point& p : points) {
      min_x = std::min(min_x, p.x);
      max_x = std::max(max_x, p.x);
      min_y = std::min(min_y, p.y);
      max_y = std::max(max_y, p.y);
    }
  }
  constexpr double kSide = 1000;
  constexpr double kMargin = 20;
  const double half_w = max_x * 0.5 - min_x * 0.5, half_h = max_y * 0.5 - min_y * 0.5;
  const double half_box = std::max(half_w, half_h);
  const double scale = half_box > 0 ? kSide / half_box : 1;  // per halved unit
  const auto sx = [&](double x) { return (x * 0.5 - min_x * 0.5) * scale; };
  const auto sy = [&](double y) { return (max_y * 0.5 - y * 0.5) * scale; };
  const double width = half_w * scale + 2 * kMargin, height = half_h * scale + 2 * kMargin;
  // Line widths from the mean edge length of a triangulation of this size in the box.
  const double edge = kSide / std::sqrt(static_cast<double>(nt) / 2 + 1);
  const double thin = std::clamp(edge / 25, 0.05, 1.0);
  const double thick = std::max(3 * thin, 1.5);
  const double radius = std::clamp(edge / 10, 0.3, 3.0);

  Writer out(path);
  const auto xy = [&](VertexId v) {
    out.put_fixed(sx(points[v].x), 3);
    out.put(' ');
    out.put_fixed(sy(points[v].y), 3);
  };
  out.put("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"");
  out.put(" viewBox=\"");
  out.put_fixed(-kMargin, 3);
  out.put(' ');
  out.put_fixed(-kMargin, 3);
  out.put(' ');
  out.put_fixed(width, 3);
  out.put(' ');
  out.put_fixed(height, 3);
  out.put("\" width=\"");
  out.put_fixed(width, 0);
  out.put("\" height=\"");
  out.put_fixed(height, 0);
  out.put("\">\n<rect x=\"");
  out.put_fixed(-kMargin, 3);
  out.put("\" y=\"");
  out.put_fixed(-kMargin, 3);
  out.put("\" width=\"100%\" height=\"100%\" fill=\"white\"/>\n");

  if (nt > 0) {
    out.put("<path fill=\"none\" stroke=\"#555\" stroke-linecap=\"round\" stroke-width=\"");
    out.put_fixed(thin, 3);
    out.put("\" d=\"");
    const bool have_neighbors = t.neighbors.size() >= 3 * nt;
    for (std::size_t k = 0; k < nt; ++k) {
      const VertexId* v = &t.triangles[3 * k];
      if (!have_neighbors) {
        out.put('M');
        xy(v[0]);
        out.put('L');
        xy(v[1]);
        out.put('L');
        xy(v[2]);
        out.put('Z');
        continue;
      }
      // Edge v[i] -> v[i+1] lies across from vertex i+2: draw an interior edge once.
      for (int i = 0; i < 3; ++i) {
        const std::int32_t nb = t.neighbors[3 * k + (i + 2) % 3];
        if (nb >= 0 && static_cast<std::size_t>(nb) < k) continue;
        out.put('M');
        xy(v[i]);
        out.put('L');
        xy(v[(i + 1) % 3]);
      }
    }
    out.put("\"/>\n");
  }

  if (!t.hull.empty()) {
    out.put("<polygon fill=\"none\" stroke=\"#c22\" stroke-linejoin=\"round\" stroke-width=\"");
    out.put_fixed(thick, 3);
    out.put("\" points=\"");
    for (std::size_t i = 0; i < t.hull.size(); ++i) {
      if (i > 0) out.put(' ');
      xy(t.hull[i]);
    }
    out.put("\"/>\n");
  }

  if (points.size() <= 20000 && !points.empty()) {
    out.put("<g fill=\"#15c\">\n");
    for (std::size_t i = 0; i < points.size(); ++i) {
      out.put("<circle cx=\"");
      out.put_fixed(sx(points[i].x), 3);
      out.put("\" cy=\"");
      out.put_fixed(sy(points[i].y), 3);
      out.put("\" r=\"");
      out.put_fixed(radius, 3);
      out.put("\"/>\n");
    }
    out.put("</g>\n");
  }
  out.put("</svg>\n");
  out.commit();
}

}  // namespace ridt::io::detail
