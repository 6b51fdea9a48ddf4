// Triangle's formats (Shewchuk's Triangle): .node points ("n 2 attributes markers" then
// "i x y ..."), .ele triangles and .neigh neighbours, numbered from the .node's first index.
#include <stdexcept>
#include "io_common.hpp"
#include "lines.hpp"

namespace ridt::io::detail {

namespace {

// Record `count`'s index `i` (`what`: "point" or "triangle"): the first 0 or 1, which sets
// `first`, the others consecutive.
void check_index(const std::string& path, std::size_t line_no, std::int64_t i, std::size_t count, std::int64_t& first,
                 const char* what) {
  if (count == 0) {
    if (i != 0 && i != 1)
      fail_line(path, line_no, "the first " + std::string(what) + " index must be 0 or 1, got " + std::to_string(i));
    first = i;
  } else if (i != first + static_cast<std::int64_t>(count)) {
    fail_line(path, line_no,
              "expected " + std::string(what) + " index " + std::to_string(first + static_cast<std::int64_t>(count)) +
                  ", got " + std::to_string(i) + " (indices must be consecutive)");
  }
}

// The fields after the first `k` of a record: numbers (attributes) up to field `attrs_end`,
// then integers (a boundary marker), `total` fields in all.
template <class CountError>
void check_rest(Fields& f, std::size_t k, std::size_t attrs_end, std::size_t total, const std::string& path,
                std::size_t line_no, const CountError& count_error) {
  for (std::string_view field; f.next(field); ++k) {
    if (k >= total) fail_line(path, line_no, count_error());
    if (k < attrs_end) {
      double a = 0;
      if (parse_double(field, a) != Parse::Ok)
        fail_line(path, line_no, "attribute " + quoted(field) + " is not a number");
    } else {
      integer(path, line_no, field, "boundary marker");
    }
  }
  if (k != total) fail_line(path, line_no, count_error());
}

// A .node file's header: "points 2 [attributes [markers]]".
struct NodeHeader {
  std::int64_t n = 0, attrs = 0, markers = 0;
  std::size_t fields = 3;  // a point's line
  std::string layout;  // "index x y ..." for messages
};

NodeHeader node_header(const std::string& path, std::size_t line_no, std::string_view line) {
  const auto v = fields_of(path, line_no, line, 2, 4, "a header \"points 2 [attributes [markers]]\"");
  const std::size_t k = v.size();
  NodeHeader h;
  h.n = integer(path, line_no, v[0], "number of points");
  const std::int64_t dim = integer(path, line_no, v[1], "dimension");
  if (k > 2) h.attrs = integer(path, line_no, v[2], "number of attributes");
  if (k > 3) h.markers = integer(path, line_no, v[3], "number of boundary markers");
  if (h.n < 0) fail_line(path, line_no, "negative number of points " + std::to_string(h.n));
  if (dim != 2) fail_line(path, line_no, "dimension is " + std::to_string(dim) + ", must be 2");
  if (h.attrs < 0 || h.attrs > 1000000) fail_line(path, line_no, "bad number of attributes " + std::to_string(h.attrs));
  if (h.markers != 0 && h.markers != 1)
    fail_line(path, line_no, "number of boundary markers must be 0 or 1, got " + std::to_string(h.markers));
  h.fields = 3 + static_cast<std::size_t>(h.attrs) + static_cast<std::size_t>(h.markers);
  h.layout = std::string("index x y") + (h.attrs > 0 ? " attributes" : "") + (h.markers > 0 ? " marker" : "");
  return h;
}

// A .ele file's header: "triangles 3 [attributes]" (or 6 nodes a triangle, where `six`).
struct EleHeader {
  std::int64_t n = 0, attrs = 0;
  int nodes = 3;
  std::size_t fields = 4;
};

EleHeader ele_header(const std::string& path, std::size_t line_no, std::string_view line, bool six) {
  const auto v = fields_of(path, line_no, line, 2, 3, "a header \"triangles 3 [attributes]\"");
  const std::size_t k = v.size();
  EleHeader h;
  h.n = integer(path, line_no, v[0], "number of triangles");
  const std::int64_t nodes = integer(path, line_no, v[1], "nodes per triangle");
  if (k > 2) h.attrs = integer(path, line_no, v[2], "number of attributes");
  if (h.n < 0) fail_line(path, line_no, "negative number of triangles " + std::to_string(h.n));
  if (nodes != 3 && !(six && nodes == 6))
    fail_line(path, line_no,
              "nodes per triangle is " + std::to_string(nodes) + ", must be 3" +
                  (nodes == 6 ? " (six-node triangles, -o2, are read by ridt check and ridt mesh -r only)" : ""));
  if (h.attrs < 0 || h.attrs > 1000000) fail_line(path, line_no, "bad number of attributes " + std::to_string(h.attrs));
  h.nodes = static_cast<int>(nodes);
  h.fields = 1 + static_cast<std::size_t>(nodes) + static_cast<std::size_t>(h.attrs);
  return h;
}

}  // namespace

namespace {

// Point k of a .node file, on line `line_no`: its index must be first + k (the first, 0 or 1,
// sets `first`).
Point node_point(const std::string& path, const NodeHeader& h, std::size_t k, std::size_t line_no,
                 std::string_view line, std::int64_t& first) {
  Fields f{line, false};
  std::string_view idx, xs, ys;
  const auto count_error = [&] {
    return "expected " + std::to_string(h.fields) + " fields \"" + h.layout + "\", got " + quoted(line);
  };
  if (!f.next(idx) || !f.next(xs) || !f.next(ys)) fail_line(path, line_no, count_error());
  check_rest(f, 3, 3 + static_cast<std::size_t>(h.attrs), h.fields, path, line_no, count_error);
  check_index(path, line_no, integer(path, line_no, idx, "point index"), k, first, "point");
  return {coordinate(path, line_no, xs, [&] { return not_a_number(xs); }),
          coordinate(path, line_no, ys, [&] { return not_a_number(ys); })};
}

// Triangle k of an .ele file, as node_point reads a point: its corners into `out`, its other
// three nodes (six-node files) into `middles`. `attribute`, where not null, takes the
// triangle's first attribute.
void ele_triangle(const std::string& path, const EleHeader& h, std::size_t k, std::size_t line_no,
                  std::string_view line, std::int64_t& first, int first_index, VertexId* out, VertexId* middles,
                  double* attribute) {
  Fields f{line, false};
  std::string_view idx, node[6], value;
  const auto count_error = [&] {
    return "expected " + std::to_string(h.fields) + " fields \"index " + (h.nodes == 6 ? "a b c ab bc ca" : "a b c") +
        (h.attrs > 0 ? " attributes" : "") + "\", got " + quoted(line);
  };
  bool whole = f.next(idx);
  for (int i = 0; i < h.nodes && whole; ++i) whole = f.next(node[i]);
  if (!whole) fail_line(path, line_no, count_error());
  const std::size_t read = 1 + static_cast<std::size_t>(h.nodes);
  if (attribute != nullptr && h.attrs > 0) {
    if (!f.next(value)) fail_line(path, line_no, count_error());
    *attribute = coordinate(path, line_no, value, [&] { return "attribute " + quoted(value) + " is not a number"; });
    check_rest(f, read + 1, h.fields, h.fields, path, line_no, count_error);
  } else {
    check_rest(f, read, h.fields, h.fields, path, line_no, count_error);
  }
  check_index(path, line_no, integer(path, line_no, idx, "triangle index"), k, first, "triangle");
  for (int i = 0; i < 3; ++i) out[i] = vertex(path, line_no, node[i], first_index);
  for (int i = 3; i < h.nodes; ++i) middles[i - 3] = vertex(path, line_no, node[i], first_index);
}

// The records after a header (`rest`, `lines` its pieces, `before` the lines before it), each
// read by read(k, line_no, line, first) on the pieces' threads: the first alone before the
// others, as it sets `first`, the index the others follow.
template <class Read>
void read_records(const LinePieces& lines, std::string_view rest, std::size_t before, std::int64_t& first,
                  Read&& read) {
  if (const std::optional<Head> one = head_line(rest, false)) read(0, before + one->line.number, one->line.text, first);
  lines.visit([&](std::size_t k, std::size_t line_no, std::string_view line) {
    std::int64_t from = first;
    read(k, line_no, line, from);
  });
}

}  // namespace

PointFile read_node_lines(const std::string& path, std::span<const Line> lines, unsigned threads) {
  if (lines.empty()) fail_file(path, "no header line \"points 2 [attributes [markers]]\"");
  const NodeHeader h = node_header(path, lines[0].number, lines[0].text);
  std::vector<Point> points(lines.size() - 1);
  std::int64_t first = 0;
  if (!points.empty()) points[0] = node_point(path, h, 0, lines[1].number, lines[1].text, first);
  parse_in_ranges(1, points.size(), threads, [&](std::size_t k) {
    std::int64_t from = first;
    points[k] = node_point(path, h, k, lines[k + 1].number, lines[k + 1].text, from);
  });
  if (points.size() != static_cast<std::size_t>(h.n))
    fail_file(path, "header says " + std::to_string(h.n) + " points but the file has " + std::to_string(points.size()));
  return PointFile(std::move(points), static_cast<int>(first));
}

PointFile read_node(const std::string& path, std::string_view text, unsigned threads) {
  const std::optional<Head> head = head_line(text);
  if (!head) fail_file(path, "no header line \"points 2 [attributes [markers]]\"");
  const NodeHeader h = node_header(path, head->line.number, head->line.text);
  const LinePieces lines(head->rest, threads, head->line.number);
  std::vector<Point> points(lines.size());
  std::int64_t first = 0;
  read_records(lines, head->rest, head->line.number, first,
               [&](std::size_t k, std::size_t line_no, std::string_view line, std::int64_t& from) {
                 points[k] = node_point(path, h, k, line_no, line, from);
               });
  if (points.size() != static_cast<std::size_t>(h.n))
    fail_file(path, "header says " + std::to_string(h.n) + " points but the file has " + std::to_string(points.size()));
  return PointFile(std::move(points), static_cast<int>(first));
}

std::vector<VertexId> read_ele(const std::string& path, std::string_view text, int first_index, unsigned threads) {
  return read_ele(path, text, first_index, threads, nullptr);
}

std::vector<VertexId> read_ele(const std::string& path, std::string_view text, int first_index, unsigned threads,
                               std::vector<double>* attributes, std::vector<VertexId>* middles) {
  const std::optional<Head> head = head_line(text);
  if (!head) fail_file(path, "no header line \"triangles 3 [attributes]\"");
  const EleHeader h = ele_header(path, head->line.number, head->line.text, middles != nullptr);
  const LinePieces lines(head->rest, threads, head->line.number);
  std::vector<VertexId> out(3 * lines.size());
  if (attributes != nullptr) attributes->assign(h.attrs > 0 ? lines.size() : 0, 0.0);
  if (middles != nullptr) middles->assign(h.nodes == 6 ? 3 * lines.size() : 0, 0);
  std::int64_t first = 0;
  read_records(lines, head->rest, head->line.number, first,
               [&](std::size_t k, std::size_t line_no, std::string_view line, std::int64_t& from) {
                 double* attribute = attributes != nullptr && h.attrs > 0 ? &(*attributes)[k] : nullptr;
                 VertexId* middle = h.nodes == 6 ? &(*middles)[3 * k] : nullptr;
                 ele_triangle(path, h, k, line_no, line, from, first_index, &out[3 * k], middle, attribute);
               });
  if (lines.size() != static_cast<std::size_t>(h.n))
    fail_file(path,
              "header says " + std::to_string(h.n) + " triangles but the file has " + std::to_string(lines.size()));
  return out;
}

void write_node(Writer& out, std::span<const Point> points, int first_index, unsigned threads) {
  write_node(out, points, first_index, threads, {});
}

void write_node(Writer& out, std::span<const Point> points, int first_index, unsigned threads,
                std::span<const std::int64_t> markers, NodeAttributes attributes) {
  const std::size_t count = attributes.count;
  if (attributes.values.size() != points.size() * count)
    throw std::logic_error("ridt: node attributes for another number of points");
  out.put_int(static_cast<std::int64_t>(points.size()));
  out.put(" 2 ");
  out.put_int(static_cast<std::int64_t>(count));
  out.put(markers.empty() ? " 0\n" : " 1\n");
  out.put_lines(points.size(), threads, [&](std::size_t k, TextPart& line) {
    line.put_int(static_cast<std::int64_t>(k) + first_index);
    line.put(' ');
    line.put_double(points[k].x);
    line.put(' ');
    line.put_double(points[k].y);
    for (std::size_t a = 0; a < count; ++a) line.put(' '), line.put_double(attributes.values[k * count + a]);
    if (!markers.empty()) line.put(' '), line.put_int(markers[k]);
    line.put('\n');
  });
}

void write_ele(Writer& out, std::span<const VertexId> tris, int first_index, std::span<const double> attributes,
               unsigned threads, int nodes) {
  const std::size_t nt = tris.size() / static_cast<std::size_t>(nodes);
  const std::int64_t fi = first_index;
  out.put_int(static_cast<std::int64_t>(nt));
  out.put(nodes == 6 ? " 6" : " 3");
  out.put(attributes.empty() ? " 0\n" : " 1\n");
  out.put_lines(nt, threads, [&](std::size_t k, TextPart& line) {
    line.put_int(static_cast<std::int64_t>(k) + fi);
    for (std::size_t i = 0; i < static_cast<std::size_t>(nodes); ++i) {
      line.put(' ');
      line.put_int(static_cast<std::int64_t>(tris[nodes * k + i]) + fi);
    }
    if (!attributes.empty()) line.put(' '), line.put_double(attributes[k]);
    line.put('\n');
  });
}

void write_neigh(Writer& out, std::span<const std::int32_t> neighbors, int first_index, unsigned threads) {
  const std::size_t nt = neighbors.size() / 3;
  const std::int64_t fi = first_index;
  out.put_int(static_cast<std::int64_t>(nt));
  out.put(" 3\n");
  out.put_lines(nt, threads, [&](std::size_t k, TextPart& line) {
    line.put_int(static_cast<std::int64_t>(k) + fi);
    for (int i = 0; i < 3; ++i) {
      const std::int32_t nb = neighbors[3 * k + i];
      line.put(' ');
      line.put_int(nb < 0 ? -1 : static_cast<std::int64_t>(nb) + fi);
    }
    line.put('\n');
  });
}

}  // namespace ridt::io::detail
