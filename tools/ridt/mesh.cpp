// ridt mesh INPUT.poly -o OUT.ele [--quality DEG] [--max-area A] [--convex-hull] [--switches pq30a0.1]
// ...: the constrained Delaunay triangulation or quality mesh of a planar straight-line graph
// (or of the convex hull of points alone, from a .node; or a mesh already made refined, from a
// .ele),
// written as Triangle writes it: OUT.ele, OUT.node (every vertex: the input's in its numbering,
// then the points added) and OUT.edge (the segments' edges), OUT.neigh with -n.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <numeric>
#include <string_view>

#include "command.hpp"
#include "ridt/constrained.hpp"
#include "ridt/interpolate.hpp"
#include "ridt/predicates.hpp"

namespace ridt::tool {
namespace {

struct Args {
  std::string input, output, switches;
  std::string method = "auto";
  unsigned threads = 0;
  double quality = 0, max_area = 0;
  std::size_t max_steiner = 0;  // 0: no limit
  bool no_steiner = false;  // S0: no refinement at all (crossings are still added)
  bool quality_given = false;  // --quality or q: the library judges the angle, NaN included
  bool convex_hull = false, zero_based = false, region_areas = false, attributes = false, no_boundary = false,
       neighbours = false, conforming = false, second_order = false, no_holes = false, refine = false;
};

// The number that follows switch `at` in Triangle's switch string (digits, '.', 'e' and a sign
// after 'e'), or "" where none does; `at` moves past it.
std::string number_after(const std::string& s, std::size_t& at) {
  std::size_t end = at + 1;
  while (end < s.size() &&
         (std::isdigit(static_cast<unsigned char>(s[end])) || s[end] == '.' || s[end] == 'e' ||
          ((s[end] == '-' || s[end] == '+') && s[end - 1] == 'e')))
    ++end;
  std::string n = s.substr(at + 1, end - at - 1);
  at = end - 1;
  return n;
}

// A switch's number; one that strtod takes only by rounding it to 0 or to infinity (1e-400,
// 1e400) is refused, as an area bound that is not positive is: 0 would mean no bound at all.
double parse_number(const std::string& text, char sw) {
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  const std::string what = std::string("switch '") + sw + "': ";
  if (text.empty() || *end != '\0') throw InputError(what + "bad number '" + text + "'");
  if (errno == ERANGE || !std::isfinite(v)) throw InputError(what + "'" + text + "' is out of range of a double");
  if (sw == 'a' && !(v > 0)) throw InputError(what + "an area bound is positive, got '" + text + "'");
  return v;
}

// Triangle's switches that ridt takes: p (a .poly: always), r (refine the mesh of a .ele), q[DEG] (quality, 20 degrees where no
// number follows), a[AREA] (an area bound; with no number, the regions' own), A (regional
// attributes), c (keep the convex hull), D (conforming Delaunay), Y (no points added on the boundary), n (.neigh),
// z (number from 0), S[N] (at most N points added by refinement), o2 (six-node triangles), O (the
// .poly's holes ignored), Q and V (quiet, verbose), and i, F, l, X and I (Triangle's choice of
// algorithm, its exact arithmetic off, its iteration numbers in file names: the exact result
// does not depend on them): ignored; the others are refused by name.
void apply_switches(Args& a) {
  const std::string& s = a.switches;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == 'q') {
      const std::string n = number_after(s, i);
      a.quality = n.empty() ? 20 : parse_number(n, c);
      a.quality_given = true;
    } else if (c == 'a') {
      const std::string n = number_after(s, i);
      if (n.empty())
        a.region_areas = true;
      else
        a.max_area = parse_number(n, c);
    } else if (c == 'D') {
      a.conforming = true;
    } else if (c == 'S') {
      const std::string n = number_after(s, i);
      const double v = n.empty() ? -1 : parse_number(n, c);
      if (!(v >= 0 && v == std::floor(v) && v < 0x1p53))
        throw InputError("switch 'S': give the most points refinement may add, a whole number (got '" + n + "')");
      a.max_steiner = static_cast<std::size_t>(v);
      a.no_steiner = a.max_steiner == 0;
    } else if (c == 'o') {
      if (i + 1 >= s.size() || s[i + 1] != '2')
        throw InputError("switch 'o' is taken as o2 only (six-node triangles: Triangle's -o2)");
      a.second_order = true;
      ++i;
    } else if (c == 'Y' && i + 1 < s.size() && s[i + 1] == 'Y') {
      throw InputError("switch 'YY' (no points on any segment) is not supported: 'Y' keeps them off the boundary");
    } else if (c == 'A' || c == 'c' || c == 'Y' || c == 'n' || c == 'z' || c == 'O' || c == 'r') {
      (c == 'A'       ? a.attributes
           : c == 'r' ? a.refine
           : c == 'c' ? a.convex_hull
           : c == 'Y' ? a.no_boundary
           : c == 'n' ? a.neighbours
           : c == 'O' ? a.no_holes
                      : a.zero_based) = true;
    } else if (std::string_view("pQViFlXI").find(c) == std::string_view::npos) {
      throw InputError(std::string("unknown or unsupported switch '") + c +
                       "' (ridt takes p, r, q, a, A, c, D, Y, S, n, z, o2, O, Q, V, i, F, l, X, I)");
    }
  }
}

