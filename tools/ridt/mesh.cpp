// ridt mesh INPUT.poly -o OUT.ele [--convex-hull] [--switches pcz] [--method M] [--threads N]:
// the constrained Delaunay triangulation of a planar straight-line graph, written as Triangle
// writes it: OUT.ele, OUT.node (every vertex, in the input's numbering) and OUT.edge (the
// segments' edges).
#include <filesystem>

#include "command.hpp"
#include "ridt/constrained.hpp"

namespace ridt::tool {
namespace {

struct Args {
  std::string input, output, switches;
  std::string method = "auto";
  unsigned threads = 0;
  bool convex_hull = false, zero_based = false;
};

// Triangle's switches that ridt takes: p (a .poly: always), c (keep the convex hull), z
// (number from 0), Q (quiet); the others are refused by name.
void apply_switches(Args& a) {
  for (const char c : a.switches) {
    switch (c) {
      case 'p':
      case 'Q':
        break;
      case 'c':
        a.convex_hull = true;
        break;
      case 'z':
        a.zero_based = true;
        break;
      case 'q':
        throw InputError("switch 'q' (a quality mesh) is not supported yet");
      case 'a':
        throw InputError("switch 'a' (an area bound) is not supported yet");
      default:
        throw InputError(std::string("unknown or unsupported switch '") + c + "' (ridt takes p, c, z and Q)");
    }
  }
}

// OUT.ele, OUT.node, OUT.edge: all or, on an error, none.
void write_mesh(const Args& a, const io::Pslg& g, const ConstrainedTriangulation& t) {
  if (std::filesystem::path(a.output).extension() != ".ele")
    throw InputError("mesh writes Triangle's files: give -o OUT.ele (OUT.node and OUT.edge are written beside it)");
  const int first = a.zero_based ? 0 : g.first_index;
  const std::filesystem::path base = std::filesystem::path(a.output).replace_extension();
  const std::string node = base.string() + ".node", edge = base.string() + ".edge";
  try {
    io::write_triangulation(a.output, g.points, t, first);
    io::write_points(node, g.points, first);
    io::write_edges(edge, t.edges, first);
  } catch (...) {
    for (const std::string& f : {a.output, node, edge}) std::filesystem::remove(f);
    throw;
  }
}

int run(Args a) {
  apply_switches(a);
  const io::Pslg g = io::read_pslg(a.input);
  if (!g.regions.empty())
    throw InputError(a.input + ": regional attributes and area bounds are not supported yet (" +
                     std::to_string(g.regions.size()) + " regions)");
  Options o;
  o.method = parse<Method>(a.method);
  o.threads = a.threads;
  o.canonical_order = true;
  Domain domain;
  domain.convex_hull = a.convex_hull;
  domain.holes = g.holes;
  const ConstrainedTriangulation t = triangulate_constrained(g.points, g.segments, o, domain);
  if (!t.warning.empty()) std::fprintf(stderr, "ridt: warning: %s\n", t.warning.c_str());
  write_mesh(a, g, t);
  return 0;
}

}  // namespace

Command add_mesh(CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* mesh = app.add_subcommand("mesh", "the constrained Delaunay triangulation of a .poly file (Triangle's -p)");
  mesh->add_option("input", a->input, "a planar straight-line graph: .poly (Triangle's)")->required();
  mesh->add_option("-o,--output", a->output, "OUT.ele; OUT.node and OUT.edge are written beside it")->required();
  mesh->add_flag("--convex-hull", a->convex_hull,
                 "keep every triangle of the convex hull (Triangle's -c); else what the segments enclose");
  mesh->add_option("--switches", a->switches, "Triangle's switches: p, c, z (number from 0) and Q are taken");
  mesh->add_option("--method", a->method, choices_help("", Method::Auto));
  mesh->add_option("--threads", a->threads, "threads (0, the default: all hardware threads)");
  return {mesh, [a] { return run(*a); }};
}

}  // namespace ridt::tool
