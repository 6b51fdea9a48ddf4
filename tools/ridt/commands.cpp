// ridt generate, ridt check, ridt voronoi and ridt formats: the small subcommands.
#include <cstdio>
#include <filesystem>
#include <string>

#include "command.hpp"
#include "ridt/check.hpp"
#include "ridt/generate.hpp"
#include "ridt/voronoi.hpp"

namespace ridt::tool {

Command add_generate(CLI::App& app) {
  struct Args {
    std::string dist = "uniform", output, memory_limit;
    std::uint32_t n = 0;
    std::uint64_t seed = 1;
  };
  auto a = std::make_shared<Args>();
  CLI::App* gen = app.add_subcommand("generate", "write points of one of the paper's distributions");
  gen->add_option("--dist", a->dist, choices_help("", Distribution::Uniform));
  gen->add_option("-n", a->n, "number of points")->required();
  gen->add_option("--seed", a->seed, "seed")->check(kSeed);
  gen->add_option("-o,--output", a->output, "output: " + io::point_output_formats())->required();
  gen->add_option("--memory-limit", a->memory_limit, kMemoryLimitHelp);
  return {gen, [a] {
            // The points (16 bytes each) and the text writer's buffers: its own and two runs of
            // 32,768 lines a thread, some 1.6 MB each (the process grew by 7.7, 23 and 166 MB at
            // 10^5, 10^6 and 10^7 text points on 2 threads, every distribution alike).
            const unsigned threads = thread_count(0);
            const std::size_t buffers =
                std::min<std::size_t>((2 * std::size_t{threads} + 1) * (std::size_t{13} << 17), std::size_t{64} * a->n);
            check_memory("generating " + std::to_string(a->n) + " points", std::size_t{18} * a->n + buffers,
                         a->memory_limit.empty() ? 0 : byte_size(a->memory_limit, "--memory-limit"));
            io::write_points(a->output, generate(parse<Distribution>(a->dist), a->n, a->seed), 0, threads);
            return 0;
          }};
}

namespace {

struct CheckArgs {
  std::string points, triangles, poly, edges;
  double min_angle = 0, max_area = 0;
  bool mesh() const { return !poly.empty() || !edges.empty() || min_angle != 0 || max_area != 0; }
};

// Triangles (corners) as a Delaunay triangulation of `points`, or as a mesh where a mesh's
// options are given.
CheckResult check_corners(const CheckArgs& a, std::span<const Point> points, int first_index,
                          std::span<const VertexId> t, unsigned threads) {
  if (!a.mesh()) return check(points, t);
  const io::Pslg g = a.poly.empty() ? io::Pslg{} : io::read_pslg(a.poly, threads);
  std::vector<VertexId> edges;
  if (!a.edges.empty()) edges = io::read_edge_file(a.edges, points.size(), first_index);
  MeshSpec spec;
  spec.edges = edges;
  spec.segments = g.segments;
  spec.input_points = a.poly.empty() ? 0 : g.points.size();
  spec.holes = g.holes;
  spec.min_angle = a.min_angle;
  spec.max_area = a.max_area;
  return check_mesh(points, t, spec);
}

// Six-node triangles (-o2): their middles, then their corners. A Delaunay triangulation is of
// every point, so for one the middles (no corner, as checked) leave the point list, the rest
// renumbered in order.
CheckResult check_six(const CheckArgs& a, const io::PointFile& p, std::span<const VertexId> t,
                      std::span<const VertexId> middles, unsigned threads) {
  const CheckResult six = check_second_order(p.points, t, middles);
  if (!six.valid) return six;
  std::vector<Point> kept;
  std::vector<VertexId> id(p.points.size(), 0), renumbered;
  for (const VertexId m : middles) id[m] = 1;
  for (std::size_t v = 0; v < id.size(); ++v)
    if (id[v] == 0) id[v] = static_cast<VertexId>(kept.size()), kept.push_back(p.points[v]);
  for (const VertexId v : t) renumbered.push_back(id[v]);
  CheckResult corners = a.mesh() ? check_corners(a, p.points, p.first_index, t, threads) : check(kept, renumbered);
  if (corners.valid) corners.message += "; " + six.message.substr(7);  // after "valid: "
  return corners;
}

int run_check(const CheckArgs& a) {
  // NaN compared false with every bound, and a negative one checked nothing: "valid".
  if (!(a.min_angle >= 0 && a.min_angle < 60))
    throw InputError("--min-angle: an angle in degrees from 0 to below 60, got " + std::to_string(a.min_angle));
  if (!(a.max_area >= 0) || !std::isfinite(a.max_area))
    throw InputError("--max-area: a positive finite area, got " + std::to_string(a.max_area));
  const unsigned threads = thread_count(0);  // as check() takes
  const io::PointFile p = io::read_points(a.points, threads);
  const CheckResult r = [&] {
    if (!a.mesh() && io::is_parts_index(a.triangles)) {
      // Parts may hold more triangles than memory with their edge table: read in passes, a
      // part at a time.
      const std::vector<std::string> parts = io::part_files(a.triangles);
      return check_in_passes(p.points, [&](const TriangleSink& sink) {
        for (const std::string& part : parts) sink(io::read_triangles(part, 0, threads));
      });
    }
    // A .ele may be of six-node triangles (-o2).
    std::vector<double> attributes;
    std::vector<VertexId> middles;
    const std::vector<VertexId> t = io::extension(a.triangles) == ".ele"
        ? io::read_elements(a.triangles, p.first_index, attributes, middles, threads)
        : io::read_triangles(a.triangles, p.first_index, threads);
    return middles.empty() ? check_corners(a, p.points, p.first_index, t, threads)
                           : check_six(a, p, t, middles, threads);
  }();
  std::printf("%s\n", r.message.c_str());
  // A mesh checked as a plain triangulation fails on its fixed boundary: say how to check it
  // as a mesh where ridt mesh's OUT.edge lies beside its OUT.ele.
  if (const std::string edges = a.triangles.substr(0, a.triangles.size() - 4) + ".edge";
      !r.valid && !a.mesh() && io::extension(a.triangles) == ".ele" && std::filesystem::exists(edges)) {
    std::fflush(stdout);
    std::fprintf(stderr,
                 "ridt check: checked as a Delaunay triangulation of its points; for a mesh (ridt mesh's output) "
                 "give its segments: --edges %s, or its input with --poly\n",
                 edges.c_str());
  }
  return r.valid ? 0 : kExitInvalid;
}

}  // namespace

Command add_check(CLI::App& app) {
  auto a = std::make_shared<CheckArgs>();
  CLI::App* chk = app.add_subcommand("check", "validate a triangulation or mesh exactly");
  chk->add_option("points", a->points, "the points (for a mesh, every vertex: ridt mesh's OUT.node)")->required();
  chk->add_option("triangles", a->triangles,
                  "the triangles: " + io::triangle_formats() +
                      " (a .ele of six-node triangles, -o2: their middles checked too), or the .parts index of "
                      "ridt-mpi's parts")
      ->required();
  chk->add_option("--poly", a->poly, "a mesh's input .poly: its segments must be chains of edges, its holes empty");
  chk->add_option("--edges", a->edges,
                  "a mesh's .edge file (ridt mesh's OUT.edge): its segment edges (without it, with --poly: the mesh's "
                  "edges along the segments)");
  chk->add_option("--min-angle", a->min_angle, "no angle below DEG degrees (but beside small input angles)");
  chk->add_option("--max-area", a->max_area, "no triangle larger than A");
  return {chk, [a] { return run_check(*a); }};
}

Command add_voronoi(CLI::App& app) {
  struct Args {
    std::string input, output, box;
    unsigned threads = 0;
  };
  auto a = std::make_shared<Args>();
  CLI::App* vor = app.add_subcommand("voronoi", "the Voronoi diagram of points");
  vor->add_option("points", a->input, "the points: " + io::point_formats())->required();
  vor->add_option("-o,--output", a->output, "output: " + io::voronoi_formats())->required();
  vor->add_option("--box", a->box,
                  "x0,y0,x1,y1: the box .svg and .off clip to (default: the points' box and "
                  "10 % around)");
  vor->add_option("--threads", a->threads, "threads (0, the default: all hardware threads)");
  return {vor, [a] {
            refuse_overwriting({a->input}, {a->output});
            const io::PointFile p = io::read_points(a->input, thread_count(a->threads));
            Options o;
            o.method = Method::Auto;
            o.threads = a->threads;
            const Triangulation t = triangulate(p.points, o);
            if (!t.warning.empty()) throw InputError("no Voronoi vertex: " + t.warning);
            const Voronoi vd = voronoi(p.points, t, a->threads);
            io::write_voronoi(a->output, p.points, t, vd, box_option(a->box, p.points));
            return 0;
          }};
}

Command add_formats(CLI::App& app) {
  struct Args {
    bool markdown = false, summary = false;
  };
  auto a = std::make_shared<Args>();
  CLI::App* f = app.add_subcommand("formats", "every file format, by extension, and what it holds in each role");
  f->add_flag("--markdown", a->markdown, "as a Markdown table (docs/cli.md's)");
  f->add_flag("--summary", a->summary, "a line a role, as a Markdown table (the README's)");
  return {f, [a] {
            std::fputs(io::formats_table(a->markdown, a->summary).c_str(), stdout);
            return 0;
          }};
}

}  // namespace ridt::tool