// The files `a` asks for: OUT.svg, or OUT.ele and the files beside it.
std::vector<std::string> outputs(const Args& a) {
  const std::string extension = io::extension(a.output);
  if (extension == ".svg") return {a.output};
  if (extension != ".ele")
    throw InputError(
        "mesh writes Triangle's files or a drawing: give -o OUT.ele (OUT.node and OUT.edge are "
        "written beside it) or OUT.svg");
  return io::mesh_file_paths(a.output, a.neighbours);
}

// The segment edges (pairs of indices) as lists of neighbours, each with the edge's index.
class SegmentEdges {
 public:
  SegmentEdges(std::span<const VertexId> edges, std::size_t points) : start_(points + 1, 0), count_(edges.size() / 2) {
    for (const VertexId v : edges) ++start_[v + 1];
    for (std::size_t v = 1; v < start_.size(); ++v) start_[v] += start_[v - 1];
    next_.resize(edges.size());
    std::vector<std::size_t> at(start_.begin(), start_.end() - 1);
    for (std::size_t k = 0; k < edges.size(); k += 2) {
      next_[at[edges[k]]++] = {edges[k + 1], static_cast<std::uint32_t>(k / 2)};
      next_[at[edges[k + 1]]++] = {edges[k], static_cast<std::uint32_t>(k / 2)};
    }
  }
  /// The neighbours of v, each with the index of the edge to it.
  std::span<const std::pair<VertexId, std::uint32_t>> around(VertexId v) const {
    return std::span(next_).subspan(start_[v], start_[v + 1] - start_[v]);
  }
  /// The index of edge a-b, or the number of edges where it is none.
  std::size_t index(VertexId a, VertexId b) const {
    for (const auto& [w, k] : around(a))
      if (w == b) return k;
    return count_;
  }

 private:
  std::vector<std::size_t> start_;
  std::vector<std::pair<VertexId, std::uint32_t>> next_;
  std::size_t count_;
};

// The pieces of input segment a-b, marked `marker`, followed from a through the segment edges
// to points on it (exactly, or added points within a rounding of it), each piece and its ends
// marked; the walk stops where the chain does (a stretch of the segment in a hole).
void mark_pieces(std::span<const Point> all, std::size_t input, VertexId a, VertexId b, std::int64_t marker,
                 const SegmentEdges& edges, std::vector<std::int64_t>& markers, std::vector<std::int64_t>& ends) {
  const Point &pa = all[a], &pb = all[b];
  const double dx = pb.x - pa.x, dy = pb.y - pa.y, length2 = dx * dx + dy * dy;
  auto along = [&](VertexId v) { return ((all[v].x - pa.x) * dx + (all[v].y - pa.y) * dy) / length2; };
  auto on = [&](VertexId v) {
    if (v == b || orientation(pa, pb, all[v]) == 0) return true;
    const double cross = dx * (all[v].y - pa.y) - dy * (all[v].x - pa.x);
    return v >= input && std::fabs(cross) <= 0x1p-40 * length2;
  };
  for (VertexId v = a; v != b;) {
    VertexId next = v;
    for (const auto& [w, k] : edges.around(v))
      if (along(w) > along(v) && along(w) <= 1 && on(w) && (next == v || along(w) < along(next))) next = w;
    if (next == v) return;
    markers[edges.index(v, next)] = marker;
    ends[v] = ends[next] = marker;
    v = next;
  }
}

struct Markers {
  std::vector<std::int64_t> edges, points;
};

