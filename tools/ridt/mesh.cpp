// ridt mesh INPUT.poly -o OUT.ele [--quality DEG] [--max-area A] [--convex-hull] [--switches pq30a0.1]
// ...: the constrained Delaunay triangulation or quality mesh of a planar straight-line graph
// (or of the convex hull of points alone, from a .node; or a mesh already made refined, from a
// .ele), as Triangle makes it: the files are read into ridt::triangle::Input, the switches and
// options parsed into ridt::triangle::Switches, the library's ridt::triangle::triangulate does
// the rest, and its Output is written as Triangle writes it (mesh_files.cpp).
#include <filesystem>
#include <string_view>

#include "command.hpp"
#include "mesh_files.hpp"
#include "ridt/triangle.hpp"

namespace ridt::tool {
namespace {

struct Args {
  std::string input, output, switches, size;
  double gradation = 0;
  std::string method = "auto";
  unsigned threads = 0;
  double quality = 0, max_area = 0;
  std::size_t max_steiner = 0;  // 0: no limit
  bool convex_hull = false, region_areas = false, attributes = false, no_boundary = false, no_segments = false,
       neighbours = false, conforming = false, second_order = false;
};

// The switches the string and the long options ask together.
triangle::Switches switches_of(const Args& a, bool quality_given, bool steiner_given) {
  triangle::Switches w = triangle::parse_switches(a.switches);
  if (quality_given) w.quality = true, w.min_angle = a.quality;
  if (a.max_area != 0) w.max_area = a.max_area;
  if (steiner_given) w.limit_steiner = a.max_steiner > 0, w.max_steiner = a.max_steiner;
  w.region_areas |= a.region_areas, w.attributes |= a.attributes, w.convex_hull |= a.convex_hull;
  w.no_boundary_steiner |= a.no_boundary || a.no_segments, w.no_segment_steiner |= a.no_segments;
  w.neighbors |= a.neighbours, w.conforming |= a.conforming, w.second_order |= a.second_order;
  w.refine |= io::extension(a.input) == ".ele";
  if (!w.refine && io::extension(a.input) != ".node") w.pslg = true;  // a .poly is a graph with or without p
  return w;
}

// Which files beside OUT.ele the switches ask for.
io::MeshFileSet files_of(const triangle::Switches& w) { return {!w.no_ele, !w.no_node, w.neighbors, w.off, w.voronoi}; }

// The files asked for: OUT.svg, or OUT.ele and the files beside it.
std::vector<std::string> outputs(const Args& a, const triangle::Switches& w) {
  const std::string extension = io::extension(a.output);
  if (extension == ".svg") {
    const char* why = "is not drawn: a drawing (.svg) has no neighbours, attributes or numbering; give -o OUT.ele";
    refuse_ignored(w.neighbors, "--neighbours (n)", why);
    refuse_ignored(w.attributes, "--attributes (A)", why);
    refuse_ignored(w.zero_based, "numbering from 0 (z)", why);
    refuse_ignored(w.second_order, "--second-order (o2)", why);
    refuse_ignored(w.all_edges || w.no_markers || w.jettison || w.no_node || w.no_ele || w.off || w.voronoi,
                   "switches e, B, j, N, E, g and v", why);
    return {a.output};
  }
  if (extension != ".ele")
    throw InputError(
        "mesh writes Triangle's files or a drawing: give -o OUT.ele (OUT.node and OUT.edge are "
        "written beside it; switch g adds OUT.off, v OUT.v.node and OUT.v.edge) or OUT.svg");
  return io::mesh_file_paths(a.output, files_of(w));
}

// The segments that a mesh's .edge file gives: all its edges where it lists fewer than there
// are (ridt mesh's OUT.edge: the segments' edges); where it lists as many as a mesh of
// `triangles` has at least (3 a triangle, each inside edge shared: Triangle's -e, ridt's e),
// those with a nonzero marker (a segment's own, or 1 on the boundary).
std::vector<VertexId> segments_of_edges(const std::string& path, std::size_t points, int first_index,
                                        std::size_t triangles) {
  std::vector<std::int64_t> markers;
  std::vector<VertexId> edges = io::read_edge_file(path, points, first_index, &markers);
  if (edges.size() < 3 * triangles || markers.empty()) return edges;  // 2 numbers an edge, 3/2 edges a triangle
  std::vector<VertexId> marked;
  for (std::size_t k = 0; k < markers.size(); ++k)
    if (markers[k] != 0) marked.push_back(edges[2 * k]), marked.push_back(edges[2 * k + 1]);
  return marked;
}

// Triangle's input from a .poly or .node (its vertices, markers, attributes, segments, holes
// and regions), moved out of the file's contents.
triangle::Input input_of(io::Pslg&& g) {
  triangle::Input in;
  in.vertices = std::move(g.points);
  in.vertex_markers = std::move(g.point_markers);
  in.attribute_count = g.vertex_attributes;
  in.vertex_attributes = std::move(g.point_attributes);
  in.segments = std::move(g.segments);
  in.segment_markers = std::move(g.segment_markers);
  in.holes = std::move(g.holes);
  for (const auto& r : g.regions) in.regions.push_back({{r[0], r[1]}, r[2], r[3]});
  return in;
}

// Triangle's -r: IN.ele and IN.node, with the segments of IN.poly (with switch p, as Triangle's
// -rp) or else of IN.edge (segments_of_edges), where there; IN.area's bounds with a and no
// number; the .ele's first attribute carried. `read` gets the files read.
triangle::Input refine_input(const Args& a, triangle::Switches& w, int& first_index, std::vector<std::string>& read) {
  const std::string base = a.input.substr(0, a.input.size() - 4);
  io::Pslg g = io::read_pslg(base + ".node", thread_count(a.threads));
  first_index = g.first_index;
  const std::size_t points = g.points.size();
  triangle::Input in = input_of(std::move(g));
  std::vector<VertexId> middles;  // of a six-node mesh: left unused, its corners refined
  in.triangles = io::read_elements(a.input, g.first_index, in.triangle_attributes, middles, thread_count(a.threads));
  read = {a.input, base + ".node"};
  if (w.pslg) {
    const io::Pslg p = io::read_pslg(base + ".poly", thread_count(a.threads));
    if (p.points.size() != points)
      throw InputError(base + ".poly has " + std::to_string(p.points.size()) + " vertices; the mesh has " +
                       std::to_string(points));
    in.segments = p.segments, in.segment_markers = p.segment_markers;
    read.push_back(base + ".poly");
  } else if (std::filesystem::exists(base + ".edge")) {
    in.segments = segments_of_edges(base + ".edge", points, first_index, in.triangles.size() / 3);
    w.pslg = true;  // the .edge's segments kept
    read.push_back(base + ".edge");
  }
  if (w.region_areas && !(w.limit_steiner && w.max_steiner == 0)) {
    in.triangle_max_area = io::read_area_file(base + ".area", in.triangles.size() / 3, first_index);
    read.push_back(base + ".area");
  } else {
    w.region_areas = false;
  }
  return in;
}

int run(const Args& a, triangle::Switches w) {
  const std::vector<std::string> out = outputs(a, w);
  Options o;
  o.method = parse<Method>(a.method);
  o.threads = a.threads;
  triangle::Input in;
  int first_index = 0;
  std::vector<std::string> read;
  if (w.refine) {
    if (io::extension(a.input) != ".ele")
      throw InputError("switch 'r' refines a mesh: give its .ele (its .node is read beside it)");
    in = refine_input(a, w, first_index, read);
  } else {
    refuse_overwriting({a.input}, out);
    io::Pslg g = io::read_pslg(a.input, thread_count(a.threads));
    first_index = g.first_index;
    read = {g.node_file};
    in = input_of(std::move(g));
  }
  if (!a.size.empty()) {
    in.size = io::read_size_field(a.size, thread_count(a.threads), a.gradation);
    read.push_back(a.size);
  }
  refuse_overwriting(read, out);
  const triangle::Output m = triangle::triangulate(in, w, o);
  if (!m.warning.empty()) std::fprintf(stderr, "ridt: warning: %s\n", m.warning.c_str());
  if (m.crossings > 0)
    std::fprintf(stderr, "ridt: %zu points added where segments cross (the first %zu added points)\n", m.crossings,
                 m.crossings);
  if (w.check) std::fprintf(stderr, "ridt: consistency check: %s\n", m.check.message.c_str());
  write_mesh(a.output, m, files_of(w), w.zero_based ? 0 : first_index, a.threads);
  return !w.check || m.check.valid ? 0 : kExitInvalid;
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
  mesh->add_option("--size", a->size,
                   "a target edge length over the plane: no triangle's longest edge above it at its centroid; " +
                       io::size_formats() +
                       " (a .node's points with the size their first attribute, a .ele with its .node: a background "
                       "mesh, a grid)");
  mesh->add_option("--gradation", a->gradation,
                   "with --size: the sizes first lowered where they grow faster than G along the field's grid or "
                   "mesh, so that neighbouring triangles' sizes differ by about G times at most (0.2: 20 %)")
      ->check(non_negative("a gradation"))
      ->needs("--size");
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
  mesh->add_option("--switches", a->switches,
                   "Triangle's switches: " + std::string(triangle::switches_taken()) +
                       " (i, F, l, X and I are ignored: the exact result does not depend on them)");
  mesh->add_option("--method", a->method, choices_help("", Method::Auto));
  mesh->add_option("--threads", a->threads,
                   "threads of the triangulation, of quality refinement (the same mesh on any number) and of the "
                   "output's text (0, the default: all hardware threads)");
  CLI::Option* steiner = mesh->get_option("--max-steiner");
  return {mesh, [a, quality, steiner] { return run(*a, switches_of(*a, quality->count() > 0, steiner->count() > 0)); }};
}

}  // namespace ridt::tool
