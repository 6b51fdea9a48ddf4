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
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "common.hpp"
#include "generate.hpp"
#include "ridt/ridt.hpp"

namespace {

using ridt::bench::median;
using ridt::bench::split;

struct Config {
  std::string method;  // serial, pessimistic, paper, optimistic, batch
  unsigned threads;
};

ridt::Options options_for(const Config& c) {
  ridt::Options o;
  o.threads = c.threads;
  if (c.method == "serial") o.method = ridt::Method::Serial;
  if (c.method == "pessimistic" || c.method == "paper") o.method = ridt::Method::Pessimistic;
  if (c.method == "paper") o.experiment.paper_locking = true;
  if (c.method == "optimistic") o.method = ridt::Method::Optimistic;
  if (c.method == "batch") o.method = ridt::Method::Batch;
  return o;
}

struct Samples {
  std::vector<double> total, insert, critical, wait, speedup, retries, idle, stall, depth, stale;
};

}  // namespace

int main(int argc, char** argv) {
  std::string n_list = "1000,10000,100000,1000000", dist_list = "uniform,grid";
  std::string thread_list = "1,2,3,4,8", method_list = "pessimistic,paper,optimistic,batch", csv;
  int reps = 5;
  ridt::Order order_kind = ridt::Order::Random;
  ridt::Locate locate_kind = ridt::Locate::Dag;
  for (int i = 1; i < argc; ++i) {
    auto arg = [&](const char* name) { return !std::strcmp(argv[i], name) && i + 1 < argc; };
    if (arg("--n")) n_list = argv[++i];
    else if (arg("--dist")) dist_list = argv[++i];
    else if (arg("--reps")) reps = std::atoi(argv[++i]);
    else if (arg("--threads")) thread_list = argv[++i];
    else if (arg("--methods")) method_list = argv[++i];
    else if (arg("--csv")) csv = argv[++i];
    else if (arg("--order") && !std::strcmp(argv[i + 1], "random")) order_kind = ridt::Order::Random, ++i;
    else if (arg("--order") && !std::strcmp(argv[i + 1], "brio")) order_kind = ridt::Order::Brio, ++i;
    else if (arg("--locate") && !std::strcmp(argv[i + 1], "dag")) locate_kind = ridt::Locate::Dag, ++i;
    else if (arg("--locate") && !std::strcmp(argv[i + 1], "root")) locate_kind = ridt::Locate::Root, ++i;
    else {
      std::fprintf(stderr,
                   "usage: %s [--n N,N,...] [--dist uniform,grid] [--reps R] [--threads 1,2,...]\n"
                   "          [--methods pessimistic,paper,optimistic,batch] [--order random|brio]\n"
                   "          [--locate dag|root] [--csv FILE]\n",
                   argv[0]);
      return 2;
    }
  }
  std::vector<Config> configs;
  for (const std::string& m : split(method_list))
    for (const std::string& t : split(thread_list)) {
      if (m == "paper" && std::stoul(t) > 2) continue;  // the locking variants: 1 and 2 threads
      configs.push_back({m, static_cast<unsigned>(std::stoul(t))});
    }
  const unsigned cores = std::thread::hardware_concurrency();

  FILE* out = csv.empty() ? nullptr : std::fopen(csv.c_str(), "w");
  if (out)
    std::fprintf(out, "distribution,n,method,threads,total_s,insert_s,critical_s,wait_s,speedup,"
                      "retries,idle_s,stall_s,queue_depth,stale_hints\n");
  std::printf("Seconds, medians of %d repetitions; speedup = serial / method, the median of the\n"
              "per-repetition ratios. %u hardware threads: runs with more threads are "
              "oversubscribed.\n", reps, cores);
  for (const std::string& dist_name : split(dist_list)) {
    const std::optional<ridt::Distribution> parsed = ridt::parse_distribution(dist_name);
    if (!parsed) {
      std::fprintf(stderr, "unknown distribution '%s'\n", dist_name.c_str());
      return 2;
    }
    const ridt::Distribution d = *parsed;
    std::printf("\n%s\n%10s %-11s %7s %9s %9s %9s %9s %8s %8s %9s %9s %8s %8s\n", dist_name.c_str(),
                "n", "method", "threads", "total", "insert", "critical", "waiting", "speedup",
                "retries", "idle", "stall", "depth", "stale");
    for (const std::string& n_text : split(n_list)) {
      const auto n = static_cast<std::uint32_t>(std::stoul(n_text));
      const std::vector<ridt::Point> pts = ridt::generate(d, n, 1);
      Samples serial;
      std::map<std::size_t, Samples> by_config;
      std::mt19937 shuffle(7);  // seeded: the same orders in every run of this build
      for (int r = 0; r < reps; ++r) {
        // Serial and each configuration once, in an order shuffled anew for each repetition:
        // a run's speed depends on what the run before it left in memory and in the caches.
        std::vector<std::size_t> order(configs.size() + 1);  // configs.size() stands for serial
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::shuffle(order.begin(), order.end(), shuffle);
        std::vector<ridt::Stats> stats(configs.size() + 1);
        for (const std::size_t c : order) {
          ridt::Options o = c == configs.size() ? ridt::Options{} : options_for(configs[c]);
          o.seed = 1 + r;
          o.order = order_kind;
          o.locate = locate_kind;
          stats[c] = ridt::triangulate(pts, o).stats;
        }
        const ridt::Stats& s0 = stats[configs.size()];
        serial.total.push_back(s0.time_triangulate_s);
        serial.insert.push_back(s0.time_insert_s);
        for (std::size_t c = 0; c < configs.size(); ++c) {
          const ridt::Stats& s = stats[c];
          Samples& m = by_config[c];
          m.total.push_back(s.time_triangulate_s);
          m.insert.push_back(s.time_insert_s);
          m.critical.push_back(s.time_critical_s);
          m.wait.push_back(s.time_wait_s);
          m.speedup.push_back(s0.time_triangulate_s / s.time_triangulate_s);
          m.retries.push_back(static_cast<double>(s.retries));
          m.idle.push_back(s.time_idle_s);
          m.stall.push_back(s.time_stall_s);
          m.depth.push_back(s.queue_depth_mean);
          m.stale.push_back(static_cast<double>(s.stale_hints));
        }
      }
      std::printf("%10u %-11s %7s %9.4f %9.4f\n", n, "serial", "1", median(serial.total),
                  median(serial.insert));
      if (out)
        std::fprintf(out, "%s,%u,serial,1,%.6f,%.6f,0,0,1,0,0,0,0,0\n", dist_name.c_str(), n,
                     median(serial.total), median(serial.insert));
      for (std::size_t c = 0; c < configs.size(); ++c) {
        const Samples& m = by_config[c];
        std::printf("%10u %-11s %7u %9.4f %9.4f %9.4f %9.4f %8.2f %8.0f %9.4f %9.4f %8.0f %8.0f\n",
                    n, configs[c].method.c_str(), configs[c].threads, median(m.total),
                    median(m.insert), median(m.critical), median(m.wait), median(m.speedup),
                    median(m.retries), median(m.idle), median(m.stall), median(m.depth),
                    median(m.stale));
        if (out)
          std::fprintf(out, "%s,%u,%s,%u,%.6f,%.6f,%.6f,%.6f,%.4f,%.0f,%.6f,%.6f,%.1f,%.0f\n",
                       dist_name.c_str(), n, configs[c].method.c_str(), configs[c].threads,
                       median(m.total), median(m.insert), median(m.critical), median(m.wait),
                       median(m.speedup), median(m.retries), median(m.idle), median(m.stall),
                       median(m.depth), median(m.stale));
      }
      std::fflush(stdout);
      if (out) std::fflush(out);
    }
  }
  if (out) std::fclose(out);
  return 0;
}
