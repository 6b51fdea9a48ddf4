// Triangle's .poly (a planar straight-line graph): "n 2 attributes markers" and n vertices
// (or n = 0 and the vertices in the .node file beside it), "m markers" and m segments
// "i a b [marker]", "h" and h holes "i x y", optionally "r" and r regions
// "i x y attribute max_area"; '#' starts a comment. Indices from the vertices' first (0 or 1).
// And Triangle's .edge: "m 1", then "i a b 1".
#include "formats.hpp"
#include "lines.hpp"

namespace ridt::io::detail {
namespace {

// The fields of line `l`: at least `least`, at most `most`.
std::vector<std::string_view> fields(const std::string& path, const Line& l, std::size_t least, std::size_t most,
                                     const char* form) {
  return fields_of(path, l.number, l.text, least, most, form);
}

// The next `count` lines from `at`, or an error naming what is missing.
void need(const std::string& path, const std::vector<Line>& lines, std::size_t at, std::int64_t count,
          const char* what) {
  if (count < 0) fail_file(path, std::string("negative number of ") + what);
  if (lines.size() - at < static_cast<std::size_t>(count))
    fail_file(path, "the file ends before its " + std::to_string(count) + " " + what);
}

// The attributes of vertex records, `count` a record after "index x y" (the records are checked).
std::vector<double> attributes_of(std::span<const Line> records, std::size_t count) {
  std::vector<double> out(records.size() * count);
  for (std::size_t k = 0; k < records.size(); ++k) {
    Fields f{records[k].text, false};
    std::string_view field;
    for (int skip = 0; skip < 3; ++skip) f.next(field);
    for (std::size_t a = 0; a < count && f.next(field); ++a) parse_double(field, out[k * count + a]);
  }
  return out;
}

// The boundary markers of vertex records, each line's last field (the records are checked).
std::vector<std::int64_t> markers_of(const std::string& path, std::span<const Line> records) {
  std::vector<std::int64_t> out(records.size());
  for (std::size_t k = 0; k < records.size(); ++k) {
    Fields f{records[k].text, false};
    std::string_view field, last;
    while (f.next(field)) last = field;
    out[k] = integer(path, records[k].number, last, "boundary marker");
  }
  return out;
}

// The text of the .node file whose vertices a .poly that lists none takes, where it is given
// rather than read from the file beside the .poly.
struct NodeText {
  std::optional<std::string_view> text;  ///< none: not given
  std::string name;
};

std::size_t read_vertices(const std::string& path, const std::vector<Line>& lines, unsigned threads, Pslg& g,
                          const NodeText* given = nullptr) {
  const auto h = fields(path, lines[0], 2, 4, "a header \"vertices 2 [attributes [markers]]\"");
  const std::int64_t n = integer(path, lines[0].number, h[0], "number of vertices");
  if (integer(path, lines[0].number, h[1], "dimension") != 2) fail_line(path, lines[0].number, "dimension must be 2");
  // The attributes and markers a header declares (read_node checks the counts and records).
  auto declared = [&](const std::vector<std::string_view>& head, std::size_t line_no, std::span<const Line> records,
                      const std::string& file) {
    if (head.size() > 2)
      g.vertex_attributes = static_cast<std::size_t>(integer(file, line_no, head[2], "number of attributes"));
    if (g.vertex_attributes > 0) g.point_attributes = attributes_of(records, g.vertex_attributes);
    if (head.size() > 3 && integer(file, line_no, head[3], "number of boundary markers") > 0)
      g.point_markers = markers_of(file, records);
  };
  PointFile p;
  if (n == 0) {  // the vertices in the .node file beside it, or in the text given for it
    if (given != nullptr && !given->text)
      fail_line(path, lines[0].number, "the file lists no vertices and no .node text is given for them");
    const std::string node = given != nullptr ? given->name : (fs::path(path).replace_extension(".node")).string();
    auto vertices = [&](std::string_view text) {
      p = read_node(node, text, threads);
      const std::vector<Line> all = split_lines(text, threads);
      if (!all.empty())
        declared(fields(node, all[0], 2, 4, "a header \"points 2 [attributes [markers]]\""), all[0].number,
                 std::span(all).subspan(1), node);
      return 0;
    };
    if (given != nullptr)
      vertices(*given->text);
    else
      FileText(node).parse(vertices);
    g.node_file = node;
  } else {  // the lines up to the last vertex's are a .node file's, line numbers and all
    need(path, lines, 1, n, "vertices");
    p = read_node_lines(path, std::span(lines).first(1 + static_cast<std::size_t>(n)), threads);
    declared(h, lines[0].number, std::span(lines).subspan(1, static_cast<std::size_t>(n)), path);
  }
  g.first_index = p.first_index;
  g.points = std::move(p).vector();
  return n == 0 ? 1 : 1 + static_cast<std::size_t>(n);
}

std::size_t read_segments(const std::string& path, const std::vector<Line>& lines, std::size_t at, unsigned threads,
                          Pslg& g) {
  if (at >= lines.size()) fail_file(path, "no segment header \"segments [markers]\"");
  const auto h = fields(path, lines[at], 1, 2, "a segment header \"segments [markers]\"");
  const std::int64_t m = integer(path, lines[at].number, h[0], "number of segments");
  need(path, lines, at + 1, m, "segments");
  g.segments.resize(2 * static_cast<std::size_t>(m));
  g.segment_markers.assign(
      h.size() > 1 && integer(path, lines[at].number, h[1], "number of markers") > 0 ? static_cast<std::size_t>(m) : 0,
      0);
  parse_in_ranges(0, static_cast<std::size_t>(m), threads, [&](std::size_t k) {
    const Line& l = lines[at + 1 + k];
    Fields f{l.text, false};
    std::string_view index, ends[2], marker, extra;
    if (!(f.next(index) && f.next(ends[0]) && f.next(ends[1])) || (f.next(marker) && f.next(extra)))
      fields(path, l, 3, 4, "\"index a b [marker]\"");  // throws, naming the fields
    const std::int64_t want = g.first_index + static_cast<std::int64_t>(k);
    if (integer(path, l.number, index, "segment index") != want)
      fail_line(path, l.number, "expected segment index " + std::to_string(want));
    for (int e = 0; e < 2; ++e) {
      const VertexId v = vertex(path, l.number, ends[e], g.first_index);
      if (v >= g.points.size()) fail_line(path, l.number, "segment end " + std::string(ends[e]) + " is not a vertex");
      g.segments[2 * k + static_cast<std::size_t>(e)] = v;
    }
    if (!g.segment_markers.empty())
      g.segment_markers[k] = marker.empty() ? 0 : integer(path, l.number, marker, "segment marker");
  });
  return at + 1 + static_cast<std::size_t>(m);
}

// Holes ("i x y") or regions ("i x y attribute max_area") after their count at `at`.
std::size_t read_seeds(const std::string& path, const std::vector<Line>& lines, std::size_t at, bool regions, Pslg& g) {
  const char* what = regions ? "regions" : "holes";
  if (at >= lines.size()) {
    if (regions) return at;  // optional
    fail_file(path, "no hole count");
  }
  const std::int64_t count = integer(path, lines[at].number, fields(path, lines[at], 1, 1, "a count")[0], what);
  need(path, lines, at + 1, count, what);
  for (std::int64_t k = 0; k < count; ++k) {
    const Line& l = lines[at + 1 + static_cast<std::size_t>(k)];
    const auto f = fields(path, l, regions ? 4 : 3, regions ? 5 : 3,
                          regions ? "\"index x y attribute [max_area]\"" : "\"index x y\"");
    std::array<double, 4> v{0, 0, 0, -1};
    for (std::size_t c = 1; c < f.size(); ++c)
      v[c - 1] = coordinate(path, l.number, f[c], [&] { return not_a_number(f[c]); });
    if (regions)
      g.regions.push_back(v);
    else
      g.holes.push_back({v[0], v[1]});
  }
  return at + 1 + static_cast<std::size_t>(count);
}

// read_poly's work, a .poly that lists no vertices taking them from `given` where it is not null.
Pslg poly_of(const std::string& path, std::string_view text, unsigned threads, const NodeText* given) {
  const std::vector<Line> lines = split_lines(text, threads);
  if (lines.empty()) fail_file(path, "no header line \"vertices 2 [attributes [markers]]\"");
  Pslg g;
  std::size_t at = read_vertices(path, lines, threads, g, given);
  at = read_segments(path, lines, at, threads, g);
  at = read_seeds(path, lines, at, false, g);
  at = read_seeds(path, lines, at, true, g);
  if (at != lines.size()) fail_line(path, lines[at].number, "unexpected line " + quoted(lines[at].text));
  return g;
}

}  // namespace

Pslg read_poly(const std::string& path, std::string_view text, unsigned threads) {
  return poly_of(path, text, threads, nullptr);
}

// A .node file as a graph of its points alone (Triangle's input without -p), their attributes
// and markers with them.
Pslg read_node_graph(const std::string& path, std::string_view text, unsigned threads) {
  const std::vector<Line> lines = split_lines(text, threads);
  if (lines.empty()) fail_file(path, "no header line \"points 2 [attributes [markers]]\"");
  const auto h = fields(path, lines[0], 2, 4, "a header \"points 2 [attributes [markers]]\"");
  if (integer(path, lines[0].number, h[0], "number of points") == 0) fail_line(path, lines[0].number, "no points");
  Pslg g;
  if (const std::size_t at = read_vertices(path, lines, threads, g); at != lines.size())
    fail_line(path, lines[at].number, "unexpected line " + quoted(lines[at].text));
  return g;
}

PointFile read_poly_points(const std::string& path, std::string_view text, unsigned threads) {
  Pslg g = read_poly(path, text, threads);
  return PointFile(std::move(g.points), g.first_index);
}

namespace {

// What an .edge file's records refer to: `points` vertices numbered from `first_index`; whether
// the header declares markers.
struct EdgeEnds {
  std::size_t points;
  int first_index;
  bool marked;
};

// Record k of an .edge file: "index a b [marker]", or a ray "index a -1 dx dy [marker]"; its
// index the first's (0 or 1, which sets `first`) plus k.
void edge_record(const std::string& name, const Line& l, std::size_t k, std::int64_t& first, const EdgeEnds& e,
                 EdgeText& out) {
  const auto f = fields(name, l, 3, 6, "\"index a b [marker]\" or \"index a -1 dx dy [marker]\"");
  const std::int64_t index = integer(name, l.number, f[0], "edge index");
  if (k == 0 && index != 0 && index != 1)
    fail_line(name, l.number, "the first edge index must be 0 or 1, got " + std::to_string(index));
  if (k == 0) first = index;
  if (index != first + static_cast<std::int64_t>(k))
    fail_line(name, l.number, "expected edge index " + std::to_string(first + static_cast<std::int64_t>(k)));
  const bool ray = integer(name, l.number, f[2], "edge end") == -1;
  if (ray ? f.size() < 5 : f.size() > 4)
    fail_line(name, l.number,
              std::string("expected ") + (ray ? "a ray \"index a -1 dx dy [marker]\"" : "\"index a b [marker]\"") +
                  ", got " + quoted(l.text));
  VertexId ends[2] = {0, 0};
  for (int i = 0; i < (ray ? 1 : 2); ++i) {
    ends[i] = vertex(name, l.number, f[1 + i], e.first_index);
    if (ends[i] >= e.points) fail_line(name, l.number, "edge end " + std::string(f[1 + i]) + " is not a vertex");
  }
  const std::size_t extra = ray ? 5 : 3;
  const std::int64_t marker = f.size() > extra ? integer(name, l.number, f[extra], "edge marker") : 0;
  if (ray) {
    out.ray_origins.push_back(ends[0]);
    out.ray_directions.push_back({coordinate(name, l.number, f[3], [&] { return not_a_number(f[3]); }),
                                  coordinate(name, l.number, f[4], [&] { return not_a_number(f[4]); })});
    return;
  }
  out.edges.insert(out.edges.end(), {ends[0], ends[1]});
  if (e.marked) out.markers.push_back(marker);
}

}  // namespace

}  // namespace ridt::io::detail

