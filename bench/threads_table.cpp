// The paper's Tables 2 and 3 for every threaded method: per method and thread count, the total
// time, the time for insertion, the time in critical sections (pessimistic: the lock;
// optimistic: holding triangles) and the waiting time, summed over threads; retries
// (optimistic); idle, stall, queue depth and stale hints (batch). Serial ridt runs in the same
// repetition as every configuration: each repetition runs serial and each configuration once,
// in a shuffled order, so a drift of the machine's speed and the state one run leaves for the
// next hit all alike; each speedup is the median of the per-repetition ratios serial / method. Writes a CSV for bench/plot_threads.py.
//
//   ridt_bench_threads [--n 1000,10000,100000,1000000] [--dist uniform,grid] [--reps R]
//                      [--threads 1,2,3,4,8] [--methods pessimistic,paper,optimistic,batch]
//                      [--order random|brio] [--locate dag|root] [--csv FILE]
// --order: the insertion order of every run, serial included (random, the paper's, by default).
// --locate: the location of every run (dag, ridt's rounds, by default; root, the paper's:
// every descent from the DAG's root, no rounds or look-ahead).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include "common.hpp"
#include "ridt/generate.hpp"
#include "ridt/ridt.hpp"

namespace {

using ridt::bench::median;
using ridt::bench::split;

struct Config {
  std::string method;  // a method's name, or paper: pessimistic with the paper's locking
  unsigned threads;
};

ridt::Options options_for(const Config& c) {
  ridt::Options o;
  o.threads = c.threads;
  o.method = ridt::parse<ridt::Method>(c.method == "paper" ? "pessimistic" : c.method);
  o.experiment.paper_locking = c.method == "paper";
  return o;
}

// The stats each row shows, by their names in ridt::for_each_stat, with the CSV's column and
// the table's.
struct Column {
  const char* stat;
  const char* csv;
  const char* table;
  const char* format;  // printf, for the table and the CSV
};
constexpr Column kColumns[] = {
    {"time_triangulate_s", "total_s", "total", "%.6f"},
    {"time_insert_s", "insert_s", "insert", "%.6f"},
    {"time_critical_s", "critical_s", "critical", "%.6f"},
    {"time_wait_s", "wait_s", "waiting", "%.6f"},
    {"speedup", "speedup", "speedup", "%.4f"},
    {"retries", "retries", "retries", "%.0f"},
    {"time_idle_s", "idle_s", "idle", "%.6f"},
    {"time_stall_s", "stall_s", "stall", "%.6f"},
    {"queue_depth_mean", "queue_depth", "depth", "%.1f"},
    {"stale_hints", "stale_hints", "stale", "%.0f"},
};

// Every numeric stat of a run, by name.
std::map<std::string, double> numbers(const ridt::Stats& s) {
  std::map<std::string, double> out;
  ridt::for_each_stat([&](const char* name, auto member) {
    if constexpr (std::is_arithmetic_v<std::remove_cvref_t<decltype(s.*member)>>)
      out[name] = static_cast<double>(s.*member);
  });
  return out;
}

struct Args {
  std::string n_list = "1000,10000,100000,1000000", dist_list = "uniform,grid";
  std::string thread_list = "1,2,3,4,8", method_list = "pessimistic,paper,optimistic,batch", csv;
  int reps = 5;
  ridt::Order order = ridt::Order::Random;
  ridt::Locate locate = ridt::Locate::Dag;
};

bool parse_args(int argc, char** argv, Args& a) {
  for (int i = 1; i < argc; ++i) {
    auto arg = [&](const char* name) { return !std::strcmp(argv[i], name) && i + 1 < argc; };
    if (arg("--n"))
      a.n_list = argv[++i];
    else if (arg("--dist"))
      a.dist_list = argv[++i];
    else if (arg("--reps"))
      a.reps = std::atoi(argv[++i]);
    else if (arg("--threads"))
      a.thread_list = argv[++i];
    else if (arg("--methods"))
      a.method_list = argv[++i];
    else if (arg("--csv"))
      a.csv = argv[++i];
    else if (arg("--order"))
      a.order = ridt::parse<ridt::Order>(argv[++i]);
    else if (arg("--locate"))
      a.locate = ridt::parse<ridt::Locate>(argv[++i]);
    else
      return false;
  }
  return true;
}

// Serial and each configuration once a repetition, in an order shuffled anew each time: a
// run's speed depends on what the run before it left in memory and in the caches. Samples
// by configuration (configs.size() stands for serial) and stat.
using Samples = std::vector<std::map<std::string, std::vector<double>>>;
Samples measure(const std::vector<ridt::Point>& pts, const std::vector<Config>& configs, const Args& a) {
  Samples samples(configs.size() + 1);
  std::mt19937 shuffle(7);  // seeded: the same orders in every run of this build
  for (int r = 0; r < a.reps; ++r) {
    std::vector<std::size_t> order(configs.size() + 1);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::shuffle(order.begin(), order.end(), shuffle);
    std::vector<std::map<std::string, double>> stats(configs.size() + 1);
    for (const std::size_t c : order) {
      ridt::Options o = c == configs.size() ? ridt::Options{} : options_for(configs[c]);
      o.seed = 1 + r, o.order = a.order, o.locate = a.locate;
      stats[c] = numbers(ridt::triangulate(pts, o).stats);
    }
    for (std::size_t c = 0; c <= configs.size(); ++c) {
      stats[c]["speedup"] = stats[configs.size()]["time_triangulate_s"] / stats[c]["time_triangulate_s"];
      for (const auto& [name, value] : stats[c]) samples[c][name].push_back(value);
    }
  }
  return samples;
}

void print_row(FILE* out, const std::string& dist, std::uint32_t n, const Config& c,
               std::map<std::string, std::vector<double>>& m) {
  std::printf("%10u %-11s %7u", n, c.method.c_str(), c.threads);
  if (out) std::fprintf(out, "%s,%u,%s,%u", dist.c_str(), n, c.method.c_str(), c.threads);
  for (const Column& col : kColumns) {
    const double v = median(m[col.stat]);
    std::printf(" %9s", ridt::bench::format(col.format, v).c_str());
    if (out) std::fprintf(out, ",%s", ridt::bench::format(col.format, v).c_str());
  }
  std::printf("\n");
  if (out) std::fprintf(out, "\n");
}

std::vector<Config> configurations(const Args& a) {
  std::vector<Config> configs;
  for (const std::string& m : split(a.method_list))
    for (const std::string& t : split(a.thread_list)) {
      if (m == "paper" && std::stoul(t) > 2) continue;  // the locking variants: 1 and 2 threads
      configs.push_back({m, static_cast<unsigned>(std::stoul(t))});
    }
  return configs;
}

void table(const Args& a, FILE* out) {
  const std::vector<Config> configs = configurations(a);
  for (const std::string& dist_name : split(a.dist_list)) {
    const auto d = ridt::parse<ridt::Distribution>(dist_name);
    std::printf("\n%s\n%10s %-11s %7s", dist_name.c_str(), "n", "method", "threads");
    for (const Column& col : kColumns) std::printf(" %9s", col.table);
    std::printf("\n");
    for (const std::string& n_text : split(a.n_list)) {
      const auto n = static_cast<std::uint32_t>(std::stoul(n_text));
      Samples samples = measure(ridt::generate(d, n, 1), configs, a);
      print_row(out, dist_name, n, {"serial", 1}, samples[configs.size()]);
      for (std::size_t c = 0; c < configs.size(); ++c) print_row(out, dist_name, n, configs[c], samples[c]);
      std::fflush(stdout);
      if (out) std::fflush(out);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  Args a;
  try {
    if (!parse_args(argc, argv, a)) {
      std::fprintf(stderr,
                   "usage: %s [--n N,N,...] [--dist uniform,grid] [--reps R] [--threads 1,2,...]\n"
                   "          [--methods pessimistic,paper,optimistic,batch] [--order random|brio]\n"
                   "          [--locate dag|root] [--csv FILE]\n",
                   argv[0]);
      return 2;
    }
    FILE* out = a.csv.empty() ? nullptr : std::fopen(a.csv.c_str(), "w");
    if (out) {
      std::fprintf(out, "distribution,n,method,threads");
      for (const Column& col : kColumns) std::fprintf(out, ",%s", col.csv);
      std::fprintf(out, "\n");
    }
    std::printf(
        "Seconds, medians of %d repetitions; speedup = serial / method, the median of the\n"
        "per-repetition ratios. %u hardware threads: runs with more threads are "
        "oversubscribed.\n",
        a.reps, std::thread::hardware_concurrency());
    table(a, out);
    if (out) std::fclose(out);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
