// ridt: the command-line tool.
//   ridt triangulate INPUT [-o OUTPUT] [--seed S] [--order brio|random] [--locate auto|dag|walk]
//                          [--method M] [--threads N] [--bounding symbolic|finite] [--k K]
//                          [--stats[=json|table]] [--profile]
//   ridt generate --dist uniform|normal|grid|clusters -n N [--seed S] -o FILE
//   ridt check POINTS TRIANGLES
//   ridt voronoi POINTS -o OUT.svg|.off|.json [--box x0,y0,x1,y1] [--threads N]
//   ridt interpolate POINTS VALUES (QUERIES | --grid nx,ny[,x0,y0,x1,y1]) -o OUT.csv|.bin|.png
//                    [--method linear|natural|nearest] [--fill V] [--threads N]
// Exit status: 0 success, 1 an invalid triangulation (check), 2 bad input or usage.
#include <sys/resource.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "generate.hpp"
#include "io.hpp"
#include "ridt/check.hpp"
#include "ridt/interpolate.hpp"
#include "ridt/voronoi.hpp"
#include "ridt/ridt.hpp"

namespace {

constexpr int kExitInvalid = 1;
constexpr int kExitUsage = 2;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

long long peak_rss_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<long long>(u.ru_maxrss) * 1024;  // Linux reports kilobytes
}