// The markers Triangle writes. A segment edge's: that of the input segment it is a piece of
// where not 0; else 1 on the boundary (an edge with no triangle across), 0 inside. A vertex's:
// the input's where not 0; else that of a marked segment edge it ends; else 1 on the boundary,
// 0 inside.
Markers markers_of(const io::Pslg& g, const ConstrainedTriangulation& t, std::span<const Point> all) {
  const SegmentEdges edges(t.edges, all.size());
  Markers m{std::vector<std::int64_t>(t.edges.size() / 2, 0), std::vector<std::int64_t>(all.size(), 0)};
  for (std::size_t s = 0; s < 3 * t.size() && s < t.neighbors.size(); ++s)
    if (t.neighbors[s] < 0) {
      const std::size_t first = s - s % 3;
      const VertexId a = t.triangles[first + (s + 1) % 3], b = t.triangles[first + (s + 2) % 3];
      m.points[a] = m.points[b] = 1;
      if (const std::size_t k = edges.index(a, b); k < m.edges.size()) m.edges[k] = 1;
    }
  std::vector<VertexId> kept(g.points.size());  // a duplicate end stands for the point kept
  for (VertexId v = 0; v < kept.size(); ++v) kept[v] = v;
  for (const Duplicate& d : t.duplicates) kept[d.dropped] = d.kept;
  for (std::size_t s = 0; s < g.segment_markers.size(); ++s)
    if (const VertexId a = kept[g.segments[2 * s]], b = kept[g.segments[2 * s + 1]];
        g.segment_markers[s] != 0 && a != b)
      mark_pieces(all, g.points.size(), a, b, g.segment_markers[s], edges, m.edges, m.points);
  for (std::size_t v = 0; v < g.point_markers.size(); ++v)
    if (g.point_markers[v] != 0) m.points[v] = g.point_markers[v];
  return m;
}

// Every vertex's attributes: the input's as given, those of the points added interpolated
// linearly over the Delaunay triangulation of the input's points (exact on attributes linear
// in the position; Triangle interpolates in the triangle that holds a point when it is added,
// so the two differ where the attributes are not linear); the nearest input point's where a
// point added lies a rounding outside their hull.
std::vector<double> vertex_attributes(const io::Pslg& g, const ConstrainedTriangulation& t, unsigned threads) {
  const std::size_t count = g.vertex_attributes;
  std::vector<double> out(g.point_attributes);
  if (t.steiner.empty()) return out;
  Options o;
  o.threads = threads;
  const Triangulation d = triangulate(g.points, o);
  std::vector<double> added = interpolate_linear(g.points, d, {g.point_attributes, count}, t.steiner,
                                                 std::numeric_limits<double>::quiet_NaN(), threads);
  const std::vector<std::int32_t> near = nearest_vertex(g.points, d, t.steiner, threads);
  for (std::size_t k = 0; k < t.steiner.size(); ++k)
    if (std::isnan(added[k * count]) && near[k] >= 0)
      std::copy_n(&g.point_attributes[static_cast<std::size_t>(near[k]) * count], count, &added[k * count]);
  out.insert(out.end(), added.begin(), added.end());
  return out;
}

// The markers of every vertex, then of the middles of the edges (-o2), by the vertices' rule: a
// marked segment edge's marker; else 1 on the boundary, 0 inside.
std::vector<std::int64_t> with_middles(const std::vector<std::int64_t>& points, const std::vector<std::int64_t>& edges,
                                       const ConstrainedTriangulation& t, const SecondOrder& s) {
  std::vector<std::int64_t> out(points);
  out.resize(points.size() + s.nodes.size(), 0);
  for (std::size_t k = 0; k < t.size(); ++k)
    for (int i = 0; i < 3; ++i)
      if (t.neighbors[3 * k + i] < 0) out[s.triangles[6 * k + 3 + i]] = 1;
  const SegmentEdges segment(t.edges, points.size());
  for (std::size_t q = 0; q < s.nodes.size(); ++q)
    if (const std::size_t e = segment.index(s.ends[2 * q], s.ends[2 * q + 1]); e < edges.size() && edges[e] != 0)
      out[points.size() + q] = edges[e];
  return out;
}

// The attributes of every vertex (`count` each, row by row), then of the middles of the edges
// (-o2): the mean of their ends', as linear interpolation along the edge gives them.
std::vector<double> with_middles(const std::vector<double>& attributes, std::size_t count, const SecondOrder& s) {
  std::vector<double> out(attributes);
  for (std::size_t q = 0; q < s.nodes.size() && count > 0; ++q)
    for (std::size_t j = 0; j < count; ++j)
      out.push_back(std::midpoint(attributes[s.ends[2 * q] * count + j], attributes[s.ends[2 * q + 1] * count + j]));
  return out;
}

