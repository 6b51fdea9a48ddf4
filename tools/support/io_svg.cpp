// A drawing of a triangulation: its triangles, hull and points, scaled to a 1000-unit box.
#include "io_common.hpp"

namespace ridt::io::detail {
namespace {

constexpr double kSide = 1000;
constexpr double kMargin = 20;

// The points' box mapped to [0, 1000] along its longer side, y flipped so up is up (ViewMap:
// finite for any finite box). Line widths come from the mean edge length of a triangulation of
// this size in the box.
struct Drawing {
  Drawing(std::span<const Point> pts, std::size_t triangles) : points(pts), map(box(pts)) {
    width = map.width + 2 * kMargin, height = map.height + 2 * kMargin;
    const double edge = kSide / std::sqrt(static_cast<double>(triangles) / 2 + 1);
    thin = std::clamp(edge / 25, 0.05, 1.0);
    thick = std::max(3 * thin, 1.5);
    radius = std::clamp(edge / 10, 0.3, 3.0);
  }
  static ViewMap box(std::span<const Point> points) {
    double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
    if (!points.empty()) min_x = max_x = points[0].x, min_y = max_y = points[0].y;
    for (const Point& p : points) {
      min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
      min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
    }
    return ViewMap(min_x, min_y, max_x, max_y, kSide);
  }
  double sx(double x) const { return map.x(x); }
  double sy(double y) const { return map.y(y); }
  void xy(Writer& out, VertexId v) const {
    out.put_fixed(sx(points[v].x), 3), out.put(' '), out.put_fixed(sy(points[v].y), 3);
  }

  std::span<const Point> points;
  ViewMap map;
  double width = 0, height = 0;
  double thin = 0, thick = 0, radius = 0;
};

void put_header(Writer& out, const Drawing& d) {
  out.put("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"");
  out.put(" viewBox=\"");
  out.put_fixed(-kMargin, 3), out.put(' '), out.put_fixed(-kMargin, 3), out.put(' ');
  out.put_fixed(d.width, 3), out.put(' '), out.put_fixed(d.height, 3);
  out.put("\" width=\""), out.put_fixed(d.width, 0), out.put("\" height=\""), out.put_fixed(d.height, 0);
  out.put("\">\n<rect x=\""), out.put_fixed(-kMargin, 3), out.put("\" y=\""), out.put_fixed(-kMargin, 3);
  out.put("\" width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
}

// Every edge once: edge v[i] -> v[i+1] lies across from vertex i+2, and an interior edge is
// drawn by the triangle with the larger index (without neighbours, each triangle whole).
void put_edges(Writer& out, const Drawing& d, const Triangulation& t) {
  const std::size_t nt = t.size();
  if (nt == 0) return;
  out.put("<path fill=\"none\" stroke=\"#555\" stroke-linecap=\"round\" stroke-width=\"");
  out.put_fixed(d.thin, 3);
  out.put("\" d=\"");
  const bool have_neighbors = t.neighbors.size() >= 3 * nt;
  for (std::size_t k = 0; k < nt; ++k) {
    const VertexId* v = &t.triangles[3 * k];
    if (!have_neighbors) {
      out.put('M'), d.xy(out, v[0]), out.put('L'), d.xy(out, v[1]), out.put('L'), d.xy(out, v[2]), out.put('Z');
      continue;
    }
    for (int i = 0; i < 3; ++i) {
      const std::int32_t nb = t.neighbors[3 * k + (i + 2) % 3];
      if (nb >= 0 && static_cast<std::size_t>(nb) < k) continue;
      out.put('M'), d.xy(out, v[i]), out.put('L'), d.xy(out, v[(i + 1) % 3]);
    }
  }
  out.put("\"/>\n");
}

void put_hull(Writer& out, const Drawing& d, const Triangulation& t) {
  if (t.hull.empty()) return;
  out.put("<polygon fill=\"none\" stroke=\"#c22\" stroke-linejoin=\"round\" stroke-width=\"");
  out.put_fixed(d.thick, 3);
  out.put("\" points=\"");
  for (std::size_t i = 0; i < t.hull.size(); ++i) {
    if (i > 0) out.put(' ');
    d.xy(out, t.hull[i]);
  }
  out.put("\"/>\n");
}

// Segments (pairs of indices) drawn apart: thick, in the hull's colour.
void put_segments(Writer& out, const Drawing& d, std::span<const VertexId> segments) {
  if (segments.empty()) return;
  out.put("<path fill=\"none\" stroke=\"#c22\" stroke-linecap=\"round\" stroke-width=\"");
  out.put_fixed(d.thick, 3);
  out.put("\" d=\"");
  for (std::size_t k = 0; k + 1 < segments.size(); k += 2)
    out.put('M'), d.xy(out, segments[k]), out.put('L'), d.xy(out, segments[k + 1]);
  out.put("\"/>\n");
}

// The points as dots, up to 20,000 of them.
void put_points(Writer& out, const Drawing& d) {
  if (d.points.size() > 20000 || d.points.empty()) return;
  out.put("<g fill=\"#15c\">\n");
  for (const Point& p : d.points) {
    out.put("<circle cx=\""), out.put_fixed(d.sx(p.x), 3), out.put("\" cy=\""), out.put_fixed(d.sy(p.y), 3);
    out.put("\" r=\""), out.put_fixed(d.radius, 3), out.put("\"/>\n");
  }
  out.put("</g>\n");
}

}  // namespace

void write_svg(const std::string& path, std::span<const Point> points, const Triangulation& t,
               std::span<const VertexId> segments) {
  const std::size_t nt = t.size();
  if (nt > kSvgMaxTriangles)
    fail_file(path,
              std::to_string(nt) + " triangles are too many to draw usefully (at most " +
                  std::to_string(kSvgMaxTriangles) + "); write .off or .ele instead");
  check_indices(path, std::span(t.triangles).first(3 * nt), points.size(), "a triangle");
  check_indices(path, t.hull, points.size(), "the hull");
  check_indices(path, segments, points.size(), "a segment");
  const Drawing d(points, nt);
  Writer out(path);
  put_header(out, d);
  put_edges(out, d, t);
  put_hull(out, d, t);
  put_segments(out, d, segments);
  put_points(out, d);
  out.put("</svg>\n");
  out.commit();
}

}  // namespace ridt::io::detail
