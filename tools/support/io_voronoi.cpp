// Voronoi diagrams to files: a drawing (.svg), faces (.off), and the whole structure (.json).
#include "formats.hpp"
#include "io_common.hpp"

namespace ridt::io {
namespace {

using detail::Writer;

// Sutherland-Hodgman against one side of the box at a time.
std::vector<Point> clip(std::vector<Point> poly, const Box& b) {
  auto side = [&](auto inside, auto cut) {
    std::vector<Point> out;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Point& p = poly[k];
      const Point& q = poly[(k + 1) % poly.size()];
      if (inside(p)) out.push_back(p);
      if (inside(p) != inside(q)) out.push_back(cut(p, q));
    }
    poly = std::move(out);
  };
  auto at_x = [](double x) {
    return [x](const Point& p, const Point& q) { return Point{x, p.y + (q.y - p.y) * ((x - p.x) / (q.x - p.x))}; };
  };
  auto at_y = [](double y) {
    return [y](const Point& p, const Point& q) { return Point{p.x + (q.x - p.x) * ((y - p.y) / (q.y - p.y)), y}; };
  };
  side([&](const Point& p) { return p.x >= b.x0; }, at_x(b.x0));
  side([&](const Point& p) { return p.x <= b.x1; }, at_x(b.x1));
  side([&](const Point& p) { return p.y >= b.y0; }, at_y(b.y0));
  side([&](const Point& p) { return p.y <= b.y1; }, at_y(b.y1));
  return poly;
}

void put_point(Writer& out, const Point& p) {
  out.put('[');
  out.put_double(p.x);
  out.put(',');
  out.put_double(p.y);
  out.put(']');
}

}  // namespace

Box box_around(std::span<const Point> points, double margin) {
  Box b;
  if (points.empty()) return {0, 0, 1, 1};
  b = {points[0].x, points[0].y, points[0].x, points[0].y};
  for (const Point& p : points)
    b.x0 = std::min(b.x0, p.x), b.y0 = std::min(b.y0, p.y), b.x1 = std::max(b.x1, p.x), b.y1 = std::max(b.y1, p.y);
  const double w = b.x1 - b.x0 > 0 ? b.x1 - b.x0 : 1, h = b.y1 - b.y0 > 0 ? b.y1 - b.y0 : 1;
  return {b.x0 - margin * w, b.y0 - margin * h, b.x1 + margin * w, b.y1 + margin * h};
}

std::vector<Point> clipped_cell(std::span<const Point> points, const Triangulation& t, const Voronoi& vd, std::size_t c,
                                const Box& box) {
  const auto cell = vd.cell(c);
  std::vector<Point> poly;
  for (const std::int32_t v : cell)
    if (v >= 0) poly.push_back(vd.vertices[static_cast<std::size_t>(v)]);
  if (!cell.empty() && cell.back() == -1) {
    // The rays leave along the outward normals of the hull edges at the site: the last
    // triangle's counter-clockwise side and the first one's clockwise side.
    const VertexId s = vd.cell_site[c];
    auto other = [&](std::int32_t tri, int step) {
      const VertexId* w = &t.triangles[3 * static_cast<std::size_t>(tri)];
      const int i = w[0] == s ? 0 : w[1] == s ? 1 : 2;
      return w[(i + step) % 3];
    };
    const Point& p = points[s];
    const Point& b = points[other(cell[cell.size() - 2], 2)];
    const Point& a = points[other(cell[0], 1)];
    const Point out{p.y - b.y, b.x - p.x}, in{a.y - p.y, p.x - a.x};
    // Far enough that the closing segment stays beyond the box.
    const double size = std::max(
        {box.x1 - box.x0, box.y1 - box.y0, std::fabs(box.x0), std::fabs(box.x1), std::fabs(box.y0), std::fabs(box.y1)});
    auto far = [&](const Point& from, const Point& d) {
      const double len = std::hypot(d.x, d.y);
      const double k = 4 * (size + std::hypot(from.x - p.x, from.y - p.y)) / len;
      return Point{from.x + k * d.x, from.y + k * d.y};
    };
    const Point last = poly.back(), first = poly.front();
    poly.push_back(far(last, out));
    poly.push_back(far(first, in));
  }
  return clip(std::move(poly), box);
}

