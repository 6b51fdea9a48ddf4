// ridt's insertion orders and location modes side by side with other Delaunay
// codes, on the same points in the same run: CGAL's Delaunay_triangulation_2
// (range insert, which sorts along a curve too), Qhull (qdelaunay's options,
// Qt), Shewchuk's Triangle (its default divide and conquer) and delaunator
// (JavaScript, through node) where they are installed.
// Every time is the median of --reps runs, the codes in a new random order each
// repetition; the ratio is to CGAL's median. Memory is what one run adds to the
// peak of a fresh process that holds its input, per point (the input is not
// counted: each code gets its points ready-made in its own format).
//
//   ridt_bench_peers [--sizes N,N,...] [--dists uniform,...] [--reps R] [--csv
//   FILE]
//                    [--node-modules DIR] [--check]
//
// --check: exit 1 when two codes return different numbers of triangles for the
// same points (a code that lost points, or a peer set up wrongly).
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "common.hpp"
#include "ridt/generate.hpp"
#include "ridt/ridt.hpp"
#include "triangle.hpp"

#ifdef RIDT_WITH_CGAL
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif
#ifdef RIDT_WITH_QHULL
extern "C" {
#include <libqhull_r/qhull_ra.h>
}
#endif

namespace {

using ridt::bench::median;
using ridt::bench::split;

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

#ifdef RIDT_WITH_CGAL
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
#endif

// One code's input, made before it is timed or its memory measured.
struct Input {
  std::vector<ridt::Point> points;
#ifdef RIDT_WITH_CGAL
  std::vector<K::Point_2> cgal;
#endif
  std::vector<double> flat;  // x0, y0, x1, y1, ...
};

struct Code {
  std::string name;
  // Triangulates once; returns seconds and the number of triangles.
  std::function<std::pair<double, std::size_t>(const Input&)> run;
};

ridt::Options ridt_options(ridt::Method m, ridt::Order order, ridt::Locate locate, unsigned threads) {
  ridt::Options o;
  o.method = m;
  o.order = order;
  o.locate = locate;
  o.threads = threads;
  o.experiment.time_threads = false;
  return o;
}

#ifdef RIDT_WITH_CGAL
std::pair<double, std::size_t> run_cgal(const Input& in) {
  const auto t0 = Clock::now();
  CGAL::Delaunay_triangulation_2<K> dt;
  dt.insert(in.cgal.begin(), in.cgal.end());
  const double s = since(t0);
  return std::pair{s, static_cast<std::size_t>(dt.number_of_faces())};
}
#endif

#ifdef RIDT_WITH_QHULL
std::pair<double, std::size_t> run_qhull(const Input& in) {
  std::vector<double> xy = in.flat;  // qhull takes a non-const array
  const auto t0 = Clock::now();
  qhT qh_storage;
  qhT* qh = &qh_storage;
  QHULL_LIB_CHECK
  qh_zero(qh, stderr);
  char options[] = "qhull d Qt Qbb Qc Qz Q12";
  const int code = qh_new_qhull(qh, 2, static_cast<int>(xy.size() / 2), xy.data(), False, options, nullptr, stderr);
  std::size_t triangles = 0;
  if (code == 0) {
    facetT* facet;
    FORALLfacets {
      if (!facet->upperdelaunay) ++triangles;
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong, totlong;
  qh_memfreeshort(qh, &curlong, &totlong);
  const double s = since(t0);
  if (code != 0) std::abort();
  return std::pair{s, triangles};
}
#endif

#ifdef RIDT_WITH_TRIANGLE
// Switches: z (ids from 0), Q (quiet), N (no copy of the points out), B (no boundary markers),
// n (each triangle's neighbours, as ridt gives them).
std::pair<double, std::size_t> run_triangle(const Input& in) {
  std::vector<double> xy = in.flat;  // Triangle takes a non-const array
  const auto t0 = Clock::now();
  triangulateio pts{}, out{};
  pts.pointlist = xy.data();
  pts.numberofpoints = static_cast<int>(xy.size() / 2);
  char options[] = "zQNBn";
  triangulate(options, &pts, &out, nullptr);
  const auto triangles = static_cast<std::size_t>(out.numberoftriangles);
  trifree(out.trianglelist);
  trifree(out.neighborlist);
  return std::pair{since(t0), triangles};
}
#endif

std::vector<Code> codes(std::uint32_t n) {
  std::vector<Code> c;
  auto ridt_code = [](std::string name, ridt::Options o) {
    return Code{std::move(name), [o](const Input& in) {
                  const ridt::Triangulation t = ridt::triangulate(in.points, o);
                  return std::pair{t.stats.time_triangulate_s, t.size()};
                }};
  };
  using ridt::Locate, ridt::Method, ridt::Order;
  // The paper's random order costs some 3 s a million points here: left out above 10^6.
  if (n <= 1000000)
    c.push_back(ridt_code("ridt random dag", ridt_options(Method::Serial, Order::Random, Locate::Dag, 1)));
  c.push_back(ridt_code("ridt brio dag", ridt_options(Method::Serial, Order::Brio, Locate::Dag, 1)));
  c.push_back(ridt_code("ridt brio walk", ridt_options(Method::Serial, Order::Brio, Locate::Walk, 1)));
  c.push_back(ridt_code("ridt optimistic 2", ridt_options(Method::Optimistic, Order::Brio, Locate::Dag, 2)));
  c.push_back(ridt_code("ridt batch 2", ridt_options(Method::Batch, Order::Brio, Locate::Dag, 2)));
  c.push_back(ridt_code("ridt partition 2", ridt_options(Method::Partition, Order::Brio, Locate::Walk, 2)));
#ifdef RIDT_WITH_CGAL
  c.push_back({"CGAL", run_cgal});
#endif
#ifdef RIDT_WITH_QHULL
  if (n <= 1000000) c.push_back({"Qhull", run_qhull});  // some 9 s a million points here
#endif
#ifdef RIDT_WITH_TRIANGLE
  c.push_back({"Triangle", run_triangle});
#endif
  return c;
}

// A figure of /proc/self/status, in bytes (it gives kilobytes).
double status_bytes(const char* key) {
  std::ifstream f("/proc/self/status");
  for (std::string line; std::getline(f, line);)
    if (line.rfind(key, 0) == 0) return std::stod(line.substr(std::strlen(key))) * 1024;
  return -1;
}

Input make_input(ridt::Distribution dist, std::uint32_t n) {
  Input in;
  in.points = ridt::generate(dist, n, 1);
#ifdef RIDT_WITH_CGAL
  for (const auto& p : in.points) in.cgal.emplace_back(p.x, p.y);
#endif
  for (const auto& p : in.points) in.flat.push_back(p.x), in.flat.push_back(p.y);
  return in;
}

// In a process of its own (this program, run again with --measure): the peak
// resident memory that one run of code c adds to a process that holds only its
// input.
int measure(std::size_t c, ridt::Distribution dist, std::uint32_t n) {
  const Input in = make_input(dist, n);
  const Code code = codes(n).at(c);
  // The peak is reset to what is resident now (Linux 4.0 and later).
  if (FILE* f = std::fopen("/proc/self/clear_refs", "w")) {
    std::fputs("5", f);
    std::fclose(f);
  }
  const double before = status_bytes("VmRSS:");
  code.run(in);
  std::printf("%.0f\n", status_bytes("VmHWM:") - before);
  return 0;
}

double added_bytes(std::size_t c, const std::string& dist, std::uint32_t n) {
  const std::string cmd = "/proc/" + std::to_string(getpid()) + "/exe --measure " + std::to_string(c) + " " + dist +
      " " + std::to_string(n);
  double added = -1;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    if (std::fscanf(p, "%lf", &added) != 1) added = -1;
    pclose(p);
  }
  return added;
}

struct Delaunator {
  std::vector<double> times;
  double extra = -1;
  std::size_t triangles = 0;
};

// delaunator through node, on the same points written to a file; empty when
// node or the module is missing.
Delaunator run_delaunator(const std::string& modules, const std::vector<ridt::Point>& pts, int reps) {
  Delaunator d;
  if (modules.empty()) return d;
  const std::string file = "/tmp/ridt_bench_peers_" + std::to_string(getpid()) + ".bin";
  {
    std::ofstream f(file, std::ios::binary);
    f.write(reinterpret_cast<const char*>(pts.data()), static_cast<std::streamsize>(pts.size() * sizeof(ridt::Point)));
  }
  const std::string script = std::string(RIDT_SOURCE_DIR) + "/bench/delaunator.mjs";
  const std::string cmd = "node '" + script + "' '" + file + "' " + std::to_string(reps) + " '" + modules + "'";
  std::string out;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    char buf[4096];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
  }
  std::remove(file.c_str());
  // {"times":[a,b,...],"triangles":N,"extra_rss_bytes":M}
  const auto times_at = out.find("[");
  const auto times_end = out.find("]");
  if (times_at == std::string::npos || times_end == std::string::npos) return d;
  std::stringstream list(out.substr(times_at + 1, times_end - times_at - 1));
  for (std::string item; std::getline(list, item, ',');) d.times.push_back(std::stod(item));
  const auto tri = out.find("\"triangles\":");
  const auto mem = out.find("\"extra_rss_bytes\":");
  if (tri != std::string::npos) d.triangles = std::stoull(out.substr(tri + 12));
  if (mem != std::string::npos) d.extra = std::stod(out.substr(mem + 18));
  return d;
}

struct Args {
  std::vector<std::uint32_t> sizes = {10000, 100000, 1000000};
  std::vector<std::string> dists = {"uniform", "normal", "grid", "clusters"};
  int reps = 5;
  std::string csv, modules;
  bool check = false;
};

bool parse_args(int argc, char** argv, Args& a) {
  if (const char* m = std::getenv("RIDT_NODE_MODULES")) a.modules = m;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--sizes" && i + 1 < argc) {
      a.sizes.clear();
      for (const auto& s : split(argv[++i])) a.sizes.push_back(static_cast<std::uint32_t>(std::stoul(s)));
    } else if (arg == "--dists" && i + 1 < argc) {
      a.dists = split(argv[++i]);
    } else if (arg == "--reps" && i + 1 < argc) {
      a.reps = std::atoi(argv[++i]);
    } else if (arg == "--csv" && i + 1 < argc) {
      a.csv = argv[++i];
    } else if (arg == "--node-modules" && i + 1 < argc) {
      a.modules = argv[++i];
    } else if (arg == "--check") {
      a.check = true;
    } else {
      return false;
    }
  }
  if (!a.modules.empty() && std::system("node --version > /dev/null 2>&1") != 0) a.modules.clear();
  return true;
}

