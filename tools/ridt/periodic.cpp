// ridt periodic: the periodic Delaunay triangulation (ridt/periodic.hpp) of points on the flat
// torus of a given domain, with its Voronoi cells.
//
// Its triangles come as text, a line each: the three corners' indices, then each corner's
// offset (dx dy: the corner is the point moved by dx widths and dy heights); its neighbours
// the same way (the three triangles across from the corners, then the offset that moves each
// onto the shared edge); its cells a line each: the cell's corners x y, counter-clockwise round
// the point where it is given.
#include "ridt/periodic.hpp"
#include "command.hpp"
#include "io.hpp"
#include "writer.hpp"

namespace ridt::tool {
namespace {

struct PeriodicArgs {
  std::string input, output, neighbors, cells, domain = "0,0,1,1";
  bool check = false;
  unsigned threads = 0;
};

PeriodicDomain domain_option(const std::string& text) {
  const std::vector<double> v = numbers(text, "--domain");
  if (v.size() != 4) throw InputError("--domain: four numbers x0,y0,x1,y1, not " + std::to_string(v.size()));
  return {{v[0], v[1]}, v[2] - v[0], v[3] - v[1]};
}

// Rows of indices (`first` added) and offset pairs, three of each a triangle.
template <class Index>
void write_rows(const std::string& path, std::span<const Index> indices, std::int64_t first,
                std::span<const Offset> offsets, unsigned threads) {
  io::Writer out(path);
  out.put_lines(indices.size() / 3, threads, [&](std::size_t t, io::TextPart& line) {
    for (std::size_t i = 0; i < 3; ++i) line.put_int(indices[3 * t + i] + first), line.put(' ');
    for (std::size_t i = 0; i < 3; ++i) {
      line.put_int(offsets[3 * t + i].dx), line.put(' '), line.put_int(offsets[3 * t + i].dy);
      line.put(i < 2 ? ' ' : '\n');
    }
  });
  out.commit();
}

void write_cells(const std::string& path, std::span<const Point> points, const PeriodicTriangulation& t) {
  const PeriodicVoronoi v = periodic_voronoi(points, t);
  io::Writer out(path);
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::uint32_t k = v.cell_offsets[i]; k < v.cell_offsets[i + 1]; ++k) {
      const Point c = v.vertices[static_cast<std::size_t>(v.cell_vertices[k])];
      if (k > v.cell_offsets[i]) out.put(' ');
      out.put_double(c.x + v.cell_shifts[k].dx * t.domain.width), out.put(' ');
      out.put_double(c.y + v.cell_shifts[k].dy * t.domain.height);
    }
    out.put('\n');
  }
  out.commit();
}

int run_periodic(const PeriodicArgs& a) {
  refuse_overwriting({a.input}, {a.output, a.neighbors, a.cells});
  const unsigned threads = thread_count(a.threads);
  const PeriodicDomain domain = domain_option(a.domain);
  const io::PointFile in = io::read_points(a.input, threads);
  // (neighbours only where they are written, or make the cells)
  const PeriodicTriangulation t =
      triangulate_periodic(in.points, domain, PeriodicOptions{threads, !a.neighbors.empty() || !a.cells.empty()});
  if (!t.duplicates.empty())
    std::fprintf(stderr, "ridt: %zu duplicate point%s dropped (the first of equal points stands for them)\n",
                 t.duplicates.size(), t.duplicates.size() == 1 ? "" : "s");
  int status = 0;
  if (a.check) {
    const CheckResult r = check_periodic(in.points, domain, t.triangles, t.offsets);
    std::fprintf(stderr, "ridt: %s\n", r.message.c_str());
    if (!r.valid) status = kExitInvalid;
  }
  write_rows(a.output, std::span<const VertexId>(t.triangles), in.first_index, t.offsets, threads);
  if (!a.neighbors.empty())
    write_rows(a.neighbors, std::span<const std::int32_t>(t.neighbors), 0, t.neighbor_offsets, threads);
  if (!a.cells.empty()) write_cells(a.cells, in.points, t);
  return status;
}

}  // namespace

Command add_periodic(CLI::App& app) {
  auto a = std::make_shared<PeriodicArgs>();
  CLI::App* cmd = app.add_subcommand(
      "periodic", "the periodic Delaunay triangulation of points on the flat torus of a domain, and its Voronoi cells");
  cmd->add_option("input", a->input, "points: " + io::point_formats() + "; each inside the domain")->required();
  cmd->add_option("--domain", a->domain,
                  "x0,y0,x1,y1: the domain [x0, x1) x [y0, y1), whose sides are identified (default 0,0,1,1)");
  cmd->add_option("-o,--output", a->output,
                  "triangles, a line each: three point indices, then each corner's offset dx dy (the point moved "
                  "by dx widths and dy heights)")
      ->required();
  cmd->add_option("--neighbors", a->neighbors,
                  "neighbours, a line each: the triangles across from the three corners (0-based), then the offset "
                  "dx dy that moves each onto the shared edge");
  cmd->add_option("--cells", a->cells,
                  "Voronoi cells, a line a point: the corners x y counter-clockwise round the point (empty for a "
                  "duplicate)");
  cmd->add_flag("--check", a->check, "check the triangulation with the exact validator (exit 1 if invalid)");
  cmd->add_option("--threads", a->threads, "threads (0, the default: all hardware threads)");
  return {cmd, [a] { return run_periodic(*a); }};
}

}  // namespace ridt::tool
