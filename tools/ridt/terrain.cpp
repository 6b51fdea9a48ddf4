// ridt tin INPUT -o OUT.gpkg|.shp|.geojson|.fgb|.ply|.obj
// ridt dem INPUT -o DEM.tif|.img|.png --resolution R [--method linear|natural|nearest]
//          [--max-edge L] [--extent x0,y0,x1,y1] [--type float32|float64] [--hillshade F.png]
// Both: [--class 2,9] [--returns all|first|last|single] [--withheld] [--columns x,y,z]
//       [--duplicates first|last|lowest|highest|mean] [--threads N] [--stats]
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>

#include "command.hpp"
#include "ridt/terrain.hpp"
#include "terrain_io.hpp"

namespace ridt::tool {
namespace {

struct Args {
  std::string input, output, classes, returns = "all", columns, duplicates = "first";
  bool withheld = false, stats = false;
  unsigned threads = 0;
  // dem only
  double resolution = 0, max_edge = std::numeric_limits<double>::infinity();
  std::string method = "linear", extent, type = "float64", hillshade;
};

// The points read, heights merged, and triangulated; the times on `stats`.
struct Tin {
  io::Terrain terrain;
  Triangulation t;
  double read_s = 0, triangulate_s = 0;
};

// Refuses the options that the input's format would ignore: LAS's filters on a table or a GDAL
// layer, a table's columns on LAS.
void refuse_ignored_filters(const Args& a) {
  const std::string ext = io::extension(a.input);
  const bool las = ext == ".las" || ext == ".laz";
  const std::string no_las = "is for LAS input, and " + a.input + " is not LAS (its points have no classes or returns)";
  refuse_ignored(!las && !a.classes.empty(), "--class", no_las);
  refuse_ignored(!las && a.returns != "all", "--returns", no_las);
  refuse_ignored(!las && a.withheld, "--withheld", no_las);
  refuse_ignored(las && !a.columns.empty(), "--columns",
                 "is for a table or a GDAL layer; LAS has its x, y and z (" + a.input + ")");
}

Tin make_tin(const Args& a, ProgressLine& progress) {
  io::PointFilter filter;
  filter.returns = parse<Returns>(a.returns);  // an unknown value named first
  refuse_ignored_filters(a);
  filter.withheld = a.withheld;
  if (!a.classes.empty())
    for (const double c : numbers(a.classes, "--class")) {
      if (c != std::floor(c) || c < 0 || c > 255) throw InputError("--class: classes are integers 0 to 255");
      filter.classes.push_back(static_cast<int>(c));
    }
  io::Columns columns;
  if (!a.columns.empty()) {
    std::vector<std::string> names;
    for (std::size_t at = 0; at <= a.columns.size();) {
      const std::size_t comma = std::min(a.columns.find(',', at), a.columns.size());
      names.push_back(a.columns.substr(at, comma - at));
      at = comma + 1;
    }
    if (names.size() != 3) throw InputError("--columns: give three names or numbers, x,y,z");
    columns = {names[0], names[1], names[2]};
  }
  const Merge merge = parse<Merge>(a.duplicates);
  Tin tin;
  auto t0 = std::chrono::steady_clock::now();
  progress.show("reading");
  tin.terrain = io::read_terrain(a.input, filter, columns);
  tin.read_s = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  progress.show("triangulating");
  Options o;
  o.method = Method::Auto;  // partition on more than one thread
  o.threads = a.threads;
  tin.t = triangulate(tin.terrain.points, o);
  if (tin.t.size() == 0)
    throw InputError(a.input + ": no TIN from " + std::to_string(tin.terrain.points.size()) + " points" +
                     (tin.t.warning.empty() ? "" : " (" + tin.t.warning + ")"));
  merge_heights(tin.t, tin.terrain.z, merge);
  tin.triangulate_s = seconds_since(t0);
  return tin;
}

void print_stats(const Tin& tin, double write_s, std::size_t cells) {
  std::printf("points %zu\ndistinct %zu\ntriangles %zu\n", tin.terrain.points.size(),
              tin.terrain.points.size() - tin.t.duplicates.size(), tin.t.size());
  if (cells > 0) std::printf("cells %zu\n", cells);
  std::printf("crs %s\ntime_read_s %.6f\ntime_triangulate_s %.6f\ntime_write_s %.6f\npeak_rss_bytes %lld\n",
              tin.terrain.crs.empty() ? "none" : "given", tin.read_s, tin.triangulate_s, write_s, peak_rss_bytes());
}

int run_tin(const Args& a) {
  refuse_overwriting({a.input}, {a.output});
  ProgressLine progress;
  const Tin tin = make_tin(a, progress);
  const auto t0 = std::chrono::steady_clock::now();
  progress.show("writing");
  io::write_tin(a.output, tin.terrain, tin.t);
  progress.clear();
  if (a.stats) print_stats(tin, seconds_since(t0), 0);
  return 0;
}

int run_dem(const Args& a) {
  if (!(a.resolution > 0) || !std::isfinite(a.resolution)) throw InputError("--resolution: a positive cell size");
  if (a.type != "float32" && a.type != "float64") throw InputError("--type: float32 or float64");
  refuse_overwriting({a.input}, {a.output, a.hillshade});
  if (!a.hillshade.empty() && io::extension(a.hillshade) != ".png")
    throw InputError("--hillshade: the hillshade is a .png picture, got " + a.hillshade +
                     " (for the DEM itself, -o DEM.tif)");
  ProgressLine progress;
  const Tin tin = make_tin(a, progress);
  io::Box box = io::box_around(tin.terrain.points, 0);
  if (!a.extent.empty()) {
    const std::vector<double> e = numbers(a.extent, "--extent");
    if (e.size() != 4 || !(e[0] < e[2]) || !(e[1] < e[3]))
      throw InputError("--extent: give x0,y0,x1,y1 with x0 < x1 and y0 < y1");
    box = {e[0], e[1], e[2], e[3]};
  }
  DemOptions o;
  o.method = parse<Surface>(a.method);
  o.max_edge = a.max_edge;
  o.threads = a.threads;
  const Dem dem(tin.terrain.points, tin.t, tin.terrain.z,
                RasterGrid::around(box.x0, box.y0, box.x1, box.y1, a.resolution), o);
  const auto t0 = std::chrono::steady_clock::now();
  io::DemFile file;
  file.crs = tin.terrain.crs;
  file.float32 = a.type == "float32";
  file.progress = [&](double f) { progress.show("writing the DEM", f); };
  io::write_dem(a.output, dem, file);
  if (!a.hillshade.empty()) io::write_hillshade(a.hillshade, dem);
  progress.clear();
  if (a.stats) print_stats(tin, seconds_since(t0), dem.grid().size());
  return 0;
}

void add_common(CLI::App* c, Args& a) {
  c->add_option("input", a.input, "points with heights: " + io::terrain_formats())->required();
  c->add_option("--class", a.classes, "LAS: keep these classifications only, e.g. 2 (ground) or 2,9");
  c->add_option("--returns", a.returns, choices_help("LAS: which returns", Returns::All));
  c->add_flag("--withheld", a.withheld, "LAS: keep points flagged withheld too");
  c->add_option(
      "--columns", a.columns,
      "x,y,z: the columns (names or 1-based numbers) of a table, or the height field of a GDAL layer as the third");
  c->add_option("--duplicates", a.duplicates, choices_help("the height of points equal in x and y", Merge::First));
  c->add_option("--threads", a.threads, "threads (0, the default: all hardware threads)");
  c->add_flag("--stats", a.stats, "print counts, times and peak memory on stdout");
}

}  // namespace

Command add_tin(CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* c = app.add_subcommand("tin", "a TIN (triangles with heights) from points with heights");
  add_common(c, *a);
  c->add_option("-o,--output", a->output, "the TIN: " + io::tin_formats())->required();
  return {c, [a] { return run_tin(*a); }};
}

Command add_dem(CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* c = app.add_subcommand("dem", "a DEM raster (GeoTIFF) interpolated in the TIN of points with heights");
  add_common(c, *a);
  c->add_option("-o,--output", a->output, "the DEM: " + io::dem_formats())->required();
  c->add_option("--resolution", a->resolution, "the cell size, in the points' units")->required();
  c->add_option("--method", a->method, choices_help("", Surface::Linear));
  c->add_option("--max-edge", a->max_edge, "no value in triangles with a side longer than this (lakes, gaps)");
  c->add_option("--extent", a->extent, "x0,y0,x1,y1 (default: the points' box), grown to multiples of the cell");
  c->add_option("--type", a->type, "float64 (default) or float32 cells");
  c->add_option("--hillshade", a->hillshade, "also a hillshade .png of the DEM");
  return {c, [a] { return run_dem(*a); }};
}

}  // namespace ridt::tool
