// ridt triangulate INPUT [-o OUTPUT] [--method M] [--threads N] [--order O] [--locate L]
//                        [--seed S] [--stats[=json|table]] and the paper's experiment switches;
// ridt triangulate INPUT.bin -o OUT.parts --out-of-core [--memory-limit SIZE] [--threads N].
#include <optional>
#include <sstream>

#include "command.hpp"
#include "ridt/out_of_core.hpp"
#include "temporaries.hpp"

namespace ridt::tool {
namespace {

struct Args {
  std::string input, output, stats;
  std::string method = "auto", order = "brio", locate = "auto", bounding = "symbolic";
  std::uint64_t seed = 1;
  double k = 10;
  unsigned threads = 0;
  bool profile = false, paper_locking = false, no_thread_timing = false, out_of_core = false;
  bool seed_given = false, k_given = false;  // options whose defaults are values too
  std::string memory_limit;
  std::uint64_t column_points = 0;
};

std::string number(double v) {
  std::ostringstream o;
  o.precision(6);
  o << v;
  return o.str();
}

// A value of Stats as JSON: an option's name quoted, a count, a time.
template <class T>
std::string json(const T& v) {
  if constexpr (std::is_enum_v<T>)
    return "\"" + std::string(to_string(v)) + "\"";
  else if constexpr (std::is_same_v<T, std::string>)
    return "\"" + v + "\"";
  else if constexpr (std::is_floating_point_v<T>)
    return number(v);
  else
    return std::to_string(v);
}

using Fields = std::vector<std::pair<std::string, std::string>>;

// The run's options and sizes, the library's stats (ridt::for_each_stat), the tool's times.
Fields stats_fields(const Args& a, const Triangulation& t, double t_read, double t_write) {
  Fields f = {{"seed", json(a.seed)},
              {"order", json(a.order)},
              {"bounding", json(a.bounding)},
              {"triangles", json(t.size())},
              {"hull", json(t.hull.size())}};
  for_each_stat([&](const char* name, auto member) { f.emplace_back(name, json(t.stats.*member)); });
  f.emplace_back("time_read_s", json(t_read));
  f.emplace_back("time_write_s", json(t_write));
  f.emplace_back("peak_rss_bytes", json(peak_rss_bytes()));
  return f;
}

void print_table(const Fields& f, const Stats& s) {
  for (const auto& [key, value] : f) std::printf("%-20s %s\n", key.c_str(), value.c_str());
  std::printf("\n%6s %-9s %10s %14s %16s %12s %8s\n", "thread", "role", "points", "insertion [s]", "critical [s]",
              "waiting [s]", "retries");
  const auto row = [](const char* thread, const char* role, const ThreadStats& p) {
    std::printf("%6s %-9s %10llu %14.6f %16.6f %12.6f %8llu\n", thread, role, static_cast<unsigned long long>(p.points),
                p.time_insert_s, p.time_critical_s, p.time_wait_s, static_cast<unsigned long long>(p.retries));
  };
  for (std::size_t i = 0; i < s.per_thread.size(); ++i)
    row(std::to_string(i).c_str(), s.per_thread[i].role.c_str(), s.per_thread[i]);
  row("all", "", {"", s.points, s.time_insert_s, s.time_critical_s, s.time_wait_s, s.retries});
}

void print_json(Fields f, const Stats& s) {
  std::string per_thread = "[";
  for (std::size_t i = 0; i < s.per_thread.size(); ++i) {
    per_thread += (i ? ", " : "") + std::string("{\"thread\": ") + std::to_string(i);
    for_each_thread_stat([&](const char* name, auto member) {
      per_thread += ", \"" + std::string(name) + "\": " + json(s.per_thread[i].*member);
    });
    per_thread += "}";
  }
  f.emplace_back("per_thread", per_thread + "]");
  std::printf("{");
  for (std::size_t i = 0; i < f.size(); ++i)
    std::printf("%s\"%s\": %s", i ? ", " : "", f[i].first.c_str(), f[i].second.c_str());
  std::printf("}\n");
}

Options options(const Args& a) {
  Options o;
  o.method = parse<Method>(a.method);
  o.order = parse<Order>(a.order);
  o.locate = parse<Locate>(a.locate);
  o.threads = a.threads;
  o.seed = a.seed;
  o.canonical_order = !a.output.empty();  // files are identical for every seed and method
  if (!a.memory_limit.empty()) o.memory_limit = byte_size(a.memory_limit, "--memory-limit");
  o.experiment.bounding = parse<Bounding>(a.bounding);
  o.experiment.k = a.k;
  o.experiment.profile = a.profile;
  o.experiment.paper_locking = a.paper_locking;
  o.experiment.time_threads = !a.no_thread_timing;
  if (a.stats != "" && a.stats != "json" && a.stats != "table")
    throw InputError("unknown stats format '" + a.stats + "' (use json or table)");
  if (!a.output.empty()) o.neighbors = io::triangulation_needs_neighbors(a.output);  // an unknown one throws
  return o;
}

// --out-of-core: strip by strip within the memory limit (the library's, ridt/out_of_core.hpp);
// the parts it writes are removed where a signal stops the tool, as its temporary files are.
int run_out_of_core(const Args& a) {
  if (a.method != "auto" || a.order != "brio" || a.locate != "auto" || a.bounding != "symbolic" || a.profile ||
      a.seed_given || a.k_given || a.paper_locking || a.no_thread_timing)
    throw InputError(
        "--out-of-core takes no --method, --order, --locate, --seed, --bounding, --k, --paper-locking, "
        "--no-thread-timing or --profile: each strip is triangulated by the walking kernel in an order of its own");
  if (a.output.empty()) throw InputError("--out-of-core needs an output, -o OUT.parts");
  if (a.stats != "" && a.stats != "json") throw InputError("--out-of-core prints its stats as json only");
  OutOfCoreOptions o;
  o.input = a.input;
  o.output = a.output;
  if (!a.memory_limit.empty()) o.memory_limit = byte_size(a.memory_limit, "--memory-limit");
  o.threads = thread_count(a.threads);
  o.column_points = a.column_points;
  ProgressLine progress;
  if (progress.on()) o.progress = [&](const char* phase, double done) { progress.show(phase, done); };
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<io::TemporaryName> parts;
  o.wrote = [&parts](const std::string& part) { parts.emplace_back(part); };
  const OutOfCoreStats st = triangulate_out_of_core(o);
  progress.clear();
  if (a.stats.empty()) return 0;
  std::printf(
      "{\"points\": %llu, \"triangles\": %llu, \"columns\": %llu, \"rows\": %llu, \"strips\": %llu, "
      "\"loaded\": %llu, \"retries\": %llu, \"time_bucket_s\": %s, \"time_triangulate_s\": %s, "
      "\"time_check_s\": %s, \"time_write_s\": %s, \"time_total_s\": %s, \"peak_rss_bytes\": %lld}\n",
      static_cast<unsigned long long>(st.points), static_cast<unsigned long long>(st.triangles),
      static_cast<unsigned long long>(st.columns), static_cast<unsigned long long>(st.rows),
      static_cast<unsigned long long>(st.strips), static_cast<unsigned long long>(st.loaded),
      static_cast<unsigned long long>(st.retries), number(st.time_bucket_s).c_str(),
      number(st.time_triangulate_s).c_str(), number(st.time_check_s).c_str(), number(st.time_write_s).c_str(),
      number(seconds_since(t0)).c_str(), peak_rss_bytes());
  return 0;
}

int run(const Args& a) {
  refuse_overwriting({a.input}, {a.output});
  if (a.out_of_core) return run_out_of_core(a);
  refuse_ignored(a.column_points != 0, "--column-points", "is for --out-of-core only");
  Options o = options(a);
  ProgressLine progress;
  if (progress.on()) o.progress = [&](double done) { progress.show(done < 1 ? "inserting" : "finishing", done); };
  auto t0 = std::chrono::steady_clock::now();
  const io::PointFile in = io::read_points(a.input, thread_count(a.threads));
  const double t_read = seconds_since(t0);
  // A .bin file is written as the canonical sort puts the triangles in place.
  std::optional<io::SortedOutput> sorted;
  if (!a.output.empty() && sorted.emplace(a.output).active())
    o.on_sorted = [&](std::size_t first, std::span<const VertexId> tri) { sorted->put(first, tri); };
  const Triangulation t = triangulate(in.points, o);
  progress.clear();
  if (!t.warning.empty()) std::fprintf(stderr, "ridt: warning: %s\n", t.warning.c_str());
  t0 = std::chrono::steady_clock::now();
  if (o.on_sorted) {
    sorted->commit(t);
  } else if (!a.output.empty()) {
    progress.show("writing");
    io::write_triangulation(a.output, in.points, t, in.first_index, thread_count(a.threads));
    progress.clear();
  }
  const double t_write = seconds_since(t0);
  if (a.stats.empty() && !a.profile) return 0;
  const Fields f = stats_fields(a, t, t_read, t_write);
  a.stats == "table" ? print_table(f, t.stats) : print_json(f, t.stats);
  return 0;
}

// The paper's experiment switches (Options::experiment), apart in the help; returns --k.
CLI::Option* add_experiment(CLI::App* tri, Args& a) {
  const std::string x = "Experiment (the paper's section 4)";
  tri->add_flag("--paper-locking", a.paper_locking, "pessimistic: lock from the leaves' parents, as the paper does")
      ->group(x);
  tri->add_flag("--no-thread-timing", a.no_thread_timing, "threaded methods: do not time critical sections and waiting")
      ->group(x);
  tri->add_flag("--profile", a.profile, "serial: time location, split and legalization (Fig. 8)")->group(x);
  tri->add_option("--bounding", a.bounding, choices_help("the starting triangle", Bounding::Symbolic))->group(x);
  return tri->add_option("--k", a.k, "finite bounding triangle: K = k * box size (default 10)")->group(x);
}

}  // namespace

Command add_triangulate(CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* tri = app.add_subcommand("triangulate", "triangulate a point file");
  tri->add_option("input", a->input, "points: " + io::point_formats())->required();
  tri->add_option("-o,--output", a->output, "triangles: " + io::triangulation_formats());
  CLI::Option* seed = tri->add_option("--seed", a->seed, "seed of the random insertion order")->check(kSeed);
  tri->add_option("--method", a->method, choices_help("", Method::Auto));
  tri->add_option("--threads", a->threads,
                  "threads of a threaded method (0, the default: all hardware threads; batch: threads - 1 locators "
                  "and one modifier)");
  tri->add_option("--order", a->order, choices_help("insertion order", Order::Brio));
  tri->add_option("--locate", a->locate, choices_help("point location", Locate::Auto));
  tri->add_option("--memory-limit", a->memory_limit,
                  "the most memory the triangulation may take, e.g. 800M or 12G (default: what the system can give); "
                  "a run that needs more is refused before it starts");
  tri->add_flag("--out-of-core", a->out_of_core,
                "for point sets larger than memory: a .bin input bucketed on disk, triangulated strip by strip "
                "within --memory-limit (default: a quarter of what is available), written as parts: -o OUT.parts");
  tri->add_option("--column-points", a->column_points,
                  "--out-of-core: points a column of cells holds (default: what --memory-limit allows; a strip owns "
                  "8 columns and loads one more on either side)");
  CLI::Option* stats =
      tri->add_option("--stats", a->stats, "print counters and times: json (default) or table")->expected(0, 1);
  CLI::Option* k = add_experiment(tri, *a);
  return {tri, [a, stats, seed, k] {
            if (*stats && a->stats.empty()) a->stats = "json";
            a->seed_given = seed->count() > 0, a->k_given = k->count() > 0;
            return run(*a);
          }};
}

}  // namespace ridt::tool
