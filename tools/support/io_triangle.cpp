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
// three nodes (six-node files) into `middles`. `attributes`, where not null, takes the
// triangle's first `wanted` attributes (at most the header's).
void ele_triangle(const std::string& path, const EleHeader& h, std::size_t k, std::size_t line_no,
                  std::string_view line, std::int64_t& first, int first_index, VertexId* out, VertexId* middles,
                  double* attributes, std::size_t wanted) {
  Fields f{line, false};
  std::string_view idx, node[6], value;
  const auto count_error = [&] {
    return "expected " + std::to_string(h.fields) + " fields \"index " + (h.nodes == 6 ? "a b c ab bc ca" : "a b c") +
        (h.attrs > 0 ? " attributes" : "") + "\", got " + quoted(line);
  };
  bool whole = f.next(idx);
  for (int i = 0; i < h.nodes && whole; ++i) whole = f.next(node[i]);
  if (!whole) fail_line(path, line_no, count_error());
  std::size_t read = 1 + static_cast<std::size_t>(h.nodes);
  for (std::size_t a = 0; attributes != nullptr && a < wanted; ++a, ++read) {
    if (!f.next(value)) fail_line(path, line_no, count_error());
    attributes[a] = coordinate(path, line_no, value, [&] { return "attribute " + quoted(value) + " is not a number"; });
  }
  check_rest(f, read, h.fields, h.fields, path, line_no, count_error);
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

namespace {

// read_ele's work: each triangle's first attribute, or (where `count` is not null) all of them
// and their number a triangle into `count`, into `attributes` where it is not null.
std::vector<VertexId> read_ele_attributes(const std::string& path, std::string_view text, int first_index,
                                          unsigned threads, std::vector<double>* attributes, std::size_t* count,
                                          std::vector<VertexId>* middles) {
  const std::optional<Head> head = head_line(text);
  if (!head) fail_file(path, "no header line \"triangles 3 [attributes]\"");
  const EleHeader h = ele_header(path, head->line.number, head->line.text, middles != nullptr);
  const LinePieces lines(head->rest, threads, head->line.number);
  // Each triangle's first attribute, or (with `count`) all of them: as many as fit in the text
  // (two bytes each at least), else a record lacks some.
  const std::size_t wanted = attributes == nullptr
      ? 0
      : static_cast<std::size_t>(count == nullptr ? std::min<std::int64_t>(h.attrs, 1) : h.attrs);
  if (wanted > 1 && lines.size() > 0 && wanted > text.size() / (2 * lines.size()))
    fail_file(path, "header says " + std::to_string(h.attrs) + " attributes a triangle, more than the file holds");
  if (count != nullptr) *count = wanted;
  std::vector<VertexId> out(3 * lines.size());
  if (attributes != nullptr) attributes->assign(wanted * lines.size(), 0.0);
  if (middles != nullptr) middles->assign(h.nodes == 6 ? 3 * lines.size() : 0, 0);
  std::int64_t first = 0;
  read_records(lines, head->rest, head->line.number, first,
               [&](std::size_t k, std::size_t line_no, std::string_view line, std::int64_t& from) {
                 double* attribute = wanted > 0 ? &(*attributes)[wanted * k] : nullptr;
                 VertexId* middle = h.nodes == 6 ? &(*middles)[3 * k] : nullptr;
                 ele_triangle(path, h, k, line_no, line, from, first_index, &out[3 * k], middle, attribute, wanted);
               });
  if (lines.size() != static_cast<std::size_t>(h.n))
    fail_file(path,
              "header says " + std::to_string(h.n) + " triangles but the file has " + std::to_string(lines.size()));
  return out;
}

}  // namespace

std::vector<VertexId> read_ele(const std::string& path, std::string_view text, int first_index, unsigned threads,
                               std::vector<double>* attributes, std::vector<VertexId>* middles) {
  return read_ele_attributes(path, text, first_index, threads, attributes, nullptr, middles);
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

namespace {

// Record k of a .neigh file ("index n1 n2 n3", its index the first's, 0 or 1, plus k): its
// neighbours into `out`, each -1 or one of `triangles` numbered from `numbering` (-1: from the
// records' first index).
void neigh_record(const std::string& path, std::size_t k, std::size_t line_no, std::string_view line,
                  std::int64_t& first, std::size_t triangles, int numbering, std::int32_t* out) {
  const auto f = fields_of(path, line_no, line, 4, 4, "\"index n1 n2 n3\"");
  check_index(path, line_no, integer(path, line_no, f[0], "triangle index"), k, first, "triangle");
  const std::int64_t from = numbering < 0 ? first : numbering;
  for (int i = 0; i < 3; ++i) {
    const std::int64_t n = integer(path, line_no, f[1 + i], "neighbour");
    if (n != -1 && (n < from || n - from >= static_cast<std::int64_t>(triangles)))
      fail_line(path, line_no,
                "neighbour " + std::to_string(n) + " is neither -1 nor one of the " + std::to_string(triangles) +
                    " triangles numbered from " + std::to_string(from));
    out[i] = n == -1 ? -1 : static_cast<std::int32_t>(n - from);
  }
}

}  // namespace

}  // namespace ridt::io::detail

namespace ridt::io {

std::vector<VertexId> parse_elements(std::string_view text, const std::string& name, int first_index,
                                     std::vector<double>& attributes, std::size_t& attribute_count,
                                     std::vector<VertexId>& middles, unsigned threads) {
  return detail::read_ele_attributes(name, text, first_index, threads, &attributes, &attribute_count, &middles);
}

std::vector<std::int32_t> parse_neighbors(std::string_view text, const std::string& name, int first_index,
                                          unsigned threads) {
  using namespace detail;
  const std::optional<Head> head = head_line(text);
  if (!head) fail_file(name, "no header line \"triangles 3\"");
  const auto h = fields_of(name, head->line.number, head->line.text, 2, 2, "a header \"triangles 3\"");
  const std::int64_t n = integer(name, head->line.number, h[0], "number of triangles");
  if (n < 0) fail_line(name, head->line.number, "negative number of triangles " + std::to_string(n));
  if (integer(name, head->line.number, h[1], "neighbours per triangle") != 3)
    fail_line(name, head->line.number, "neighbours per triangle must be 3");
  const LinePieces lines(head->rest, threads, head->line.number);
  if (lines.size() != static_cast<std::size_t>(n))
    fail_file(name, "header says " + std::to_string(n) + " triangles but the file has " + std::to_string(lines.size()));
  if (lines.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    fail_file(name, "more triangles than a 32-bit index can number");
  std::vector<std::int32_t> out(3 * lines.size());
  std::int64_t first = 0;
  read_records(lines, head->rest, head->line.number, first,
               [&](std::size_t k, std::size_t line_no, std::string_view line, std::int64_t& from) {
                 neigh_record(name, k, line_no, line, from, lines.size(), first_index, &out[3 * k]);
               });
  return out;
}

}  // namespace ridt::io
