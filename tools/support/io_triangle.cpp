// Triangle's formats (Shewchuk's Triangle): .node points ("n 2 attributes markers" then
// "i x y ..."), .ele triangles and .neigh neighbours, numbered from the .node's first index.
#include "io_common.hpp"

namespace ridt::io::detail {

PointFile read_node(const std::string& path, std::string_view text) {
  struct {
    std::vector<Point> points;
    int first_index = 0;
  } out;
  bool have_header = false;
  std::int64_t n = 0, attrs = 0, markers = 0;
  std::size_t fields_per_line = 3;
  std::size_t count = 0;
  std::string layout;  // "index x y ..." for messages
  for_each_line(text, [&](std::size_t line_no, std::string_view line) {
    if (!have_header) {
      Fields f{line, false};
      std::string_view v[4];
      std::size_t k = 0;
      std::string_view field;
      while (f.next(field)) {
        if (k == 4) {
          fail_line(path, line_no, "expected a header \"points 2 [attributes [markers]]\", got " + quoted(line));
        }
        v[k++] = field;
      }
      if (k < 2) {
        fail_line(path, line_no, "expected a header \"points 2 [attributes [markers]]\", got " + quoted(line));
      }
      n = integer(path, line_no, v[0], "number of points");
      const std::int64_t dim = integer(path, line_no, v[1], "dimension");
      if (k > 2) attrs = integer(path, line_no, v[2], "number of attributes");
      if (k > 3) markers = integer(path, line_no, v[3], "number of boundary markers");
      if (n < 0) fail_line(path, line_no, "negative number of points " + std::to_string(n));
      if (dim != 2) fail_line(path, line_no, "dimension is " + std::to_string(dim) + ", must be 2");
      if (attrs < 0 || attrs > 1000000) fail_line(path, line_no, "bad number of attributes " + std::to_string(attrs));
      if (markers != 0 && markers != 1) {
        fail_line(path, line_no, "number of boundary markers must be 0 or 1, got " + std::to_string(markers));
      }
      fields_per_line = 3 + static_cast<std::size_t>(attrs) + static_cast<std::size_t>(markers);
      layout = "index x y";
      if (attrs > 0) layout += " attributes";
      if (markers > 0) layout += " marker";
      // Never trust the header for a huge allocation: a point takes at least 6 bytes.
      out.points.reserve(std::min(static_cast<std::size_t>(n), text.size() / 6 + 1));
      have_header = true;
      return;
    }
    Fields f{line, false};
    std::string_view idx, xs, ys;
    const auto count_error = [&] {
      return "expected " + std::to_string(fields_per_line) + " fields \"" + layout + "\", got " + quoted(line);
    };
    if (!f.next(idx) || !f.next(xs) || !f.next(ys)) fail_line(path, line_no, count_error());
    // The remaining fields: attributes (numbers), then the marker (an integer).
    std::string_view field;
    std::size_t k = 3;
    while (f.next(field)) {
      if (k >= fields_per_line) fail_line(path, line_no, count_error());
      if (k < 3 + static_cast<std::size_t>(attrs)) {
        double a = 0;
        if (parse_double(field, a) != Parse::Ok)
          fail_line(path, line_no, "attribute " + quoted(field) + " is not a number");
      } else {
        integer(path, line_no, field, "boundary marker");
      }
      ++k;
    }
    if (k != fields_per_line) fail_line(path, line_no, count_error());
    const std::int64_t i = integer(path, line_no, idx, "point index");
    if (count == 0) {
      if (i != 0 && i != 1) {
        fail_line(path, line_no, "the first point index must be 0 or 1, got " + std::to_string(i));
      }
      out.first_index = static_cast<int>(i);
    } else if (i != out.first_index + static_cast<std::int64_t>(count)) {
      fail_line(path, line_no,
                "expected point index " + std::to_string(out.first_index + count) + ", got " + std::to_string(i) +
                    " (indices must be consecutive)");
    }
    const double x = coordinate(path, line_no, xs, [&] { return not_a_number(xs); });
    const double y = coordinate(path, line_no, ys, [&] { return not_a_number(ys); });
    out.points.push_back({x, y});
    ++count;
  });
  if (!have_header) fail_file(path, "no header line \"points 2 [attributes [markers]]\"");
  if (count != static_cast<std::size_t>(n)) {
    fail_file(path, "header says " + std::to_string(n) + " points but the file has " + std::to_string(count));
  }
  return PointFile(std::move(out.points), out.first_index);
}

std::vector<VertexId> read_ele(const std::string& path, std::string_view text, int first_index) {
  std::vector<VertexId> out;
  bool have_header = false;
  std::int64_t n = 0, attrs = 0;
  std::size_t fields_per_line = 4;
  std::size_t count = 0;
  std::int64_t first_triangle = 0;
  const char* const header_form = "expected a header \"triangles 3 [attributes]\", got ";
  for_each_line(text, [&](std::size_t line_no, std::string_view line) {
    if (!have_header) {
      Fields f{line, false};
      std::string_view v[3];
      std::size_t k = 0;
      std::string_view field;
      while (f.next(field)) {
        if (k == 3) fail_line(path, line_no, header_form + quoted(line));
        v[k++] = field;
      }
      if (k < 2) fail_line(path, line_no, header_form + quoted(line));
      n = integer(path, line_no, v[0], "number of triangles");
      const std::int64_t nodes = integer(path, line_no, v[1], "nodes per triangle");
      if (k > 2) attrs = integer(path, line_no, v[2], "number of attributes");
      if (n < 0) fail_line(path, line_no, "negative number of triangles " + std::to_string(n));
      if (nodes != 3) {
        fail_line(path, line_no, "nodes per triangle is " + std::to_string(nodes) + ", must be 3");
      }
      if (attrs < 0 || attrs > 1000000) fail_line(path, line_no, "bad number of attributes " + std::to_string(attrs));
      fields_per_line = 4 + static_cast<std::size_t>(attrs);
      out.reserve(3 * std::min(static_cast<std::size_t>(n), text.size() / 8 + 1));
      have_header = true;
      return;
    }
    Fields f{line, false};
    std::string_view idx, a, b, c, field;
    const auto count_error = [&] {
      return "expected " + std::to_string(fields_per_line) + " fields \"index a b c" +
          (attrs > 0 ? " attributes" : "") + "\", got " + quoted(line);
    };
    if (!(f.next(idx) && f.next(a) && f.next(b) && f.next(c))) fail_line(path, line_no, count_error());
    std::size_t k = 4;
    while (f.next(field)) {
      if (k >= fields_per_line) fail_line(path, line_no, count_error());
      double attr = 0;
      if (parse_double(field, attr) != Parse::Ok)
        fail_line(path, line_no, "attribute " + quoted(field) + " is not a number");
      ++k;
    }
    if (k != fields_per_line) fail_line(path, line_no, count_error());
    const std::int64_t i = integer(path, line_no, idx, "triangle index");
    if (count == 0) {
      if (i != 0 && i != 1) {
        fail_line(path, line_no, "the first triangle index must be 0 or 1, got " + std::to_string(i));
      }
      first_triangle = i;
    } else if (i != first_triangle + static_cast<std::int64_t>(count)) {
      fail_line(path, line_no,
                "expected triangle index " + std::to_string(first_triangle + count) + ", got " + std::to_string(i) +
                    " (indices must be consecutive)");
    }
    out.push_back(vertex(path, line_no, a, first_index));
    out.push_back(vertex(path, line_no, b, first_index));
    out.push_back(vertex(path, line_no, c, first_index));
    ++count;
  });
  if (!have_header) fail_file(path, "no header line \"triangles 3 [attributes]\"");
  if (count != static_cast<std::size_t>(n)) {
    fail_file(path, "header says " + std::to_string(n) + " triangles but the file has " + std::to_string(count));
  }
  return out;
}

void write_node(Writer& out, std::span<const Point> points) {
  out.put_int(static_cast<std::int64_t>(points.size()));
  out.put(" 2 0 0\n");
  for (std::size_t i = 0; i < points.size(); ++i) {
    out.put_int(static_cast<std::int64_t>(i));
    out.put(' ');
    out.put_double(points[i].x);
    out.put(' ');
    out.put_double(points[i].y);
    out.put('\n');
  }
}

void write_ele(Writer& out, std::span<const VertexId> tris, int first_index) {
  const std::size_t nt = tris.size() / 3;
  const std::int64_t fi = first_index;
  out.put_int(static_cast<std::int64_t>(nt));
  out.put(" 3 0\n");
  for (std::size_t k = 0; k < nt; ++k) {
    out.put_int(static_cast<std::int64_t>(k) + fi);
    for (int i = 0; i < 3; ++i) {
      out.put(' ');
      out.put_int(static_cast<std::int64_t>(tris[3 * k + i]) + fi);
    }
    out.put('\n');
  }
}

void write_neigh(Writer& out, std::span<const std::int32_t> neighbors, int first_index) {
  const std::size_t nt = neighbors.size() / 3;
  const std::int64_t fi = first_index;
  out.put_int(static_cast<std::int64_t>(nt));
  out.put(" 3\n");
  for (std::size_t k = 0; k < nt; ++k) {
    out.put_int(static_cast<std::int64_t>(k) + fi);
    for (int i = 0; i < 3; ++i) {
      const std::int32_t nb = neighbors[3 * k + i];
      out.put(' ');
      out.put_int(nb < 0 ? -1 : static_cast<std::int64_t>(nb) + fi);
    }
    out.put('\n');
  }
}

}  // namespace ridt::io::detail
