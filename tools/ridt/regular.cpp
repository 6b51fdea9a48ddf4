// ridt regular: the regular (weighted Delaunay) triangulation (ridt/regular.hpp) of points with
// weights, read as rows x y w or as Triangle's .node whose first attribute is the weight, with
// the power diagram.
#include <fstream>

#include "command.hpp"
#include "io.hpp"
#include "ridt/regular.hpp"
#include "writer.hpp"

namespace ridt::tool {
namespace {

struct WeightedPoints {
  std::vector<Point> points;
  std::vector<double> weights;
  int first_index = 0;
};

// A .node file's points and first attribute, or rows of three numbers (text, or .bin float64).
WeightedPoints read_weighted(const std::string& path, unsigned threads) {
  WeightedPoints w;
  if (path.size() >= 5 && path.compare(path.size() - 5, 5, ".node") == 0) {
    io::Pslg g = io::read_pslg(path, threads);
    if (g.vertex_attributes == 0) throw IoError(path + ": no attribute to take the weights from");
    w.points = std::move(g.points);
    w.weights.reserve(w.points.size());
    for (std::size_t i = 0; i < w.points.size(); ++i) w.weights.push_back(g.point_attributes[i * g.vertex_attributes]);
    w.first_index = g.first_index;
    return w;
  }
  io::read_weighted(path, w.points, w.weights);
  return w;
}

void write_indices(const std::string& path, std::span<const VertexId> indices, int first_index) {
  io::Writer out(path);
  for (const VertexId v : indices) {
    out.put_int(v + static_cast<VertexId>(first_index));
    out.put('\n');
  }
  out.commit();
}

struct RegularArgs {
  std::string input, output, power, hidden, box;
  bool check = false;
  unsigned threads = 0;
};

int run_regular(const RegularArgs& a) {
  refuse_overwriting({a.input}, {a.output, a.power, a.hidden});
  const unsigned threads = thread_count(a.threads);
  const WeightedPoints w = read_weighted(a.input, threads);
  const RegularTriangulation t = triangulate_regular(w.points, w.weights, threads);
  if (!t.duplicates.empty())
    std::fprintf(stderr, "ridt: %zu duplicate point%s dropped (the first of equal points stands for them)\n",
                 t.duplicates.size(), t.duplicates.size() == 1 ? "" : "s");
  if (!t.hidden.empty())
    std::fprintf(stderr, "ridt: %zu point%s hidden by the others' weights (an empty power cell)\n", t.hidden.size(),
                 t.hidden.size() == 1 ? "" : "s");
  int status = 0;
  if (a.check) {
    const CheckResult r = check_regular(w.points, w.weights, t.triangles);
    std::fprintf(stderr, "ridt: %s\n", r.message.c_str());
    if (!r.valid) status = kExitInvalid;
  }
  io::write_triangulation(a.output, w.points, t, w.first_index, threads);
  if (!a.hidden.empty()) write_indices(a.hidden, t.hidden, w.first_index);
  if (!a.power.empty())
    io::write_voronoi(a.power, w.points, t, power_diagram(w.points, w.weights, t, threads),
                      box_option(a.box, w.points));
  return status;
}

}  // namespace

Command add_regular(CLI::App& app) {
  auto a = std::make_shared<RegularArgs>();
  CLI::App* cmd = app.add_subcommand(
      "regular", "the regular (weighted Delaunay) triangulation of points with weights, and their power diagram");
  cmd->add_option("input", a->input,
                  "weighted points: rows x y w (text, numbers apart by spaces or commas, '#' comments; or .bin, "
                  "three float64 a point), or a .node whose first attribute is the weight")
      ->required();
  cmd->add_option("-o,--output", a->output, "triangles: " + io::triangulation_formats())->required();
  cmd->add_option("--power", a->power, "the power diagram: " + io::voronoi_formats());
  cmd->add_option("--box", a->box,
                  "x0,y0,x1,y1: the box --power's .svg and .off clip to (default: the points' box and 10 % around)");
  cmd->add_option("--hidden", a->hidden, "the hidden points' indices, one a line (points whose power cell is empty)");
  cmd->add_flag("--check", a->check, "check the triangulation with the exact validator (exit 1 if invalid)");
  cmd->add_option("--threads", a->threads, "threads (0, the default: all hardware threads)");
  return {cmd, [a] { return run_regular(*a); }};
}

}  // namespace ridt::tool