namespace detail {

void write_voronoi_json(Writer& out, const VoronoiOut& v) {
  const Voronoi& vd = v.vd;
  out.put("{\"vertices\":[");
  for (std::size_t k = 0; k < vd.vertices.size(); ++k) {
    if (k) out.put(',');
    put_point(out, vd.vertices[k]);
  }
  out.put("],\n\"cells\":[");
  for (std::size_t c = 0; c < vd.cells(); ++c) {
    out.put(c ? ",[" : "[");
    const auto cell = vd.cell(c);
    for (std::size_t k = 0; k < cell.size(); ++k) {
      if (k) out.put(',');
      out.put_int(cell[k]);
    }
    out.put(']');
  }
  out.put("],\n\"point_cell\":[");
  for (std::size_t i = 0; i < vd.point_cell.size(); ++i) {
    if (i) out.put(',');
    out.put_int(vd.point_cell[i]);
  }
  out.put("],\n\"ridges\":[");
  for (std::size_t k = 0; k < vd.ridges.size(); ++k) {
    const Ridge& r = vd.ridges[k];
    out.put(k ? ",[" : "[");
    out.put_int(r.a), out.put(','), out.put_int(r.b), out.put(','), out.put_int(r.u), out.put(','), out.put_int(r.v);
    out.put(']');
  }
  out.put("]}\n");
}

namespace {

std::vector<std::vector<Point>> clipped_cells(const VoronoiOut& v) {
  std::vector<std::vector<Point>> cells(v.vd.cells());
  for (std::size_t c = 0; c < v.vd.cells(); ++c) cells[c] = clipped_cell(v.points, v.t, v.vd, c, v.box);
  return cells;
}

}  // namespace

void write_voronoi_off(Writer& out, const VoronoiOut& v) {
  const std::vector<std::vector<Point>> cells = clipped_cells(v);
  std::size_t corners = 0, faces = 0;
  for (const auto& poly : cells) corners += poly.size(), faces += !poly.empty();
  out.put("OFF\n");
  out.put_int(static_cast<std::int64_t>(corners));
  out.put(' ');
  out.put_int(static_cast<std::int64_t>(faces));
  out.put(" 0\n");
  for (const auto& poly : cells)
    for (const Point& p : poly) out.put_double(p.x), out.put(' '), out.put_double(p.y), out.put(" 0\n");
  std::int64_t next = 0;
  for (const auto& poly : cells) {
    if (poly.empty()) continue;
    out.put_int(static_cast<std::int64_t>(poly.size()));
    for (std::size_t k = 0; k < poly.size(); ++k) out.put(' '), out.put_int(next++);
    out.put('\n');
  }
}

// The cells clipped to the box and the sites inside it, the box mapped to 1000 units along its
// longer side, y up.
void write_voronoi_svg(Writer& out, const VoronoiOut& v) {
  if (v.vd.cells() > kSvgMaxTriangles)
    fail_file(v.path,
              std::to_string(v.vd.cells()) + " cells are too many to draw usefully (at most " +
                  std::to_string(kSvgMaxTriangles) + "); write .json or .off instead");
  const Box& box = v.box;
  const ViewMap map(box.x0, box.y0, box.x1, box.y1, 1000);
  auto x = [&](double c) { return map.x(c); };
  auto y = [&](double c) { return map.y(c); };
  out.put("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 ");
  out.put_fixed(map.width, 3), out.put(' '), out.put_fixed(map.height, 3);
  out.put("\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
  out.put("<g fill=\"#dbe9f6\" stroke=\"#2c6fad\" stroke-width=\"0.6\" stroke-linejoin=\"round\">\n");
  for (const auto& poly : clipped_cells(v)) {
    if (poly.empty()) continue;
    out.put("<polygon points=\"");
    for (std::size_t k = 0; k < poly.size(); ++k) {
      if (k) out.put(' ');
      out.put_fixed(x(poly[k].x), 3), out.put(','), out.put_fixed(y(poly[k].y), 3);
    }
    out.put("\"/>\n");
  }
  out.put("</g>\n<g fill=\"#b22222\">\n");
  const double radius = std::clamp(300 / std::sqrt(static_cast<double>(v.points.size()) + 1), 0.3, 4.0);
  for (const Point& p : v.points) {
    if (p.x < box.x0 || p.x > box.x1 || p.y < box.y0 || p.y > box.y1) continue;
    out.put("<circle cx=\""), out.put_fixed(x(p.x), 3), out.put("\" cy=\""), out.put_fixed(y(p.y), 3);
    out.put("\" r=\""), out.put_fixed(radius, 3), out.put("\"/>\n");
  }
  out.put("</g>\n</svg>\n");
}

}  // namespace detail

}  // namespace ridt::io