// OUT.ele, OUT.node, OUT.edge (and OUT.neigh): all or, on an error, none; or a drawing,
// OUT.svg, its segments apart.
void write_mesh(const Args& a, const io::Pslg& g, const ConstrainedTriangulation& t) {
  std::vector<Point> all = g.points;
  all.insert(all.end(), t.steiner.begin(), t.steiner.end());
  if (io::extension(a.output) == ".svg") return io::write_mesh_svg(a.output, all, t, t.edges);
  io::MeshFiles m;
  m.points = all;
  m.triangles = std::span(t.triangles).first(3 * t.size());
  if (a.attributes) m.attributes = t.attributes;
  m.edges = t.edges;
  const Markers markers = markers_of(g, t, all);
  m.edge_markers = markers.edges;
  m.point_markers = markers.points;
  const std::vector<double> attributes =
      g.vertex_attributes > 0 ? vertex_attributes(g, t, thread_count(a.threads)) : std::vector<double>{};
  m.point_attributes = attributes;
  m.point_attribute_count = g.vertex_attributes;
  if (a.neighbours) m.neighbors = std::span(t.neighbors).first(std::min(t.neighbors.size(), 3 * t.size()));
  m.first_index = a.zero_based ? 0 : g.first_index;
  if (!a.second_order) return io::write_mesh_files(a.output, m, thread_count(a.threads));
  const SecondOrder s = second_order(all, t);
  const std::vector<std::int64_t> point_markers = with_middles(markers.points, markers.edges, t, s);
  const std::vector<double> point_attributes = with_middles(attributes, g.vertex_attributes, s);
  all.insert(all.end(), s.nodes.begin(), s.nodes.end());
  m.points = all;
  m.triangles = s.triangles;
  m.nodes = 6;
  m.point_markers = point_markers;
  m.point_attributes = point_attributes;
  io::write_mesh_files(a.output, m, thread_count(a.threads));
}

// The quality a asks for (none at all with -S0: the crossings, which the graph needs, stay).
Quality quality_of(const Args& a) {
  Quality q;
  q.min_angle = a.quality_given ? a.quality : 0;
  q.max_area = a.max_area;
  q.split_boundary = !a.no_boundary;
  q.conforming = a.conforming;
  q.max_steiner = a.max_steiner;
  return a.no_steiner ? Quality{} : q;
}

// Triangle's -r: IN.ele and IN.node refined, with the segments of IN.poly (with switch p, as
// Triangle's -rp) or else of IN.edge (ridt mesh's OUT.edge: the segments' edges), where there,
// kept; IN.area's bounds with -a and no number; the .ele's first attribute carried.
int run_refine(const Args& a, const std::vector<std::string>& out, const Options& o) {
  if (io::extension(a.input) != ".ele")
    throw InputError("switch 'r' refines a mesh: give its .ele (its .node is read beside it)");
  refuse_ignored(a.convex_hull, "--convex-hull (c)", "does not apply: a mesh refined keeps its own triangles' domain");
  const std::string base = a.input.substr(0, a.input.size() - 4);
  io::Pslg g = io::read_pslg(base + ".node", thread_count(a.threads));
  std::vector<double> attributes;
  const std::vector<VertexId> triangles = io::read_elements(a.input, g.first_index, attributes, o.threads);
  std::vector<std::string> read = {a.input, base + ".node"};
  if (a.switches.find('p') != std::string::npos) {
    const io::Pslg p = io::read_pslg(base + ".poly", thread_count(a.threads));
    if (p.points.size() != g.points.size())
      throw InputError(base + ".poly has " + std::to_string(p.points.size()) + " vertices; the mesh has " +
                       std::to_string(g.points.size()));
    g.segments = p.segments, g.segment_markers = p.segment_markers;
    read.push_back(base + ".poly");
  } else if (std::filesystem::exists(base + ".edge")) {
    g.segments = io::read_edge_file(base + ".edge", g.points.size(), g.first_index);
    read.push_back(base + ".edge");
  }
  std::vector<double> areas;
  if (a.region_areas && !a.no_steiner) {
    areas = io::read_area_file(base + ".area", triangles.size() / 3, g.first_index);
    read.push_back(base + ".area");
  }
  refuse_overwriting(read, out);
  const ConstrainedTriangulation t = refine_mesh(g.points, triangles, g.segments, quality_of(a), areas, attributes, o);
  if (!t.warning.empty()) std::fprintf(stderr, "ridt: warning: %s\n", t.warning.c_str());
  Args carry = a;
  carry.attributes = a.attributes || !attributes.empty();
  write_mesh(carry, g, t);
  return 0;
}