namespace ridt::io {

Pslg parse_poly_text(std::string_view text, const std::string& name, std::optional<std::string_view> node,
                     const std::string& node_name, unsigned threads) {
  const detail::NodeText given{node, node_name};
  return detail::poly_of(name, text, threads, &given);
}

Pslg parse_node_text(std::string_view text, const std::string& name, unsigned threads) {
  return detail::read_node_graph(name, text, threads);
}

std::vector<VertexId> read_edge_file(const std::string& path, std::size_t points, int first_index,
                                     std::vector<std::int64_t>* markers) {
  return detail::FileText(path).parse([&](std::string_view text) {
    const std::vector<detail::Line> lines = detail::split_lines(text, 1);
    Pslg g;
    g.points.resize(points);
    g.first_index = first_index;
    const std::size_t at = detail::read_segments(path, lines, 0, 1, g);
    if (at != lines.size())
      detail::fail_line(path, lines[at].number, "unexpected line " + detail::quoted(lines[at].text));
    if (markers != nullptr) *markers = std::move(g.segment_markers);
    return std::move(g.segments);
  });
}

EdgeText parse_edge_text(std::string_view text, const std::string& name, std::size_t points, int first_index) {
  const std::vector<detail::Line> lines = detail::split_lines(text, 1);
  if (lines.empty()) detail::fail_file(name, "no edge header \"edges [markers]\"");
  const auto h = detail::fields(name, lines[0], 1, 2, "an edge header \"edges [markers]\"");
  const std::int64_t m = detail::integer(name, lines[0].number, h[0], "number of edges");
  const bool marked = h.size() > 1 && detail::integer(name, lines[0].number, h[1], "number of markers") > 0;
  detail::need(name, lines, 1, m, "edges");
  if (lines.size() > 1 + static_cast<std::size_t>(m)) {
    const detail::Line& l = lines[1 + static_cast<std::size_t>(m)];
    detail::fail_line(name, l.number, "unexpected line " + detail::quoted(l.text));
  }
  EdgeText out;
  std::int64_t first = 0;
  for (std::size_t k = 0; k < static_cast<std::size_t>(m); ++k)
    detail::edge_record(name, lines[1 + k], k, first, {points, first_index, marked}, out);
  return out;
}

std::vector<double> read_area_file(const std::string& path, std::size_t triangles, int first_index) {
  return detail::FileText(path).parse(
      [&](std::string_view text) { return parse_area_text(text, path, triangles, first_index); });
}

std::vector<double> parse_area_text(std::string_view text, const std::string& name,
                                    std::optional<std::size_t> triangles, int first_index) {
  const std::vector<detail::Line> lines = detail::split_lines(text, 1);
  if (lines.empty()) detail::fail_file(name, "no header line \"triangles\"");
  const std::int64_t count = detail::integer(
      name, lines[0].number, detail::fields(name, lines[0], 1, 1, "a header \"triangles\"")[0], "number of triangles");
  if (triangles && count != static_cast<std::int64_t>(*triangles))
    detail::fail_line(
        name, lines[0].number,
        "the file bounds " + std::to_string(count) + " triangles; the mesh has " + std::to_string(*triangles));
  if (count < 0) detail::fail_line(name, lines[0].number, "negative number of triangles " + std::to_string(count));
  const auto n = static_cast<std::size_t>(count);
  if (lines.size() != n + 1)
    detail::fail_file(
        name,
        "header says " + std::to_string(count) + " triangles but the file has " + std::to_string(lines.size() - 1));
  std::vector<double> out(n);
  std::int64_t first = first_index;
  for (std::size_t k = 0; k < n; ++k) {
    const detail::Line& l = lines[k + 1];
    const auto f = detail::fields(name, l, 2, 2, "\"index max_area\"");
    const std::int64_t index = detail::integer(name, l.number, f[0], "triangle index");
    if (k == 0 && first < 0) {
      if (index != 0 && index != 1)
        detail::fail_line(name, l.number, "the first triangle index must be 0 or 1, got " + std::to_string(index));
      first = index;
    }
    if (index != first + static_cast<std::int64_t>(k))
      detail::fail_line(name, l.number,
                        "expected triangle index " + std::to_string(first + static_cast<std::int64_t>(k)));
    out[k] = detail::coordinate(name, l.number, f[1], [&] { return detail::not_a_number(f[1]); });
  }
  return out;
}

std::vector<VertexId> read_elements(const std::string& path, int first_index, std::vector<double>& attributes,
                                    std::vector<VertexId>& middles, unsigned threads) {
  return detail::FileText(path).parse(
      [&](std::string_view text) { return detail::read_ele(path, text, first_index, threads, &attributes, &middles); });
}

void write_mesh_svg(const std::string& path, std::span<const Point> points, const Triangulation& t,
                    std::span<const VertexId> edges) {
  detail::write_svg(path, points, t, edges);
}

}  // namespace ridt::io
