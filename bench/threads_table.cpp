// The paper's Tables 2 and 3 for the pessimistic method: per thread count, the total time,
// the time for insertion, the time in the critical section and the waiting time (summed over
// threads), medians of --reps runs; plus serial ridt in the same run, and the paper's locking
// variant beside ridt's. Writes a CSV for bench/plot_threads.py (Figs. 11 and 14).
//
//   ridt_bench_threads [--max-n N] [--reps R] [--threads 1,2,4,6,8] [--csv FILE]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "generate.hpp"
#include "ridt/ridt.hpp"

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

struct Row {
  double total, insert, critical, wait;
};

Row measure(const std::vector<ridt::Point>& pts, ridt::Options o, int reps) {
  std::vector<double> total, insert, critical, wait;
  for (int r = 0; r < reps; ++r) {
    o.seed = 1 + r;
    const ridt::Stats s = ridt::triangulate(pts, o).stats;
    total.push_back(s.time_triangulate_s);
    insert.push_back(s.time_insert_s);
    critical.push_back(s.time_critical_s);
    wait.push_back(s.time_wait_s);
  }
  return {median(total), median(insert), median(critical), median(wait)};
}

}  // namespace

int main(int argc, char** argv) {
  std::uint32_t max_n = 1000000;
  int reps = 5;
  std::string csv, thread_list = "1,2,4,6,8";
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--max-n") && i + 1 < argc) max_n = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--reps") && i + 1 < argc) reps = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) thread_list = argv[++i];
    else if (!std::strcmp(argv[i], "--csv") && i + 1 < argc) csv = argv[++i];
    else {
      std::fprintf(stderr, "usage: %s [--max-n N] [--reps R] [--threads 1,2,4] [--csv FILE]\n", argv[0]);
      return 2;
    }
  }
  std::vector<unsigned> thread_counts;
  std::stringstream ss(thread_list);
  for (std::string t; std::getline(ss, t, ',');) thread_counts.push_back(std::stoul(t));
  const unsigned cores = std::thread::hardware_concurrency();

  FILE* out = csv.empty() ? nullptr : std::fopen(csv.c_str(), "w");
  if (out) std::fprintf(out, "distribution,n,variant,threads,total_s,insert_s,critical_s,wait_s\n");
  std::printf("Pessimistic method, seconds, medians of %d runs; %u hardware threads%s\n", reps,
              cores, " (runs with more threads are oversubscribed)");
  for (ridt::Distribution d : {ridt::Distribution::Uniform, ridt::Distribution::Grid}) {
    std::printf("\n%s\n%9s %-8s %7s %9s %9s %9s %9s %8s\n", ridt::to_string(d), "n", "variant",
                "threads", "total", "insert", "critical", "waiting", "speedup");
    for (std::uint32_t n : {100u, 1000u, 10000u, 50000u, 100000u, 500000u, 1000000u}) {
      if (n > max_n) break;
      const std::vector<ridt::Point> pts = ridt::generate(d, n, 1);
      const Row serial = measure(pts, {}, reps);
      std::printf("%9u %-8s %7s %9.4f %9.4f %9s %9s\n", n, "serial", "-", serial.total,
                  serial.insert, "-", "-");
      if (out)
        std::fprintf(out, "%s,%u,serial,1,%.6f,%.6f,0,0\n", ridt::to_string(d), n, serial.total, serial.insert);
      for (bool paper : {false, true}) {
        double one = 0;
        for (unsigned t : thread_counts) {
          if (paper && t > 2) continue;  // the variants are compared at 1 and 2 threads
          ridt::Options o;
          o.method = ridt::Method::Pessimistic;
          o.threads = t;
          o.paper_locking = paper;
          const Row r = measure(pts, o, reps);
          if (t == 1) one = r.total;
          const char* name = paper ? "paper" : "leaf";
          std::printf("%9u %-8s %7u %9.4f %9.4f %9.4f %9.4f %8.2f\n", n, name, t, r.total,
                      r.insert, r.critical, r.wait, one > 0 ? one / r.total : 0.0);
          if (out)
            std::fprintf(out, "%s,%u,%s,%u,%.6f,%.6f,%.6f,%.6f\n", ridt::to_string(d), n, name, t,
                         r.total, r.insert, r.critical, r.wait);
          std::fflush(stdout);
        }
      }
    }
  }
  if (out) std::fclose(out);
  return 0;
}
