// ridt: the command-line tool. One file a subcommand (command.hpp):
//   ridt triangulate INPUT [-o OUTPUT] [--method M] [--threads N] [--order O] [--locate L] ...
//   ridt generate --dist uniform|normal|grid|clusters -n N [--seed S] -o FILE
//   ridt check POINTS TRIANGLES
//   ridt voronoi POINTS -o OUT.svg|.off|.json [--box x0,y0,x1,y1] [--threads N]
//   ridt interpolate POINTS VALUES (QUERIES | --grid nx,ny[,x0,y0,x1,y1]) -o OUT.csv|.bin|.png
//   ridt mesh INPUT.poly -o OUT.ele [--convex-hull] [--switches pcz]
//   ridt tin INPUT.las|.csv|.gpkg -o OUT.gpkg|.shp|.ply [--class 2]
//   ridt dem INPUT.las|.csv|.gpkg -o DEM.tif --resolution R [--method M] [--max-edge L]
//   ridt sphere POINTS -o OUT.off [--voronoi CELLS.off] [--areas AREAS.txt] [--check]
//   ridt regular WEIGHTED -o OUT.ele [--power CELLS.svg] [--hidden FILE] [--check]
//   ridt periodic POINTS -o OUT.txt [--domain x0,y0,x1,y1] [--neighbors FILE] [--cells FILE] [--check]
// Exit status: 0 success, 1 an invalid triangulation (check), 2 bad input or usage, 3 an
// internal error.

#include <optional>

#include "command.hpp"
#include "temporaries.hpp"

namespace {

using namespace ridt::tool;

// The input files are mapped into memory where they are regular files: one cut short while it
// is read (or on storage that fails) raises SIGBUS at the pages past its new end. The tool then
// says so and exits with status 2 (temporaries.hpp's end_on_signals), as it does on any error.
constexpr const char* kBusError =
    "ridt: error: an input file could not be read to its end (it was cut short while ridt read it, or its "
    "storage failed)\n";

/// "ridt VERSION (COMPILER, assertions on|off)": what benchmark pages record of the binary.
std::string version() {
#if defined(__clang__)
  const std::string compiler = std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  const std::string compiler = std::string("g++ ") + __VERSION__;
#else
  const std::string compiler = "unknown compiler";
#endif
#ifdef NDEBUG
  const char* asserts = "assertions off";
#else
  const char* asserts = "assertions on";
#endif
  return std::string("ridt ") + RIDT_VERSION + " (" + compiler + ", " + asserts + ")";
}

// Parses the command line; returns the exit status when the tool is done already (help,
// version, a usage error).
std::optional<int> parse(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "ridt: error: %s\nrun 'ridt --help' for usage\n", e.what());
    return kExitUsage;
  }
  return std::nullopt;
}

// Runs the chosen subcommand; errors become a message and an exit status.
int run(const std::vector<Command>& commands) {
  try {
    for (const Command& c : commands)
      if (*c.app) return c.run();
  } catch (const ridt::IoError& e) {
    std::fprintf(stderr, "ridt: error: %s\n", e.what());
    return kExitUsage;
  } catch (const ridt::InputError& e) {
    std::fprintf(stderr, "ridt: error: %s\n", e.what());
    return kExitUsage;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "ridt: error: out of memory (the system gave less than the run needed)\n");
    return kExitUsage;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ridt: internal error: %s\n", e.what());
    return 3;
  }
  return kExitUsage;
}

}  // namespace

int main(int argc, char** argv) {
  // One triangulation a process: blocks kept for a next call would only raise the peak.
  ridt::set_memory_cache_limit(0);
  // Interrupted, killed or cut short: no temporary file left beside an output.
  ridt::io::end_on_signals(kBusError);
  CLI::App app{"ridt: exact 2D Delaunay triangulation by randomized incremental insertion"};
  app.require_subcommand(1);
  app.set_version_flag("--version", version());
  const std::vector<Command> commands = {add_triangulate(app), add_generate(app), add_check(app),    add_voronoi(app),
                                         add_interpolate(app), add_mesh(app),     add_tin(app),      add_dem(app),
                                         add_sphere(app),      add_regular(app),  add_periodic(app), add_formats(app)};
  if (const std::optional<int> done = parse(app, argc, argv)) return *done;
  return run(commands);
}
