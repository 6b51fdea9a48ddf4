// ridt mesh INPUT.poly -o OUT.ele [--quality DEG] [--max-area A] [--convex-hull] [--switches pq30a0.1]
// ...: the constrained Delaunay triangulation or quality mesh of a planar straight-line graph
// (or of the convex hull of points alone, from a .node; or a mesh already made refined, from a
// .ele),
// written as Triangle writes it (mesh_files.cpp): OUT.ele, OUT.node (every vertex: the input's
// in its numbering, then the points added) and OUT.edge (the segments' edges), OUT.neigh with -n.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <numeric>
#include <string_view>

#include "command.hpp"
#include "mesh_files.hpp"
#include "ridt/check.hpp"
#include "ridt/constrained.hpp"

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
       neighbours = false, conforming = false, second_order = false, no_holes = false, refine = false,
       no_markers = false, no_node = false, no_ele = false, all_edges = false, jettison = false, consistency = false,
       off = false, voronoi = false, no_segments = false;
};

// The number that follows switch `at` in Triangle's switch string (digits and '.', then an
// exponent: 'e', an optional sign and digits; an 'e' not followed so is the next switch, as in
// "q30e"), or "" where none does; `at` moves past it.
std::string number_after(const std::string& s, std::size_t& at) {
  auto digit = [&s](std::size_t i) { return i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); };
  std::size_t end = at + 1;
  while (digit(end) || (end < s.size() && s[end] == '.')) ++end;
  if (end > at + 1 && end < s.size() && s[end] == 'e') {
    const std::size_t sign = end + 1 < s.size() && (s[end + 1] == '-' || s[end + 1] == '+') ? 1 : 0;
    if (digit(end + 1 + sign)) {
      end += 1 + sign;
      while (digit(end)) ++end;
    }
  }
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

// The switches that only set a flag.
constexpr std::pair<char, bool Args::*> kFlags[] = {
    {'A', &Args::attributes},  {'c', &Args::convex_hull}, {'Y', &Args::no_boundary}, {'n', &Args::neighbours},
    {'O', &Args::no_holes},    {'z', &Args::zero_based},  {'r', &Args::refine},      {'B', &Args::no_markers},
    {'N', &Args::no_node},     {'E', &Args::no_ele},      {'e', &Args::all_edges},   {'j', &Args::jettison},
    {'C', &Args::consistency}, {'g', &Args::off},         {'v', &Args::voronoi}};

// Triangle's switches that ridt takes: p (a .poly: always; with r, read the .poly beside the
// mesh), r (refine the mesh of a .ele), q[DEG] (quality, 20 degrees where no number follows),
// a[AREA] (an area bound; with no number, the regions' own, or with r the .area file's), A
// (regional attributes), c (keep the convex hull), D (conforming Delaunay), Y (no points added
// on the boundary; YY, on no segment either), S[N] (at most N points added by refinement), o2
// (six-node triangles), O (the .poly's holes ignored); for the files written, e (every edge in
// .edge), n (.neigh), j (no vertex of no triangle), z (number from 0), B (no boundary markers),
// N and E (no .node, no .ele), P (no .poly: ridt writes none), g (.off), v (the dual: .v.node,
// .v.edge), C (the mesh checked, the verdict on stderr); Q and V (quiet, verbose), and i, F, l,
// X and I (Triangle's choice of algorithm, its exact arithmetic off, its iteration numbers in
// file names: the exact result does not depend on them): ignored; the others are refused by
// name.
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
      a.no_boundary = a.no_segments = true;
      ++i;
    } else if (const auto flag =
                   std::find_if(std::begin(kFlags), std::end(kFlags), [c](auto f) { return f.first == c; });
               flag != std::end(kFlags)) {
      a.*(flag->second) = true;
    } else if (c == 'u') {
      throw InputError(
          "switch 'u' (a test compiled into Triangle) is not taken here: give it to the library "
          "(Quality::unsuitable) or to Python (unsuitable=)");
    } else if (std::string_view("pPQViFlXI").find(c) == std::string_view::npos) {
      throw InputError(
          std::string("unknown or unsupported switch '") + c +
          "' (ridt takes p, r, q, a, A, c, D, Y, YY, S, e, n, j, z, o2, O, B, N, E, P, g, v, C, Q, V, i, F, l, X, I)");
    }
  }
}

