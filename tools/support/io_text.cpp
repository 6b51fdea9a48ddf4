// Text files: "x y" or "x,y" a line for points, "a b c" for triangles; '#' starts a comment.
#include "io_common.hpp"
#include "lines.hpp"

namespace ridt::io::detail {

PointFile read_text_points(const std::string& path, std::string_view text, unsigned threads) {
  const LinePieces lines(without_bom(text), threads);
  std::vector<Point> points(lines.size());
  lines.visit([&](std::size_t k, std::size_t line_no, std::string_view line) {
    Fields f{line, true};
    std::string_view a, b, extra;
    const bool two = f.next(a) && f.next(b) && !f.next(extra) && !f.bad;
    const auto format_error = [&] { return "expected two numbers \"x y\" or \"x,y\", got " + quoted(line); };
    if (!two) fail_line(path, line_no, format_error());
    // Both fields' syntax first, so that "1e999 abc" is a format error, not a range one.
    double x = 0, y = 0;
    const Parse px = parse_double(a, x), py = parse_double(b, y);
    if (px != Parse::Ok || py != Parse::Ok) {
      if (px == Parse::Bad || py == Parse::Bad) fail_line(path, line_no, format_error());
      const std::string_view bad = px != Parse::Ok ? a : b;
      fail_line(path, line_no, "coordinate " + quoted(bad) + " is out of range");
    }
    if (std::isnan(x) || std::isnan(y)) fail_line(path, line_no, "coordinate is NaN");
    if (std::isinf(x) || std::isinf(y)) fail_line(path, line_no, "coordinate is infinite");
    points[k] = {x, y};
  });
  return PointFile(std::move(points));
}

std::vector<VertexId> read_text_triangles(const std::string& path, std::string_view text, int first_index,
                                          unsigned threads) {
  const LinePieces lines(without_bom(text), threads);
  std::vector<VertexId> out(3 * lines.size());
  lines.visit([&](std::size_t k, std::size_t line_no, std::string_view line) {
    Fields f{line, true};
    std::string_view a, b, c, extra;
    if (!(f.next(a) && f.next(b) && f.next(c) && !f.next(extra) && !f.bad)) {
      fail_line(path, line_no, "expected three vertex indices \"a b c\", got " + quoted(line));
    }
    out[3 * k] = vertex(path, line_no, a, first_index);
    out[3 * k + 1] = vertex(path, line_no, b, first_index);
    out[3 * k + 2] = vertex(path, line_no, c, first_index);
  });
  return out;
}

namespace {

// One point a line, its coordinates apart by `separator`.
void put_points(Writer& out, std::span<const Point> points, unsigned threads, char separator) {
  out.put_lines(points.size(), threads, [&](std::size_t k, TextPart& line) {
    line.put_double(points[k].x);
    line.put(separator);
    line.put_double(points[k].y);
    line.put('\n');
  });
}

}  // namespace

void write_text_points(Writer& out, std::span<const Point> points, int /*first_index*/, unsigned threads) {
  put_points(out, points, threads, ' ');
}

void write_csv_points(Writer& out, std::span<const Point> points, int /*first_index*/, unsigned threads) {
  put_points(out, points, threads, ',');
}

}  // namespace ridt::io::detail
