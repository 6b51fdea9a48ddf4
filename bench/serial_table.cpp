// The paper's Table 1 (serial time by distribution and n) and Fig. 8 (share of location,
// subdivision and legalization), with CGAL's Delaunay_triangulation_2 (range insert, which
// sorts spatially) on the same points in the same run. Every figure is the median of --reps
// runs; the ratio column is ridt / CGAL.
//
//   ridt_bench_serial [--max-n N] [--sizes N,N,...] [--dists uniform,...] [--reps R] [--csv FILE]
//
// --sizes and --dists pick rows and columns (a column left out prints as dashes); by default
// all four distributions at n = 100 ... --max-n.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "common.hpp"
#include "ridt/generate.hpp"
#include "ridt/ridt.hpp"

#ifdef RIDT_WITH_CGAL
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

namespace {

using ridt::bench::median;
using ridt::bench::split;

double cgal_seconds(const std::vector<ridt::Point>& pts) {
#ifdef RIDT_WITH_CGAL
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<K::Point_2> p;
  p.reserve(pts.size());
  for (const auto& q : pts) p.emplace_back(q.x, q.y);
  const auto t0 = std::chrono::steady_clock::now();
  CGAL::Delaunay_triangulation_2<K> dt;
  dt.insert(p.begin(), p.end());
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (dt.number_of_vertices() == 0 && !pts.empty()) std::abort();
  return s;
#else
  (void)pts;
  return 0;
#endif
}

struct Args {
  std::uint32_t max_n = 1000000;
  int reps = 5;
  std::string csv;
  std::vector<std::uint32_t> sizes = {100, 500, 1000, 5000, 10000, 50000, 100000, 500000, 1000000};
  bool wanted[4] = {true, true, true, true};
};

bool parse_args(int argc, char** argv, Args& a) {
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--max-n") && i + 1 < argc) {
      a.max_n = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc) {
      a.sizes.clear();
      for (const std::string& n : split(argv[++i])) a.sizes.push_back(static_cast<std::uint32_t>(std::stoul(n)));
    } else if (!std::strcmp(argv[i], "--dists") && i + 1 < argc) {
      std::fill(std::begin(a.wanted), std::end(a.wanted), false);
      for (const std::string& name : split(argv[++i]))
        a.wanted[static_cast<int>(ridt::parse<ridt::Distribution>(name))] = true;
    } else if (!std::strcmp(argv[i], "--reps") && i + 1 < argc) {
      a.reps = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--csv") && i + 1 < argc) {
      a.csv = argv[++i];
    } else {
      return false;
    }
  }
  return a.reps >= 1;
}

// Fig. 8's shares of the insertion time (profiled runs).
struct Share {
  std::uint32_t n;
  double loc, split, leg;
};

// One cell of Table 1: ridt (the paper's random order) and CGAL on distribution d, n points;
// the uniform cells also give Fig. 8's shares.
void cell(const Args& a, ridt::Distribution d, std::uint32_t n, FILE* out, std::vector<Share>& fig8) {
  const std::vector<ridt::Point> pts = ridt::generate(d, n, 1);
  std::vector<double> ours, theirs, loc, split, leg;
  for (int r = 0; r < a.reps; ++r) {
    ridt::Options o;
    o.order = ridt::Order::Random;  // the paper's Table 1; bench/peers_table.cpp has BRIO
    o.seed = 1 + r;
    ours.push_back(ridt::triangulate(pts, o).stats.time_triangulate_s);
    theirs.push_back(cgal_seconds(pts));
    o.experiment.profile = true;
    const ridt::Stats s = ridt::triangulate(pts, o).stats;
    const double total = s.time_locate_s + s.time_split_s + s.time_legalize_s;
    loc.push_back(s.time_locate_s / total);
    split.push_back(s.time_split_s / total);
    leg.push_back(s.time_legalize_s / total);
  }
  const double ridt_s = median(ours), cgal_s = median(theirs);
  std::printf(" | %8.4f %8.4f %6.2f", ridt_s, cgal_s, cgal_s > 0 ? ridt_s / cgal_s : 0.0);
  std::fflush(stdout);
  if (d == ridt::Distribution::Uniform) fig8.push_back({n, median(loc), median(split), median(leg)});
  if (out)
    std::fprintf(out, "%s,%u,%.6f,%.6f,%.4f,%.4f,%.4f,%.4f\n", ridt::to_string(d).data(), n, ridt_s, cgal_s,
                 cgal_s > 0 ? ridt_s / cgal_s : 0.0, median(loc), median(split), median(leg));
}

}  // namespace

int main(int argc, char** argv) {
  Args a;
  if (!parse_args(argc, argv, a)) {
    std::fprintf(
        stderr,
        "usage: %s [--max-n N] [--sizes N,N,...] [--dists uniform,normal,grid,clusters] [--reps R] [--csv FILE]\n",
        argv[0]);
    return 2;
  }
  FILE* out = a.csv.empty() ? nullptr : std::fopen(a.csv.c_str(), "w");
  if (out) std::fprintf(out, "distribution,n,ridt_s,cgal_s,ratio,locate_share,split_share,legalize_share\n");
  std::printf("Table 1: serial times [s], median of %d runs, ridt random order vs CGAL range insert\n", a.reps);
  std::printf("%9s", "n");
  for (const auto& d : ridt::names<ridt::Distribution>())
    std::printf(" | %-8s %8s %6s", d.name.data(), "CGAL", "ratio");
  std::printf("\n");
  std::vector<Share> fig8;
  for (std::uint32_t n : a.sizes) {
    if (n > a.max_n) continue;
    std::printf("%9u", n);
    for (const auto& d : ridt::names<ridt::Distribution>()) {
      if (a.wanted[static_cast<int>(d.value)])
        cell(a, d.value, n, out, fig8);
      else
        std::printf(" | %8s %8s %6s", "-", "-", "-");
    }
    std::printf("\n");
  }
  std::printf("\nFig. 8: share of insertion time, uniform points (profiled runs)\n");
  std::printf("%9s %9s %9s %9s\n", "n", "locate", "split", "legalize");
  for (const Share& s : fig8)
    std::printf("%9u %8.1f%% %8.1f%% %8.1f%%\n", s.n, 100 * s.loc, 100 * s.split, 100 * s.leg);
  if (out) std::fclose(out);
  return 0;
}