// Which files beside OUT.ele `a` asks for.
io::MeshFileSet files_of(const Args& a) { return {!a.no_ele, !a.no_node, a.neighbours, a.off, a.voronoi}; }

// The files `a` asks for: OUT.svg, or OUT.ele and the files beside it.
std::vector<std::string> outputs(const Args& a) {
  const std::string extension = io::extension(a.output);
  if (extension == ".svg") return {a.output};
  if (extension != ".ele")
    throw InputError(
        "mesh writes Triangle's files or a drawing: give -o OUT.ele (OUT.node and OUT.edge are "
        "written beside it; switch g adds OUT.off, v OUT.v.node and OUT.v.edge) or OUT.svg");
  return io::mesh_file_paths(a.output, files_of(a));
}

// The quality a asks for (none at all with -S0: the crossings, which the graph needs, stay).
Quality quality_of(const Args& a) {
  Quality q;
  q.min_angle = a.quality_given ? a.quality : 0;
  q.max_area = a.max_area;
  q.split_boundary = !a.no_boundary;
  q.split_segments = !a.no_segments;
  q.conforming = a.conforming;
  q.max_steiner = a.max_steiner;
  return a.no_steiner ? Quality{} : q;
}

// The files of t, the mesh of g, as `a` asks; with C first its exact check (ridt::check_mesh:
// the segments as chains of edges, the holes empty, the bounds asked where refinement met
// them), the verdict on stderr, and exit status 1 where it fails. `attributes`: write the
// triangles' attributes whether or not A asked (a mesh refined carries its own).
int finish(const Args& a, const io::Pslg& g, const ConstrainedTriangulation& t, std::span<const Point> holes,
           bool attributes) {
  bool valid = true;
  if (a.consistency) {
    std::vector<Point> all = g.points;
    all.insert(all.end(), t.steiner.begin(), t.steiner.end());
    MeshSpec spec;
    spec.edges = t.edges;
    spec.segments = g.segments;
    spec.input_points = g.points.size();
    spec.holes = holes;
    const Quality q = quality_of(a);
    // Where refinement stopped early no bound holds; with -Y a triangle with a small angle may
    // have to stay (its point would fall on the boundary), though none too large does.
    spec.min_angle = t.warning.empty() && q.split_boundary && q.split_segments ? q.min_angle : 0;
    spec.max_area = t.warning.empty() ? q.max_area : 0;
    const CheckResult r = check_mesh(all, t.triangles, spec);
    std::fprintf(stderr, "ridt: consistency check: %s\n", r.message.c_str());
    valid = r.valid;
  }
  MeshOutput o;
  o.path = a.output, o.threads = a.threads, o.attributes = a.attributes || attributes;
  o.files = files_of(a);
  o.zero_based = a.zero_based, o.second_order = a.second_order, o.markers = !a.no_markers;
  o.all_edges = a.all_edges, o.jettison = a.jettison;
  write_mesh(o, g, t);
  return valid ? 0 : kExitInvalid;
}

// The segments that a mesh's .edge file gives: all its edges where it lists fewer than there
// are (ridt mesh's OUT.edge: the segments' edges); where it lists as many as a mesh of
// `triangles` has at least (3 a triangle, each inside edge shared: Triangle's -e, ridt's e),
// those with a nonzero marker (a segment's own, or 1 on the boundary).
std::vector<VertexId> segments_of_edges(const std::string& path, const io::Pslg& g, std::size_t triangles) {
  std::vector<std::int64_t> markers;
  std::vector<VertexId> edges = io::read_edge_file(path, g.points.size(), g.first_index, &markers);
  if (edges.size() < 3 * triangles || markers.empty()) return edges;  // 2 numbers an edge, 3/2 edges a triangle
  std::vector<VertexId> marked;
  for (std::size_t k = 0; k < markers.size(); ++k)
    if (markers[k] != 0) marked.push_back(edges[2 * k]), marked.push_back(edges[2 * k + 1]);
  return marked;
}