// One line on stderr that says how far a long run is, only when stderr is a terminal: never
// in a pipe or a file, and never on stdout, where --stats goes. It appears once the run has
// taken half a second, changes at most ten times a second, and is erased when done.
class ProgressLine {
 public:
  ProgressLine() : on_(isatty(STDERR_FILENO) == 1), start_(std::chrono::steady_clock::now()) {}
  ~ProgressLine() { clear(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  bool on() const { return on_; }

  /// "ridt: PHASE" and, for a fraction in [0, 1), its percentage.
  void show(const char* phase, double fraction = -1) {
    if (!on_) return;
    const double now = seconds_since(start_);
    if (now < 0.5 || (shown_ && now - last_ < 0.1 && phase == phase_)) return;
    if (fraction >= 0 && fraction < 1)
      std::fprintf(stderr, "\r\033[Kridt: %s %3.0f%%", phase, 100 * fraction);
    else
      std::fprintf(stderr, "\r\033[Kridt: %s", phase);
    std::fflush(stderr);
    shown_ = true, last_ = now, phase_ = phase;
  }

  /// Erases the line (before a message, and at the end).
  void clear() {
    if (!shown_) return;
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
    shown_ = false;
  }

 private:
  bool on_, shown_ = false;
  std::chrono::steady_clock::time_point start_;
  double last_ = 0;
  const char* phase_ = nullptr;
};

struct TriangulateArgs {
  std::string input, output, bounding = "symbolic", method = "serial", stats;
  std::string order = "brio", locate = "auto";
  std::uint64_t seed = 1;
  double k = 10;
  unsigned threads = 0;
  bool profile = false, paper_locking = false, no_thread_timing = false;
};

void print_stats(const TriangulateArgs& a, const ridt::Triangulation& t, double t_read,
                 double t_write, bool table) {
  const ridt::Stats& s = t.stats;
  struct Field {
    const char* key;
    std::string value;
  };
  auto num = [](double v) {
    std::ostringstream o;
    o.precision(6);
    o << v;
    return o.str();
  };
  std::vector<Field> f = {
      {"method", "\"" + a.method + "\""},
      {"threads", std::to_string(s.threads)},
      {"seed", std::to_string(a.seed)},
      {"order", "\"" + a.order + "\""},
      {"locate", s.locate == ridt::Locate::Walk ? "\"walk\"" : s.locate == ridt::Locate::Root ? "\"root\"" : "\"dag\""},
      {"bounding", "\"" + a.bounding + "\""},
      {"points", std::to_string(s.points)},
      {"distinct", std::to_string(s.distinct)},
      {"duplicates", std::to_string(s.duplicates)},
      {"triangles", std::to_string(t.size())},
      {"hull", std::to_string(t.hull.size())},
      {"dag_nodes", std::to_string(s.dag_nodes)},
      {"flips", std::to_string(s.flips)},
      {"edge_splits", std::to_string(s.edge_splits)},
      {"time_read_s", num(t_read)},
      {"time_triangulate_s", num(s.time_triangulate_s)},
      {"time_insert_s", num(s.time_insert_s)},
      {"time_critical_s", num(s.time_critical_s)},
      {"time_wait_s", num(s.time_wait_s)},
      {"time_write_s", num(t_write)},
  };
  if (a.method == "optimistic" || a.method == "partition") f.push_back({"retries", std::to_string(s.retries)});
  if (a.method == "batch") {
    f.push_back({"time_idle_s", num(s.time_idle_s)});
    f.push_back({"time_stall_s", num(s.time_stall_s)});
    f.push_back({"queue_depth_mean", num(s.queue_depth_mean)});
    f.push_back({"stale_hints", std::to_string(s.stale_hints)});
  }
  if (a.profile) {
    f.push_back({"time_locate_s", num(s.time_locate_s)});
    f.push_back({"time_split_s", num(s.time_split_s)});
    f.push_back({"time_legalize_s", num(s.time_legalize_s)});
  }
  f.push_back({"peak_rss_bytes", std::to_string(peak_rss_bytes())});
  if (table) {
    for (const Field& x : f) std::printf("%-20s %s\n", x.key, x.value.c_str());
    std::printf("\n%6s %-9s %10s %14s %16s %12s %8s\n", "thread", "role", "points",
                "insertion [s]", "critical [s]", "waiting [s]", "retries");
    for (std::size_t i = 0; i < s.per_thread.size(); ++i) {
      const ridt::ThreadStats& p = s.per_thread[i];
      std::printf("%6zu %-9s %10llu %14.6f %16.6f %12.6f %8llu\n", i, p.role.c_str(),
                  static_cast<unsigned long long>(p.points), p.time_insert_s, p.time_critical_s,
                  p.time_wait_s, static_cast<unsigned long long>(p.retries));
    }
    std::printf("%6s %-9s %10llu %14.6f %16.6f %12.6f %8llu\n", "all", "",
                static_cast<unsigned long long>(s.points), s.time_insert_s, s.time_critical_s,
                s.time_wait_s, static_cast<unsigned long long>(s.retries));
    return;
  }
  std::string per_thread = "[";
  for (std::size_t i = 0; i < s.per_thread.size(); ++i) {
    const ridt::ThreadStats& p = s.per_thread[i];
    per_thread += (i ? ", " : "") + std::string("{\"thread\": ") + std::to_string(i) +
                  ", \"role\": \"" + p.role + "\"" +
                  ", \"points\": " + std::to_string(p.points) +
                  ", \"retries\": " + std::to_string(p.retries) +
                  ", \"time_insert_s\": " + num(p.time_insert_s) +
                  ", \"time_critical_s\": " + num(p.time_critical_s) +
                  ", \"time_wait_s\": " + num(p.time_wait_s) + "}";
  }
  f.push_back({"per_thread", per_thread + "]"});
  std::printf("{");
  for (std::size_t i = 0; i < f.size(); ++i)
    std::printf("%s\"%s\": %s", i ? ", " : "", f[i].key, f[i].value.c_str());
  std::printf("}\n");
}

// A seed as text: the whole of it a decimal integer that fits 64 bits. CLI11 2.1 converts
// with strtoull, which takes "-1" as 2^64 - 1 and any larger number as 2^64 - 1 too, so the
// text is checked before it is converted.
const CLI::Validator kSeed(
    [](std::string& text) -> std::string {
      std::uint64_t v = 0;
      const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (ec == std::errc() && end == text.data() + text.size()) return "";
      return "a seed is an integer from 0 to 18446744073709551615, got '" + text + "'";
    },
    "SEED");

// The value named `name` among `choices`, or an error that lists them.
template <typename T>
T pick(const char* what, const std::string& name,
       std::initializer_list<std::pair<const char*, T>> choices) {
  std::string list;
  std::size_t i = 0;
  for (const auto& [text, value] : choices) {
    if (name == text) return value;
    if (i > 0) list += i + 1 == choices.size() ? " or " : ", ";
    list += text;
    ++i;
  }
  throw ridt::InputError("unknown " + std::string(what) + " '" + name + "' (use " + list + ")");
}

int run_triangulate(const TriangulateArgs& a) {
  ridt::Options o;
  o.seed = a.seed;
  o.experiment.k = a.k;
  o.experiment.profile = a.profile;
  o.canonical_order = !a.output.empty();  // files are identical for every seed and method
  using ridt::Bounding, ridt::Locate, ridt::Method, ridt::Order;
  o.experiment.bounding = pick<Bounding>("bounding", a.bounding,
                              {{"symbolic", Bounding::Symbolic}, {"finite", Bounding::Finite}});
  o.method = pick<Method>("method", a.method,
                          {{"serial", Method::Serial}, {"pessimistic", Method::Pessimistic},
                           {"optimistic", Method::Optimistic}, {"batch", Method::Batch},
                           {"partition", Method::Partition}});
  o.order = pick<Order>("order", a.order, {{"brio", Order::Brio}, {"random", Order::Random}});
  o.locate = pick<Locate>("location", a.locate,
                          {{"auto", Locate::Auto}, {"dag", Locate::Dag}, {"walk", Locate::Walk}, {"root", Locate::Root}});
  o.threads = a.threads;
  o.experiment.paper_locking = a.paper_locking;
  o.experiment.time_threads = !a.no_thread_timing;
  if (a.stats != "" && a.stats != "json" && a.stats != "table")
    throw ridt::InputError("unknown stats format '" + a.stats + "' (use json or table)");
  if (!a.output.empty()) ridt::io::check_triangulation_extension(a.output);

  ProgressLine progress;
  if (progress.on())
    o.progress = [&](double done) { progress.show(done < 1 ? "inserting" : "finishing", done); };
  auto t0 = std::chrono::steady_clock::now();
  const ridt::io::PointFile in = ridt::io::read_points(a.input);
  const double t_read = seconds_since(t0);
  const ridt::Triangulation t = ridt::triangulate(in.points, o);
  progress.clear();
  if (!t.warning.empty()) std::fprintf(stderr, "ridt: warning: %s\n", t.warning.c_str());
  t0 = std::chrono::steady_clock::now();
  if (!a.output.empty()) {
    progress.show("writing");
    ridt::io::write_triangulation(a.output, in.points, t, in.first_index);
    progress.clear();
  }
  const double t_write = seconds_since(t0);
  if (!a.stats.empty() || a.profile) print_stats(a, t, t_read, t_write, a.stats == "table");
  return 0;
}

// Numbers apart by commas, e.g. "200,100" or "0,0,1,1"; `what` names them in a message.
std::vector<double> numbers(const std::string& text, const char* what) {
  std::vector<double> out;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    double v = 0;
    const char* first = text.data() + at;
    const char* last = text.data() + comma;
    const auto r = std::from_chars(first, last, v);
    if (r.ec != std::errc() || r.ptr != last || !std::isfinite(v))
      throw ridt::InputError(std::string(what) + ": '" + text + "' is not a list of finite numbers apart by commas");
    out.push_back(v);
    at = comma + 1;
  }
  return out;
}

ridt::io::Box box_option(const std::string& text, std::span<const ridt::Point> points) {
  if (text.empty()) return ridt::io::box_around(points, 0.1);
  const std::vector<double> b = numbers(text, "--box");
  if (b.size() != 4 || !(b[0] < b[2]) || !(b[1] < b[3]))
    throw ridt::InputError("--box: give x0,y0,x1,y1 with x0 < x1 and y0 < y1");
  return {b[0], b[1], b[2], b[3]};
}

int run_voronoi(const std::string& in, const std::string& out, const std::string& box, unsigned threads) {
  const ridt::io::PointFile p = ridt::io::read_points(in);
  ridt::Options o;
  o.method = threads == 1 ? ridt::Method::Serial : ridt::Method::Partition;
  o.threads = threads;
  const ridt::Triangulation t = ridt::triangulate(p.points, o);
  if (!t.warning.empty()) throw ridt::InputError("no Voronoi vertex: " + t.warning);
  const ridt::Voronoi vd = ridt::voronoi(p.points, t, threads);
  ridt::io::write_voronoi(out, p.points, t, vd, box_option(box, p.points));
  return 0;
}

struct InterpolateArgs {
  std::string points, values, queries, grid, method = "linear", output;
  double fill = std::numeric_limits<double>::quiet_NaN();
  unsigned threads = 1;
};

int run_interpolate(const InterpolateArgs& a) {
  if (a.queries.empty() == a.grid.empty()) throw ridt::InputError("give either a QUERIES file or --grid, not both");
  if (a.method != "linear" && a.method != "natural" && a.method != "nearest")
    throw ridt::InputError("unknown method '" + a.method + "' (use linear, natural or nearest)");
  const ridt::io::PointFile p = ridt::io::read_points(a.points);
  std::size_t components = 0;
  const std::vector<double> values = ridt::io::read_values(a.values, components);
  if (values.size() != p.points.size() * components)
    throw ridt::InputError(a.values + ": " + std::to_string(values.size() / components) + " rows of values for " +
                           std::to_string(p.points.size()) + " points");
  std::vector<ridt::Point> queries;
  std::vector<double> xs, ys;  // a grid's axes
  std::size_t nx = 0, ny = 0;
  if (!a.grid.empty()) {
    const std::vector<double> g = numbers(a.grid, "--grid");
    if ((g.size() != 2 && g.size() != 6) || g[0] < 2 || g[1] < 2 || g[0] != std::floor(g[0]) ||
        g[1] != std::floor(g[1]) || g[0] * g[1] > 1e9)
      throw ridt::InputError("--grid: give nx,ny (at least 2 each) or nx,ny,x0,y0,x1,y1");
    nx = static_cast<std::size_t>(g[0]), ny = static_cast<std::size_t>(g[1]);
    const ridt::io::Box b = g.size() == 6 ? ridt::io::Box{g[2], g[3], g[4], g[5]} : ridt::io::box_around(p.points, 0);
    for (std::size_t i = 0; i < nx; ++i)
      xs.push_back(b.x0 + (b.x1 - b.x0) * static_cast<double>(i) / static_cast<double>(nx - 1));
    for (std::size_t j = 0; j < ny; ++j)
      ys.push_back(b.y0 + (b.y1 - b.y0) * static_cast<double>(j) / static_cast<double>(ny - 1));
    queries.resize(nx * ny);
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) queries[j * nx + i] = {xs[i], ys[j]};
  } else {
    const ridt::io::PointFile q = ridt::io::read_points(a.queries);
    queries.assign(q.points.begin(), q.points.end());
  }
  ridt::Options o;
  o.method = a.threads == 1 ? ridt::Method::Serial : ridt::Method::Partition;
  o.threads = a.threads;
  const ridt::Triangulation t = ridt::triangulate(p.points, o);
  const ridt::Values v{values, components};
  std::vector<double> out;
  if (a.method == "nearest") {
    const std::vector<std::int32_t> near = ridt::nearest_vertex(p.points, t, queries, a.threads);
    out.assign(queries.size() * components, a.fill);
    for (std::size_t q = 0; q < queries.size(); ++q)
      if (near[q] >= 0)
        std::copy_n(&values[static_cast<std::size_t>(near[q]) * components], components, &out[q * components]);
  } else if (!xs.empty()) {  // a grid: each triangle takes the nodes it holds
    const ridt::Grid g{xs, ys};
    out.resize(g.size() * components);
    if (a.method == "natural")
      ridt::interpolate_natural_neighbor(p.points, t, v, g, out, a.fill, a.threads);
    else
      ridt::interpolate_linear(p.points, t, v, g, out, a.fill, a.threads);
  } else if (a.method == "natural") {
    out = ridt::interpolate_natural_neighbor(p.points, t, v, queries, a.fill, a.threads);
  } else {
    out = ridt::interpolate_linear(p.points, t, v, queries, a.fill, a.threads);
  }
  ridt::io::write_values(a.output, queries, out, components, nx, ny);
  return 0;
}

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

}  // namespace