// Each code once a repetition, in an order shuffled anew each time: times and triangle counts.
void interleaved(const std::vector<Code>& list, const Input& in, int reps, std::mt19937& shuffle,
                 std::vector<std::vector<double>>& times, std::vector<std::size_t>& triangles) {
  times.assign(list.size(), {});
  triangles.assign(list.size(), 0);
  std::vector<std::size_t> order(list.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  for (int r = 0; r < reps; ++r) {
    std::shuffle(order.begin(), order.end(), shuffle);
    for (const std::size_t c : order) {
      const auto [s, t] = list[c].run(in);
      times[c].push_back(s);
      triangles[c] = t;
    }
  }
}

// A row of the table: a code's median, its ratio to CGAL's, the memory it adds a point.
struct Row {
  std::string name;
  double seconds, bytes;
  std::size_t triangles;
};

// The rows of one distribution and size, printed (and to the CSV); with --check, the number
// of codes whose triangle count differs from the first's.
int report(const Args& a, const std::string& dist, std::uint32_t n, const std::vector<Row>& rows, FILE* out) {
  double cgal = 0;
  for (const Row& r : rows)
    if (r.name == "CGAL") cgal = r.seconds;
  std::printf("\n%s, n = %u\n%-20s %10s %8s %8s %10s\n", dist.c_str(), n, "code", "median_s", "ratio", "B/pt",
              "triangles");
  int disagreements = 0;
  for (const Row& r : rows) {
    const double ratio = cgal > 0 ? r.seconds / cgal : 0;
    std::printf("%-20s %10.4f %8.3f %8.0f %10zu\n", r.name.c_str(), r.seconds, ratio, r.bytes / n, r.triangles);
    if (out)
      std::fprintf(out, "%s,%u,%s,%.6f,%.4f,%.1f,%zu\n", dist.c_str(), n, r.name.c_str(), r.seconds, ratio, r.bytes / n,
                   r.triangles);
    if (a.check && r.triangles != rows.front().triangles) {
      std::fprintf(stderr, "%s, n = %u: %s gave %zu triangles, %s %zu\n", dist.c_str(), n, r.name.c_str(), r.triangles,
                   rows.front().name.c_str(), rows.front().triangles);
      ++disagreements;
    }
  }
  std::fflush(stdout);
  return disagreements;
}

int table(const Args& a, FILE* out) {
  std::mt19937 shuffle(12345);
  int disagreements = 0;
  for (const std::string& dist_name : a.dists) {
    const ridt::Distribution dist = ridt::parse<ridt::Distribution>(dist_name);
    for (const std::uint32_t n : a.sizes) {
      const Input in = make_input(dist, n);
      const std::vector<Code> list = codes(n);
      std::vector<std::vector<double>> times;
      std::vector<std::size_t> triangles;
      interleaved(list, in, a.reps, shuffle, times, triangles);
      std::vector<Row> rows;
      for (std::size_t c = 0; c < list.size(); ++c)
        rows.push_back({list[c].name, median(times[c]), added_bytes(c, dist_name, n), triangles[c]});
      const Delaunator d = run_delaunator(a.modules, in.points, a.reps);
      if (!d.times.empty()) rows.push_back({"delaunator (node)", median(d.times), d.extra, d.triangles});
      disagreements += report(a, dist_name, n, rows, out);
    }
  }
  return disagreements;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 5 && std::string(argv[1]) == "--measure")
    return measure(std::stoul(argv[2]), ridt::parse<ridt::Distribution>(argv[3]),
                   static_cast<std::uint32_t>(std::stoul(argv[4])));
  Args a;
  if (!parse_args(argc, argv, a)) {
    std::fprintf(stderr,
                 "usage: %s [--sizes N,N,...] [--dists uniform,normal,grid,clusters] [--reps R] [--csv FILE] "
                 "[--node-modules DIR] [--check]\n",
                 argv[0]);
    return 2;
  }
  FILE* out = a.csv.empty() ? nullptr : std::fopen(a.csv.c_str(), "w");
  if (out) std::fprintf(out, "distribution,n,code,median_s,ratio_to_cgal,added_bytes_per_point,triangles\n");
  std::printf("Medians of %d runs [s]; ratio = time / CGAL's; B/pt = peak memory a run adds, per point\n", a.reps);
  const int disagreements = table(a, out);
  if (out) std::fclose(out);
  return disagreements > 0 ? 1 : 0;
}