// Triangle's -r: IN.ele and IN.node refined, with the segments of IN.poly (with switch p, as
// Triangle's -rp) or else of IN.edge (segments_of_edges), where there, kept; IN.area's bounds
// with -a and no number; the .ele's first attribute carried.
int run_refine(const Args& a, const std::vector<std::string>& out, const Options& o) {
  if (io::extension(a.input) != ".ele")
    throw InputError("switch 'r' refines a mesh: give its .ele (its .node is read beside it)");
  refuse_ignored(a.convex_hull, "--convex-hull (c)", "does not apply: a mesh refined keeps its own triangles' domain");
  const std::string base = a.input.substr(0, a.input.size() - 4);
  io::Pslg g = io::read_pslg(base + ".node", thread_count(a.threads));
  std::vector<double> attributes;
  std::vector<VertexId> middles;  // of a six-node mesh: left unused, its corners refined
  const std::vector<VertexId> triangles = io::read_elements(a.input, g.first_index, attributes, middles, o.threads);
  std::vector<std::string> read = {a.input, base + ".node"};
  if (a.switches.find('p') != std::string::npos) {
    const io::Pslg p = io::read_pslg(base + ".poly", thread_count(a.threads));
    if (p.points.size() != g.points.size())
      throw InputError(base + ".poly has " + std::to_string(p.points.size()) + " vertices; the mesh has " +
                       std::to_string(g.points.size()));
    g.segments = p.segments, g.segment_markers = p.segment_markers;
    read.push_back(base + ".poly");
  } else if (std::filesystem::exists(base + ".edge")) {
    g.segments = segments_of_edges(base + ".edge", g, triangles.size() / 3);
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
  return finish(a, g, t, {}, !attributes.empty());
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
    refuse_ignored(a.all_edges || a.no_markers || a.jettison || a.no_node || a.no_ele || a.off || a.voronoi,
                   "switches e, B, j, N, E, g and v", why);
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
  return finish(a, g, t, domain.holes, false);
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
  mesh->add_option("-o,--output", a->output,
                   "OUT.ele (OUT.node and OUT.edge are written beside it, and as the switches ask OUT.neigh, OUT.off, "
                   "OUT.v.node and OUT.v.edge), or OUT.svg")
      ->required();
  CLI::Option* quality =
      mesh->add_option("--quality", a->quality, "no angle below DEG degrees, up to 34 (Triangle's -q)");
  mesh->add_option("--max-area", a->max_area, "no triangle larger than A (Triangle's -a)");
  mesh->add_flag("--region-areas", a->region_areas,
                 "the regions' own area bounds; refining a .ele, each triangle's from its .area file (Triangle's -a "
                 "with no number)");
  mesh->add_flag("--attributes", a->attributes, "each triangle's regional attribute in OUT.ele (Triangle's -A)");
  mesh->add_flag("--no-boundary-steiner", a->no_boundary, "no points added on the boundary (Triangle's -Y)");
  mesh->add_flag("--no-segment-steiner", a->no_segments,
                 "no points added on any segment, inside ones too, nor on the boundary (Triangle's -YY)");
  mesh->add_flag("--convex-hull", a->convex_hull,
                 "keep every triangle of the convex hull (Triangle's -c); else what the segments enclose");
  mesh->add_flag("--neighbours", a->neighbours, "write OUT.neigh too (Triangle's -n)");
  mesh->add_flag("--conforming", a->conforming, "conforming Delaunay: every edge Delaunay (Triangle's -D)");
  mesh->add_option("--max-steiner", a->max_steiner,
                   "stop refining after adding N points, with a warning (Triangle's -S; 0, the default: no limit)");
  mesh->add_flag("--second-order", a->second_order,
                 "six-node triangles for quadratic elements: a node at the middle of every edge, in OUT.node after "
                 "the vertices (Triangle's -o2)");
  mesh->add_option(
      "--switches", a->switches,
      "Triangle's switches: p, r, q, a, A, c, D, Y, YY, S, e, n, j, z, o2, O, B, N, E, P, g, v, C, Q, V; i, F, l, "
      "X and I are ignored (the exact result does not depend on them)");
  mesh->add_option("--method", a->method, choices_help("", Method::Auto));
  mesh->add_option("--threads", a->threads,
                   "threads of the triangulation and of the output's text (0, the default: all hardware threads)");
  return {mesh, [a, quality] {
            a->quality_given = quality->count() > 0;
            return run(*a);
          }};
}

}  // namespace ridt::tool