int main(int argc, char** argv) {
  // One triangulation a process: blocks kept for a next call would only raise the peak.
  ridt::set_memory_cache_limit(0);
  CLI::App app{"ridt: exact 2D Delaunay triangulation by randomized incremental insertion"};
  app.require_subcommand(1);
  app.set_version_flag("--version", version());

  TriangulateArgs ta;
  CLI::App* tri = app.add_subcommand("triangulate", "triangulate a point file");
  tri->add_option("input", ta.input, "points: .node, .bin (float64 pairs) or text")->required();
  tri->add_option("-o,--output", ta.output, "triangles: .ele, .neigh, .off, .obj, .svg or .bin");
  tri->add_option("--seed", ta.seed, "seed of the random insertion order")->check(kSeed);
  tri->add_option("--order", ta.order,
                  "insertion order: brio (default; random rounds, each along a Hilbert curve) or "
                  "random (the paper's)");
  tri->add_option("--locate", ta.locate,
                  "point location: auto (default: walk where the method and order allow, else "
                  "dag), dag (the history DAG, in rounds along a curve), walk (from the last "
                  "insertion, no DAG; serial and partition methods, brio order) or root (the "
                  "paper's: every point descends the DAG from its root, no rounds or look-ahead)");
  tri->add_option("--method", ta.method,
                  "serial (default), pessimistic, optimistic, batch (the paper's, on the DAG) or "
                  "partition (threads own regions; no lock, no DAG)");
  tri->add_option("--threads", ta.threads,
                  "threads of a threaded method (0: all hardware threads; batch: threads - 1 "
                  "locators and one modifier)");
  CLI::Option* stats = tri->add_option("--stats", ta.stats, "print counters and times: json (default) or table")
                           ->expected(0, 1);
  // The paper's experiment switches (Options::experiment), apart in the help.
  const std::string x = "Experiment (the paper's section 4)";
  tri->add_flag("--paper-locking", ta.paper_locking, "pessimistic: lock from the leaves' parents, as the paper does")
      ->group(x);
  tri->add_flag("--no-thread-timing", ta.no_thread_timing,
                "threaded methods: do not time critical sections and waiting")
      ->group(x);
  tri->add_flag("--profile", ta.profile, "serial: time location, split and legalization (Fig. 8)")->group(x);
  tri->add_option("--bounding", ta.bounding,
                  "symbolic (default) or finite (the paper's; can lose hull edges, with a warning)")
      ->group(x);
  tri->add_option("--k", ta.k, "finite bounding triangle: K = k * box size (default 10)")->group(x);

  std::string dist, gen_out;
  std::uint32_t gen_n = 0;
  std::uint64_t gen_seed = 1;
  CLI::App* gen = app.add_subcommand("generate", "write points of one of the paper's distributions");
  gen->add_option("--dist", dist, "uniform, normal, grid or clusters")->required();
  gen->add_option("-n", gen_n, "number of points")->required();
  gen->add_option("--seed", gen_seed, "seed")->check(kSeed);
  gen->add_option("-o,--output", gen_out, "output: .node, .bin or text")->required();

  std::string check_points, check_tris;
  CLI::App* chk = app.add_subcommand("check", "validate a triangulation exactly");
  chk->add_option("points", check_points, "the points")->required();
  chk->add_option("triangles", check_tris, "the triangles: .ele, .bin, text, or the .parts index of ridt-mpi's parts")->required();

  std::string vor_in, vor_out, vor_box;
  unsigned vor_threads = 1;
  CLI::App* vor = app.add_subcommand("voronoi", "the Voronoi diagram of points");
  vor->add_option("points", vor_in, "the points: .node, .bin or text")->required();
  vor->add_option("-o,--output", vor_out, "output: .svg (the cells clipped to the box, and the sites), .off (each "
                                          "clipped cell a face) or .json (vertices, cells, ridges)")
      ->required();
  vor->add_option("--box", vor_box, "x0,y0,x1,y1: the box .svg and .off clip to (default: the points' box and "
                                    "10 % around)");
  vor->add_option("--threads", vor_threads, "threads (0: all hardware threads; default 1)");

  InterpolateArgs ia;
  CLI::App* ip = app.add_subcommand("interpolate", "interpolate values given at points, at queries or on a grid");
  ip->add_option("points", ia.points, "the points: .node, .bin or text")->required();
  ip->add_option("values", ia.values, "their values, a row a point: text/.csv (one or more a line) or .bin "
                                      "(float64)")
      ->required();
  ip->add_option("queries", ia.queries, "the query points (or --grid)");
  ip->add_option("--grid", ia.grid, "nx,ny[,x0,y0,x1,y1]: the nodes of a grid, row by row from (x0, y0) "
                                    "(default box: the points')");
  ip->add_option("--method", ia.method, "linear (default), natural (Sibson's natural neighbours) or nearest");
  ip->add_option("--fill", ia.fill, "the value outside the convex hull (default nan)");
  ip->add_option("-o,--output", ia.output, "output: .csv (x,y,values), .bin (float64 values) or, for a grid, "
                                           ".png (a colour map)")
      ->required();
  ip->add_option("--threads", ia.threads, "threads (0: all hardware threads; default 1)");

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

  try {
    if (*tri) {
      if (*stats && ta.stats.empty()) ta.stats = "json";
      return run_triangulate(ta);
    }
    if (*gen) {
      const auto d = ridt::parse_distribution(dist);
      if (!d)
        throw ridt::InputError("unknown distribution '" + dist +
                               "' (use uniform, normal, grid or clusters)");
      ridt::io::write_points(gen_out, ridt::generate(*d, gen_n, gen_seed));
      return 0;
    }
    if (*vor) return run_voronoi(vor_in, vor_out, vor_box, vor_threads);
    if (*ip) return run_interpolate(ia);
    if (*chk) {
      const ridt::io::PointFile p = ridt::io::read_points(check_points);
      const auto t = ridt::io::read_triangles(check_tris, p.first_index);
      const ridt::CheckResult r = ridt::check(p.points, t);
      std::printf("%s\n", r.message.c_str());
      return r.valid ? 0 : kExitInvalid;
    }
  } catch (const ridt::io::IoError& e) {
    std::fprintf(stderr, "ridt: error: %s\n", e.what());
    return kExitUsage;
  } catch (const ridt::InputError& e) {
    std::fprintf(stderr, "ridt: error: %s\n", e.what());
    return kExitUsage;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ridt: internal error: %s\n", e.what());
    return 3;
  }
  return kExitUsage;
}