int run(Args a) {
  apply_switches(a);
  a.refine = a.refine || io::extension(a.input) == ".ele";
  if (io::extension(a.output) == ".svg") {
    const char* why = "is not drawn: a drawing (.svg) has no neighbours, attributes or numbering; give -o OUT.ele";
    refuse_ignored(a.neighbours, "--neighbours (n)", why);
    refuse_ignored(a.attributes, "--attributes (A)", why);
    refuse_ignored(a.zero_based, "numbering from 0 (z)", why);
    refuse_ignored(a.second_order, "--second-order (o2)", why);
  }
  const std::vector<std::string> out = outputs(a);
  Options o;
  o.method = parse<Method>(a.method);
  o.threads = a.threads;
  o.canonical_order = true;
  if (a.refine) return run_refine(a, out, o);
  refuse_overwriting({a.input}, out);
  const io::Pslg g = io::read_pslg(a.input, thread_count(a.threads));
  refuse_overwriting({g.node_file}, out);
  Domain domain;
  domain.convex_hull = a.convex_hull || io::extension(a.input) == ".node";  // points alone: their hull
  if (!a.no_holes) domain.holes = g.holes;
  for (const auto& r : g.regions) domain.regions.push_back({{r[0], r[1]}, r[2], a.region_areas ? r[3] : 0});
  if (a.no_steiner)  // Triangle's -S0: nothing refined
    for (Region& r : domain.regions) r.max_area = 0;
  const ConstrainedTriangulation t = triangulate_constrained(g.points, g.segments, o, domain, quality_of(a));
  if (!t.warning.empty()) std::fprintf(stderr, "ridt: warning: %s\n", t.warning.c_str());
  if (t.crossings > 0)
    std::fprintf(stderr, "ridt: %zu points added where segments cross (the first %zu added points)\n", t.crossings,
                 t.crossings);
  write_mesh(a, g, t);
  return 0;
}

}  // namespace

Command add_mesh(CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* mesh = app.add_subcommand(
      "mesh", "the constrained Delaunay triangulation or quality mesh of a .poly file (Triangle's -p, -q, -a)");
  mesh->add_option(
          "input", a->input,
          "a planar straight-line graph: .poly (Triangle's); or points alone, .node, their convex hull meshed "
          "(Triangle's input without -p); or a mesh to refine, .ele, with its .node beside it, and its .poly's "
          "segments (else its .edge's) where there (Triangle's -r)")
      ->required();
  mesh->add_option("-o,--output", a->output, "OUT.ele (OUT.node and OUT.edge are written beside it), or OUT.svg")
      ->required();
  CLI::Option* quality =
      mesh->add_option("--quality", a->quality, "no angle below DEG degrees, up to 34 (Triangle's -q)");
  mesh->add_option("--max-area", a->max_area, "no triangle larger than A (Triangle's -a)");
  mesh->add_flag("--region-areas", a->region_areas,
                 "the regions' own area bounds; refining a .ele, each triangle's from its .area file (Triangle's -a "
                 "with no number)");
  mesh->add_flag("--attributes", a->attributes, "each triangle's regional attribute in OUT.ele (Triangle's -A)");
  mesh->add_flag("--no-boundary-steiner", a->no_boundary, "no points added on the boundary (Triangle's -Y)");
  mesh->add_flag("--convex-hull", a->convex_hull,
                 "keep every triangle of the convex hull (Triangle's -c); else what the segments enclose");
  mesh->add_flag("--neighbours", a->neighbours, "write OUT.neigh too (Triangle's -n)");
  mesh->add_flag("--conforming", a->conforming, "conforming Delaunay: every edge Delaunay (Triangle's -D)");
  mesh->add_option("--max-steiner", a->max_steiner,
                   "stop refining after adding N points, with a warning (Triangle's -S; 0, the default: no limit)");
  mesh->add_flag("--second-order", a->second_order,
                 "six-node triangles for quadratic elements: a node at the middle of every edge, in OUT.node after "
                 "the vertices (Triangle's -o2)");
  mesh->add_option("--switches", a->switches,
                   "Triangle's switches: p, r, q, a, A, c, D, Y, S, n, z, o2, O, Q, V; i, F, l, X and I are "
                   "ignored (the exact result does not depend on them)");
  mesh->add_option("--method", a->method, choices_help("", Method::Auto));
  mesh->add_option("--threads", a->threads,
                   "threads of the triangulation and of the output's text (0, the default: all hardware threads)");
  return {mesh, [a, quality] {
            a->quality_given = quality->count() > 0;
            return run(*a);
          }};
}

}  // namespace ridt::tool
